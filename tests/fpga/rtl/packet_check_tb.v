// Icarus Verilog testbench of our seed 000 RTL with the packet check (top's PACKET_CRC = 1; the protocol is in
// sim/architectures/fpga_uart/README.md): a motion packet, G1 X +32 Y -16 F1200 (01 00000020 FFFFFFF0 04B0, the
// worked example of seed 000 §4.9 at a tenth of its steps), with its CRC-16/CCITT-FALSE AF 4E (Python's
// binascii.crc_hqx with the preset 0xFFFF, a second implementation of the law), sent bit by bit at 115200 Bd:
//   1. with one bit of StepsX inverted (X +36): NAK 0x55, its start bit 3 clocks after the decoder's crc_error strobe
//      (top sees the strobe one clock later and pulses tx_start, uart_tx leaves IDLE on the next clock and drives
//      the start bit on the one after, as for the ACK), and no move;
//   2. as sent: the move, 32 X pulses 15,625 clocks apart, and the ACK 0xAA 3 clocks after busy falls, as the seed;
//   3. the same packet again (its sequence bit, bit 7 of byte 0, unchanged: the host lost the ACK): ACK 0xAA 3 clocks
//      after the pkt_repeat strobe, and no second move;
//   4. the next move with the sequence bit flipped, G1 X +2 (81 00000002 00000000 04B0, CRC 8E 10): run and ACKed.
// Prints PASS or FAIL lines (the ctest test matches them).
module packet_check_tb;
    localparam integer BIT = 434;  // clocks per bit at 50 MHz
    reg clk = 1'b0;
    reg rst_n = 1'b0;
    reg rx = 1'b1;
    wire tx, dir_x, step_x, n_enbl_x, dir_y, step_y, n_enbl_y, laser, busy;

    top #(.PACKET_CRC(1)) dut (.clk(clk), .rst_n(rst_n), .rx(rx), .tx(tx), .dir_x(dir_x), .step_x(step_x),
                               .n_enbl_x(n_enbl_x), .dir_y(dir_y), .step_y(step_y), .n_enbl_y(n_enbl_y),
                               .laser(laser), .busy(busy));

    always #10 clk = ~clk;  // 50 MHz

    integer cycle = 0;
    always @(posedge clk) cycle <= cycle + 1;

    `include "tb_tasks.vh"

    // The 13 bytes of a motion packet, most significant first: b0, StepsX, StepsY, FeedRate, CRC.
    task send_motion(input [7:0] b0, input [31:0] sx, input [31:0] sy, input [15:0] feed, input [15:0] crc);
        begin
            send_byte(b0);
            send_byte(sx[31:24]); send_byte(sx[23:16]); send_byte(sx[15:8]); send_byte(sx[7:0]);
            send_byte(sy[31:24]); send_byte(sy[23:16]); send_byte(sy[15:8]); send_byte(sy[7:0]);
            send_byte(feed[15:8]); send_byte(feed[7:0]);
            send_byte(crc[15:8]); send_byte(crc[7:0]);
        end
    endtask

    // The decoder's strobes and busy, by the cycle of their last rise or fall.
    integer pkt_valids = 0, crc_errors = 0, repeats = 0, busy_rises = 0;
    integer crc_error_at = 0, repeat_at = 0, busy_fell = 0;
    always @(posedge dut.pkt_valid) if (rst_n) pkt_valids = pkt_valids + 1;
    always @(posedge dut.crc_error) if (rst_n) begin
        crc_errors = crc_errors + 1;
        crc_error_at = cycle;
    end
    always @(posedge dut.pkt_repeat) if (rst_n) begin
        repeats = repeats + 1;
        repeat_at = cycle;
    end
    always @(posedge busy) if (rst_n) busy_rises = busy_rises + 1;
    always @(negedge busy) if (rst_n) busy_fell = cycle;

    // X STEP rises: their count and the periods between them.
    integer x_rises = 0, x_last_rise = 0, x_period_bad = 0;
    always @(posedge step_x) if (rst_n) begin
        if (x_rises > 0 && x_rises != 32 && cycle - x_last_rise != 15625) x_period_bad = x_period_bad + 1;
        x_last_rise = cycle;
        x_rises = x_rises + 1;
    end

    localparam integer MAX_FRAMES = 8;
    `include "tx_frames.vh"

    initial begin
        repeat (4) @(posedge clk);
        rst_n = 1'b1;
        repeat (100) @(posedge clk);

        send_motion(8'h01, 32'd36, -32'sd16, 16'd1200, 16'hAF4E);  // X +32 with one bit inverted
        repeat (12 * BIT) @(posedge clk);
        check(frames, 1, "frames on tx after the bad packet");
        check(frame_byte[0], 8'h55, "answer to the bad packet (NAK)");
        check(frame_start[0] - crc_error_at, 3, "clocks from crc_error to the NAK start bit");
        check(busy_rises, 0, "moves run for the bad packet");

        send_motion(8'h01, 32'd32, -32'sd16, 16'd1200, 16'hAF4E);
        wait (busy_fell != 0);
        repeat (12 * BIT) @(posedge clk);
        check(frames, 2, "frames on tx after the good packet");
        check(frame_byte[1], 8'hAA, "answer to the good packet (ACK)");
        check(frame_start[1] - busy_fell, 3, "clocks from busy falling to the ACK start bit");
        check(x_rises, 32, "X STEP pulses of the move");
        check(dir_y, 0, "DIR_Y for -16");

        send_motion(8'h01, 32'd32, -32'sd16, 16'd1200, 16'hAF4E);  // again: the same sequence bit
        repeat (12 * BIT) @(posedge clk);
        check(frames, 3, "frames on tx after the repeat");
        check(frame_byte[2], 8'hAA, "answer to the repeat (ACK)");
        check(frame_start[2] - repeat_at, 3, "clocks from pkt_repeat to the ACK start bit");
        check(busy_rises, 1, "moves run after the repeat");

        send_motion(8'h81, 32'd2, 32'd0, 16'd1200, 16'h8E10);  // the next move: sequence bit flipped
        wait (busy_rises == 2 && !busy);
        repeat (12 * BIT) @(posedge clk);
        check(frames, 4, "frames on tx after the next move");
        check(frame_byte[3], 8'hAA, "answer to the next move (ACK)");
        check(x_rises, 34, "X STEP pulses of both moves");
        check(x_period_bad, 0, "X periods other than 15625 clocks");
        check(pkt_valids, 2, "pkt_valid strobes");
        check(crc_errors, 1, "crc_error strobes");
        check(repeats, 1, "pkt_repeat strobes");
        if (failures == 0)
            $display("PASS: NAK 0x%h for the bad CRC, the move and ACK 0x%h, the repeat ACKed (0x%h) and not run, the next move run",
                     frame_byte[0], frame_byte[1], frame_byte[2]);
        $finish;
    end
endmodule
