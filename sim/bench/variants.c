/* The engine rows (variants.h). The first row is the reference every other
 * figure of the benchmark is divided by ("x engine"), and the one the
 * OpenCV variants are compared with. */
#include <stdlib.h>
#include <string.h>

#include "variants.h"

#include <stddef.h>

/* A preset at its own defaults (sim/docs/presets.md), the scene's threshold
 * where the preset has a threshold of the same meaning. */
static int preset_row(bloom_config_t *cfg, bloom_preset_t p, int keep_threshold)
{
    const uint32_t t = cfg->threshold;
    if (!bloom_preset_available(p) || bloom_config_preset(cfg, p) != BLOOM_OK)
        return -1;
    if (keep_threshold)
        cfg->threshold = t;
    return 0;
}
static int preset_gamedev(bloom_config_t *cfg)
{
    return preset_row(cfg, BLOOM_PRESET_GAMEDEV, 1);
}
static int preset_xna(bloom_config_t *cfg)
{
    return preset_row(cfg, BLOOM_PRESET_XNA, 1);
}
static int preset_attenuation(bloom_config_t *cfg)
{
    return preset_row(cfg, BLOOM_PRESET_ATTENUATION, 1);
}
static int preset_arm(bloom_config_t *cfg)
{
    return preset_row(cfg, BLOOM_PRESET_ARM, 1);
}
static int preset_cod(bloom_config_t *cfg)
{
    return preset_row(cfg, BLOOM_PRESET_COD, 0); /* Bevy's threshold 0 */
}

/* 16-bit pyramid samples (cfg.sample_bits, sim/docs/fixed-point.md). */
static int samples16(bloom_config_t *cfg)
{
    cfg->sample_bits = 16;
    return bloom_query(cfg, NULL) == BLOOM_OK ? 0 : -1;
}

const bench_engine_t bench_engines[] = {
    {"RGB888->RGB888", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0u, NULL, NULL},
    {"XRGB8888->XRGB8888", BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888, 0u, NULL, NULL},
    {"RGB565->RGB565", BLOOM_FMT_RGB565, BLOOM_FMT_RGB565, 0u, NULL, NULL},
    {"RGB888->RGB888,no-AVX2", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, BLOOM_FLAG_NO_AVX2, NULL, NULL},
    {"RGB888->RGB888,C-only", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, BLOOM_FLAG_NO_SIMD, NULL, NULL},
    {"XRGB8888->XRGB8888,no-AVX2", BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888, BLOOM_FLAG_NO_AVX2, NULL, NULL},
    {"XRGB8888->XRGB8888,C-only", BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888, BLOOM_FLAG_NO_SIMD, NULL, NULL},
    {"RGB565->RGB565,C-only", BLOOM_FMT_RGB565, BLOOM_FMT_RGB565, BLOOM_FLAG_NO_SIMD, NULL, NULL},
    {"RGB888->RGB888,s16", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0u, samples16, NULL},
    {"RGB565->RGB565,s16", BLOOM_FMT_RGB565, BLOOM_FMT_RGB565, 0u, samples16, NULL},
    {"RGB888->RGB888,s16,C-only", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, BLOOM_FLAG_NO_SIMD, samples16, NULL},
    {"preset-gamedev", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0u, preset_gamedev, NULL},
    {"preset-xna", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0u, preset_xna, NULL},
    {"preset-attenuation", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0u, preset_attenuation, NULL},
    {"preset-arm", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0u, preset_arm, NULL},
    {"preset-cod", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0u, preset_cod, NULL},
    {"preset-gamedev,C-only", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, BLOOM_FLAG_NO_SIMD, preset_gamedev, NULL},
    {"preset-xna,C-only", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, BLOOM_FLAG_NO_SIMD, preset_xna, NULL},
    {"preset-attenuation,C-only", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, BLOOM_FLAG_NO_SIMD, preset_attenuation,
     NULL},
    {"preset-arm,C-only", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, BLOOM_FLAG_NO_SIMD, preset_arm, NULL},
    {"preset-cod,C-only", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, BLOOM_FLAG_NO_SIMD, preset_cod, NULL},
};
const int bench_engine_count = (int)(sizeof bench_engines / sizeof bench_engines[0]);

int bench_engine_config(const bench_engine_t *e, int w, int h, bloom_config_t *cfg)
{
    bloom_config_default(cfg, w, h);
    cfg->in_fmt = e->in_fmt;
    cfg->out_fmt = e->out_fmt;
    cfg->flags |= e->flags;
    cfg->threshold = BLOOM_Q16(BENCH_THRESHOLD);
    if (e->setup && e->setup(cfg) != 0)
        return -1;
    return 0;
}

int bench_engine_attach(bloom_t *b, const bloom_config_t *cfg)
{
    static uint8_t *plane;
    static size_t plane_bytes;
    if (cfg->aux_fmt == BLOOM_AUX_NONE)
        return 0;
    const int w = cfg->width, h = cfg->height, bpp = cfg->aux_fmt == BLOOM_AUX_U16 ? 2 : 1;
    const size_t need = (size_t)w * (size_t)h * (size_t)bpp;
    if (need > plane_bytes) {
        free(plane);
        plane = malloc(need);
        plane_bytes = plane ? need : 0;
        if (!plane)
            return -1;
    }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const uint32_t v = (uint32_t)((long)x * 65535 / (w > 1 ? w - 1 : 1));
            uint8_t *q = plane + ((size_t)y * (size_t)w + (size_t)x) * (size_t)bpp;
            if (bpp == 2) {
                const uint16_t v16 = (uint16_t)v;
                memcpy(q, &v16, 2);
            } else {
                *q = (uint8_t)(v >> 8);
            }
        }
    return bloom_set_aux(b, plane, (ptrdiff_t)w * bpp) == BLOOM_OK ? 0 : -1;
}
