// UART transmitter, 8N1, LSB first (seed 000 §4.4, §5.2.2): on tx_start it latches tx_data and drives the start
// bit, eight data bits and the stop bit, FULL_BIT clocks each; tx_busy is high from tx_start to the stop bit's end.
module uart_tx #(
    parameter FULL_BIT = 434  // clocks per bit: 50 MHz / 115200 Bd
) (
    input  wire       clk,
    input  wire       rst,
    input  wire [7:0] tx_data,
    input  wire       tx_start,
    output reg        tx_busy,
    output reg        tx
);
    localparam IDLE = 2'd0, START = 2'd1, DATA = 2'd2, STOP = 2'd3;
    reg [1:0]  state;
    reg [15:0] clk_count;
    reg [2:0]  bit_index;
    reg [7:0]  tx_shift;

    always @(posedge clk) begin
        if (rst) begin
            state <= IDLE;
            clk_count <= 16'd0;
            bit_index <= 3'd0;
            tx_shift <= 8'd0;
            tx_busy <= 1'b0;
            tx <= 1'b1;
        end else
            case (state)
                IDLE: begin
                    tx <= 1'b1;
                    tx_busy <= 1'b0;
                    if (tx_start) begin
                        tx_shift <= tx_data;
                        tx_busy <= 1'b1;
                        clk_count <= 16'd0;
                        state <= START;
                    end
                end
                START: begin
                    tx <= 1'b0;
                    if (clk_count == FULL_BIT - 1) begin
                        clk_count <= 16'd0;
                        bit_index <= 3'd0;
                        state <= DATA;
                    end else
                        clk_count <= clk_count + 16'd1;
                end
                DATA: begin
                    tx <= tx_shift[bit_index];
                    if (clk_count == FULL_BIT - 1) begin
                        clk_count <= 16'd0;
                        if (bit_index == 3'd7) begin
                            bit_index <= 3'd0;
                            state <= STOP;
                        end else
                            bit_index <= bit_index + 3'd1;
                    end else
                        clk_count <= clk_count + 16'd1;
                end
                default: begin  // STOP
                    tx <= 1'b1;
                    if (clk_count == FULL_BIT - 1) begin
                        clk_count <= 16'd0;
                        tx_busy <= 1'b0;
                        state <= IDLE;
                    end else
                        clk_count <= clk_count + 16'd1;
                end
            endcase
    end
endmodule
