/* The xna preset's SIMD twins (bloom_preset_xna_sse2.c, _avx2.c where the
 * CPU has AVX2, _neon.c on aarch64) against their C kernels, bit for bit:
 * the Kawase sums with and without their rounding, the screen addend;
 * widths 1 .. 1921, unaligned pointers, worst-case and random values. And
 * the screen addend against the screen formula it replaces. On a target
 * without twins it compares the C kernels with themselves (and says so). */
#include "bloom_preset_xna.h"
#include "harness.h"

#include <stdlib.h>
#include <string.h>

#define MAXW 1921
#define PAD 16

static uint32_t rng = 0x9E3779B9u;
static uint32_t rnd32(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

/* Fill n words: kind 0 random 32-bit, 1 all LIN_MAX, 2 random up to
 * LIN_MAX, 3 small (0 .. 40), 4 around ONE. */
static void fill(uint32_t *p, int n, int kind)
{
    for (int j = 0; j < n; j++) {
        const uint32_t r = rnd32();
        switch (kind) {
        case 0:
            p[j] = r;
            break;
        case 1:
            p[j] = BLOOM_LIN_MAX;
            break;
        case 2:
            p[j] = r % (BLOOM_LIN_MAX + 1u);
            break;
        case 3:
            p[j] = r % 41u;
            break;
        default:
            p[j] = BLOOM_LIN_ONE - 4u + r % 9u;
            break;
        }
    }
}

typedef struct {
    const char *name;
    xna_kawase_fn kawase;
    xna_screen_fn screen;
} twin_t;

static uint32_t in4[4][3 * MAXW + PAD], cs_a[3 * MAXW + PAD], cs_b[3 * MAXW + PAD];
static uint32_t out_a[3 * MAXW + PAD], out_b[3 * MAXW + PAD];

static void test_kawase(const twin_t *t)
{
    int bad = 0, cases = 0;
    for (int w = 1; w <= MAXW; w++) {
        const int off = w % 4, n = 3 * w;
        const int kind = w % 5 == 0 ? 1 : w % 3 == 0 ? 2 : w % 7 == 0 ? 3 : 0;
        for (int r = 0; r < 4; r++)
            fill(in4[r] + off, n, kind);
        const uint32_t *const rows[4] = {in4[0] + off, in4[1] + ((off + 1) & 3), in4[2] + off, in4[3] + off};
        const int is[2] = {w % 8, (3 * w + 1) % 8};
        for (int k = 0; k < 2; k++)
            for (int rd = 0; rd < 2; rd++) {
                memset(out_a, 0xA5, sizeof out_a);
                memset(out_b, 0xA5, sizeof out_b);
                xna_kawase_c(rows, cs_a, out_a + 1, w, is[k], rd);
                t->kawase(rows, cs_b + ((w + 1) & 3), out_b + 1, w, is[k], rd);
                cases++;
                if (memcmp(out_a, out_b, sizeof out_a) ||
                    memcmp(cs_a, cs_b + ((w + 1) & 3), (size_t)n * sizeof *cs_a)) {
                    if (bad++ < 5)
                        fprintf(stderr, "%s kawase w %d i %d rnd %d differs\n", t->name, w, is[k], rd);
                }
            }
    }
    CHECKF(bad == 0, "%s: %d of %d Kawase cases differ", t->name, bad, cases);
}

static uint32_t s_in[3 * MAXW + PAD], x_a[3 * MAXW + PAD], x_b[3 * MAXW + PAD];

static void test_screen(const twin_t *t)
{
    int bad = 0, cases = 0;
    for (int w = 1; w <= MAXW; w++) {
        const int n = 3 * w, off = (w * 5) % 4;
        fill(s_in + off, n, w % 2 ? 0 : 4);
        fill(x_a + off, n, w % 3 == 0 ? 4 : w % 3 == 1 ? 0 : 2);
        if (w % 11 == 0)
            for (int j = 0; j < n; j++)
                x_a[off + j] = (j & 1) ? 0xFFFFFFFFu : BLOOM_LIN_ONE;
        memcpy(x_b, x_a, sizeof x_a);
        xna_screen_c(s_in + off, x_a + off, n);
        t->screen(s_in + off, x_b + off, n);
        cases++;
        if (memcmp(x_a, x_b, sizeof x_a) && bad++ < 5)
            fprintf(stderr, "%s screen n %d differs\n", t->name, n);
    }
    CHECKF(bad == 0, "%s: %d of %d screen cases differ", t->name, bad, cases);
}

/* s + P = b + ((s (ONE - b) + ONE/2) >> F), b = min(B, ONE), for s <= ONE. */
static void test_screen_formula(void)
{
    int bad = 0;
    for (int k = 0; k < 200000; k++) {
        uint32_t s = k < 1000 ? (uint32_t)k * (BLOOM_LIN_ONE / 999u) : rnd32() % (BLOOM_LIN_ONE + 1u);
        uint32_t B = (k & 3) == 0 ? rnd32() : (k & 3) == 1 ? rnd32() % (BLOOM_LIN_ONE + 2u) : rnd32() % 64u;
        if (k % 97 == 0)
            s = BLOOM_LIN_ONE;
        if (k % 89 == 0)
            B = BLOOM_LIN_ONE;
        const uint32_t b = B > BLOOM_LIN_ONE ? BLOOM_LIN_ONE : B;
        const uint64_t p = ((uint64_t)s * (BLOOM_LIN_ONE - b) + (BLOOM_LIN_ONE >> 1)) >> BLOOM_LIN_BITS;
        const uint32_t want = b + (uint32_t)p;
        uint32_t x = B;
        xna_screen_c(&s, &x, 1);
        if (s + x != want && bad++ < 5)
            fprintf(stderr, "screen formula s %u B %u: %u, want %u\n", s, B, s + x, want);
    }
    CHECKF(bad == 0, "%d screen formula cases differ", bad);
}

int main(void)
{
    twin_t twins[3];
    int nt = 0;
#if defined(BLOOM_SIMD_SSE2)
    twins[nt++] = (twin_t){"sse2", xna_kawase_sse2, xna_screen_sse2};
#if defined(BLOOM_SIMD_AVX2)
    if (bloom_cpu_avx2())
        twins[nt++] = (twin_t){"avx2", xna_kawase_avx2, xna_screen_avx2};
    else
        SKIP("cpu avx2: the CPU or the OS lacks AVX2");
#endif
#endif
#if defined(BLOOM_SIMD_NEON)
    twins[nt++] = (twin_t){"neon", xna_kawase_neon, xna_screen_neon};
#endif
    if (!nt) {
        printf("no SIMD twins on this target: the C kernels against themselves\n");
        twins[nt++] = (twin_t){"c", xna_kawase_c, xna_screen_c};
    }
    for (int k = 0; k < nt; k++) {
        test_kawase(&twins[k]);
        test_screen(&twins[k]);
    }
    test_screen_formula();
    /* the preset picks each twin by the kernel set's instruction set */
    xna_kawase_fn kf;
    xna_screen_fn sf;
    xna_kernels(BLOOM_ISA_C, &kf, &sf);
    CHECK(kf == xna_kawase_c && sf == xna_screen_c);
#if defined(BLOOM_SIMD_SSE2)
    xna_kernels(BLOOM_ISA_SSE2, &kf, &sf);
    CHECK(kf == xna_kawase_sse2 && sf == xna_screen_sse2);
#endif
#if defined(BLOOM_SIMD_AVX2)
    xna_kernels(BLOOM_ISA_AVX2, &kf, &sf);
    CHECK(kf == xna_kawase_avx2 && sf == xna_screen_avx2);
#endif
#if defined(BLOOM_SIMD_NEON)
    xna_kernels(BLOOM_ISA_NEON, &kf, &sf);
    CHECK(kf == xna_kawase_neon && sf == xna_screen_neon);
#endif
    return harness_finish();
}
