// Shared by the seed 000 testbenches that read the FPGA's answers (included inside the module, which declares clk,
// rst_n, tx, cycle, BIT and MAX_FRAMES): the frames on tx as the host's UART reads them, the start bit's cycle, then
// the eight data bits mid-bit.
    integer frames = 0;
    integer frame_start [0:MAX_FRAMES - 1];
    reg [7:0] frame_byte [0:MAX_FRAMES - 1];
    always @(negedge tx) if (rst_n) begin : read_frame
        integer i;
        reg [7:0] b;
        frame_start[frames] = cycle;
        repeat (BIT / 2) @(posedge clk);
        for (i = 0; i < 8; i = i + 1) begin
            repeat (BIT) @(posedge clk);
            b[i] = tx;
        end
        frame_byte[frames] = b;
        frames = frames + 1;
        repeat (BIT) @(posedge clk);  // past the stop bit
    end
