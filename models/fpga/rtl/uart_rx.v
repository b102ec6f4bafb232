// UART receiver, 8N1, LSB first (seed 000 §4.3, §5.2.1): a two-flip-flop synchroniser on rx, the start bit checked
// at its middle (HALF_BIT clocks after the falling edge is seen), then one sample every FULL_BIT clocks, mid-bit.
// A byte whose stop bit is low is dropped (framing error); a good one is latched and rx_valid pulses for one clock.
module uart_rx #(
    parameter FULL_BIT = 434,  // clocks per bit: 50 MHz / 115200 Bd (§4.2)
    parameter HALF_BIT = 217
) (
    input  wire       clk,
    input  wire       rst,  // synchronous, active high
    input  wire       rx,
    output reg  [7:0] rx_data,
    output reg        rx_valid
);
    localparam S_IDLE = 2'd0, S_START = 2'd1, S_RECEIVE = 2'd2, S_STOP = 2'd3;
    reg [1:0]  state;
    reg [15:0] count;
    reg [2:0]  bit_idx;
    reg [7:0]  rx_shift;
    reg        rx_s1, rx_s2;

    always @(posedge clk) begin
        if (rst) begin
            state <= S_IDLE;
            count <= 16'd0;
            bit_idx <= 3'd0;
            rx_shift <= 8'd0;
            rx_data <= 8'd0;
            rx_valid <= 1'b0;
            rx_s1 <= 1'b1;
            rx_s2 <= 1'b1;
        end else begin
            rx_s1 <= rx;
            rx_s2 <= rx_s1;
            rx_valid <= 1'b0;
            case (state)
                S_IDLE: begin
                    count <= 16'd0;
                    bit_idx <= 3'd0;
                    if (!rx_s2) begin
                        state <= S_START;
                        count <= 16'd1;
                    end
                end
                S_START:
                    if (count == HALF_BIT) begin
                        if (!rx_s2) begin  // still low mid-bit: a start bit, not a glitch
                            count <= 16'd1;
                            state <= S_RECEIVE;
                        end else begin
                            count <= 16'd0;
                            state <= S_IDLE;
                        end
                    end else
                        count <= count + 16'd1;
                S_RECEIVE:
                    if (count == FULL_BIT) begin
                        count <= 16'd1;
                        rx_shift[bit_idx] <= rx_s2;
                        if (bit_idx == 3'd7) begin
                            bit_idx <= 3'd0;
                            state <= S_STOP;
                        end else
                            bit_idx <= bit_idx + 3'd1;
                    end else
                        count <= count + 16'd1;
                default:  // S_STOP
                    if (count == FULL_BIT) begin
                        count <= 16'd0;
                        state <= S_IDLE;
                        if (rx_s2) begin
                            rx_data <= rx_shift;
                            rx_valid <= 1'b1;
                        end
                    end else
                        count <= count + 16'd1;
            endcase
        end
    end
endmodule
