/* The default pipeline's stages as row functions, shared by the presets
 * built on it (unity, attenuation). */
#ifndef BLOOM_GRAPH_ROWS_H
#define BLOOM_GRAPH_ROWS_H

#include "bloom_presets.h"

bool bg_fn_d1(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
              void *dst);
bool bg_fn_box(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
               void *dst);
bool bg_fn_add_tent(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                    void *dst);
bool bg_fn_out_add(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                   void *dst);
/* Whether output row function fn writes a tile's row in place from
 * column bg_out_x0 (bg_fn_out_add and its 16-bit twin): bloom_plan asks. */
bool bg_out_from_x0(bg_row_fn fn);

/* The default pipeline's graph (built) turned to 16-bit rows (cfg.sample_bits
 * = 16) on levels 1 .. BLOOM_S16_LEVELS: its stages' 16-bit twins, d1_16
 * for the first stage (bg_s16_d1 over the preset's own), par->s16 and the
 * scratch row they use; a stage without a twin fails the graph. Not in
 * builds without BLOOM_USE_S16. */
void bloom_stages_s16(bg_graph_t *g, bg_params_t *par, bg_row_fn d1_16);
/* The default's first stage on 16-bit rows (bg_s16_d1 over bg_fn_d1). */
bool bg_fn_d1_16(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                 void *dst);
/* A 16-bit first stage: d1's 32-bit row (in scratch row 0), narrowed. */
bool bg_s16_d1(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
               void *dst, bg_row_fn d1);

/* The default pipeline's down and up chains with d1_fn making level 1
 * (input 0: source rows 2r-1 .. 2r+2; input 1 with d1_aux: aux rows
 * 2r .. 2r+1), every node zero-preserving. Returns the node of U_1 (D_1
 * when L = 1). */
int bg_build_updown(bg_graph_t *g, bg_row_fn d1_fn, bool d1_aux);
/* The output node S + I * tent(U_1) reading node u1; sets g->out_node.
 * (Inline: the default's build hook is its only caller in a default-only
 * build, the Cortex-M flash figure.) */
static inline int bg_build_out_add(bg_graph_t *g, int u1)
{
    const int o = bg_node(g, bg_fn_out_add, g->w[0], g->h[0], 3, 0);
    bg_input(g, o, u1, BG_UP, -1, 1);
    bg_input(g, o, BG_SRC, BG_SAME, 0, 0);
    return g->out_node = o;
}

#endif
