/* Running the core and the reference model side by side on one frame, and
 * the error statistics between them. Shared by the conformance tests. */
#ifndef BLOOM_CONFORM_H
#define BLOOM_CONFORM_H

#include <math.h>

#include "bloom_model.h"
#include "testutil.h"

/* Errors against a model, in output LSB. The signed sum is kept beside the
 * absolute one: a bias hides in a mean of absolute errors. */
typedef struct {
    long long n, exact, over1, plus, minus; /* plus/minus: samples above/below */
    int peak;
    double sum, sum_abs, sum_sq;
} errstat_t;

static inline void errstat_add(errstat_t *e, long long d)
{
    long long a = d < 0 ? -d : d;
    e->n++;
    e->exact += a == 0;
    e->plus += d > 0;
    e->minus += d < 0;
    e->sum += (double)d;
    e->over1 += a > 1;
    if (a > e->peak)
        e->peak = (int)a;
    e->sum_abs += (double)a;
    e->sum_sq += (double)a * (double)a;
}

static inline void errstat_merge(errstat_t *into, const errstat_t *e)
{
    into->n += e->n;
    into->exact += e->exact;
    into->over1 += e->over1;
    into->plus += e->plus;
    into->minus += e->minus;
    into->sum += e->sum;
    into->peak = e->peak > into->peak ? e->peak : into->peak;
    into->sum_abs += e->sum_abs;
    into->sum_sq += e->sum_sq;
}

static inline double errstat_exact_pct(const errstat_t *e)
{
    return e->n ? 100.0 * (double)e->exact / (double)e->n : 100.0;
}

static inline double errstat_mean(const errstat_t *e)
{
    return e->n ? e->sum / (double)e->n : 0.0;
}

/* The bias bound: |signed mean| <= 0.0015 LSB (IEEE 1180's criterion for a
 * fixed-point transform against its float reference). */
#define ERR_BIAS_MAX 0.0015

static inline void errstat_print(const char *what, const errstat_t *e)
{
    printf("%-34s peak %d LSB, exact %.3f%%, signed mean %+.5f LSB (%lld above, %lld below), "
           "mean |e| %.5f, MSE %.5f, %lld samples\n",
           what, e->peak, errstat_exact_pct(e), errstat_mean(e), e->plus, e->minus,
           e->n ? e->sum_abs / (double)e->n : 0.0, e->n ? e->sum_sq / (double)e->n : 0.0, e->n);
}

static inline void fmt_max(bloom_format_t f, int m[3])
{
    m[0] = m[1] = m[2] = f == BLOOM_FMT_RGBQ16 ? 0 : f == BLOOM_FMT_RGBF32 ? BLOOM_MODEL_F32 : 255;
    if (f == BLOOM_FMT_RGB565) {
        m[0] = m[2] = 31;
        m[1] = 63;
    }
}

/* Channel codes (or Q16 words) of every pixel, R, G, B. */
static inline uint32_t *frame_codes(const frame_t *f)
{
    uint32_t *c = (uint32_t *)xmalloc((size_t)f->w * (size_t)f->h * 3u * sizeof *c);
    for (int y = 0; y < f->h; y++)
        for (int x = 0; x < f->w; x++) {
            const uint8_t *p = f->p + (size_t)y * f->stride + (size_t)x * (size_t)f->bpp;
            uint32_t *o = c + ((size_t)y * (size_t)f->w + (size_t)x) * 3u;
            switch (f->fmt) {
            case BLOOM_FMT_RGBQ16:
            case BLOOM_FMT_RGBF32: /* the float's bits */
                memcpy(o, p, 12);
                break;
            case BLOOM_FMT_RGB565: {
                uint32_t w = (uint32_t)p[0] | ((uint32_t)p[1] << 8);
                o[0] = w >> 11;
                o[1] = (w >> 5) & 63u;
                o[2] = w & 31u;
                break;
            }
            case BLOOM_FMT_XRGB8888:
                o[0] = p[2];
                o[1] = p[1];
                o[2] = p[0];
                break;
            default:
                o[0] = p[0];
                o[1] = p[1];
                o[2] = p[2];
            }
        }
    return c;
}

/* The model's parameters for c (bloom_model_params_from: the core's
 * quantized values in bit-true mode); c is known valid. */
static inline void model_params(const bloom_config_t *c, int bittrue, bloom_model_params_t *p)
{
    bloom_model_preset_args_t a;
    memset(&a, 0, sizeof a);
    a.cfg = c;
    a.bittrue = bittrue;
    if (bloom_model_params_from(&a, p))
        memset(p, 0, sizeof *p);
}

/* src through a fresh engine for c, with the aux plane aux (rows aux_stride
 * bytes apart) unless NULL, into *out (allocated here, and freed again
 * when the engine fails). The engine's status. */
static inline bloom_status_t core_output(const bloom_config_t *c, const frame_t *src, const void *aux,
                                         ptrdiff_t aux_stride, frame_t *out)
{
    engine_t e = engine_new(c);
    *out = frame_alloc(c->width, c->height, c->out_fmt, 0);
    bloom_status_t st = aux ? bloom_set_aux(e.b, aux, aux_stride) : BLOOM_OK;
    if (st == BLOOM_OK)
        st = bloom_process(e.b, src->p, (ptrdiff_t)src->stride, out->p, (ptrdiff_t)out->stride);
    engine_free(&e);
    if (st != BLOOM_OK)
        frame_free(out);
    return st;
}

typedef struct {
    errstat_t vs_float;                     /* core against the float model, output codes */
    long long bittrue_diff;                 /* samples where core and bit-true model differ */
    long long untouched, untouched_changed; /* samples with B == 0, and how many changed */
    int ok;                                 /* the model ran */
} conform_t;

/* Run src through the core (config c) and both models; compare. */
static inline conform_t conform_run(const bloom_config_t *c, const frame_t *src)
{
    conform_t r;
    memset(&r, 0, sizeof r);
    bloom_info_t info;
    if (bloom_query(c, &info) != BLOOM_OK)
        return r;
    frame_t out;
    if (core_output(c, src, NULL, 0, &out) != BLOOM_OK)
        return r;
    const size_t n = (size_t)c->width * (size_t)c->height * 3u;
    uint32_t *in = frame_codes(src), *core = frame_codes(&out);
    uint32_t *bt = (uint32_t *)xmalloc(n * sizeof *bt), *fl = (uint32_t *)xmalloc(n * sizeof *fl);
    int smax[3], dmax[3];
    fmt_max(c->in_fmt, smax);
    fmt_max(c->out_fmt, dmax);
    bloom_model_params_t pb, pf;
    model_params(c, 1, &pb);
    model_params(c, 0, &pf);
    bloom_model_pyramid_t pyr;
    int lb = bloom_model_run(&pb, in, smax, bt, dmax, NULL);
    int lf = bloom_model_run(&pf, in, smax, fl, dmax, NULL);
    int lp = bloom_model_pyramid(&pb, in, smax, &pyr);
    r.ok = lb == info.levels && lf == info.levels && lp == info.levels;
    if (r.ok) {
        const int same_fmt = c->in_fmt == c->out_fmt && !(c->flags & BLOOM_FLAG_DEBUG_VIEW);
        for (size_t i = 0; i < n; i++) {
            r.bittrue_diff += core[i] != bt[i];
            errstat_add(&r.vs_float, (long long)core[i] - (long long)fl[i]);
            if (same_fmt && pyr.B.px[i - i % 3] == 0 && pyr.B.px[i - i % 3 + 1] == 0 &&
                pyr.B.px[i - i % 3 + 2] == 0) {
                r.untouched++;
                r.untouched_changed += core[i] != in[i];
            }
        }
        bloom_model_pyramid_free(&pyr);
    }
    free(in);
    free(core);
    free(bt);
    free(fl);
    frame_free(&out);
    return r;
}

#endif
