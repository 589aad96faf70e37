/* bloom_tile_icount: one frame of the benchmark scene rendered as a tiling
 * of vertical strips, one bloom_process call per strip, for
 * `valgrind --tool=callgrind --toggle-collect=bloom_process`
 * (sim/bench/tile_icount.sh, `make tile-table`; issue 14, item 2).
 *
 *   bloom_tile_icount W H LEVELS STRIP [IMAGE]
 *
 * STRIP is the strip's output columns, 0 for the untiled frame. The default
 * preset with the benchmark's threshold (variants.h), RGB888 in and out, as
 * the default row of `make icount`. One workspace of the largest strip's
 * size is re-initialised for every strip: the memory a strip renderer needs;
 * bloom_init is outside the counted calls (an engine kept per strip would
 * not repeat it per frame). Prints the output's FNV-1a so the script can
 * see every tiling give the untiled frame's bytes. Deterministic. */
#include <stdio.h>
#include <stdlib.h>

#include "bloom.h"
#include "scene.h"
#include "tile_strips.h"
#include "variants.h"

static int fail(const char *what, const char *why)
{
    fprintf(stderr, "bloom_tile_icount: %s: %s\n", what, why);
    return 1;
}

int main(int argc, char **argv)
{
    if (argc < 5 || argc > 6) {
        fprintf(stderr, "usage: bloom_tile_icount W H LEVELS STRIP [IMAGE]\n");
        return 2;
    }
    const int w = atoi(argv[1]), h = atoi(argv[2]), levels = atoi(argv[3]), sw = atoi(argv[4]);
    if (w < 1 || h < 1 || w > BLOOM_MAX_DIM || h > BLOOM_MAX_DIM || sw < 0)
        return fail("size", "out of range");
    bloom_config_t cfg;
    bloom_config_default(&cfg, w, h);
    cfg.levels = levels;
    cfg.threshold = BLOOM_Q16(BENCH_THRESHOLD);
    tile_plan_t plan;
    bloom_status_t st = tile_plan(&cfg, sw, &plan);
    if (st != BLOOM_OK)
        return fail("bloom_query", bloom_status_str(st));

    char err[512];
    const size_t stride = (size_t)w * 3u, bytes = stride * (size_t)h;
    uint8_t *src = malloc(bytes), *dst = calloc(bytes, 1);
    void *ws = malloc(plan.ws_max); /* malloc's alignment covers BLOOM_WORKSPACE_ALIGN */
    if (!src || !dst || !ws)
        return fail("memory", "out of memory");
    if (scene_make(argc == 6 ? argv[5] : SCENE_IMAGE_DEFAULT, w, h, src, err, sizeof err))
        return fail("scene", err);
    for (int s = 0; s < plan.strips; s++) {
        bloom_config_t c = cfg;
        bloom_t *b;
        tile_strip_config(&c, sw, s);
        if ((st = bloom_init(&b, ws, plan.ws_max, &c)) != BLOOM_OK)
            return fail("bloom_init", bloom_status_str(st));
        /* never in place: a strip's halo reads its neighbours' source */
        if ((st = bloom_process(b, src, (ptrdiff_t)stride, dst, (ptrdiff_t)stride)) != BLOOM_OK)
            return fail("bloom_process", bloom_status_str(st));
    }
    uint32_t sum = 2166136261u;
    for (size_t i = 0; i < bytes; i++)
        sum = (sum ^ dst[i]) * 16777619u;
    printf("%dx%d levels %d strip %d strips %d workspace %zu fnv1a %08x\n", w, h, levels, sw, plan.strips,
           plan.ws_max, (unsigned)sum);
    free(ws);
    free(dst);
    free(src);
    return 0;
}
