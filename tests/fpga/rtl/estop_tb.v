// Icarus Verilog testbench of our seed 000 RTL with the safety inputs (top's ESTOP = 1, INTERLOCK = 1; the behaviour
// in sim/architectures/fpga_uart/README.md): a long cut, G1 X +100 F65535 (01 00000064 00000000 FFFF: 286 clocks a
// step), sent bit by bit at 115200 Bd. The inputs change between clock edges, after edge n:
//   1. the lid opened during the cut: the laser falls at edge n+3 (two synchroniser flip-flops, then laser_ctrl's
//      register), STEP goes on; closed again: the laser rises at n+3;
//   2. the e-stop pressed during the cut: busy falls at n+2 (estop_meta, then step_gen's registers), STEP is low
//      there and never rises again, the laser falls at n+3, and the byte on tx is the halt byte 0x4B (no ACK);
//   3. a packet after the press does not run, and releasing the e-stop changes nothing (latched until reset).
// Prints PASS or FAIL lines (the ctest test matches them).
module estop_tb;
    localparam integer BIT = 434;  // clocks per bit at 50 MHz
    reg clk = 1'b0;
    reg rst_n = 1'b0;
    reg rx = 1'b1;
    reg estop = 1'b0;
    reg lid_open = 1'b0;
    wire tx, dir_x, step_x, n_enbl_x, dir_y, step_y, n_enbl_y, laser, busy;

    top #(.ESTOP(1), .INTERLOCK(1)) dut (.clk(clk), .rst_n(rst_n), .rx(rx), .estop(estop), .lid_open(lid_open),
                                         .tx(tx), .dir_x(dir_x), .step_x(step_x), .n_enbl_x(n_enbl_x), .dir_y(dir_y),
                                         .step_y(step_y), .n_enbl_y(n_enbl_y), .laser(laser), .busy(busy));

    always #10 clk = ~clk;  // 50 MHz

    integer cycle = 0;
    always @(posedge clk) cycle <= cycle + 1;

    `include "tb_tasks.vh"

    // The seed's 11-byte motion packet, its first byte in the top bits.
    task send_packet(input [8*11-1:0] bytes);
        integer i;
        for (i = 10; i >= 0; i = i - 1) send_byte(bytes[8*i +: 8]);
    endtask

    // The edges of the pins since reset: the last of each, and the STEP rises and busy rises counted.
    integer busy_rises = 0, busy_fell = 0, laser_rose = 0, laser_fell = 0, step_rises = 0, last_step_rise = 0;
    always @(posedge busy) if (rst_n) busy_rises = busy_rises + 1;
    always @(negedge busy) if (rst_n) busy_fell = cycle;
    always @(posedge laser) if (rst_n) laser_rose = cycle;
    always @(negedge laser) if (rst_n) laser_fell = cycle;
    always @(posedge step_x) if (rst_n) begin
        step_rises = step_rises + 1;
        last_step_rise = cycle;
    end

    // Every byte uart_tx sends, read mid-bit.
    integer tx_bytes = 0;
    reg [7:0] tx_last = 8'h00;
    initial begin : read_tx
        integer i;
        forever begin
            @(negedge tx);
            repeat (BIT + BIT / 2) @(posedge clk);
            for (i = 0; i < 8; i = i + 1) begin
                tx_last[i] = tx;
                repeat (BIT) @(posedge clk);
            end
            tx_bytes = tx_bytes + 1;
        end
    end

    // Sets an input between edges, after edge `at` (the value of cycle when it changes).
    integer at = 0, steps_before = 0;
    initial begin
        repeat (4) @(posedge clk);
        rst_n = 1'b1;
        repeat (100) @(posedge clk);

        send_packet(88'h01_00000064_00000000_FFFF);
        wait (laser);
        repeat (2000) @(posedge clk);
        @(negedge clk) begin lid_open = 1'b1; at = cycle; end
        repeat (10) @(posedge clk);
        check(laser_fell - at, 3, "clocks from the lid opening to the laser off");
        steps_before = step_rises;
        repeat (1000) @(posedge clk);
        check(step_rises > steps_before, 1, "STEP goes on with the lid open");
        check(laser, 0, "laser held off with the lid open");
        @(negedge clk) begin lid_open = 1'b0; at = cycle; end
        repeat (10) @(posedge clk);
        check(laser_rose - at, 3, "clocks from the lid closing to the laser on");

        repeat (2000) @(posedge clk);
        wait (step_x);
        repeat (20) @(posedge clk);
        @(negedge clk) begin estop = 1'b1; at = cycle; end
        repeat (10) @(posedge clk);
        check(busy_fell - at, 2, "clocks from the e-stop to busy low");
        check(step_x, 0, "STEP low after the e-stop");
        check(laser_fell - at, 3, "clocks from the e-stop to the laser off");
        steps_before = step_rises;
        @(negedge clk) estop = 1'b0;
        repeat (12 * BIT) @(posedge clk);
        check(tx_bytes, 1, "bytes sent after the e-stop");
        check(tx_last, 8'h4B, "the halt byte");
        send_packet(88'h01_00000004_00000000_FFFF);
        repeat (2000) @(posedge clk);
        check(busy_rises, 1, "moves run (none after the e-stop)");
        check(step_rises, steps_before, "STEP rises after the e-stop");
        check(tx_bytes, 1, "bytes sent after the packet that followed the e-stop");
        if (failures == 0)
            $display("PASS: laser off 3 clocks after the lid opened, busy and STEP low 2 and the laser 3 after the e-stop, %0s",
                     "halt byte 0x4B, nothing run after it");
        $finish;
    end
endmodule
