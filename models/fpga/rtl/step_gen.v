// Step generator (seed 000 §2.4, §5.2.4): a packet's signed step counts and dominant-axis feed become a STEP period
// per axis (the "reference word" family of [1]: a period counter and a remaining-steps counter per axis).
//   IDLE -> SETUP (DIR and |steps|) -> DIR_WAIT (periods, DIR_SETTLE clocks) -> RUN -> DONE (busy falls).
// The dominant axis steps every num/feed clocks; the other every (num/feed) x abs_dom / abs_sub, with the
// dominant axis' numerator (its cycles per step are the time base). STEP rises at the start of each period and
// stays high PULSE_HIGH clocks; RUN lasts abs_dom x period_dom clocks exactly.
// With RAMP = 1 (our trapezoidal ramp, fpga.ramp) RUN steps where step_ramp.v says instead, from the dominant period
// and the init packet's start speed and acceleration; the periods are computed as without it (they set the cruise).
module step_gen #(
    parameter PULSE_HIGH        = 100,       // 2 us at 50 MHz (the DRV8825 needs 1.9 us)
    parameter DIR_SETTLE        = 200,       // 4 us between DIR and the first STEP
    parameter FEED_ZERO_PERIOD  = 62500,     // period for a packet with feed 0 (appendix step_gen)
    parameter NUMERATOR_DEFAULT = 18750000,
    // 0: the subordinate period's product at 32 bits, as the appendix prints it (it wraps past 2^32 - 1);
    // 1: the product at 64 bits, the quotient saturated at 2^32 - 1 (what the text's formula means).
    parameter EXACT_PERIOD      = 1,
    // 0: the periods in one clock, as the seed computes them (two 32-bit dividers and a multiplier); 1: one bit per
    // clock in period_divider during DIR_WAIT, the same periods in place before RUN (DIR_SETTLE must be at least
    // 130: the division takes 129 clocks, 97 with EXACT_PERIOD = 0).
    parameter DIVIDER           = 0,
    // 0: every step at the packet's period (the seed); 1: the trapezoidal ramp of step_ramp.v (DIR_SETTLE must be at
    // least 52: its cruise is divided during DIR_WAIT after the periods; 181 with DIVIDER = 1).
    parameter RAMP               = 0,
    parameter RAMP_ACCEL_DEFAULT = 18014,  // the ramp's registers until an init packet sets them (fpga_config.hpp)
    parameter RAMP_START_DEFAULT = 68719
) (
    input  wire        clk,
    input  wire        rst,
    input  wire [31:0] steps_x,
    input  wire [31:0] steps_y,
    input  wire [15:0] feed_rate,
    input  wire        pkt_valid,
    input  wire [31:0] numerator_x,
    input  wire [31:0] numerator_y,
    input  wire [31:0] ramp_accel,
    input  wire [31:0] ramp_start,
    input  wire        cfg_valid,
    input  wire        halt,  // our e-stop (top.v's ESTOP): held high until reset; tied low without it
    output reg         dir_x,
    output reg         step_x,
    output reg         dir_y,
    output reg         step_y,
    output reg         busy,
    output wire        done  // in DONE: busy falls at this edge (the packet queue hands over the next move there)
);
    localparam [2:0] IDLE = 3'd0, SETUP = 3'd1, DIR_WAIT = 3'd2, RUN = 3'd3, DONE = 3'd4, HALTED = 3'd5;
    reg [2:0]  state;
    reg [31:0] num_x, num_y;
    reg [31:0] abs_x, abs_y, rem_x, rem_y, period_x, period_y, cnt_x, cnt_y;
    reg [8:0]  dir_cnt;
    reg [31:0] accel_reg, start_reg;  // with the ramp
    reg        ramp_load;             // the periods were written at the last edge

    assign done = state == DONE;

    wire [31:0] feed = {16'd0, feed_rate};
    wire        x_dominant = abs_x >= abs_y;
    wire [31:0] per_step = x_dominant ? num_x / feed : num_y / feed;
    wire [31:0] abs_dom = x_dominant ? abs_x : abs_y;
    wire [31:0] abs_sub = x_dominant ? abs_y : abs_x;
    wire [31:0] product32 = per_step * abs_dom;
    wire [63:0] quotient64 = ({32'd0, per_step} * {32'd0, abs_dom}) / {32'd0, abs_sub};
    wire [31:0] sub_period = abs_sub == 32'd0 ? 32'd0
                           : EXACT_PERIOD == 0 ? product32 / abs_sub
                           : (quotient64[63:32] != 32'd0 ? 32'hFFFFFFFF : quotient64[31:0]);
    // The sequential divider's results, and whether they are the periods of this move (not feed 0, not a move of
    // no steps, whose periods DIR_WAIT sets itself).
    wire [31:0] seq_per_step, seq_sub_period;
    wire        seq_done;
    reg         seq_wanted;
    generate
        if (DIVIDER == 1) begin : sequential
            period_divider #(.EXACT_PERIOD(EXACT_PERIOD)) divider (
                .clk(clk), .start(state == DIR_WAIT && dir_cnt == 9'd0), .num_dom(x_dominant ? num_x : num_y),
                .feed(feed_rate), .abs_dom(abs_dom), .abs_sub(abs_sub), .per_step(seq_per_step),
                .sub_period(seq_sub_period), .done(seq_done));
        end else begin : single_cycle
            assign seq_per_step = 32'd0;
            assign seq_sub_period = 32'd0;
            assign seq_done = 1'b0;
        end
    endgenerate

    wire ramp_rise_dom, ramp_rise_sub, ramp_fall, ramp_finished;
    generate
        if (RAMP != 0) begin : ramped
            step_ramp #(.PULSE_HIGH(PULSE_HIGH)) ramp (
                .clk(clk), .rst(rst), .load(ramp_load), .run(state == RUN),
                .period_dom(x_dominant ? period_x : period_y), .abs_dom(abs_dom), .abs_sub(abs_sub),
                .start_reg(start_reg), .accel_reg(accel_reg),
                .rise_dom(ramp_rise_dom), .rise_sub(ramp_rise_sub), .fall(ramp_fall), .finished(ramp_finished));
        end else begin : unramped
            assign {ramp_rise_dom, ramp_rise_sub, ramp_fall, ramp_finished} = 4'd0;
        end
    endgenerate

    wire x_done = (rem_x == 32'd1 && cnt_x == period_x - 32'd1) || rem_x == 32'd0 || period_x == 32'd0;
    wire y_done = (rem_y == 32'd1 && cnt_y == period_y - 32'd1) || rem_y == 32'd0 || period_y == 32'd0;

    always @(posedge clk) begin
        if (rst) begin
            state <= IDLE;
            num_x <= NUMERATOR_DEFAULT;
            num_y <= NUMERATOR_DEFAULT;
            {abs_x, abs_y, rem_x, rem_y, period_x, period_y, cnt_x, cnt_y} <= 256'd0;
            dir_cnt <= 9'd0;
            seq_wanted <= 1'b0;
            accel_reg <= RAMP_ACCEL_DEFAULT;
            start_reg <= RAMP_START_DEFAULT;
            ramp_load <= 1'b0;
            dir_x <= 1'b0;
            dir_y <= 1'b0;
            step_x <= 1'b0;
            step_y <= 1'b0;
            busy <= 1'b0;
        end else if (halt) begin  // STEP and busy fall at the edge that sees it; no init or packet is taken after
            step_x <= 1'b0;
            step_y <= 1'b0;
            busy <= 1'b0;
            state <= HALTED;
        end else begin
            if (cfg_valid && state == IDLE) begin  // an init arriving mid-move is dropped
                num_x <= numerator_x;
                num_y <= numerator_y;
                accel_reg <= ramp_accel;
                start_reg <= ramp_start;
            end
            ramp_load <= 1'b0;
            case (state)
                IDLE: begin
                    step_x <= 1'b0;
                    step_y <= 1'b0;
                    busy <= 1'b0;
                    if (pkt_valid) begin
                        busy <= 1'b1;
                        state <= SETUP;
                    end
                end
                SETUP: begin
                    dir_x <= !steps_x[31];  // zero or positive: DIR high
                    dir_y <= !steps_y[31];
                    abs_x <= steps_x[31] ? ~steps_x + 32'd1 : steps_x;
                    abs_y <= steps_y[31] ? ~steps_y + 32'd1 : steps_y;
                    dir_cnt <= 9'd0;
                    state <= DIR_WAIT;
                end
                DIR_WAIT: begin
                    if (dir_cnt == 9'd0) begin
                        rem_x <= abs_x;
                        rem_y <= abs_y;
                        cnt_x <= 32'd0;
                        cnt_y <= 32'd0;
                        ramp_load <= feed_rate == 16'd0 || DIVIDER != 1;
                        if (feed_rate == 16'd0) begin
                            period_x <= FEED_ZERO_PERIOD;
                            period_y <= FEED_ZERO_PERIOD;
                        end else if (abs_x == 32'd0 && abs_y == 32'd0) begin
                            period_x <= 32'd0;
                            period_y <= 32'd0;
                        end else if (DIVIDER == 1) begin
                            seq_wanted <= 1'b1;
                        end else if (x_dominant) begin
                            period_x <= per_step;
                            period_y <= sub_period;
                        end else begin
                            period_y <= per_step;
                            period_x <= sub_period;
                        end
                    end
                    if (seq_done && seq_wanted) begin
                        seq_wanted <= 1'b0;
                        ramp_load <= 1'b1;
                        period_x <= x_dominant ? seq_per_step : (abs_x == 32'd0 ? 32'd0 : seq_sub_period);
                        period_y <= x_dominant ? (abs_y == 32'd0 ? 32'd0 : seq_sub_period) : seq_per_step;
                    end
                    if (dir_cnt >= DIR_SETTLE - 1) begin
                        dir_cnt <= 9'd0;
                        state <= (abs_x == 32'd0 && abs_y == 32'd0) ? DONE : RUN;
                    end else
                        dir_cnt <= dir_cnt + 9'd1;
                end
                RUN: if (RAMP != 0) begin
                    if (x_dominant ? ramp_rise_dom : ramp_rise_sub) step_x <= 1'b1;
                    else if (ramp_fall) step_x <= 1'b0;
                    if (x_dominant ? ramp_rise_sub : ramp_rise_dom) step_y <= 1'b1;
                    else if (ramp_fall) step_y <= 1'b0;
                    if (ramp_finished) state <= DONE;
                end else begin
                    if (rem_x != 32'd0 && period_x != 32'd0) begin
                        if (cnt_x == 32'd0) step_x <= 1'b1;
                        else if (cnt_x == PULSE_HIGH) step_x <= 1'b0;
                        if (cnt_x >= period_x - 32'd1) begin
                            cnt_x <= 32'd0;
                            rem_x <= rem_x - 32'd1;
                        end else
                            cnt_x <= cnt_x + 32'd1;
                    end else
                        step_x <= 1'b0;
                    if (rem_y != 32'd0 && period_y != 32'd0) begin
                        if (cnt_y == 32'd0) step_y <= 1'b1;
                        else if (cnt_y == PULSE_HIGH) step_y <= 1'b0;
                        if (cnt_y >= period_y - 32'd1) begin
                            cnt_y <= 32'd0;
                            rem_y <= rem_y - 32'd1;
                        end else
                            cnt_y <= cnt_y + 32'd1;
                    end else
                        step_y <= 1'b0;
                    if (x_done && y_done) begin
                        step_x <= 1'b0;
                        step_y <= 1'b0;
                        state <= DONE;
                    end
                end
                DONE: begin
                    busy <= 1'b0;
                    step_x <= 1'b0;
                    step_y <= 1'b0;
                    state <= IDLE;
                end
                default: state <= IDLE;
            endcase
        end
    end
endmodule
