/* bloom_icount: exactly one bloom_process call on the benchmark scene, for
 * `valgrind --tool=callgrind --toggle-collect=bloom_process` (issue 7,
 * item 2; sim/bench/icount.sh drives it).
 *
 *   bloom_icount --list                  the engine rows of variants.c
 *   bloom_icount VARIANT W H [IMAGE]     scene, engine, one frame call
 *   bloom_icount --repeat N VARIANT W H [IMAGE]
 *                                        the same frame call N times (for a
 *                                        sampling profiler: make profile)
 *   bloom_icount [--repeat N] --levels L VARIANT W H [IMAGE]
 *                                        at L levels instead of the row's
 *                                        (make target-cost's level sweep)
 *
 * Deterministic: no clocks, no randomness, no address-dependent choices. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bloom.h"
#include "scene.h"
#include "variants.h"

static int fail(const char *what, const char *why)
{
    fprintf(stderr, "bloom_icount: %s: %s\n", what, why);
    return 1;
}

int main(int argc, char **argv)
{
    if (argc == 2 && !strcmp(argv[1], "--list")) {
        for (int i = 0; i < bench_engine_count; i++)
            printf("%s\n", bench_engines[i].name);
        return 0;
    }
    int repeat = 1, levels = 0;
    while (argc >= 3 && (!strcmp(argv[1], "--repeat") || !strcmp(argv[1], "--levels"))) {
        const int v = atoi(argv[2]);
        if (argv[1][2] == 'r') {
            if ((repeat = v) < 1 || v > 100000)
                return fail("--repeat", "needs a count of 1 .. 100000");
        } else if ((levels = v) < 1 || v > BLOOM_MAX_LEVELS) {
            return fail("--levels", "needs a count of 1 .. BLOOM_MAX_LEVELS");
        }
        argc -= 2;
        argv += 2;
    }
    if (argc < 4 || argc > 5) {
        fprintf(stderr, "usage: bloom_icount --list | [--repeat N] [--levels L] VARIANT W H [IMAGE]\n");
        return 2;
    }
    const bench_engine_t *e = NULL;
    for (int i = 0; i < bench_engine_count; i++)
        if (!strcmp(argv[1], bench_engines[i].name))
            e = &bench_engines[i];
    if (!e)
        return fail(argv[1], "no such engine row (bloom_icount --list)");
    const int w = atoi(argv[2]), h = atoi(argv[3]);
    if (w < 1 || h < 1 || w > BLOOM_MAX_DIM || h > BLOOM_MAX_DIM)
        return fail("size", "out of range");

    bloom_config_t cfg;
    if (bench_engine_config(e, w, h, &cfg)) {
        printf("skipped: %s not available\n", e->name);
        return 0;
    }
    if (levels)
        cfg.levels = levels;
#ifdef BLOOM_COST_SAMPLE_BITS /* make target-cost's width (COST_CFLAGS_16) */
    cfg.sample_bits = BLOOM_COST_SAMPLE_BITS;
#endif
    bloom_info_t info;
    bloom_status_t st = bloom_query(&cfg, &info);
    if (st != BLOOM_OK)
        return fail("bloom_query", bloom_status_str(st));

    char err[512];
    const size_t n = (size_t)w * (size_t)h;
    const size_t ibpp = (size_t)bloom_format_bpp(cfg.in_fmt), obpp = (size_t)bloom_format_bpp(cfg.out_fmt);
    uint8_t *rgb = malloc(n * 3u), *src = malloc(n * ibpp), *dst = malloc(n * obpp);
    void *ws = malloc(info.workspace_bytes);
    if (!rgb || !src || !dst || !ws)
        return fail("memory", "out of memory");
    if (scene_make(argc == 5 ? argv[4] : SCENE_IMAGE_DEFAULT, w, h, rgb, err, sizeof err))
        return fail("scene", err);
    if (scene_convert(rgb, w, h, cfg.in_fmt, src, ibpp * (size_t)w))
        return fail(e->name, "the scene has no such input format");
    bloom_t *b;
    if ((st = bloom_init(&b, ws, info.workspace_bytes, &cfg)) != BLOOM_OK)
        return fail("bloom_init", bloom_status_str(st));
    if (bench_engine_attach(b, &cfg))
        return fail("aux plane", e->name);

    for (int i = 0; i < repeat; i++) {
        st = bloom_process(b, src, (ptrdiff_t)(ibpp * (size_t)w), dst, (ptrdiff_t)(obpp * (size_t)w));
        if (st != BLOOM_OK)
            return fail("bloom_process", bloom_status_str(st));
    }

    /* A checksum of the output, so a changed result is visible next to a
     * changed count. */
    uint32_t sum = 2166136261u;
    for (size_t i = 0; i < n * obpp; i++)
        sum = (sum ^ dst[i]) * 16777619u;
    printf("%s %dx%d levels %d workspace %zu output-fnv1a %08x\n", e->name, w, h, info.levels,
           info.workspace_bytes, (unsigned)sum);
    if (e->teardown)
        e->teardown();
    free(ws);
    free(dst);
    free(src);
    free(rgb);
    return 0;
}
