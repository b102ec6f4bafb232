// period_divider (models/fpga/rtl) against Verilog's own / and * on 64 bits: edge operands (feed 1 and 65535,
// steps 1 and 2^31, a product past 2^32, a quotient past 2^32 - 1) and 2000 pseudo-random ones, for both
// arithmetics (EXACT_PERIOD 1: 64-bit product, quotient saturated; 0: product wrapped at 32 bits). Also that done
// comes 129 clocks after start (97 wrapped), inside DIR_WAIT's 200. Prints PASS or FAIL lines.
module period_divider_tb;
    reg clk = 1'b0;
    always #10 clk = ~clk;

    reg         start = 1'b0;
    reg  [31:0] num_dom, abs_dom, abs_sub;
    reg  [15:0] feed;
    wire [31:0] per_step_exact, sub_exact, per_step_wrap, sub_wrap;
    wire        done_exact, done_wrap;

    period_divider #(.EXACT_PERIOD(1)) exact (
        .clk(clk), .start(start), .num_dom(num_dom), .feed(feed), .abs_dom(abs_dom), .abs_sub(abs_sub),
        .per_step(per_step_exact), .sub_period(sub_exact), .done(done_exact));
    period_divider #(.EXACT_PERIOD(0)) wrap (
        .clk(clk), .start(start), .num_dom(num_dom), .feed(feed), .abs_dom(abs_dom), .abs_sub(abs_sub),
        .per_step(per_step_wrap), .sub_period(sub_wrap), .done(done_wrap));

    integer failures = 0, vectors = 0, clocks_exact = 0, clocks_wrap = 0;
    reg [31:0] want_per_step, want_wrap;
    reg [63:0] want_exact;

    task run(input [31:0] n, input [15:0] f, input [31:0] dom, input [31:0] sub);
        integer c;
        begin
            num_dom = n;
            feed = f;
            abs_dom = dom;
            abs_sub = sub;
            want_per_step = n / f;
            want_exact = ({32'd0, want_per_step} * {32'd0, dom}) / {32'd0, sub};
            want_wrap = (want_per_step * dom) / sub;
            @(negedge clk) start = 1'b1;
            @(negedge clk) start = 1'b0;
            c = 1;
            clocks_exact = 0;
            clocks_wrap = 0;
            while (clocks_exact == 0 || clocks_wrap == 0) begin
                @(negedge clk);
                c = c + 1;
                if (done_wrap && clocks_wrap == 0) clocks_wrap = c;
                if (done_exact && clocks_exact == 0) clocks_exact = c;
            end
            vectors = vectors + 1;
            if (per_step_exact !== want_per_step || per_step_wrap !== want_per_step) begin
                $display("FAIL: %0d / %0d: %0d and %0d, expected %0d", n, f, per_step_exact, per_step_wrap,
                         want_per_step);
                failures = failures + 1;
            end
            if (sub_exact !== (want_exact[63:32] != 0 ? 32'hFFFFFFFF : want_exact[31:0])) begin
                $display("FAIL: exact (%0d / %0d) x %0d / %0d: %0d, expected %0d", n, f, dom, sub, sub_exact,
                         want_exact);
                failures = failures + 1;
            end
            if (sub_wrap !== want_wrap) begin
                $display("FAIL: wrapped (%0d / %0d) x %0d / %0d: %0d, expected %0d", n, f, dom, sub, sub_wrap,
                         want_wrap);
                failures = failures + 1;
            end
            if (clocks_exact != 129 || clocks_wrap != 97) begin
                $display("FAIL: done %0d and %0d clocks after start, expected 129 and 97", clocks_exact, clocks_wrap);
                failures = failures + 1;
            end
        end
    endtask

    integer i;
    reg [31:0] lfsr = 32'hACE1_2468;
    function [31:0] next(input [31:0] x);  // Galois LFSR, x^32 + x^22 + x^2 + x + 1
        next = x[0] ? (x >> 1) ^ 32'h8020_0003 : x >> 1;
    endfunction

    initial begin
        run(18750000, 1200, 320, 160);         // the seed's worked example: 15625, 31250
        run(18750000, 1, 73600, 1);            // feed 1: a product far past 2^32, quotient saturated when exact
        run(18750000, 100, 73600, 36800);      // product 1.38e10 (the overflow the seed's text does not have)
        run(32'hFFFFFFFF, 16'hFFFF, 32'h80000000, 32'h7FFFFFFF);
        run(32'hFFFFFFFF, 1, 32'hFFFFFFFF, 1);
        run(300, 65535, 5, 3);                 // num below feed: period 0
        run(300000, 1000, 20, 10);
        for (i = 0; i < 2000; i = i + 1) begin
            lfsr = next(lfsr);
            num_dom = lfsr;
            lfsr = next(lfsr);
            feed = lfsr[15:0] == 0 ? 16'd1 : lfsr[15:0];
            lfsr = next(lfsr);
            abs_dom = lfsr >> (lfsr[4:0]);
            lfsr = next(lfsr);
            abs_sub = (lfsr >> (lfsr[4:0])) == 0 ? 32'd1 : lfsr >> (lfsr[4:0]);
            run(num_dom, feed, abs_dom, abs_sub);
        end
        if (failures == 0) $display("PASS: %0d operand sets, both arithmetics, done after 129 and 97 clocks", vectors);
        $finish;
    end
endmodule
