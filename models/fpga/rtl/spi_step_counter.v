// step_counter of one axis (not in seed 004; models/fpga/spi/step_counter.hpp): counts the rises of the axis's STEP
// register, +1 with DIR high (forward), -1 with DIR low, in a signed 32-bit register that wraps. It detects a rise
// from the STEP register against its value one edge earlier, so a rise at edge n updates the count at n + 1 (DIR as
// registered at n: setup and hold >= 1 keep it from changing at n), and a register loading the count at edge m (the
// SPI reply) captures every rise at edges <= m - 2 (core/step_count_history.hpp).
module spi_step_counter (
    input  wire        clk,
    input  wire        rst,
    input  wire        step,
    input  wire        dir,
    output reg  [31:0] count
);
    reg step_d;

    always @(posedge clk) begin
        if (rst) begin
            step_d <= 1'b0;  // STEP's reset level
            count <= 32'd0;
        end else begin
            step_d <= step;
            if (step && !step_d) count <= dir ? count + 32'd1 : count - 32'd1;
        end
    end
endmodule
