/* fuzz_api: the engine's API (include/bloom.h). Each input makes a
 * configuration (a preset and its defaults, then fields in and out of
 * range), checks what bloom_query says of it against the documented
 * ranges, and runs frames of at most 64x64 through a random sequence of
 * row pushes and pulls, band pushes and whole frames, misuse included
 * (push after the last row, pull before any push, begin twice, NULL
 * handles, a workspace one byte short or misaligned). The workspace, the
 * frames, the gaps between their rows and the aux plane are fenced by
 * ASan-poisoned canaries checked after every call; the source must not
 * change; every output row must equal the same frame run whole by a
 * second engine whose flags differ in what must not change the bits
 * (NO_SKIP, NO_SIMD, NO_AVX2, COPY_SOURCE). */
#include "fuzz.h"
#include "fuzz_api.h"

#include "bloom.h"

#include <stdlib.h>
#include <string.h>

#define CAN 64 /* canary bytes before and after every buffer */

/* ---- fenced buffers ---------------------------------------------------- */

/* rows rows of row bytes, stride apart; the gaps and both ends canaries. */
typedef struct {
    uint8_t *block, *p;
    size_t row, stride, bytes;
    int rows;
} buf_t;

static void buf_new(buf_t *b, size_t row, size_t stride, int rows)
{
    b->row = row;
    b->stride = stride;
    b->rows = rows;
    b->bytes = stride * (size_t)(rows - 1) + row;
    b->block = malloc(b->bytes + 2 * CAN);
    b->p = b->block + CAN;
    memset(b->p, 0, b->bytes);
    fz_canary_set(b->block, CAN);
    fz_canary_set(b->p + b->bytes, CAN);
    if (stride > row)
        for (int r = 0; r + 1 < rows; r++)
            fz_canary_set(b->p + (size_t)r * stride + row, stride - row);
}

static uint8_t *buf_row(const buf_t *b, int y)
{
    return b->p + (size_t)y * b->stride;
}

static void buf_check(const buf_t *b, const char *what, const char *after)
{
    FZ_CHECKF(fz_canary_ok(b->block, CAN) && fz_canary_ok(b->p + b->bytes, CAN), "%s fence hit after %s",
              what, after);
    if (b->stride > b->row)
        for (int r = 0; r + 1 < b->rows; r++)
            FZ_CHECKF(fz_canary_ok(b->p + (size_t)r * b->stride + b->row, b->stride - b->row),
                      "%s: the gap after row %d written by %s", what, r, after);
}

static void buf_free(buf_t *b)
{
    free(b->block); /* free checks nothing of poisoning: the block is the allocation */
    memset(b, 0, sizeof *b);
}

/* ---- the run's state ----------------------------------------------------- */

typedef struct {
    bloom_config_t c;
    bloom_info_t info;
    int w, h, in_bpp, out_bpp, aux_bpp, copy;
    buf_t src, dst, aux, ws, ref;
    uint8_t *pristine; /* the source rows as made, packed */
    bloom_t *b;
    int in, out, aux_set; /* rows pushed and pulled as the API said; set_aux done */
    const char *op;
} run_t;

static uint32_t rng_state;
static uint32_t rng(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return rng_state;
}

/* After every call: the fences hold, the source is as made, the row
 * counts are what the statuses said. */
static void check_all(const run_t *r)
{
    buf_check(&r->ws, "workspace", r->op);
    buf_check(&r->src, "source", r->op);
    buf_check(&r->dst, "destination", r->op);
    buf_check(&r->aux, "aux plane", r->op);
    for (int y = 0; y < r->h; y++)
        FZ_CHECKF(!memcmp(buf_row(&r->src, y), r->pristine + (size_t)y * r->src.row, r->src.row),
                  "source row %d changed by %s", y, r->op);
    FZ_CHECKF(bloom_rows_in(r->b) == r->in && bloom_rows_out(r->b) == r->out,
              "after %s: rows in %d out %d, the statuses said %d and %d", r->op, bloom_rows_in(r->b),
              bloom_rows_out(r->b), r->in, r->out);
}

static void expect_row(const run_t *r, const uint8_t *got, int y)
{
    FZ_CHECKF(!memcmp(got, buf_row(&r->ref, y), r->dst.row),
              "output row %d (by %s) differs from the whole frame's", y, r->op);
}

/* No output row is ready that the API did not give: output row y is ready
 * once source row min(y + latency, h - 1) is in (bloom.h, README). */
static void check_drained(const run_t *r)
{
    if (r->out < r->h) {
        const int need = r->out + r->info.latency_rows < r->h - 1 ? r->out + r->info.latency_rows : r->h - 1;
        FZ_CHECKF(r->in <= need, "after %s: output row %d not given with %d rows in (latency %d)", r->op,
                  r->out, r->in, r->info.latency_rows);
    }
}

/* ---- frames ---------------------------------------------------------------- */

/* The source (and aux plane): what the input's pattern byte says, from a
 * generator seeded by the input. */
static void fill(uint8_t *p, size_t n, int bpp12, unsigned pattern)
{
    for (size_t i = 0; i < n; i++) {
        const uint32_t v = rng();
        switch (pattern % 4) {
        case 0:
            p[i] = (uint8_t)v;
            break; /* noise */
        case 1:
            p[i] = (v & 63) == 0 ? 0xFF : (uint8_t)(v & 7); /* dark, a few lights */
        case 2:
            p[i] = 0xFF;
            break; /* all at the top */
        default:
            p[i] = (uint8_t)(i * 7);
            break; /* ramps */
        }
    }
    if (bpp12 && pattern % 4 == 2) /* Q16.16 words: keep some above 2^24 and some at 1.0 */
        for (size_t i = 0; i + 4 <= n; i += 4)
            if (rng() & 1)
                p[i + 3] = 0, p[i + 2] = 1, p[i + 1] = p[i] = 0;
}

/* A second engine (flags differing only in what must not change the
 * bits) runs the frame whole into r->ref. */
static void make_reference(run_t *r, uint32_t flip)
{
    bloom_config_t c = r->c;
    c.flags ^= flip;
    bloom_info_t info;
    FZ_CHECKF(bloom_query(&c, &info) == BLOOM_OK, "flags %#x taken, %#x refused", r->c.flags, c.flags);
    /* the same schedule, but for COPY_SOURCE: xna leaves its dark window of
     * source rows out there (6 copied rows of workspace), 6 rows sooner */
    FZ_CHECK(info.levels == r->info.levels &&
             (info.latency_rows == r->info.latency_rows || flip == BLOOM_FLAG_COPY_SOURCE));
    uint8_t *ws = malloc(info.workspace_bytes);
    memset(ws, 0x5A, info.workspace_bytes); /* another garbage than the engine under test's */
    bloom_t *b;
    FZ_CHECK(bloom_init(&b, ws, info.workspace_bytes, &c) == BLOOM_OK);
    if (r->aux_bpp)
        FZ_CHECK(bloom_set_aux(b, r->aux.p, (ptrdiff_t)r->aux.stride) == BLOOM_OK);
    buf_new(&r->ref, r->dst.row, r->dst.stride, r->h);
    const bloom_status_t st =
        bloom_process(b, r->src.p, (ptrdiff_t)r->src.stride, r->ref.p, (ptrdiff_t)r->ref.stride);
    FZ_CHECKF(st == BLOOM_OK, "whole frame: %s", bloom_status_str(st));
    FZ_CHECK(bloom_rows_in(b) == r->h && bloom_rows_out(b) == r->h);
    free(ws);
}

/* Workspace refusals: one byte short, misaligned, NULLs. */
static void check_init_refusals(const run_t *r)
{
    const size_t n = r->info.workspace_bytes;
    bloom_t *b;
    uint8_t *shortws = malloc(n - 1); /* exactly: ASan sees a byte written past it */
    FZ_CHECK(bloom_init(&b, shortws, n - 1, &r->c) == BLOOM_E_WORKSPACE);
    free(shortws);
    uint8_t *big = malloc(n + 8);
    FZ_CHECK(bloom_init(&b, big + 1, n, &r->c) == BLOOM_E_ALIGN);
    FZ_CHECK(bloom_init(NULL, big, n, &r->c) == BLOOM_E_NULL);
    FZ_CHECK(bloom_init(&b, NULL, n, &r->c) == BLOOM_E_NULL);
    FZ_CHECK(bloom_init(&b, big, n, NULL) == BLOOM_E_NULL);
    free(big);
}

static void check_nulls(run_t *r)
{
    uint8_t *row = buf_row(&r->src, 0), *out = buf_row(&r->dst, 0);
    const ptrdiff_t ss = (ptrdiff_t)r->src.stride, ds = (ptrdiff_t)r->dst.stride;
    FZ_CHECK(bloom_begin(NULL) == BLOOM_E_NULL && bloom_push_row(NULL, row) == BLOOM_E_NULL);
    FZ_CHECK(bloom_push_row_aux(NULL, row, row) == BLOOM_E_NULL && bloom_pull_row(NULL, out) == BLOOM_E_NULL);
    FZ_CHECK(bloom_set_aux(NULL, row, 1) == BLOOM_E_NULL && bloom_set_aux(r->b, NULL, 1) == BLOOM_E_NULL);
    FZ_CHECK(bloom_run_rows(NULL, row, ss, 1, out, ds) == BLOOM_E_NULL);
    FZ_CHECK(bloom_process(NULL, row, ss, out, ds) == BLOOM_E_NULL);
    FZ_CHECK(bloom_push_row(r->b, NULL) == BLOOM_E_NULL && bloom_pull_row(r->b, NULL) == BLOOM_E_NULL);
    FZ_CHECK(bloom_run_rows(r->b, NULL, ss, 1, out, ds) == BLOOM_E_NULL);
    FZ_CHECK(bloom_run_rows(r->b, row, ss, 1, NULL, ds) == BLOOM_E_NULL);
    FZ_CHECK(bloom_rows_in(NULL) == BLOOM_E_NULL && bloom_rows_out(NULL) == BLOOM_E_NULL);
}

/* Destinations over source rows the engine still reads (pointer mode):
 * refused, nothing written (bloom.h, BLOOM_E_ALIAS). */
static void check_alias(const run_t *r, unsigned pick)
{
    if (!r->copy && r->in > r->out + 1) { /* a pulled row over a later source row still held */
        const int y = r->out + 1 + (int)(pick % (unsigned)(r->in - r->out - 1));
        const bloom_status_t st = bloom_pull_row(r->b, buf_row(&r->src, y));
        FZ_CHECKF(st == BLOOM_E_ALIAS, "output row %d pulled over source row %d: %s", r->out, y,
                  bloom_status_str(st));
    }
    /* a band written over its own source: two rows, one row down; or the
     * same rows in another format */
    const int same = r->c.in_fmt == r->c.out_fmt, n = same ? 2 : 1, shift = same ? 1 : 0;
    if (r->in + n <= r->h) {
        const bloom_status_t st =
            bloom_run_rows(r->b, r->src.p, (ptrdiff_t)r->src.stride, n,
                           r->src.p + (size_t)shift * r->src.stride, (ptrdiff_t)r->src.stride);
        FZ_CHECKF(st == BLOOM_E_ALIAS, "a band written over its source (%d rows down): %s", shift,
                  bloom_status_str(st));
    }
}

/* Pulls one row (into a private exact-size row when priv): checks the
 * status against the state, and the row against the whole frame's. */
static bloom_status_t pull(run_t *r, int priv)
{
    const int y = r->out;
    uint8_t *own = priv ? malloc(r->dst.row) : NULL;
    uint8_t *dst = own ? own : buf_row(&r->dst, y < r->h ? y : 0);
    const bloom_status_t st = bloom_pull_row(r->b, dst);
    if (y >= r->h) {
        FZ_CHECKF(st == BLOOM_DONE, "pull after the last row: %d", st);
    } else if (st == BLOOM_OK) {
        FZ_CHECKF(y < r->in, "output row %d given with %d source rows in", y, r->in);
        expect_row(r, dst, y);
        if (own)
            memcpy(buf_row(&r->dst, y), own, r->dst.row);
        r->out++;
    } else {
        FZ_CHECKF(st == BLOOM_AGAIN, "pull of row %d: %s", y, bloom_status_str(st));
        check_drained(r);
    }
    free(own);
    return st;
}

/* Pushes the next source row (from private copies freed right after the
 * call in COPY_SOURCE mode: ASan sees a pointer kept to them). misuse:
 * without the aux row the preset reads, or with one it reads none of. */
static void push(run_t *r, int misuse, int priv)
{
    const int y = r->in < r->h ? r->in : r->h - 1, with_aux = misuse ? !r->aux_bpp : r->aux_bpp;
    const uint8_t *row = buf_row(&r->src, y), *arow = buf_row(&r->aux, y);
    uint8_t *own = NULL, *aown = NULL;
    if (priv && r->copy) {
        own = malloc(r->src.row);
        aown = malloc(r->aux.row);
        memcpy(own, row, r->src.row);
        memcpy(aown, arow, r->aux.row);
        row = own;
        arow = aown;
    }
    const bloom_status_t st = with_aux ? bloom_push_row_aux(r->b, row, arow) : bloom_push_row(r->b, row);
    free(own);
    free(aown);
    if (r->aux_bpp && !with_aux) {
        FZ_CHECKF(st == BLOOM_E_AUX, "a push without the aux row the preset reads: %s", bloom_status_str(st));
    } else if (with_aux && !r->aux_bpp) { /* every pipeline that reads no plane refuses one */
        FZ_CHECKF(st == BLOOM_E_AUX, "an aux row for a pipeline that reads none: %s", bloom_status_str(st));
    } else if (r->in >= r->h) {
        FZ_CHECKF(st == BLOOM_E_STATE, "push after the last row: %s", bloom_status_str(st));
    } else if (st == BLOOM_E_BUSY) { /* a row the engine still needs: a pull must free it */
        r->op = "a pull after BLOOM_E_BUSY";
        FZ_CHECKF(pull(r, 0) == BLOOM_OK, "BLOOM_E_BUSY at row %d, and nothing to pull", y);
    } else {
        FZ_CHECKF(st == BLOOM_OK, "push of row %d: %s", y, bloom_status_str(st));
        r->in++;
    }
}

/* A band of n rows through bloom_run_rows (into dst, or in place). */
static void band(run_t *r, int n, buf_t *dst)
{
    const int out0 = r->out;
    const bloom_status_t st =
        bloom_run_rows(r->b, r->src.p, (ptrdiff_t)r->src.stride, n, dst->p, (ptrdiff_t)dst->stride);
    if (n < 0 || r->in + n > r->h) {
        FZ_CHECKF(st == BLOOM_E_STATE, "a band of %d rows after %d of %d: %s", n, r->in, r->h,
                  bloom_status_str(st));
        return;
    }
    if (r->aux_bpp && !r->aux_set) {
        FZ_CHECKF(st == BLOOM_E_AUX, "a band without bloom_set_aux: %s", bloom_status_str(st));
        return;
    }
    FZ_CHECKF(st == BLOOM_OK, "a band of %d rows: %s", n, bloom_status_str(st));
    r->in += n;
    r->out = bloom_rows_out(r->b);
    FZ_CHECK(r->out >= out0 && r->out <= r->in);
    for (int y = out0; y < r->out; y++)
        expect_row(r, buf_row(dst, y), y);
    check_drained(r);
}

static void run_frames(run_t *r, fz_in_t *in)
{
    r->w = r->c.width;
    r->h = r->c.height;
    r->in_bpp = bloom_format_bpp(r->c.in_fmt);
    r->out_bpp = bloom_format_bpp(r->c.out_fmt);
    r->aux_bpp = r->c.aux_fmt == BLOOM_AUX_U16 ? 2 : r->c.aux_fmt == BLOOM_AUX_U8 ? 1 : 0;
    r->copy = (r->c.flags & BLOOM_FLAG_COPY_SOURCE) != 0;
    /* strides: packed or with a gap, in whole samples (rows of uint32_t
     * or uint16_t words are read as such) */
    const unsigned gaps = fz_u8(in);
    const size_t srow = (size_t)r->w * (size_t)r->in_bpp, drow = (size_t)r->w * (size_t)r->out_bpp;
    buf_new(&r->src, srow, srow + (gaps & 1 ? 4 * (1 + gaps % 5) : 0), r->h);
    buf_new(&r->dst, drow, drow + (gaps & 2 ? 4 * (1 + gaps % 3) : 0), r->h);
    buf_new(&r->aux, (size_t)r->w * 2, (size_t)r->w * 2 + (gaps & 4 ? 2 : 0), r->h);
    rng_state = fz_u32(in) | 1;
    const unsigned pattern = fz_u8(in);
    r->pristine = malloc(srow * (size_t)r->h);
    for (int y = 0; y < r->h; y++) {
        fill(buf_row(&r->src, y), srow, r->in_bpp == 12, pattern);
        memcpy(r->pristine + (size_t)y * srow, buf_row(&r->src, y), srow);
        fill(buf_row(&r->aux, y), r->aux.row, 0, pattern >> 2);
    }
    static const uint32_t same[] = {BLOOM_FLAG_NO_SKIP, BLOOM_FLAG_NO_SIMD, BLOOM_FLAG_NO_AVX2,
                                    BLOOM_FLAG_COPY_SOURCE};
    make_reference(r, same[fz_u8(in) % 4]);
    check_init_refusals(r);
    /* the engine under test, in a fenced workspace full of garbage */
    buf_new(&r->ws, r->info.workspace_bytes, r->info.workspace_bytes, 1);
    memset(r->ws.p, (int)fz_u8(in), r->info.workspace_bytes);
    r->op = "bloom_init";
    FZ_CHECK(bloom_init(&r->b, r->ws.p, r->info.workspace_bytes, &r->c) == BLOOM_OK);
    check_all(r);
    buf_t inplace = {0};
    for (int ops = 0; in->n && ops < 400; ops++) {
        /* low 4 bits: the call; high bits: its variant */
        const unsigned op = fz_u8(in);
        bloom_status_t st;
        switch (op & 15) {
        case 0:
            r->op = "bloom_begin";
            FZ_CHECK(bloom_begin(r->b) == BLOOM_OK);
            r->in = r->out = 0;
            break;
        case 1:
        case 2:
        case 3:
        case 14:
            r->op = "bloom_push_row";
            push(r, (op & 0xC0) == 0xC0, (op >> 4) & 1);
            break;
        case 4:
        case 5:
        case 6:
        case 15:
            r->op = "bloom_pull_row";
            pull(r, (op >> 4) & 1);
            break;
        case 7: /* pull until AGAIN or DONE, as the README's loop */
            r->op = "bloom_pull_row (drain)";
            while (pull(r, 0) == BLOOM_OK)
                ;
            break;
        case 12:
            r->op = "a destination over the source";
            check_alias(r, fz_u8(in));
            break;
        case 8:
            r->op = "bloom_run_rows";
            band(r, (int)(fz_u8(in) % (unsigned)(r->h + 3)) - 1, &r->dst);
            break;
        case 9:
            r->op = "bloom_set_aux";
            st = bloom_set_aux(r->b, r->aux.p, (ptrdiff_t)r->aux.stride);
            FZ_CHECKF(st == (r->aux_bpp ? BLOOM_OK : BLOOM_E_AUX), "%s", bloom_status_str(st));
            r->aux_set |= st == BLOOM_OK;
            break;
        case 10:
            r->op = "NULL handles";
            check_nulls(r);
            break;
        default:             /* 11 and 13 */
            if (op & 0x10) { /* bloom_init over the running engine: a fresh start */
                r->op = "bloom_init again";
                FZ_CHECK(bloom_init(&r->b, r->ws.p, r->info.workspace_bytes, &r->c) == BLOOM_OK);
                r->in = r->out = r->aux_set = 0;
                break;
            }
            if (r->aux_bpp && !r->aux_set) { /* a whole frame without the plane: refused */
                r->op = "bloom_process without bloom_set_aux";
                st = bloom_process(r->b, r->src.p, (ptrdiff_t)r->src.stride, r->dst.p,
                                   (ptrdiff_t)r->dst.stride);
                FZ_CHECKF(st == BLOOM_E_AUX, "%s", bloom_status_str(st));
                r->in = r->out = 0;
                break;
            }
            if ((op & 0x20) && r->c.in_fmt == r->c.out_fmt) {
                /* in place (formats and strides match): bands over a copy */
                r->op = "in place";
                if (!inplace.block)
                    buf_new(&inplace, r->src.row, r->src.stride, r->h);
                for (int y = 0; y < r->h; y++)
                    memcpy(buf_row(&inplace, y), buf_row(&r->src, y), r->src.row);
                FZ_CHECK(bloom_begin(r->b) == BLOOM_OK);
                r->in = r->out = 0;
                const buf_t keep = r->src;
                r->src = inplace;
                while (r->in < r->h)
                    band(r, 1 + (int)(fz_u8(in) % (unsigned)r->h) % (r->h - r->in), &inplace);
                r->src = keep;
                buf_check(&inplace, "in-place frame", r->op);
                break;
            }
            r->op = "bloom_process";
            st = bloom_process(r->b, r->src.p, (ptrdiff_t)r->src.stride, r->dst.p, (ptrdiff_t)r->dst.stride);
            FZ_CHECKF(st == BLOOM_OK, "%s", bloom_status_str(st));
            r->in = r->out = r->h;
            for (int y = 0; y < r->h; y++)
                expect_row(r, buf_row(&r->dst, y), y);
            break;
        }
        check_all(r);
    }
    if (inplace.block)
        buf_free(&inplace);
    buf_free(&r->ws);
    buf_free(&r->src);
    buf_free(&r->dst);
    buf_free(&r->aux);
    buf_free(&r->ref);
    free(r->pristine);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in_t in = {data, size};
    fz_api_check_pure(&in);
    run_t r;
    memset(&r, 0, sizeof r);
    const int pristine = fz_api_make_config(&in, &r.c);
    const bloom_status_t st = bloom_query(&r.c, &r.info);
    FZ_CHECK(bloom_status_str(st) != NULL);
    if (pristine)
        FZ_CHECKF(st == BLOOM_OK, "a preset's defaults refused: %s", bloom_status_str(st));
    if (st != BLOOM_OK) {
        FZ_CHECK(st < 0 && bloom_workspace_size(&r.c) == 0);
        uint64_t ws[64];
        bloom_t *b = (bloom_t *)(void *)ws; /* not NULL: a refusal must clear it */
        FZ_CHECK(bloom_init(&b, ws, sizeof ws, &r.c) != BLOOM_OK && b == NULL);
        return 0;
    }
    fz_api_check_taken(&r.c, &r.info);
    run_frames(&r, &in);
    return 0;
}
