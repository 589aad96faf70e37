// First-word-fall-through FIFO on an inferred simple dual-port memory
// (one write port, one registered read port: iCE40 EBR, Xilinx BRAM,
// ECP5 DP16KD). Used as the delay line of each level's D_k rows, which
// wait there for the up chain (sim/docs/streaming.md, "Latency").
//
// The memory's read is one clock deep; two output registers behind it
// keep one word per clock flowing. in_ready depends on registers only,
// so no combinational path crosses the FIFO.
`default_nettype none
module bloom_fifo #(
    parameter W = 63,
    parameter DEPTH = 512
) (
    input wire clk,
    input wire rst,
    input wire in_valid,
    output wire in_ready,
    input wire [W-1:0] in_data,
    output wire out_valid,
    input wire out_ready,
    output wire [W-1:0] out_data
);
    localparam AW = DEPTH > 1 ? $clog2(DEPTH) : 1;
    reg [W-1:0] mem [0:DEPTH-1];
    reg [AW-1:0] wp, rp;
    reg [AW:0] cnt;                  // words in the memory
    reg pend;                        // a read is on its way out of the memory
    reg [W-1:0] rdata;
    reg [W-1:0] q0, q1;              // q0 is the head
    reg [1:0] qn;

    assign in_ready = cnt != DEPTH;
    assign out_valid = qn != 0;
    assign out_data = q0;
    wire push = in_valid && in_ready;
    wire pop = out_valid && out_ready;
    // issue a read when the queue will have room for it
    wire [2:0] after = {1'b0, qn} + pend - pop;
    wire issue = cnt != 0 && after < 2;

    always @(posedge clk) begin
        if (push) mem[wp] <= in_data;
        if (issue) rdata <= mem[rp];
    end

    reg [W-1:0] nq0, nq1;
    reg [1:0] nqn;
    always @(*) begin
        nq0 = q0;
        nq1 = q1;
        nqn = qn;
        if (pop) begin
            nq0 = q1;
            nqn = nqn - 1'b1;
        end
        if (pend) begin
            if (nqn == 0) nq0 = rdata;
            else nq1 = rdata;
            nqn = nqn + 1'b1;
        end
    end

    always @(posedge clk) begin
        if (rst) begin
            wp <= 0;
            rp <= 0;
            cnt <= 0;
            pend <= 1'b0;
            qn <= 0;
        end else begin
            if (push) wp <= (wp == DEPTH - 1) ? {AW{1'b0}} : wp + 1'b1;
            if (issue) rp <= (rp == DEPTH - 1) ? {AW{1'b0}} : rp + 1'b1;
            cnt <= cnt + push - issue;
            pend <= issue;
            q0 <= nq0;
            q1 <= nq1;
            qn <= nqn;
        end
    end
endmodule
`default_nettype wire
