/* A preset's engine against its models (sim/bloom_model.h presets): the
 * core bit for bit against the bit-true model, and the error statistics
 * against the float model. Shared by tests/test_preset_*.c. */
#ifndef PRESET_CONFORM_H
#define PRESET_CONFORM_H

#include "conform.h"

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
    engine_t e = engine_new(c);
    frame_t out = frame_alloc(c->width, c->height, c->out_fmt, 0);
    bloom_status_t st = aux ? bloom_set_aux(e.b, aux, aux_stride) : BLOOM_OK;
    if (st == BLOOM_OK)
        st = bloom_process(e.b, src->p, (ptrdiff_t)src->stride, out.p, (ptrdiff_t)out.stride);
    engine_free(&e);
    if (st != BLOOM_OK) {
        fprintf(stderr, "bloom_process (%s): %s\n", bloom_preset_name(c->preset), bloom_status_str(st));
        frame_free(&out);
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
