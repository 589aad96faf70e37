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

/* max3, lum8 and out8 (8-bit sRGB RGB888 and XRGB8888 rows) over
 * widths 1 .. 1921, unaligned: random codes, all 255, codes in a narrow
 * band; blooms random <= M, M itself, and the edges of the keep bound;
 * factors 0, random, the largest (intensity 10, white tint) and 2^32 - 1;
 * out8 also in place. */
typedef struct {
    uint8_t src[4 * NMAX + 64], o1[4 * NMAX + 64], o2[4 * NMAX + 64];
    uint32_t c4[2][NMAX + PAD], c2[2][NMAX + PAD];
} bytes_t;

static int check_px(const bloom_arm_kern_t *k, bufs_t *b, bytes_t *t)
{
    const bloom_arm_kern_t *c = &bloom_arm_kern_c;
    int bad = 0;
    for (int n = 1; n <= NMAX; n++)
        for (int mode = 0; mode < 4; mode++) {
            if (n > 80 && mode != 0 && n % 7 != 0)
                continue;
            const int off = (n + mode) % 4;
            uint32_t *u[3] = {b->in[0] + off, b->in[1] + off + 1, b->in[2] + off + 2};
            for (int i = 0; i < 3; i++)
                fill(u[i], n, M, mode);
            bad += c->max3(u[0], u[1], u[2], n) != k->max3(u[0], u[1], u[2], n);
            for (int x4 = 0; x4 < 2; x4++) {
                const int bpp = x4 ? 4 : 3;
                const size_t nb = (size_t)n * (size_t)bpp;
                uint8_t *s = t->src + off;
                const uint32_t r0 = next();
                for (size_t i = 0; i < nb; i++) {
                    const uint32_t r = next() >> 8;
                    s[i] = (uint8_t)(mode == 1 ? 255u : mode == 2 ? (r0 & 63u) + r % 3u : r);
                }
                /* lum8: rows 0 .. 3 summed */
                uint32_t *a4 = t->c4[0] + off, *a2 = t->c2[0] + off, *b4 = t->c4[1] + off,
                         *b2 = t->c2[1] + off;
                for (int i = 0; i < 4; i++) {
                    c->lum8(s, a4, a2, n, x4, i);
                    k->lum8(s, b4, b2, n, x4, i);
                }
                bad += memcmp(a4, b4, (size_t)n * 4u) != 0 || memcmp(a2, b2, (size_t)n * 4u) != 0;
#if !BLOOM_SMALL
                /* out8 */
                uint32_t *bl = b->in[3] + off;
                fill(bl, n, M, mode == 3 ? 0 : mode);
                if (mode == 3)
                    for (int i = 0; i < n; i++) /* P at the keep bound: B near 158, 12 c */
                        bl[i] = (next() % 2 ? 158u : 12u * (next() % 256u)) + next() % 3u - 1u + 1u;
                uint32_t f[3];
                for (int ch = 0; ch < 3; ch++) {
                    const uint32_t r = next() % 8u;
                    f[ch] = r == 0   ? 0u
                            : r == 1 ? 655360u
                            : r == 2 ? 0xFFFFFFFFu
                            : r == 3 ? 65536u
                                     : next() % 700000u;
                }
                uint8_t *o1 = t->o1 + off + 1, *o2 = t->o2 + off + 2;
                memset(o1, 0x33, nb + 8);
                memset(o2, 0x33, nb + 8);
                c->out8(s, bl, f, o1, n, x4);
                k->out8(s, bl, f, o2, n, x4);
                bad += memcmp(o1, o2, nb + 8) != 0;
                memcpy(o2, s, nb); /* in place */
                k->out8(o2, bl, f, o2, n, x4);
                bad += memcmp(o1, o2, nb) != 0;
#endif
            }
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
    static bytes_t t;
    const int badp = check_px(k, &b, &t);
    CHECKF(badp == 0, "arm %s max3, lum8, out8 = C over widths 1 .. %d, unaligned (%d cases differ)", k->name,
           NMAX, badp);
    printf("arm %s: max3, lum8, out8 bit-identical to C, widths 1 .. %d\n", k->name, NMAX);
}
#endif

int main(void)
{
#if BLOOM_USE_ARM
    /* the AVX2 encoder reads the bucket table as words at v >> 8, v <= t[255] */
    CHECKF((bloom_srgb_enc8[255] >> (BLOOM_LIN_BITS - 12)) + 4u <= sizeof bloom_srgb_bkt8,
           "arm out8: a word read of the bucket table at t[255] >> %d stays in its %zu bytes",
           BLOOM_LIN_BITS - 12, sizeof bloom_srgb_bkt8);
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
    SKIP("cpu without SIMD twins for arm (this target has none: C kernels only)");
#endif
#else
    SKIP("arm preset: compiled out (BLOOM_USE_ARM=0)");
#endif
    return harness_finish();
}
