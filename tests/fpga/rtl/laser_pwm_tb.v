// Icarus Verilog testbench of our seed 000 RTL with the laser's PWM (top's LASER_PWM_PERIOD = 40 clocks; the protocol
// is in sim/architectures/fpga_uart/README.md): 13-byte motion packets, G1 X +4 F1200 (01 00000004 00000000 04B0),
// each followed by its PWM high time, sent bit by bit at 115200 Bd:
//   1. high time 10: the laser rises one clock after busy, every pulse is 10 clocks and the pulses 40 apart, the
//      pin low one clock after busy falls, and the clocks high are those of the count: 10 of every whole 40 of the
//      move's busy clocks, and up to 10 of the rest;
//   2. high time 40 (the whole period): one pulse, from a clock after busy rises to a clock after it falls;
//   3. a rapid (motion 0) with high time 20: the laser stays low.
// Prints PASS or FAIL lines (the ctest test matches them).
module laser_pwm_tb;
    localparam integer BIT = 434;  // clocks per bit at 50 MHz
    localparam integer PERIOD = 40;
    reg clk = 1'b0;
    reg rst_n = 1'b0;
    reg rx = 1'b1;
    wire tx, dir_x, step_x, n_enbl_x, dir_y, step_y, n_enbl_y, laser, busy;

    top #(.LASER_PWM_PERIOD(PERIOD)) dut (.clk(clk), .rst_n(rst_n), .rx(rx), .tx(tx), .dir_x(dir_x), .step_x(step_x),
                                          .n_enbl_x(n_enbl_x), .dir_y(dir_y), .step_y(step_y), .n_enbl_y(n_enbl_y),
                                          .laser(laser), .busy(busy));

    always #10 clk = ~clk;  // 50 MHz

    integer cycle = 0;
    always @(posedge clk) cycle <= cycle + 1;

    `include "tb_tasks.vh"

    // The 13 bytes of a motion packet, most significant first: motion, StepsX, StepsY, FeedRate, LaserHigh.
    task send_motion(input [7:0] b0, input [31:0] sx, input [15:0] high);
        begin
            send_byte(b0);
            send_byte(sx[31:24]); send_byte(sx[23:16]); send_byte(sx[15:8]); send_byte(sx[7:0]);
            send_byte(8'h00); send_byte(8'h00); send_byte(8'h00); send_byte(8'h00);
            send_byte(8'h04); send_byte(8'hB0);
            send_byte(high[15:8]); send_byte(high[7:0]);
        end
    endtask

    // busy's last rise and fall, the laser's pulses since the last clear: their count, the first rise, the last fall,
    // the clocks high, and the pulses of another length than `want_high` or rises another PERIOD apart.
    integer busy_rose = 0, busy_fell = 0, moves = 0;
    integer pulses = 0, first_rise = 0, last_rise = 0, last_fall = 0, on_clocks = 0, bad_length = 0, bad_spacing = 0;
    integer want_high = 0;
    always @(posedge busy) if (rst_n) begin
        busy_rose = cycle;
        moves = moves + 1;
    end
    always @(negedge busy) if (rst_n) busy_fell = cycle;
    always @(posedge laser) if (rst_n) begin
        if (pulses == 0) first_rise = cycle;
        else if (cycle - last_rise != PERIOD) bad_spacing = bad_spacing + 1;
        last_rise = cycle;
        pulses = pulses + 1;
    end
    always @(negedge laser) if (rst_n) begin
        last_fall = cycle;
        on_clocks = on_clocks + (cycle - last_rise);
        if (busy && cycle - last_rise != want_high) bad_length = bad_length + 1;  // the last may be cut by the end
    end

    task clear;
        begin
            pulses = 0; on_clocks = 0; bad_length = 0; bad_spacing = 0;
        end
    endtask

    // The clocks the count allows high in a move busy for n clocks.
    function integer expected_on(input integer n, input integer high);
        expected_on = (n / PERIOD) * high + ((n % PERIOD) < high ? (n % PERIOD) : high);
    endfunction

    integer n;
    initial begin
        repeat (4) @(posedge clk);
        rst_n = 1'b1;
        repeat (100) @(posedge clk);

        want_high = 10;
        send_motion(8'h01, 32'd4, 16'd10);
        wait (moves == 1 && !busy);
        repeat (10) @(posedge clk);
        n = busy_fell - busy_rose;
        check(first_rise - busy_rose, 1, "clocks from busy to the laser (high 10)");
        check(bad_length, 0, "pulses other than 10 clocks");
        check(bad_spacing, 0, "pulses other than 40 clocks apart");
        check(on_clocks, expected_on(n, 10), "clocks high in the move (high 10)");
        check(last_fall <= busy_fell + 1, 1, "laser low a clock after busy (high 10)");
        check(pulses, (n + PERIOD - 1) / PERIOD, "pulses in the move (high 10)");

        clear;
        want_high = 0;
        send_motion(8'h01, 32'd4, 16'd40);
        wait (moves == 2 && !busy);
        repeat (10) @(posedge clk);
        check(pulses, 1, "pulses at the whole period");
        check(first_rise - busy_rose, 1, "clocks from busy to the laser (high 40)");
        check(last_fall - busy_fell, 1, "clocks from busy falling to the laser (high 40)");

        clear;
        send_motion(8'h00, -32'sd8, 16'd20);
        wait (moves == 3 && !busy);
        repeat (10) @(posedge clk);
        check(pulses, 0, "pulses in the rapid");
        if (failures == 0)
            $display("PASS: 10 of 40 clocks high through a %0d-clock move (%0d pulses), held high at 40, low in the rapid",
                     n, (n + PERIOD - 1) / PERIOD);
        $finish;
    end
endmodule
