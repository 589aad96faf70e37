/* Tiles (issue 14): the engine renders any rectangle of a frame bit for bit
 * as the whole frame has it, for every preset, pixel format and level
 * count, over tilings of many shapes (vertical strips down to 1 pixel wide,
 * horizontal bands, grids, tiles smaller than their halo, the corners, odd
 * sizes), through the frame call and the row calls; each tile engine writes
 * nothing outside its tile; a tile is refused in place; the workspace
 * follows the tile's width. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bloom.h"
#include "harness.h"
#include "testutil.h"

static int imin_t(int a, int b)
{
    return a < b ? a : b;
}

/* A depth/mask plane of the frame's size for the presets that read one. */
static uint8_t *aux_plane(const bloom_config_t *c, uint32_t seed)
{
    if (c->aux_fmt == BLOOM_AUX_NONE)
        return NULL;
    const size_t n = (size_t)c->width * (size_t)c->height * (c->aux_fmt == BLOOM_AUX_U16 ? 2u : 1u);
    uint8_t *a = (uint8_t *)xmalloc(n);
    uint32_t s = seed;
    for (size_t i = 0; i < n; i++)
        a[i] = (uint8_t)rng_next(&s);
    return a;
}

static ptrdiff_t aux_stride(const bloom_config_t *c)
{
    return (ptrdiff_t)c->width * (c->aux_fmt == BLOOM_AUX_U16 ? 2 : 1);
}

/* The tile (x, y, w, h) of src into dst through its own engine, by the frame
 * call, or (rows) by the row calls fed the frame's rows. */
static bloom_status_t run_tile(const bloom_config_t *base, const frame_t *src, const uint8_t *aux,
                               frame_t *dst, int x, int y, int w, int h, bool rows)
{
    bloom_config_t c = *base;
    c.tile_x = x;
    c.tile_y = y;
    c.tile_w = w;
    c.tile_h = h;
    bloom_info_t info;
    bloom_status_t st = bloom_query(&c, &info);
    if (st != BLOOM_OK)
        return st;
    engine_t e = engine_new(&c);
    if (!rows) {
        st = aux ? bloom_set_aux(e.b, aux, aux_stride(&c)) : BLOOM_OK;
        if (st == BLOOM_OK)
            st = bloom_process(e.b, src->p, (ptrdiff_t)src->stride, dst->p, (ptrdiff_t)dst->stride);
    } else {
        st = bloom_begin(e.b);
        for (int r = 0; st == BLOOM_OK && r < info.src_h; r++) {
            const int fy = info.src_y + r;
            const uint8_t *ar = aux ? aux + (ptrdiff_t)fy * aux_stride(&c) : NULL;
            st = bloom_push_row_aux(e.b, src->p + (size_t)fy * src->stride, ar);
            while (st == BLOOM_OK)
                st = bloom_pull_row(e.b, dst->p + (size_t)(y + bloom_rows_out(e.b)) * dst->stride);
            if (st == BLOOM_AGAIN || st == BLOOM_DONE)
                st = BLOOM_OK;
        }
        while (st == BLOOM_OK)
            st = bloom_pull_row(e.b, dst->p + (size_t)(y + bloom_rows_out(e.b)) * dst->stride);
        if (st == BLOOM_DONE)
            st = bloom_rows_out(e.b) == h ? BLOOM_OK : BLOOM_E_INTERNAL;
    }
    engine_free(&e);
    return st;
}

/* A tiling: columns cut at the multiples of sw, rows at the multiples of sh
 * (sw = width: no vertical cut); every tile run; false if any failed. */
static bool run_tiling(const bloom_config_t *c, const frame_t *src, const uint8_t *aux, frame_t *dst, int sw,
                       int sh, bool rows)
{
    for (int y = 0; y < c->height; y += sh)
        for (int x = 0; x < c->width; x += sw) {
            const int w = imin_t(sw, c->width - x), h = imin_t(sh, c->height - y);
            bloom_status_t st = run_tile(c, src, aux, dst, x, y, w, h, rows);
            if (st != BLOOM_OK) {
                fprintf(stderr, "tile %d,%d %dx%d: %s\n", x, y, w, h, bloom_status_str(st));
                return false;
            }
        }
    return true;
}

typedef struct {
    int sw, sh; /* strip width, band height (0: the whole side) */
} tiling_t;

/* Every tiling of a frame against the whole frame's bytes; each tile alone
 * on a frame of sentinel bytes (nothing outside it written). */
static void tilings(const bloom_config_t *c, uint32_t seed, int *cases)
{
    const char *pn = bloom_preset_name(c->preset);
    frame_t src = frame_random(c, c->in_fmt, seed);
    uint8_t *aux = aux_plane(c, seed * 7u + 3u);
    frame_t ref = run_engine_aux(c, &src, aux, aux_stride(c));
    const int W = c->width, H = c->height;
    const tiling_t t[] = {{1, 0},  {7, 0}, {64, 0},  {W / 3 + 1, 0},         {0, 1},        {0, 5},
                          {0, 33}, {3, 4}, {50, 17}, {W / 2 + 1, H / 2 + 1}, {W - 1, H - 1}};
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        const int sw = t[i].sw > 0 ? imin_t(t[i].sw, W) : W, sh = t[i].sh > 0 ? imin_t(t[i].sh, H) : H;
        if (sw == W && sh == H)
            continue;
        const bool rows = i % 3 == 1; /* some through the row calls */
        frame_t out = frame_alloc(W, H, c->out_fmt, 0);
        memset(out.p, 0xA7, out.bytes);
        const bool ran = run_tiling(c, &src, aux, &out, sw, sh, rows);
        CHECKF(ran && frame_equal(&out, &ref) && frame_intact(&out),
               "%s %dx%d L%d fmt %d->%d: tiles of %dx%d%s give the whole frame's bytes", pn, W, H, c->levels,
               (int)c->in_fmt, (int)c->out_fmt, sw, sh, rows ? " (row calls)" : "");
        frame_free(&out);
        (*cases)++;
    }
    /* one tile alone: its pixels, and nothing else touched (a corner, the
     * middle, a 1x1) */
    const int tx[3] = {W - imin_t(9, W), W / 3, W / 2}, ty[3] = {0, H / 4, H / 2};
    const int tw[3] = {imin_t(9, W), imin_t(W / 3 + 1, W - W / 3), 1},
              th[3] = {imin_t(6, H), H / 2 + 1 - H / 4, 1};
    for (int k = 0; k < 3; k++) {
        frame_t out = frame_alloc(W, H, c->out_fmt, 0);
        memset(out.p, 0xA7, out.bytes);
        const bloom_status_t st = run_tile(c, &src, aux, &out, tx[k], ty[k], tw[k], th[k], k == 1);
        bool ok = st == BLOOM_OK && frame_intact(&out);
        const size_t bpp = (size_t)out.bpp;
        for (int y = 0; ok && y < H; y++)
            for (int x = 0; ok && x < W; x++) {
                const uint8_t *a = out.p + (size_t)y * out.stride + (size_t)x * bpp;
                const uint8_t *b = ref.p + (size_t)y * ref.stride + (size_t)x * bpp;
                const bool in = x >= tx[k] && x < tx[k] + tw[k] && y >= ty[k] && y < ty[k] + th[k];
                for (size_t q = 0; q < bpp; q++)
                    ok = ok && (in ? a[q] == b[q] : a[q] == 0xA7);
            }
        CHECKF(ok, "%s %dx%d: the tile %d,%d %dx%d alone: its pixels, nothing else written", pn, W, H, tx[k],
               ty[k], tw[k], th[k]);
        frame_free(&out);
    }
    frame_free(&ref);
    frame_free(&src);
    free(aux);
}

static void presets_formats(void)
{
    static const int sizes[][2] = {{97, 61}, {200, 150}, {333, 77}, {64, 64}, {1, 9}};
    static const bloom_format_t fmts[][2] = {{BLOOM_FMT_RGB888, BLOOM_FMT_RGB888},
                                             {BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888},
                                             {BLOOM_FMT_RGB565, BLOOM_FMT_RGB565},
                                             {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16}};
    int cases = 0;
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p))
            continue;
        for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
            for (size_t fi = 0; fi < sizeof fmts / sizeof fmts[0]; fi++) {
                if (!bloom_format_bpp(fmts[fi][0]) || !bloom_format_bpp(fmts[fi][1]))
                    continue;
                if ((si + fi + (size_t)p) % 2) /* half of the grid: every size, format and preset met */
                    continue;
                bloom_config_t c;
                bloom_config_default(&c, sizes[si][0], sizes[si][1]);
                c.in_fmt = fmts[fi][0];
                c.out_fmt = fmts[fi][1];
                c.levels = 3 + (int)((si + fi) % 6); /* 3 .. 8 */
                bloom_config_preset(&c, (bloom_preset_t)p);
                c.threshold = p == BLOOM_PRESET_XNA ? BLOOM_Q16(0.3) : c.threshold ? BLOOM_Q16(0.5) : 0;
                /* every kernel set (a tile's nodes hand the kernels rows from
                 * a column on, wider than they make: each twin meets that) */
                static const uint32_t sets[3] = {0, BLOOM_FLAG_NO_AVX2, BLOOM_FLAG_NO_SIMD};
                c.flags |= sets[(si + 2 * fi + (size_t)p) % 3];
                if (p == BLOOM_PRESET_COD && fi != 1) /* its levels in delay lines */
                    c.flags |= BLOOM_FLAG_KEEP_LEVELS;
                tilings(&c, (uint32_t)(p * 101 + (int)si * 7 + (int)fi), &cases);
            }
    }
    printf("tilings: %d tilings of every preset over sizes 97x61 .. 333x77 and 1x9, 4 format pairs, "
           "3 .. 8 levels, every kernel set: the whole frame's bytes\n",
           cases);
}

static void refusals(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 64, 48);
    const int bad[][4] = {{-1, 0, 10, 10}, {0, 0, 65, 10}, {60, 0, 5, 1},
                          {0, 40, 1, 9},   {0, 0, 0, 5},   {3, 3, 0, 0}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        c.tile_x = bad[i][0];
        c.tile_y = bad[i][1];
        c.tile_w = bad[i][2];
        c.tile_h = bad[i][3];
        CHECKF(bloom_query(&c, NULL) == BLOOM_E_TILE, "tile %d,%d %dx%d refused", bad[i][0], bad[i][1],
               bad[i][2], bad[i][3]);
    }
    /* in place: a tile's halo reads its neighbours' source */
    c.tile_x = 16;
    c.tile_y = 8;
    c.tile_w = 20;
    c.tile_h = 20;
    engine_t e = engine_new(&c);
    frame_t f = frame_alloc(64, 48, BLOOM_FMT_RGB888, 200);
    CHECK(bloom_process(e.b, f.p, (ptrdiff_t)f.stride, f.p, (ptrdiff_t)f.stride) == BLOOM_E_ALIAS);
    engine_free(&e);
    frame_free(&f);
}

/* The workspace follows the strip's width (and the window around it). */
static void memory(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 1920, 1080);
    const size_t whole = bloom_workspace_size(&c);
    c.tile_x = 768;
    c.tile_y = 0;
    c.tile_w = 256;
    c.tile_h = 1080;
    bloom_info_t info;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    CHECKF(info.workspace_bytes < whole / 2,
           "a 256-column strip of 1920x1080 needs %zu bytes (whole frame %zu)", info.workspace_bytes, whole);
    printf("workspace: 1920x1080 RGB888 5 levels, whole frame %zu bytes; a strip of 256 columns %zu bytes "
           "(source columns %d .. %d)\n",
           whole, info.workspace_bytes, info.src_x, info.src_x + info.src_w - 1);
}

int main(void)
{
    refusals();
    memory();
    presets_formats();
    return harness_finish();
}
