/* The engine rows (variants.h). The first row is the reference every other
 * figure of the benchmark is divided by ("x engine"), and the one the
 * OpenCV variants are compared with. */
#include "variants.h"

#include <stddef.h>

const bench_engine_t bench_engines[] = {
    {"RGB888->RGB888", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0u, NULL, NULL},
    {"XRGB8888->XRGB8888", BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888, 0u, NULL, NULL},
    {"RGB565->RGB565", BLOOM_FMT_RGB565, BLOOM_FMT_RGB565, 0u, NULL, NULL},
    /* Presets and SIMD on/off go here, e.g.
     * {"RGB888->RGB888,C-only", BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0u, force_c, restore_simd}, */
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
