// Icarus Verilog testbench of our seed 000 RTL with the packet queue (top's QUEUE_DEPTH = 2, PACKET_CRC = 1; the
// protocol in sim/architectures/fpga_uart/README.md): numbered motion packets (bits 6:2 of byte 0), each with its
// CRC-16/CCITT-FALSE computed here one bit at a time (crc_hqx of Python's binascii with the preset 0xFFFF gives
// the same: 0xCD9F for the first packet below), sent bit by bit at 500 kBd (FULL_BIT = 100, so that the moves
// outlast four packets on the wire in few clocks):
//   1. packets 0, 1 and 2, G1 X +250 F65535 (286 clocks a step: 71,500 clocks, five packets 65,000): 0 runs at
//      once, 1 and 2 wait; packet 3 finds no slot and is refused; packet 1 sent again is answered, not queued again;
//   2. the three moves back to back: busy low one clock between them;
//   3. packet 3 sent again once they have run: queued and run (G1 X +10).
// Each packet and each busy fall is answered by a 2-byte status, 1 1 running free[4:0] then 1 0 refused next[4:0],
// the expected bytes written here from those rules: its start bit 4 clocks after the decoder's pkt_valid (the queue
// judges the packet at the next edge, top starts the status at the one after, uart_tx leaves IDLE and drives the
// start bit on the two after) or 3 after busy falls (the queue hands over the next move at that edge), and the
// second byte's start bit 10 bits and 2 clocks after the first's. Prints PASS or FAIL lines (the ctest test matches
// them).
module packet_queue_tb;
    localparam integer BIT = 100;  // clocks per bit: 500 kBd at 50 MHz
    localparam integer LONG_STEPS = 250;
    localparam integer SHORT_STEPS = 10;
    reg clk = 1'b0;
    reg rst_n = 1'b0;
    reg rx = 1'b1;
    wire tx, dir_x, step_x, n_enbl_x, dir_y, step_y, n_enbl_y, laser, busy;

    top #(.FULL_BIT(BIT), .PACKET_CRC(1), .QUEUE_DEPTH(2)) dut (
        .clk(clk), .rst_n(rst_n), .rx(rx), .estop(1'b0), .lid_open(1'b0), .tx(tx), .dir_x(dir_x), .step_x(step_x),
        .n_enbl_x(n_enbl_x), .dir_y(dir_y), .step_y(step_y), .n_enbl_y(n_enbl_y), .laser(laser), .busy(busy));

    always #10 clk = ~clk;  // 50 MHz

    integer cycle = 0;
    always @(posedge clk) cycle <= cycle + 1;

    `include "tb_tasks.vh"

    // CRC-16/CCITT-FALSE, one message bit at a time into the register's top (polynomial 0x1021).
    reg [15:0] crc;
    task send_checked(input [7:0] b);
        integer i;
        begin
            for (i = 7; i >= 0; i = i - 1) crc = (crc[15] ^ b[i]) ? {crc[14:0], 1'b0} ^ 16'h1021 : {crc[14:0], 1'b0};
            send_byte(b);
        end
    endtask

    // A motion packet numbered `seq`: G1 X +steps F65535, then its CRC high byte first.
    task send_move(input [4:0] seq, input [31:0] steps);
        reg [15:0] sent;
        begin
            crc = 16'hFFFF;
            send_checked({1'b0, seq, 2'b01});
            send_checked(steps[31:24]); send_checked(steps[23:16]); send_checked(steps[15:8]); send_checked(steps[7:0]);
            repeat (4) send_checked(8'h00);
            send_checked(8'hFF); send_checked(8'hFF);
            sent = crc;
            send_byte(sent[15:8]);
            send_byte(sent[7:0]);
        end
    endtask

    // The decoder's packets and the busy falls, by cycle; the gaps busy stays low between moves.
    integer pkt_valids = 0, busy_rises = 0, busy_falls = 0, busy_fell = 0, gap_bad = 0;
    integer pkt_valid_at [0:7];
    integer busy_fall_at [0:7];
    always @(posedge dut.pkt_valid) if (rst_n) begin
        pkt_valid_at[pkt_valids] = cycle;
        pkt_valids = pkt_valids + 1;
    end
    always @(negedge busy) if (rst_n) begin
        busy_fall_at[busy_falls] = cycle;
        busy_falls = busy_falls + 1;
        busy_fell = cycle;
    end
    always @(posedge busy) if (rst_n) begin
        if (busy_rises == 1 || busy_rises == 2) begin  // the moves queued behind the first
            if (cycle - busy_fell != 1) gap_bad = gap_bad + 1;
        end
        busy_rises = busy_rises + 1;
    end
    integer x_rises = 0;
    always @(posedge step_x) if (rst_n) x_rises = x_rises + 1;

    localparam integer MAX_FRAMES = 32;
    `include "tx_frames.vh"

    // Status s: its two bytes as expected, the first's start bit `after` clocks after cycle `from`.
    task check_status(input integer s, input [7:0] b0, input [7:0] b1, input integer from, input integer after);
        begin
            check(frame_byte[2 * s], b0, "status byte 0");
            check(frame_byte[2 * s + 1], b1, "status byte 1");
            check(frame_start[2 * s] - from, after, "clocks to the status's start bit");
            check(frame_start[2 * s + 1] - frame_start[2 * s], 10 * BIT + 2, "clocks between its two start bits");
        end
    endtask

    initial begin
        repeat (4) @(posedge clk);
        rst_n = 1'b1;
        repeat (100) @(posedge clk);

        send_move(5'd0, LONG_STEPS);
        send_move(5'd1, LONG_STEPS);
        send_move(5'd2, LONG_STEPS);
        send_move(5'd3, LONG_STEPS);
        send_move(5'd1, LONG_STEPS);
        wait (busy_falls == 3);
        repeat (12 * 2 * BIT) @(posedge clk);
        send_move(5'd3, SHORT_STEPS);
        wait (busy_falls == 4);
        repeat (25 * BIT) @(posedge clk);

        check(frames, 20, "bytes sent: ten statuses");
        // running 1, free 2 (the move handed over at once), next 1; then one slot fewer each, next one more.
        check_status(0, 8'hE2, 8'h81, pkt_valid_at[0], 4);
        check_status(1, 8'hE1, 8'h82, pkt_valid_at[1], 4);
        check_status(2, 8'hE0, 8'h83, pkt_valid_at[2], 4);
        check_status(3, 8'hE0, 8'hA3, pkt_valid_at[3], 4);  // refused: no slot
        check_status(4, 8'hE0, 8'h83, pkt_valid_at[4], 4);  // queued already: answered, not refused
        check_status(5, 8'hE1, 8'h83, busy_fall_at[0], 3);  // the next move handed over at the busy fall
        check_status(6, 8'hE2, 8'h83, busy_fall_at[1], 3);
        check_status(7, 8'hC2, 8'h83, busy_fall_at[2], 3);  // none left: not running
        check_status(8, 8'hE2, 8'h84, pkt_valid_at[5], 4);
        check_status(9, 8'hC2, 8'h84, busy_fall_at[3], 3);
        check(busy_rises, 4, "moves run");
        check(gap_bad, 0, "queued moves not started the clock after busy fell");
        check(x_rises, 3 * LONG_STEPS + SHORT_STEPS, "X steps");
        if (failures == 0)
            $display("PASS: statuses E2 81, E1 82, E0 83, E0 A3 (no slot), E0 83 (sent again), E1 83, E2 83, C2 83, %0s",
                     "E2 84, C2 84 at 4 clocks after the packet or 3 after busy falls; queued moves 1 clock apart");
        $finish;
    end
endmodule
