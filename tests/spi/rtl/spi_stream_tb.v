// Icarus Verilog testbench that plays an SPI input waveform into our seed 004 RTL (models/fpga/rtl/spi_fpga_top.v)
// and writes every change of its output pins, for the edge-for-edge comparison with the event model
// (tests/spi/spi_rtl_icarus_test.cpp).
//   +in=FILE   the input changes, one "t_ps pin level" per line in time order, pin 0 = ss, 1 = sclk, 2 = mosi
//              (idle levels before the first: ss high, sclk and mosi low)
//   +out=FILE  written: "pin edge level" per output change, edge n being the clock edge at n x CLK_PS; the levels
//              after reset are written first, as edge 0
//   +edges=N   the last edge to run
// The design is reset over RESET_EDGES edges up to edge 0 (the model's edge 0 at time 0, before its first sample
// at edge 1); the waveform's times are shifted by as much. A change is driven with a non-blocking assignment, so an
// edge at the same instant samples the level before it, as the model's synchroniser takes only the changes strictly
// before an edge. The design's parameters are this module's, set with iverilog -P.
`timescale 1ps / 1ps
module spi_stream_tb;
    parameter CLK_PS       = 20000;  // 50 MHz
    parameter FIFO_DEPTH   = 4;
    parameter PULSE_CYCLES = 100;
    parameter DIR_SETUP    = 50;
    parameter DIR_HOLD     = 50;
    parameter IMMEDIATE    = 0;
    localparam integer RESET_EDGES = 4;

    reg clk = 1'b0;
    reg rst_n = 1'b0;
    reg ss = 1'b1, sclk = 1'b0, mosi = 1'b0;
    wire miso, step_x, dir_x, n_enbl_x, step_y, dir_y, n_enbl_y, laser;

    spi_fpga_top #(.FIFO_DEPTH(FIFO_DEPTH), .PULSE_CYCLES(PULSE_CYCLES), .DIR_SETUP(DIR_SETUP), .DIR_HOLD(DIR_HOLD),
                   .IMMEDIATE(IMMEDIATE)) dut (
        .clk(clk), .rst_n(rst_n), .sclk(sclk), .mosi(mosi), .ss(ss), .miso(miso), .step_x(step_x), .dir_x(dir_x),
        .n_enbl_x(n_enbl_x), .step_y(step_y), .dir_y(dir_y), .n_enbl_y(n_enbl_y), .laser(laser));

    integer edge_n = -RESET_EDGES;  // the last rising edge, counted from the waveform's edge 0
    initial begin
        #CLK_PS;
        forever begin
            clk = 1'b1;
            edge_n = edge_n + 1;
            #(CLK_PS / 2) clk = 1'b0;
            #(CLK_PS - CLK_PS / 2);
        end
    end
    // Reset is sampled at edges up to 0; the design runs from edge 1.
    always @(posedge clk) if (edge_n == 0) rst_n <= 1'b1;

    reg [8*256-1:0] in_file, out_file;
    integer last_edge, in_fd, out_fd, n, pin, level;
    reg [63:0] t_ps;
    initial begin
        if (!$value$plusargs("in=%s", in_file) || !$value$plusargs("out=%s", out_file) ||
            !$value$plusargs("edges=%d", last_edge)) begin
            $display("FAIL: usage +in=FILE +out=FILE +edges=N");
            $finish;
        end
        in_fd = $fopen(in_file, "r");
        out_fd = $fopen(out_file, "w");
        if (in_fd == 0 || out_fd == 0) begin
            $display("FAIL: cannot open the files");
            $finish;
        end
        n = $fscanf(in_fd, "%d %d %d\n", t_ps, pin, level);
        while (n == 3) begin
            #(t_ps + RESET_EDGES * CLK_PS - $time);
            case (pin)
                0: ss <= level[0];
                1: sclk <= level[0];
                2: mosi <= level[0];
                default: $display("FAIL: pin %0d", pin);
            endcase
            n = $fscanf(in_fd, "%d %d %d\n", t_ps, pin, level);
        end
    end

    // Each output's level after every edge, written where it changed (and all of them after edge 0).
    reg [7:0] was;
    wire [7:0] now = {n_enbl_y, n_enbl_x, laser, dir_y, step_y, dir_x, step_x, miso};
    task report(input integer i, input [8*8-1:0] name);
        if (edge_n == 0 || now[i] != was[i]) $fdisplay(out_fd, "%0s %0d %0d", name, edge_n, now[i]);
    endtask
    always @(negedge clk) begin
        if (edge_n >= 0) begin
            report(0, "miso");
            report(1, "step_x");
            report(2, "dir_x");
            report(3, "step_y");
            report(4, "dir_y");
            report(5, "laser");
            report(6, "n_enbl_x");
            report(7, "n_enbl_y");
            was = now;
        end
        if (edge_n == last_edge) begin
            $fclose(out_fd);
            $display("PASS: ran to edge %0d", edge_n);
            $finish;
        end
    end
endmodule
