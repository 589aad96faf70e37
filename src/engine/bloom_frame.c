/* The row, band and frame calls of the API: argument checks, the aliasing
 * rules (a destination may overlap its source only in place), and the band
 * and frame calls: one walk of the static schedule fed the frames
 * (bloom_sched_feed), or, in the size build, loops over the row calls of
 * the scheduler (bloom_sched.c). */
#include <string.h>

#include "bloom_engine.h"
#include "bloom_internal.h"

int bloom_rows_in(const bloom_t *b)
{
    if (!b)
        return BLOOM_E_NULL;
    return b->src_n;
}

int bloom_rows_out(const bloom_t *b)
{
    if (!b)
        return BLOOM_E_NULL;
    return b->out_rows;
}

/* Source rows of a frame (the source rectangle's), and output rows (the
 * tile's), and the frame rows the first of each is. */
static int rows_total(const bloom_t *b)
{
    return b->gr.h[0];
}
static int out_total(const bloom_t *b)
{
    return bg_tiled(&b->row) ? b->cfg.tile_h : b->gr.h[0];
}
static int out_row0(const bloom_t *b)
{
    return bg_tiled(&b->row) ? b->cfg.tile_y : 0;
}

bloom_status_t bloom_set_aux(bloom_t *b, const void *aux, ptrdiff_t aux_stride)
{
    if (!b || !aux)
        return BLOOM_E_NULL;
    if (!bg_aux_bpp(&b->row))
        return BLOOM_E_AUX;
    b->aux_frame = (const uint8_t *)aux;
    b->aux_stride = aux_stride;
    return BLOOM_OK;
}

bloom_status_t bloom_push_row_aux(bloom_t *b, const void *src_row, const void *aux_row)
{
    if (!b || !src_row)
        return BLOOM_E_NULL;
    return bloom_sched_push(b, src_row, aux_row);
}

bloom_status_t bloom_push_row(bloom_t *b, const void *src_row)
{
    if (!b || !src_row)
        return BLOOM_E_NULL;
    return bloom_sched_push(b, src_row, NULL);
}

#if !BLOOM_SMALL
/* Whether byte ranges [a, a + an) and [c, c + cn) meet. */
static bool ranges_meet(uintptr_t a, size_t an, uintptr_t c, size_t cn)
{
    return a < c + cn && c < a + an;
}
#endif

/* Whether output row y written at d would overwrite a source row the engine
 * still reads (pointer mode): any held row after y, or row y itself unless
 * d is that row and the formats are the same (in place). Rows before y are
 * never read again once y is out; empty slots (a negative tag) are skipped. */
static bool dst_overlaps(const void *const *ptr, const int32_t *tag, int cap, size_t src_bytes,
                         size_t dst_bytes, bool same, int y, const uint8_t *d)
{
#if BLOOM_SMALL /* the size build: only d over row y itself in another format */
    const int s = y % cap;
    (void)src_bytes;
    (void)dst_bytes;
    return (tag[s] & ~BLOOM_TAG_ZERO) == y && ptr[s] == d && !same;
#else
    for (int s = 0; s < cap; s++) {
        const int32_t r = tag[s] & ~BLOOM_TAG_ZERO;
        if (r >= y && ranges_meet((uintptr_t)d, dst_bytes, (uintptr_t)ptr[s], src_bytes) &&
            (r != y || ptr[s] != d || !same))
            return true;
    }
    return false;
#endif
}

/* The row call checks dst_row against every source row still held (a scan
 * of the source ring per row); the band and frame calls check their whole
 * span once instead (frames_overlap) and make their rows without it. */
bloom_status_t bloom_pull_row(bloom_t *b, void *dst_row)
{
    if (!b || !dst_row)
        return BLOOM_E_NULL;
    /* a tile writes its columns of the row, and never in place */
    const bool same = b->cfg.in_fmt == b->cfg.out_fmt && !bg_tiled(&b->row);
    const size_t obpp = (size_t)bloom_format_bpp(b->cfg.out_fmt);
    const size_t out_bytes = (size_t)(bg_tiled(&b->row) ? b->cfg.tile_w : b->cfg.width) * obpp;
    const uint8_t *d = (const uint8_t *)dst_row + (bg_tiled(&b->row) ? (size_t)b->cfg.tile_x * obpp : 0u);
    if (!b->src_copy && dst_overlaps(b->src_ptr, b->src_tag, b->src_cap, b->src_row_bytes, out_bytes, same,
                                     b->gr.node[b->gr.out_node].next, d))
        return BLOOM_E_ALIAS;
    return bloom_sched_pull(b, dst_row);
}

#if !BLOOM_SMALL
/* The byte span of rows r0 .. r1 - 1 of a frame (row 0 at p), for either
 * sign of the stride. */
static void span(const uint8_t *p, ptrdiff_t stride, int r0, int r1, uintptr_t *lo, uintptr_t *hi)
{
    const uintptr_t a = (uintptr_t)(p + (ptrdiff_t)r0 * stride),
                    z = (uintptr_t)(p + (ptrdiff_t)(r1 - 1) * stride);
    *lo = a < z ? a : z;
    *hi = a < z ? z : a;
}
#endif

/* A band's source and destination rows may overlap only as the same frame
 * (same rows, stride and format: in place): a destination row written over
 * a source row not yet pushed, or in another format, would corrupt it
 * (with COPY_SOURCE too: rows are copied only when pushed). */
static bool frames_overlap(const bloom_t *b, const uint8_t *s, ptrdiff_t ss, const uint8_t *d, ptrdiff_t ds,
                           int r0, int r1)
{
    if ((s == d && ss == ds && b->cfg.in_fmt == b->cfg.out_fmt && !bg_tiled(&b->row)) || r1 <= r0)
        return false;
#if BLOOM_SMALL /* the size build: the same buffer in another format or stride only */
    (void)ds;
    return s == d;
#else
    uintptr_t slo, shi, dlo, dhi;
    const size_t w = (size_t)b->cfg.width;
    /* The source rows this call pushes and the ones earlier calls pushed
     * that the ring may still hold (pointer mode), against the destination
     * rows it may write: from the next output row on (they trail the
     * source by the latency), up to the last row pushed. With a tile,
     * conservatively, every row of the tile. */
    const int held = b->src_copy ? r0 : imax(r0 - b->src_cap, 0);
    span(s, ss, bg_win_y(&b->row) + held, bg_win_y(&b->row) + r1, &slo, &shi);
    if (bg_tiled(&b->row))
        span(d, ds, b->cfg.tile_y, b->cfg.tile_y + b->cfg.tile_h, &dlo, &dhi);
    else
        span(d, ds, imin(bloom_rows_out(b), r1 - 1), r1, &dlo, &dhi);
    return ranges_meet(slo, shi - slo + w * (size_t)bloom_format_bpp(b->cfg.in_fmt), dlo,
                       dhi - dlo + w * (size_t)bloom_format_bpp(b->cfg.out_fmt));
#endif
}

#if BG_DARK_COPY
/* The frame call's dark rows (bloom_process): a source row tagged dark is
 * copied to its destination row as it is pushed, by the dark test itself
 * as it reads the row (kern.dark_copy: a row found bright leaves a part
 * copied, written over at its turn), when the preset's output of such a
 * row with no bloom is that copy (par.dark_copy) and the copy is the bytes
 * themselves (bloom_copy_is_bytes), out of place and untiled. At the row's turn the
 * output node's copy then has nothing to do (par.dst_copied, bg_copy_row); a
 * row that does get bloom is written over as before. A dark frame thus
 * costs one pass over each row, as a copy does: the destination
 * rows of a frame call are only defined when it returns
 * (sim/docs/streaming.md). The band and row calls never write a row before
 * its turn. */
static bool dark_copies(const bloom_t *b, const uint8_t *s, const uint8_t *d)
{
    return b->row.dark_src && b->row.par.dark_copy && s != d && !bg_tiled(&b->row) &&
           bloom_copy_is_bytes(&b->row.par.out);
}
#endif

static bloom_status_t run_rows(bloom_t *b, const void *src, ptrdiff_t src_stride, int nrows, void *dst,
                               ptrdiff_t dst_stride, bool frame)
{
    if (!b || !src || !dst)
        return BLOOM_E_NULL;
    const uint8_t *s = (const uint8_t *)src;
    uint8_t *d = (uint8_t *)dst;
    if (nrows < 0 || nrows > rows_total(b) - bloom_rows_in(b)) /* (no sum that could overflow) */
        return BLOOM_E_STATE;
    const int end = bloom_rows_in(b) + nrows;
    if (frames_overlap(b, s, src_stride, d, dst_stride, bloom_rows_in(b), end))
        return BLOOM_E_ALIAS;
    const uint8_t *aux = NULL;
    ptrdiff_t aux_stride = 0;
    if (bg_aux_bpp(&b->row)) {
        aux = b->aux_frame;
        aux_stride = b->aux_stride;
        if (!aux)
            return BLOOM_E_AUX;
    }
#if BLOOM_SCHED_TABLE
    /* one walk of the schedule pushes and pulls every row (bloom_feed_t);
     * the cursor on the source row of the next output row (untiled, the
     * output row of that number is made from it) */
#if BG_DARK_COPY
    const bool copies = frame && dark_copies(b, s, d);
#else
    (void)frame; /* (no early copies of dark rows in this build) */
    const bool copies = false;
#endif
    const int orow = bloom_rows_out(b);
    bloom_feed_t f = {.src = s,
                      .aux = aux,
                      .dst = d,
                      .src_stride = src_stride,
                      .aux_stride = aux_stride,
                      .dst_stride = dst_stride,
                      .end = end,
                      .out_y0 = out_row0(b),
                      .copies = copies,
                      .orow = orow,
                      .oslot = copies ? orow % b->src_cap : 0};
    return bloom_sched_feed(b, &f);
#else
    (void)frame; /* (only the frame call copies dark rows early) */
    for (;;) {
        bloom_status_t st;
        do
            st = bloom_sched_pull(b, d + (ptrdiff_t)(out_row0(b) + bloom_rows_out(b)) *
                                             dst_stride); /* span checked above */
        while (st == BLOOM_OK);
        if (st < 0)
            return st;
        const int r = bloom_rows_in(b);
        if (r == end)
            return BLOOM_OK;
        const ptrdiff_t fr = (ptrdiff_t)bg_win_y(&b->row) + r; /* the frame row */
        st = bloom_sched_push(b, s + fr * src_stride, aux ? aux + fr * aux_stride : NULL);
        if (st < 0)
            return st; /* BUSY cannot happen right after a full drain */
    }
#endif
}

bloom_status_t bloom_run_rows(bloom_t *b, const void *src, ptrdiff_t src_stride, int nrows, void *dst,
                              ptrdiff_t dst_stride)
{
    return run_rows(b, src, src_stride, nrows, dst, dst_stride, false);
}

bloom_status_t bloom_process(bloom_t *b, const void *src, ptrdiff_t src_stride, void *dst,
                             ptrdiff_t dst_stride)
{
    bloom_status_t st = bloom_begin(b);
    if (st == BLOOM_OK)
        st = run_rows(b, src, src_stride, rows_total(b), dst, dst_stride, true);
    if (st == BLOOM_OK && bloom_rows_out(b) != out_total(b))
        st = BLOOM_E_INTERNAL;
    return st;
}
