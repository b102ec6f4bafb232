// laser_latch (beyond seed 004, whose FPGA has no laser output; models/fpga/spi/laser_latch.hpp): the register behind
// the `laser` pin, reset low (laser off). It loads a frame's laser bit (bit 30 of the X rate word,
// models/spi/README.md) at the edge cmd_fifo reports the frame applied, i.e. when the last axis loads its word of that
// frame, so the laser switches when the frame's rates all govern. Dropped and rejected frames never reach it.
module spi_laser_latch (
    input  wire clk,
    input  wire rst,
    input  wire applied,
    input  wire applied_laser,
    output reg  laser
);
    always @(posedge clk) begin
        if (rst) laser <= 1'b0;
        else if (applied) laser <= applied_laser;
    end
endmodule
