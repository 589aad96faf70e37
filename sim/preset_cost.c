/* Cost of every preset against the default, measured side by side in one
 * run (issue 4), and the workspace each needs.
 *
 *   preset_cost [--sizes WxH,...] [--runs N] [--md FILE] [--csv FILE]
 *       times bloom_process per preset (median of N runs, rounds
 *       interleaved so that load changes hit every preset alike), as ratios
 *       to the default preset and to a cold memcpy of the frame measured in
 *       the same rounds; prints a table, writes Markdown and CSV.
 *   preset_cost --one NAME W H [dark]
 *       one bloom_process call of preset NAME on the scene, or with `dark`
 *       on the dark frame (for callgrind: make preset-icount).
 *   preset_cost --list    the presets this build has.
 *
 * Two frames per size: the scene of sim/bench (a real photograph stretched
 * to the frame, plus bright spots), and a dark frame (the same with every
 * code scaled to at most 60, linear light 0.045: below every preset's
 * threshold but cod's default 0, where nothing is dark). Each preset runs
 * with its SIMD kernels and with BLOOM_FLAG_NO_SIMD in the same rounds.
 * Presets with an aux plane get a synthetic one: a vertical depth ramp
 * (attenuation: far at the top), no mask (arm). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bloom.h"
#include "bench/scene.h"

#define MAX_SIZES 8
/* Every timed run, engine or memcpy, reads its own frame of a ring this
 * large (larger than the 260 MB last-level cache of the machines here), so
 * that no side reads a source the side before it left in a cache. */
#define RING_BYTES (512u << 20)

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

static int cmp_d(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_d);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

typedef struct {
    bloom_config_t cfg;
    void *ws;
    bloom_t *b;
    uint8_t *aux;
    size_t ws_bytes;
} engine_t;

static int engine_make(engine_t *e, bloom_preset_t p, int w, int h, uint32_t flags)
{
    memset(e, 0, sizeof *e);
    bloom_config_default(&e->cfg, w, h);
    if (bloom_config_preset(&e->cfg, p) != BLOOM_OK)
        return -1;
    e->cfg.flags |= flags;
    bloom_info_t info;
    bloom_status_t st = bloom_query(&e->cfg, &info);
    if (st != BLOOM_OK) {
        fprintf(stderr, "preset_cost: %s: %s\n", bloom_preset_name(p), bloom_status_str(st));
        return -1;
    }
    e->ws_bytes = info.workspace_bytes;
    e->ws = aligned_alloc(64, (e->ws_bytes + 63u) & ~(size_t)63u);
    if (!e->ws || bloom_init(&e->b, e->ws, e->ws_bytes, &e->cfg) != BLOOM_OK)
        return -1;
    if (e->cfg.aux_fmt != BLOOM_AUX_NONE) {
        const int bpp = e->cfg.aux_fmt == BLOOM_AUX_U16 ? 2 : 1;
        e->aux = malloc((size_t)w * (size_t)h * (size_t)bpp);
        if (!e->aux)
            return -1;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                const unsigned v = (unsigned)(65535 - (long)y * 65535 / (h > 1 ? h - 1 : 1));
                if (bpp == 2) {
                    const uint16_t v16 = (uint16_t)v;
                    memcpy(e->aux + 2 * ((size_t)y * (size_t)w + (size_t)x), &v16, 2);
                } else {
                    e->aux[(size_t)y * (size_t)w + (size_t)x] = (uint8_t)(v >> 8);
                }
            }
        if (bloom_set_aux(e->b, e->aux, (ptrdiff_t)w * bpp) != BLOOM_OK)
            return -1;
    }
    return 0;
}

static void engine_drop(engine_t *e)
{
    free(e->ws);
    free(e->aux);
}

static int run(engine_t *e, const uint8_t *src, uint8_t *dst, int w)
{
    return bloom_process(e->b, src, (ptrdiff_t)w * 3, dst, (ptrdiff_t)w * 3) == BLOOM_OK ? 0 : -1;
}

static int one(const char *name, int w, int h, int dark)
{
    const int p = bloom_preset_from_name(name);
    if (p < 0 || !bloom_preset_available((bloom_preset_t)p)) {
        printf("skipped: preset %s not in this build\n", name);
        return 0;
    }
    char err[256];
    uint8_t *src = malloc((size_t)w * (size_t)h * 3), *dst = malloc((size_t)w * (size_t)h * 3);
    engine_t e;
    if (!src || !dst || scene_make(SCENE_IMAGE_DEFAULT, w, h, src, err, sizeof err)) {
        fprintf(stderr, "preset_cost: %s %dx%d: no scene\n", name, w, h);
        return 1;
    }
    if (dark) /* the dark frame of measure() */
        for (size_t i = 0; i < (size_t)w * (size_t)h * 3; i++)
            src[i] = (uint8_t)(src[i] * 60u / 255u);
    if (engine_make(&e, (bloom_preset_t)p, w, h, 0) || run(&e, src, dst, w)) {
        fprintf(stderr, "preset_cost: %s %dx%d failed\n", name, w, h);
        return 1;
    }
    unsigned long long sum = 0;
    for (size_t i = 0; i < (size_t)w * (size_t)h * 3; i++)
        sum = sum * 31u + dst[i];
    printf("%s %dx%d checksum %016llx workspace %zu\n", name, w, h, sum, e.ws_bytes);
    engine_drop(&e);
    free(src);
    free(dst);
    return 0;
}

/* The rows measured: every preset at its defaults, then cod with its levels
 * kept in delay lines (BLOOM_FLAG_KEEP_LEVELS: the same bytes, more
 * workspace). */
static const struct {
    bloom_preset_t p;
    uint32_t flags;
    const char *name;
} rows[] = {{BLOOM_PRESET_UNITY, 0, NULL},
            {BLOOM_PRESET_GAMEDEV, 0, NULL},
            {BLOOM_PRESET_XNA, 0, NULL},
            {BLOOM_PRESET_ATTENUATION, 0, NULL},
            {BLOOM_PRESET_ARM, 0, NULL},
            {BLOOM_PRESET_COD, 0, NULL},
            {BLOOM_PRESET_COD, BLOOM_FLAG_KEEP_LEVELS, "cod keep-levels"}};
enum { NROWS = sizeof rows / sizeof rows[0] };

/* One size and frame: every preset with and without SIMD and a cold memcpy,
 * interleaved in each of `runs` rounds; medians, ratios within the run. */
static int measure(int w, int h, int dark, int runs, FILE *fm, FILE *fc)
{
    const size_t fb = (size_t)w * (size_t)h * 3;
    char err[256];
    uint8_t *src = malloc(fb), *dst = malloc(fb);
    size_t nring = RING_BYTES / fb < 4 ? 4 : RING_BYTES / fb;
    uint8_t *ring = malloc(nring * fb);
    if (!src || !dst || !ring || scene_make(SCENE_IMAGE_DEFAULT, w, h, src, err, sizeof err)) {
        fprintf(stderr, "preset_cost: %s\n", src && dst && ring ? err : "out of memory");
        return 1;
    }
    if (dark)
        for (size_t i = 0; i < fb; i++)
            src[i] = (uint8_t)(src[i] * 60u / 255u);
    for (size_t i = 0; i < nring; i++)
        memcpy(ring + i * fb, src, fb);
    enum { NE = 2 * NROWS }; /* row p: engine 2p with SIMD, 2p + 1 C only */
    engine_t e[NE];
    int have[NE];
    double *t[NE + 1];
    for (int i = 0; i <= NE; i++)
        t[i] = calloc((size_t)runs, sizeof(double));
    for (int i = 0; i < NE; i++)
        have[i] =
            bloom_preset_available(rows[i / 2].p) &&
            !engine_make(&e[i], rows[i / 2].p, w, h, rows[i / 2].flags | (i % 2 ? BLOOM_FLAG_NO_SIMD : 0u)) &&
            !run(&e[i], src, dst, w); /* warm-up */
    size_t slot = 0;
    unsigned long long rng = 0x9E3779B97F4A7C15ull;
    for (int r = 0; r < runs; r++) {
        /* a new order every round (a fixed seed): no engine always runs
         * after the same one (after cod's long runs every engine is slower,
         * the copy too) or first after the cold copy */
        int order[NE];
        for (int q = 0; q < NE; q++)
            order[q] = q;
        for (int q = NE - 1; q > 0; q--) {
            rng = rng * 6364136223846793005ull + 1442695040888963407ull;
            const int k = (int)((rng >> 33) % (unsigned long long)(q + 1)), tq = order[q];
            order[q] = order[k];
            order[k] = tq;
        }
        for (int q = 0; q < NE; q++) {
            const int i = order[q];
            if (!have[i])
                continue;
            const uint8_t *cold = ring + slot * fb;
            slot = (slot + 1) % nring;
            const double t0 = now_ms();
            run(&e[i], cold, dst, w);
            t[i][r] = now_ms() - t0;
        }
        /* the floor: copy a frame that is not in any cache */
        const double t0 = now_ms();
        memcpy(dst, ring + slot * fb, fb);
        t[NE][r] = now_ms() - t0;
        slot = (slot + 1) % nring;
    }
    double med[NE];
    for (int i = 0; i < NE; i++)
        med[i] = have[i] ? median(t[i], runs) : 0.0;
    const double mc = median(t[NE], runs), def = med[0];
    char size[32];
    const char *frame = dark ? "dark" : "scene";
    snprintf(size, sizeof size, "%dx%d", w, h);
    for (int p = 0; p < NROWS; p++) {
        if (!have[2 * p] || !have[2 * p + 1])
            continue;
        const double m = med[2 * p], mcn = med[2 * p + 1];
        const char *name = rows[p].name ? rows[p].name : bloom_preset_name(rows[p].p);
        printf("%-10s %-6s %-16s %10.3f %10.2f %10.1f %10.3f %8.2f %12zu\n", size, frame, name, m, m / def,
               m / mc, mcn, m / mcn, e[2 * p].ws_bytes);
        if (fc)
            fprintf(fc, "%s,%s,%s,%.4f,%.3f,%.2f,%.4f,%.3f,%zu\n", size, frame, name, m, m / def, m / mc, mcn,
                    m / mcn, e[2 * p].ws_bytes);
        if (fm)
            fprintf(fm, "| %s | %s | %s | %.2f | %.2f | %.1f | %.2f | %.2f | %zu |\n", size, frame, name, m,
                    m / def, m / mc, mcn, m / mcn, e[2 * p].ws_bytes);
    }
    for (int i = 0; i < NE; i++)
        if (have[i])
            engine_drop(&e[i]);
    printf("%-10s %-6s %-16s %10.3f %10.2f %10.1f\n", size, frame, "memcpy", mc, mc / def, 1.0);
    for (int i = 0; i <= NE; i++)
        free(t[i]);
    free(src);
    free(dst);
    free(ring);
    return 0;
}

int main(int argc, char **argv)
{
    int sw[MAX_SIZES], sh[MAX_SIZES], nsizes = 0, runs = 15;
    const char *md = NULL, *csv = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--one") && i + 3 < argc)
            return one(argv[i + 1], atoi(argv[i + 2]), atoi(argv[i + 3]),
                       i + 4 < argc && !strcmp(argv[i + 4], "dark"));
        if (!strcmp(argv[i], "--list")) {
            for (int p = 0; p < BLOOM_PRESET_COUNT; p++)
                if (bloom_preset_available((bloom_preset_t)p))
                    printf("%s\n", bloom_preset_name((bloom_preset_t)p));
            return 0;
        }
        if (!strcmp(argv[i], "--sizes") && i + 1 < argc) {
            nsizes = scene_parse_sizes(argv[++i], sw, sh, MAX_SIZES);
            if (nsizes < 1) {
                fprintf(stderr, "preset_cost: bad --sizes\n");
                return 2;
            }
        } else if (!strcmp(argv[i], "--runs") && i + 1 < argc) {
            runs = atoi(argv[++i]);
            if (runs < 1 || runs > 1000)
                return 2;
        } else if (!strcmp(argv[i], "--md") && i + 1 < argc) {
            md = argv[++i];
        } else if (!strcmp(argv[i], "--csv") && i + 1 < argc) {
            csv = argv[++i];
        } else {
            fprintf(stderr, "usage: preset_cost [--sizes WxH,...] [--runs N] [--md F] [--csv F] | --one NAME "
                            "W H [dark] | --list\n");
            return 2;
        }
    }
    if (!nsizes) {
        sw[0] = 640, sh[0] = 480, sw[1] = 1920, sh[1] = 1080;
        nsizes = 2;
    }
    FILE *fm = md ? fopen(md, "w") : NULL, *fc = csv ? fopen(csv, "w") : NULL;
    if ((md && !fm) || (csv && !fc)) {
        fprintf(stderr, "preset_cost: cannot write %s\n", md && !fm ? md : csv);
        return 1;
    }
    if (fc)
        fprintf(
            fc,
            "size,frame,preset,median_ms,x_default,x_memcpy,c_only_ms,simd_over_c_only,workspace_bytes\n");
    if (fm)
        fprintf(fm,
                "| size | frame | preset | median ms | x default | x cold memcpy | C-only ms | SIMD / C-only "
                "| workspace bytes |\n"
                "|---|---|---|---:|---:|---:|---:|---:|---:|\n");
    printf("%-10s %-6s %-16s %10s %10s %10s %10s %8s %12s\n", "size", "frame", "preset", "median ms",
           "x default", "x memcpy", "C-only ms", "SIMD/C", "workspace");
    for (int s = 0; s < nsizes; s++)
        for (int dark = 0; dark < 2; dark++)
            if (measure(sw[s], sh[s], dark, runs, fm, fc))
                return 1;
    if (fm)
        fclose(fm);
    if (fc)
        fclose(fc);
    return 0;
}
