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
 * g->zin (bit j of zin[i]: row j of input i) and may take shortcuts.
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

typedef struct bloom bloom_graph_t;
typedef struct bg_node bg_node_t;

/* Row r of node n. in[i][j] is row base(r) + lo_i + j of input i (clamped),
 * j = 0 .. hi_i - lo_i: const uint8_t * pixels for BG_SRC, const uint8_t *
 * or const uint16_t * for BG_AUX, const uint32_t * samples for a node.
 * dst is the node's ring slot (w * ch uint32_t), or for the output node the
 * caller's row of encoded pixels. Returns false only when dst was made all
 * zero (the engine then tags the row zero); true says nothing. */
typedef bool (*bg_row_fn)(const bloom_graph_t *g, const bg_node_t *n, int r,
                          const void *const *const in[BG_MAX_IN], void *dst);

typedef struct {
    int8_t node; /* node index, BG_SRC or BG_AUX */
    uint8_t map; /* bg_map_t */
    int8_t lo, hi;
} bg_input_t;

/* How the scheduler gathers one input's rows (engine/; bloom_carve lays it
 * out, one per input of every node, in the workspace): the ring read, its
 * slots' row pointers and tags (twice over: see bg_node_t; a tile's input
 * read from a column on gets its own view of the pointers, offset, when
 * the slots stay), its slots and height; `add`, bytes still to add per row
 * (that offset, for the caller's own source rows); and a cursor: the first
 * row read by the last row made and its slot (rows only move forward, so
 * no division per row). */
typedef struct {
    const void *const *ring;
    const int32_t *tags;
    uint16_t cap, h;
    uint16_t row, slot;
    uint32_t add;
} bg_gather_t;

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
    int put; /* its ring slot (next % cap, kept as a cursor) */
#endif
    /* Columns xa .. xa + w - 1 of the level (at the node's resolution) are
     * made: all of them (xa = 0) but in a tile's window, where a node makes
     * only what its readers use (bloom_plan; g->views); its row function
     * sees its inputs from the columns it reads first on (bg_in_w). */
    int xa;
};

struct bloom {
    bloom_config_t cfg;
    int L; /* pyramid depth the preset uses */
    int w[BLOOM_MAX_LEVELS + 1], h[BLOOM_MAX_LEVELS + 1];
    bloom_knee_t knee;    /* threshold and knee, Q12.20 */
    bloom_out_t out;      /* formats, sRGB or linear, I_q */
    bloom_kernels_t kern; /* row kernels (C or SIMD, same bits) */
    bool skip;            /* zero-row shortcuts on (BLOOM_USE_SKIP, not BLOOM_FLAG_NO_SKIP) */
    bool dark_src;        /* source rows are tagged dark by `dark` (the build hook set dark_cut) */
    uint32_t dark_cut;    /* build hook: a source pixel with no channel above it makes zeros */
    bloom_dark_t dark;    /* the largest codes of each width at or below dark_cut */
    /* The frame, and the window of it the graph works on (bloom_plan): the
     * source rectangle, from column win_x and row win_y of the frame, w[0]
     * x h[0]. With a tile (tiled) the output is the window's columns
     * tile_x0 .. tile_x1 - 1 and rows tile_y0 .. tile_y1 - 1 (the tile):
     * the output node writes out_row, the tile's part is copied out. */
    int frame_w, frame_h, win_x, win_y;
    bool tiled;
    bool views; /* build hook: every row function reads its widths by bg_in_w (a
                   tile's nodes then make only the columns read; else only the
                   output node does) */
    int tile_x0, tile_x1, tile_y0, tile_y1;
    uint8_t *out_row;
    int out_rows; /* output rows given to the caller this frame */
    int nnodes, out_node;
    uint32_t zin[BG_MAX_IN]; /* during a row function: which input rows are zero */
    /* scratch rows for row functions: scratch_rows rows of scratch_len words */
    uint32_t *scratch;
    size_t scratch_len;
    int scratch_rows; /* rows the preset's row functions use (0 .. BG_SCRATCH) */
    /* source and aux rings: one slot per pushed row, the same for both;
     * pointers and tags twice over as a node's (rowp, tag), the pointers
     * the caller's rows or the copies' (BLOOM_FLAG_COPY_SOURCE) */
    const void **src_ptr, **aux_ptr;
    uint8_t *src_copy, *aux_copy;
    int32_t *src_tag;
    int src_cap;
    int node_cap; /* (beside src_cap: no hole in the struct) nodes that fit at node */
    size_t src_row_bytes, aux_row_bytes;
    int src_bpp, aux_bpp;
    const uint8_t *aux_frame; /* bloom_set_aux */
    ptrdiff_t aux_stride;
    /* the nodes that read the source or aux rings (bloom_plan, builds with
     * presets), for the push's check of the oldest source row still needed */
    int8_t src_reader[BG_MAX_NODES];
    int nsrc_readers;
    /* progress */
    int src_n;
    int src_put; /* the source ring's slot for row src_n (src_n % src_cap) */
    bool failed, dry;
    int need_src, latency;
    /* The static schedule (BLOOM_SCHED_TABLE; engine/bloom_sched.c): the
     * dry run's firings in order, one byte each: a node index (make its
     * next row; the output node: the next output row is due), BG_S_PUSH
     * (the next source row must have been pushed) or BG_S_FREE (one more
     * source row is read by no firing to come). sched_len bytes at sched
     * (in the workspace; NULL while the dry run only counts them). */
    uint8_t *sched;
    int sched_len, sched_at;
    int src_free; /* source rows no firing to come reads: push r needs r - src_cap < src_free */
    int src_seen; /* BG_S_PUSH bytes the walk has passed */
    /* the nodes: in the workspace right after this struct (bloom_init), or
     * on the stack (bloom_query); node_cap of them fit (above) */
    bg_node_t *node;
};
#define BG_SCRATCH 4
/* Each ring slot's tag (and source row pointer) is kept this many times:
 * twice with the static schedule's gathers (bg_node_t), once without. */
#define BG_RING_COPIES (BLOOM_SCHED_TABLE ? 2 : 1)
#define BG_S_FREE 0xFE
#define BG_S_PUSH 0xFF

/* ---- graph construction (for build hooks) ---------------------------- */

/* Level sizes by the common rule (bloom-model.md) for n requested levels:
 * the level count from the frame's size, the sizes from the window's
 * (g->w[0], g->h[0]: the same halving); sets g->L, g->w, g->h. */
void bg_levels(bloom_graph_t *g, int n);
/* A node of w x h x ch at `level`; returns its index, or -1 when full. */
int bg_node(bloom_graph_t *g, bg_row_fn fn, int w, int h, int ch, int level);
/* Node n reads input `from` at rows base(r) + lo .. base(r) + hi. */
void bg_input(bloom_graph_t *g, int n, int from, bg_map_t map, int lo, int hi);
/* Node n is zero-preserving: all-zero input rows (dark source rows, aux
 * rows aside) make an all-zero row, which is then not computed. */
static inline void bg_zero(bloom_graph_t *g, int n)
{
    if (n >= 0 && n < g->nnodes)
        g->node[n].z = true;
}
/* The knee's cut t - k (0 if k >= t): a source pixel with no channel above
 * it gives zeros after the box and the knee. */
static inline uint32_t bg_knee_cut(const bloom_graph_t *g)
{
    return g->knee.t > g->knee.k ? g->knee.t - g->knee.k : 0u;
}

/* ---- helpers for row functions --------------------------------------- */

/* Scratch row i (0 .. g->scratch_rows - 1) of g->scratch_len words (at least
 * 3 * width + 16). Row functions run one at a time: a scratch row is free
 * again when the function returns. */
static inline uint32_t *bg_scratch(const bloom_graph_t *g, int i)
{
    return g->scratch + (size_t)i * g->scratch_len;
}
/* Whether rows lo .. hi (indices into in[i]) of input i are all zero
 * (never in a build without BLOOM_USE_SKIP: the shortcuts compile out). */
static inline bool bg_in_zero(const bloom_graph_t *g, int i, int lo, int hi)
{
    const uint32_t m = ((2u << hi) - 1u) & ~((1u << lo) - 1u);
    return BLOOM_USE_SKIP && (g->zin[i] & m) == m;
}
/* Whether the engine renders a tile (never in BLOOM_SMALL builds: the
 * tile code compiles out of the size build). */
static inline bool bg_tiled(const bloom_graph_t *g)
{
    return !BLOOM_SMALL && g->tiled;
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
static inline int bg_in_w(const bloom_graph_t *g, const bg_node_t *n, int i)
{
    const int from = n->in[i].node;
#if BLOOM_SMALL
    return from < 0 ? g->w[0] : g->node[from].w;
#else
    const int end = from < 0 ? g->w[0] : g->node[from].xa + g->node[from].w;
    return end - bg_base(n->in[i].map, n->xa);
#endif
}

/* bg_in_w for an input that is a node (not the source or the aux plane):
 * the same width, without the test (the Cortex-M core's size). */
static inline int bg_node_in_w(const bloom_graph_t *g, const bg_node_t *n, int i)
{
#if BLOOM_SMALL
    return g->node[n->in[i].node].w;
#else
    return bg_in_w(g, n, i);
#endif
}

/* The window's first column and row in the frame (0 without tiles). */
static inline int bg_win_x(const bloom_graph_t *g)
{
    return BLOOM_SMALL ? 0 : g->win_x;
}
static inline int bg_win_y(const bloom_graph_t *g)
{
    return BLOOM_SMALL ? 0 : g->win_y;
}
/* Bytes per aux sample: always 0 in a build without presets (only they read
 * an aux plane: its code compiles out of the default-only core). */
static inline int bg_aux_bpp(const bloom_graph_t *g)
{
    return BLOOM_USE_GRAPH ? g->aux_bpp : 0;
}
/* A source row decoded to Q12.20 R, G, B (w0 pixels). */
void bg_decode_row(const bloom_graph_t *g, const uint8_t *src, uint32_t *dst);
/* Aux sample x of an aux row, scaled to Q16 (0 .. 65536): code * 65536 / max
 * rounded half up (exact for U16: 65535 -> 65536). */
uint32_t bg_aux_q16(const bloom_graph_t *g, const void *row, int x);
uint32_t bg_aux_q24(const bloom_graph_t *g, const void *row, int x);

#endif
