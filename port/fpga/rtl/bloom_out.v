// The composite and the encoder (sim/docs/fixed-point.md steps 6 and 7;
// the C kernel is bloom_row_out_c in src/kernels/bloom_row.c):
//
//   P = (I B + 32768) >> 16,  v = S + P (or P alone in the debug view),
//   code = the number of c in 1..n with v >= E_n[c]  (v >= 2^20: n).
//
// B comes from the last tent (bloom_up, HAS_ADD = 0), S is the source
// pixel read a second time (c_axis), decoded. The encoder is a binary
// search over the generated thresholds, one bit per pipeline stage
// (8 stages; 5- and 6-bit channels pass the last ones through).
// Widths: B < 2^25 (UW), I_q < 2^24, so I B < 2^49; S + P < 2^34, and
// anything at 2^20 or above is the top code.
// A plain pipeline: every stage moves when the output is free (so
// m_tready reaches b_ready and c_tready in the same clock).
`default_nettype none
module bloom_out #(
    parameter UW = 25,
    parameter FMT888 = 1,        // 1: RGB888 (tdata[7:0] = R), 0: RGB565
    parameter PW = FMT888 ? 24 : 16
) (
    input wire clk,
    input wire rst,
    input wire [23:0] i_q,       // linear intensity, Q16.16
    input wire debug,            // the bloom alone
    input wire b_valid,
    output wire b_ready,
    input wire [3*UW-1:0] b_data,
    input wire s_valid,
    output wire s_ready,
    input wire [PW-1:0] s_data,
    output wire o_valid,
    input wire o_ready,
    output wire [PW-1:0] o_data
);
`include "bloom_rom.vh"
    localparam NS = 13;          // stages: join, product, sum, load, 8 search, pack
    localparam VW = UW + 24 - 16 + 1; // v before saturation

    reg [NS-1:0] v;
    wire en = !v[NS-1] || o_ready;
    wire take = en && b_valid && s_valid;
    assign b_ready = take;
    assign s_ready = take;

    // the decoded source pixel
    wire [62:0] sd;
    generate
        if (FMT888) begin : g_dec888
            assign sd = {dec8(s_data[PW-1:16]), dec8(s_data[15:8]), dec8(s_data[7:0])};
        end else begin : g_dec565
            assign sd = {dec5(s_data[4:0]), dec6(s_data[10:5]), dec5(s_data[15:11])};
        end
    endgenerate

    function [20:0] thr;         // E_n[i] of the channel's code width
        input integer nb;
        input [7:0] i;
        begin
            if (nb == 8) thr = enc8(i);
            else if (nb == 6) thr = enc6(i[5:0]);
            else thr = enc5(i[4:0]);
        end
    endfunction
    function [PW-1:0] pack;      // codes R, G, B (8 bits each) to the pixel
        input [23:0] c;
        begin
            if (FMT888) pack = c[PW-1:0];
            else pack = {c[4:0], c[13:8], c[20:16]};
        end
    endfunction
    function integer nbits;
        input integer ch;
        begin
            nbits = FMT888 ? 8 : (ch == 1 ? 6 : 5);
        end
    endfunction

    reg [3*21-1:0] j_s;
    reg [3*UW-1:0] j_b;
    reg [3*(UW+24)-1:0] p_p;
    reg [3*21-1:0] p_s;
    reg [3*21-1:0] c_v;          // v, saturated to 2^20
    reg [9*24-1:0] c_c;          // the code, one more bit per stage (9 x 3 x 8)
    reg [9*63-1:0] c_vv;         // v along the search (9 x 3 x 21)
    reg [PW-1:0] o_px;
    assign o_valid = v[NS-1];
    assign o_data = o_px;

    integer ch, st, nb;
    reg [VW-1:0] vsum;
    reg [7:0] cand, code;
    reg [20:0] vv;
    always @(posedge clk) begin
        if (rst) v <= 0;
        else if (en) v <= {v[NS-2:0], take};
        if (en) begin
            j_s <= debug ? 63'd0 : sd;
            j_b <= b_data;
            for (ch = 0; ch < 3; ch = ch + 1)
                p_p[ch*(UW+24) +: UW+24] <= i_q * j_b[ch*UW +: UW];
            p_s <= j_s;
            for (ch = 0; ch < 3; ch = ch + 1) begin
                vsum = ((p_p[ch*(UW+24) +: UW+24] + 16'h8000) >> 16) + p_s[ch*21 +: 21];
                c_v[ch*21 +: 21] <= vsum >= (1 << 20) ? 21'h100000 : vsum[20:0];
            end
            c_vv[62:0] <= c_v;
            c_c[23:0] <= 0;
            for (st = 0; st < 8; st = st + 1) begin
                c_vv[(st+1)*63 +: 63] <= c_vv[st*63 +: 63];
                for (ch = 0; ch < 3; ch = ch + 1) begin
                    nb = nbits(ch);
                    code = c_c[st*24 + ch*8 +: 8];
                    vv = c_vv[st*63 + ch*21 +: 21];
                    if (vv == 21'h100000)
                        code = (1 << nb) - 1;
                    else if (st < nb) begin
                        cand = code | (8'd1 << (nb - 1 - st));
                        if (vv >= thr(nb, cand)) code = cand;
                    end
                    c_c[(st+1)*24 + ch*8 +: 8] <= code;
                end
            end
            o_px <= pack(c_c[8*24 +: 24]);
        end
    end
endmodule
`default_nettype wire
