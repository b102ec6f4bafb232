// Seed 000's FPGA (§5.2.6): uart_rx -> packet_decoder -> step_gen and laser_ctrl; at each fall of busy, uart_tx
// sends the ACK byte 0xAA unless it is still sending the last one (that ACK is dropped: there is no pending flag).
// rst_n is the board's KEY[0], active low, applied synchronously. The DRV8825s' nENBL are held low (enabled): the
// seed's FPGA drives no enable pin. The board's LEDs and seven-segment displays are left out.
//
// PACKET_CRC = 1 adds our packet check (packet_decoder.v): the edge after a crc_error strobe starts the NAK 0x55 if
// uart_tx is free; the edge after a pkt_repeat strobe starts an ACK if uart_tx is free and no move runs (a repeat
// of the move still running is ACKed when busy falls). An ACK and a NAK asked for at the same edge send the ACK, as
// the event model does (models/fpga/top.cpp): uart_tx sends one byte, and a packet left without its NAK is sent again
// after the host's ACK timeout.
//
// ESTOP = 1 adds our e-stop input (fpga.estop, active high): estop_meta samples it, and step_gen's registers are the
// synchroniser's second stage: the edge after estop_meta rises drops STEP and busy and latches halted (laser_ctrl
// follows busy an edge later: three clocks after the input at most). From the edge that sees estop_meta no ACK or
// NAK starts; the edge after halted rises, or the first after that with uart_tx free, starts the halt byte 0x4B.
// All latched until reset. INTERLOCK = 1 adds the lid's input (fpga.interlock, high while open): through two
// flip-flops it holds laser_ctrl's output off. Without them the inputs are read by nothing (tie them low).
//
// QUEUE_DEPTH > 0 (with PACKET_CRC = 1) adds our packet queue (fpga.queue_depth, packet_queue.v) between the decoder
// and step_gen/laser_ctrl, and replaces the ACK and the NAK with the queue's 2-byte status (common/queue_protocol.hpp):
// the edge after a status_req starts its first byte if uart_tx is free and no status is under way, with the values
// the queue's registers hold then (running, free slots; refused since the last status, next number); the second
// byte starts at the edge after uart_tx's busy falls, and a status asked for meanwhile at the edge after that one's.
// With the e-stop no status starts from the edge that sees estop_meta; one under way ends before the halt byte.
module top #(
    parameter CLK_HZ            = 50000000,
    parameter BAUD              = 115200,
    parameter FULL_BIT          = CLK_HZ / BAUD,  // clocks per UART bit (HALF_BIT = FULL_BIT / 2)
    parameter PULSE_HIGH        = 100,
    parameter DIR_SETTLE        = 200,
    parameter FEED_ZERO_PERIOD  = 62500,
    parameter TIMEOUT_CYCLES    = 5000000,
    parameter NUMERATOR_DEFAULT = 18750000,
    parameter EXACT_PERIOD      = 1,
    // 1: the decoder's numerators reach step_gen (what §5.2.6 asks of the final integration); 0: unconnected, as the
    // appendix top.v prints it, so init packets change nothing.
    parameter INIT_WIRED        = 1,
    // 0: step_gen's periods in one clock (the seed); 1: one bit per clock during DIR_WAIT (period_divider.v), for
    // FPGAs without room for the single-cycle division: the pins are the same.
    parameter DIVIDER           = 0,
    // 1: the packet check above (protocol.crc = "crc16"); 0: the seed's packets and ACK alone.
    parameter PACKET_CRC        = 0,
    // > 0: our PWM laser power (fpga.laser_pwm): the PWM period in clocks, each motion packet carrying its high time
    // (packet_decoder.v, laser_ctrl.v); 0: the seed's on/off laser and packets.
    parameter LASER_PWM_PERIOD  = 0,
    parameter ESTOP             = 0,
    parameter INTERLOCK         = 0,
    // 1: our trapezoidal ramp (fpga.ramp = "trapezoidal": step_ramp.v), its start speed and acceleration registers
    // in a 17-byte init packet (packet_decoder.v), with their values until one arrives; 0: the seed's step_gen.
    parameter RAMP               = 0,
    parameter RAMP_ACCEL_DEFAULT = 18014,
    parameter RAMP_START_DEFAULT = 68719,
    // > 0: the packet queue above, of that many packets (1 .. 16); 0: the seed's stop-and-wait on the ACK.
    parameter QUEUE_DEPTH        = 0
) (
    input  wire clk,
    input  wire rst_n,
    input  wire rx,
    input  wire estop,
    input  wire lid_open,
    output wire tx,
    output wire dir_x,
    output wire step_x,
    output wire n_enbl_x,
    output wire dir_y,
    output wire step_y,
    output wire n_enbl_y,
    output wire laser,
    output wire busy
);
    wire rst = ~rst_n;

    wire [7:0]  rx_data;
    wire        rx_valid;
    wire [1:0]  motion;
    wire [4:0]  seq;
    wire [31:0] steps_x, steps_y, numerator_x, numerator_y, ramp_accel, ramp_start;
    wire [15:0] feed_rate, laser_high;
    wire        pkt_valid, cfg_valid, crc_error, pkt_repeat, done;
    wire        tx_busy;
    reg         tx_start, busy_prev;
    reg         tx_nak;  // the byte tx_start sends: NAK 0x55, else ACK 0xAA (held between starts)
    reg         tx_halt;  // the byte tx_start sends is the halt byte 0x4B (the last one)
    reg         estop_meta, halted, halt_sent, lid_meta, lid_sync;
    wire        halt = ESTOP != 0 && (estop_meta || halted);
    wire        halt_byte = ESTOP != 0 && halted && !halt_sent;

    uart_rx #(.FULL_BIT(FULL_BIT), .HALF_BIT(FULL_BIT / 2)) uart_rx_inst (
        .clk(clk), .rst(rst), .rx(rx), .rx_data(rx_data), .rx_valid(rx_valid));

    packet_decoder #(.TIMEOUT_CYCLES(TIMEOUT_CYCLES), .NUMERATOR_DEFAULT(NUMERATOR_DEFAULT),
                     .PACKET_CRC(PACKET_CRC), .LASER_PWM(LASER_PWM_PERIOD != 0), .RAMP(RAMP != 0),
                     .RAMP_ACCEL_DEFAULT(RAMP_ACCEL_DEFAULT), .RAMP_START_DEFAULT(RAMP_START_DEFAULT),
                     .QUEUE(QUEUE)) pkt_dec_inst (
        .clk(clk), .rst(rst), .rx_data(rx_data), .rx_valid(rx_valid), .motion(motion), .seq(seq), .steps_x(steps_x),
        .steps_y(steps_y), .feed_rate(feed_rate), .laser_high(laser_high), .pkt_valid(pkt_valid),
        .numerator_x(numerator_x), .numerator_y(numerator_y), .ramp_accel(ramp_accel), .ramp_start(ramp_start),
        .cfg_valid(cfg_valid), .crc_error(crc_error), .pkt_repeat(pkt_repeat));

    // What step_gen and laser_ctrl take: the decoder's packets, or the queue's moves.
    wire [1:0]  move_motion;
    wire [31:0] move_steps_x, move_steps_y;
    wire [15:0] move_feed_rate, move_laser_high;
    wire        move_valid;
    // The queue's status and strobes (packet_queue.v); status_start: the first byte of a status starts.
    wire        status_req, q_running, q_refusal, q_queued, q_again, q_refused;
    wire [4:0]  q_next_seq, q_free;
    reg  [1:0]  status_tx;  // the status sender: idle, its first byte or its second under way
    reg         status_due, status_refused, status_start;
    reg  [7:0]  status_byte, status_byte1;
    localparam  QUEUE = QUEUE_DEPTH != 0;
    localparam [1:0] STATUS_IDLE = 2'd0, STATUS_BYTE0 = 2'd1, STATUS_BYTE1 = 2'd2;
    generate
        if (QUEUE) begin : queue
            wire [1:0]  q_motion;
            wire [31:0] q_steps_x, q_steps_y;
            wire [15:0] q_feed_rate, q_laser_high;
            wire        q_pkt_valid;
            packet_queue #(.DEPTH(QUEUE_DEPTH), .PWM(LASER_PWM_PERIOD != 0)) packet_queue_inst (
                .clk(clk), .rst(rst), .motion(motion), .seq(seq), .steps_x(steps_x), .steps_y(steps_y),
                .feed_rate(feed_rate), .laser_high(laser_high), .pkt_valid(pkt_valid), .crc_error(crc_error),
                .done(done), .halt(halt), .q_motion(q_motion), .q_steps_x(q_steps_x), .q_steps_y(q_steps_y),
                .q_feed_rate(q_feed_rate), .q_laser_high(q_laser_high), .q_pkt_valid(q_pkt_valid),
                .status_req(status_req), .running(q_running), .next_seq(q_next_seq), .free(q_free),
                .refusal(q_refusal), .queued(q_queued), .again(q_again), .refused(q_refused));
            assign {move_motion, move_steps_x, move_steps_y, move_feed_rate, move_laser_high, move_valid} =
                {q_motion, q_steps_x, q_steps_y, q_feed_rate, q_laser_high, q_pkt_valid};
        end else begin : no_queue
            assign {move_motion, move_steps_x, move_steps_y, move_feed_rate, move_laser_high, move_valid} =
                {motion, steps_x, steps_y, feed_rate, laser_high, pkt_valid};
            assign {status_req, q_running, q_refusal, q_queued, q_again, q_refused, q_next_seq, q_free} = 16'd0;
        end
    endgenerate

    step_gen #(.PULSE_HIGH(PULSE_HIGH), .DIR_SETTLE(DIR_SETTLE), .FEED_ZERO_PERIOD(FEED_ZERO_PERIOD),
               .NUMERATOR_DEFAULT(NUMERATOR_DEFAULT), .EXACT_PERIOD(EXACT_PERIOD), .DIVIDER(DIVIDER), .RAMP(RAMP),
               .RAMP_ACCEL_DEFAULT(RAMP_ACCEL_DEFAULT), .RAMP_START_DEFAULT(RAMP_START_DEFAULT)) step_gen_inst (
        .clk(clk), .rst(rst), .steps_x(move_steps_x), .steps_y(move_steps_y), .feed_rate(move_feed_rate),
        .pkt_valid(move_valid),
        .numerator_x(INIT_WIRED ? numerator_x : 32'd0), .numerator_y(INIT_WIRED ? numerator_y : 32'd0),
        .ramp_accel(INIT_WIRED ? ramp_accel : 32'd0), .ramp_start(INIT_WIRED ? ramp_start : 32'd0),
        .cfg_valid(INIT_WIRED ? cfg_valid : 1'b0), .halt(halt), .dir_x(dir_x), .step_x(step_x), .dir_y(dir_y),
        .step_y(step_y), .busy(busy), .done(done));

    laser_ctrl #(.PWM_PERIOD(LASER_PWM_PERIOD)) laser_ctrl_inst (
        .clk(clk), .rst(rst), .motion(move_motion), .laser_high(move_laser_high), .pkt_valid(move_valid), .busy(busy),
        .inhibit(INTERLOCK != 0 && lid_sync), .laser(laser));

    uart_tx #(.FULL_BIT(FULL_BIT)) uart_tx_inst (
        .clk(clk), .rst(rst), .tx_data(tx_halt ? 8'h4B : QUEUE ? status_byte : tx_nak ? 8'h55 : 8'hAA), .tx_start(tx_start),
        .tx_busy(tx_busy), .tx(tx));

    // busy fell at the last edge, or (with the check) a move that has run came again; a packet failed its CRC.
    wire ack = !halt && !QUEUE && ((busy_prev && !busy) || (PACKET_CRC != 0 && pkt_repeat && !busy));
    wire nak = !halt && !QUEUE && PACKET_CRC != 0 && crc_error;
    // uart_tx takes a byte: it is idle and no start is on its way (tx_busy rises the edge after tx_start).
    wire tx_free = !tx_busy && !tx_start;
    wire status_now = QUEUE && !halt && tx_free && status_tx != STATUS_BYTE0 && (status_due || status_req);

    always @(posedge clk) begin
        if (rst) begin
            tx_start <= 1'b0;
            busy_prev <= 1'b0;
            tx_nak <= 1'b0;
            tx_halt <= 1'b0;
            {estop_meta, halted, halt_sent, lid_meta, lid_sync} <= 5'd0;
            if (QUEUE) begin
                {status_tx, status_due, status_refused, status_start} <= 5'd0;
                {status_byte, status_byte1} <= 16'd0;
            end
        end else begin
            tx_start <= 1'b0;
            busy_prev <= busy;
            estop_meta <= estop;
            halted <= halted || estop_meta;
            lid_meta <= lid_open;
            lid_sync <= lid_meta;
            if ((ack || nak) && !tx_busy) begin
                tx_start <= 1'b1;
                tx_nak <= nak && !ack;  // written so, not !ack, for synthesis to see it stay 0 without the check
            end
            if (QUEUE) begin
                status_start <= status_now;
                status_refused <= (status_refused && !status_now) || q_refusal;
                status_due <= (status_due || status_req) && !status_now;
                if (status_now) begin
                    tx_start <= 1'b1;
                    status_byte <= {2'b11, q_running, q_free};
                    status_byte1 <= {2'b10, status_refused, q_next_seq};
                    status_tx <= STATUS_BYTE0;
                end else if (status_tx == STATUS_BYTE0 && tx_free) begin
                    tx_start <= 1'b1;
                    status_byte <= status_byte1;
                    status_tx <= STATUS_BYTE1;
                end else if (status_tx == STATUS_BYTE1 && tx_free)
                    status_tx <= STATUS_IDLE;
            end
            if (halt_byte && !tx_busy && (!QUEUE || (!tx_start && status_tx != STATUS_BYTE0))) begin  // never with an ACK or a NAK: halt is high
                tx_start <= 1'b1;
                tx_nak <= 1'b0;
                tx_halt <= 1'b1;
                halt_sent <= 1'b1;
            end
        end
    end

    assign n_enbl_x = 1'b0;
    assign n_enbl_y = 1'b0;
endmodule
