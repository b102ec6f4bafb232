// Laser enable (seed 000 §5.2.5, the fixed version): the packet's motion code is latched on the clock step_gen sees
// pkt_valid (G0 off; G1, G2, G3 on), and the laser is on while step_gen is busy, one clock behind busy.
//
// PWM_PERIOD > 0 adds our PWM laser power (seed 000 §7.2 proposes it; sim/architectures/fpga_uart/README.md has the
// protocol): the packet's high time is latched with the motion code, a count of the clock restarts at 0 there, counts
// while step_gen is busy (an idle FPGA stays at rest) and wraps at PWM_PERIOD - 1, and the laser is also gated by
// count < high: a duty of high / PWM_PERIOD.
//
// inhibit, our interlock (top.v's INTERLOCK: the lid's synchronised input, low without it), holds the laser off.
module laser_ctrl #(
    parameter PWM_PERIOD = 0  // clocks; 0: the seed's on/off laser
) (
    input  wire        clk,
    input  wire        rst,
    input  wire [1:0]  motion,
    input  wire [15:0] laser_high,
    input  wire        pkt_valid,
    input  wire        busy,
    input  wire        inhibit,
    output reg         laser
);
    localparam [15:0] COUNT_LAST = PWM_PERIOD - 1;
    reg        engrave;
    reg [15:0] high;
    reg [15:0] count;
    wire       pwm_on = PWM_PERIOD == 0 || count < high;

    always @(posedge clk) begin
        if (rst) begin
            engrave <= 1'b0;
            high <= 16'd0;
            count <= 16'd0;
            laser <= 1'b0;
        end else begin
            if (pkt_valid) begin
                engrave <= motion != 2'd0;
                high <= laser_high;
            end
            if (pkt_valid)
                count <= 16'd0;
            else if (busy)
                count <= count == COUNT_LAST ? 16'd0 : count + 16'd1;
            laser <= engrave & busy & pwm_on & !inhibit;
        end
    end
endmodule
