// pulse_gen of one axis of seed 004's FPGA (§5.1.3 pulsegen: a pulse of `duration` clocks every period; here the
// period is the rate word, so STEP rises exactly `period` clocks apart) with DIR setup and hold enforced by delaying,
// as models/fpga/spi/core/pulse_gen_core.hpp schedules it. A word loaded at edge a governs from a on (a rise due at
// a is decided by it):
//   period 0 : stopped, no further rise; a pulse in progress completes; DIR keeps its level; a pending DIR change
//              is cancelled;
//   period P : P' = max(P, PULSE_CYCLES + 1) (STEP keeps one low clock); if the direction differs from DIR, DIR
//              changes at d = max(a, last rise + DIR_HOLD); the next rise is at max(a, last DIR change + DIR_SETUP,
//              last rise + spacing), spacing = P' (IMMEDIATE) or PULSE_CYCLES + 1 (at the next pulse).
//   After a rise at R: STEP falls at R + PULSE_CYCLES and rises again at R + P'.
// The absolute edges of the model become counters here: since_rise counts the clocks since the last STEP rise
// (saturated: "none yet"), rise_wait and dir_wait the clocks to the scheduled rise and DIR change, and the margins a
// load needs (hold left, setup left, shortest spacing left) count down from a rise or DIR change to 0, so that a word's
// schedule is a few small comparisons rather than a chain of 32-bit subtractions (a shorter path to the registers).
// rd (combinational) takes the FIFO's word at this edge: IMMEDIATE, whenever one is readable (one per edge);
// otherwise (RateApply::AtNextPulse) only when stopped or at the edge the running period ends (models/fpga/spi/README.md,
// "When a rate applies").
module spi_pulse_gen #(
    parameter PULSE_CYCLES = 100,  // STEP high, clocks (2 us at 50 MHz)
    parameter DIR_SETUP    = 50,   // DIR change -> next STEP rise, clocks, >= 1
    parameter DIR_HOLD     = 50,   // STEP rise -> DIR change, clocks, >= 1
    parameter IMMEDIATE    = 0     // 1: RateApply::Immediately; 0: RateApply::AtNextPulse
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        readable,
    input  wire        word_dir,     // 1 = forward = DIR high
    input  wire [29:0] word_period,  // clocks between STEP rises, 0 = stop
    output wire        rd,
    output reg         step,
    output reg         dir
);
    localparam [31:0] MIN_PERIOD = PULSE_CYCLES + 1;
    localparam [31:0] PULSE = PULSE_CYCLES;
    localparam [31:0] SETUP = DIR_SETUP;
    localparam [31:0] HOLD = DIR_HOLD;
    localparam [31:0] NONE = 32'h7FFFFFFF;  // saturated since_rise: no rise yet, above any spacing

    reg        running;    // a rise is scheduled
    reg [31:0] period;     // P' of the word governing
    reg [31:0] rise_wait;  // clocks from this edge to the scheduled rise (0: it is due at this edge)
    reg        dir_pend;
    reg [31:0] dir_wait;
    reg [31:0] since_rise;  // this edge minus the last rise
    // Margins at this edge: max(0, DIR_HOLD - since_rise), that + DIR_SETUP, max(0, DIR_SETUP - clocks since the last
    // DIR change), max(0, PULSE_CYCLES + 1 - since_rise).
    reg [31:0] hold_left, hold_setup_left, setup_left, space_left;

    wire rise_due = running && rise_wait == 32'd0;
    assign rd = readable && (IMMEDIATE != 0 || !running || rise_due);

    // The word's schedule, from this edge (the model's load()).
    wire [31:0] w_period = {2'b00, word_period};
    wire [31:0] new_period = w_period < MIN_PERIOD ? MIN_PERIOD : w_period;
    wire        reversal = word_dir != dir;
    wire [31:0] t_space = IMMEDIATE == 0 ? space_left
                        : (since_rise >= new_period ? 32'd0 : new_period - since_rise);
    wire [31:0] t_setup = reversal ? hold_setup_left : setup_left;
    wire [31:0] delay = t_space > t_setup ? t_space : t_setup;
    wire        load_run = rd && word_period != 30'd0;

    // delay == 0 without waiting for the subtraction and the maximum: every margin is 0 (a reversal never is: it
    // waits DIR_SETUP >= 1), and with IMMEDIATE the new period has passed since the last rise.
    wire space_zero = space_left == 32'd0 && (IMMEDIATE == 0 || since_rise >= w_period);
    wire delay_zero = space_zero && !reversal && setup_left == 32'd0;
    wire rise_now = load_run ? delay_zero : (!rd && rise_due);
    wire dir_now = load_run ? (reversal && hold_left == 32'd0) : (!rd && dir_pend && dir_wait == 32'd0);
    wire fall_now = step && since_rise == PULSE;

    always @(posedge clk) begin
        if (rst) begin
            running <= 1'b0;
            period <= MIN_PERIOD;
            rise_wait <= 32'd0;
            dir_pend <= 1'b0;
            dir_wait <= 32'd0;
            since_rise <= NONE;
            hold_left <= 32'd0;  // no rise, no DIR change yet
            hold_setup_left <= SETUP;
            setup_left <= 32'd0;
            space_left <= 32'd0;
            step <= 1'b0;
            dir <= 1'b0;  // reset low
        end else begin
            since_rise <= rise_now ? 32'd1 : (since_rise == NONE ? NONE : since_rise + 32'd1);
            if (rise_now) begin
                hold_left <= HOLD - 32'd1;
                hold_setup_left <= HOLD - 32'd1 + SETUP;
                space_left <= MIN_PERIOD - 32'd1;
            end else begin
                if (hold_left != 32'd0) hold_left <= hold_left - 32'd1;
                if (hold_setup_left != SETUP) hold_setup_left <= hold_setup_left - 32'd1;
                if (space_left != 32'd0) space_left <= space_left - 32'd1;
            end
            if (dir_now) setup_left <= SETUP - 32'd1;
            else if (setup_left != 32'd0) setup_left <= setup_left - 32'd1;
            if (rise_now) step <= 1'b1;
            else if (fall_now) step <= 1'b0;
            if (dir_now) dir <= ~dir;

            if (rd) begin
                // A new word cancels the rise and the DIR change it has not reached yet.
                running <= load_run;
                dir_pend <= load_run && reversal && hold_left != 32'd0;
                dir_wait <= hold_left - 32'd1;
                if (load_run) begin
                    period <= new_period;
                    rise_wait <= rise_now ? new_period - 32'd1 : delay - 32'd1;
                end
            end else begin
                if (running) rise_wait <= rise_due ? period - 32'd1 : rise_wait - 32'd1;
                if (dir_pend) begin
                    if (dir_wait == 32'd0) dir_pend <= 1'b0;
                    else dir_wait <= dir_wait - 32'd1;
                end
            end
        end
    end
endmodule
