/* The gamedev preset's row kernels (sim/docs/presets/gamedev.md, "Kernels"):
 * the 9-tap Gaussian's two passes and the 8-bit tone curve, in C
 * (bloom_preset_gamedev_kern.c) and as SSE2 / AVX2 / NEON twins with the
 * same bits (bloom_preset_gamedev_{sse2,avx2,neon}.c; the Gaussian and the
 * dark-block test written once, bloom_preset_gamedev_simd.h), picked by
 * the engine's instruction set (ctx->kern.isa, chosen once at bloom_init). */
#ifndef BLOOM_PRESET_GAMEDEV_K_H
#define BLOOM_PRESET_GAMEDEV_K_H

#include "bloom_kernels.h"
#include "bloom_preset_gamedev.h"

#if BLOOM_USE_GAMEDEV

/* The 9-tap Gaussian: the article's weights divided by their printed sum
 * (1.000001), in Q24, rounded to nearest, the centre one 1 lower so that
 * 3808876 + 2 * (3264759 + 2040477 + 906875 + 272059) = 2^24 exactly (a
 * flat field stays flat). Each weight is within 1.21 * 2^-24 of its real
 * value. */
#define GW0 3808876u
#define GW1 3264759u
#define GW2 2040477u
#define GW3 906875u
#define GW4 272059u
#define GQ 24
#define GHALF (1u << (GQ - 1))

/* Vertical pass: dst[i] = (W0 a4[i] + sum_j Wj (a[4-j][i] + a[4+j][i]) + 2^23)
 * >> 24 for i < m (a[0..8]: rows r-4 .. r+4). */
typedef void (*gd_gauss_v_fn)(const uint32_t *const a[9], uint32_t *dst, int m);
/* Horizontal pass, interior samples i = i0 .. i1-1 of an interleaved RGB row
 * (taps v[i - 12] .. v[i + 12] all inside the row): the same sum over
 * v[i + 3j], j = -4 .. 4. */
typedef void (*gd_gauss_h_fn)(const uint32_t *v, uint32_t *dst, int i0, int i1);
/* The 8-bit tone curve of n samples: out[i] = code_of(t, bk, to_q20(S +
 * ((s bl[i] + 2^15) >> 16))), S = dec[sc[i]] when sc is not NULL (sRGB
 * 8-bit codes decoded on the fly), else sv[i]. t: 257 thresholds, bk: their
 * bucket table, s <= 2^20 (the strength). out may be (uint8_t *)bl (each
 * byte is written after the words it overlaps were read). */
typedef void (*gd_tone8_fn)(const uint32_t *bl, const uint32_t *sv, const uint8_t *sc, const uint32_t *dec,
                            uint8_t *out, int n, uint32_t s, const uint32_t *t, const uint8_t *bk);

/* A byte row through a table of 256 bytes: d[i] = tab[s[i]] for i < n (the
 * rows without bloom, RGB888 to RGB888). d may equal s. */
typedef void (*gd_lut8_fn)(const uint8_t *s, const uint8_t *tab, uint8_t *d, int n);

/* The dark-block test of level 1: b[i] = max(s[0][i], .., s[3][i]) - c,
 * saturated at 0, for the n bytes of four source rows (8-bit formats): a
 * byte is not 0 where a code is above the dark code c. */
typedef void (*gd_bright_fn)(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c);

typedef struct {
    gd_bright_fn bright; /* NULL: no dark-block test (C and BLOOM_SMALL: the box is cheaper) */
    gd_gauss_v_fn gauss_v;
    gd_gauss_h_fn gauss_h;
    gd_tone8_fn tone8; /* NULL in BLOOM_SMALL builds (no bucket tables) */
    gd_lut8_fn lut8;
    const char *name;
} gd_kern_t;

/* The kernels for an instruction set (the C ones where a twin is missing). */
const gd_kern_t *gd_kern_for(bloom_isa_t isa);

void gd_gauss_v_c(const uint32_t *const a[9], uint32_t *dst, int m);
void gd_gauss_h_c(const uint32_t *v, uint32_t *dst, int i0, int i1);
void gd_lut8_c(const uint8_t *s, const uint8_t *tab, uint8_t *d, int n);
void gd_bright_c(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c);
/* A whole row of w pixels: the edge pixels (columns clamped) in C, the
 * interior by k->gauss_h. */
void gd_gauss_h_row(const gd_kern_t *k, const uint32_t *v, uint32_t *dst, int w);

#if !BLOOM_SMALL
void gd_tone8_c(const uint32_t *bl, const uint32_t *sv, const uint8_t *sc, const uint32_t *dec, uint8_t *out,
                int n, uint32_t s, const uint32_t *t, const uint8_t *bk);

/* The bucket key of v (bloom_preset_gamedev.h): v below 64, else 64 + 32 (e
 * - 6) + the five bits after the leading one at bit e. */
static inline uint32_t gd_key(uint32_t v)
{
    if (v < 64)
        return v;
#if defined(__GNUC__)
    const int e = 31 - __builtin_clz(v);
#else
    int e = 31;
    while (!(v >> e))
        e--;
#endif
    return 64u + 32u * (uint32_t)(e - 6) + ((v >> (e - 5)) & 31u);
}

/* The number of thresholds t[1 .. n] at or below v: the code of v's bucket
 * and two compares. */
static inline uint32_t gd_code_bk(const uint32_t *t, const uint8_t *bk, uint32_t v)
{
    uint32_t k = bk[gd_key(v)];
    k += t[k + 1] <= v;
    k += t[k + 1] <= v;
    return k;
}

/* The tone curve's input: c = S + P at F bits as the tables' Q12.20,
 * saturated at 2^32 - 2 (every threshold is below 2^30, so that changes no
 * code). */
static inline uint32_t gd_to_q20(uint64_t c)
{
    c <<= 20 - BLOOM_LIN_BITS;
    return c > 0xFFFFFFFEu ? 0xFFFFFFFEu : (uint32_t)c;
}
#endif

#if defined(BLOOM_SIMD_SSE2) && !BLOOM_SMALL
void gd_bright_sse2(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c);
void gd_gauss_v_sse2(const uint32_t *const a[9], uint32_t *dst, int m);
void gd_gauss_h_sse2(const uint32_t *v, uint32_t *dst, int i0, int i1);
#if defined(BLOOM_SIMD_AVX2)
void gd_bright_avx2(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c);
void gd_gauss_v_avx2(const uint32_t *const a[9], uint32_t *dst, int m);
void gd_lut8_avx2(const uint8_t *s, const uint8_t *tab, uint8_t *d, int n);
void gd_gauss_h_avx2(const uint32_t *v, uint32_t *dst, int i0, int i1);
#endif
#endif
#if defined(BLOOM_SIMD_NEON) && !BLOOM_SMALL
void gd_bright_neon(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c);
void gd_gauss_v_neon(const uint32_t *const a[9], uint32_t *dst, int m);
void gd_gauss_h_neon(const uint32_t *v, uint32_t *dst, int i0, int i1);
void gd_lut8_neon(const uint8_t *s, const uint8_t *tab, uint8_t *d, int n);
#endif

#endif
#endif
