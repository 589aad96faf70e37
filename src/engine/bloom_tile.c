/* A tile's plan (engine/, bloom.c's bloom_plan drives it): how far the
 * output's pixels reach into the source (the halo), the window of the
 * frame a tile reads, and the columns each node of that window makes.
 * sim/docs/tiles.md has the figures. */
#include <limits.h>

#include "bloom_engine.h"
#include "bloom_internal.h"

#if !BLOOM_SMALL
/* How far (in frame pixels, either way) the output node's pixels reach into
 * the source: the halo of a tile. Walked down the graph: a pixel p at
 * resolution 2^-k covers frame pixels [p 2^k, (p + 1) 2^k - 1]; an input at
 * resolution 2^-e read at rows base(p) + lo .. base(p) + hi adds, exactly
 * (not a pixel more for the rounding: a margin above the reach costs every
 * strip its work and memory), on the low side -lo 2^e (BG_DOWN, BG_SAME) or
 * 2^(e-1) - lo 2^e (BG_UP, p odd), on the high side (hi - 1) 2^e, hi 2^e or
 * (2 hi + 1) 2^(e-1), plus the input's own reach. Resolutions come from the
 * maps, not the nodes' memory levels. A kernel reaches as far across as its
 * rows reach down (box, tents, Gaussian, Kawase, 13-tap: square
 * footprints); the halo is the larger side, for both axes, so a kernel whose
 * columns mirror its rows is covered too. (Default 5 levels: 124.)
 *
 * Worked example, the default at 2 levels (before, after):
 *   D1 reads the source (e 0) DOWN at -1 .. 2:          1, 1
 *   D2 reads D1 (e 1) DOWN at -1 .. 2: 2, 2 + D1's 1, 1 = 3, 3
 *   U1 reads D2 (e 2) UP at -1 .. 1: 2 + 4, 3 * 2 + D2's = 9, 9
 *      (and D1's copy SAME at 0 .. 0: 1, 1; the larger is kept)
 *   out reads U1 (e 1) UP at -1 .. 1: 1 + 2, 3 * 1 + 9 = 12, 12
 * so the halo is 12: a strip of columns 0 .. 63 reads source columns
 * 0 .. 75 (76 is a multiple of 2^L). */
static int tile_halo(const bloom_t *g)
{
    /* per node: how far its pixels reach into the source before and after
     * their own span (frame pixels), and log2 of its pixel's size in frame
     * pixels */
    int reach_lo[BG_MAX_NODES], reach_hi[BG_MAX_NODES], px_log2[BG_MAX_NODES];
    for (int i = 0; i < g->gr.nnodes; i++) {
        const bg_node_t *n = &g->gr.node[i];
        reach_lo[i] = reach_hi[i] = 0;
        px_log2[i] = 0;
        for (int j = 0; j < n->nin; j++) {
            const bg_input_t *in = &n->in[j];
            const int from = in->node, e = from < 0 ? 0 : px_log2[from];
            /* a pixel finer than the frame's (e < 0: no preset builds one)
             * counts as a frame pixel: a reach above the true one, never below */
            const int s = 1 << imax(e, in->map == BG_UP ? 1 : 0), lo = in->lo, hi = in->hi;
            const int flo = from < 0 ? 0 : reach_lo[from], fhi = from < 0 ? 0 : reach_hi[from];
            int l, h;
            if (in->map == BG_DOWN) {
                l = -lo * s, h = (hi - 1) * s;
            } else if (in->map == BG_SAME) {
                l = -lo * s, h = hi * s;
            } else { /* BG_UP: the input has twice the pixel size (e >= 1) */
                l = s / 2 - lo * s, h = (2 * hi + 1) * (s / 2);
            }
            reach_lo[i] = imax(reach_lo[i], l + flo);
            reach_hi[i] = imax(reach_hi[i], h + fhi);
            if (j == 0)
                px_log2[i] = e + (in->map == BG_DOWN ? 1 : in->map == BG_UP ? -1 : 0);
        }
    }
    return imax(0, imax(reach_lo[g->gr.out_node], reach_hi[g->gr.out_node]));
}

/* [a, b) of a frame side n around [t, t + tn): the margin m either side,
 * then out to multiples of `align` (the window's levels then halve like the
 * frame's), within the frame. */
static void window_side(int t, int tn, int n, int m, int align, int *a, int *b)
{
    const long lo = (long)t - m, hi = (long)t + tn + m;
    *a = lo <= 0 ? 0 : (int)(lo / align * align);
    *b = hi >= n ? n : (int)imin(n, (int)((hi + align - 1) / align * align));
}

/* The columns each node of a tile's window makes: what its readers read,
 * walked back from the output (the tile's columns; the output node is most
 * of the work, and its halo columns would be thrown away). A node's first
 * column xa is the first one needed less the pixels its kernels would
 * spoil by clamping their reads at xa's input columns (an UP input read
 * from column m + lo, m = x >> 1, spoils x < -2 lo; DOWN, 2x + lo:
 * x < ceil(-lo / 2); SAME: x < -lo), even when it reads an UP input (the
 * tents' weights go by the column's parity); none at the level's edge 0,
 * where clamping is the edge rule. Its last is the last needed plus, for a
 * SAME input read to column x + hi, hi more (kernels that clamp at their
 * own width, as a horizontal pass does); its inputs are made as far as it
 * reads, or to the edge, where the kernels' clamp at bg_in_w (or at their
 * own width) is the edge rule again. Without the preset's views only the
 * output node is narrowed (every preset's output row function reads its
 * widths by bg_in_w); the others make every column. */
void bloom_tile_cut(bloom_t *g)
{
    /* per node: the first column its readers read, and one past the last */
    int first_read[BG_MAX_NODES], end_read[BG_MAX_NODES];
    for (int i = 0; i < g->gr.nnodes; i++)
        first_read[i] = INT_MAX, end_read[i] = INT_MIN;
    first_read[g->gr.out_node] = g->tile_x0;
    end_read[g->gr.out_node] = g->tile_x1;
    for (int i = g->gr.out_node; i >= 0; i--) { /* readers come after their inputs */
        bg_node_t *n = &g->gr.node[i];
        int a = 0, b = n->w, spoil = 0, spoil_r = 0, up = 0;
        if ((g->row.par.views || i == g->gr.out_node) && first_read[i] < end_read[i]) {
            for (int j = 0; j < n->nin; j++) {
                const int lo = n->in[j].lo, map = n->in[j].map;
                spoil = imax(spoil, map == BG_UP ? -2 * lo : map == BG_DOWN ? (1 - lo) / 2 : -lo);
                spoil_r = imax(spoil_r, map == BG_SAME ? n->in[j].hi : 0);
                up |= map == BG_UP;
            }
            a = imax(0, first_read[i] - spoil);
            a = up ? a & ~1 : a;
            b = imin(n->w, end_read[i] + spoil_r);
        }
        n->xa = a;
        n->w = b - a;
        for (int j = 0; j < n->nin; j++) {
            const bg_input_t *in = &n->in[j];
            if (in->node < 0)
                continue;
            const int m = in->map, f = in->node, wf = g->gr.node[f].w;
            const int first = bg_base(m, a), last = bg_base(m, b - 1) + in->hi;
            first_read[f] = imin(first_read[f], first);
            end_read[f] = imax(end_read[f], imin(last + 1, wf));
        }
    }
}

void bloom_tile_window(const bloom_t *g, const bloom_config_t *cfg, int *x0, int *y0, int *x1, int *y1)
{
    const int align = 1 << g->gr.L, m = tile_halo(g);
    window_side(cfg->tile_x, cfg->tile_w, cfg->width, m, align, x0, x1);
    window_side(cfg->tile_y, cfg->tile_h, cfg->height, m, align, y0, y1);
}
#endif
