// step_gen's periods one bit per clock, for an FPGA without room for the seed's single-cycle 32-bit division and
// product (seed 000 §7.2 names the arithmetic as what stands between the design and a low-cost FPGA): during
// DIR_WAIT's 200 clocks, which the seed spends waiting anyway, it computes
//   per_step   = num_dom / feed                                   (restoring division, 32 clocks)
//   product    = per_step x abs_dom                               (shift and add, 32 clocks)
//   sub_period = product / abs_sub                                (restoring division, 64 clocks; 32 at 32 bits)
// The results, with done, are in place 129 clocks after the clock that takes start (97 with EXACT_PERIOD = 0), the
// quotients the single-clock step_gen gives: the periods are there before RUN, so the pins do not change by a clock.
module period_divider #(
    parameter EXACT_PERIOD = 1  // 0: the product taken at 32 bits, as the appendix step_gen takes it
) (
    input  wire        clk,
    input  wire        start,    // one clock: latch the operands
    input  wire [31:0] num_dom,
    input  wire [15:0] feed,
    input  wire [31:0] abs_dom,
    input  wire [31:0] abs_sub,
    output reg  [31:0] per_step,
    output reg  [31:0] sub_period,
    output reg         done
);
    localparam [2:0] S_IDLE = 3'd0, S_DIV1 = 3'd1, S_MUL = 3'd2, S_DIV2 = 3'd3;
    reg [2:0]  state = S_IDLE;
    reg [6:0]  bits;       // iterations left
    reg [63:0] dividend;   // shifted out from the top, one bit per clock
    reg [63:0] quotient;
    reg [32:0] rem;
    reg [31:0] divisor;
    reg [31:0] mul_a;      // shifted right
    reg [63:0] mul_b;      // shifted left
    reg [63:0] product;
    reg [31:0] dom, sub;

    wire [32:0] trial = {rem[31:0], dividend[63]};
    wire        fits = trial >= {1'b0, divisor};

    always @(posedge clk) begin
        done <= 1'b0;
        case (state)
            S_IDLE:
                if (start) begin
                    dividend <= {num_dom, 32'd0};
                    divisor <= {16'd0, feed};
                    quotient <= 64'd0;
                    rem <= 33'd0;
                    bits <= 7'd32;
                    dom <= abs_dom;
                    sub <= abs_sub;
                    state <= S_DIV1;
                end
            S_DIV1, S_DIV2: begin
                rem <= fits ? trial - {1'b0, divisor} : trial;
                quotient <= {quotient[62:0], fits};
                dividend <= {dividend[62:0], 1'b0};
                bits <= bits - 7'd1;
                if (bits == 7'd1) begin
                    if (state == S_DIV1) begin
                        per_step <= {quotient[30:0], fits};
                        mul_a <= {quotient[30:0], fits};
                        mul_b <= {32'd0, dom};
                        product <= 64'd0;
                        bits <= 7'd32;
                        state <= S_MUL;
                    end else begin
                        sub_period <= EXACT_PERIOD == 0 || quotient[62:31] == 32'd0 ? {quotient[30:0], fits}
                                                                                  : 32'hFFFFFFFF;
                        done <= 1'b1;
                        state <= S_IDLE;
                    end
                end
            end
            S_MUL: begin
                if (mul_a[0]) product <= product + mul_b;
                mul_a <= {1'b0, mul_a[31:1]};
                mul_b <= {mul_b[62:0], 1'b0};
                bits <= bits - 7'd1;
                if (bits == 7'd1) begin
                    // The last partial product joins here; the division starts on the next clock.
                    dividend <= EXACT_PERIOD == 0 ? {(mul_a[0] ? product[31:0] + mul_b[31:0] : product[31:0]), 32'd0}
                                                  : (mul_a[0] ? product + mul_b : product);
                    divisor <= sub;
                    quotient <= 64'd0;
                    rem <= 33'd0;
                    bits <= EXACT_PERIOD == 0 ? 7'd32 : 7'd64;
                    state <= S_DIV2;
                end
            end
            default: state <= S_IDLE;
        endcase
    end
endmodule
