// A harness for synthesizing (and placing and routing) one unit of the
// pipeline on its own (make check-fpga-synth): the unit's inputs come from a shift
// register fed by one pin, its outputs are registered and folded into one
// pin, so the tools keep every path and the unit needs three pins. The
// figure it gives is the unit's own Fmax and size, not the board's.
`default_nettype none
module bloom_harness #(
    parameter UNIT = 0          // 0 bloom_box (level 1), 1 bloom_up (level 0), 2 bloom_knee, 3 bloom_out
) (
    input wire clk,
    input wire din,
    output reg dout
);
    localparam IW = 256;
    reg [IW-1:0] sh;
    always @(posedge clk) sh <= {sh[IW-2:0], din};
    wire rst = sh[IW-1];
    wire [127:0] o;
    generate
        if (UNIT == 0) begin : g_box
            wire [62:0] d;
            wire v, r;
            bloom_box #(.SW(21), .XW(9), .YW(8), .WMAX(320)) u (
                .clk(clk), .rst(rst), .win(sh[8:0]), .hin(sh[16:9]), .in_valid(sh[17]), .in_ready(r),
                .in_data(sh[80:18]), .out_valid(v), .out_ready(sh[81]), .out_data(d));
            assign o = {r, v, d};
        end else if (UNIT == 1) begin : g_up
            wire [74:0] d;
            wire v, r, ar;
            bloom_up #(.UW(25), .SW(21), .XW(9), .YW(8), .WIMAX(160), .HAS_ADD(0)) u (
                .clk(clk), .rst(rst), .wi(sh[8:0]), .hi(sh[16:9]), .wo(sh[25:17]), .ho(sh[33:26]),
                .in_valid(sh[34]), .in_ready(r), .in_data(sh[109:35]), .add_valid(1'b0), .add_ready(ar),
                .add_data(63'd0), .out_valid(v), .out_ready(sh[110]), .out_data(d));
            assign o = {ar, r, v, d};
        end else if (UNIT == 3) begin : g_out
            wire [15:0] d;
            wire v, br, sr;
            bloom_out #(.UW(25), .FMT888(0)) u (
                .clk(clk), .rst(rst), .i_q(sh[23:0]), .debug(sh[24]), .b_valid(sh[25]), .b_ready(br),
                .b_data(sh[100:26]), .s_valid(sh[101]), .s_ready(sr), .s_data(sh[117:102]),
                .o_valid(v), .o_ready(sh[118]), .o_data(d));
            assign o = {br, sr, v, d};
        end else begin : g_knee
            wire [62:0] d;
            wire v, r;
            bloom_knee #(.SW(21), .II(3)) u (
                .clk(clk), .rst(rst), .t_q(sh[28:0]), .k_q(sh[57:29]), .in_valid(sh[58]), .in_ready(r),
                .in_data(sh[121:59]), .out_valid(v), .out_ready(sh[122]), .out_data(d));
            assign o = {r, v, d};
        end
    endgenerate
    reg [127:0] q;
    always @(posedge clk) begin
        q <= o;
        dout <= ^q;
    end
endmodule
`default_nettype wire
