/* Shared helpers of the tests: frames with canary bytes, guarded
 * workspaces, engines, random content. Header-only (static functions). */
#ifndef BLOOM_TESTUTIL_H
#define BLOOM_TESTUTIL_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bloom.h"

#define CANARY 64 /* bytes before and after every buffer */
#define CANARY_BYTE 0xC5

static inline uint32_t rng_next(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static inline void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    return p;
}

/* A buffer with canaries on both sides; p is 8-byte aligned. */
typedef struct {
    uint8_t *base, *p;
    size_t bytes;
} guarded_t;

static inline guarded_t guarded_alloc(size_t bytes)
{
    guarded_t g;
    g.bytes = bytes;
    g.base = (uint8_t *)xmalloc(bytes + 2 * CANARY + 8);
    g.p = g.base + CANARY + (8 - ((uintptr_t)(g.base + CANARY) & 7u)) % 8u;
    memset(g.base, CANARY_BYTE, bytes + 2 * CANARY + 8);
    return g;
}

static inline int guarded_intact(const guarded_t *g)
{
    for (uint8_t *q = g->base; q < g->p; q++)
        if (*q != CANARY_BYTE)
            return 0;
    for (size_t i = 0; i < CANARY; i++)
        if (g->p[g->bytes + i] != CANARY_BYTE)
            return 0;
    return 1;
}

static inline void guarded_free(guarded_t *g)
{
    free(g->base);
    g->base = g->p = NULL;
}

/* An image in one of the engine's formats, stride padded by 5 bytes so no
 * kernel can assume stride == width * bpp. */
typedef struct {
    guarded_t g;
    uint8_t *p;
    int w, h, bpp;
    bloom_format_t fmt;
    size_t stride, bytes;
} frame_t;

static inline frame_t frame_alloc(int w, int h, bloom_format_t fmt, int fill_code)
{
    frame_t f;
    f.w = w;
    f.h = h;
    f.fmt = fmt;
    f.bpp = bloom_format_bpp(fmt);
    f.stride = (size_t)w * (size_t)f.bpp + (fmt == BLOOM_FMT_RGBQ16 || fmt == BLOOM_FMT_RGBF32 ? 4u : 5u);
    f.bytes = f.stride * (size_t)h;
    f.g = guarded_alloc(f.bytes);
    f.p = f.g.p;
    memset(f.p, 0, f.bytes);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t *q = f.p + (size_t)y * f.stride + (size_t)x * (size_t)f.bpp;
            if (fmt == BLOOM_FMT_RGBQ16) {
                uint32_t v[3] = {(uint32_t)fill_code, (uint32_t)fill_code, (uint32_t)fill_code};
                memcpy(q, v, sizeof v);
            } else if (fmt == BLOOM_FMT_RGBF32) { /* fill_code as a Q16.16 value */
                const float v[3] = {(float)fill_code / 65536.0f, (float)fill_code / 65536.0f,
                                    (float)fill_code / 65536.0f};
                memcpy(q, v, sizeof v);
            } else if (fmt == BLOOM_FMT_RGB565) {
                uint32_t c = (uint32_t)fill_code;
                uint32_t wv = ((c >> 3) << 11) | ((c >> 2) << 5) | (c >> 3);
                q[0] = (uint8_t)wv;
                q[1] = (uint8_t)(wv >> 8);
            } else {
                memset(q, fill_code, (size_t)f.bpp);
            }
        }
    return f;
}

/* Random codes; RGBQ16 words up to 4.0; RGBF32 values up to 4.0 with a
 * 2^-24 step (finer than the engine's, so its rounding is exercised). */
static inline frame_t frame_random(const bloom_config_t *c, bloom_format_t fmt, uint32_t seed)
{
    frame_t f = frame_alloc(c->width, c->height, fmt, 0);
    uint32_t s = seed * 2654435761u + 1u;
    for (int y = 0; y < f.h; y++) {
        uint8_t *row = f.p + (size_t)y * f.stride;
        if (fmt == BLOOM_FMT_RGBQ16) {
            for (int i = 0; i < f.w * 3; i++) {
                uint32_t v = rng_next(&s) % (4u << 16);
                memcpy(row + 4 * i, &v, 4);
            }
        } else if (fmt == BLOOM_FMT_RGBF32) {
            for (int i = 0; i < f.w * 3; i++) {
                const float v = (float)(rng_next(&s) % (1u << 26)) / 16777216.0f;
                memcpy(row + 4 * i, &v, 4);
            }
        } else {
            for (size_t i = 0; i < (size_t)f.w * (size_t)f.bpp; i++)
                row[i] = (uint8_t)rng_next(&s);
        }
    }
    return f;
}

static inline int frame_intact(const frame_t *f)
{
    return guarded_intact(&f->g);
}

static inline int frame_equal(const frame_t *a, const frame_t *b)
{
    for (int y = 0; y < a->h; y++)
        if (memcmp(a->p + (size_t)y * a->stride, b->p + (size_t)y * b->stride, (size_t)a->w * (size_t)a->bpp))
            return 0;
    return 1;
}

/* Byte i of the packed pixel data (rows without padding). */
static inline int frame_byte(const frame_t *f, size_t i)
{
    size_t rowb = (size_t)f->w * (size_t)f->bpp;
    return f->p[(i / rowb) * f->stride + i % rowb];
}

static inline void frame_set_q16(frame_t *f, int x, int y, uint32_t v)
{
    uint32_t px[3] = {v, v, v};
    memcpy(f->p + (size_t)y * f->stride + (size_t)x * 12u, px, sizeof px);
}

static inline uint32_t frame_get_q16(const frame_t *f, int x, int y)
{
    uint32_t v;
    memcpy(&v, f->p + (size_t)y * f->stride + (size_t)x * 12u, 4);
    return v;
}

static inline void frame_free(frame_t *f)
{
    guarded_free(&f->g);
}

/* Tent weights (in eighths) that full-resolution X gives to low-resolution
 * cells a and b (interior cells: no edge clamping involved). */
static inline uint32_t tent_weight_sum(int X, int a, int b)
{
    uint32_t s = 0;
    const int m = X >> 1, even = !(X & 1);
    const int cells[2] = {a, b};
    for (int i = 0; i < 2; i++) {
        if (cells[i] == m)
            s += 4;
        else if (cells[i] == m - 1)
            s += even ? 3 : 1;
        else if (cells[i] == m + 1)
            s += even ? 1 : 3;
    }
    return s;
}

/* A linear Q16.16 frame with every sample at v. */
static inline frame_t frame_q16_fill(int w, int h, uint32_t v)
{
    frame_t f = frame_alloc(w, h, BLOOM_FMT_RGBQ16, 0);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            frame_set_q16(&f, x, y, v);
    return f;
}

typedef struct {
    guarded_t ws;
    bloom_t *b;
} engine_t;

static inline engine_t engine_new(const bloom_config_t *c)
{
    engine_t e;
    size_t n = bloom_workspace_size(c);
    e.ws = guarded_alloc(n);
    e.b = NULL;
    bloom_status_t st = bloom_init(&e.b, e.ws.p, n, c);
    if (st != BLOOM_OK) {
        fprintf(stderr, "bloom_init: %s\n", bloom_status_str(st));
        exit(2);
    }
    return e;
}

static inline void engine_free(engine_t *e);

/* src through a fresh engine for c; the output frame (exits on failure). */
static inline frame_t run_engine(const bloom_config_t *c, const frame_t *src)
{
    engine_t e = engine_new(c);
    frame_t out = frame_alloc(c->width, c->height, c->out_fmt, 0);
    bloom_status_t st = bloom_process(e.b, src->p, (ptrdiff_t)src->stride, out.p, (ptrdiff_t)out.stride);
    if (st != BLOOM_OK) {
        fprintf(stderr, "bloom_process: %s\n", bloom_status_str(st));
        exit(2);
    }
    engine_free(&e);
    return out;
}

/* The same with an aux plane (aux may be NULL for presets without one). */
static inline frame_t run_engine_aux(const bloom_config_t *c, const frame_t *src, const void *aux,
                                     ptrdiff_t aux_stride)
{
    engine_t e = engine_new(c);
    frame_t out = frame_alloc(c->width, c->height, c->out_fmt, 0);
    bloom_status_t st = aux ? bloom_set_aux(e.b, aux, aux_stride) : BLOOM_OK;
    if (st == BLOOM_OK)
        st = bloom_process(e.b, src->p, (ptrdiff_t)src->stride, out.p, (ptrdiff_t)out.stride);
    if (st != BLOOM_OK) {
        fprintf(stderr, "bloom_process: %s\n", bloom_status_str(st));
        exit(2);
    }
    engine_free(&e);
    return out;
}

static inline void engine_free(engine_t *e)
{
    if (!guarded_intact(&e->ws)) {
        fprintf(stderr, "workspace canary overwritten\n");
        exit(2);
    }
    guarded_free(&e->ws);
}

#endif
