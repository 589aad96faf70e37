/* A preset's engine against its models (sim/model/bloom_model.h presets): the
 * core bit for bit against the bit-true model, and the error statistics
 * against the float model. Shared by tests/test_preset_*.c. */
#ifndef PRESET_CONFORM_H
#define PRESET_CONFORM_H

#include "conform.h"
#include "harness.h"

typedef struct {
    errstat_t vs_float;     /* core against the float model, output codes */
    long long bittrue_diff; /* samples where core and bit-true model differ */
    int ok;                 /* engine and both models ran */
} preset_conform_t;

/* aux: w*h codes of the aux plane as the core reads them (uint8_t or
 * uint16_t per cfg->aux_fmt, rows aux_stride bytes apart), or NULL. */
static inline preset_conform_t preset_conform(const bloom_config_t *c, const frame_t *src, const void *aux,
                                              ptrdiff_t aux_stride)
{
    preset_conform_t r;
    memset(&r, 0, sizeof r);
    bloom_info_t info;
    if (bloom_query(c, &info) != BLOOM_OK)
        return r;
    frame_t out;
    const bloom_status_t st = core_output(c, src, aux, aux_stride, &out);
    if (st != BLOOM_OK) {
        fprintf(stderr, "bloom_process (%s): %s\n", bloom_preset_name(c->preset), bloom_status_str(st));
        return r;
    }
    const size_t n = (size_t)c->width * (size_t)c->height * 3u, np = n / 3u;
    uint32_t *in = frame_codes(src), *core = frame_codes(&out);
    uint32_t *bt = (uint32_t *)xmalloc(n * sizeof *bt), *fl = (uint32_t *)xmalloc(n * sizeof *fl);
    uint32_t *ax = NULL;
    bloom_model_preset_args_t a;
    memset(&a, 0, sizeof a);
    a.cfg = c;
    a.src = in;
    fmt_max(c->in_fmt, a.src_max);
    fmt_max(c->out_fmt, a.dst_max);
    if (aux) {
        ax = (uint32_t *)xmalloc(np * sizeof *ax);
        for (int y = 0; y < c->height; y++)
            for (int x = 0; x < c->width; x++) {
                const uint8_t *row = (const uint8_t *)aux + (ptrdiff_t)y * aux_stride;
                uint16_t v16;
                if (c->aux_fmt == BLOOM_AUX_U16)
                    memcpy(&v16, row + 2 * x, 2);
                ax[(size_t)y * (size_t)c->width + (size_t)x] = c->aux_fmt == BLOOM_AUX_U16 ? v16 : row[x];
            }
        a.aux = ax;
        a.aux_max = c->aux_fmt == BLOOM_AUX_U16 ? 65535 : 255;
    }
    a.bittrue = 1;
    a.dst_codes = bt;
    const int l1 = bloom_model_preset_run(&a);
    a.bittrue = 0;
    a.dst_codes = fl;
    const int l2 = bloom_model_preset_run(&a);
    if (l1 > 0 && l2 > 0) {
        r.ok = 1;
        for (size_t i = 0; i < n; i++) {
            r.bittrue_diff += core[i] != bt[i];
            errstat_add(&r.vs_float, (long long)core[i] - (long long)fl[i]);
        }
    }
    free(in);
    free(core);
    free(bt);
    free(fl);
    free(ax);
    frame_free(&out);
    return r;
}

/* What preset_check_rows saw on the first frame, for a test's own checks. */
typedef struct {
    int busy;               /* BLOOM_E_BUSY answers */
    int pushed_before_pull; /* rows in at the first BLOOM_E_BUSY (0: none) */
    int source_rows;        /* bloom_info_t.source_rows */
} rows_check_t;

/* The row interface of c's engine on src (with the aux plane aux, rows
 * aux_stride bytes apart, unless NULL), against a whole-frame run (CHECKs):
 * a workspace one byte short refused; a pull before any push answers
 * BLOOM_AGAIN; with an aux plane a push without its row refused
 * (BLOOM_E_AUX, nothing pushed); rows pushed without pulling until
 * BLOOM_E_BUSY, then pulled until BLOOM_AGAIN, and so on; after the last
 * push pulled until BLOOM_DONE; a push after it refused (BLOOM_E_STATE);
 * the output that of the frame run, for two frames on the same engine (the
 * second BUSY at the same rows); the ring full at some point unless it
 * holds the whole frame; then bloom_process in place (dst = src) gives the
 * same output too, and the workspace canaries are intact. */
static inline rows_check_t preset_check_rows(const bloom_config_t *c, const frame_t *src, const void *aux,
                                             ptrdiff_t aux_stride)
{
    rows_check_t res[2];
    memset(res, 0, sizeof res);
    const char *pn = bloom_preset_name(c->preset);
    frame_t ref = run_engine_aux(c, src, aux, aux_stride);
    bloom_info_t info;
    CHECK(bloom_query(c, &info) == BLOOM_OK);
    guarded_t ws = guarded_alloc(info.workspace_bytes);
    bloom_t *b = NULL;
    CHECKF(bloom_init(&b, ws.p, info.workspace_bytes - 1, c) == BLOOM_E_WORKSPACE, "%s: one byte short", pn);
    CHECK(bloom_init(&b, ws.p, info.workspace_bytes, c) == BLOOM_OK);
    for (int frame = 0; frame < 2; frame++) {
        rows_check_t *rc = &res[frame];
        rc->source_rows = info.source_rows;
        frame_t out = frame_alloc(c->width, c->height, c->out_fmt, 0);
        CHECK(bloom_begin(b) == BLOOM_OK);
        CHECK(bloom_pull_row(b, out.p) == BLOOM_AGAIN);
        if (aux) {
            CHECKF(bloom_push_row(b, src->p) == BLOOM_E_AUX, "%s: a push without the aux row", pn);
            CHECK(bloom_rows_in(b) == 0);
        }
        bloom_status_t st = BLOOM_OK;
        while (bloom_rows_in(b) < c->height) {
            const int r = bloom_rows_in(b);
            const uint8_t *row = src->p + (size_t)r * src->stride;
            st = aux ? bloom_push_row_aux(b, row, (const uint8_t *)aux + (ptrdiff_t)r * aux_stride)
                     : bloom_push_row(b, row);
            if (st == BLOOM_E_BUSY) { /* drain and retry */
                rc->busy++;
                if (!rc->pushed_before_pull)
                    rc->pushed_before_pull = r;
                while ((st = bloom_pull_row(b, out.p + (size_t)bloom_rows_out(b) * out.stride)) == BLOOM_OK)
                    ;
                CHECK(st == BLOOM_AGAIN);
            } else if (st != BLOOM_OK) {
                break;
            }
        }
        CHECK(st != BLOOM_E_INTERNAL);
        while ((st = bloom_pull_row(b, out.p + (size_t)bloom_rows_out(b) * out.stride)) == BLOOM_OK)
            ;
        CHECK(st == BLOOM_DONE);
        CHECK((aux ? bloom_push_row_aux(b, src->p, aux) : bloom_push_row(b, src->p)) == BLOOM_E_STATE);
        CHECKF(frame_equal(&out, &ref), "%s: row interface (frame %d) = whole frame", pn, frame);
        CHECKF(rc->busy > 0 || info.source_rows >= c->height,
               "%s: ring fills when pushing without pulling (%d)", pn, rc->busy);
        frame_free(&out);
    }
    CHECKF(res[1].busy == res[0].busy && res[1].pushed_before_pull == res[0].pushed_before_pull,
           "%s: second frame BUSY %d times from row %d (first %d from %d)", pn, res[1].busy,
           res[1].pushed_before_pull, res[0].busy, res[0].pushed_before_pull);
    /* in place: dst aliases src */
    frame_t inpl = frame_alloc(c->width, c->height, c->in_fmt, 0);
    memcpy(inpl.p, src->p, src->bytes);
    if (aux)
        CHECK(bloom_set_aux(b, aux, aux_stride) == BLOOM_OK);
    CHECK(bloom_process(b, inpl.p, (ptrdiff_t)inpl.stride, inpl.p, (ptrdiff_t)inpl.stride) == BLOOM_OK);
    CHECKF(frame_equal(&inpl, &ref), "%s: in place = out of place", pn);
    CHECK(guarded_intact(&ws));
    guarded_free(&ws);
    frame_free(&inpl);
    frame_free(&ref);
    return res[0];
}

/* A deterministic aux plane: a smooth ramp plus noise (depth, mask or map),
 * uint8_t or uint16_t per fmt; rows stride bytes apart (returned). */
static inline void *aux_plane(int w, int h, bloom_aux_format_t fmt, uint32_t seed, ptrdiff_t *stride)
{
    const int bpp = fmt == BLOOM_AUX_U16 ? 2 : 1;
    *stride = (ptrdiff_t)w * bpp + 3;
    uint8_t *p = (uint8_t *)xmalloc((size_t)*stride * (size_t)h);
    uint32_t s = seed * 2654435761u + 7u;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const uint32_t ramp = (uint32_t)((x + y) * 65535 / (w + h > 2 ? w + h - 2 : 1));
            uint32_t v = (ramp + (rng_next(&s) & 8191u)) > 65535u ? 65535u : ramp + (rng_next(&s) & 8191u);
            uint8_t *q = p + (ptrdiff_t)y * *stride + x * bpp;
            if (bpp == 2) {
                const uint16_t v16 = (uint16_t)v;
                memcpy(q, &v16, 2);
            } else {
                *q = (uint8_t)(v >> 8);
            }
        }
    return p;
}

#endif
