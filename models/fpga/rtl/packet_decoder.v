// Packet decoder (seed 000 §4.5-4.10, §5.2.3): the first byte decides the packet: 0xFF an init packet of 9 bytes
// (two big-endian 32-bit numerators), anything else a motion packet of 11 bytes (motion, steps X and Y as signed
// 32-bit, feed as unsigned 16-bit, all big-endian). The byte counter is the state. A partial packet is cleared when
// TIMEOUT_CYCLES clocks pass without a byte (the 100 ms watchdog, counted from the last byte). pkt_valid and
// cfg_valid pulse for one clock; the fields keep their last values.
module packet_decoder #(
    parameter TIMEOUT_CYCLES    = 5000000,   // 100 ms at 50 MHz
    parameter NUMERATOR_DEFAULT = 18750000   // §5.2.3: 1/32 microstep, GT2 belt, 20-tooth pulley
) (
    input  wire        clk,
    input  wire        rst,
    input  wire [7:0]  rx_data,
    input  wire        rx_valid,
    output reg  [1:0]  motion,
    output reg  [31:0] steps_x,
    output reg  [31:0] steps_y,
    output reg  [15:0] feed_rate,
    output reg         pkt_valid,
    output reg  [31:0] numerator_x,
    output reg  [31:0] numerator_y,
    output reg         cfg_valid
);
    localparam [7:0] CFG_MARKER = 8'hFF;
    reg [3:0]  byte_count;
    reg [22:0] timeout_cnt;
    reg        timeout_active;
    reg        is_cfg_pkt;
    reg [7:0]  b0, b1, b2, b3, b4, b5, b6, b7, b8, b9;

    always @(posedge clk) begin
        if (rst) begin
            byte_count <= 4'd0;
            timeout_cnt <= 23'd0;
            timeout_active <= 1'b0;
            is_cfg_pkt <= 1'b0;
            {b0, b1, b2, b3, b4, b5, b6, b7, b8, b9} <= 80'd0;
            motion <= 2'd0;
            steps_x <= 32'd0;
            steps_y <= 32'd0;
            feed_rate <= 16'd0;
            pkt_valid <= 1'b0;
            numerator_x <= NUMERATOR_DEFAULT;
            numerator_y <= NUMERATOR_DEFAULT;
            cfg_valid <= 1'b0;
        end else begin
            pkt_valid <= 1'b0;
            cfg_valid <= 1'b0;
            if (timeout_active && !rx_valid) begin
                timeout_cnt <= timeout_cnt + 23'd1;
                if (timeout_cnt >= TIMEOUT_CYCLES - 1) begin
                    byte_count <= 4'd0;
                    timeout_cnt <= 23'd0;
                    timeout_active <= 1'b0;
                    is_cfg_pkt <= 1'b0;
                end
            end
            if (rx_valid) begin
                timeout_cnt <= 23'd0;
                case (byte_count)
                    4'd0: b0 <= rx_data;
                    4'd1: b1 <= rx_data;
                    4'd2: b2 <= rx_data;
                    4'd3: b3 <= rx_data;
                    4'd4: b4 <= rx_data;
                    4'd5: b5 <= rx_data;
                    4'd6: b6 <= rx_data;
                    4'd7: b7 <= rx_data;
                    4'd8: b8 <= rx_data;
                    4'd9: b9 <= rx_data;
                    default: ;
                endcase
                if (byte_count == 4'd0) begin
                    timeout_active <= 1'b1;
                    is_cfg_pkt <= rx_data == CFG_MARKER;
                end
                if (is_cfg_pkt && byte_count == 4'd8) begin
                    numerator_x <= {b1, b2, b3, b4};
                    numerator_y <= {b5, b6, b7, rx_data};
                    cfg_valid <= 1'b1;
                    byte_count <= 4'd0;
                    timeout_active <= 1'b0;
                    is_cfg_pkt <= 1'b0;
                end else if (!is_cfg_pkt && byte_count == 4'd10) begin
                    motion <= b0[1:0];
                    steps_x <= {b1, b2, b3, b4};
                    steps_y <= {b5, b6, b7, b8};
                    feed_rate <= {b9, rx_data};
                    pkt_valid <= 1'b1;
                    byte_count <= 4'd0;
                    timeout_active <= 1'b0;
                end else
                    byte_count <= byte_count + 4'd1;
            end
        end
    end
endmodule
