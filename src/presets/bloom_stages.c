/* The default pipeline's stages as row functions (bloom_stages.h): the
 * box with the knee, the box, the tent with its add, the output. Each is a
 * thin wrapper of the row kernels of bloom_row.c (C or their SIMD twins,
 * the same bits), so every preset built from them computes the default's
 * bits, and each takes the zero-row shortcuts its inputs allow. */
#include "bloom_stages.h"

#include <string.h>

/* Input 0: source rows base-1 .. base+2 (BG_DOWN). Box down, then the knee;
 * false when the row came out all zero. */
bool bg_fn_d1(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
              void *dst)
{
    const uint8_t *const s[4] = {(const uint8_t *)in[0][0], (const uint8_t *)in[0][1],
                                 (const uint8_t *)in[0][2], (const uint8_t *)in[0][3]};
#if BLOOM_SMALL
    (void)r;
    bloom_row_box_src_c(s, ctx->par.out.in_fmt, ctx->par.out.linear, (uint32_t *)dst, n->w, ctx->w0);
    return bloom_row_knee_c((uint32_t *)dst, n->w, &ctx->par.knee);
#else
    /* the same (the SIMD kernels skip the box where the knee zeroes anyway),
     * the upper rows' sums taken from the row before where it kept them */
    bloom_d1_keep_t *kp = ctx->d1_keep;
    if (kp)
        kp->y = r;
    return ctx->kern.d1(s, ctx->par.out.in_fmt, ctx->par.out.linear, (uint32_t *)dst, n->w,
                        bg_in_w(ctx, n, 0), &ctx->par.knee, &ctx->dark, kp);
#endif
}

/* Input 0: node rows base-1 .. base+2 (BG_DOWN), 3 channels. Box down. */
bool bg_fn_box(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
               void *dst)
{
    (void)r;
    const uint32_t *const s[4] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2], (const uint32_t *)in[0][3]};
    ctx->kern.box(s, (uint32_t *)dst, n->w, bg_node_in_w(ctx, n, 0));
    return true;
}

/* Input 0: the level below, rows m-1 .. m+1 (BG_UP); input 1: the same
 * level's row (BG_SAME 0..0). dst = in1 + tent(in0): the tent alone where
 * in1 is zero, a copy of in1 where the rows below are (both zero: the node
 * is zero-preserving, never run). */
bool bg_fn_add_tent(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                    void *dst)
{
    const uint32_t *d = (const uint32_t *)in[1][0];
    if (bg_in_zero(ctx, 0, 0, 2)) {
        memcpy(dst, d, (size_t)n->w * 3u * sizeof *d);
        return true;
    }
    const uint32_t *const u[3] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2]};
    ctx->kern.tent(u, r & 1, bg_in_zero(ctx, 1, 0, 0) ? NULL : d, (uint32_t *)dst, 0, n->w,
                   bg_node_in_w(ctx, n, 0));
    return true;
}

/* The output node of the additive pipelines. Input 0: level 1, rows
 * m-1 .. m+1 (BG_UP); input 1: the source row (BG_SAME 0..0).
 * out = S + I * tent(in0), encoded (bloom_row_out_c); where in0 is all
 * zero, B = 0: the source row copied (bloom_row_copy_c). */
bool bg_fn_out_add(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                   void *dst)
{
    const int x0 = bg_out_x0(ctx); /* (a tile's row in place: dst is column x0) */
    const uint8_t *src = (const uint8_t *)in[1][0] + (size_t)bg_out_src_x(ctx) * ctx->src_bpp;
    const int sw = bg_node_in_w(ctx, n, 0);
    const uint32_t *const u[3] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2]};
    if (bg_in_zero(ctx, 0, 0, 2))
        bg_copy_row(ctx, src, (uint8_t *)dst, n->w - x0);
    else if (!BLOOM_SMALL && ctx->kern.htent_eo) /* the flat kernels: every set but BLOOM_SMALL's */
        bloom_row_out_k(&ctx->kern, u, r & 1, src, (uint8_t *)dst, x0, n->w, sw, &ctx->par.out);
    else /* (x0 0: bloom_plan writes a row in place only with the flat kernels) */
        bloom_row_out_c(u, r & 1, src, (uint8_t *)dst, n->w, sw, &ctx->par.out);
    return true;
}

#if BLOOM_USE_S16
/* The same stages on 16-bit rows (bloom_row16.c; bloom_stages_s16). */

bool bg_s16_d1(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
               void *dst, bg_row_fn d1)
{
    uint32_t *t = bg_scratch(ctx, 0);
    (void)d1(ctx, n, r, in, t);
    return bloom_row_narrow16_k(&ctx->kern, t, (uint16_t *)dst, n->w * 3, ctx->par.s16) != 0;
}

bool bg_fn_d1_16(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                 void *dst)
{
    return bg_s16_d1(ctx, n, r, in, dst, bg_fn_d1);
}

/* A box of 16-bit rows: into a 16-bit level, or (the node's own samples
 * 32-bit) into the first 32-bit level, BLOOM_S16_LEVELS + 1, its sums
 * widened (<< (F - G)) and rounded as the 32-bit box rounds. */
static bool fn_box16(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                     void *dst)
{
    (void)r;
    const uint16_t *const s[4] = {(const uint16_t *)in[0][0], (const uint16_t *)in[0][1],
                                  (const uint16_t *)in[0][2], (const uint16_t *)in[0][3]};
    bloom_row_box16_k(&ctx->kern, s, dst, n->sb == 4, n->w, bg_node_in_w(ctx, n, 0), ctx->par.s16);
    return true;
}

/* U_k = D_k + tent(U_k+1) on a 16-bit level. Below the last 16-bit level
 * (BLOOM_S16_LEVELS) the rows read are 32-bit: their tent, in scratch row
 * 0, is narrowed (half to even) before D_k is added. */
static bool fn_add_tent16(const bg_ctx_t *ctx, const bg_node_t *n, int r,
                          const void *const *const in[BG_MAX_IN], void *dst)
{
    const uint16_t *d = (const uint16_t *)in[1][0];
    if (bg_in_zero(ctx, 0, 0, 2)) {
        memcpy(dst, d, (size_t)n->w * 3u * sizeof *d);
        return true;
    }
    const uint16_t *add = bg_in_zero(ctx, 1, 0, 0) ? NULL : d;
    const int sw = bg_node_in_w(ctx, n, 0);
    if (ctx->node[n->in[0].node].sb == 4) {
        const uint32_t *const u[3] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                      (const uint32_t *)in[0][2]};
        uint32_t *t = bg_scratch(ctx, 0);
        ctx->kern.tent(u, r & 1, NULL, t, 0, n->w, sw);
        bloom_row_narrow16_add_k(&ctx->kern, t, add, (uint16_t *)dst, n->w * 3, ctx->par.s16);
    } else {
        const uint16_t *const u[3] = {(const uint16_t *)in[0][0], (const uint16_t *)in[0][1],
                                      (const uint16_t *)in[0][2]};
        bloom_row_tent16_k(&ctx->kern, u, r & 1, add, (uint16_t *)dst, n->w, sw);
    }
    return true;
}

/* The output of U_1's 16-bit rows: bg_fn_out_add with the tent widening
 * the samples in its sums (bloom_row_out16_k). */
static bool fn_out_add16(const bg_ctx_t *ctx, const bg_node_t *n, int r,
                         const void *const *const in[BG_MAX_IN], void *dst)
{
    const int x0 = bg_out_x0(ctx);
    const uint8_t *src = (const uint8_t *)in[1][0] + (size_t)bg_out_src_x(ctx) * ctx->src_bpp;
    const uint16_t *const u[3] = {(const uint16_t *)in[0][0], (const uint16_t *)in[0][1],
                                  (const uint16_t *)in[0][2]};
    if (bg_in_zero(ctx, 0, 0, 2))
        bg_copy_row(ctx, src, (uint8_t *)dst, n->w - x0);
    else
        bloom_row_out16_k(&ctx->kern, u, ctx->par.s16, r & 1, src, (uint8_t *)dst, x0, n->w,
                          bg_node_in_w(ctx, n, 0), &ctx->par.out);
    return true;
}

void bloom_stages_s16(bg_graph_t *g, bg_params_t *par, bg_row_fn d1_16)
{
    par->s16 = (uint8_t)(BLOOM_LIN_BITS - bloom_s16_frac(g->L, bloom_knee_peak(&par->knee)));
    /* one row of level 1 in the internal format: D_1 before it is narrowed,
     * or the tent out of the first 32-bit level before it is */
    par->scratch_rows = imax(par->scratch_rows, 1);
    par->scratch_len = (size_t)g->w[1] * 3u + 16u;
    const int top = BLOOM_S16_LEVELS; /* levels 1 .. top 16-bit, the deeper ones 32-bit */
    for (int i = 0; i < g->nnodes; i++) {
        bg_node_t *n = &g->node[i];
        const int k = n->level;
        if (k > top + 1 || (k == top + 1 && n->fn != bg_fn_box)) /* 32-bit, reading 32-bit rows */
            continue;
        const bool d1 = k == 1 && n->nin >= 1 && n->in[0].node == BG_SRC; /* the first stage */
        n->fn = d1                        ? d1_16
                : n->fn == bg_fn_box      ? fn_box16      /* (into level top + 1: 32-bit samples) */
                : n->fn == bg_fn_add_tent ? fn_add_tent16 /* (at level top: reads 32-bit rows) */
                : n->fn == bg_fn_out_add  ? fn_out_add16
                                          : NULL; /* (no other stage has a 16-bit twin) */
        if (!n->fn)
            g->failed = true;
        if (i != g->out_node && k <= top)
            bg_s16(g, i);
    }
}
#endif

/* A zero-preserving node of level k (w, h of the level, 3 channels) made by
 * fn from rows 2r-1 .. 2r+2 of `from`, and with aux from aux rows 2r .. 2r+1. */
static int down_node(bg_graph_t *g, bg_row_fn fn, int k, int from, bool aux)
{
    const int n = bg_node(g, fn, g->w[k], g->h[k], 3, k);
    bg_input(g, n, from, BG_DOWN, -1, 2);
    if (BLOOM_USE_GRAPH && aux) /* (only a preset reads an aux plane) */
        bg_input(g, n, BG_AUX, BG_DOWN, 0, 1);
    bg_zero(g, n);
    return n;
}

int bg_build_updown(bg_graph_t *g, bg_row_fn d1_fn, bool d1_aux)
{
    const int L = g->L;
    int D[BLOOM_MAX_LEVELS + 1];
    D[1] = D[2] = -1; /* (L >= 1 always: for the compiler) */
    /* down chain: D1 from the source, Dk from D(k-1) */
    for (int k = 1; k <= L; k++)
        D[k] = k == 1 ? down_node(g, d1_fn, 1, BG_SRC, d1_aux) : down_node(g, bg_fn_box, k, D[k - 1], false);
    /* up chain: U_L = D_L; U_k = D_k + tent(U_k+1). D_1 is computed a
     * second time for the up pass and, when L >= 3, D_2 from that copy: no
     * delay line at the two widest levels (sim/docs/streaming.md). */
    int up1 = D[1], up2 = L >= 2 ? D[2] : -1;
    if (L >= 2)
        up1 = down_node(g, d1_fn, 1, BG_SRC, d1_aux);
    if (L >= 3)
        up2 = down_node(g, bg_fn_box, 2, up1, false);
    int U = D[L];
    for (int k = L - 1; k >= 1; k--) {
        const int u = bg_node(g, bg_fn_add_tent, g->w[k], g->h[k], 3, k);
        bg_input(g, u, U, BG_UP, -1, 1); /* first: the same level's row is made when the one below is ready */
        bg_input(g, u, k == 1 ? up1 : k == 2 ? up2 : D[k], BG_SAME, 0, 0);
        bg_zero(g, u);
        U = u;
    }
    return U;
}

#if !BLOOM_SMALL
bool bg_out_from_x0(bg_row_fn fn)
{
#if BLOOM_USE_S16
    if (fn == fn_out_add16)
        return true;
#endif
    return fn == bg_fn_out_add;
}
#endif
