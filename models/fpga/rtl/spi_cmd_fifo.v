// cmd_fifo of seed 004's FPGA (§5.1.1 FIFO bus): whole rate frames from spi_slave, one read port per axis, an entry
// freed once both axes have read it; register timing as models/fpga/spi/core/cmd_fifo_core.hpp documents it:
//   a frame pushed at edge p is readable from p + 1 (avail_* and level count it from then);
//   level is the frames pushed before this edge and not freed before it (a read at r frees its slot from r + 1);
//   a push while level == DEPTH is dropped: the FIFO keeps its older frames;
//   an axis with nothing to read gets readable_* low (its generator keeps its last rate).
// The read ports are combinational (the word at the axis's read index), so a generator that reads at edge r loads the
// word at r, as the model's generator does. `applied` is high at the edge a read completes a frame (the laser bit of
// that frame on applied_laser): with both axes reading in frame order, at most one frame completes per edge, the
// oldest unfreed one, i.e. the entry of the axis that has the most left to read.
module spi_cmd_fifo #(
    parameter DEPTH = 4  // frames, 1..255
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        push,
    input  wire [31:0] push_word_x,  // rate words as on the wire: bit 31 dir, bit 30 laser (X), 29..0 period
    input  wire [31:0] push_word_y,
    output wire [7:0]  level,
    input  wire        rd_x,
    input  wire        rd_y,
    output wire        readable_x,
    output wire        readable_y,
    output wire        dir_x,
    output wire [29:0] period_x,
    output wire        dir_y,
    output wire [29:0] period_y,
    output wire        applied,
    output wire        applied_laser
);
    reg [30:0] mem_x [0:DEPTH-1];  // {dir, period}
    reg [30:0] mem_y [0:DEPTH-1];
    reg        mem_laser [0:DEPTH-1];
    reg [7:0]  level_r, avail_x, avail_y, wi, rix, riy;

    wire push_ok = push && level_r < DEPTH;
    wire rx_ok = rd_x && avail_x != 8'd0;
    wire ry_ok = rd_y && avail_y != 8'd0;

    assign level = level_r;
    assign readable_x = avail_x != 8'd0;
    assign readable_y = avail_y != 8'd0;
    assign {dir_x, period_x} = mem_x[rix];
    assign {dir_y, period_y} = mem_y[riy];
    // X completes the oldest frame when Y has read it already (less left to read) or reads it at this edge.
    assign applied = (rx_ok && (avail_y < avail_x || (avail_y == avail_x && ry_ok))) ||
                     (ry_ok && avail_x < avail_y);
    assign applied_laser = avail_x >= avail_y ? mem_laser[rix] : mem_laser[riy];

    function [7:0] next_index(input [7:0] i);
        next_index = i == DEPTH - 1 ? 8'd0 : i + 8'd1;
    endfunction

    always @(posedge clk) begin
        if (rst) begin
            level_r <= 8'd0;
            avail_x <= 8'd0;
            avail_y <= 8'd0;
            wi <= 8'd0;
            rix <= 8'd0;
            riy <= 8'd0;
        end else begin
            if (push_ok) begin
                mem_x[wi] <= {push_word_x[31], push_word_x[29:0]};
                mem_y[wi] <= {push_word_y[31], push_word_y[29:0]};  // Y's bit 30 is reserved: not stored
                mem_laser[wi] <= push_word_x[30];
                wi <= next_index(wi);
            end
            if (rx_ok) rix <= next_index(rix);
            if (ry_ok) riy <= next_index(riy);
            level_r <= level_r + {7'd0, push_ok} - {7'd0, applied};
            avail_x <= avail_x + {7'd0, push_ok} - {7'd0, rx_ok};
            avail_y <= avail_y + {7'd0, push_ok} - {7'd0, ry_ok};
        end
    end
endmodule
