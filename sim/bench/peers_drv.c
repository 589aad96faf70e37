/* The engine's side of `make bench-peers` (sim/bench/peers.sh).
 *   peers_drv scene OUT.rgb W H
 *       writes the benchmark scene (scene.c, the frame of bloom_bench) as raw
 *       RGB888, so that every peer reads the very same pixels
 *   peers_drv time FRAME.rgb W H PAIRS THRESHOLD
 *       PAIRS times: a cold memcpy of the frame, then bloom_process on it
 *       (RGB888 in and out, bloom_config_default but the threshold), each
 *       on its own slot of two rings so that no frame is in the cache; prints
 *       "memcpy_ms engine_ms", the medians over the pairs.
 * Timed in-process like the peers' own drivers (peers_gegl.c): process
 * start-up and file reading are not part of any figure. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bloom.h"
#include "scene.h"

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static int cmp_d(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_d);
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

static int scene(const char *out, int w, int h)
{
    char err[256];
    uint8_t *rgb = malloc((size_t)w * h * 3);
    FILE *f;
    if (!rgb || scene_make(SCENE_IMAGE_DEFAULT, w, h, rgb, err, sizeof err)) {
        fprintf(stderr, "peers_drv: scene: %s\n", rgb ? err : "out of memory");
        return 1;
    }
    f = fopen(out, "wb");
    if (!f || fwrite(rgb, 1, (size_t)w * h * 3, f) != (size_t)w * h * 3 || fclose(f)) {
        perror(out);
        return 1;
    }
    free(rgb);
    return 0;
}

static int timing(const char *path, int w, int h, int pairs, double thr)
{
    const size_t fb = (size_t)w * h * 3;
    const int slots = 2 * pairs; /* one fresh input and output slot per call */
    uint8_t *in = malloc(fb * slots), *out = malloc(fb * slots);
    double *tm = malloc(sizeof(double) * pairs), *te = malloc(sizeof(double) * pairs);
    bloom_config_t cfg;
    bloom_t *b;
    void *ws;
    FILE *f = fopen(path, "rb");
    if (!in || !out || !tm || !te || !f || fread(in, 1, fb, f) != fb) {
        fprintf(stderr, "peers_drv: cannot read %s or out of memory\n", path);
        return 1;
    }
    fclose(f);
    for (int i = 1; i < slots; i++)
        memcpy(in + fb * i, in, fb);
    memset(out, 0, fb * slots); /* every page touched before timing */
    bloom_config_default(&cfg, w, h);
    cfg.threshold = (uint32_t)(thr * 65536 + 0.5);
    ws = aligned_alloc(64, (bloom_workspace_size(&cfg) + 63) / 64 * 64);
    if (!ws || bloom_init(&b, ws, bloom_workspace_size(&cfg), &cfg) != BLOOM_OK) {
        fprintf(stderr, "peers_drv: bloom_init failed\n");
        return 1;
    }
    bloom_process(b, in, (ptrdiff_t)w * 3, out, (ptrdiff_t)w * 3); /* warm-up: code, tables */
    for (int i = 0; i < slots; i++) /* evict: walk far more memory than the LLC */
        memset(out + fb * i, i, fb);
    for (int p = 0; p < pairs; p++) {
        uint8_t *s = in + fb * 2 * p, *d = out + fb * 2 * p;
        double t0 = now_ms();
        memcpy(d, s, fb);
        double t1 = now_ms();
        bloom_process(b, s + fb, (ptrdiff_t)w * 3, d + fb, (ptrdiff_t)w * 3);
        double t2 = now_ms();
        tm[p] = t1 - t0;
        te[p] = t2 - t1;
    }
    printf("%.4f %.4f\n", median(tm, pairs), median(te, pairs));
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 5 && !strcmp(argv[1], "scene"))
        return scene(argv[2], atoi(argv[3]), atoi(argv[4]));
    if (argc == 7 && !strcmp(argv[1], "time"))
        return timing(argv[2], atoi(argv[3]), atoi(argv[4]), atoi(argv[5]), atof(argv[6]));
    fprintf(stderr, "usage: peers_drv scene OUT.rgb W H | time FRAME.rgb W H PAIRS THRESHOLD\n");
    return 2;
}
