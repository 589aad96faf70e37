/* The row-graph engine behind the presets other than the default.
 *
 * A preset is a small graph of row stages ("nodes"): each node makes rows
 * of one image (w x h, 1 or 3 samples per pixel, Q12.20 like the default
 * pipeline) from a few rows of its inputs: the source frame, the aux plane,
 * or other nodes. An input is read at rows base(r) + lo .. base(r) + hi,
 * clamped to the input's height (the edge rule), where base(r) is 2r (a
 * node at half the input's resolution), r (same resolution) or r >> 1
 * (twice the input's resolution). The engine is the default scheduler
 * generalised: pull-driven, every node keeps a ring of rows, and the ring
 * sizes come from a dry run of the same code (bloom_query). Nothing is
 * allocated; nothing is kept at full resolution but the source rows the
 * caller keeps readable (or the engine copies, BLOOM_FLAG_COPY_SOURCE).
 *
 * The output node is special: its row function writes the caller's
 * destination row (encoded pixels) instead of a ring slot. */
#ifndef BLOOM_GRAPH_H
#define BLOOM_GRAPH_H

#include <string.h>

#include "bloom_internal.h"

#define BG_MAX_NODES 48
#define BG_MAX_IN 3
#define BG_MAX_ROWS 40 /* input rows one node row reads, all inputs together */
#define BG_SRC (-1)    /* input: the source frame (encoded pixels) */
#define BG_AUX (-2)    /* input: the aux plane (uint8_t or uint16_t per pixel) */

typedef enum {
    BG_DOWN, /* base(r) = 2r: the node has half the input's resolution */
    BG_SAME, /* base(r) = r */
    BG_UP    /* base(r) = r >> 1: the node has twice the input's resolution */
} bg_map_t;

typedef struct bloom_graph bloom_graph_t;
typedef struct bg_node bg_node_t;

/* Row r of node n. in[i][j] is row base(r) + lo_i + j of input i (clamped),
 * j = 0 .. hi_i - lo_i: const uint8_t * pixels for BG_SRC, const uint8_t *
 * or const uint16_t * for BG_AUX, const uint32_t * samples for a node.
 * dst is the node's ring slot (w * ch uint32_t), or for the output node the
 * caller's row of encoded pixels. */
typedef void (*bg_row_fn)(const bloom_graph_t *g, const bg_node_t *n, int r,
                          const void *const *const in[BG_MAX_IN], void *dst);

typedef struct {
    int node; /* node index, BG_SRC or BG_AUX */
    bg_map_t map;
    int lo, hi;
} bg_input_t;

struct bg_node {
    bg_row_fn fn;
    int w, h, ch; /* size; ch = samples per pixel (1 or 3) */
    int level;    /* pyramid level it belongs to (row memory per level) */
    int nin;
    bg_input_t in[BG_MAX_IN];
    uint32_t k[4]; /* the row function's constants */
    /* ring (not for the output node) */
    uint32_t *buf;
    int32_t *tag;
    int cap;
    int next; /* next row to compute */
    int need; /* dry run: largest occupancy */
};

struct bloom_graph {
    bloom_config_t cfg;
    int L; /* pyramid depth the preset uses */
    int w[BLOOM_MAX_LEVELS + 1], h[BLOOM_MAX_LEVELS + 1];
    bloom_knee_t knee;    /* threshold and knee, Q12.20 */
    bloom_out_t out;      /* formats, sRGB or linear, I_q */
    bloom_kernels_t kern; /* row kernels (C or SIMD, same bits) */
    int nnodes, out_node;
    bg_node_t node[BG_MAX_NODES];
    /* scratch rows for row functions: BG_SCRATCH rows of scratch_len words */
    uint32_t *scratch;
    size_t scratch_len;
    int scratch_rows; /* rows the preset's row functions use; a build hook that
                         leaves it at -1 gets BG_SCRATCH */
    /* source and aux rings: one slot per pushed row, the same for both */
    const uint8_t **src_ptr, **aux_ptr;
    uint8_t *src_copy, *aux_copy;
    int32_t *src_tag;
    int src_cap;
    size_t src_row_bytes, aux_row_bytes;
    int src_bpp, aux_bpp;
    const uint8_t *aux_frame; /* bloom_set_aux */
    ptrdiff_t aux_stride;
    /* progress */
    int src_n;
    bool failed, dry;
    int need_src, latency;
};
#define BG_SCRATCH 4

/* Preset hooks: defaults, parameter checks, graph construction. build()
 * sets g->L, sizes, the nodes and g->out_node; g->cfg, g->knee, g->out and
 * the level sizes of the common rule (bg_levels) are set before. */
typedef struct {
    const char *name;
    void (*defaults)(bloom_config_t *cfg);
    bloom_status_t (*validate)(const bloom_config_t *cfg);
    bloom_status_t (*build)(bloom_graph_t *g);
} bloom_preset_ops_t;

#if BLOOM_USE_GAMEDEV
extern const bloom_preset_ops_t bloom_preset_gamedev;
#endif
#if BLOOM_USE_XNA
extern const bloom_preset_ops_t bloom_preset_xna;
#endif
#if BLOOM_USE_ATTENUATION
extern const bloom_preset_ops_t bloom_preset_attenuation;
#endif
#if BLOOM_USE_ARM
extern const bloom_preset_ops_t bloom_preset_arm;
#endif
#if BLOOM_USE_COD
extern const bloom_preset_ops_t bloom_preset_cod;
#endif
/* The hooks of preset p, or NULL if unknown or compiled out. */
const bloom_preset_ops_t *bloom_preset_ops(bloom_preset_t p);

/* ---- graph construction (for build hooks) ---------------------------- */

/* Level sizes by the common rule (bloom-model.md) for n requested levels;
 * sets g->L, g->w, g->h. */
void bg_levels(bloom_graph_t *g, int n);
/* A node of w x h x ch at `level`; returns its index, or -1 when full. */
int bg_node(bloom_graph_t *g, bg_row_fn fn, int w, int h, int ch, int level);
/* Node n reads input `from` at rows base(r) + lo .. base(r) + hi. */
void bg_input(bloom_graph_t *g, int n, int from, bg_map_t map, int lo, int hi);

/* ---- helpers for row functions --------------------------------------- */

/* Scratch row i (0 .. g->scratch_rows - 1) of g->scratch_len words (at least
 * 3 * width + 16). Row functions run one at a time: a scratch row is free
 * again when the function returns. */
static inline uint32_t *bg_scratch(const bloom_graph_t *g, int i)
{
    return g->scratch + (size_t)i * g->scratch_len;
}
/* A source row decoded to Q12.20 R, G, B (w0 pixels). */
void bg_decode_row(const bloom_graph_t *g, const uint8_t *src, uint32_t *dst);
/* Aux sample x of an aux row, scaled to Q16 (0 .. 65536): code * 65536 / max
 * rounded half up (exact for U16: 65535 -> 65536). */
uint32_t bg_aux_q16(const bloom_graph_t *g, const void *row, int x);
uint32_t bg_aux_q24(const bloom_graph_t *g, const void *row, int x);

/* ---- shared with the default engine (bloom.c) --------------------------- */

/* bloom_query's description of a planned engine: zeroes info, then sets the
 * level count L and sizes w/h[0..L], the latency, the source rows
 * (need_src, at least 1) and the quantized knee and intensity. The caller
 * adds the ring and workspace bytes (its carve). Inline: the minimal
 * firmware (no presets) keeps its size. */
static inline void bloom_info_fill(bloom_info_t *info, int L, const int *w, const int *h, int latency,
                                   int need_src, const bloom_knee_t *knee, const bloom_out_t *out)
{
    memset(info, 0, sizeof *info);
    info->levels = L;
    for (int k = 0; k <= L; k++) {
        info->level_w[k] = w[k];
        info->level_h[k] = h[k];
    }
    info->latency_rows = latency;
    info->source_rows = need_src > 1 ? need_src : 1;
    info->threshold_q = knee->t;
    info->knee_q = knee->k;
    info->intensity_q = out->intensity;
}

/* ---- the engine (bloom.c dispatches here) ----------------------------- */

bloom_status_t bloom_graph_validate(const bloom_config_t *cfg);
/* Plan g from cfg (build + dry run); fills info if not NULL. */
bloom_status_t bloom_graph_plan(bloom_graph_t *g, const bloom_config_t *cfg, bloom_info_t *info);
/* Bytes of the graph engine's workspace after the plan (g planned). */
uint64_t bloom_graph_carve(bloom_graph_t *g, uint8_t *base, size_t *per_level);
bloom_status_t bloom_graph_begin(bloom_graph_t *g);
bloom_status_t bloom_graph_push(bloom_graph_t *g, const void *src_row, const void *aux_row);
bloom_status_t bloom_graph_pull(bloom_graph_t *g, void *dst_row);

#endif
