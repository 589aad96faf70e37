/* The gamedev preset's C row kernels (bloom_preset_gamedev_k.h): the
 * Gaussian's passes, the 8-bit tone curve, the byte table of the rows
 * without bloom, and the kernel sets of each instruction set. The SIMD
 * twins are bloom_preset_gamedev_{sse2,avx2,neon}.c, the same bits. */
#include "bloom_preset_gamedev_k.h"

#if BLOOM_USE_GAMEDEV

/* Vertical pass over m samples of the nine rows a[0..8] (rows r-4 .. r+4,
 * clamped by the engine). Symmetric pairs are added first (< 2^29), each
 * product < 2^51, the sum < 2^24 * 2^28 = 2^52: a 64-bit sum, one UMLAL
 * per pair on Cortex-M. */
void gd_gauss_v_c(const uint32_t *const a[9], uint32_t *dst, int m)
{
    const uint32_t *a0 = a[0], *a1 = a[1], *a2 = a[2], *a3 = a[3], *a4 = a[4], *a5 = a[5], *a6 = a[6],
                   *a7 = a[7], *a8 = a[8];
    for (int i = 0; i < m; i++) {
        const uint64_t s = (uint64_t)GW0 * a4[i] + (uint64_t)GW1 * (a3[i] + a5[i]) +
                           (uint64_t)GW2 * (a2[i] + a6[i]) + (uint64_t)GW3 * (a1[i] + a7[i]) +
                           (uint64_t)GW4 * (a0[i] + a8[i]) + GHALF;
        dst[i] = (uint32_t)(s >> GQ);
    }
}

static inline int clampx(int x, int w)
{
    return x < 0 ? 0 : x >= w ? w - 1 : x;
}

/* Horizontal pass at an edge pixel x (columns clamped). */
static void gauss_h_edge(const uint32_t *v, uint32_t *dst, int x, int w)
{
    static const uint32_t wt[5] = {GW0, GW1, GW2, GW3, GW4};
    for (int ch = 0; ch < 3; ch++) {
        uint64_t s = (uint64_t)GW0 * v[3 * x + ch] + GHALF;
        for (int j = 1; j <= 4; j++)
            s += (uint64_t)wt[j] * (v[3 * clampx(x - j, w) + ch] + v[3 * clampx(x + j, w) + ch]);
        dst[3 * x + ch] = (uint32_t)(s >> GQ);
    }
}

/* Horizontal pass of interior samples i0 .. i1-1 (no clamping). */
void gd_gauss_h_c(const uint32_t *v, uint32_t *dst, int i0, int i1)
{
    for (int i = i0; i < i1; i++) {
        const uint64_t s = (uint64_t)GW0 * v[i] + (uint64_t)GW1 * (v[i - 3] + v[i + 3]) +
                           (uint64_t)GW2 * (v[i - 6] + v[i + 6]) + (uint64_t)GW3 * (v[i - 9] + v[i + 9]) +
                           (uint64_t)GW4 * (v[i - 12] + v[i + 12]) + GHALF;
        dst[i] = (uint32_t)(s >> GQ);
    }
}

void gd_bright_c(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c)
{
    for (int i = 0; i < n; i++) {
        uint32_t m = s[0][i] > s[1][i] ? s[0][i] : s[1][i];
        m = s[2][i] > m ? s[2][i] : m;
        m = s[3][i] > m ? s[3][i] : m;
        b[i] = (uint8_t)(m > c ? m - c : 0u);
    }
}

void gd_lut8_c(const uint8_t *s, const uint8_t *tab, uint8_t *d, int n)
{
    for (int i = 0; i < n; i++)
        d[i] = tab[s[i]];
}

/* Horizontal pass of a row of w pixels: v (3 samples per pixel) -> dst. */
void gd_gauss_h_row(const gd_kern_t *k, const uint32_t *v, uint32_t *dst, int w)
{
    const int lo = w < 4 ? w : 4, hi = w - 4 > lo ? w - 4 : lo;
    for (int x = 0; x < lo; x++)
        gauss_h_edge(v, dst, x, w);
    if (hi > lo)
        k->gauss_h(v, dst, 3 * lo, 3 * hi);
    for (int x = hi; x < w; x++)
        gauss_h_edge(v, dst, x, w);
}

/* The kernels of each instruction set: the twins this build has, the C
 * ones elsewhere (same bits). BLOOM_SMALL builds: C, no tone kernel. */
#if !BLOOM_SMALL
#define GD_TONE8_C gd_tone8_c
#else
#define GD_TONE8_C NULL
#endif
static const gd_kern_t gd_kern_c = {NULL, gd_gauss_v_c, gd_gauss_h_c, GD_TONE8_C, gd_lut8_c, "c"};
#if defined(BLOOM_SIMD_SSE2) && !BLOOM_SMALL
static const gd_kern_t gd_kern_sse2 = {gd_bright_sse2, gd_gauss_v_sse2, gd_gauss_h_sse2,
                                       gd_tone8_c,     gd_lut8_c,       "sse2"};
#if defined(BLOOM_SIMD_AVX2)
static const gd_kern_t gd_kern_avx2 = {gd_bright_avx2, gd_gauss_v_avx2, gd_gauss_h_avx2,
                                       gd_tone8_c,     gd_lut8_avx2,    "avx2"};
#endif
#endif
#if defined(BLOOM_SIMD_NEON) && !BLOOM_SMALL
static const gd_kern_t gd_kern_neon = {gd_bright_neon, gd_gauss_v_neon, gd_gauss_h_neon,
                                       gd_tone8_c,     gd_lut8_neon,    "neon"};
#endif

const gd_kern_t *gd_kern_for(bloom_isa_t isa)
{
    switch (isa) {
#if defined(BLOOM_SIMD_SSE2) && !BLOOM_SMALL
    case BLOOM_ISA_SSE2:
        return &gd_kern_sse2;
#if defined(BLOOM_SIMD_AVX2)
    case BLOOM_ISA_AVX2:
        return &gd_kern_avx2;
#endif
#endif
#if defined(BLOOM_SIMD_NEON) && !BLOOM_SMALL
    case BLOOM_ISA_NEON:
        return &gd_kern_neon;
#endif
    default:
        return &gd_kern_c;
    }
}

#if !BLOOM_SMALL
void gd_tone8_c(const uint32_t *bl, const uint32_t *sv, const uint8_t *sc, const uint32_t *dec, uint8_t *out,
                int n, uint32_t s, const uint32_t *t, const uint8_t *bk)
{
    for (int i = 0; i < n; i++) {
        const uint32_t S = sc ? dec[sc[i]] : sv[i];
        out[i] = (uint8_t)gd_code_bk(t, bk, gd_to_q20((((uint64_t)s * bl[i] + 32768u) >> 16) + S));
    }
}
#endif

#else
typedef int bloom_preset_gamedev_kern_unused_t;
#endif
