// Icarus Verilog testbench of our seed 000 RTL (models/fpga/rtl) on the seed's worked example (§4.9, §5.2.4): the
// motion packet 01 00 00 01 40 FF FF FF 60 04 B0 (G1, X +320, Y -160, F1200) sent bit by bit at 115200 Bd into rx,
// on the default numerators (18,750,000). Expected, from the seed's formulas: X period 18,750,000 / 1200 = 15,625
// clocks, 320 pulses; Y period 15,625 x 320 / 160 = 31,250 clocks, 160 pulses, DIR_Y low; STEP high 100 clocks;
// DIR to the first STEP 201 clocks; busy falls when the last X period is waited out, and the ACK 0xAA starts on tx
// three clocks later (top sees the fall one clock after it and pulses tx_start, uart_tx leaves IDLE on the next
// clock and drives the start bit on the one after). Prints PASS or FAIL lines (the ctest test matches them).
module worked_example_tb;
    parameter DIVIDER = 0;  // top's: the seed's single-clock periods, or the sequential divider
    localparam integer BIT = 434;  // clocks per bit at 50 MHz
    reg clk = 1'b0;
    reg rst_n = 1'b0;
    reg rx = 1'b1;
    wire tx, dir_x, step_x, n_enbl_x, dir_y, step_y, n_enbl_y, laser, busy;

    top #(.DIVIDER(DIVIDER)) dut (.clk(clk), .rst_n(rst_n), .rx(rx), .tx(tx), .dir_x(dir_x), .step_x(step_x), .n_enbl_x(n_enbl_x),
             .dir_y(dir_y), .step_y(step_y), .n_enbl_y(n_enbl_y), .laser(laser), .busy(busy));

    always #10 clk = ~clk;  // 50 MHz

    integer cycle = 0;
    always @(posedge clk) cycle <= cycle + 1;

    `include "tb_tasks.vh"

    // STEP pulses: count, period between rises, high time; DIR when the first STEP rises.
    integer x_rises = 0, x_last_rise = 0, x_period_bad = 0, x_high_bad = 0, x_first_rise = 0;
    integer y_rises = 0, y_last_rise = 0, y_period_bad = 0, y_high_bad = 0;
    integer dir_set = 0;
    // Only after reset: the registers' first values (x to 0) are not edges of the design.
    always @(posedge step_x) if (rst_n) begin
        if (x_rises == 0) x_first_rise = cycle;
        else if (cycle - x_last_rise != 15625) x_period_bad = x_period_bad + 1;
        x_last_rise = cycle;
        x_rises = x_rises + 1;
    end
    always @(negedge step_x) if (rst_n && cycle - x_last_rise != 100) x_high_bad = x_high_bad + 1;
    always @(posedge step_y) if (rst_n) begin
        if (y_rises > 0 && cycle - y_last_rise != 31250) y_period_bad = y_period_bad + 1;
        y_last_rise = cycle;
        y_rises = y_rises + 1;
    end
    always @(negedge step_y) if (rst_n && cycle - y_last_rise != 100) y_high_bad = y_high_bad + 1;
    always @(posedge dir_x) if (rst_n) dir_set = cycle;  // DIR_X rises for the positive X count

    // The ACK as the host's UART reads it: the start bit's middle, then the eight data bits, LSB first.
    integer busy_fell = 0, ack_start = 0;
    reg [7:0] ack = 8'h00;
    always @(negedge busy) if (rst_n) busy_fell = cycle;
    initial begin : read_ack
        integer i;
        @(negedge tx);
        ack_start = cycle;
        repeat (BIT / 2) @(posedge clk);
        for (i = 0; i < 8; i = i + 1) begin
            repeat (BIT) @(posedge clk);
            ack[i] = tx;
        end
    end

    initial begin
        repeat (4) @(posedge clk);
        rst_n = 1'b1;
        repeat (100) @(posedge clk);
        send_byte(8'h01);
        send_byte(8'h00); send_byte(8'h00); send_byte(8'h01); send_byte(8'h40);
        send_byte(8'hFF); send_byte(8'hFF); send_byte(8'hFF); send_byte(8'h60);
        send_byte(8'h04); send_byte(8'hB0);
        wait (busy_fell != 0);
        repeat (20 * BIT) @(posedge clk);
        check(x_rises, 320, "X STEP pulses");
        check(y_rises, 160, "Y STEP pulses");
        check(x_period_bad, 0, "X periods other than 15625 clocks");
        check(y_period_bad, 0, "Y periods other than 31250 clocks");
        check(x_high_bad, 0, "X pulses not 100 clocks high");
        check(y_high_bad, 0, "Y pulses not 100 clocks high");
        check(dir_x, 1, "DIR_X for +320");
        check(dir_y, 0, "DIR_Y for -160");
        check(x_first_rise - dir_set, 201, "clocks from DIR to the first STEP");
        check(busy_fell - x_last_rise, 15625, "clocks from the last X rise to busy falling");
        check(ack, 8'hAA, "ACK byte");
        check(ack_start - busy_fell, 3, "clocks from busy falling to the ACK start bit");
        if (failures == 0)
            $display("PASS: X 320 x 15625 clocks, Y 160 x 31250, STEP high 100, DIR lead 201, ACK 0x%h %0d clocks after busy",
                     ack, ack_start - busy_fell);
        $finish;
    end
endmodule
