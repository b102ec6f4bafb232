// Icarus Verilog testbench that plays an rx waveform into our seed 000 RTL (models/fpga/rtl/top.v) and writes every
// change of its output pins, for the comparison with the cycle-ticked reference (fpga_rtl_icarus_test.cpp).
//   +rx=FILE   the rx line's changes, one "t_ps level" per line, in time order (idle high before the first)
//   +out=FILE  written: "pin edge level" per output change, edge n being the clock edge at n x 20 ns, and every
//              pin's level after reset as edge 0
//   +edges=N   the last edge to run
// The design is reset over RESET_EDGES edges before edge 1; the waveform's times are shifted by as much. A change is
// driven with a non-blocking assignment, so an edge at the same instant samples the level before it, as the
// reference's edges take only the changes strictly before them.
`timescale 1ps / 1ps
module stream_tb;
    parameter DIVIDER = 0;  // top's: the seed's single-clock periods, or the sequential divider
    localparam integer HALF_PS = 10000;  // 50 MHz
    localparam integer RESET_EDGES = 4;
    reg clk = 1'b0;
    reg rst_n = 1'b0;
    reg rx = 1'b1;
    wire tx, dir_x, step_x, n_enbl_x, dir_y, step_y, n_enbl_y, laser, busy;

    top #(.DIVIDER(DIVIDER)) dut (.clk(clk), .rst_n(rst_n), .rx(rx), .tx(tx), .dir_x(dir_x), .step_x(step_x), .n_enbl_x(n_enbl_x),
             .dir_y(dir_y), .step_y(step_y), .n_enbl_y(n_enbl_y), .laser(laser), .busy(busy));

    integer edge_n = -RESET_EDGES;  // the last rising edge, counted from the waveform's edge 1
    initial begin
        #(2 * HALF_PS);
        forever begin
            clk = 1'b1;
            edge_n = edge_n + 1;
            #HALF_PS clk = 1'b0;
            #HALF_PS;
        end
    end
    always @(posedge clk) if (edge_n == 0) rst_n <= 1'b1;

    reg [8*256-1:0] rx_file, out_file;
    integer last_edge, in_fd, out_fd, n, level;
    reg [63:0] t_ps;
    initial begin
        if (!$value$plusargs("rx=%s", rx_file) || !$value$plusargs("out=%s", out_file) ||
            !$value$plusargs("edges=%d", last_edge)) begin
            $display("FAIL: usage +rx=FILE +out=FILE +edges=N");
            $finish;
        end
        in_fd = $fopen(rx_file, "r");
        out_fd = $fopen(out_file, "w");
        n = $fscanf(in_fd, "%d %d\n", t_ps, level);
        while (n == 2) begin
            #(t_ps + (RESET_EDGES + 0) * 2 * HALF_PS - $time);
            rx <= level[0];
            n = $fscanf(in_fd, "%d %d\n", t_ps, level);
        end
    end

    // Each output's level after every edge from edge 1 on, written where it changed.
    reg [6:0] was;
    wire [6:0] now = {busy, laser, step_y, dir_y, step_x, dir_x, tx};
    always @(negedge clk) begin
        if (edge_n == 0) begin
            was = now;
            $fdisplay(out_fd, "tx 0 %0d\ndir_x 0 %0d\nstep_x 0 %0d\ndir_y 0 %0d\nstep_y 0 %0d\nlaser 0 %0d\nbusy 0 %0d",
                      now[0], now[1], now[2], now[3], now[4], now[5], now[6]);
        end
        if (edge_n >= 1) begin
            if (now[0] != was[0]) $fdisplay(out_fd, "tx %0d %0d", edge_n, now[0]);
            if (now[1] != was[1]) $fdisplay(out_fd, "dir_x %0d %0d", edge_n, now[1]);
            if (now[2] != was[2]) $fdisplay(out_fd, "step_x %0d %0d", edge_n, now[2]);
            if (now[3] != was[3]) $fdisplay(out_fd, "dir_y %0d %0d", edge_n, now[3]);
            if (now[4] != was[4]) $fdisplay(out_fd, "step_y %0d %0d", edge_n, now[4]);
            if (now[5] != was[5]) $fdisplay(out_fd, "laser %0d %0d", edge_n, now[5]);
            if (now[6] != was[6]) $fdisplay(out_fd, "busy %0d %0d", edge_n, now[6]);
            was = now;
        end
        if (edge_n == last_edge) begin
            $fclose(out_fd);
            $finish;
        end
    end
endmodule
