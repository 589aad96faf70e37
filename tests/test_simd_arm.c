/* The arm preset's SIMD twins (src/presets/bloom_preset_arm_sse2.c, _avx2.c,
 * _neon.c) against its C kernels (bloom_preset_arm_kern.c): every kernel,
 * widths 1 .. 1921, unaligned (each buffer offset by 0 .. 3 words), over
 * random values, the largest values of the overflow proof (arm.md: a
 * sample <= M = 2^28 - 16, column sums c4 <= 4M and c2 <= 2M, up sums
 * a <= 4M and v <= 8M), and values at the 64 h + l split of the up twins.
 * The same bytes out, and the same OR returned. */
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "bloom_preset_arm.h"

#if BLOOM_USE_ARM
#define M (BLOOM_MAX_LINEAR << BLOOM_Q16_SHIFT)
#define NMAX 1921
#define PAD 16

static uint32_t rng = 12345u;
static uint32_t next(void)
{
    rng = rng * 1664525u + 1013904223u;
    return rng >> 1 ^ rng << 7;
}

/* n values <= top: random, top itself, 0, and 64 h + l edges. */
static void fill(uint32_t *p, int n, uint32_t top, int mode)
{
    for (int i = 0; i < n; i++) {
        const uint32_t r = next();
        switch (mode) {
        case 0:
            p[i] = r % (top + 1u);
            break;
        case 1:
            p[i] = top;
            break;
        case 2:
            p[i] = (r & 1) ? top - (r >> 1) % 64u : (r >> 1) % 128u;
            break;
        default:
            p[i] = ((r % (top / 64u)) << 6) | (r & 1 ? 63u : 0u);
            break;
        }
    }
}

typedef struct {
    uint32_t in[6][NMAX * 2 + 2 * PAD];
    uint32_t o1[2][NMAX * 2 + 2 * PAD], o2[2][NMAX * 2 + 2 * PAD];
} bufs_t;

static int check_set(const bloom_arm_kern_t *k, bufs_t *b)
{
    const bloom_arm_kern_t *c = &bloom_arm_kern_c;
    int bad = 0;
    for (int n = 1; n <= NMAX; n++)
        for (int mode = 0; mode < 4; mode++) {
            if (n > 80 && mode != 0 && n % 7 != 0)
                continue; /* the edge modes on every width up to 80, then every 7th */
            const int off = (n + mode) % 4;
            uint32_t *s[6];
            for (int i = 0; i < 6; i++)
                s[i] = b->in[i] + off + i % 2;
            uint32_t *o1a = b->o1[0] + off, *o1b = b->o1[1] + off, *o2a = b->o2[0] + off + 1,
                     *o2b = b->o2[1] + off;
            const size_t w2 = (size_t)(2 * n + 2) * sizeof(uint32_t);
            /* down_v: samples <= M */
            for (int i = 0; i < 4; i++)
                fill(s[i], n, M, mode);
            c->down_v(s[0], s[1], s[2], s[3], o1a, o1b, n);
            k->down_v(s[0], s[1], s[2], s[3], o2a, o2b, n);
            bad += memcmp(o1a, o2a, (size_t)n * 4u) != 0 || memcmp(o1b, o2b, (size_t)n * 4u) != 0;
            /* down_h: c4 <= 4M, c2 <= 2M, read [0 .. 2n+1] */
            fill(s[4], 2 * n + 2, 4u * M, mode);
            fill(s[5], 2 * n + 2, 2u * M, mode);
            memset(o1a, 0xA5, w2);
            memset(o2a, 0xA5, w2);
            uint32_t r1 = c->down_h(s[4], s[5], o1a, n), r2 = k->down_h(s[4], s[5], o2a, n);
            bad += r1 != r2 || memcmp(o1a, o2a, w2) != 0;
            /* up_v: samples <= M */
            for (int i = 0; i < 3; i++)
                fill(s[i], n, M, mode);
            c->up_v(s[0], s[1], s[2], o1a, o1b, n);
            k->up_v(s[0], s[1], s[2], o2a, o2b, n);
            bad += memcmp(o1a, o2a, (size_t)n * 4u) != 0 || memcmp(o1b, o2b, (size_t)n * 4u) != 0;
            /* up_h: a <= 4M, v <= 8M, read [0 .. n+1], n pairs */
            fill(s[4], n + 2, 4u * M, mode);
            fill(s[5], n + 2, 8u * M, mode);
            memset(o1a, 0x5A, w2);
            memset(o2a, 0x5A, w2);
            r1 = c->up_h(s[4], s[5], o1a, n);
            r2 = k->up_h(s[4], s[5], o2a, n);
            bad += r1 != r2 || memcmp(o1a, o2a, w2) != 0;
            /* zeros: OR 0 */
            memset(s[4], 0, (size_t)(2 * n + 2) * 4u);
            memset(s[5], 0, (size_t)(2 * n + 2) * 4u);
            bad += k->up_h(s[4], s[5], o2a, n) != 0 || k->down_h(s[4], s[5], o2a, n) != 0;
        }
    return bad;
}

static void run(const bloom_arm_kern_t *k, bloom_isa_t isa)
{
    static bufs_t b;
    CHECKF(bloom_arm_kern(isa) == k, "arm kernels: the set for isa %d is %s", (int)isa, k->name);
    const int bad = check_set(k, &b);
    CHECKF(bad == 0, "arm %s twins = C kernels over widths 1 .. %d, unaligned (%d cases differ)", k->name,
           NMAX, bad);
    printf("arm %s: down_v, down_h, up_v, up_h bit-identical to C, widths 1 .. %d\n", k->name, NMAX);
}
#endif

int main(void)
{
#if BLOOM_USE_ARM
    run(&bloom_arm_kern_c, BLOOM_ISA_C);
#if defined(BLOOM_SIMD_SSE2)
    run(&bloom_arm_kern_sse2, BLOOM_ISA_SSE2);
#endif
#if defined(BLOOM_SIMD_AVX2)
    if (bloom_cpu_avx2())
        run(&bloom_arm_kern_avx2, BLOOM_ISA_AVX2);
    else
        SKIP("cpu avx2: this CPU has no AVX2 (the arm AVX2 twins)");
#endif
#if defined(BLOOM_SIMD_NEON)
    run(&bloom_arm_kern_neon, BLOOM_ISA_NEON);
#endif
#if !defined(BLOOM_SIMD_SSE2) && !defined(BLOOM_SIMD_NEON)
    SKIP("arm SIMD twins: none on this target (C kernels only)");
#endif
#else
    SKIP("arm preset: compiled out (BLOOM_USE_ARM=0)");
#endif
    return harness_finish();
}
