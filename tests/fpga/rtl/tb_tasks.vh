// Shared by the seed 000 testbenches (included inside the module, which declares clk, rx and BIT): a failure count
// with its check, and one 8N1 frame sent as a sender clocked like the FPGA.
    integer failures = 0;
    task check(input integer got, input integer want, input [8*56-1:0] what);
        if (got !== want) begin
            $display("FAIL: %0s: %0d, expected %0d", what, got, want);
            failures = failures + 1;
        end
    endtask

    // One 8N1 frame, the line changed between clock edges (on the falling edge), as a sender clocked like the FPGA.
    task send_byte(input [7:0] b);
        integer i;
        begin
            @(negedge clk) rx = 1'b0;
            repeat (BIT) @(negedge clk);
            for (i = 0; i < 8; i = i + 1) begin
                rx = b[i];
                repeat (BIT) @(negedge clk);
            end
            rx = 1'b1;
            repeat (BIT) @(negedge clk);
        end
    endtask
