// Box down, level k-1 -> level k (sim/docs/fixed-point.md step 2; the C
// kernel is bloom_row_box_c / box_src_range in src/kernels/bloom_row.c).
//
// The input is one level's pixels in raster order (win x hin), one per
// clock at most; the output is the next level's pixels in raster order,
// D = round_half_even(sum of the 4x4 block / 16), edges replicated.
//
// Horizontally, column pairs P(j) = col(2j-1) + col(2j) (clamped) are
// formed as pixels arrive and H(x) = P(x) + P(x+1) leaves at column 2x+2
// (or at the row's last column): at most one H every other clock, except
// that an odd-width row ends with two (the second one waits a clock in a
// skid register; the next row's first two columns make none).
//
// Vertically, destination row y sums H rows 2y-1 .. 2y+2 (clamped). Every
// H row r adds into two accumulator rows, the lower y (r = 2y+1 or 2y+2)
// and the higher y (r = 2y-1 or 2y), kept in two banks by the parity of
// y: a read-modify-write at column x on each, two clocks deep, with the
// last write forwarded. Row 0 counts twice (row -1), the last row 2 or 3
// times. A destination row completes at its row 2y+2 and leaves then;
// when hin is odd (>= 3) the last input row completes two rows at once:
// the lower leaves, the higher is written back and flushed from its bank
// after the row, while the next frame's row 0 fills the other bank (the
// next frame's row 1 waits for the flush: it is never needed in practice,
// the flush is half as long as a row).
//
// Widths (8-bit and 5/6-bit codes: samples <= 2^20, SW = 21 bits): H <=
// 2^22 (SW + 2), the 16-sample sums <= 2^24 (AW = SW + 4), rounding adds 8.
//
// Flow control: one enable for the whole stage, en = !out_valid ||
// out_ready; the stage holds at most its three pipeline registers (the
// sums, the sum that leaves, the rounded pixel).
`default_nettype none
module bloom_box #(
    parameter SW = 21,   // sample bits per channel (values <= 2^20)
    parameter XW = 12,   // column counter bits
    parameter YW = 12,   // row counter bits
    parameter WMAX = 1024 // widest input row
) (
    input wire clk,
    input wire rst,
    input wire [XW-1:0] win,
    input wire [YW-1:0] hin,
    input wire in_valid,
    output wire in_ready,
    input wire [3*SW-1:0] in_data,
    output reg out_valid,
    input wire out_ready,
    output reg [3*SW-1:0] out_data
);
    localparam HW = SW + 2;            // H: a sum of 4 samples
    localparam AW = SW + 4;            // a sum of 16 samples
    localparam DW = (WMAX + 1) / 2;    // accumulator row length
    localparam DA = DW > 1 ? $clog2(DW) : 1;

    wire [XW:0] win1 = {1'b0, win} + 1'b1;
    wire [YW:0] hin1 = {1'b0, hin} + 1'b1;
    wire [XW-1:0] wout = win1[XW:1];
    wire [YW-1:0] hout = hin1[YW:1];
    wire en = !out_valid || out_ready;

    // ---- stage 0: column pairs -> H ----------------------------------
    reg [XW-1:0] ix;
    reg [YW-1:0] iy;
    reg boff;                          // bank of row y = (y + boff) & 1
    reg [3*HW-1:0] pprev;              // P(j-1)
    reg [3*SW-1:0] part;               // col 2j-1 of P(j)
    reg fl_pend, fl_act;               // a flush is due / running
    wire lastc = ix == win - 1'b1;
    wire lastr = iy == hin - 1'b1;
    wire need_flush = !hin[0] ? 1'b0 : (hin != 1);
    // the next frame's row 1 would write the bank being flushed
    wire block = (fl_pend || fl_act) && iy != 0;
    assign in_ready = en && !block;
    wire take = in_valid && in_ready;

    reg [3*HW-1:0] p2, hval, hskid, pj;
    reg hgen, sgen;
    reg [XW-1:0] hx;
    integer ch;
    always @(*) begin
        hgen = 1'b0;
        sgen = 1'b0;
        hx = ix >> 1;
        for (ch = 0; ch < 3; ch = ch + 1) begin
            p2[ch*HW +: HW] = {1'b0, in_data[ch*SW +: SW], 1'b0};
            pj[ch*HW +: HW] = {2'b0, part[ch*SW +: SW]} + {2'b0, in_data[ch*SW +: SW]};
            hval[ch*HW +: HW] = pprev[ch*HW +: HW] + pj[ch*HW +: HW];
            hskid[ch*HW +: HW] = pj[ch*HW +: HW] + p2[ch*HW +: HW];
        end
        if (ix == 0) begin
            hgen = lastc;              // width 1: H(0) = 4 col0
            for (ch = 0; ch < 3; ch = ch + 1)
                hval[ch*HW +: HW] = p2[ch*HW +: HW] + p2[ch*HW +: HW];
        end else if (ix[0]) begin
            hgen = lastc;              // even width: P(j) = 2 col(2j-1)
            for (ch = 0; ch < 3; ch = ch + 1)
                hval[ch*HW +: HW] = pprev[ch*HW +: HW] + p2[ch*HW +: HW];
        end else begin
            hgen = 1'b1;               // H(j-1) = P(j-1) + P(j)
            hx = (ix >> 1) - 1'b1;
            sgen = lastc;              // odd width: H(j) = P(j) + 2 col(2j)
        end
    end

    // H rows travel with: even row, row 0, last row, m = r/2 is 0, bank
    // parity of y = m, the frame's last H
    reg s1_v, s1_even, s1_r0, s1_last, s1_m0, s1_bp, s1_endf;
    reg [3*HW-1:0] s1_h;
    reg [XW-1:0] s1_x;
    reg sk_v, sk_even, sk_r0, sk_last, sk_m0, sk_bp, sk_endf;
    reg [3*HW-1:0] sk_h;
    reg [XW-1:0] sk_x;
    wire bp_now = iy[1] ^ boff;        // parity of m = iy >> 1, plus boff
    wire endf_now = lastr && lastc;

    always @(posedge clk) begin
        if (rst) begin
            ix <= 0;
            iy <= 0;
            boff <= 1'b0;
            s1_v <= 1'b0;
            sk_v <= 1'b0;
            fl_pend <= 1'b0;
        end else if (en) begin
            s1_v <= 1'b0;
            sk_v <= 1'b0;
            if (sk_v) begin
                s1_v <= 1'b1;
                s1_h <= sk_h;
                s1_x <= sk_x;
                {s1_even, s1_r0, s1_last, s1_m0, s1_bp, s1_endf} <=
                    {sk_even, sk_r0, sk_last, sk_m0, sk_bp, sk_endf};
            end
            if (take) begin
                if (ix == 0) pprev <= p2;
                else if (ix[0]) part <= in_data;
                else pprev <= pj;
                if (hgen) begin
                    s1_v <= 1'b1;
                    s1_h <= hval;
                    s1_x <= hx;
                    {s1_even, s1_r0, s1_last, s1_m0, s1_bp, s1_endf} <=
                        {!iy[0], iy == 0, lastr, (iy >> 1) == 0, bp_now, endf_now && !sgen};
                end
                if (sgen) begin
                    sk_v <= 1'b1;
                    sk_h <= hskid;
                    sk_x <= ix >> 1;
                    {sk_even, sk_r0, sk_last, sk_m0, sk_bp, sk_endf} <=
                        {!iy[0], iy == 0, lastr, (iy >> 1) == 0, bp_now, endf_now};
                end
                if (lastc) begin
                    ix <= 0;
                    if (lastr) begin
                        iy <= 0;
                        boff <= boff ^ hout[0];
                        if (need_flush) fl_pend <= 1'b1;
                    end else
                        iy <= iy + 1'b1;
                end else
                    ix <= ix + 1'b1;
            end
            if (fl_act) fl_pend <= 1'b0;
        end
    end

    // ---- stage 1: targets, weights, reads ------------------------------
    // t1: the lower destination row, t2: the higher one (see the header)
    wire t1_ex = s1_even ? !s1_m0 : 1'b1;
    wire t2_ex = s1_even ? 1'b1 : !s1_last;
    wire [2:0] t1_w = (!s1_even && s1_last) ? 3'd2 : 3'd1;
    wire [2:0] t2_w = s1_even ? ((s1_r0 ? 3'd2 : 3'd1) + (s1_last ? 3'd2 : 3'd0)) : 3'd1;
    wire t2_start = s1_even ? s1_r0 : 1'b1;
    wire t1_emit = s1_even ? 1'b1 : s1_last;
    wire t2_emit = s1_even && s1_last && s1_m0;
    wire t1_b = s1_even ? !s1_bp : s1_bp;
    wire t2_b = !t1_b;

    // the two accumulator banks; read port address: the flush or stage 1
    reg [3*AW-1:0] bank0 [0:DW-1];
    reg [3*AW-1:0] bank1 [0:DW-1];
    reg [3*AW-1:0] rd0, rd1;
    reg [XW-1:0] fl_x;
    reg fl_b;
    wire [DA-1:0] ra0 = (fl_act && !fl_b) ? fl_x[DA-1:0] : s1_x[DA-1:0];
    wire [DA-1:0] ra1 = (fl_act && fl_b) ? fl_x[DA-1:0] : s1_x[DA-1:0];
    reg we0, we1;
    reg [DA-1:0] wa0, wa1;
    reg [3*AW-1:0] wd0, wd1;
    always @(posedge clk) begin
        if (en) begin
            rd0 <= bank0[ra0];
            rd1 <= bank1[ra1];
            if (we0) bank0[wa0] <= wd0;
            if (we1) bank1[wa1] <= wd1;
        end
    end

    // ---- stage 2: accumulate, write back, emit ------------------------
    reg s2_v, s2_t1ex, s2_t2ex, s2_t2st, s2_t1em, s2_t2em, s2_t1b, s2_endf;
    reg [2:0] s2_t1w, s2_t2w;
    reg [3*HW-1:0] s2_h;
    reg [XW-1:0] s2_x;
    reg f2_v;                          // flush data in rd<fl_b>
    // the write of the previous enabled clock, per bank (forwarded)
    reg lw0_v, lw1_v;
    reg [DA-1:0] lw0_x, lw1_x;
    reg [3*AW-1:0] lw0_d, lw1_d;
    wire [3*AW-1:0] acc0 = (lw0_v && lw0_x == s2_x[DA-1:0]) ? lw0_d : rd0;
    wire [3*AW-1:0] acc1 = (lw1_v && lw1_x == s2_x[DA-1:0]) ? lw1_d : rd1;
    wire [3*AW-1:0] a1 = s2_t1b ? acc1 : acc0;
    wire [3*AW-1:0] a2 = s2_t1b ? acc0 : acc1;

    function [AW-1:0] wmul;            // w * h for w in 1..4: shifts and adds
        input [2:0] w;
        input [HW-1:0] h;
        begin
            case (w)
            3'd2: wmul = {h, 1'b0};
            3'd3: wmul = {h, 1'b0} + h;
            3'd4: wmul = {h, 2'b0};
            default: wmul = h;
            endcase
        end
    endfunction
    function [SW-1:0] rnd16;           // (s + 7 + ((s >> 4) & 1)) >> 4
        input [AW-1:0] s;
        reg [AW:0] t;
        begin
            t = {1'b0, s} + 5'd7 + s[4];
            rnd16 = t[SW+3:4];
        end
    endfunction

    reg [3*AW-1:0] s1v, s2v;
    reg e3_v;
    reg [3*AW-1:0] e3_s;
    reg [3*SW-1:0] e3_out;
    always @(*) begin
        for (ch = 0; ch < 3; ch = ch + 1) begin
            s1v[ch*AW +: AW] = a1[ch*AW +: AW] + wmul(s2_t1w, s2_h[ch*HW +: HW]);
            s2v[ch*AW +: AW] = (s2_t2st ? {AW{1'b0}} : a2[ch*AW +: AW]) + wmul(s2_t2w, s2_h[ch*HW +: HW]);
            e3_out[ch*SW +: SW] = rnd16(e3_s[ch*AW +: AW]);
        end
        we0 = 1'b0;
        we1 = 1'b0;
        wa0 = s2_x[DA-1:0];
        wa1 = s2_x[DA-1:0];
        wd0 = s1v;
        wd1 = s1v;
        if (s2_v && s2_t1ex && !s2_t1em) begin
            if (s2_t1b) we1 = 1'b1;
            else we0 = 1'b1;
        end
        if (s2_v && s2_t2ex && !s2_t2em) begin
            if (s2_t1b) begin
                we0 = 1'b1;
                wd0 = s2v;
            end else begin
                we1 = 1'b1;
                wd1 = s2v;
            end
        end
    end

    always @(posedge clk) begin
        if (rst) begin
            s2_v <= 1'b0;
            f2_v <= 1'b0;
            fl_act <= 1'b0;
            lw0_v <= 1'b0;
            lw1_v <= 1'b0;
            e3_v <= 1'b0;
            out_valid <= 1'b0;
        end else if (en) begin
            s2_v <= s1_v;
            s2_h <= s1_h;
            s2_x <= s1_x;
            s2_t1ex <= t1_ex;
            s2_t2ex <= t2_ex;
            s2_t1w <= t1_w;
            s2_t2w <= t2_w;
            s2_t2st <= t2_start;
            s2_t1em <= t1_emit;
            s2_t2em <= t2_emit;
            s2_t1b <= t1_b;
            s2_endf <= s1_endf;
            lw0_v <= we0;
            lw0_x <= wa0;
            lw0_d <= wd0;
            lw1_v <= we1;
            lw1_x <= wa1;
            lw1_d <= wd1;
            // the flush: one read per clock, its data one clock later
            f2_v <= fl_act;
            if (fl_act) begin
                if (fl_x == wout - 1'b1) fl_act <= 1'b0;
                fl_x <= fl_x + 1'b1;
            end
            if (s2_v && s2_endf && fl_pend) begin
                fl_act <= 1'b1;
                fl_x <= 0;
                fl_b <= s2_t1b ? 1'b0 : 1'b1; // t2's bank
            end
            // stage 3 takes the sum that leaves; the rounding is after it
            e3_v <= 1'b0;
            if (f2_v) begin
                e3_v <= 1'b1;
                e3_s <= fl_b ? rd1 : rd0;
            end
            if (s2_v && s2_t1ex && s2_t1em) begin
                e3_v <= 1'b1;
                e3_s <= s1v;
            end
            if (s2_v && s2_t2em) begin
                e3_v <= 1'b1;
                e3_s <= s2v;
            end
            out_valid <= e3_v;
            out_data <= e3_out;
        end
    end
endmodule
`default_nettype wire
