/* Row functions shared by the presets (bloom_graph.h): the default
 * pipeline's stages as graph nodes. Each is a thin wrapper of a row kernel
 * of bloom_row.c, so a preset built from them computes the default's bits. */
#include "bloom_graph_rows.h"

#include <string.h>

#if BLOOM_USE_GRAPH

/* Input 0: source rows base-1 .. base+2 (BG_DOWN). Box down, then the knee. */
void bg_fn_d1(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
              void *dst)
{
    (void)r;
    const uint8_t *const s[4] = {(const uint8_t *)in[0][0], (const uint8_t *)in[0][1],
                                 (const uint8_t *)in[0][2], (const uint8_t *)in[0][3]};
    bloom_row_box_src_c(s, g->out.in_fmt, g->out.linear, (uint32_t *)dst, n->w, g->w[0]);
    bloom_row_knee_c((uint32_t *)dst, n->w, &g->knee);
}

/* Input 0: node rows base-1 .. base+2 (BG_DOWN), 3 channels. Box down. */
void bg_fn_box(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
               void *dst)
{
    (void)r;
    const uint32_t *const s[4] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2], (const uint32_t *)in[0][3]};
    g->kern.box(s, (uint32_t *)dst, n->w, g->node[n->in[0].node].w);
}

/* Input 0: the same level's row (BG_SAME 0..0); input 1: the level below,
 * rows m-1 .. m+1 (BG_UP). dst = in0 + tent(in1). */
void bg_fn_add_tent(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                    void *dst)
{
    const uint32_t *const u[3] = {(const uint32_t *)in[1][0], (const uint32_t *)in[1][1],
                                  (const uint32_t *)in[1][2]};
    memcpy(dst, in[0][0], (size_t)n->w * 3u * sizeof(uint32_t));
    g->kern.tent(u, r & 1, (const uint32_t *)dst, (uint32_t *)dst, 0, n->w, g->node[n->in[1].node].w);
}

/* The output node of the additive pipelines. Input 0: the source row
 * (BG_SAME 0..0); input 1: level 1, rows m-1 .. m+1 (BG_UP).
 * out = S + I * tent(in1), encoded (bloom_row_out_c). */
void bg_fn_out_add(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                   void *dst)
{
    const uint32_t *const u[3] = {(const uint32_t *)in[1][0], (const uint32_t *)in[1][1],
                                  (const uint32_t *)in[1][2]};
    if (bloom_kernels_simd(&g->kern))
        bloom_row_out_k(&g->kern, u, r & 1, (const uint8_t *)in[0][0], (uint8_t *)dst, n->w,
                        g->node[n->in[1].node].w, &g->out);
    else
        bloom_row_out_c(u, r & 1, (const uint8_t *)in[0][0], (uint8_t *)dst, n->w, g->node[n->in[1].node].w,
                        &g->out);
}

int bg_build_updown(bloom_graph_t *g, bg_row_fn d1_fn, bool d1_aux)
{
    const int L = g->L;
    int D[BLOOM_MAX_LEVELS + 1], U;
    /* down chain: D1 from the source, Dk from D(k-1) */
    D[1] = bg_node(g, d1_fn, g->w[1], g->h[1], 3, 1);
    bg_input(g, D[1], BG_SRC, BG_DOWN, -1, 2);
    if (d1_aux)
        bg_input(g, D[1], BG_AUX, BG_DOWN, 0, 1);
    for (int k = 2; k <= L; k++) {
        D[k] = bg_node(g, bg_fn_box, g->w[k], g->h[k], 3, k);
        bg_input(g, D[k], D[k - 1], BG_DOWN, -1, 2);
    }
    /* up chain: U_L = D_L; U_k = D_k + tent(U_k+1). As in the default
     * engine, D_1 is computed a second time for the up pass and, when
     * L >= 3, D_2 from that copy: no delay line at the two widest levels. */
    int up[3] = {0, D[1], L >= 2 ? D[2] : -1};
    if (L >= 2) {
        up[1] = bg_node(g, d1_fn, g->w[1], g->h[1], 3, 1);
        bg_input(g, up[1], BG_SRC, BG_DOWN, -1, 2);
        if (d1_aux)
            bg_input(g, up[1], BG_AUX, BG_DOWN, 0, 1);
    }
    if (L >= 3) {
        up[2] = bg_node(g, bg_fn_box, g->w[2], g->h[2], 3, 2);
        bg_input(g, up[2], up[1], BG_DOWN, -1, 2);
    }
    U = D[L];
    for (int k = L - 1; k >= 1; k--) {
        const int u = bg_node(g, bg_fn_add_tent, g->w[k], g->h[k], 3, k);
        bg_input(g, u, k <= 2 ? up[k] : D[k], BG_SAME, 0, 0);
        bg_input(g, u, U, BG_UP, -1, 1);
        U = u;
    }
    return U;
}

#else
typedef int bloom_graph_rows_unused_t;
#endif
