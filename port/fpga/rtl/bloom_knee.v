// The soft_q knee on every level-1 pixel (sim/docs/fixed-point.md step 3;
// the C kernel is bloom_row_knee_c in src/kernels/bloom_row.c), exact:
//
//   bmax = max(r, g, b); x = clamp(bmax - T + K, 0, 2K)
//   soft_q = (2 x^2 + D/2) / D,  D = 8K + 84            (a per-frame divisor)
//   num  = max(soft_q, bmax - T, 0)
//   f    = bmax < 11 ? num * 1600000 : (num * 2^24 + bmax/2) / bmax   (Q24)
//   c'   = (c f + 2^23) >> 24                           for each channel
//
// Samples are at most 2^20 here (8-bit and 5/6-bit codes decode to at most
// 1.0), so x <= bmax <= 2^20 (K <= T), 2 x^2 + D/2 < 2^42, soft_q < 2^20,
// num <= bmax, f <= 2^24 and num * 2^24 + bmax/2 < 2^45. Both divisions are
// restoring divisions (compare, subtract, shift): 20 quotient bits over a
// 33-bit remainder for soft_q, 25 over a 22-bit remainder for f.
//
// The pipeline is phase-locked: a pixel enters every II clocks, and every
// divider unit performs II steps of its division on the pixel it holds
// before passing it on (II = 1: one pixel per clock, 45 units; II = 2 or
// 3: a half or a third of the units, for small FPGAs, fed through a queue:
// level-1 pixels come at most one every two clocks, a quarter of a clock
// on average, so II = 4 would have no slack left; II = 1 and 3 are the
// tested builds).
`default_nettype none
module bloom_knee #(
    parameter SW = 21,
    parameter II = 1
) (
    input wire clk,
    input wire rst,
    input wire [28:0] t_q,             // threshold, Q12.20, <= 2^28
    input wire [28:0] k_q,             // knee width T*s, Q12.20, <= T
    input wire in_valid,
    output wire in_ready,
    input wire [3*SW-1:0] in_data,
    output wire out_valid,
    input wire out_ready,
    output wire [3*SW-1:0] out_data
);
    localparam Q1 = 20, Q2 = 25;               // quotient bits
    localparam N1 = (Q1 + II - 1) / II;        // units of each division
    localparam N2 = (Q2 + II - 1) / II;
    localparam R1 = 33, R2 = SW + 1;           // remainder bits
    localparam PB = II > 1 ? $clog2(II) : 1;

    wire [31:0] dd = {k_q, 3'b0} + 32'd84;     // D = 8K + E8 (E8 = 84 at F = 20)

    // ---- phase ---------------------------------------------------------
    reg [PB-1:0] ph;
    reg f_v;                                   // the output unit holds a pixel
    wire at_end = ph == II - 1;
    wire stall = at_end && f_v && !out_ready;
    wire adv = !stall;
    wire tick = adv && at_end;
    assign in_ready = tick;
    wire take = in_valid && in_ready;

    // ---- A: bmax, bmax - T, x -------------------------------------------
    reg [SW-1:0] in_max;
    always @(*) begin
        in_max = in_data[SW-1:0];
        if (in_data[2*SW-1:SW] > in_max) in_max = in_data[2*SW-1:SW];
        if (in_data[3*SW-1:2*SW] > in_max) in_max = in_data[3*SW-1:2*SW];
    end
    wire [30:0] xs_raw = {10'b0, in_max} + {2'b0, k_q} - {2'b0, t_q}; // signed
    wire [30:0] two_k = {1'b0, k_q, 1'b0};
    wire [SW-1:0] xs = xs_raw[30] ? {SW{1'b0}} : (xs_raw > two_k ? two_k[SW-1:0] : xs_raw[SW-1:0]);
    wire [30:0] ov_raw = {10'b0, in_max} - {2'b0, t_q};
    wire [SW-1:0] overp = ov_raw[30] ? {SW{1'b0}} : ov_raw[SW-1:0];

    reg a_v;
    reg [3*SW-1:0] a_c;
    reg [SW-1:0] a_b, a_o, a_x;

    // ---- B: 2 x^2 + D/2 ---------------------------------------------------
    wire [2*SW-1:0] sq = a_x * a_x;
    wire [41:0] n1 = {sq[40:0], 1'b0} + {11'b0, dd[31:1]};

    // ---- division 1: soft_q = n1 / D -------------------------------------
    reg [N1:0] d1_v;
    reg [N1*R1-1:0] d1_r;
    reg [N1*Q1-1:0] d1_n;                      // dividend bits still to bring down
    reg [N1*Q1-1:0] d1_q;
    reg [N1*3*SW-1:0] d1_c;
    reg [N1*SW-1:0] d1_b, d1_o;

    // ---- division 2: f = (num 2^24 + bmax/2) / bmax ------------------------
    reg [N2*R2-1:0] d2_r;
    reg [N2*Q2-1:0] d2_n;
    reg [N2*Q2-1:0] d2_q;
    reg [N2*3*SW-1:0] d2_c;
    reg [N2*SW-1:0] d2_b;
    reg [N2*SW-1:0] d2_num;
    reg [N2:0] d2_v;

    // C: num and the second dividend, from the last unit of division 1
    wire [Q1-1:0] soft_q;
    wire [SW-1:0] c_b = d1_b[(N1-1)*SW +: SW];
    wire [SW-1:0] c_o = d1_o[(N1-1)*SW +: SW];
    wire [SW-1:0] c_num = {1'b0, soft_q} > c_o ? {1'b0, soft_q} : c_o;
    wire [44:0] n2 = {c_num, 24'b0} | {21'b0, 1'b0, c_b[SW-1:1]};

    // E: the factor, F: the products
    wire [SW-1:0] e_b = d2_b[(N2-1)*SW +: SW];
    wire [SW-1:0] e_num = d2_num[(N2-1)*SW +: SW];
    wire [Q2-1:0] e_q;
    wire [24:0] f = e_num == 0 ? 25'd0 : (e_b < 11 ? e_num[3:0] * 25'd1600000 : e_q);
    wire [3*SW-1:0] e_c = d2_c[(N2-1)*3*SW +: 3*SW];
    reg [3*SW-1:0] f_c;
    reg [SW+24:0] prod;
    integer ch;
    always @(*) begin
        for (ch = 0; ch < 3; ch = ch + 1) begin
            prod = e_c[ch*SW +: SW] * f + 46'h800000;
            f_c[ch*SW +: SW] = prod[SW+23:24];
        end
    end
    reg [3*SW-1:0] f_out;
    assign out_valid = f_v;
    assign out_data = f_out;

    // one step of each division; the unit's step number is u*II + ph
    function [R1+Q1+Q1-1:0] it1;               // {r, n, q}
        input [R1-1:0] r;
        input [Q1-1:0] n;
        input [Q1-1:0] q;
        input do_it;
        reg [R1-1:0] t;
        begin
            t = {r[R1-2:0], n[Q1-1]};
            if (!do_it) it1 = {r, n, q};
            else if (t >= {1'b0, dd}) it1 = {t - {1'b0, dd}, n << 1, q[Q1-2:0], 1'b1};
            else it1 = {t, n << 1, q[Q1-2:0], 1'b0};
        end
    endfunction
    function [R2+Q2+Q2-1:0] it2;
        input [R2-1:0] r;
        input [Q2-1:0] n;
        input [Q2-1:0] q;
        input [SW-1:0] d;
        input do_it;
        reg [R2-1:0] t;
        begin
            t = {r[R2-2:0], n[Q2-1]};
            if (!do_it) it2 = {r, n, q};
            else if (t >= {1'b0, d}) it2 = {t - {1'b0, d}, n << 1, q[Q2-2:0], 1'b1};
            else it2 = {t, n << 1, q[Q2-2:0], 1'b0};
        end
    endfunction
    // the quotient of each division's last unit after its last step (this clock's)
    wire [R1+Q1+Q1-1:0] last1 = it1(d1_r[(N1-1)*R1 +: R1], d1_n[(N1-1)*Q1 +: Q1], d1_q[(N1-1)*Q1 +: Q1],
                                    (N1 - 1) * II + II - 1 < Q1);
    wire [SW-1:0] last_b = d2_b[(N2-1)*SW +: SW];
    wire [R2+Q2+Q2-1:0] last2 = it2(d2_r[(N2-1)*R2 +: R2], d2_n[(N2-1)*Q2 +: Q2], d2_q[(N2-1)*Q2 +: Q2],
                                    last_b == 0 ? 21'd1 : last_b, (N2 - 1) * II + II - 1 < Q2);
    assign soft_q = last1[Q1-1:0];
    assign e_q = last2[Q2-1:0];

    integer u;
    reg [R1+Q1+Q1-1:0] s1;
    reg [R2+Q2+Q2-1:0] s2;
    reg [SW-1:0] dv;
    always @(posedge clk) begin
        if (rst) begin
            ph <= 0;
            a_v <= 1'b0;
            d1_v <= 0;
            d2_v <= 0;
            f_v <= 1'b0;
        end else begin
            if (f_v && out_ready && !tick) f_v <= 1'b0;
            if (adv) begin
                ph <= at_end ? {PB{1'b0}} : ph + 1'b1;
                // division units: a step, and at the tick the hand-over
                for (u = N1 - 1; u >= 0; u = u - 1) begin
                    s1 = it1(d1_r[u*R1 +: R1], d1_n[u*Q1 +: Q1], d1_q[u*Q1 +: Q1], u * II + ph < Q1);
                    if (!tick) begin
                        {d1_r[u*R1 +: R1], d1_n[u*Q1 +: Q1], d1_q[u*Q1 +: Q1]} <= s1;
                    end else if (u + 1 < N1) begin
                        {d1_r[(u+1)*R1 +: R1], d1_n[(u+1)*Q1 +: Q1], d1_q[(u+1)*Q1 +: Q1]} <= s1;
                        d1_c[(u+1)*3*SW +: 3*SW] <= d1_c[u*3*SW +: 3*SW];
                        d1_b[(u+1)*SW +: SW] <= d1_b[u*SW +: SW];
                        d1_o[(u+1)*SW +: SW] <= d1_o[u*SW +: SW];
                    end
                end
                for (u = N2 - 1; u >= 0; u = u - 1) begin
                    dv = d2_b[u*SW +: SW] == 0 ? 21'd1 : d2_b[u*SW +: SW];
                    s2 = it2(d2_r[u*R2 +: R2], d2_n[u*Q2 +: Q2], d2_q[u*Q2 +: Q2], dv, u * II + ph < Q2);
                    if (!tick) begin
                        {d2_r[u*R2 +: R2], d2_n[u*Q2 +: Q2], d2_q[u*Q2 +: Q2]} <= s2;
                    end else if (u + 1 < N2) begin
                        {d2_r[(u+1)*R2 +: R2], d2_n[(u+1)*Q2 +: Q2], d2_q[(u+1)*Q2 +: Q2]} <= s2;
                        d2_c[(u+1)*3*SW +: 3*SW] <= d2_c[u*3*SW +: 3*SW];
                        d2_b[(u+1)*SW +: SW] <= d2_b[u*SW +: SW];
                        d2_num[(u+1)*SW +: SW] <= d2_num[u*SW +: SW];
                    end
                end
                if (tick) begin
                    // A
                    a_v <= take;
                    a_c <= in_data;
                    a_b <= in_max;
                    a_o <= overp;
                    a_x <= xs;
                    // B -> the first unit of division 1
                    d1_v <= {d1_v[N1-1:0], a_v};
                    d1_r[R1-1:0] <= {11'b0, n1[41:20]};
                    d1_n[Q1-1:0] <= n1[19:0];
                    d1_q[Q1-1:0] <= 0;
                    d1_c[3*SW-1:0] <= a_c;
                    d1_b[SW-1:0] <= a_b;
                    d1_o[SW-1:0] <= a_o;
                    // C -> the first unit of division 2
                    d2_v <= {d2_v[N2-1:0], d1_v[N1-1]};
                    d2_r[R2-1:0] <= {2'b0, c_num[SW-1:1]};
                    d2_n[Q2-1:0] <= n2[24:0];
                    d2_q[Q2-1:0] <= 0;
                    d2_c[3*SW-1:0] <= d1_c[(N1-1)*3*SW +: 3*SW];
                    d2_b[SW-1:0] <= c_b;
                    d2_num[SW-1:0] <= c_num;
                    // E, F -> the output
                    f_v <= d2_v[N2-1];
                    f_out <= f_c;
                end
            end
        end
    end
endmodule
`default_nettype wire
