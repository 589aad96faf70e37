/* The attenuation preset against its models: bit-exact to the bit-true
 * model over a grid of sizes, depths, formats, parameters and both depth
 * widths; within 1 LSB of the float model; depth 0 (near) with a = 1 and
 * r = 0 removes all bloom, far depth keeps the default's. */
#include <stdlib.h>

#include "harness.h"
#include "imgframe.h"
#include "preset_conform.h"

#if BLOOM_USE_ATTENUATION
static void grid(void)
{
    static const int sizes[][2] = {{1, 1}, {2, 2}, {3, 5}, {16, 9}, {33, 17}, {64, 48}, {97, 61}};
    static const uint32_t params[][2] = {
        {BLOOM_Q16(0.75), BLOOM_Q16(0.25)}, {BLOOM_ONE, 0}, {BLOOM_Q16(0.3), BLOOM_Q16(0.9)}, {0, 0}};
    static const bloom_format_t fmts[][2] = {{BLOOM_FMT_RGB888, BLOOM_FMT_RGB888},
                                             {BLOOM_FMT_RGB565, BLOOM_FMT_XRGB8888},
                                             {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16},
                                             {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGB888}};
    errstat_t all;
    memset(&all, 0, sizeof all);
    long long diff = 0;
    int runs = 0, failed = 0;
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (size_t pi = 0; pi < sizeof params / sizeof params[0]; pi++)
            for (size_t f = 0; f < sizeof fmts / sizeof fmts[0]; f++)
                for (int levels = 1; levels <= 6; levels += 2) {
                    bloom_config_t c;
                    bloom_config_default(&c, sizes[s][0], sizes[s][1]);
                    bloom_config_preset(&c, BLOOM_PRESET_ATTENUATION);
                    c.levels = levels;
                    c.in_fmt = fmts[f][0];
                    c.out_fmt = fmts[f][1];
                    c.threshold = BLOOM_Q16(0.5);
                    c.p.attenuation = params[pi][0];
                    c.p.max_reduction = params[pi][1];
                    c.aux_fmt = (s + f) & 1 ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
                    frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(s * 7 + pi * 3 + f + (size_t)levels));
                    ptrdiff_t as;
                    void *aux = aux_plane(c.width, c.height, c.aux_fmt, (uint32_t)s, &as);
                    preset_conform_t r = preset_conform(&c, &src, aux, as);
                    failed += !r.ok;
                    diff += r.bittrue_diff;
                    if (c.out_fmt == BLOOM_FMT_RGB888)
                        errstat_merge(&all, &r.vs_float);
                    runs++;
                    free(aux);
                    frame_free(&src);
                }
    CHECKF(failed == 0, "attenuation: engine and models ran (%d of %d failed)", failed, runs);
    CHECKF(diff == 0, "attenuation: bit-exact to the bit-true model over %d runs (%lld samples differ)", runs,
           diff);
    errstat_print("attenuation vs float (RGB888 out)", &all);
    CHECKF(all.peak <= 1, "attenuation: peak %d LSB against the float model", all.peak);
}

/* a = 1, r = 0 and depth 0 everywhere: the factor is 0, no bloom at all. */
static void near_plane_kills_bloom(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 48, 32);
    bloom_config_preset(&c, BLOOM_PRESET_ATTENUATION);
    c.p.attenuation = BLOOM_ONE;
    c.p.max_reduction = 0;
    c.threshold = BLOOM_Q16(0.2);
    frame_t src = frame_random(&c, c.in_fmt, 9);
    uint8_t *depth = (uint8_t *)calloc(48 * 32, 1);
    frame_t out = run_engine_aux(&c, &src, depth, 48);
    CHECKF(frame_equal(&out, &src), "near plane (d = 0, a = 1, r = 0): output = input");
    /* far plane (d = max): factor 1, the default pipeline's bytes */
    memset(depth, 255, 48 * 32);
    frame_t far = run_engine_aux(&c, &src, depth, 48);
    bloom_config_t u;
    bloom_config_default(&u, 48, 32);
    u.threshold = c.threshold;
    frame_t ref = run_engine(&u, &src);
    CHECKF(frame_equal(&far, &ref), "far plane (d = 1): the default preset's output");
    frame_free(&out);
    frame_free(&far);
    frame_free(&ref);
    frame_free(&src);
    free(depth);
}

/* A real image with a depth ramp (top far, bottom near). */
static void real_image(void)
{
    frame_t src;
    if (!imgframe_load("rocket_floodlights.ppm", &src)) {
        CHECKF(0, "real image rocket_floodlights.ppm readable");
        return;
    }
    bloom_config_t c;
    bloom_config_default(&c, src.w, src.h);
    bloom_config_preset(&c, BLOOM_PRESET_ATTENUATION);
    uint8_t *depth = (uint8_t *)xmalloc((size_t)src.w * (size_t)src.h);
    for (int y = 0; y < src.h; y++)
        memset(depth + (size_t)y * (size_t)src.w, 255 - y * 255 / (src.h > 1 ? src.h - 1 : 1), (size_t)src.w);
    preset_conform_t r = preset_conform(&c, &src, depth, src.w);
    CHECK(r.ok);
    CHECKF(r.bittrue_diff == 0, "attenuation rocket: bit-exact (%lld differ)", r.bittrue_diff);
    errstat_print("attenuation rocket vs float", &r.vs_float);
    CHECK(r.vs_float.peak <= 1);
    free(depth);
    frame_free(&src);
}
#endif

int main(void)
{
#if BLOOM_USE_ATTENUATION
    grid();
    near_plane_kills_bloom();
    real_image();
#else
    SKIP("attenuation preset: compiled out (BLOOM_USE_ATTENUATION=0)");
#endif
    return harness_finish();
}
