/* The engine's graph (one engine for every preset): a preset is a small
 * graph of row stages ("nodes") that its build hook makes with the
 * functions below (graph/bloom_graph.c); the scheduler (engine/) makes
 * their rows, pulled by the output.
 *
 * Each node makes rows of one image (w x h, 1 or 3 samples per pixel,
 * Q12.20) from a few rows of its inputs: the source frame, the aux plane,
 * or other nodes. An input is read at rows base(r) + lo .. base(r) + hi,
 * clamped to the input's height (the edge rule), where base(r) is 2r (a
 * node at half the input's resolution), r (same resolution) or r >> 1
 * (twice the input's resolution). Every node keeps a ring of rows; the ring
 * sizes come from a dry run of the same scheduler (bloom_query). Nothing is
 * allocated; nothing is kept at full resolution but the source rows the
 * caller keeps readable (or the engine copies, BLOOM_FLAG_COPY_SOURCE).
 *
 * Zero rows: a ring slot whose tag carries BLOOM_TAG_ZERO holds a row known
 * to be all zero (its samples are zeros: readers need not know). A node
 * marked zero-preserving (bg_zero) whose input rows are all zero is not
 * run; a row function that returns false made an all-zero row. A source
 * row tagged dark (no channel above the preset's dark codes) counts as zero
 * for the zero-preserving nodes that read the source (the first stage,
 * which the dark codes are computed for); the aux plane does not count (a
 * factor). Row functions see which of their input rows are zero in
 * ctx->zin (bit j of zin[i]: row j of input i) and may take shortcuts.
 *
 * The output node is special: its row function writes the caller's
 * destination row (encoded pixels) instead of a ring slot. */
#ifndef BLOOM_GRAPH_H
#define BLOOM_GRAPH_H

#include <string.h>

#include "bloom_internal.h"
#include "bloom_kernels.h"

/* Nodes of the largest graph built in: the default's 2L + 2 at L = 16 (room
 * for 2L + 4), or a preset's (cod: about 3L + 3). */
#if BLOOM_USE_GRAPH
#define BG_MAX_NODES 52
#else
#define BG_MAX_NODES (2 * BLOOM_MAX_LEVELS + 4)
#endif
#define BG_MAX_IN 3
/* input rows one node row reads, all inputs together (the default's
 * nodes read 4: a smaller array on the Cortex-M stack without presets) */
#if BLOOM_USE_GRAPH
#define BG_MAX_ROWS 40
#else
#define BG_MAX_ROWS 8
#endif
#define BG_SRC (-1) /* input: the source frame (encoded pixels) */
#define BG_AUX (-2) /* input: the aux plane (uint8_t or uint16_t per pixel) */

typedef enum {
    BG_DOWN, /* base(r) = 2r: the node has half the input's resolution */
    BG_SAME, /* base(r) = r */
    BG_UP    /* base(r) = r >> 1: the node has twice the input's resolution */
} bg_map_t;

typedef struct bg_ctx bg_ctx_t;
typedef struct bg_node bg_node_t;

/* Row r of node n. in[i][j] is row base(r) + lo_i + j of input i (clamped),
 * j = 0 .. hi_i - lo_i: const uint8_t * pixels for BG_SRC, const uint8_t *
 * or const uint16_t * for BG_AUX, const uint32_t * samples for a node.
 * dst is the node's ring slot (w * ch uint32_t), or for the output node the
 * caller's row of encoded pixels. Returns false only when dst was made all
 * zero (the engine then tags the row zero); true says nothing. A row
 * function sees its row context (bg_ctx_t), never the engine. */
typedef bool (*bg_row_fn)(const bg_ctx_t *ctx, const bg_node_t *n, int r,
                          const void *const *const in[BG_MAX_IN], void *dst);

typedef struct {
    int8_t node; /* node index, BG_SRC or BG_AUX */
    uint8_t map; /* bg_map_t */
    int8_t lo, hi;
} bg_input_t;

/* How the scheduler gathers one input's rows (engine/ fills it in: bloom_carve
 * lays it out, one per input of every node, in the workspace, beside the
 * node's ring): the ring read, its slots' row pointers and tags (twice
 * over: see bg_node_t; a tile's input read from a column on gets its own
 * view of the pointers, offset, when the slots stay), its slots and
 * height; `add`, bytes still to add per row (that offset, for the
 * caller's own source rows); and a cursor, off: row j is in slot j - off,
 * off moved on by cap when a row read passes the lap's end (rows only move
 * forward, so no division per row). Which rows read are
 * zero come from the ring's bitmap zb (bit s: slot s holds a zero row,
 * twice over as the tags: one word for a node's ring of at most BG_ZB_CAP
 * slots, as many as it takes for the source ring's), else (a larger node
 * ring) from the tags; zmask has a bit per row read, all of which must be
 * zero for the reader to be skipped, but for the aux plane (zaux: a
 * factor). Rows whose first row read, base(r) + lo, is below fend read no
 * clamped row (base(r) + hi < h): run_row's short path, with the slots'
 * own pointers and the bitmap (fend 0: never, for an input with an offset
 * to add, which run_row tests next, or a ring with no bitmap). */
typedef struct {
    const void *const *ring;
    const int32_t *tags;
    const void *zb; /* uint64_t (a node's ring), uint32_t words (zw: the source's) */
    uint16_t cap, h;
    int32_t off; /* the cursor: the row in slot 0 of the ring's current lap */
    int8_t lo;   /* the input's rows base(r) + lo .. base(r) + lo + n1 (bg_input_t) */
    uint8_t n1;  /* (hi - lo) */
    uint8_t sh;  /* base(r) = 2r >> sh: 0 BG_DOWN, 1 BG_SAME, 2 BG_UP */
    bool zaux;   /* the aux plane: its zero rows do not make the reader's zero */
    uint16_t fend;
    uint8_t zw; /* (lo .. zw fill 64 bits: no workspace) */
    uint32_t add;
    uint32_t zmask;
} bg_gather_t;
#define BG_ZB_CAP 32

struct bg_node {
    bg_row_fn fn;
    int w, h;     /* size */
    uint8_t ch;   /* samples per pixel (1 or 3) */
    int8_t level; /* pyramid level it belongs to (row memory per level) */
    uint8_t nin;  /* inputs */
    bool z;       /* zero-preserving: all-zero input rows make an all-zero row */
    bg_input_t in[BG_MAX_IN];
#if BLOOM_SCHED_TABLE
    bg_gather_t *gat; /* nin of them: the scheduler's (bloom_carve) */
#endif
    uint32_t k[4]; /* the row function's constants */
    /* ring (not for the output node): cap rows at buf; each slot's row
     * pointer and tag (the row it holds) are kept twice over, at s and
     * s + cap, so that any run of consecutive slots is one array */
    uint32_t *buf;
#if BLOOM_SCHED_TABLE
    const void **rowp;
#endif
    int32_t *tag;
    uint16_t cap;  /* ring rows (at most the node's height, <= BLOOM_MAX_DIM = 2^14) */
    uint16_t need; /* dry run: largest occupancy (the same bound); both 16 bits so
                      that xa below costs no workspace, on 32-bit targets either
                      (unsigned: Thumb-2 loads them in 16-bit instructions) */
    int next;      /* next row to compute */
#if BLOOM_SCHED_TABLE
    int put;     /* its ring slot (next % cap, kept as a cursor) */
    uint64_t zb; /* zero bitmap of the ring (bg_gather_t), cap <= BG_ZB_CAP */
#endif
    /* Columns xa .. xa + w - 1 of the level (at the node's resolution) are
     * made: all of them (xa = 0) but in a tile's window, where a node makes
     * only what its readers use (bloom_plan; bg_params_t.views); its row function
     * sees its inputs from the columns it reads first on (bg_in_w). */
    int xa;
#if BLOOM_USE_S16
    uint8_t sb; /* bytes per sample: 4 (uint32_t), or 2 (uint16_t: bg_s16); last, in
                   the struct's tail padding (no workspace on 64-bit hosts) */
#endif
};
/* Bytes per sample of node n (4 where 16-bit samples are compiled out). */
#if BLOOM_USE_S16
#define BG_SB(n) ((n)->sb)
#else
#define BG_SB(n) 4u
#endif

/* The parameters a build hook returns beside its graph, which its row
 * functions then see (bg_ctx_t.par). The engine fills them in from the
 * configuration first; the hook changes what its recipe changes. */
typedef struct {
    bloom_knee_t knee;  /* threshold and knee, Q12.20 */
    bloom_out_t out;    /* formats, sRGB or linear, I_q (the output's bloom factor) */
    uint32_t dark_cut;  /* a source pixel with no channel above it makes zeros
                           (BG_NO_CUT, the default: source rows are not tested) */
    size_t scratch_len; /* 3 w + 16 words per scratch row; a hook may ask more */
    int scratch_rows;   /* scratch rows the row functions use (0 .. BG_SCRATCH) */
    bool views;         /* every row function reads its widths by bg_in_w (a tile's
                           nodes then make only the columns read; else only the
                           output node does) */
    uint8_t s16;        /* 16-bit samples (cfg.sample_bits): F - G, the shift from
                           the internal format to the rings' Q(16-G).G; 0: 32-bit */
    bool dark_copy;     /* an output row over a dark source row with zero bloom is
                           the source row (bloom_row_copy_c): bloom_process may copy
                           a dark row to its destination when it reads it */
    bool dst_copied;    /* this output row already holds its source row's bytes
                           (bloom_process copied the dark row when it read it):
                           bg_copy_row has nothing to do. Both bools sit in the
                           struct's tail padding (no workspace byte on any target) */
} bg_params_t;
#define BG_NO_CUT 0xFFFFFFFFu
/* Whether bloom_process's early copy of dark rows is compiled in
 * (BLOOM_DARK_COPY; it needs the dark test; the size build leaves it out):
 * else dark_copy and dst_copied are never set, and the tests on them
 * compile out. */
#define BG_DARK_COPY (BLOOM_DARK_COPY && BLOOM_USE_SKIP && !BLOOM_SMALL)

/* What a row function sees (its row context): the parameters and kernels,
 * the nodes (for their widths, bg_in_w), which of its input rows are zero,
 * the scratch rows and where the window lies in the frame. The engine owns
 * it (engine/bloom_engine.h) and sets it up at bloom_init from the
 * configuration and what the preset's build hook returned (par); zin
 * changes per row. */
struct bg_ctx {
    bg_params_t par;           /* the build hook's: knee, output, dark cut, scratch */
    bloom_kernels_t kern;      /* row kernels (C or SIMD, same bits) */
    bloom_dark_t dark;         /* the largest codes of each width at or below the dark cut */
    const bloom_config_t *cfg; /* the preset's own parameters (cfg->p) and the rest */
    const bg_node_t *node;     /* the graph's nodes */
    uint32_t zin[BG_MAX_IN];   /* which input rows are zero (bit j of zin[i]: row j of input i) */
    uint32_t *scratch;         /* par.scratch_rows rows of par.scratch_len words */
    int w0;                    /* the window's width: the source rows' pixels */
    uint8_t src_bpp, aux_bpp;  /* bytes per source pixel and aux sample (0: no aux plane) */
    bool skip;                 /* zero-row shortcuts on (BLOOM_USE_SKIP, not BLOOM_FLAG_NO_SKIP) */
    bool dark_src;             /* source rows are tagged dark by `dark` (the preset set a dark cut) */
    bool tiled;                /* a tile's window (bloom_plan) */
    int win_x, win_y;          /* the window's first column and row in the frame */
#if !BLOOM_SMALL
    int out_x0;               /* bg_out_x0 */
    int out_src_x;            /* bg_out_src_x */
    bloom_d1_keep_t *d1_keep; /* the level-1 box's sums kept for the next row (bg_fn_d1), or NULL */
#endif
};

/* The graph a preset's build hook makes (graph construction below): the
 * level sizes, the nodes and which is the output. */
typedef struct {
    const bloom_config_t *cfg; /* the configuration (checked) */
    int frame_w, frame_h;      /* the frame (bg_levels) */
    int L;                     /* pyramid depth the preset uses */
    int w[BLOOM_MAX_LEVELS + 1], h[BLOOM_MAX_LEVELS + 1];
    bg_node_t *node;
    int nnodes, node_cap, out_node;
    bool failed; /* out of nodes, or a malformed input */
} bg_graph_t;

#define BG_SCRATCH 4

/* ---- graph construction (for build hooks) ---------------------------- */

/* Level sizes by the common rule (bloom-model.md) for n requested levels:
 * the level count from the frame's size, the sizes from the window's
 * (g->w[0], g->h[0]: the same halving); sets g->L, g->w, g->h. */
void bg_levels(bg_graph_t *g, int n);
/* A node of w x h x ch at `level`; returns its index, or -1 when full. */
int bg_node(bg_graph_t *g, bg_row_fn fn, int w, int h, int ch, int level);
/* Node n keeps uint16_t samples (16-bit rows, cfg.sample_bits). */
#if BLOOM_USE_S16
static inline void bg_s16(bg_graph_t *g, int n)
{
    if (n >= 0 && n < g->nnodes)
        g->node[n].sb = 2;
}
#endif
/* Bytes of one row of node n. */
static inline size_t bg_row_bytes(const bg_node_t *n)
{
    return (size_t)n->w * n->ch * BG_SB(n);
}
/* Node n reads input `from` at rows base(r) + lo .. base(r) + hi. */
void bg_input(bg_graph_t *g, int n, int from, bg_map_t map, int lo, int hi);
/* Node n is zero-preserving: all-zero input rows (dark source rows, aux
 * rows aside) make an all-zero row, which is then not computed. */
static inline void bg_zero(bg_graph_t *g, int n)
{
    if (n >= 0 && n < g->nnodes)
        g->node[n].z = true;
}
/* The knee's cut t - k (0 if k >= t): a source pixel with no channel above
 * it gives zeros after the box and the knee. */
static inline uint32_t bg_knee_cut(const bg_params_t *p)
{
    return p->knee.t > p->knee.k ? p->knee.t - p->knee.k : 0u;
}

/* ---- helpers for row functions --------------------------------------- */

/* Scratch row i (0 .. par.scratch_rows - 1) of par.scratch_len words (at least
 * 3 * width + 16). Row functions run one at a time: a scratch row is free
 * again when the function returns. */
static inline uint32_t *bg_scratch(const bg_ctx_t *ctx, int i)
{
    return ctx->scratch + (size_t)i * ctx->par.scratch_len;
}
/* An output row with zero bloom: the source row copied to dst (decoded and
 * encoded again where that is not the identity), unless bloom_process has
 * already copied it there (par.dst_copied: a dark row, bloom_frame.c). */
static inline void bg_copy_row(const bg_ctx_t *ctx, const uint8_t *src, uint8_t *dst, int w)
{
    if (!BG_DARK_COPY || !ctx->par.dst_copied)
        bloom_row_copy_c(src, dst, w, &ctx->par.out);
}
/* Whether rows lo .. hi (indices into in[i]) of input i are all zero
 * (never in a build without BLOOM_USE_SKIP: the shortcuts compile out). */
static inline bool bg_in_zero(const bg_ctx_t *ctx, int i, int lo, int hi)
{
    const uint32_t m = ((2u << hi) - 1u) & ~((1u << lo) - 1u);
    return BLOOM_USE_SKIP && (ctx->zin[i] & m) == m;
}
/* Whether the engine renders a tile (never in BLOOM_SMALL builds: the
 * tile code compiles out of the size build). */
static inline bool bg_tiled(const bg_ctx_t *ctx)
{
    return !BLOOM_SMALL && ctx->tiled;
}
/* The output node's first column written, counted from the node's first
 * column: where a tile's row is written in place (an output row function
 * that honours it: bg_out_from_x0), the tile's first column, at which the
 * function's dst then points (the columns before it are read, not made:
 * its inputs' clamped reads spoil them); else 0. */
static inline int bg_out_x0(const bg_ctx_t *ctx)
{
#if !BLOOM_SMALL
    return ctx->out_x0;
#else
    (void)ctx;
    return 0;
#endif
}
/* Where the output node's source row pointer (its BG_SRC input) is read
 * from for its first column written, in pixels: where a tile's row is
 * written in place the pointer is the window's column 0 (the gather adds
 * no offset to the caller's rows) and this is the tile's first column;
 * else the pointer is at the first column and this is 0. */
static inline int bg_out_src_x(const bg_ctx_t *ctx)
{
#if !BLOOM_SMALL
    return ctx->out_src_x;
#else
    (void)ctx;
    return 0;
#endif
}
/* The first row (or column) of an input that row (column) r of its reader
 * is based at: 2r for BG_DOWN, r for BG_SAME, r >> 1 for BG_UP. */
static inline int bg_base(int map, int r)
{
    return map == BG_DOWN ? 2 * r : map == BG_SAME ? r : r >> 1;
}

/* The width of input i of node n as n's row function sees it: from the
 * first column n reads (its first column xa, halved for BG_UP, doubled for
 * BG_DOWN) to the last the input made; the row function's input rows start
 * at that column (tiles: bg_node_t.xa; else the input's width). */
static inline int bg_in_w(const bg_ctx_t *ctx, const bg_node_t *n, int i)
{
    const int from = n->in[i].node;
#if BLOOM_SMALL
    return from < 0 ? ctx->w0 : ctx->node[from].w;
#else
    const int end = from < 0 ? ctx->w0 : ctx->node[from].xa + ctx->node[from].w;
    return end - bg_base(n->in[i].map, n->xa);
#endif
}

/* bg_in_w for an input that is a node (not the source or the aux plane):
 * the same width, without the test (the Cortex-M core's size). */
static inline int bg_node_in_w(const bg_ctx_t *ctx, const bg_node_t *n, int i)
{
#if BLOOM_SMALL
    return ctx->node[n->in[i].node].w;
#else
    return bg_in_w(ctx, n, i);
#endif
}

/* The window's first column and row in the frame (0 without tiles). */
static inline int bg_win_x(const bg_ctx_t *ctx)
{
    return BLOOM_SMALL ? 0 : ctx->win_x;
}
static inline int bg_win_y(const bg_ctx_t *ctx)
{
    return BLOOM_SMALL ? 0 : ctx->win_y;
}
/* Bytes per aux sample: always 0 in a build without presets (only they read
 * an aux plane: its code compiles out of the default-only core). */
static inline int bg_aux_bpp(const bg_ctx_t *ctx)
{
    return BLOOM_USE_GRAPH ? ctx->aux_bpp : 0;
}
/* A source row decoded to Q12.20 R, G, B (w0 pixels). */
void bg_decode_row(const bg_ctx_t *ctx, const uint8_t *src, uint32_t *dst);
/* Aux sample x of an aux row, scaled to Q16 (0 .. 65536): code * 65536 / max
 * rounded half up (exact for U16: 65535 -> 65536). */
uint32_t bg_aux_q16(const bg_ctx_t *ctx, const void *row, int x);
uint32_t bg_aux_q24(const bg_ctx_t *ctx, const void *row, int x);

#endif
