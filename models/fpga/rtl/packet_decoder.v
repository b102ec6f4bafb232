// Packet decoder (seed 000 §4.5-4.10, §5.2.3): the first byte decides the packet: 0xFF an init packet of 9 bytes
// (two big-endian 32-bit numerators), anything else a motion packet of 11 bytes (motion, steps X and Y as signed
// 32-bit, feed as unsigned 16-bit, all big-endian). The byte counter is the state. A partial packet is cleared when
// TIMEOUT_CYCLES clocks pass without a byte (the 100 ms watchdog, counted from the last byte). pkt_valid and
// cfg_valid pulse for one clock; the fields keep their last values.
//
// PACKET_CRC = 1 adds our packet check (seed 000 §7.2 proposes a CRC field; sim/architectures/fpga_uart/README.md has
// the protocol): each packet is followed by its CRC-16/CCITT-FALSE, high byte first (11-byte init, 13-byte motion),
// run through the register one byte per clock, so that a packet received as sent leaves it at zero. A packet that
// does not strobes crc_error instead of pkt_valid or cfg_valid. Bit 7 of a motion packet's first byte alternates
// from one new move to the next: a good motion packet with the bit of the last one passed on is the host sending it
// again because it lost the ACK, so it strobes pkt_repeat and is not run twice. The strobes last one clock, at the
// edge pkt_valid would have.
//
// LASER_PWM = 1 adds our PWM laser power's field (laser_ctrl.v): a motion packet has two more bytes after the feed, the
// PWM high time in clocks, big-endian (13 bytes, 15 with the check).
//
// RAMP = 1 adds our trapezoidal ramp's registers (step_ramp.v): an init packet has eight more bytes after the
// numerators, the acceleration and the start speed, big-endian (17 bytes, 19 with the check).
//
// QUEUE = 1 (our packet queue, packet_queue.v) numbers the motion packets instead: bits 6:2 of the first byte go out
// on seq with the fields, and no packet is a repeat (the queue finds those by their numbers).
module packet_decoder #(
    parameter TIMEOUT_CYCLES    = 5000000,   // 100 ms at 50 MHz
    parameter NUMERATOR_DEFAULT = 18750000,  // §5.2.3: 1/32 microstep, GT2 belt, 20-tooth pulley
    parameter PACKET_CRC        = 0,         // 1: the packet check above; 0: the seed's packets
    parameter LASER_PWM         = 0,         // 1: the PWM high time above; 0: the seed's packets
    parameter RAMP              = 0,         // 1: the ramp's registers above; 0: the seed's init packet
    parameter RAMP_ACCEL_DEFAULT = 18014,    // their values until an init packet sets them
    parameter RAMP_START_DEFAULT = 68719,
    parameter QUEUE             = 0          // 1: the packet numbers above; 0: the alternating bit
) (
    input  wire        clk,
    input  wire        rst,
    input  wire [7:0]  rx_data,
    input  wire        rx_valid,
    output reg  [1:0]  motion,
    output reg  [4:0]  seq,
    output reg  [31:0] steps_x,
    output reg  [31:0] steps_y,
    output reg  [15:0] feed_rate,
    output reg  [15:0] laser_high,
    output reg         pkt_valid,
    output reg  [31:0] numerator_x,
    output reg  [31:0] numerator_y,
    output reg  [31:0] ramp_accel,
    output reg  [31:0] ramp_start,
    output reg         cfg_valid,
    output reg         crc_error,
    output reg         pkt_repeat
);
    localparam [7:0] CFG_MARKER  = 8'hFF;
    localparam       CHECKED     = PACKET_CRC != 0;  // one bit, for the conditions below
    localparam       PWM         = LASER_PWM != 0;
    localparam       RAMPED      = RAMP != 0;
    localparam       COUNT_BITS  = RAMPED ? 5 : 4;  // the ramp's init packet is 17 bytes long
    // The byte_count of a packet's last byte: with the check, two CRC bytes follow the seed's 9 or 11 (13 with the
    // high time, 17 the ramp's init).
    localparam [COUNT_BITS-1:0] INIT_LAST   = (RAMPED ? 5'd16 : 5'd8) + (CHECKED ? 5'd2 : 5'd0);
    localparam [COUNT_BITS-1:0] MOTION_LAST = (PWM ? 4'd12 : 4'd10) + (CHECKED ? 4'd2 : 4'd0);
    reg [COUNT_BITS-1:0] byte_count;
    reg [22:0] timeout_cnt;
    reg        timeout_active;
    reg        is_cfg_pkt;
    // With the check the last byte is the CRC's, so the fields' last bytes (b8, b10, b12) come from the bank too; so
    // does the feed's (b10) with the high time after it.
    reg [7:0]  b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12;
    reg [7:0]  b13, b14, b15, b16;  // the ramp's init
    reg [15:0] crc;       // the CRC register over the packet's bytes so far
    reg        seq_seen;  // a motion packet has been passed on since reset
    reg        last_seq;  // its sequence bit

    // CRC-16/CCITT-FALSE (polynomial 0x1021, most significant bit first) after one more byte: the eight shifts of the
    // bit-serial register (common/crc16.hpp's law) unrolled into one clock, so that a packet's last byte is judged at
    // the edge the seed's pkt_valid has, not eight clocks later.
    function [15:0] crc16_update;
        input [15:0] reg_in;
        input [7:0]  data;
        integer i;
        begin
            crc16_update = reg_in ^ {data, 8'h00};
            for (i = 0; i < 8; i = i + 1)
                crc16_update = crc16_update[15] ? {crc16_update[14:0], 1'b0} ^ 16'h1021
                                                : {crc16_update[14:0], 1'b0};
        end
    endfunction

    // The register over this packet with the byte now received, 0xFFFF the preset at byte 0.
    wire [15:0] crc_next = crc16_update(byte_count == 4'd0 ? 16'hFFFF : crc, rx_data);
    // Without the check every packet is good and none is a repeat.
    wire        crc_good = !CHECKED || crc_next == 16'd0;
    wire        is_repeat = CHECKED && QUEUE == 0 && seq_seen && b0[7] == last_seq;

    always @(posedge clk) begin
        if (rst) begin
            byte_count <= 4'd0;
            timeout_cnt <= 23'd0;
            timeout_active <= 1'b0;
            is_cfg_pkt <= 1'b0;
            {b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12} <= 104'd0;
            crc <= 16'd0;
            seq_seen <= 1'b0;
            last_seq <= 1'b0;
            motion <= 2'd0;
            steps_x <= 32'd0;
            steps_y <= 32'd0;
            feed_rate <= 16'd0;
            laser_high <= 16'd0;
            pkt_valid <= 1'b0;
            numerator_x <= NUMERATOR_DEFAULT;
            numerator_y <= NUMERATOR_DEFAULT;
            cfg_valid <= 1'b0;
            crc_error <= 1'b0;
            pkt_repeat <= 1'b0;
            // Only with the ramp: unused without it, their reset still moved Yosys's LUT mapping of the seed's design.
            if (QUEUE != 0) seq <= 5'd0;
            if (RAMPED) begin
                {b13, b14, b15, b16} <= 32'd0;
                ramp_accel <= RAMP_ACCEL_DEFAULT;
                ramp_start <= RAMP_START_DEFAULT;
            end
        end else begin
            pkt_valid <= 1'b0;
            cfg_valid <= 1'b0;
            crc_error <= 1'b0;
            pkt_repeat <= 1'b0;
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
                crc <= crc_next;
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
                    4'd10: b10 <= rx_data;
                    4'd11: b11 <= rx_data;
                    4'd12: b12 <= rx_data;
                    default: ;
                endcase
                if (RAMPED)
                    case (byte_count)
                        5'd13: b13 <= rx_data;
                        5'd14: b14 <= rx_data;
                        5'd15: b15 <= rx_data;
                        5'd16: b16 <= rx_data;
                        default: ;
                    endcase
                if (byte_count == 4'd0) begin
                    timeout_active <= 1'b1;
                    is_cfg_pkt <= rx_data == CFG_MARKER;
                end
                if (is_cfg_pkt && byte_count == INIT_LAST) begin
                    if (crc_good) begin
                        numerator_x <= {b1, b2, b3, b4};
                        numerator_y <= {b5, b6, b7, CHECKED || RAMPED ? b8 : rx_data};
                        if (RAMPED) begin
                            ramp_accel <= {b9, b10, b11, b12};
                            ramp_start <= {b13, b14, b15, CHECKED ? b16 : rx_data};
                        end
                        cfg_valid <= 1'b1;
                    end else
                        crc_error <= 1'b1;
                    byte_count <= 4'd0;
                    timeout_active <= 1'b0;
                    is_cfg_pkt <= 1'b0;
                end else if (!is_cfg_pkt && byte_count == MOTION_LAST) begin
                    if (!crc_good)
                        crc_error <= 1'b1;
                    else if (is_repeat)
                        pkt_repeat <= 1'b1;
                    else begin
                        motion <= b0[1:0];
                        if (QUEUE != 0) seq <= b0[6:2];
                        steps_x <= {b1, b2, b3, b4};
                        steps_y <= {b5, b6, b7, b8};
                        feed_rate <= {b9, CHECKED || PWM ? b10 : rx_data};
                        if (PWM) laser_high <= {b11, CHECKED ? b12 : rx_data};
                        pkt_valid <= 1'b1;
                        seq_seen <= 1'b1;
                        last_seq <= b0[7];
                    end
                    byte_count <= 4'd0;
                    timeout_active <= 1'b0;
                end else
                    byte_count <= byte_count + 4'd1;
            end
        end
    end
endmodule
