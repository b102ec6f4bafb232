// Laser enable (seed 000 §5.2.5, the fixed version): the packet's motion code is latched on the clock step_gen sees
// pkt_valid (G0 off; G1, G2, G3 on), and the laser is on while step_gen is busy, one clock behind busy.
module laser_ctrl (
    input  wire       clk,
    input  wire       rst,
    input  wire [1:0] motion,
    input  wire       pkt_valid,
    input  wire       busy,
    output reg        laser
);
    reg engrave;

    always @(posedge clk) begin
        if (rst) begin
            engrave <= 1'b0;
            laser <= 1'b0;
        end else begin
            if (pkt_valid) engrave <= motion != 2'd0;
            laser <= engrave & busy;
        end
    end
endmodule
