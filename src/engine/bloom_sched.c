/* The scheduler (bloom_engine.h): rows in and out, and the dry run.
 *
 * The order in which node rows are made depends on the frame geometry
 * alone. The dry run (bloom_plan, at bloom_query and bloom_init) finds it
 * the pull-driven way: each output row asks its inputs for the rows it
 * reads, each node row asks its inputs, down to the source rows pushed so
 * far, one push at a time; a request that cannot be met yet is resumed
 * after the next push. It sizes every ring by what that order keeps, and
 * (BLOOM_SCHED_TABLE) writes the order down as the static schedule, one
 * byte per firing, folded to the start-up, one period and the end (the
 * order repeats every 2^L pushes once the pyramid has filled): a frame
 * then walks the table, so a push's BUSY and a
 * pull's AGAIN are a counter compared with another, and nothing is
 * searched per row. Without the table (the size build) each pull runs the
 * same pull-driven walk on the real rows. Either way a row is made from
 * the same input rows: the same bits. */
#include "bloom_engine.h"
#include "bloom_fold.h"

#include <string.h>

#define FAR (1 << 30)
#define ZBIT BLOOM_TAG_ZERO
/* A node slot that holds no row yet (the zero bit kept: see bloom_begin). */
#define NO_ROW 0x3FFFFFFF

#if defined(__GNUC__)
#define BLOOM_NOINLINE __attribute__((noinline))
#else
#define BLOOM_NOINLINE
#endif

/* ---- rows -------------------------------------------------------------- */

static int in_height(const bloom_t *g, int from)
{
    return from < 0 ? g->gr.h[0] : g->gr.node[from].h;
}

/* The oldest row of `from` that a node still reads; FAR if none. The
 * source and aux rings share slots: a reader of either keeps both. */
static int oldest_of(const bloom_t *g, int from)
{
    int o = FAR;
    const int hin = in_height(g, from);
    /* a node's readers come after it; the source's are listed (builds
     * with presets: their graphs are big) */
    const bool list = BLOOM_USE_GRAPH && from < 0;
    const int nc = list ? g->nsrc_readers : g->gr.nnodes;
    for (int ci = (from < 0 ? 0 : from + 1); ci < nc; ci++) {
        const bg_node_t *n = &g->gr.node[list ? g->src_reader[ci] : ci];
        if (n->next >= n->h)
            continue;
        for (int i = 0; i < n->nin; i++)
            if (n->in[i].node == from || (BLOOM_USE_GRAPH && from == BG_SRC && n->in[i].node == BG_AUX))
                o = imin(o, clampi(bg_base(n->in[i].map, n->next) + n->in[i].lo, 0, hin - 1));
    }
    return o;
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

/* The last row of input i that row r of node n reads. */
static int input_top(const bloom_t *g, const bg_node_t *n, int i, int r)
{
    const bg_input_t *in = &n->in[i];
    return clampi(bg_base(in->map, r) + in->hi, 0, in_height(g, in->node) - 1);
}

static bool ensure(bloom_t *g, int ni, int j);

/* Make sure every input row of node row r exists. */
static bool ensure_inputs(bloom_t *g, const bg_node_t *n, int r)
{
    for (int i = 0; i < n->nin; i++)
        if (!ensure(g, n->in[i].node, input_top(g, n, i, r)))
            return false;
    return true;
}

/* Run node row r into dst: gather the input rows and which are zero, call
 * the row function, unless the node is zero-preserving and every input row
 * it depends on is zero. Returns ROW_MADE, ROW_ZEROS (the function made
 * zeros) or ROW_SKIPPED (dst not written). Not inlined:
 * the recursion of ensure() keeps small frames (the Cortex-M stack figure). */
enum { ROW_MADE, ROW_ZEROS, ROW_SKIPPED };

#if BLOOM_SCHED_TABLE
static bool walk_to_output(bloom_t *g, void *dst);

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

/* One byte of the static schedule: counted always (its size), written when
 * the table has its place (bloom_init's second dry run), folded (bloom_fold.c). */
static void emit(bloom_t *g, int byte)
{
#if BLOOM_SCHED_TABLE
    if (g->scan) /* the first dry run */
        bloom_fold_byte(g, byte);
    const int i = g->dry_n++, rep = g->fold_e - g->fold_b;
    if (g->fold_m > 1 && i >= g->fold_e && i < g->fold_b + g->fold_m * rep) {
        /* a repeat of the block: the same byte, or no fold */
        if (g->sched && g->sched[g->fold_b + (i - g->fold_b) % rep] != (uint8_t)byte)
            g->failed = true;
        return;
    }
    if (g->sched)
        g->sched[g->sched_len] = (uint8_t)byte;
    g->sched_len++;
#else
    (void)g;
    (void)byte;
#endif
}

/* Dry run: the source rows that no firing to come reads, one BG_S_FREE
 * byte each (the oldest row still read only moves forward). */
static void emit_free(bloom_t *g)
{
#if BLOOM_SCHED_TABLE
    const int o = imin(oldest_of(g, BG_SRC), g->gr.h[0]);
    for (; g->src_free < o; g->src_free++)
        emit(g, BG_S_FREE);
#else
    (void)g;
#endif
}

/* Node ni's next row, its inputs known to exist: sized and written down
 * (dry run) or made. A row overwritten while still needed is caught where
 * it is read (run_row compares the tags), so the write needs no check. */
static BLOOM_NOINLINE void next_row(bloom_t *g, int ni)
{
    bg_node_t *n = &g->gr.node[ni];
    const int r = n->next;
    if (BLOOM_SCHED_TABLE || g->dry) { /* (the table's rows are made by its walk) */
        n->need = (uint16_t)imax(n->need, r - imin(oldest_of(g, ni), r) + 1);
        emit(g, ni);
    } else {
        make_row(g, n, r);
    }
    n->next++;
    if (g->dry)
        emit_free(g);
}

/* Rows of node ni up to j (the source: pushed). The recursion runs down the
 * chain of nodes, one small frame per node (g, n, j, i live across the
 * call): the Cortex-M stack figure. */
static bool ensure(bloom_t *g, int ni, int j)
{
    if (ni < 0)
        return j < g->src_n;
    const bg_node_t *n = &g->gr.node[ni];
    while (n->next <= j) {
        for (int i = 0; i < n->nin; i++) {
            const int from = n->in[i].node, top = input_top(g, n, i, n->next);
            if (from < 0 ? top >= g->src_n : g->gr.node[from].next <= top && !ensure(g, from, top))
                return false; /* (a row already made needs no call) */
        }
        next_row(g, ni);
    }
    return true;
}

/* ---- the dry run and the frame ---------------------------------------- */

void bloom_dry_frame(bloom_t *g)
{
    bg_node_t *o = &g->gr.node[g->gr.out_node];
#if BLOOM_SCHED_TABLE /* (bloom_init runs it a second time, to write the table) */
    for (int i = 0; i < g->gr.nnodes; i++)
        g->gr.node[i].next = 0;
    g->src_n = 0;
    g->src_free = 0;
    g->sched_len = 0;
    g->dry_n = 0;
    struct bloom_fold_scan scan;
    if (!g->sched) /* the first run looks for the period; the second folds by it */
        bloom_fold_start(g, &scan);
#endif
    g->dry = true;
    emit_free(g);
    for (int y = 0; y < g->gr.h[0]; y++) {
        g->need_src = imax(g->need_src, y - imin(oldest_of(g, BG_SRC), y) + 1);
        emit(g, BG_S_PUSH);
        g->src_n = y + 1;
        while (o->next < g->gr.h[0]) {
            if (!ensure_inputs(g, o, o->next))
                break;
            g->latency = imax(g->latency, y - o->next);
            emit(g, g->gr.out_node);
            o->next++;
            emit_free(g);
        }
    }
#if BLOOM_SCHED_TABLE
    if (g->scan)
        bloom_fold_finish(g);
#endif
    g->dry = false;
}

bloom_status_t bloom_sched_push(bloom_t *g, const void *src_row, const void *aux_row, void *copy)
{
    if (bg_aux_bpp(&g->row) && !aux_row)
        return BLOOM_E_AUX;
    if (!bg_aux_bpp(&g->row) && aux_row) /* a plane the preset does not read */
        return BLOOM_E_AUX;
    if (g->src_n >= g->gr.h[0])
        return BLOOM_E_STATE;
    if (bg_tiled(&g->row) && g->gr.node[g->gr.out_node].next >= g->tile_y1) {
        g->src_n++; /* the tile is out: the rest of the window's rows are not needed */
        return BLOOM_OK;
    }
#if BLOOM_SCHED_TABLE
    const int r = g->src_n, slot = g->src_put;
    /* the rows the table makes before the next output row may free the
     * slot (a pull could not: it stops at that row); then a push is BUSY
     * only when an output row is due */
    if (r - g->src_cap >= g->src_free)
        walk_to_output(g, NULL);
    if (g->failed)
        return BLOOM_E_INTERNAL;
    if (r - g->src_cap >= g->src_free)
#else
    const int r = g->src_n, slot = r % g->src_cap;
    if (r - g->src_cap >= oldest_of(g, BG_SRC))
#endif
        return BLOOM_E_BUSY;
    /* the window's columns of the frame row (win_x is 0 without a tile) */
    src_row = (const uint8_t *)src_row + (size_t)bg_win_x(&g->row) * (size_t)g->row.src_bpp;
    if (bg_aux_bpp(&g->row))
        aux_row = (const uint8_t *)aux_row + (size_t)bg_win_x(&g->row) * (size_t)bg_aux_bpp(&g->row);
    if (g->src_copy) { /* (the slots' pointers are the copies', set once) */
        memcpy(g->src_copy + (size_t)slot * g->src_row_bytes, src_row, g->src_row_bytes);
        if (bg_aux_bpp(&g->row))
            memcpy(g->aux_copy + (size_t)slot * g->aux_row_bytes, aux_row, g->aux_row_bytes);
    } else {
        put_ptr(g->src_ptr, slot, g->src_cap, src_row);
        if (bg_aux_bpp(&g->row))
            put_ptr(g->aux_ptr, slot, g->src_cap, aux_row);
    }
#if BG_DARK_COPY
    const bool dark =
        g->row.dark_src &&
        (copy ? g->row.kern.dark_copy(g->cfg.in_fmt, (const uint8_t *)src_row, g->gr.w[0], &g->row.dark, copy)
              : g->row.kern.dark(g->cfg.in_fmt, (const uint8_t *)src_row, g->gr.w[0], &g->row.dark));
#elif BLOOM_USE_SKIP
    (void)copy;
    const bool dark =
        g->row.dark_src &&
        BLOOM_KERN_DARK(&g->row.kern)(g->cfg.in_fmt, (const uint8_t *)src_row, g->gr.w[0], &g->row.dark);
#else
    (void)copy;
    const bool dark = false;
#endif
    const int32_t tag = dark ? r | ZBIT : r;
#if BLOOM_SCHED_TABLE
    if ((put_tag(g->src_tag, NULL, slot, g->src_cap, tag) ^ tag) & ZBIT)
        flip_src_bits(g->src_zb, slot, g->src_cap);
    g->src_put = slot + 1 == g->src_cap ? 0 : slot + 1;
#else
    put_tag(g->src_tag, NULL, slot, g->src_cap, tag);
#endif
    g->src_n++;
    return BLOOM_OK;
}

#if BLOOM_SCHED_TABLE
/* Walk the schedule up to the output's next row: true when it is due (its
 * inputs made), and then made into dst if there is one (the walk passes
 * its byte); false when the walk waits for a push. The tile's halo rows
 * above it are passed (their inputs are made, they are not). The one
 * caller of run_row: every row is made here, run_row inlined. */
static bool walk_to_output(bloom_t *g, void *dst)
{
    /* the output node is the last (bloom_plan checks it): a byte below it
     * is a node row, the commonest */
    bg_node_t *node = g->gr.node, *o = &node[g->gr.out_node];
    const int out = g->gr.out_node;
    const uint8_t *t = g->sched;
    int at = g->sched_at;
    /* the walk stops at `end`: the period's end while it is walked again,
     * then the table's */
    int end = g->walk_end;
    for (;; at++) {
        if (at >= end) { /* (the period may end the table: no end part) */
            if (g->fold_rep >= g->fold_m - 1)
                break;
            at = g->fold_b; /* the period again */
            end = g->walk_end = ++g->fold_rep < g->fold_m - 1 ? g->fold_e : g->sched_len;
        }
        const int e = t[at];
        if (e < out) {
            make_row(g, &node[e], node[e].next);
            node[e].next++;
        } else if (e == out) {
            if (!bg_tiled(&g->row) || o->next >= g->tile_y0) {
                if (dst) {
                    run_row(g, o, o->next, dst);
                    at++;
                }
                g->sched_at = at;
                return true;
            }
            o->next++;
        } else if (e == BG_S_FREE) {
            g->src_free++;
        } else { /* BG_S_PUSH */
            if (g->src_seen == g->src_n)
                break;
            g->src_seen++;
        }
    }
    g->sched_at = at;
    return false;
}
#endif

bloom_status_t bloom_sched_pull(bloom_t *g, void *dst_row)
{
    bg_node_t *o = &g->gr.node[g->gr.out_node];
#if BLOOM_SCHED_TABLE
    if (o->next >= g->gr.h[0] || (bg_tiled(&g->row) && o->next >= g->tile_y1))
        return BLOOM_DONE;
    void *row = bg_tiled(&g->row) ? (void *)g->out_row : dst_row;
    if (!walk_to_output(g, row) || g->failed) /* (the row made) */
        return g->failed ? BLOOM_E_INTERNAL : BLOOM_AGAIN;
#else
#if !BLOOM_SMALL
    if (g->row.tiled) /* halo rows above the tile: their inputs are made, they are not */
        while (o->next < g->tile_y0 && o->next < g->src_n && ensure_inputs(g, o, o->next))
            o->next++;
#endif
    const int y = o->next;
    if (y >= g->gr.h[0] || (bg_tiled(&g->row) && y >= g->tile_y1))
        return BLOOM_DONE;
    if (y >= g->src_n || !ensure_inputs(g, o, y))
        return g->failed ? BLOOM_E_INTERNAL : BLOOM_AGAIN;
    run_row(g, o, y, bg_tiled(&g->row) ? (void *)g->out_row : dst_row);
    if (g->failed)
        return BLOOM_E_INTERNAL;
#endif
    if (bg_tiled(&g->row)) { /* the tile's columns of the window's row */
        const size_t bpp = (size_t)bloom_bpp(g->cfg.out_fmt);
        memcpy((uint8_t *)dst_row + (size_t)g->cfg.tile_x * bpp,
               g->out_row + (size_t)(g->tile_x0 - o->xa) * bpp, (size_t)(g->tile_x1 - g->tile_x0) * bpp);
    }
    o->next++;
    g->out_rows++;
    return BLOOM_OK;
}
