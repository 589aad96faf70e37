/* Rows for the SIMD kernel tests (test_simd.c, test_simd_out.c): the
 * widths tried, rows with guard words after them, and samples drawn by mode. */
#ifndef SIMD_ROWS_H
#define SIMD_ROWS_H

#include "harness.h"
#include "testutil.h"

static const int widths[] = {1, 2, 3, 7, 8, 15, 16, 17, 31, 33, 1920, 1921};
#define NWIDTHS ((int)(sizeof widths / sizeof widths[0]))
#define GUARD 4u /* words after every output row */
#define GUARD_WORD 0xA5A5A5A5u
#define SMAX ((1u << 28) - 16u) /* largest linear sample */

static uint32_t seed = 12345u;

/* A row of n words at `off` words past a fresh allocation of exactly
 * off + n (+ guard) words: reads past the end hit the sanitizer. */
typedef struct {
    uint32_t *base, *p;
    size_t n;
} row_t;

static inline row_t row_new(size_t n, int off, int guard)
{
    row_t r;
    const size_t total = (size_t)off + n + (guard ? GUARD : 0u);
    r.base = (uint32_t *)xmalloc(total * sizeof(uint32_t) + (total ? 0u : 4u));
    r.p = r.base + off;
    r.n = n;
    for (size_t i = 0; i < total; i++)
        r.base[i] = GUARD_WORD;
    return r;
}

static inline int row_guard_ok(const row_t *r)
{
    for (size_t i = 0; i < GUARD; i++)
        if (r->p[r->n + i] != GUARD_WORD)
            return 0;
    return 1;
}

/* mode 0: random samples up to SMAX; 1: all SMAX; 2: random 0/SMAX/small;
 * 3: any 32-bit value (sums wrap the same way in C and SIMD). */
static inline uint32_t sample(int mode, uint32_t max)
{
    const uint32_t r = rng_next(&seed);
    switch (mode) {
    case 0:
        return r % (max + 1u == 0u ? 0xFFFFFFFFu : max + 1u);
    case 1:
        return max;
    case 2: {
        const uint32_t k = r & 3u;
        return k == 0 ? 0u : k == 1 ? max : k == 2 ? max - (r >> 28) : (r >> 8) & 15u;
    }
    default:
        return r;
    }
}

static inline void fill(uint32_t *p, size_t n, int mode, uint32_t max)
{
    for (size_t i = 0; i < n; i++)
        p[i] = sample(mode, max);
}

#endif
