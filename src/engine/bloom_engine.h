/* The engine behind the API (engine/): planning a configuration into its
 * preset's graph, sizing and carving the workspace (bloom.c), the
 * scheduler that makes the rows (bloom_sched.c), the row, band and frame
 * calls (bloom_frame.c). It uses the graph, the presets' hooks, the
 * kernels and the pixel formats; nothing below uses it. */
#ifndef BLOOM_ENGINE_H
#define BLOOM_ENGINE_H

#include "bloom_graph.h"
#include "bloom_presets.h"

/* Size, depth, parameters, formats, flags, preset and aux plane of cfg
 * (bloom_params.c): BLOOM_OK or the most specific refusal. */
bloom_status_t bloom_validate(const bloom_config_t *cfg);

/* Workspace carving (bloom.c) is counted in 64 bits so that a
 * configuration too big for a 32-bit address space is refused, not
 * wrapped: n rounded up to a multiple of 8. */
static inline uint64_t bloom_align8(uint64_t n)
{
    return (n + 7u) & ~(uint64_t)7u;
}

/* Ring tags hold the row number; this bit marks a row known to be all zero
 * (or, in the source ring, a dark row). Rows are < 2^30. */
#define BLOOM_TAG_ZERO 0x40000000

static inline int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* Each ring slot's tag (and source row pointer) is kept this many times:
 * twice with the static schedule's gathers (bg_node_t), once without. */
#define BG_RING_COPIES (BLOOM_SCHED_TABLE ? 2 : 1)
#define BG_S_FREE 0xFE
#define BG_S_PUSH 0xFF

/* The engine (the public bloom_t): the configuration, the preset's graph
 * and the row context its row functions see, the rings, the tile and the
 * progress of the frame. It lives at the start of the caller's workspace
 * (bloom_init), or on the stack while bloom_query plans. */
struct bloom {
    bloom_config_t cfg;
    bg_graph_t gr; /* the preset's graph: levels, nodes, the output node */
    bg_ctx_t row;  /* what row functions see (gr's nodes, the kernels, parameters) */
    /* The window of the frame the graph works on (bloom_plan): the source
     * rectangle from column row.win_x and row row.win_y of the frame,
     * gr.w[0] x gr.h[0]. With a tile (row.tiled) the output is the
     * window's columns tile_x0 .. tile_x1 - 1 and rows tile_y0 .. tile_y1 - 1
     * (the tile): the output node writes the tile's columns of the
     * caller's row in place (out_direct), or else out_row, whose tile
     * part is copied out. */
    int tile_x0, tile_x1, tile_y0, tile_y1;
    uint8_t *out_row;
    int out_rows; /* output rows given to the caller this frame */
#if !BLOOM_SMALL
    bloom_d1_keep_t d1_keep; /* row.d1_keep's (its arrays in the workspace) */
    int d1_keep_n;           /* entries of d1_keep.tag (0: none kept) */
#endif
    /* source and aux rings: one slot per pushed row, the same for both;
     * pointers and tags twice over as a node's (rowp, tag), the pointers
     * the caller's rows or the copies' (BLOOM_FLAG_COPY_SOURCE) */
    const void **src_ptr, **aux_ptr;
    uint8_t *src_copy, *aux_copy;
    int32_t *src_tag;
#if BLOOM_SCHED_TABLE
    uint32_t *src_zb; /* the source ring's zero bitmap (bg_gather_t), 2 src_cap bits */
#endif
    int src_cap;
    size_t src_row_bytes, aux_row_bytes;
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
    bool out_direct; /* a tile's output rows are written in place (bg_out_x0), not into out_row */
    int need_src, latency;
    /* The static schedule (BLOOM_SCHED_TABLE; engine/bloom_sched.c): the
     * dry run's firings in order, one byte each: a node index (make its
     * next row; the output node: the next output row is due), BG_S_PUSH
     * (the next source row must have been pushed) or BG_S_FREE (one more
     * source row is read by no firing to come). sched_len bytes at sched
     * (in the workspace; NULL while the dry run only counts them). */
    uint8_t *sched;
    int sched_len, sched_at;
    /* The table is folded: the firing order repeats every 2^L pushes once
     * the pyramid has filled, so the start-up is written down, one period
     * once, then the end. Bytes [fold_b, fold_e) are walked fold_m times
     * (fold_rep done so far this frame); fold_m = 1: no fold. */
#if BLOOM_SCHED_TABLE /* (the size build has no table: no workspace for these) */
    int fold_b, fold_e, fold_m, fold_rep;
    int walk_end;                 /* where the walk stops: fold_e while the period repeats, then sched_len */
    int dry_n;                    /* dry run: bytes of the unfolded table so far */
    struct bloom_fold_scan *scan; /* dry run: the period search (bloom_fold.c) */
#endif
    int src_free; /* source rows no firing to come reads: push r needs r - src_cap < src_free */
    int src_seen; /* BG_S_PUSH bytes the walk has passed */
};

/* Plan b from cfg (checked): build the preset's graph into `nodes` (room
 * for cap), dry run. BLOOM_E_WORKSPACE if the graph needs more nodes. */
bloom_status_t bloom_plan(bloom_t *b, const bloom_config_t *cfg, bg_node_t *nodes, int cap);
/* Workspace bytes of the engine: the struct, its nodes, the rings; with
 * base NULL (the engine at base otherwise) only count.
 * per_level[k] (if not NULL, zeroed) gets the ring bytes of level k. */
uint64_t bloom_carve(bloom_t *b, uint8_t *base, size_t *per_level);
#if !BLOOM_SMALL
/* A tile's window [x0, x1) x [y0, y1) of the frame: the tile, the halo of
 * b's graph over the whole frame either way, out to multiples of the
 * deepest level's pixel (its levels then halve as the frame's), within the
 * frame (bloom_tile.c). */
void bloom_tile_window(const bloom_t *b, const bloom_config_t *cfg, int *x0, int *y0, int *x1, int *y1);
/* Each node of b's window graph cut to the columns its readers use. */
void bloom_tile_cut(bloom_t *b);
#endif
/* The dry run: ring sizes, source rows, latency. */
void bloom_dry_frame(bloom_t *b);
/* A source row in (the row call's push; the frame call's dark rows are
 * copied by its feed's pushes, bloom_sched_feed). */
bloom_status_t bloom_sched_push(bloom_t *b, const void *src_row, const void *aux_row);
bloom_status_t bloom_sched_pull(bloom_t *b, void *dst_row);
#if BLOOM_SCHED_TABLE
/* The rows of a band or frame call (bloom_frame.c's run_rows), fed to the
 * schedule's walk in one call: window row i of the source at
 * src + (win_y + i) src_stride (aux alike; NULL without the plane), output
 * row j of the tile (or frame) at dst + (out_y0 + j) dst_stride. The walk
 * pushes the next row where the table has a push, up to `end` rows in,
 * and makes each output row due into its place: no push or pull call per
 * row. copies (the frame call's dark rows, BG_DARK_COPY): a dark source
 * row copied to its destination row as pushed; orow, oslot: the cursor on
 * the source row of the next output row (its slot). */
typedef struct {
    const uint8_t *src, *aux;
    uint8_t *dst;
    ptrdiff_t src_stride, aux_stride, dst_stride;
    int end, out_y0;
    bool copies;
    int orow, oslot;
} bloom_feed_t;
bloom_status_t bloom_sched_feed(bloom_t *b, bloom_feed_t *f);
#endif

#endif
