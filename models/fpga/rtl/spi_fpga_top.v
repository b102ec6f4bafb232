// Seed 004's FPGA (§5.1: SPI slave -> FIFO -> pulse generators, an iCE40 HX8K design in MyHDL in the thesis), extended
// as the event model models/fpga/spi/spi_fpga_top.hpp is: two axes (X, Y), a step counter per axis read back in the
// SPI reply, and a laser register fed by the frames' laser bit. Instances are named as the model's blocks.
// rst_n is active low and applied synchronously. All timing is in clocks of `clk` (the model's 50 MHz by default:
// the rate words' periods are in these clocks). nENBL: not in the model nor in the seed's FPGA, which drives no
// enable pin; held low (drivers enabled), as seed 000's top does.
module spi_fpga_top #(
    parameter FIFO_DEPTH   = 4,    // frames, 1..255
    parameter PULSE_CYCLES = 100,  // STEP high, clocks (seed 004 §5.1.3 `duration`)
    parameter DIR_SETUP    = 50,   // clocks, >= 1
    parameter DIR_HOLD     = 50,   // clocks, >= 1
    parameter IMMEDIATE    = 0     // 0: rates apply at the next pulse (the model's default), 1: immediately
) (
    input  wire clk,
    input  wire rst_n,
    input  wire sclk,
    input  wire mosi,
    input  wire ss,  // active low
    output wire miso,
    output wire step_x,
    output wire dir_x,
    output wire n_enbl_x,
    output wire step_y,
    output wire dir_y,
    output wire n_enbl_y,
    output wire laser
);
    wire rst = ~rst_n;

    wire [7:0]  fifo_level;
    wire [31:0] count_x, count_y, word_x, word_y;
    wire        frame_push;
    wire        rd_x, rd_y, readable_x, readable_y, fifo_dir_x, fifo_dir_y, applied, applied_laser;
    wire [29:0] period_x, period_y;

    spi_slave #(.FIFO_DEPTH(FIFO_DEPTH)) spi_slave (
        .clk(clk), .rst(rst), .sclk(sclk), .mosi(mosi), .ss(ss), .miso(miso), .fifo_level(fifo_level),
        .count_x(count_x), .count_y(count_y), .frame_push(frame_push), .word_x(word_x), .word_y(word_y));

    spi_cmd_fifo #(.DEPTH(FIFO_DEPTH)) cmd_fifo (
        .clk(clk), .rst(rst), .push(frame_push), .push_word_x(word_x), .push_word_y(word_y), .level(fifo_level),
        .rd_x(rd_x), .rd_y(rd_y), .readable_x(readable_x), .readable_y(readable_y), .dir_x(fifo_dir_x),
        .period_x(period_x), .dir_y(fifo_dir_y), .period_y(period_y), .applied(applied),
        .applied_laser(applied_laser));

    spi_pulse_gen #(.PULSE_CYCLES(PULSE_CYCLES), .DIR_SETUP(DIR_SETUP), .DIR_HOLD(DIR_HOLD), .IMMEDIATE(IMMEDIATE))
    pulse_gen_x (
        .clk(clk), .rst(rst), .readable(readable_x), .word_dir(fifo_dir_x), .word_period(period_x), .rd(rd_x),
        .step(step_x), .dir(dir_x));

    spi_pulse_gen #(.PULSE_CYCLES(PULSE_CYCLES), .DIR_SETUP(DIR_SETUP), .DIR_HOLD(DIR_HOLD), .IMMEDIATE(IMMEDIATE))
    pulse_gen_y (
        .clk(clk), .rst(rst), .readable(readable_y), .word_dir(fifo_dir_y), .word_period(period_y), .rd(rd_y),
        .step(step_y), .dir(dir_y));

    spi_step_counter step_counter_x (.clk(clk), .rst(rst), .step(step_x), .dir(dir_x), .count(count_x));
    spi_step_counter step_counter_y (.clk(clk), .rst(rst), .step(step_y), .dir(dir_y), .count(count_y));

    spi_laser_latch laser_latch (
        .clk(clk), .rst(rst), .applied(applied), .applied_laser(applied_laser), .laser(laser));

    assign n_enbl_x = 1'b0;
    assign n_enbl_y = 1'b0;
endmodule
