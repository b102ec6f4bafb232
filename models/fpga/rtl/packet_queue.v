// Packet queue (top.v's QUEUE_DEPTH > 0; our option on seed 000 §7.2's command queue and FIFO packet buffer,
// fpga.queue_depth; the frame and the rules in models/common/queue_protocol.hpp and
// sim/architectures/fpga_uart/README.md). Between packet_decoder and step_gen: numbered motion packets are taken in
// order, at most DEPTH waiting, each once. A packet the decoder completes at edge k is judged at k+1: the number
// expected next is queued if a slot is free; one up to 16 behind it was queued already (the host lost its status)
// and is answered again; anything else is refused. The oldest queued move goes to step_gen with a one-clock
// q_pkt_valid at the first edge step_gen takes it: at once when no move runs (the packet judged at k+1 is handed over
// there), else at the edge busy falls (step_gen's done: it is IDLE at the next one), so that queued moves run back to
// back. Every packet judged, every CRC error and every busy fall asks for a status (status_req, one clock). With halt
// (the e-stop) nothing more is handed over or answered; packets are still judged.
module packet_queue #(
    parameter DEPTH = 4,  // 1 .. 16
    parameter PWM   = 0   // 1: the laser's PWM high time is queued with each move
) (
    input  wire        clk,
    input  wire        rst,
    input  wire [1:0]  motion,
    input  wire [4:0]  seq,
    input  wire [31:0] steps_x,
    input  wire [31:0] steps_y,
    input  wire [15:0] feed_rate,
    input  wire [15:0] laser_high,
    input  wire        pkt_valid,
    input  wire        crc_error,
    input  wire        done,  // step_gen is in DONE: busy falls at this edge
    input  wire        halt,
    output reg  [1:0]  q_motion,
    output reg  [31:0] q_steps_x,
    output reg  [31:0] q_steps_y,
    output reg  [15:0] q_feed_rate,
    output reg  [15:0] q_laser_high,
    output reg         q_pkt_valid,
    output reg         status_req,
    output reg         running,   // a move handed to step_gen has not ended
    output reg  [4:0]  next_seq,  // the number of the next packet taken
    output wire [4:0]  free,      // slots free
    output wire        refusal,   // the packet or CRC error judged at this edge is answered as refused
    output reg         queued,    // one-clock strobes: a packet queued, answered again, refused
    output reg         again,
    output reg         refused
);
    localparam WIDTH = PWM != 0 ? 98 : 82;  // motion, steps X and Y, feed (and the PWM high time)
    reg [WIDTH-1:0] slot [0:DEPTH-1];
    reg [3:0] wr, rd;
    reg [4:0] count;

    wire [4:0]       ahead = seq - next_seq;  // modulo 32
    wire             take = pkt_valid && ahead == 5'd0 && count < DEPTH;
    wire             behind = pkt_valid && !take && ahead >= 5'd16;  // a window of at most 16: behind and ahead apart
    wire [WIDTH-1:0] incoming = PWM != 0 ? {laser_high, feed_rate, steps_y, steps_x, motion}
                                         : {feed_rate, steps_y, steps_x, motion};
    // After a busy fall the oldest queued move, or the one judged now when none waits; with no move running only
    // the one judged now can be (no move runs while one waits).
    wire             hand = !halt && (done || !running) && (count != 5'd0 || take);
    wire [WIDTH-1:0] handed = count != 5'd0 ? slot[rd] : incoming;

    assign free = DEPTH - count;
    assign refusal = !halt && ((pkt_valid && !take && !behind) || crc_error);

    function [3:0] after;  // the slot after i, round the ring
        input [3:0] i;
        after = i == DEPTH - 1 ? 4'd0 : i + 4'd1;
    endfunction

    always @(posedge clk) begin
        if (rst) begin
            {q_motion, q_steps_x, q_steps_y, q_feed_rate, q_laser_high} <= 98'd0;
            {q_pkt_valid, status_req, running, queued, again, refused} <= 6'd0;
            next_seq <= 5'd0;
            wr <= 4'd0;
            rd <= 4'd0;
            count <= 5'd0;
        end else begin
            q_pkt_valid <= 1'b0;
            status_req <= !halt && (pkt_valid || crc_error || done);
            queued <= take;
            again <= behind;
            refused <= pkt_valid && !take && !behind;
            if (take) begin  // written even when handed over at once: rd steps past it then
                slot[wr] <= incoming;
                wr <= after(wr);
                next_seq <= next_seq + 5'd1;
            end
            if (hand) begin
                q_motion <= handed[1:0];
                q_steps_x <= handed[33:2];
                q_steps_y <= handed[65:34];
                q_feed_rate <= handed[81:66];
                if (PWM != 0) q_laser_high <= handed[WIDTH-1:WIDTH-16];
                q_pkt_valid <= 1'b1;
                rd <= after(rd);
                running <= 1'b1;
            end else if (done)
                running <= 1'b0;
            count <= count + {4'd0, take} - {4'd0, hand};
        end
    end
endmodule
