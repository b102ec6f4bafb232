// Icarus Verilog testbench of our seed 000 RTL with the trapezoidal ramp (top's RAMP = 1; the law is in
// sim/architectures/fpga_uart/README.md "The trapezoidal ramp"): a 17-byte init packet (the default numerators,
// acceleration 2^24 / 2^48 steps per clock^2, start 2^22 / 2^32 steps per clock: one step per 1024 clocks) and two
// moves at F36621 (18,750,000 / 36621 = 512 clocks a step at the cruise), sent bit by bit at 115200 Bd:
//   1. X +100, Y +37: 24 steps up to the cruise in 16,384 clocks, the cruise, and the same down;
//   2. X -4, Y +10: Y dominant, too short for the cruise: it turns round past half its steps.
// The expected clock of every dominant step comes from the velocity's closed form, clock by clock: min(v0 + a i,
// cruise) until the turn at clock c, then max(v_c - a (i - c), v0); a step where the sum of the velocities (from
// 2^48 - v0) passes a multiple of 2^48. The other axis steps at dominant step n when floor((n abs_sub + abs_dom / 2)
// / abs_dom) grows. Each STEP high 100 clocks, the first DIR_SETTLE + 1 clocks after DIR, busy falling 101 clocks
// after the last rise. Prints PASS or FAIL lines (the ctest test matches them).
module step_ramp_tb;
    parameter DIVIDER = 0;       // top's: the seed's single-clock periods, or the sequential divider
    parameter DIR_SETTLE = 200;  // top's
    localparam integer BIT = 434;  // clocks per bit at 50 MHz
    localparam [63:0] ONE = 64'd1 << 48;  // one step in the phase
    localparam [63:0] V0 = 64'd1 << 38;   // the start register 2^22, shifted to the velocity's 48 fraction bits
    localparam [63:0] ACCEL = 64'd1 << 24;
    localparam [63:0] CRUISE = ONE / 512;
    localparam integer MAX_STEPS = 100;
    reg clk = 1'b0;
    reg rst_n = 1'b0;
    reg rx = 1'b1;
    wire tx, dir_x, step_x, n_enbl_x, dir_y, step_y, n_enbl_y, laser, busy;

    top #(.DIVIDER(DIVIDER), .DIR_SETTLE(DIR_SETTLE), .RAMP(1)) dut (
        .clk(clk), .rst_n(rst_n), .rx(rx), .tx(tx), .dir_x(dir_x), .step_x(step_x), .n_enbl_x(n_enbl_x), .dir_y(dir_y),
        .step_y(step_y), .n_enbl_y(n_enbl_y), .laser(laser), .busy(busy));

    always #10 clk = ~clk;  // 50 MHz

    integer cycle = 0;
    always @(posedge clk) cycle <= cycle + 1;

    `include "tb_tasks.vh"

    task send_word(input [31:0] w);
        begin
            send_byte(w[31:24]); send_byte(w[23:16]); send_byte(w[15:8]); send_byte(w[7:0]);
        end
    endtask

    // The rises of each STEP in the move so far (cycles), their high times other than 100, DIR's last change, busy's
    // fall.
    integer x_rise [0:MAX_STEPS - 1];
    integer y_rise [0:MAX_STEPS - 1];
    integer x_count = 0, y_count = 0, bad_high = 0, dir_changed = 0, busy_fell = 0, moves = 0;
    always @(posedge step_x) if (rst_n) begin
        x_rise[x_count] = cycle;
        x_count = x_count + 1;
    end
    always @(posedge step_y) if (rst_n) begin
        y_rise[y_count] = cycle;
        y_count = y_count + 1;
    end
    always @(negedge step_x) if (rst_n && cycle - x_rise[x_count - 1] != 100) bad_high = bad_high + 1;
    always @(negedge step_y) if (rst_n && cycle - y_rise[y_count - 1] != 100) bad_high = bad_high + 1;
    always @(dir_x or dir_y) if (rst_n) dir_changed = cycle;
    always @(negedge busy) if (rst_n) begin
        busy_fell = cycle;
        moves = moves + 1;
    end

    // The expected RUN clocks of the dominant steps (expected[k], from the first RUN clock).
    integer expected [0:MAX_STEPS - 1];
    task expect_steps(input integer abs_dom);
        reg [63:0] sum, v, v_turn;
        integer i, k, turn, ramp_steps;
        begin
            sum = ONE - V0;
            k = 0;
            turn = -1;
            ramp_steps = 0;
            for (i = 0; k < abs_dom; i = i + 1) begin
                if (turn < 0)
                    v = V0 + ACCEL * i < CRUISE ? V0 + ACCEL * i : CRUISE;
                else
                    v = v_turn >= V0 + ACCEL * (i - turn) ? v_turn - ACCEL * (i - turn) : V0;
                sum = sum + v;
                if (sum >= ONE) begin
                    sum = sum - ONE;
                    expected[k] = i;
                    k = k + 1;
                    // Past half the steps while speeding up, or fewer left than the speeding up took.
                    if (turn < 0 && (V0 + ACCEL * i < CRUISE ? 2 * k > abs_dom : abs_dom - k < ramp_steps)) begin
                        turn = i;
                        v_turn = v;
                    end
                end
                if (turn < 0 && V0 + ACCEL * (i + 1) >= CRUISE && ramp_steps == 0) ramp_steps = k;
            end
        end
    endtask

    // One move's pins against the expectation: dom_rise/sub_rise are the dominant and the other axis' rises.
    task check_move(input integer abs_dom, input integer abs_sub, input y_dominant);
        integer k, n, sub_k, run0, dom_count, sub_count, wrong_dom, wrong_sub;
        begin
            expect_steps(abs_dom);
            dom_count = y_dominant ? y_count : x_count;
            sub_count = y_dominant ? x_count : y_count;
            check(dom_count, abs_dom, "dominant steps");
            check(sub_count, abs_sub, "other axis' steps");
            run0 = y_dominant ? y_rise[0] : x_rise[0];
            check(run0 - dir_changed, DIR_SETTLE + 1, "clocks from DIR to the first STEP");
            wrong_dom = 0;
            wrong_sub = 0;
            sub_k = 0;
            for (k = 0; k < abs_dom && k < dom_count; k = k + 1) begin
                if ((y_dominant ? y_rise[k] : x_rise[k]) - run0 != expected[k]) begin
                    if (wrong_dom == 0)
                        $display("FAIL: dominant step %0d at RUN clock %0d, expected %0d", k,
                                 (y_dominant ? y_rise[k] : x_rise[k]) - run0, expected[k]);
                    wrong_dom = wrong_dom + 1;
                end
                n = k + 1;
                if ((n * abs_sub + abs_dom / 2) / abs_dom > ((n - 1) * abs_sub + abs_dom / 2) / abs_dom) begin
                    if (sub_k >= sub_count || (y_dominant ? x_rise[sub_k] : y_rise[sub_k]) - run0 != expected[k])
                        wrong_sub = wrong_sub + 1;
                    sub_k = sub_k + 1;
                end
            end
            check(wrong_dom, 0, "dominant steps off their clock");
            check(wrong_sub, 0, "other axis' steps off Bresenham's");
            check(busy_fell - (y_dominant ? y_rise[abs_dom - 1] : x_rise[abs_dom - 1]), 101,
                  "clocks from the last rise to busy's fall");
        end
    endtask

    // A design whose ramp never ends its move fails instead of running on (the whole bench takes about 5 ms).
    initial begin
        #20_000_000;
        $display("FAIL: not done after 20 ms");
        $finish;
    end

    integer run_clocks;
    initial begin
        repeat (4) @(posedge clk);
        rst_n = 1'b1;
        repeat (100) @(posedge clk);

        send_byte(8'hFF);
        send_word(32'd18750000);
        send_word(32'd18750000);
        send_word(ACCEL[31:0]);
        send_word(32'd1 << 22);

        send_byte(8'h01);
        send_word(32'd100);
        send_word(32'd37);
        send_byte(8'h8F); send_byte(8'h0D);  // 36621
        wait (moves == 1);
        repeat (10) @(posedge clk);
        check_move(100, 37, 1'b0);
        run_clocks = expected[99] + 101;

        x_count = 0;
        y_count = 0;
        send_byte(8'h01);
        send_word(-32'sd4);
        send_word(32'd10);
        send_byte(8'h8F); send_byte(8'h0D);
        wait (moves == 2);
        repeat (10) @(posedge clk);
        check_move(10, 4, 1'b1);

        check(bad_high, 0, "STEP pulses other than 100 clocks");
        if (failures == 0)
            $display("PASS: X 100 and Y 37 steps on their clocks over %0d RUN clocks; Y 10 and X 4, turning at %0d",
                     run_clocks, expected[5]);
        $finish;
    end
endmodule
