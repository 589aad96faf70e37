/* The two helpers every timing program here uses: a monotonic clock in
 * seconds and a qsort comparison of doubles (for medians). Header-only, so
 * that the benchmarks, the report, bench_threads and bench_cam share one
 * copy without a library between them. Needs _POSIX_C_SOURCE (clock_gettime). */
#ifndef BENCH_TIMING_H
#define BENCH_TIMING_H

#include <time.h>

static inline double bench_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static inline int bench_cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

#endif
