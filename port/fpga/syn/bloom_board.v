// A board around bloom_top for place and route: what an iCE40 on a small
// board has room for (39 pins on the UP5K's SG48 package). Pixels move as
// bytes, as DVP cameras and 8080-style LCD buses carry RGB565 (two bytes
// per pixel; three for RGB888): one byte bus in, shared by the frame
// (in_sel = 0) and its second read for the composite (in_sel = 1), one
// byte bus out; the registers are written over SPI (mode 0, 35 bits per
// write: address[2:0], then data[31:0], most significant first; chip
// select low for the transfer). The block itself runs one pixel per clock;
// a board bus this narrow cannot feed it that fast, and this wrapper is
// only here to give the tools real pins to place.
`default_nettype none
module bloom_board #(
    parameter WMAX = 320,
    parameter HMAX = 240,
    parameter LMAX = 5,
    parameter FMT888 = 0,
    parameter KNEE_II = 3
) (
    input wire clk,
    input wire rst,
    input wire [7:0] in_d,
    input wire in_v,
    input wire in_sel,
    input wire in_user,          // on a frame's first byte
    input wire in_last,          // on a row's last byte
    output wire in_rdy,
    output reg [7:0] out_d,
    output reg out_v,
    output reg out_user,
    output reg out_last,
    input wire out_rdy,
    input wire spi_sck,
    input wire spi_cs_n,
    input wire spi_mosi
);
    localparam PW = FMT888 ? 24 : 16;
    localparam NB = PW / 8;

    // ---- SPI register writes (the SPI pins sampled by clk) -------------
    reg [2:0] sck_s, cs_s;
    reg [1:0] mosi_s;
    reg [34:0] sh;
    reg reg_we;
    always @(posedge clk) begin
        sck_s <= {sck_s[1:0], spi_sck};
        cs_s <= {cs_s[1:0], spi_cs_n};
        mosi_s <= {mosi_s[0], spi_mosi};
        reg_we <= 1'b0;
        if (!cs_s[1] && sck_s[2:1] == 2'b01) sh <= {sh[33:0], mosi_s[1]};
        if (cs_s[2:1] == 2'b01) reg_we <= 1'b1;
    end

    // ---- bytes to pixels ---------------------------------------------
    reg [PW-1:0] s_px, c_px;
    reg [1:0] s_n, c_n;
    reg s_v, c_v, s_u, c_u, s_l, c_l;
    wire s_rdy, c_rdy;
    assign in_rdy = in_sel ? !c_v : !s_v;
    always @(posedge clk) begin
        if (rst) begin
            s_n <= 0;
            c_n <= 0;
            s_v <= 1'b0;
            c_v <= 1'b0;
        end else begin
            if (s_v && s_rdy) s_v <= 1'b0;
            if (c_v && c_rdy) c_v <= 1'b0;
            if (in_v && in_rdy) begin
                if (!in_sel) begin
                    s_px <= {in_d, s_px[PW-1:8]};
                    if (s_n == 0) s_u <= in_user;
                    s_l <= in_last;
                    s_n <= s_n == NB - 1 ? 2'd0 : s_n + 1'b1;
                    if (s_n == NB - 1) s_v <= 1'b1;
                end else begin
                    c_px <= {in_d, c_px[PW-1:8]};
                    if (c_n == 0) c_u <= in_user;
                    c_l <= in_last;
                    c_n <= c_n == NB - 1 ? 2'd0 : c_n + 1'b1;
                    if (c_n == NB - 1) c_v <= 1'b1;
                end
            end
        end
    end

    wire [PW-1:0] m_d;
    wire m_v, m_u, m_l;
    reg [PW-1:0] o_px;
    reg [1:0] o_n;
    reg o_full;
    wire [31:0] rdata;
    bloom_top #(.WMAX(WMAX), .HMAX(HMAX), .LMAX(LMAX), .FMT888(FMT888), .KNEE_II(KNEE_II)) bloom (
        .clk(clk), .rst(rst), .reg_we(reg_we), .reg_addr(sh[34:32]), .reg_wdata(sh[31:0]), .reg_rdata(rdata),
        .s_tdata(s_px), .s_tvalid(s_v), .s_tready(s_rdy), .s_tuser(s_u), .s_tlast(s_l),
        .c_tdata(c_px), .c_tvalid(c_v), .c_tready(c_rdy), .c_tuser(c_u), .c_tlast(c_l),
        .m_tdata(m_d), .m_tvalid(m_v), .m_tready(!o_full), .m_tuser(m_u), .m_tlast(m_l));

    // ---- pixels to bytes ---------------------------------------------
    reg o_u, o_l;
    always @(posedge clk) begin
        if (rst) begin
            o_full <= 1'b0;
            o_n <= 0;
            out_v <= 1'b0;
        end else begin
            if (out_v && out_rdy) out_v <= 1'b0;
            if (!o_full && m_v) begin
                o_full <= 1'b1;
                o_px <= m_d;
                o_u <= m_u;
                o_l <= m_l;
                o_n <= 0;
            end else if (o_full && (!out_v || out_rdy)) begin
                out_v <= 1'b1;
                out_d <= o_px[7:0];
                out_user <= o_u && o_n == 0;
                out_last <= o_l && o_n == NB - 1;
                o_px <= o_px >> 8;
                o_n <= o_n + 1'b1;
                if (o_n == NB - 1) o_full <= 1'b0;
            end
        end
    end
endmodule
`default_nettype wire
