// SPI mode 0 slave of seed 004's FPGA (§5.1.1, SS active low §5.2), oversampling SCLK with the FPGA clock, as the
// event model models/fpga/spi/spi_slave.hpp and its core (core/spi_slave_core.hpp) describe it:
//   SCLK, MOSI and SS pass two flip-flops (s1, s2); a third register (s3) holds the previous s2, so a pin change that
//   the first flip-flop captures at edge e is acted on at edge e + 2 (kSpiSyncStages), the registered outputs
//   changing there:
//     SS fell               -> FrameStart: bit counter cleared, the reply (status + step counters, as their registers
//                              hold them before this edge) loaded, MISO = reply bit 0 (the status MSB)
//     SCLK rose (s2 SS low) -> MOSI as captured with it shifted in (MSB first)
//     SCLK fell (s2 SS low) -> MISO = the next reply bit (zeros past the reply)
//     SS rose               -> FrameEnd: exactly 72 bits with command byte 0x52 are pushed to cmd_fifo at this edge
//                              (frame_push is combinational, so the FIFO registers it here); any other frame is
//                              rejected; MISO returns low
//   Reset levels of the synchronised pins: SS high, SCLK low, MOSI low (models/fpga/spi/README.md, Decisions).
// Status byte (models/spi/README.md): bit 7 = 1, bit 6 = a frame rejected since the previous reply, bit 5 = a frame
// dropped (FIFO full) since the previous reply, bit 4 = FIFO full, bits 3..0 = FIFO level saturated at 15. The two
// sticky flags are set at the FrameEnd edge and cleared by the FrameStart that reports them.
module spi_slave #(
    parameter FIFO_DEPTH = 4  // frames, 1..255
) (
    input  wire               clk,
    input  wire               rst,  // synchronous, active high
    input  wire               sclk,
    input  wire               mosi,
    input  wire               ss,
    output reg                miso,
    // cmd_fifo status as its registers hold it before the edge
    input  wire [7:0]         fifo_level,
    input  wire [31:0]        count_x,
    input  wire [31:0]        count_y,
    // the frame handed to cmd_fifo at the FrameEnd edge (valid with frame_push)
    output wire               frame_push,
    output wire [31:0]        word_x,
    output wire [31:0]        word_y
);
    localparam [6:0] FRAME_BITS = 7'd72;  // 1 + 4 x 2 bytes
    localparam [7:0] CMD_RATES = 8'h52;

    reg ss_s1, ss_s2, ss_s3, sclk_s1, sclk_s2, sclk_s3, mosi_s1, mosi_s2;
    reg [71:0] rx_sr;   // MOSI bits, the last one in bit 0
    reg [6:0]  bits;    // rising SCLK edges of this frame, saturated at 127
    reg [71:0] tx_sr;   // reply bits not yet on MISO, the next one in bit 71
    reg        rejected_flag, dropped_flag;

    // Edge detection on stage 2 against stage 3; SCLK counts only while stage 2's SS is low (core: `cs & clk_rise`).
    wire ss_fell   = ss_s3 && !ss_s2;
    wire ss_rose   = !ss_s3 && ss_s2;
    wire sclk_rose = !ss_s2 && sclk_s2 && !sclk_s3;
    wire sclk_fell = !ss_s2 && !sclk_s2 && sclk_s3;

    wire              fifo_full = fifo_level >= FIFO_DEPTH;
    wire [3:0]        level_sat = fifo_level > 8'd15 ? 4'd15 : fifo_level[3:0];
    wire [7:0]        status = {1'b1, rejected_flag, dropped_flag, fifo_full, level_sat};
    wire [71:0]       reply = {status, count_x, count_y};

    wire accepted = bits == FRAME_BITS && rx_sr[71:64] == CMD_RATES;
    assign frame_push = ss_rose && accepted;
    assign word_x = rx_sr[63:32];
    assign word_y = rx_sr[31:0];

    // A FrameStart clears the count before a rising SCLK edge seen in the same sample is added (core order).
    wire [6:0] bits_base = ss_fell ? 7'd0 : bits;

    always @(posedge clk) begin
        if (rst) begin
            {ss_s1, ss_s2, ss_s3} <= 3'b111;
            {sclk_s1, sclk_s2, sclk_s3} <= 3'b000;
            {mosi_s1, mosi_s2} <= 2'b00;
            rx_sr <= 72'd0;
            bits <= 7'd0;
            tx_sr <= 72'd0;
            miso <= 1'b0;
            rejected_flag <= 1'b0;
            dropped_flag <= 1'b0;
        end else begin
            ss_s1 <= ss;
            ss_s2 <= ss_s1;
            ss_s3 <= ss_s2;
            sclk_s1 <= sclk;
            sclk_s2 <= sclk_s1;
            sclk_s3 <= sclk_s2;
            mosi_s1 <= mosi;
            mosi_s2 <= mosi_s1;

            bits <= (sclk_rose && bits_base != 7'd127) ? bits_base + 7'd1 : bits_base;
            if (sclk_rose) rx_sr <= {rx_sr[70:0], mosi_s2};

            // MISO: bit 0 of the reply at FrameStart, the next bit at each falling SCLK edge. A falling edge in the
            // same sample as the SS fall puts bit 1 out at once (the core's FrameStart, then its MisoShift).
            if (ss_fell) begin
                rejected_flag <= 1'b0;  // reported in this reply
                dropped_flag <= 1'b0;
                if (sclk_fell) begin
                    miso <= reply[70];
                    tx_sr <= {reply[69:0], 2'b00};
                end else begin
                    miso <= reply[71];
                    tx_sr <= {reply[70:0], 1'b0};
                end
            end else if (sclk_fell) begin
                miso <= tx_sr[71];
                tx_sr <= {tx_sr[70:0], 1'b0};
            end

            if (ss_rose) begin
                miso <= 1'b0;
                if (!accepted) rejected_flag <= 1'b1;
                else if (fifo_full) dropped_flag <= 1'b1;  // cmd_fifo drops it at this edge
            end
        end
    end
endmodule
