/* The scheduler's rows (bloom_sched.c, its one includer): a node row made
 * from its gathered inputs (run_row), into its ring slot and tagged
 * (make_row), the tags' and bitmaps' upkeep. Static: the walk of the
 * static schedule inlines them (no call per node row), and the size build
 * keeps run_row apart for its stack. */
#ifndef BLOOM_SCHED_ROWS_H
#define BLOOM_SCHED_ROWS_H

#include "bloom_engine.h"

#include <string.h>

#define ZBIT BLOOM_TAG_ZERO

static int in_height(const bloom_t *g, int from)
{
    return from < 0 ? g->gr.h[0] : g->gr.node[from].h;
}

#if !BLOOM_SCHED_TABLE
/* The source (or aux) row held in slot `slot` of the source ring. */
static const void *src_slot(const bloom_t *g, int from, int slot)
{
    if (!BLOOM_USE_GRAPH || from == BG_SRC) /* (only presets read an aux plane) */
        return g->src_copy ? g->src_copy + (size_t)slot * g->src_row_bytes : g->src_ptr[slot];
    return g->aux_copy ? g->aux_copy + (size_t)slot * g->aux_row_bytes : g->aux_ptr[slot];
}
#endif

/* Run node row r into dst: gather the input rows and which are zero, call
 * the row function, unless the node is zero-preserving and every input row
 * it depends on is zero. Returns ROW_MADE, ROW_ZEROS (the function made
 * zeros) or ROW_SKIPPED (dst not written). Not inlined:
 * the recursion of ensure() keeps small frames (the Cortex-M stack figure). */
enum { ROW_MADE, ROW_ZEROS, ROW_SKIPPED };

#if BLOOM_SCHED_TABLE
/* Which of the rows in slots slot .. slot + n1 of an input's ring are zero,
 * from its bitmap (the source's: bits of two words past a word's end). */
static inline uint32_t zero_bits(const bg_gather_t *ga, int slot)
{
    if (!ga->zw) /* a node's: one word (slot + n1 < 2 cap <= 64) */
        return (uint32_t)(*(const uint64_t *)ga->zb >> slot) & ga->zmask;
    const uint32_t *z = (const uint32_t *)ga->zb + (slot >> 5);
    const int o = slot & 31;
    uint32_t v = z[0] >> o;
    if (o + ga->n1 > 31) /* (o > 0: n1 < 32) */
        v |= z[1] << (32 - o);
    return v & ga->zmask;
}

/* The slot of row `first` (the first row the input reads), the cursor
 * moved on a lap when it passes the ring's end: readers' rows only go
 * forward, so no division, and a store only at a lap's end. */
static inline int move_cursor(bg_gather_t *ga, int first)
{
    int slot = first - ga->off;
    if (slot >= ga->cap) {
        int off = ga->off;
        do {
            off += ga->cap;
            slot -= ga->cap;
        } while (slot >= ga->cap);
        ga->off = off;
    }
    return slot;
}

/* The cursor moved to row lo, the first of rows lo .. lo + n1 that lie
 * inside the input: their slots are consecutive from it (rings keep their
 * slots' row pointers and tags twice over: any run of consecutive slots is
 * one array). Rows are made in order: the first read intact and the last
 * made, all are. */
static BLOOM_ALWAYS_INLINE int cursor_check(bloom_t *g, bg_gather_t *ga, int lo)
{
    const int slot = move_cursor(ga, lo);
#if BLOOM_CHECK_RINGS
    const int32_t *tags = ga->tags + slot;
    if (((tags[0] ^ lo) | (tags[ga->n1] ^ (lo + ga->n1))) & ~ZBIT)
        g->failed = true;
#else
    (void)g;
#endif
    return slot;
}

/* The gather of one input whose rows reach past an edge, or whose ring
 * has no bitmap (run_row's long path): the slot cursor moved to the first
 * row read, the row pointers laid out in rows[*used ..] (edge rows
 * repeated, a tile's column offset added) or, when neither, the slots'
 * own; returns which are zero. */
static BLOOM_NOINLINE uint32_t gather_edge(bloom_t *g, bg_gather_t *ga, int lo, const void **rows, int *used,
                                           const void *const **in)
{
    const int hin = ga->h, n1 = ga->n1;
    const int first = clampi(lo, 0, hin - 1), last = clampi(lo + n1, 0, hin - 1);
    const int slot = move_cursor(ga, first);
    const int32_t *tags = ga->tags + slot;
    const void *const *ring = ga->ring + slot;
#if BLOOM_CHECK_RINGS
    if ((tags[0] & ~ZBIT) != first || (tags[last - first] & ~ZBIT) != last)
        g->failed = true;
#else
    (void)g;
#endif
    uint32_t zm = 0;
    if (lo == first && lo + n1 == last && !ga->add) { /* no edge row, no offset: the slots' own pointers */
        if (BLOOM_USE_SKIP && ga->zb)
            zm = zero_bits(ga, slot);
        else if (BLOOM_USE_SKIP)
            for (int k = 0; k <= n1; k++)
                zm |= ((uint32_t)tags[k] >> 30 & 1u) << k;
        *in = ring;
        return zm;
    }
    *in = rows + *used; /* edge rows repeated, or a tile's column offset added */
    for (int j = lo; j <= lo + n1; j++) {
        const int d = clampi(j, 0, hin - 1) - first;
        if (BLOOM_USE_SKIP)
            zm |= ((uint32_t)tags[d] >> 30 & 1u) << (j - lo);
        rows[(*used)++] = (const uint8_t *)ring[d] + ga->add;
    }
    return zm;
}
#endif

/* Node n's row r into dst, its inputs gathered. With the static schedule
 * one walk makes every row (walk_to_output): inlined there; the size build
 * calls it from two places. */
#if BLOOM_SCHED_TABLE
#define RUN_ROW_INLINE BLOOM_ALWAYS_INLINE
#else
#define RUN_ROW_INLINE BLOOM_NOINLINE
#endif
static RUN_ROW_INLINE int run_row(bloom_t *g, bg_node_t *n, int r, void *dst)
{
    const void *rows[BG_MAX_ROWS];
    const void *const *in[BG_MAX_IN]; /* (the row function reads in[0 .. nin - 1]) */
    int used = 0;
#if BLOOM_SCHED_TABLE
    const int nin = n->nin;
    bg_gather_t *ga = n->gat;
    uint32_t *zin = g->row.zin;
    uint32_t live = 0; /* bits of rows read that are not zero (the aux plane's aside) */
    for (int i = 0; i < nin; i++, ga++) {
        /* base(r) = 2r >> sh: 2r (BG_DOWN), r (BG_SAME), r >> 1 (BG_UP) */
        const int lo = ((2 * r) >> ga->sh) + ga->lo;
        uint32_t zm = 0;
        if ((unsigned)lo < ga->fend) { /* no edge row, no offset: the slots' own pointers */
            const int slot = cursor_check(g, ga, lo);
            in[i] = ga->ring + slot;
            if (BLOOM_USE_SKIP)
                zm = zero_bits(ga, slot);
        } else if (ga->add && lo >= 0 && lo + ga->n1 < ga->h) { /* (fend 0: the untiled test stays one) */
            /* the caller's own rows (a source ring has a bitmap), a tile's column offset added */
            const int slot = cursor_check(g, ga, lo);
            const void **p = rows + used;
            in[i] = p;
            used += ga->n1 + 1;
            for (int k = 0; k <= ga->n1; k++)
                p[k] = (const uint8_t *)ga->ring[slot + k] + ga->add;
            if (BLOOM_USE_SKIP)
                zm = zero_bits(ga, slot);
        } else {
            zm = gather_edge(g, ga, lo, rows, &used, &in[i]);
        }
        if (!BLOOM_USE_SKIP)
            continue;
        zin[i] = zm;
        if (!ga->zaux)
            live |= zm ^ ga->zmask;
    }
    /* (decided after the gather: nothing else is live across its loop) */
    if (BLOOM_USE_SKIP && !live && g->row.skip && n->z)
        return ROW_SKIPPED;
#else /* the size build: no cursors, no doubled rings, no aux plane, no tiles */
    bool all_zero = BLOOM_USE_SKIP && g->row.skip && n->z;
    for (int i = 0; i < n->nin; i++) {
        const bg_input_t *ip = &n->in[i];
        const int from = ip->node, hin = in_height(g, from), b = bg_base(ip->map, r);
        const bg_node_t *src = from >= 0 ? &g->gr.node[from] : NULL;
        const int cap = src ? src->cap : g->src_cap;
        const int32_t *tags = src ? src->tag : g->src_tag;
        /* the rows are consecutive (repeated at the edges): one division for
         * the first slot, then a step with wrap-around */
        int prev = clampi(b + ip->lo, 0, hin - 1), slot = prev % cap;
        uint32_t zm = 0;
        in[i] = rows + used;
        for (int j = ip->lo; j <= ip->hi; j++) {
            const int rr = clampi(b + j, 0, hin - 1);
            if (rr != prev) {
                prev = rr;
                slot = slot + 1 == cap ? 0 : slot + 1;
            }
            const int32_t tag = tags[slot];
#if BLOOM_CHECK_RINGS
            if ((tag & ~ZBIT) != rr)
                g->failed = true;
#endif
            if (BLOOM_USE_SKIP && (tag & ZBIT))
                zm |= 1u << (j - ip->lo);
#if BLOOM_USE_S16
            rows[used++] = src ? (const void *)((const uint8_t *)src->buf + (size_t)slot * bg_row_bytes(src))
#else
            rows[used++] = src ? (const void *)(src->buf + (size_t)slot * (size_t)src->w * src->ch)
#endif
                               : src_slot(g, from, slot);
        }
        if (!BLOOM_USE_SKIP)
            continue;
        g->row.zin[i] = zm;
        if (from != BG_AUX && zm != (2u << (ip->hi - ip->lo)) - 1u)
            all_zero = false;
    }
    if (all_zero)
        return ROW_SKIPPED;
#endif
    if (BLOOM_CHECK_RINGS && g->failed)
        return ROW_MADE; /* an input row was overwritten: nothing is made of it */
    return !n->fn(&g->row, n, r, in, dst) && BLOOM_USE_SKIP && g->row.skip ? ROW_ZEROS : ROW_MADE;
}

/* Tag v into slot s of a ring of cap slots (both copies with the static
 * schedule's doubled rings); a node's bitmap zb holds the tags' zero bits
 * (bloom_begin), flipped only when the slot's changes. Returns the old tag
 * (the source's bitmap: flip_src_bits). */
static inline int32_t put_tag(int32_t *tags, uint64_t *zb, int s, int cap, int32_t v)
{
    const int32_t old = tags[s];
    tags[s] = v;
    if (BLOOM_SCHED_TABLE)
        tags[s + cap] = v;
    if (BLOOM_SCHED_TABLE && zb && cap <= BG_ZB_CAP && ((old ^ v) & ZBIT)) /* (both copies) */
        *zb ^= (1ull << s) | (1ull << (s + cap));
    return old;
}
#if BLOOM_SCHED_TABLE
#define NODE_ZB(n) (&(n)->zb)
/* The source ring's bitmap (32-bit words, the Cortex-M's own): bits s and
 * s + cap flipped. */
static inline void flip_src_bits(uint32_t *zb, int s, int cap)
{
    zb[s >> 5] ^= 1u << (s & 31);
    s += cap;
    zb[s >> 5] ^= 1u << (s & 31);
}
#else
#define NODE_ZB(n) NULL
#endif
static inline void put_ptr(const void **ptrs, int s, int cap, const void *v)
{
    ptrs[s] = v;
    if (BLOOM_SCHED_TABLE)
        ptrs[s + cap] = v;
}

/* Node row r into its ring slot, tagged. A zero row leaves zeros in the
 * slot (a slot tagged zero holds zeros: if it did already, nothing is
 * written). */
static BLOOM_ALWAYS_INLINE void make_row(bloom_t *g, bg_node_t *n, int r)
{
#if BLOOM_SCHED_TABLE
    const int s = n->put;
    n->put = s + 1 == n->cap ? 0 : s + 1;
#define SLOT_ROW(n, s) ((void *)(uintptr_t)(n)->rowp[s])
#else
    const int s = r % n->cap;
#define SLOT_ROW(n, s) ((void *)((uint8_t *)(n)->buf + (size_t)(s)*bg_row_bytes(n)))
#endif
    const int made = run_row(g, n, r, SLOT_ROW(n, s));
    /* (the old tag and the row's place read after: only s lives across
     * the gather and the call; no row function reads its own node) */
    if (BLOOM_USE_SKIP && made == ROW_SKIPPED && !(n->tag[s] & ZBIT))
        memset(SLOT_ROW(n, s), 0, bg_row_bytes(n));
#undef SLOT_ROW
    put_tag(n->tag, NODE_ZB(n), s, n->cap, BLOOM_USE_SKIP && made != ROW_MADE ? r | ZBIT : r);
}

#endif
