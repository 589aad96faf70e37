/* Graph construction for the presets' build hooks and the helpers their
 * row functions share (bloom_graph.h). */
#include "bloom_graph.h"

#include <string.h>

/* ---- construction ------------------------------------------------------ */

void bg_levels(bg_graph_t *g, int n)
{
    int fw = g->frame_w, fh = g->frame_h;
    g->L = 1;
    for (int k = 1; k <= BLOOM_MAX_LEVELS; k++) {
        fw = BLOOM_SMALL ? (g->w[k - 1] + 1) / 2 : (fw + 1) / 2; /* (no tiles: the frame is the window) */
        fh = BLOOM_SMALL ? (g->h[k - 1] + 1) / 2 : (fh + 1) / 2;
        if (k > 1 && (k > n || imin(fw, fh) < 2))
            break;
        g->w[k] = (g->w[k - 1] + 1) / 2;
        g->h[k] = (g->h[k - 1] + 1) / 2;
        g->L = k;
    }
}

int bg_node(bg_graph_t *g, bg_row_fn fn, int w, int h, int ch, int level)
{
    if (g->nnodes >= g->node_cap) {
        g->failed = true;
        return -1;
    }
    bg_node_t *n = &g->node[g->nnodes];
    memset(n, 0, sizeof *n);
    n->fn = fn;
    n->w = w;
    n->h = h;
    n->ch = (uint8_t)ch;
#if BLOOM_USE_S16
    n->sb = 4;
#endif
    n->level = (int8_t)level;
    return g->nnodes++;
}

void bg_input(bg_graph_t *g, int n, int from, bg_map_t map, int lo, int hi)
{
    if (n < 0 || g->node[n].nin >= BG_MAX_IN) { /* no node (out of room), or too many inputs */
        g->failed = true;
        return;
    }
    bg_node_t *nd = &g->node[n];
#if !BLOOM_SMALL || BLOOM_USE_GRAPH
    /* A build hook's mistakes (a size build of the default alone leaves these
     * checks out: its only graph is the default's, which every other build
     * checks the same way; with presets in it, it keeps them):
     * inputs built before their readers, a bit of zin per row, at most
     * BG_MAX_ROWS rows gathered for one node row. */
    int rows = hi - lo + 1;
    for (int i = 0; i < nd->nin; i++)
        rows += nd->in[i].hi - nd->in[i].lo + 1;
    if (n >= g->nnodes || from >= n || from < BG_AUX || lo > hi || hi - lo > 30 || rows > BG_MAX_ROWS) {
        g->failed = true;
        return;
    }
#endif
    nd->in[nd->nin++] = (bg_input_t){(int8_t)from, (uint8_t)map, (int8_t)lo, (int8_t)hi};
}

/* ---- helpers for row functions ---------------------------------------- */

void bg_decode_row(const bg_ctx_t *ctx, const uint8_t *src, uint32_t *dst)
{
    const int bpp = ctx->src_bpp;
    for (int x = 0; x < ctx->w0; x++)
        bloom_pixel_decode(ctx->par.out.in_fmt, ctx->par.out.linear, src + (size_t)x * (size_t)bpp,
                           dst + 3 * x);
}

#if BLOOM_USE_GRAPH
uint32_t bg_aux_q16(const bg_ctx_t *ctx, const void *row, int x)
{
    if (ctx->aux_bpp == 2) { /* BLOOM_AUX_U16 */
        uint16_t c16;        /* rows need not be 2-byte aligned */
        memcpy(&c16, (const uint8_t *)row + 2 * x, 2);
        const uint32_t c = c16;
        return c + ((c + 32768u) >> 16); /* c * 65536 / 65535, rounded: exact at 0 and 65535 */
    }
    const uint32_t c = ((const uint8_t *)row)[x];
    return c * 257u + (c >= 128u); /* (c * 65536 + 127) / 255: c * 65536 = 255 * 257c + c */
}

/* The same code as a Q24 fraction of the plane's top code, rounded (the
 * attenuation factor: at Q16 a constant depth gave every pixel the same
 * rounding, up to 1.2e-5 of a bright sample). */
uint32_t bg_aux_q24(const bg_ctx_t *ctx, const void *row, int x)
{
    if (ctx->aux_bpp == 2) { /* BLOOM_AUX_U16 */
        uint16_t c16;
        memcpy(&c16, (const uint8_t *)row + 2 * x, 2);
        const uint32_t c = c16; /* c 2^24 / 65535 = 256 c + 256 c / 65535 */
        return 256u * c + (256u * c + 32767u) / 65535u;
    }
    const uint32_t c = ((const uint8_t *)row)[x];
    return 65793u * c + (c >= 128u); /* c 2^24 / 255 = 65793 c + c / 255 */
}
#endif
