// Icarus bench: the second, four-state simulator. One case per run
// (+case=PREFIX, files from gen_vectors.c): streams the frames back to
// back through bloom_top with random valid gaps and back-pressure,
// compares every output pixel with the C library's, and fails if an X or
// Z reaches the outputs (the handshakes on every clock after reset; tdata,
// tuser and tlast whenever tvalid is high). Nothing in the block is
// initialised but by its reset.
`timescale 1ns / 1ps
`default_nettype none
module tb_icarus;
    parameter FMT888 = 1;
    parameter WMAX = 64;
    parameter HMAX = 64;
    parameter LMAX = 5;
    parameter KNEE_II = 1;
    parameter MAXPX = 3 * 64 * 64;
    localparam PW = FMT888 ? 24 : 16;

    reg clk = 0, rst = 1;
    reg reg_we = 0;
    reg [2:0] reg_addr = 0;
    reg [31:0] reg_wdata = 0;
    wire [31:0] reg_rdata;
    reg [PW-1:0] s_tdata = 0, c_tdata = 0;
    reg s_tvalid = 0, s_tuser = 0, s_tlast = 0, c_tvalid = 0, c_tuser = 0, c_tlast = 0, m_tready = 0;
    wire s_tready, c_tready, m_tvalid, m_tuser, m_tlast;
    wire [PW-1:0] m_tdata;

    bloom_top #(.WMAX(WMAX), .HMAX(HMAX), .LMAX(LMAX), .FMT888(FMT888), .KNEE_II(KNEE_II)) dut (
        .clk(clk), .rst(rst), .reg_we(reg_we), .reg_addr(reg_addr), .reg_wdata(reg_wdata), .reg_rdata(reg_rdata),
        .s_tdata(s_tdata), .s_tvalid(s_tvalid), .s_tready(s_tready), .s_tuser(s_tuser), .s_tlast(s_tlast),
        .c_tdata(c_tdata), .c_tvalid(c_tvalid), .c_tready(c_tready), .c_tuser(c_tuser), .c_tlast(c_tlast),
        .m_tdata(m_tdata), .m_tvalid(m_tvalid), .m_tready(m_tready), .m_tuser(m_tuser), .m_tlast(m_tlast));

    reg [31:0] cfg [0:11];
    reg [31:0] vin [0:MAXPX-1];
    reg [31:0] vout [0:MAXPX-1];
    reg [8*256-1:0] prefix;
    integer w, h, frames, npx, gap, bp, seed;
    integer sp, cp, mp, diffs, xs, framing, clocks, idle;
    reg s_go, c_go, m_go;

    always #5 clk = ~clk;

    task wr(input [2:0] a, input [31:0] v);
        begin
            @(negedge clk);
            reg_we = 1;
            reg_addr = a;
            reg_wdata = v;
            @(negedge clk);
            reg_we = 0;
        end
    endtask

    initial begin
        if (!$value$plusargs("case=%s", prefix)) begin
            $display("FAIL: no +case=PREFIX");
            $finish;
        end
        $readmemh({prefix, ".cfg"}, cfg);
        w = cfg[0];
        h = cfg[1];
        frames = cfg[7];
        seed = cfg[8];
        gap = cfg[9];
        bp = cfg[10];
        npx = w * h;
        $readmemh({prefix, ".in"}, vin, 0, frames * npx - 1);
        $readmemh({prefix, ".out"}, vout, 0, frames * npx - 1);
        repeat (3) @(negedge clk);
        rst = 0;
        wr(0, cfg[6]);
        wr(1, w);
        wr(2, h);
        wr(3, cfg[2]);
        wr(4, cfg[3]);
        wr(5, cfg[4]);
        wr(6, cfg[5]);
        reg_addr = 3;
        #1;
        if (reg_rdata[20:16] !== cfg[11][4:0]) begin
            $display("FAIL %0s: the block builds %0d levels, the C engine %0d", prefix, reg_rdata[20:16], cfg[11]);
            $finish;
        end
        sp = 0;
        cp = 0;
        mp = 0;
        diffs = 0;
        xs = 0;
        framing = 0;
        clocks = 0;
        idle = 0;
        while (mp < frames * npx && idle < 100000) begin
            // drive on the falling edge, sample on the rising one
            @(negedge clk);
            if (!s_tvalid) begin // a new pixel, or a gap; a pixel offered stays until taken
                s_tvalid = sp < frames * npx && ($random(seed) & 127) >= gap;
                s_tdata = vin[sp];
                s_tuser = sp % npx == 0;
                s_tlast = sp % w == w - 1;
            end
            if (!c_tvalid) begin
                c_tvalid = cp < frames * npx && ($random(seed) & 127) >= gap;
                c_tdata = vin[cp];
                c_tuser = cp % npx == 0;
                c_tlast = cp % w == w - 1;
            end
            m_tready = ($random(seed) & 127) >= bp;
            #1;
            if (^{s_tready, c_tready, m_tvalid} === 1'bx) xs = xs + 1;
            if (m_tvalid === 1'b1 && ^{m_tdata, m_tuser, m_tlast} === 1'bx) xs = xs + 1;
            s_go = s_tvalid && s_tready === 1'b1;
            c_go = c_tvalid && c_tready === 1'b1;
            m_go = m_tvalid === 1'b1 && m_tready;
            if (m_go) begin
                if (m_tdata !== vout[mp][PW-1:0]) begin
                    if (diffs < 5)
                        $display("  %0s: pixel %0d: got %h want %h", prefix, mp, m_tdata, vout[mp][PW-1:0]);
                    diffs = diffs + 1;
                end
                if (m_tuser !== (mp % npx == 0) || m_tlast !== (mp % w == w - 1)) framing = framing + 1;
            end
            @(posedge clk);
            clocks = clocks + 1;
            idle = m_go ? 0 : idle + 1;
            if (s_go) begin
                sp = sp + 1;
                s_tvalid = 0;
            end
            if (c_go) begin
                cp = cp + 1;
                c_tvalid = 0;
            end
            if (m_go) mp = mp + 1;
        end
        if (mp < frames * npx || diffs || xs || framing)
            $display("FAIL %0s: %0dx%0d L=%0d, %0d frames: %0d of %0d pixels out, %0d differ, %0d with X, %0d framing",
                     prefix, w, h, cfg[11], frames, mp, frames * npx, diffs, xs, framing);
        else
            $display("ok   %0s: %0dx%0d L=%0d, %0d frames, gaps %0d/128, back-pressure %0d/128: %0d clocks, 0 differ, no X",
                     prefix, w, h, cfg[11], frames, gap, bp, clocks);
        $finish;
    end
endmodule
`default_nettype wire
