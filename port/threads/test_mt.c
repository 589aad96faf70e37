/* bloom_mt (issue 14 item 3): a frame spread over 1 .. 4 threads is bit for
 * bit the one-thread frame, for every preset and pixel format at several
 * sizes (wide frames cut into strips, narrow ones into grids or bands, a
 * frame too small for N tiles); the pool is reused over frames; the one
 * caller buffer is all the helper writes besides the output (canaries);
 * in place, a short buffer and a caller's own tile are refused. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bloom.h"
#include "bloom_mt.h"
#include "harness.h"
#include "testutil.h"

typedef struct {
    guarded_t buf;
    bloom_mt_t *mt;
} mt_run_t;

static bloom_status_t mt_new(mt_run_t *r, const bloom_config_t *c, int n)
{
    const size_t bytes = bloom_mt_size(c, n);
    r->mt = NULL;
    r->buf = guarded_alloc(bytes ? bytes : 1);
    /* an odd start: the helper aligns inside the buffer itself */
    return bytes ? bloom_mt_init(&r->mt, r->buf.p, bytes, c, n) : BLOOM_E_SIZE;
}

static bool mt_del(mt_run_t *r)
{
    bloom_mt_free(r->mt);
    const bool ok = guarded_intact(&r->buf);
    guarded_free(&r->buf);
    return ok;
}

static uint8_t *aux_plane(const bloom_config_t *c, uint32_t seed, ptrdiff_t *stride)
{
    *stride = (ptrdiff_t)c->width * (c->aux_fmt == BLOOM_AUX_U16 ? 2 : 1);
    if (c->aux_fmt == BLOOM_AUX_NONE)
        return NULL;
    const size_t n = (size_t)*stride * (size_t)c->height;
    uint8_t *a = (uint8_t *)xmalloc(n);
    for (size_t i = 0; i < n; i++)
        a[i] = (uint8_t)rng_next(&seed);
    return a;
}

/* Two frames through one mt of n threads (the pool reused); the second
 * frame's output against ref2, the first's against ref1. */
static bool run_mt(const bloom_config_t *c, int n, const frame_t *s1, const frame_t *s2, const uint8_t *aux,
                   ptrdiff_t aux_stride, const frame_t *ref1, const frame_t *ref2, int *tiles)
{
    mt_run_t r;
    bloom_status_t st = mt_new(&r, c, n);
    if (st == BLOOM_OK && aux)
        st = bloom_mt_set_aux(r.mt, aux, aux_stride);
    bool ok = st == BLOOM_OK;
    *tiles = bloom_mt_tiles(r.mt);
    const frame_t *src[2] = {s1, s2}, *ref[2] = {ref1, ref2};
    for (int k = 0; ok && k < 2; k++) {
        frame_t out = frame_alloc(c->width, c->height, c->out_fmt, 0);
        memset(out.p, 0xA7, out.bytes);
        st = bloom_mt_process(r.mt, src[k]->p, (ptrdiff_t)src[k]->stride, out.p, (ptrdiff_t)out.stride);
        ok = st == BLOOM_OK && frame_equal(&out, ref[k]) && frame_intact(&out);
        frame_free(&out);
    }
    if (st != BLOOM_OK)
        fprintf(stderr, "bloom_mt: %s\n", bloom_mt_status_str(st));
    return mt_del(&r) && ok;
}

static void presets_formats(void)
{
    /* wide (strips), medium (3 strips or a 2x2 grid), narrow (bands), tall
     * and thin, and one too small for 4 tiles */
    static const int sizes[][2] = {{333, 77}, {200, 150}, {97, 61}, {40, 100}, {1, 9}, {3, 2}};
    static const bloom_format_t fmts[][2] = {{BLOOM_FMT_RGB888, BLOOM_FMT_RGB888},
                                             {BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888},
                                             {BLOOM_FMT_RGB565, BLOOM_FMT_RGB565},
                                             {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16},
                                             {BLOOM_FMT_RGB888, BLOOM_FMT_RGB565}};
    int cases = 0, frames = 0;
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p)) {
            SKIP("preset %s: compiled out", bloom_preset_name((bloom_preset_t)p));
            continue;
        }
        for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
            for (size_t fi = 0; fi < sizeof fmts / sizeof fmts[0]; fi++) {
                if (!bloom_format_bpp(fmts[fi][0]) || !bloom_format_bpp(fmts[fi][1]))
                    continue;
                bloom_config_t c;
                bloom_config_default(&c, sizes[si][0], sizes[si][1]);
                c.in_fmt = fmts[fi][0];
                c.out_fmt = fmts[fi][1];
                c.levels = 3 + (int)((si + fi) % 5); /* 3 .. 7 */
                bloom_config_preset(&c, (bloom_preset_t)p);
                c.threshold = p == BLOOM_PRESET_XNA ? BLOOM_Q16(0.3) : c.threshold ? BLOOM_Q16(0.5) : 0;
                const uint32_t seed = (uint32_t)(p * 131 + (int)si * 17 + (int)fi);
                frame_t s1 = frame_random(&c, c.in_fmt, seed), s2 = frame_random(&c, c.in_fmt, seed + 999u);
                ptrdiff_t as;
                uint8_t *aux = aux_plane(&c, seed * 7u + 3u, &as);
                /* the reference: the one-thread helper, itself held to the
                 * plain engine */
                frame_t e1 = run_engine_aux(&c, &s1, aux, as), e2 = run_engine_aux(&c, &s2, aux, as);
                for (int n = 1; n <= 4; n++) {
                    int tiles = 0;
                    const bool ok = run_mt(&c, n, &s1, &s2, aux, as, &e1, &e2, &tiles);
                    CHECKF(ok && tiles >= 1 && tiles <= n,
                           "%s %dx%d L%d fmt %d->%d, %d threads (%d tiles): the one-thread bytes, two frames",
                           bloom_preset_name(c.preset), c.width, c.height, c.levels, (int)c.in_fmt,
                           (int)c.out_fmt, n, tiles);
                    cases++;
                    frames += 2;
                }
                frame_free(&e1);
                frame_free(&e2);
                frame_free(&s1);
                frame_free(&s2);
                free(aux);
            }
    }
    printf("threads: %d cases (every preset, 5 format pairs, sizes 333x77 .. 3x2, 1 .. 4 threads, %d frames "
           "through reused pools): the one-thread bytes\n",
           cases, frames);
}

static void grids(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 1920, 1080);
    CHECK(bloom_mt_tiles_for(&c, 4) == 4);
    CHECK(bloom_mt_tiles_for(&c, 1000) == BLOOM_MT_MAX_THREADS);
    CHECK(bloom_mt_tiles_for(&c, 0) == bloom_mt_cpus());
    bloom_config_default(&c, 3, 2);
    CHECKF(bloom_mt_tiles_for(&c, 8) == 6, "3x2 in 8 tiles: %d (one per pixel)", bloom_mt_tiles_for(&c, 8));
    bloom_config_default(&c, 1920, 1080);
    const size_t one = bloom_workspace_size(&c), four = bloom_mt_size(&c, 4);
    CHECKF(four > one, "4 strips of 1920x1080 in %zu bytes (one engine %zu)", four, one);
    printf("buffer: 1920x1080 RGB888 5 levels: 1 thread %zu bytes, 2 threads %zu, 4 threads %zu\n",
           bloom_mt_size(&c, 1), bloom_mt_size(&c, 2), four);
}

static void refusals(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 160, 40);
    frame_t f = frame_alloc(160, 40, BLOOM_FMT_RGB888, 200);
    for (int n = 1; n <= 3; n++) {
        mt_run_t r;
        CHECK(mt_new(&r, &c, n) == BLOOM_OK);
        /* in place, and a destination that overlaps a later source row */
        CHECKF(bloom_mt_process(r.mt, f.p, (ptrdiff_t)f.stride, f.p, (ptrdiff_t)f.stride) == BLOOM_E_ALIAS,
               "%d threads: in place refused with the engine's BLOOM_E_ALIAS", n);
        CHECK(bloom_mt_process(r.mt, f.p, (ptrdiff_t)f.stride, f.p + f.stride * 20, (ptrdiff_t)f.stride) ==
              BLOOM_E_ALIAS);
        CHECK(bloom_mt_process(r.mt, NULL, 0, f.p, 0) == BLOOM_E_NULL);
        CHECK(mt_del(&r));
        const size_t bytes = bloom_mt_size(&c, n);
        guarded_t g = guarded_alloc(bytes);
        bloom_mt_t *mt = (bloom_mt_t *)&g; /* overwritten with NULL on refusal */
        CHECK(bloom_mt_init(&mt, g.p, bytes - 1, &c, n) == BLOOM_E_WORKSPACE && mt == NULL);
        guarded_free(&g);
    }
    bloom_config_t t = c;
    t.tile_w = 10;
    t.tile_h = 10;
    CHECK(bloom_mt_size(&t, 2) == 0);
    bloom_mt_t *mt;
    uint64_t small[8];
    CHECK(bloom_mt_init(&mt, small, sizeof small, &t, 2) == BLOOM_E_TILE);
    t = c;
    t.levels = 0;
    CHECK(bloom_mt_init(&mt, small, sizeof small, &t, 2) == BLOOM_E_LEVELS);
    CHECK(strstr(bloom_mt_status_str(BLOOM_MT_E_THREAD), "pthread_create") != NULL);
    frame_free(&f);
}

int main(void)
{
    grids();
    refusals();
    presets_formats();
    return harness_finish();
}
