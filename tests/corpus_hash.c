/* corpus_hash: the engine over the whole test corpus (the random grid of
 * test_conformance.c, widened to all 16 format pairs; test_extreme.c's
 * frames; the real images of tests/data), one line per run: "<config> <FNV-1a 64 of the output>",
 * then a total; after them every other preset over a grid and two images.
 * Integers only, so the listing must be byte-identical on
 * every architecture: tests/cross.sh diffs the x86-64 listing against
 * aarch64 and armhf builds run under qemu-user.
 *
 *   corpus_hash [DATA_DIR]     (default $BLOOM_DATA_DIR, else tests/data) */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imgframe.h"

typedef struct {
    const char *name;
    uint32_t threshold, knee, intensity, flags;
} params_t;

/* test_conformance.c's parameter sets. */
static const params_t PARAMS[] = {
    {"default", BLOOM_Q16(1.0), BLOOM_Q16(0.5), BLOOM_Q16(1.0), 0},
    {"threshold-0.5", BLOOM_Q16(0.5), BLOOM_Q16(0.5), BLOOM_Q16(1.0), 0},
    {"hard-knee", BLOOM_Q16(0.6), 0, BLOOM_Q16(1.0), 0},
    {"knee-1", BLOOM_Q16(0.6), BLOOM_ONE, BLOOM_Q16(1.0), 0},
    {"linear", BLOOM_Q16(0.5), BLOOM_Q16(0.5), BLOOM_Q16(1.0), BLOOM_FLAG_LINEAR},
    {"debug-view", BLOOM_Q16(0.8), BLOOM_Q16(0.5), BLOOM_Q16(1.0), BLOOM_FLAG_DEBUG_VIEW},
    {"threshold-0", 0, BLOOM_Q16(0.5), BLOOM_Q16(0.3), 0},
    {"intensity-0", BLOOM_Q16(0.5), BLOOM_Q16(0.5), 0, 0},
    {"intensity-10", BLOOM_Q16(0.5), BLOOM_Q16(0.5), BLOOM_MAX_INTENSITY, 0},
    {"threshold-256", BLOOM_MAX_THRESHOLD, BLOOM_Q16(0.5), BLOOM_Q16(1.0), 0},
};
#define NPARAMS (sizeof PARAMS / sizeof PARAMS[0])

static const bloom_format_t FMTS[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                      BLOOM_FMT_RGBQ16};
static const char *const FMT_NAME[] = {"?", "RGB888", "XRGB8888", "RGB565", "RGBQ16", "RGBF32"};

#define FNV_OFFSET 0xcbf29ce484222325ull
#define FNV_PRIME 0x100000001b3ull

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = (const uint8_t *)p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * FNV_PRIME;
    return h;
}

/* Packed output rows; RGBQ16 words hashed as little-endian bytes so the
 * hash is the same on a big-endian host with a correct engine. */
static uint64_t frame_hash(const frame_t *f)
{
    uint64_t h = FNV_OFFSET;
    const size_t rowb = (size_t)f->w * (size_t)f->bpp;
    for (int y = 0; y < f->h; y++) {
        const uint8_t *row = f->p + (size_t)y * f->stride;
        if (f->fmt != BLOOM_FMT_RGBQ16) {
            h = fnv(h, row, rowb);
            continue;
        }
        for (size_t i = 0; i < rowb; i += 4) {
            uint32_t v;
            memcpy(&v, row + i, 4);
            const uint8_t le[4] = {(uint8_t)v, (uint8_t)(v >> 8), (uint8_t)(v >> 16), (uint8_t)(v >> 24)};
            h = fnv(h, le, 4);
        }
    }
    return h;
}

/* The row padding frame_alloc zeroes must stay zero, canaries intact. */
static int frame_clean(const frame_t *f)
{
    const size_t rowb = (size_t)f->w * (size_t)f->bpp;
    for (int y = 0; y < f->h; y++)
        for (size_t i = rowb; i < f->stride; i++)
            if (f->p[(size_t)y * f->stride + i])
                return 0;
    return frame_intact(f);
}

static uint64_t total = FNV_OFFSET, total_default = FNV_OFFSET;
static int runs, errors;
static const void *aux_plane; /* the aux plane of the next runs, or NULL */
static ptrdiff_t aux_stride;

/* One run: c over src; prints the line and folds it into the total. */
static void run(const char *what, const bloom_config_t *c, const frame_t *src)
{
    char line[512];
    bloom_info_t info;
    bloom_status_t st = bloom_query(c, &info);
    int n = snprintf(line, sizeof line, "%s %dx%d N%d f%" PRIx32 " %s->%s", what, c->width, c->height,
                     c->levels, c->flags, FMT_NAME[c->in_fmt], FMT_NAME[c->out_fmt]);
    if (st != BLOOM_OK) {
        snprintf(line + n, sizeof line - (size_t)n, " query: %s", bloom_status_str(st));
        errors++;
    } else {
        /* Only pointer-size-free figures: workspace bytes differ on 32-bit. */
        n += snprintf(line + n, sizeof line - (size_t)n,
                      " L%d lat%d src%d q%08" PRIx32 ",%08" PRIx32 ",%08" PRIx32, info.levels,
                      info.latency_rows, info.source_rows, info.threshold_q, info.knee_q, info.intensity_q);
        engine_t e = engine_new(c);
        frame_t out = frame_alloc(c->width, c->height, c->out_fmt, 0);
        st = c->aux_fmt != BLOOM_AUX_NONE ? bloom_set_aux(e.b, aux_plane, aux_stride) : BLOOM_OK;
        if (st == BLOOM_OK)
            st = bloom_process(e.b, src->p, (ptrdiff_t)src->stride, out.p, (ptrdiff_t)out.stride);
        if (st != BLOOM_OK) {
            snprintf(line + n, sizeof line - (size_t)n, " process: %s", bloom_status_str(st));
            errors++;
        } else if (!frame_clean(&out)) {
            snprintf(line + n, sizeof line - (size_t)n, " wrote outside its rows");
            errors++;
        } else {
            snprintf(line + n, sizeof line - (size_t)n, " %016" PRIx64, frame_hash(&out));
        }
        frame_free(&out);
        engine_free(&e); /* exits if the workspace canary was hit */
    }
    puts(line);
    total = fnv(total, line, strlen(line));
    total = fnv(total, "\n", 1);
    if (c->preset == BLOOM_PRESET_UNITY) {
        total_default = fnv(total_default, line, strlen(line));
        total_default = fnv(total_default, "\n", 1);
    }
    runs++;
}

static void apply(bloom_config_t *c, const params_t *p)
{
    c->threshold = p->threshold;
    c->soft_knee = p->knee;
    c->intensity = p->intensity;
    c->flags = p->flags;
}

/* test_conformance.c's grid, with every one of the 16 format pairs. */
static void random_corpus(void)
{
    static const int sizes[][2] = {{1, 1},   {1, 13}, {13, 1},    {2, 2},     {3, 5},    {17, 9},
                                   {64, 48}, {80, 3}, {257, 131}, {131, 257}, {300, 200}};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        const int w = sizes[si][0], h = sizes[si][1];
        const int big = w * h > 20000;
        for (int lv = 1; lv <= 16; lv += big ? 5 : 1)
            for (size_t pi = 0; pi < NPARAMS; pi++)
                for (size_t fi = 0; fi < 16; fi++) {
                    if (big && (fi + pi + (size_t)lv) % 3)
                        continue; /* big frames: a third, as the conformance test */
                    bloom_config_t c;
                    bloom_config_default(&c, w, h);
                    c.levels = lv;
                    apply(&c, &PARAMS[pi]);
                    c.in_fmt = FMTS[fi / 4];
                    c.out_fmt = FMTS[fi % 4];
                    /* source rows copied on every 7th run: the other workspace layout */
                    if ((si + pi + fi + (size_t)lv) % 7 == 0)
                        c.flags |= BLOOM_FLAG_COPY_SOURCE;
                    const uint32_t seed = (uint32_t)(si * 1000 + pi * 31 + fi + (size_t)lv);
                    frame_t src = frame_random(&c, c.in_fmt, seed);
                    char what[64];
                    snprintf(what, sizeof what, "random %s seed%" PRIu32, PARAMS[pi].name, seed);
                    run(what, &c, &src);
                    frame_free(&src);
                }
    }
}

/* test_extreme.c's frames, engine only: the largest intermediates, words
 * above the range, a hot pixel at 256.0, saturation, limits, thin frames. */
static void extreme_corpus(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 1024, 1024);
    c.levels = 16;
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
    c.threshold = c.soft_knee = 0;
    c.intensity = BLOOM_MAX_INTENSITY;
    frame_t src = frame_q16_fill(c.width, c.height, BLOOM_MAX_LINEAR);
    run("extreme all-max", &c, &src);
    c.flags = BLOOM_FLAG_DEBUG_VIEW;
    run("extreme all-max", &c, &src);
    c.out_fmt = BLOOM_FMT_RGB565;
    run("extreme all-max", &c, &src);
    frame_free(&src);

    bloom_config_default(&c, 70, 40);
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
    c.threshold = BLOOM_Q16(2.0);
    src = frame_q16_fill(c.width, c.height, 0xFFFFFFFFu);
    run("extreme words-above-2^24", &c, &src);
    frame_free(&src);

    for (int lv = 1; lv <= 16; lv++) {
        bloom_config_default(&c, 300, 260);
        c.levels = lv;
        c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
        c.flags = BLOOM_FLAG_DEBUG_VIEW;
        src = frame_q16_fill(c.width, c.height, 0);
        frame_set_q16(&src, 150, 130, BLOOM_MAX_LINEAR);
        run("extreme hot-pixel", &c, &src);
        frame_free(&src);
    }

    for (size_t oi = 0; oi < 4; oi++) {
        bloom_config_default(&c, 97, 53);
        c.out_fmt = FMTS[oi];
        c.threshold = 0;
        c.intensity = BLOOM_MAX_INTENSITY;
        src = frame_alloc(c.width, c.height, c.in_fmt, 200);
        run("extreme clamped", &c, &src);
        frame_free(&src);
    }

    static const uint32_t lim[][3] = {{0, 0, BLOOM_Q16(1.0)},
                                      {0, BLOOM_ONE, BLOOM_Q16(1.0)},
                                      {BLOOM_Q16(0.5), 0, BLOOM_Q16(1.0)},
                                      {BLOOM_Q16(0.5), BLOOM_ONE, BLOOM_Q16(1.0)},
                                      {BLOOM_Q16(0.2), BLOOM_Q16(0.5), 0},
                                      {BLOOM_Q16(0.2), BLOOM_Q16(0.5), BLOOM_MAX_INTENSITY},
                                      {BLOOM_MAX_THRESHOLD, 0, BLOOM_MAX_INTENSITY},
                                      {BLOOM_MAX_THRESHOLD, BLOOM_ONE, BLOOM_Q16(1.0)}};
    for (size_t li = 0; li < sizeof lim / sizeof lim[0]; li++)
        for (size_t fi = 0; fi < 4; fi++) {
            bloom_config_default(&c, 120, 90);
            c.threshold = lim[li][0];
            c.soft_knee = lim[li][1];
            c.intensity = lim[li][2];
            c.in_fmt = FMTS[fi];
            c.out_fmt = FMTS[3 - fi];
            src = frame_random(&c, c.in_fmt, 7u + (uint32_t)li);
            if (c.in_fmt == BLOOM_FMT_RGBQ16) /* HDR content up to the largest value */
                for (int k = 0; k < 40; k++)
                    frame_set_q16(&src, (k * 37) % c.width, (k * 53) % c.height, BLOOM_MAX_LINEAR);
            run("extreme limits", &c, &src);
            frame_free(&src);
        }

    static const int sizes[][2] = {{1, 2},    {2, 1},    {1, 1000}, {1000, 1}, {3, 3},
                                   {2, 1500}, {1500, 2}, {4, 700},  {700, 4}};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
        for (int lv = 1; lv <= 16; lv++) {
            bloom_config_default(&c, sizes[si][0], sizes[si][1]);
            c.levels = lv;
            c.threshold = BLOOM_Q16(0.3);
            src = frame_random(&c, c.in_fmt, 3u + (uint32_t)si);
            run("extreme thin", &c, &src);
            frame_free(&src);
        }
}

/* dir/name as a frame (frame_from_img); when it cannot be read, a line of
 * the listing, an error counted and 0. */
static int load_image(const char *dir, const char *name, frame_t *out)
{
    char path[1024], err[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    img_t im;
    if (img_read(path, &im, err, sizeof err) != 0) {
        printf("image %s: %s\n", name, err);
        errors++;
        return 0;
    }
    *out = frame_from_img(&im);
    img_free(&im);
    return 1;
}

/* Each image: the conformance test's configuration into every output
 * format, and a few parameter sets (levels 1, 5, 9) into RGB888. */
static void image_corpus(const char *dir)
{
    static const char *const names[] = {"rocket_floodlights.ppm", "hubble_deep_field.ppm", "studio_lamps.pfm",
                                        "hall_lamps.pfm"};
    static const struct {
        size_t param;
        int levels;
    } extra[] = {{2, 9}, {4, 5}, {5, 5}, {6, 1}, {8, 5}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        frame_t src;
        if (!load_image(dir, names[i], &src))
            continue;
        const bloom_format_t in = src.fmt;
        char what[128];
        for (size_t fi = 0; fi < 4; fi++) {
            bloom_config_t c;
            bloom_config_default(&c, src.w, src.h);
            c.in_fmt = in;
            c.out_fmt = FMTS[fi];
            if (in == BLOOM_FMT_RGBQ16)
                c.threshold = BLOOM_Q16(2.0); /* HDR: lamps only, as the test */
            snprintf(what, sizeof what, "image %s conformance", names[i]);
            run(what, &c, &src);
        }
        for (size_t k = 0; k < sizeof extra / sizeof extra[0]; k++) {
            bloom_config_t c;
            bloom_config_default(&c, src.w, src.h);
            apply(&c, &PARAMS[extra[k].param]);
            c.levels = extra[k].levels;
            c.in_fmt = in;
            c.out_fmt = BLOOM_FMT_RGB888;
            snprintf(what, sizeof what, "image %s %s", names[i], PARAMS[extra[k].param].name);
            run(what, &c, &src);
        }
        frame_free(&src);
    }
}

/* Every other preset: defaults and each preset flag over a grid of sizes,
 * depths and format pairs, then the real images; a deterministic aux plane
 * (8- and 16-bit) where the preset reads one. */
static void preset_corpus(const char *dir)
{
    static const int sizes[][2] = {{1, 1}, {3, 5}, {17, 9}, {64, 48}, {101, 67}};
    static const bloom_format_t pairs[][2] = {{BLOOM_FMT_RGB888, BLOOM_FMT_RGB888},
                                              {BLOOM_FMT_RGB565, BLOOM_FMT_XRGB8888},
                                              {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16},
                                              {BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565}};
    static const uint32_t variants[] = {0, BLOOM_FLAG_SATURATE, BLOOM_FLAG_BAKED, BLOOM_FLAG_ADDITIVE,
                                        BLOOM_FLAG_LINEAR | BLOOM_FLAG_DEBUG_VIEW};
    char what[160];
    for (int p = 1; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p))
            continue;
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
            const int w = sizes[s][0], h = sizes[s][1];
            uint16_t *aux = (uint16_t *)xmalloc((size_t)w * (size_t)h * 2u);
            for (int i = 0; i < w * h; i++)
                aux[i] = (uint16_t)((uint32_t)i * 40503u + (uint32_t)(i / w) * 977u);
            for (size_t v = 0; v < sizeof variants / sizeof variants[0]; v++)
                for (size_t f = 0; f < sizeof pairs / sizeof pairs[0]; f++)
                    for (int levels = 1; levels <= 5; levels += 2) {
                        bloom_config_t c;
                        bloom_config_default(&c, w, h);
                        bloom_config_preset(&c, (bloom_preset_t)p);
                        c.levels = levels;
                        c.in_fmt = pairs[f][0];
                        c.out_fmt = pairs[f][1];
                        c.flags |= variants[v];
                        if (c.aux_fmt != BLOOM_AUX_NONE || (variants[v] & BLOOM_FLAG_BAKED))
                            c.aux_fmt = (f & 1) ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
                        bloom_info_t info;
                        if (bloom_query(&c, &info) != BLOOM_OK)
                            continue; /* a flag of another preset */
                        aux_plane = aux;
                        aux_stride = (ptrdiff_t)w * (c.aux_fmt == BLOOM_AUX_U16 ? 2 : 1);
                        frame_t src = frame_random(&c, c.in_fmt,
                                                   (uint32_t)(p * 1000 + (int)s * 50 + (int)f * 7 + levels));
                        snprintf(what, sizeof what, "preset %s flags+%" PRIx32,
                                 bloom_preset_name((bloom_preset_t)p), variants[v]);
                        run(what, &c, &src);
                        frame_free(&src);
                    }
            free(aux);
        }
        static const char *const names[] = {"rocket_floodlights.ppm", "hall_lamps.pfm"};
        for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
            frame_t src;
            if (!load_image(dir, names[i], &src))
                continue;
            bloom_config_t c;
            bloom_config_default(&c, src.w, src.h);
            bloom_config_preset(&c, (bloom_preset_t)p);
            c.in_fmt = src.fmt;
            uint8_t *aux = (uint8_t *)xmalloc((size_t)src.w * (size_t)src.h);
            for (int y = 0; y < src.h; y++)
                memset(aux + (size_t)y * (size_t)src.w, 255 - y * 255 / src.h, (size_t)src.w);
            aux_plane = aux;
            aux_stride = src.w;
            if (c.aux_fmt != BLOOM_AUX_NONE)
                c.aux_fmt = BLOOM_AUX_U8;
            snprintf(what, sizeof what, "preset %s image %s", bloom_preset_name((bloom_preset_t)p), names[i]);
            run(what, &c, &src);
            free(aux);
            frame_free(&src);
        }
    }
    aux_plane = NULL;
}

/* RGBF32 input: random floats with the special values planted (NaN,
 * +-Inf, -0, negative, subnormal, the ties k + 1/2 LSB, 256 and the
 * largest float below it) through every preset into the three code formats
 * and RGBQ16: the integer decode of the bits must agree everywhere. */
static void f32_corpus(void)
{
    static const uint32_t special[] = {0x7FC00000u, 0x7F800000u, 0xFF800000u, 0x80000000u,
                                       0xBF800000u, 0x00000001u, 0x007FFFFFu, 0x35000000u,
                                       0x35400000u, 0x43800000u, 0x437FFFFFu, 0x3F800000u};
    static const bloom_format_t outs[] = {BLOOM_FMT_RGB888, BLOOM_FMT_RGB565, BLOOM_FMT_XRGB8888,
                                          BLOOM_FMT_RGBQ16};
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p) || p == BLOOM_PRESET_ATTENUATION)
            continue; /* (it needs its depth plane; its source rows are the default's) */
        for (size_t o = 0; o < sizeof outs / sizeof outs[0]; o++) {
            bloom_config_t c;
            bloom_config_default(&c, 67, 45);
            bloom_config_preset(&c, (bloom_preset_t)p);
            c.in_fmt = BLOOM_FMT_RGBF32;
            c.out_fmt = outs[o];
            frame_t src = frame_random(&c, c.in_fmt, 41u + (uint32_t)p);
            for (int k = 0; k < 3 * c.width * c.height; k += 7) {
                const uint32_t v = special[(size_t)(k / 7) % (sizeof special / sizeof special[0])];
                memcpy(src.p + (size_t)(k / (3 * c.width)) * src.stride + 4u * (size_t)(k % (3 * c.width)),
                       &v, 4);
            }
            char what[96];
            snprintf(what, sizeof what, "RGBF32 in, preset %s", bloom_preset_name((bloom_preset_t)p));
            run(what, &c, &src);
            frame_free(&src);
        }
    }
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : getenv("BLOOM_DATA_DIR");
    random_corpus();
    extreme_corpus();
    image_corpus(dir && *dir ? dir : "tests/data");
    preset_corpus(dir && *dir ? dir : "tests/data");
    f32_corpus();
    printf("total %d runs, %d errors, hash %016" PRIx64 " (default preset alone: %016" PRIx64 ")\n", runs,
           errors, total, total_default);
    return errors ? 1 : 0;
}
