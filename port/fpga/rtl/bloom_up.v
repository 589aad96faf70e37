// Tent up, level k+1 -> level k, and the additive blend U_k = D_k + tent
// (sim/docs/fixed-point.md steps 4 and 5; the C kernel is tent_impl in
// src/kernels/bloom_row.c). With HAS_ADD = 0 it makes B, the full-size
// bloom the composite adds to the source.
//
// The input rows (U_{k+1}, wi x hi, raster order) go into a ring of four
// row banks, bank = global row number & 3. Output row j reads rows m-1,
// m, m+1 (m = j >> 1, clamped to the frame): a "V reader" walks the
// columns n = 0 .. wi-1, reading the same column of every bank in one
// clock, and forms the vertical tent V(n) = (a u0 + 4 u1 + c u2 + 4) >> 3
// with (a, c) = (3, 1) on even rows and (1, 3) on odd ones (half up). The
// V values queue in four registers (a circle); the horizontal side takes two at the
// start of a row and one every other output pixel after, and makes
// T(x) = (a' V(n-1) + 4 V(n) + c' V(n+1) + 3) >> 3, n = x >> 1, (a', c') =
// (3, 1) for even x and (1, 3) for odd x (half down), one pixel per clock.
//
// Widths: U <= 16 * 2^20 for up to 16 levels (UW = 25 bits); the weighted
// sums of eight U reach 2^28 (UW + 3 bits, plus the rounding); D_k adds
// at most 2^20, and U_k stays below 2^25.
//
// A row may be written once the reader no longer needs the row four
// below it; the reader starts a row once its lowest row is complete.
// Frames follow each other without a gap: the rows' global numbers run
// on across frames, and the reader's frame base moves by hi at its end.
`default_nettype none
module bloom_up #(
    parameter UW = 25,     // up-sum bits per channel
    parameter SW = 21,     // bits of the added D_k samples
    parameter XW = 12,
    parameter YW = 12,
    parameter WIMAX = 512, // widest input row
    parameter HAS_ADD = 1
) (
    input wire clk,
    input wire rst,
    input wire [XW-1:0] wi,
    input wire [YW-1:0] hi,
    input wire [XW-1:0] wo,
    input wire [YW-1:0] ho,
    input wire in_valid,
    output wire in_ready,
    input wire [3*UW-1:0] in_data,
    input wire add_valid,
    output wire add_ready,
    input wire [3*SW-1:0] add_data,
    output reg out_valid,
    input wire out_ready,
    output reg [3*UW-1:0] out_data
);
    localparam BA = WIMAX > 1 ? $clog2(WIMAX) : 1;
    localparam GW = 16;                // global row numbers, modulo 2^16

    // ---- writer ------------------------------------------------------
    reg [XW-1:0] wx;
    reg [GW-1:0] wrow;                 // global number of the row being written
    reg [GW-1:0] oldest;               // the reader's lowest row still needed
    wire [GW-1:0] wahead = wrow - oldest;
    assign in_ready = wahead < 4;
    wire push = in_valid && in_ready;
    always @(posedge clk) begin
        if (rst) begin
            wx <= 0;
            wrow <= 0;
        end else if (push) begin
            if (wx == wi - 1'b1) begin
                wx <= 0;
                wrow <= wrow + 1'b1;
            end else
                wx <= wx + 1'b1;
        end
    end

    reg [3*UW-1:0] bk0 [0:WIMAX-1];
    reg [3*UW-1:0] bk1 [0:WIMAX-1];
    reg [3*UW-1:0] bk2 [0:WIMAX-1];
    reg [3*UW-1:0] bk3 [0:WIMAX-1];
    reg [3*UW-1:0] q0, q1, q2, q3;

    // ---- V reader ----------------------------------------------------
    reg [YW-1:0] rj;                   // output row
    reg [XW-1:0] rn;                   // input column
    reg [GW-1:0] rbase;                // global number of the frame's row 0
    wire [YW-1:0] m = rj >> 1;
    wire [YW-1:0] rr0 = (m == 0) ? {YW{1'b0}} : m - 1'b1;
    wire [YW-1:0] rr2 = (m + 1'b1 > hi - 1'b1) ? hi - 1'b1 : m + 1'b1;
    wire [GW-1:0] g0 = rbase + rr0, g1 = rbase + m, g2 = rbase + rr2;
    wire [GW-1:0] have = wrow - g2;    // > 0: row g2 is complete
    wire avail = have != 0 && !have[GW-1];
    reg [2:0] vcnt;
    reg p_v, p_odd;
    reg [1:0] p_b0, p_b1, p_b2;
    wire issue = avail && ({1'b0, vcnt} + p_v <= 3);
    wire [YW-1:0] rj1 = rj + 1'b1;
    wire [YW-1:0] m1 = rj1 >> 1;

    always @(posedge clk) begin
        if (push) begin
            case (wrow[1:0])
            2'd0: bk0[wx[BA-1:0]] <= in_data;
            2'd1: bk1[wx[BA-1:0]] <= in_data;
            2'd2: bk2[wx[BA-1:0]] <= in_data;
            default: bk3[wx[BA-1:0]] <= in_data;
            endcase
        end
        if (issue) begin
            q0 <= bk0[rn[BA-1:0]];
            q1 <= bk1[rn[BA-1:0]];
            q2 <= bk2[rn[BA-1:0]];
            q3 <= bk3[rn[BA-1:0]];
        end
    end

    always @(posedge clk) begin
        if (rst) begin
            rj <= 0;
            rn <= 0;
            rbase <= 0;
            oldest <= 0;
            p_v <= 1'b0;
        end else begin
            p_v <= issue;
            if (issue) begin
                p_b0 <= g0[1:0];
                p_b1 <= g1[1:0];
                p_b2 <= g2[1:0];
                p_odd <= rj[0];
                if (rn == wi - 1'b1) begin
                    rn <= 0;
                    if (rj == ho - 1'b1) begin
                        rj <= 0;
                        rbase <= rbase + hi;
                        oldest <= rbase + hi;
                    end else begin
                        rj <= rj1;
                        oldest <= rbase + ((m1 == 0) ? {YW{1'b0}} : m1 - 1'b1);
                    end
                end else
                    rn <= rn + 1'b1;
            end
        end
    end

    function [3*UW-1:0] pick;
        input [1:0] b;
        input [3*UW-1:0] a0, a1, a2, a3;
        begin
            case (b)
            2'd0: pick = a0;
            2'd1: pick = a1;
            2'd2: pick = a2;
            default: pick = a3;
            endcase
        end
    endfunction
    wire [3*UW-1:0] u0 = pick(p_b0, q0, q1, q2, q3);
    wire [3*UW-1:0] u1 = pick(p_b1, q0, q1, q2, q3);
    wire [3*UW-1:0] u2 = pick(p_b2, q0, q1, q2, q3);
    reg [3*UW-1:0] vnew;
    reg [UW+3:0] vs;
    integer ch;
    always @(*) begin
        for (ch = 0; ch < 3; ch = ch + 1) begin
            // (3, 4, 1) or (1, 4, 3): u0 + u2 + 4 u1 + 2 (the heavier end), one adder tree
            vs = u0[ch*UW +: UW] + u2[ch*UW +: UW] + {u1[ch*UW +: UW], 2'b0} +
                 {(p_odd ? u2[ch*UW +: UW] : u0[ch*UW +: UW]), 1'b0} + 3'd4;
            vnew[ch*UW +: UW] = vs[UW+2:3];
        end
    end

    // ---- V queue and the horizontal side -----------------------------
    // four entries in a circle: written at vw, read at vr and vr + 1
    reg [3*UW-1:0] vq0, vq1, vq2, vq3;
    reg [1:0] vw, vr;
    wire [3*UW-1:0] v0 = pick(vr, vq0, vq1, vq2, vq3);
    wire [3*UW-1:0] v1 = pick(vr + 2'd1, vq0, vq1, vq2, vq3);
    reg [3*UW-1:0] wp, wc, wn;         // V(n-1), V(n), V(n+1)
    reg [XW-1:0] hx;                   // output column
    wire [XW-1:0] hn = hx >> 1;
    wire en = !out_valid || out_ready;
    wire wide = wi != 1;               // the row has a V(1)
    wire last = hx == wo - 1'b1;
    wire shift_pop = hx[0] && !last && ({1'b0, hn} + 2'd2 <= {1'b0, wi} - 1'b1);
    wire [1:0] npop = (hx == 0) ? (wide ? 2'd2 : 2'd1) : (shift_pop ? 2'd1 : 2'd0);
    wire can = {1'b0, vcnt} >= npop && (HAS_ADD == 0 || add_valid);
    wire emit = en && can;
    assign add_ready = HAS_ADD != 0 && emit;

    wire [3*UW-1:0] xp = (hx == 0) ? v0 : wp;
    wire [3*UW-1:0] xc = (hx == 0) ? v0 : wc;
    wire [3*UW-1:0] xn = (hx == 0) ? (wide ? v1 : v0) : wn;
    reg [3*UW-1:0] tval;
    reg [UW+3:0] ts;
    always @(*) begin
        for (ch = 0; ch < 3; ch = ch + 1) begin
            ts = xp[ch*UW +: UW] + xn[ch*UW +: UW] + {xc[ch*UW +: UW], 2'b0} +
                 {(hx[0] ? xn[ch*UW +: UW] : xp[ch*UW +: UW]), 1'b0} + 2'd3;
            tval[ch*UW +: UW] = ts[UW+2:3] + (HAS_ADD != 0 ? add_data[ch*SW +: SW] : {SW{1'b0}});
        end
    end

    wire [1:0] pop = emit ? npop : 2'd0;
    wire [2:0] c1 = vcnt - pop;
    always @(posedge clk) begin
        if (p_v) begin
            case (vw)
            2'd0: vq0 <= vnew;
            2'd1: vq1 <= vnew;
            2'd2: vq2 <= vnew;
            default: vq3 <= vnew;
            endcase
        end
    end

    always @(posedge clk) begin
        if (rst) begin
            vcnt <= 0;
            vw <= 0;
            vr <= 0;
            hx <= 0;
            out_valid <= 1'b0;
        end else begin
            vcnt <= c1 + p_v;
            vr <= vr + pop;
            if (p_v) vw <= vw + 1'b1;
            if (en) out_valid <= can;
            if (emit) begin
                out_data <= tval;
                hx <= last ? {XW{1'b0}} : hx + 1'b1;
                if (hx == 0) begin
                    wp <= v0;
                    wc <= v0;
                    wn <= wide ? v1 : v0;
                end else if (hx[0]) begin
                    wp <= wc;
                    wc <= wn;
                    if (shift_pop) wn <= v0;
                end
            end
        end
    end
endmodule
`default_nettype wire
