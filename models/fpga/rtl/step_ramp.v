// step_gen's trapezoidal ramp (step_gen's RAMP = 1; our option on seed 000 §7.2's proposal of trapezoidal ramps on
// the FPGA): the law of models/fpga/core/step_ramp.hpp, clock for clock, which the event model computes a stretch at
// a time. On every RUN clock:
//   phase += velocity                  (48 bits; its carry out is a dominant step)
//   ACCEL:  2 done > abs_dom at a step   -> DECEL (and the DECEL update)
//           velocity + accel >= cruise   -> velocity = cruise, ramp_steps = done, CRUISE
//           else                         -> velocity += accel
//   CRUISE: abs_dom - done < ramp_steps at a step -> DECEL (and the DECEL update)
//   DECEL:  velocity = max(velocity - accel, start)
// with done the dominant steps made, this clock's included. The other axis steps with a dominant step when
// Bresenham's error (from abs_dom / 2) reaches abs_dom. Each step's STEPs fall PULSE_HIGH clocks after they rose;
// the velocity never exceeds one step per 2 PULSE_HIGH clocks, so a pulse has fallen before the next rises.
//
// The cruise velocity, 2^48 / max(period_dom, 2 PULSE_HIGH), is divided one bit per clock on the 49 clocks after
// `load`, and the registers take the move's start on the next: ready 51 clocks into DIR_WAIT with step_gen's
// single-clock periods (its DIR_SETTLE at least 52), 180 with the sequential divider's (at least 181).
module step_ramp #(
    parameter PULSE_HIGH = 100
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        load,        // one clock: the move's period_dom is in place from this clock on
    input  wire        run,         // a RUN clock
    input  wire [31:0] period_dom,  // the dominant axis' period, clocks
    input  wire [31:0] abs_dom,     // the dominant axis' steps (X on a tie), > 0
    input  wire [31:0] abs_sub,
    input  wire [31:0] start_reg,   // the init packet's start speed, 2^-32 steps per clock
    input  wire [31:0] accel_reg,   // the init packet's acceleration, 2^-48 steps per clock^2
    output wire        rise_dom,    // the dominant axis' STEP rises at this clock
    output wire        rise_sub,    // and the other axis' with it
    output wire        fall,        // the STEPs that rose PULSE_HIGH clocks ago fall at this clock
    output wire        finished     // that fall is the move's last
);
    localparam [1:0]  ACCEL = 2'd0, CRUISE = 2'd1, DECEL = 2'd2;
    localparam [31:0] MIN_PERIOD = 2 * PULSE_HIGH;  // the ramp's steps never come faster

    reg [5:0]  div_left;  // division clocks left
    reg        prepare;   // the registers take the move's start at this clock
    reg [31:0] rem;
    reg [47:0] cruise;    // the quotient, shifted in from the bottom
    reg [47:0] phase, velocity, start_v;
    reg [1:0]  state;
    reg [31:0] done, ramp_steps;
    reg [32:0] error;
    reg        high;      // a pulse is high
    reg [31:0] high_cnt;  // clocks since it rose

    // The division of 2^48: its dividend's one bit comes in on the first of the 49 clocks.
    wire [31:0] divisor = period_dom > MIN_PERIOD ? period_dom : MIN_PERIOD;
    wire [32:0] trial = {rem, div_left == 6'd49};
    wire        fits = trial >= {1'b0, divisor};

    // The start velocity: the register, at most the cruise, at least 1.
    wire [47:0] start_wide = {start_reg, 16'd0};
    wire [47:0] start_held = start_wide < cruise ? start_wide : cruise;
    wire [47:0] start_now = start_held == 48'd0 ? 48'd1 : start_held;

    wire [48:0] sum = {1'b0, phase} + {1'b0, velocity};
    wire [31:0] done_next = done + 32'd1;
    wire [32:0] error_sum = error + {1'b0, abs_sub};
    wire [48:0] v_up = {1'b0, velocity} + {17'd0, accel_reg};
    wire [47:0] v_down = {1'b0, velocity} >= {1'b0, start_v} + {17'd0, accel_reg} ? velocity - {16'd0, accel_reg}
                                                                                  : start_v;
    assign rise_dom = run && sum[48] && done != abs_dom;
    assign rise_sub = rise_dom && error_sum >= {1'b0, abs_dom};
    assign fall = run && high && high_cnt == PULSE_HIGH;
    assign finished = fall && done == abs_dom;

    always @(posedge clk) begin
        prepare <= 1'b0;
        if (rst)
            div_left <= 6'd0;
        else if (load) begin
            rem <= 32'd0;
            div_left <= 6'd49;
        end else if (div_left != 6'd0) begin
            rem <= fits ? trial[31:0] - divisor : trial[31:0];
            cruise <= {cruise[46:0], fits};
            div_left <= div_left - 6'd1;
            prepare <= div_left == 6'd1;
        end
        if (prepare) begin
            start_v <= start_now;
            velocity <= start_now;
            phase <= 48'd0 - start_now;  // the first RUN clock carries
            state <= ACCEL;
            done <= 32'd0;
            ramp_steps <= 32'd0;
            error <= {1'b0, abs_dom >> 1};
            high <= 1'b0;
        end
        if (run) begin
            phase <= sum[47:0];
            if (rise_dom) begin
                done <= done_next;
                error <= rise_sub ? error_sum - {1'b0, abs_dom} : error_sum;
                high <= 1'b1;
                high_cnt <= 32'd1;
            end else if (high) begin
                if (fall) high <= 1'b0;
                high_cnt <= high_cnt + 32'd1;
            end
            case (state)
                ACCEL:
                    if (rise_dom && {done_next, 1'b0} > {1'b0, abs_dom}) begin
                        state <= DECEL;
                        velocity <= v_down;
                    end else if (v_up >= {1'b0, cruise}) begin
                        state <= CRUISE;
                        ramp_steps <= rise_dom ? done_next : done;
                        velocity <= cruise;
                    end else
                        velocity <= v_up[47:0];
                CRUISE:
                    if (rise_dom && abs_dom - done_next < ramp_steps) begin
                        state <= DECEL;
                        velocity <= v_down;
                    end
                default: velocity <= v_down;
            endcase
        end
    end
endmodule
