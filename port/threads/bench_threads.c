/* bench_threads: the figures of sim/docs/threads.md (bench_threads.sh).
 *
 *   bench_threads time W H ROUNDS   paired rounds of one frame on 1 thread
 *                                   and on 2 threads (bloom_mt), the order
 *                                   alternating so that neither side always
 *                                   runs on a warm cache; medians and the
 *                                   median of the per-round ratios; and in
 *                                   the same rounds the machine's own
 *                                   ceiling: two whole frames by two
 *                                   independent engines at once, on two
 *                                   threads, against one frame
 *   bench_threads icount W H N      one frame through the N strip engines
 *                                   one after another on this thread (no
 *                                   pool: callgrind counts instructions,
 *                                   not threads), for --toggle-collect=
 *                                   bloom_process; N = 1 is the untiled frame
 * The default preset, RGB888 in and out, the benchmark scene of make bench. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bloom.h"
#include "bloom_mt.h"
#include "scene.h"
#include "timing.h"

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, bench_cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static bloom_mt_t *mt_make(const bloom_config_t *c, int n, void **buf)
{
    const size_t bytes = bloom_mt_size(c, n);
    bloom_mt_t *mt = NULL;
    *buf = malloc(bytes);
    bloom_status_t st = *buf ? bloom_mt_init(&mt, *buf, bytes, c, n) : BLOOM_E_WORKSPACE;
    if (st != BLOOM_OK) {
        fprintf(stderr, "bench_threads: %d threads: %s\n", n, bloom_mt_status_str(st));
        exit(1);
    }
    return mt;
}

static double frame_time(bloom_mt_t *mt, const uint8_t *src, uint8_t *dst, ptrdiff_t stride)
{
    const double t0 = bench_now_s();
    const bloom_status_t st = bloom_mt_process(mt, src, stride, dst, stride);
    const double t = bench_now_s() - t0;
    if (st != BLOOM_OK) {
        fprintf(stderr, "bench_threads: %s\n", bloom_mt_status_str(st));
        exit(1);
    }
    return t;
}

/* One untiled frame by its own engine (the ceiling's two jobs). */
typedef struct {
    bloom_t *b;
    const uint8_t *src;
    uint8_t *dst;
    ptrdiff_t stride;
} job_t;

static void *job_run(void *a)
{
    job_t *j = (job_t *)a;
    if (bloom_process(j->b, j->src, j->stride, j->dst, j->stride) != BLOOM_OK)
        exit(1);
    return NULL;
}

static bloom_t *engine_make(const bloom_config_t *c, void **ws)
{
    const size_t n = bloom_workspace_size(c);
    *ws = aligned_alloc(64, (n + 63u) & ~(size_t)63u);
    bloom_t *b = NULL;
    if (!*ws || bloom_init(&b, *ws, n, c) != BLOOM_OK) {
        fprintf(stderr, "bench_threads: no engine\n");
        exit(1);
    }
    return b;
}

/* Two jobs at once on two threads: their wall time. */
static double pair_time(job_t *a, job_t *b)
{
    pthread_t t;
    const double t0 = bench_now_s();
    if (pthread_create(&t, NULL, job_run, b))
        exit(1);
    job_run(a);
    pthread_join(t, NULL);
    return bench_now_s() - t0;
}

static int run_time(const bloom_config_t *c, const uint8_t *src, uint8_t *dst, int rounds)
{
    void *b1, *b2;
    bloom_mt_t *m1 = mt_make(c, 1, &b1), *m2 = mt_make(c, 2, &b2);
    const ptrdiff_t stride = (ptrdiff_t)c->width * 3;
    uint8_t *dst2 = malloc((size_t)stride * (size_t)c->height);
    double *t1 = malloc(sizeof(double) * (size_t)rounds), *t2 = malloc(sizeof(double) * (size_t)rounds),
           *ratio = malloc(sizeof(double) * (size_t)rounds);
    const size_t fb = (size_t)stride * (size_t)c->height;
    uint8_t *src3 = malloc(fb), *dst3 = malloc(fb), *dst4 = malloc(fb);
    double *ceil = malloc(sizeof(double) * (size_t)rounds);
    if (!dst2 || !t1 || !t2 || !ratio || !src3 || !dst3 || !dst4 || !ceil)
        return 1;
    memcpy(src3, src, fb);
    void *wa, *wb;
    job_t ja = {engine_make(c, &wa), src, dst3, stride}, jb = {engine_make(c, &wb), src3, dst4, stride};
    for (int w = 0; w < 3; w++) { /* warm-up: pages touched, threads scheduled */
        frame_time(m1, src, dst, stride);
        frame_time(m2, src, dst2, stride);
    }
    for (int r = 0; r < rounds; r++) {
        if (r % 2) {
            t2[r] = frame_time(m2, src, dst2, stride);
            t1[r] = frame_time(m1, src, dst, stride);
        } else {
            t1[r] = frame_time(m1, src, dst, stride);
            t2[r] = frame_time(m2, src, dst2, stride);
        }
        ratio[r] = t1[r] / t2[r];
        const double t0 = bench_now_s();
        job_run(&ja);
        const double one = bench_now_s() - t0;
        ceil[r] = 2.0 * one / pair_time(&ja, &jb); /* the ceiling in this round */
    }
    const int same = !memcmp(dst, dst2, (size_t)stride * (size_t)c->height);
    printf("size %dx%d\nrounds %d\ncpus %d\ntiles2 %d\nt1_ms %.3f\nt2_ms %.3f\nratio %.3f\nidentical %d\n"
           "ceiling %.3f\n",
           c->width, c->height, rounds, bloom_mt_cpus(), bloom_mt_tiles(m2), median(t1, rounds) * 1e3,
           median(t2, rounds) * 1e3, median(ratio, rounds), same, median(ceil, rounds));
    free(wa);
    free(wb);
    free(src3);
    free(dst3);
    free(dst4);
    free(ceil);
    bloom_mt_free(m1);
    bloom_mt_free(m2);
    free(b1);
    free(b2);
    free(dst2);
    free(t1);
    free(t2);
    free(ratio);
    return same ? 0 : 1;
}

static int run_icount(const bloom_config_t *c, const uint8_t *src, uint8_t *dst, int n)
{
    void *buf;
    bloom_mt_t *mt = mt_make(c, n, &buf);
    const ptrdiff_t stride = (ptrdiff_t)c->width * 3;
    size_t ws = 0;
    for (int i = 0; i < bloom_mt_tiles(mt); i++) {
        bloom_t *b = bloom_mt_engine(mt, i);
        if (bloom_process(b, src, stride, dst, stride) != BLOOM_OK)
            return 1;
    }
    for (int i = 0; i < bloom_mt_tiles(mt); i++) {
        bloom_config_t t = *c;
        if (n > 1) { /* the tiles' own sizes, as bloom_mt cut them */
            t.tile_x = (int)((long)c->width * i / n);
            t.tile_w = (int)((long)c->width * (i + 1) / n) - t.tile_x;
            t.tile_h = c->height;
        }
        ws += bloom_workspace_size(&t);
    }
    printf("tiles %d\nworkspace %zu\n", bloom_mt_tiles(mt), ws);
    bloom_mt_free(mt);
    free(buf);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 5 || (strcmp(argv[1], "time") && strcmp(argv[1], "icount"))) {
        fprintf(stderr, "usage: bench_threads time|icount W H ROUNDS|STRIPS\n");
        return 2;
    }
    const int w = atoi(argv[2]), h = atoi(argv[3]), k = atoi(argv[4]);
    if (w < 1 || h < 1 || k < 1)
        return 2;
    bloom_config_t c;
    bloom_config_default(&c, w, h);
    uint8_t *src = malloc((size_t)w * (size_t)h * 3), *dst = malloc((size_t)w * (size_t)h * 3);
    char err[256];
    if (!src || !dst || scene_make(SCENE_IMAGE_DEFAULT, w, h, src, err, sizeof err)) {
        fprintf(stderr, "bench_threads: scene: %s\n", src && dst ? err : "out of memory");
        return 1;
    }
    const int rc = !strcmp(argv[1], "time") ? run_time(&c, src, dst, k) : run_icount(&c, src, dst, k);
    free(src);
    free(dst);
    return rc;
}
