/* bloom_bench's measuring machinery (bench.h): the cold frame rings, the
 * timed runs of one contender and the paired rounds of several. Moved out
 * of bench.c, which keeps the variants, the sizes and main. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "timing.h"

/* CPU time of the whole process, every thread (OpenCV's workers included). */
double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* ---- the cold ring -------------------------------------------------------
 * Two rings (input, output) of ring_bytes each, at least 4x the largest
 * last-level cache figure: each run takes the next slot, so its input and
 * output frames were last touched ring_bytes of traffic ago. */

void ring_alloc(ring_t *r, size_t bytes)
{
    void *a = NULL, *b = NULL;
    if (posix_memalign(&a, 4096, bytes) || posix_memalign(&b, 4096, bytes))
        die("cannot allocate the frame rings (%s); try --ring-mb", "posix_memalign");
    memset(a, 0, bytes); /* fault the pages in now, not during a run */
    memset(b, 0, bytes);
    r->src = a;
    r->dst = b;
    r->bytes = bytes;
    r->filled_fmt = 0;
}

/* Slots of slot_bytes (rounded up to pages) for input and output frames;
 * the input slots get frame (frame_bytes); refilled when fmt/size change. */
void ring_prepare(ring_t *r, const uint8_t *frame, size_t frame_bytes, size_t slot_bytes, int fmt, size_t wh)
{
    const size_t slot = (slot_bytes + 4095u) & ~(size_t)4095u;
    if (r->slot != slot) {
        r->slot = slot;
        r->nslots = (int)(r->bytes / slot);
        r->next = 0;
        r->filled_fmt = 0;
    }
    if (r->nslots < 2)
        die("frame rings too small for a frame (%s); raise --ring-mb", "ring");
    if (r->filled_fmt != fmt || r->filled_size != wh) {
        for (int i = 0; i < r->nslots; i++)
            memcpy(r->src + (size_t)i * slot, frame, frame_bytes);
        r->filled_fmt = fmt;
        r->filled_size = wh;
    }
}

double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, bench_cmp_double);
    return n & 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* warm-ups, then runs; median and minimum in ms. Returns 0 or the run's
 * error. The last warm-up (steady state: buffers allocated) decides whether
 * the row is slow enough for fewer runs. */
int measure(ring_t *r, run_fn fn, void *ctx, int warm, int runs, row_t *row)
{
    double last = 0.0;
    for (int i = 0; i < warm; i++) {
        const int s = r->next++ % r->nslots;
        const double t0 = bench_now_s();
        const int e = fn(ctx, r->src + (size_t)s * r->slot, r->dst + (size_t)s * r->slot);
        last = bench_now_s() - t0;
        if (e)
            return e;
    }
    if (last > SLOW_RUN_S && runs > SLOW_RUNS)
        runs = SLOW_RUNS;
    double *t = xmalloc(sizeof *t * (size_t)runs), *c = xmalloc(sizeof *c * (size_t)runs);
    for (int i = 0; i < runs; i++) {
        const int s = r->next++ % r->nslots;
        const double c0 = cpu_s(), t0 = bench_now_s();
        const int e = fn(ctx, r->src + (size_t)s * r->slot, r->dst + (size_t)s * r->slot);
        t[i] = bench_now_s() - t0;
        c[i] = cpu_s() - c0;
        if (e) {
            free(t);
            free(c);
            return e;
        }
    }
    row->runs = runs;
    row->median_ms = 1e3 * median(t, runs);
    row->min_ms = 1e3 * t[0]; /* sorted by median() */
    row->cpu_ms = 1e3 * median(c, runs);
    free(t);
    free(c);
    return 0;
}

/* ---- paired rounds --------------------------------------------------------
 * The figures the issue-7 targets compare, measured in rounds: every round
 * runs each contender once (the order rotated from round to round), each on
 * the next cold slot, and the ratios are taken within the round before the
 * median over the rounds, so that a slow spell of a shared machine hits
 * numerator and denominator alike. Contender 0 is the memcpy floor,
 * contender 1 the engine reference. */

void paired(ring_t *r, const contender_t *c, int nc, int rounds, int w, int h)
{
    double *t = xmalloc(sizeof *t * (size_t)(nc * rounds)), *q = xmalloc(sizeof *q * (size_t)rounds);
    for (int round = -1; round < rounds; round++) /* round -1: warm-up */
        for (int k = 0; k < nc; k++) {
            const int i = (k + round + 1) % nc;
            const int sl = r->next++ % r->nslots;
            const double t0 = bench_now_s();
            if (c[i].fn(c[i].ctx, r->src + (size_t)sl * r->slot, r->dst + (size_t)sl * r->slot))
                exit(1);
            if (round >= 0)
                t[i * rounds + round] = bench_now_s() - t0;
        }
    for (int i = 0; i < nc; i++) {
        row_t *row = new_row(w, h, "paired", c[i].name);
        row->runs = rounds;
        for (int k = 0; k < rounds; k++)
            q[k] = t[i * rounds + k] / t[k];
        row->x_memcpy = median(q, rounds);
        for (int k = 0; k < rounds; k++)
            q[k] = t[i * rounds + k] / t[rounds + k];
        row->x_engine = median(q, rounds);
        row->xc_memcpy = row->xc_engine = -1.0;
        for (int k = 0; k < rounds; k++)
            q[k] = t[i * rounds + k];
        row->median_ms = 1e3 * median(q, rounds);
        row->min_ms = 1e3 * q[0];
        row->cpu_ms = -1.0;
        snprintf(row->note, sizeof row->note, "ratios: median over %d rounds of the ratio within a round",
                 rounds);
    }
    free(t);
    free(q);
}
