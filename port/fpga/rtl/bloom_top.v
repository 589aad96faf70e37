// bloom_top: the default pipeline of the C engine (BLOOM_PRESET_UNITY,
// sRGB, apply view or debug view) as a streaming block, bit for bit.
//
//   s_axis -> decode -> box_1 -> knee -> D_1 -> box_2 -> D_2 ... -> D_L
//                                        |               |            |
//                                     FIFO_1          FIFO_2          |
//                                        |               |            |
//   m_axis <- encode <- composite <- tent(U_1) <- U_1 = D_1 + tent(U_2) ... U_L = D_L
//                           ^
//   c_axis (the source again, read a second time) -> decode
//
// Every arrow is a valid/ready stream in raster order; each level's D_k
// waits in its FIFO (a delay line of about 2^(L-k+2) rows) until the up
// chain reaches it. Levels beyond L are idle. Port map, registers and
// timing: port/fpga/README.md.
`default_nettype none
module bloom_top #(
    parameter WMAX = 1920,
    parameter HMAX = 1080,
    parameter LMAX = 5,        // deepest pyramid the build carries (1 .. 16)
    parameter FMT888 = 1,      // pixels: 1 RGB888, 0 RGB565
    parameter KNEE_II = 1,     // clocks per level-1 pixel in the knee (1 .. 3)
    parameter MARGIN = 8,      // delay-line rows beyond 2^(L-k+2)
    parameter PW = FMT888 ? 24 : 16
) (
    input wire clk,
    input wire rst,
    // register port (word addresses; README.md, "Registers")
    input wire reg_we,
    input wire [2:0] reg_addr,
    input wire [31:0] reg_wdata,
    output reg [31:0] reg_rdata,
    // the frame, into the pyramid
    input wire [PW-1:0] s_tdata,
    input wire s_tvalid,
    output wire s_tready,
    input wire s_tuser,
    input wire s_tlast,
    // the same frame again, for the composite
    input wire [PW-1:0] c_tdata,
    input wire c_tvalid,
    output wire c_tready,
    input wire c_tuser,
    input wire c_tlast,
    // the result
    output wire [PW-1:0] m_tdata,
    output wire m_tvalid,
    input wire m_tready,
    output wire m_tuser,
    output wire m_tlast
);
    localparam SW = 21, UW = 25;
    localparam XW = $clog2(WMAX + 1), YW = $clog2(HMAX + 1);

`include "bloom_rom.vh"

    // ---- registers -----------------------------------------------------
    reg [XW-1:0] r_w;
    reg [YW-1:0] r_h;
    reg [4:0] r_n;
    reg [28:0] r_t, r_k;
    reg [23:0] r_i;
    reg r_debug;
    reg [2:0] sync_err;        // sticky: s_axis framing, c_axis framing, a refused write
    reg bad_write;
    wire [4:0] lv;             // levels built, L
    wire idle;
    always @(posedge clk) begin
        if (rst) begin
            r_w <= 1;
            r_h <= 1;
            r_n <= 1;
            r_t <= 29'd1048576;
            r_k <= 29'd524288;
            r_i <= 24'd65536;
            r_debug <= 1'b0;
        end else if (reg_we && !bad_write) begin
            case (reg_addr)
            3'd0: r_debug <= reg_wdata[0];
            3'd1: r_w <= reg_wdata[XW-1:0];
            3'd2: r_h <= reg_wdata[YW-1:0];
            3'd3: r_n <= reg_wdata[4:0];
            3'd4: begin
                r_t <= reg_wdata[28:0];
                r_k <= 0;      // K_q <= T_q always: KNEE_Q is written after
            end
            3'd5: r_k <= reg_wdata[28:0];
            3'd6: r_i <= reg_wdata[23:0];
            default: ;
            endcase
        end
    end
    // a value the block cannot run is refused: the register keeps its old
    // value and CTRL bit 7 says so (the ranges bloom_query checks, and the
    // build's largest frame; K_q <= T_q: a THRESHOLD_Q write sets KNEE_Q
    // to 0, and KNEE_Q is written after it)
    always @(*) begin
        case (reg_addr)
        3'd1: bad_write = reg_wdata == 0 || reg_wdata > WMAX;
        3'd2: bad_write = reg_wdata == 0 || reg_wdata > HMAX;
        3'd3: bad_write = reg_wdata == 0 || reg_wdata > 16;
        3'd4: bad_write = reg_wdata > 32'h10000000;
        3'd5: bad_write = reg_wdata > {3'b0, r_t};
        3'd6: bad_write = reg_wdata >= 32'h1000000;
        default: bad_write = 1'b0;
        endcase
    end
    always @(*) begin
        case (reg_addr)
        3'd0: reg_rdata = {24'b0, sync_err, 4'b0, r_debug};
        3'd1: reg_rdata = r_w;
        3'd2: reg_rdata = r_h;
        3'd3: reg_rdata = {11'b0, lv, 11'b0, r_n};
        3'd4: reg_rdata = r_t;
        3'd5: reg_rdata = r_k;
        3'd6: reg_rdata = r_i;
        default: reg_rdata = {idle, 7'b0, LMAX[7:0], 4'b0, FMT888[0] ? 4'd8 : 4'd5, 8'h0b}; // ID
        endcase
    end

    // ---- level sizes and the level count -------------------------------
    wire [XW-1:0] lw [0:LMAX];
    wire [YW-1:0] lh [0:LMAX];
    wire [LMAX:0] exists;      // level k is built
    assign lw[0] = r_w;
    assign lh[0] = r_h;
    assign exists[0] = 1'b1;
    genvar k;
    generate
        for (k = 1; k <= LMAX; k = k + 1) begin : g_size
            // ceil(ceil(w / 2) / 2) = ceil(w / 4): each size straight from the register
            wire [XW+16:0] w1 = {17'b0, r_w} + ((17'd1 << k) - 1'b1);
            wire [YW+16:0] h1 = {17'b0, r_h} + ((17'd1 << k) - 1'b1);
            assign lw[k] = w1 >> k;
            assign lh[k] = h1 >> k;
            // level 1 always; level k > 1 while k <= N and min(w, h) >= 2
            if (k == 1) begin : g_one
                assign exists[k] = 1'b1;
            end else begin : g_more
                // sizes only shrink: level k built means every level below it is
                assign exists[k] = r_n >= k && lw[k] >= 2 && lh[k] >= 2;
            end
        end
    endgenerate
    reg [4:0] lcount;
    integer j;
    always @(*) begin
        lcount = 0;
        for (j = 1; j <= LMAX; j = j + 1)
            if (exists[j]) lcount = j;
    end
    assign lv = lcount;

    // ---- per-level streams ----------------------------------------------
    wire [3*SW-1:0] d_data [1:LMAX];   // D_k (after the knee for k = 1)
    wire [LMAX:1] d_valid, d_ready;
    wire [3*SW-1:0] b_in_data [1:LMAX]; // into box_k
    wire [LMAX:1] b_in_valid, b_in_ready;
    wire [3*UW-1:0] u_data [1:LMAX];   // U_k
    wire [LMAX:1] u_valid, u_ready;
    wire [3*UW-1:0] up_data [1:LMAX];  // up_k's output (k < LMAX)
    wire [LMAX:1] up_valid, up_ready;
    wire [3*SW-1:0] f_data [1:LMAX];   // FIFO_k's output
    wire [LMAX:1] f_valid, f_ready, f_in_valid, f_in_ready;

    // the source, decoded
    wire [3*SW-1:0] s_lin;
    generate
        if (FMT888) begin : g_dec888
            assign s_lin = {dec8(s_tdata[23:16]), dec8(s_tdata[15:8]), dec8(s_tdata[7:0])};
        end else begin : g_dec565
            assign s_lin = {dec5(s_tdata[4:0]), dec6(s_tdata[10:5]), dec5(s_tdata[15:11])};
        end
    endgenerate
    assign b_in_data[1] = s_lin;
    assign b_in_valid[1] = s_tvalid;
    assign s_tready = b_in_ready[1];

    generate
        for (k = 1; k <= LMAX; k = k + 1) begin : g_lvl
            wire [3*SW-1:0] bx_data;
            wire bx_valid, bx_ready;
            bloom_box #(.SW(SW), .XW(XW), .YW(YW), .WMAX((WMAX + (1 << (k - 1)) - 1) >> (k - 1))) box (
                .clk(clk), .rst(rst), .win(lw[k-1]), .hin(lh[k-1]),
                .in_valid(b_in_valid[k]), .in_ready(b_in_ready[k]), .in_data(b_in_data[k]),
                .out_valid(bx_valid), .out_ready(bx_ready), .out_data(bx_data));
            if (k == 1) begin : g_knee
                wire [3*SW-1:0] kq_data;
                wire kq_valid, kq_ready;
                if (KNEE_II > 1) begin : g_queue
                    // level-1 pixels come one every two clocks along a row,
                    // a quarter of a clock on average; at the end of a frame
                    // two rows in a row (even height) or a row and the box's
                    // flush (odd height): a knee taking one every KNEE_II <= 3
                    // clocks needs a queue of one level-1 row to keep up
                    bloom_fifo #(.W(3 * SW), .DEPTH((WMAX + 1) / 2 + 16)) kq (
                        .clk(clk), .rst(rst), .in_valid(bx_valid), .in_ready(bx_ready), .in_data(bx_data),
                        .out_valid(kq_valid), .out_ready(kq_ready), .out_data(kq_data));
                end else begin : g_direct
                    assign kq_valid = bx_valid;
                    assign kq_data = bx_data;
                    assign bx_ready = kq_ready;
                end
                bloom_knee #(.SW(SW), .II(KNEE_II)) knee (
                    .clk(clk), .rst(rst), .t_q(r_t), .k_q(r_k),
                    .in_valid(kq_valid), .in_ready(kq_ready), .in_data(kq_data),
                    .out_valid(d_valid[k]), .out_ready(d_ready[k]), .out_data(d_data[k]));
            end else begin : g_noknee
                assign d_valid[k] = bx_valid;
                assign d_data[k] = bx_data;
                assign bx_ready = d_ready[k];
            end

            // D_k: to box_{k+1} and FIFO_k below L, as U_k at L
            wire below, at_l;
            if (k < LMAX) begin : g_below
                assign below = exists[k] && exists[k+1];
            end else begin : g_deepest
                assign below = 1'b0;
            end
            assign at_l = exists[k] && !below;
            if (k < LMAX) begin : g_fork
                assign b_in_data[k+1] = d_data[k];
                assign b_in_valid[k+1] = d_valid[k] && below && f_in_ready[k];
                assign f_in_valid[k] = d_valid[k] && below && b_in_ready[k+1];
                assign d_ready[k] = below ? (b_in_ready[k+1] && f_in_ready[k]) : (at_l ? u_ready[k] : 1'b1);

                localparam integer WK = (WMAX + (1 << k) - 1) >> k;
                localparam integer DEP = ((1 << (LMAX - k + 2)) + MARGIN) * WK;
                bloom_fifo #(.W(3 * SW), .DEPTH(DEP)) fifo (
                    .clk(clk), .rst(rst), .in_valid(f_in_valid[k]), .in_ready(f_in_ready[k]), .in_data(d_data[k]),
                    .out_valid(f_valid[k]), .out_ready(f_ready[k]), .out_data(f_data[k]));

                // U_k = D_k + tent(U_{k+1})
                bloom_up #(.UW(UW), .SW(SW), .XW(XW), .YW(YW), .WIMAX((WMAX + (1 << (k + 1)) - 1) >> (k + 1)),
                           .HAS_ADD(1)) up (
                    .clk(clk), .rst(rst), .wi(lw[k+1]), .hi(lh[k+1]), .wo(lw[k]), .ho(lh[k]),
                    .in_valid(u_valid[k+1]), .in_ready(u_ready[k+1]), .in_data(u_data[k+1]),
                    .add_valid(f_valid[k]), .add_ready(f_ready[k]), .add_data(f_data[k]),
                    .out_valid(up_valid[k]), .out_ready(up_ready[k]), .out_data(up_data[k]));
                assign u_valid[k] = at_l ? d_valid[k] : up_valid[k];
                assign u_data[k] = at_l ? {{(UW-SW){1'b0}}, d_data[k][3*SW-1:2*SW],
                                           {(UW-SW){1'b0}}, d_data[k][2*SW-1:SW],
                                           {(UW-SW){1'b0}}, d_data[k][SW-1:0]} : up_data[k];
                assign up_ready[k] = !at_l && u_ready[k];
            end else begin : g_last
                assign d_ready[k] = at_l ? u_ready[k] : 1'b1;
                assign u_valid[k] = d_valid[k] && at_l;
                assign u_data[k] = {{(UW-SW){1'b0}}, d_data[k][3*SW-1:2*SW],
                                    {(UW-SW){1'b0}}, d_data[k][2*SW-1:SW],
                                    {(UW-SW){1'b0}}, d_data[k][SW-1:0]};
            end
        end
    endgenerate

    // ---- B and the composite -------------------------------------------
    wire [3*UW-1:0] bl_data;
    wire bl_valid, bl_ready;
    wire [3*SW-1:0] unused_add = 0;
    wire unused_add_ready;
    bloom_up #(.UW(UW), .SW(SW), .XW(XW), .YW(YW), .WIMAX((WMAX + 1) / 2), .HAS_ADD(0)) up0 (
        .clk(clk), .rst(rst), .wi(lw[1]), .hi(lh[1]), .wo(lw[0]), .ho(lh[0]),
        .in_valid(u_valid[1]), .in_ready(u_ready[1]), .in_data(u_data[1]),
        .add_valid(1'b0), .add_ready(unused_add_ready), .add_data(unused_add),
        .out_valid(bl_valid), .out_ready(bl_ready), .out_data(bl_data));
    bloom_out #(.UW(UW), .FMT888(FMT888)) out (
        .clk(clk), .rst(rst), .i_q(r_i), .debug(r_debug),
        .b_valid(bl_valid), .b_ready(bl_ready), .b_data(bl_data),
        .s_valid(c_tvalid), .s_ready(c_tready), .s_data(c_tdata),
        .o_valid(m_tvalid), .o_ready(m_tready), .o_data(m_tdata));

    // ---- framing: tuser/tlast out, and checked on the way in ------------
    reg [XW-1:0] sx, cx, mx;
    reg [YW-1:0] sy, cy, my;
    reg [15:0] frames_in, frames_out;
    assign m_tuser = mx == 0 && my == 0;
    assign m_tlast = mx == r_w - 1'b1;
    assign idle = frames_in == frames_out && sx == 0 && sy == 0 && mx == 0 && my == 0;
    wire s_take = s_tvalid && s_tready, c_take = c_tvalid && c_tready, m_take = m_tvalid && m_tready;
    always @(posedge clk) begin
        if (rst) begin
            sx <= 0;
            sy <= 0;
            cx <= 0;
            cy <= 0;
            mx <= 0;
            my <= 0;
            frames_in <= 0;
            frames_out <= 0;
            sync_err <= 0;
        end else begin
            if (reg_we && reg_addr == 3'd0) sync_err <= sync_err & ~reg_wdata[7:5];
            if (reg_we && bad_write) sync_err[2] <= 1'b1;
            if (s_take) begin
                if (s_tuser != (sx == 0 && sy == 0) || s_tlast != (sx == r_w - 1'b1)) sync_err[0] <= 1'b1;
                sx <= (sx == r_w - 1'b1) ? {XW{1'b0}} : sx + 1'b1;
                if (sx == r_w - 1'b1) sy <= (sy == r_h - 1'b1) ? {YW{1'b0}} : sy + 1'b1;
                if (sx == r_w - 1'b1 && sy == r_h - 1'b1) frames_in <= frames_in + 1'b1;
            end
            if (c_take) begin
                if (c_tuser != (cx == 0 && cy == 0) || c_tlast != (cx == r_w - 1'b1)) sync_err[1] <= 1'b1;
                cx <= (cx == r_w - 1'b1) ? {XW{1'b0}} : cx + 1'b1;
                if (cx == r_w - 1'b1) cy <= (cy == r_h - 1'b1) ? {YW{1'b0}} : cy + 1'b1;
            end
            if (m_take) begin
                mx <= (mx == r_w - 1'b1) ? {XW{1'b0}} : mx + 1'b1;
                if (mx == r_w - 1'b1) my <= (my == r_h - 1'b1) ? {YW{1'b0}} : my + 1'b1;
                if (mx == r_w - 1'b1 && my == r_h - 1'b1) frames_out <= frames_out + 1'b1;
            end
        end
    end
endmodule
`default_nettype wire
