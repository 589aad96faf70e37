/* The scheduler (bloom_engine.h): rows in and out (a row at a time, or a
 * band or frame fed to one walk), and the dry run.
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
#include "bloom_sched_rows.h"

#include <string.h>

#define FAR (1 << 30)
/* A node slot that holds no row yet (the zero bit kept: see bloom_begin). */
#define NO_ROW 0x3FFFFFFF

/* ---- rows -------------------------------------------------------------- */

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

static void push_row(bloom_t *g, int slot, const void *src_row, const void *aux_row, void *copy);
#if BLOOM_SCHED_TABLE
static bool walk_to_output(bloom_t *g, void *dst, bloom_feed_t *f);
#endif

bloom_status_t bloom_sched_push(bloom_t *g, const void *src_row, const void *aux_row)
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
        walk_to_output(g, NULL, NULL);
    if (g->failed)
        return BLOOM_E_INTERNAL;
    if (r - g->src_cap >= g->src_free)
#else
    const int r = g->src_n, slot = r % g->src_cap;
    if (r - g->src_cap >= oldest_of(g, BG_SRC))
#endif
        return BLOOM_E_BUSY;
    push_row(g, slot, src_row, aux_row, NULL);
    return BLOOM_OK;
}

/* Source row src_n into ring slot `slot`, which no reader still needs
 * (bloom_sched_push's checks passed, or a feed's walk at the table's push);
 * copy: where a dark row's bytes go (the frame call's feed), else NULL. */
static void push_row(bloom_t *g, int slot, const void *src_row, const void *aux_row, void *copy)
{
    const int r = g->src_n;
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
}

#if BLOOM_SCHED_TABLE
/* Where the output node makes its row for the caller's row dst_row: there,
 * or a tile's columns of it (written in place: the row function starts at
 * bg_out_x0), or out_row (copied out by out_made). */
static void *out_place(const bloom_t *g, void *dst_row)
{
    if (!bg_tiled(&g->row))
        return dst_row;
    return g->out_direct ? (uint8_t *)dst_row + (size_t)g->cfg.tile_x * (size_t)bloom_bpp(g->cfg.out_fmt)
                         : (void *)g->out_row;
}
#endif

/* Output row o->next made (at out_place(dst_row)): the tile's columns of
 * out_row copied to dst_row, counted. */
static void out_made(bloom_t *g, void *dst_row)
{
    bg_node_t *o = &g->gr.node[g->gr.out_node];
    if (bg_tiled(&g->row) && !g->out_direct) { /* the tile's columns of the window's row */
        const size_t bpp = (size_t)bloom_bpp(g->cfg.out_fmt);
        memcpy((uint8_t *)dst_row + (size_t)g->cfg.tile_x * bpp,
               g->out_row + (size_t)(g->tile_x0 - o->xa) * bpp, (size_t)(g->tile_x1 - g->tile_x0) * bpp);
    }
    o->next++;
    g->out_rows++;
}

#if BLOOM_SCHED_TABLE
/* The feed's next source row pushed, at the table's push (its slot free,
 * checked: the table is checked at bloom_init, but not the rings without
 * BLOOM_CHECK_RINGS); false when it is not. */
static BLOOM_NOINLINE bool feed_push(bloom_t *g, const bloom_feed_t *f)
{
    if (g->src_n - g->src_cap >= g->src_free) { /* a wrong table: fail, not overwrite a row still read */
        g->failed = true;
        return false;
    }
    const ptrdiff_t fr = (ptrdiff_t)bg_win_y(&g->row) + g->src_n; /* the frame row */
    push_row(g, g->src_put, f->src + fr * f->src_stride, f->aux ? f->aux + fr * f->aux_stride : NULL,
             f->copies ? f->dst + fr * f->dst_stride : NULL); /* (untiled: output row r is frame row r) */
    return true;
}

/* The feed's next output row: its place, and whether the push copied its
 * source row there (a dark row: par.dst_copied). */
static uint8_t *feed_row(bloom_t *g, bloom_feed_t *f)
{
    if (f->copies) {
        for (; f->orow < g->out_rows; f->orow++)
            f->oslot = f->oslot + 1 == g->src_cap ? 0 : f->oslot + 1;
        g->row.par.dst_copied = g->src_tag[f->oslot] == (g->out_rows | ZBIT);
    }
    return f->dst + (ptrdiff_t)(f->out_y0 + g->out_rows) * f->dst_stride;
}

/* Walk the schedule up to the output's next row: true when it is due (its
 * inputs made), and then made into dst if there is one (the walk passes
 * its byte); false when the walk waits for a push. With a feed f, the walk
 * pushes its rows and makes every output row due into its place, and goes
 * on to the feed's end, the tile's last row or the table's (true if any
 * output row was due: unused). The tile's
 * halo rows above it are passed (their inputs are made, they are not). The
 * one caller of run_row: every row is made here, run_row inlined. */
static bool walk_to_output(bloom_t *g, void *dst, bloom_feed_t *f)
{
    /* the output node is the last (bloom_plan checks it): a byte below it
     * is a node row, the commonest */
    bg_node_t *node = g->gr.node, *o = &node[g->gr.out_node];
    const int out = g->gr.out_node;
    const uint8_t *t = g->sched;
    int at = g->sched_at;
    bool due = false;
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
            if (bg_tiled(&g->row) && o->next < g->tile_y0) {
                o->next++;
                continue;
            }
            due = true;
            if (!dst && !f)
                break;
            uint8_t *row = f ? feed_row(g, f) : NULL;
            run_row(g, o, o->next, f ? out_place(g, row) : dst);
            if (f && !g->failed) { /* (a failed row is not counted: the call fails) */
                out_made(g, row);
                if (o->next < (bg_tiled(&g->row) ? g->tile_y1 : g->gr.h[0]))
                    continue;
            }
            at++;
            break;
        } else if (e == BG_S_FREE) {
            g->src_free++;
        } else { /* BG_S_PUSH */
            if (g->src_seen == g->src_n) {
                if (!f || g->src_n == f->end || g->failed || !feed_push(g, f))
                    break; /* (after a failed row the call ends at the next push) */
            }
            g->src_seen++;
        }
    }
    g->sched_at = at;
    return due;
}

bloom_status_t bloom_sched_feed(bloom_t *g, bloom_feed_t *f)
{
    const bg_node_t *o = &g->gr.node[g->gr.out_node];
    const int last = bg_tiled(&g->row) ? g->tile_y1 : g->gr.h[0];
    if (o->next < last)
        walk_to_output(g, NULL, f);
    g->row.par.dst_copied = false;
    if (g->failed)
        return BLOOM_E_INTERNAL;
    if (o->next >= last)
        g->src_n = f->end; /* the tile is out: the rest of the window's rows are not needed */
    return BLOOM_OK;
}
#endif

bloom_status_t bloom_sched_pull(bloom_t *g, void *dst_row)
{
    bg_node_t *o = &g->gr.node[g->gr.out_node];
#if BLOOM_SCHED_TABLE
    if (o->next >= g->gr.h[0] || (bg_tiled(&g->row) && o->next >= g->tile_y1))
        return BLOOM_DONE;
    if (!walk_to_output(g, out_place(g, dst_row), NULL) || g->failed) /* (the row made) */
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
    out_made(g, dst_row);
    return BLOOM_OK;
}
