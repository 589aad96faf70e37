/* The xna preset's own row kernels (bloom_preset_xna.c) and their SSE2,
 * AVX2 and NEON twins (bloom_preset_xna_sse2.c, _avx2.c, _neon.c), the
 * same bits; the preset picks them by ctx->kern.isa. */
#ifndef BLOOM_PRESET_XNA_H
#define BLOOM_PRESET_XNA_H

#include "bloom_kernels.h"

/* The sums of a Kawase pass at offset i on rows of w pixels (3 w samples):
 * cs[j] = r[0][j] + r[1][j] + r[2][j] + r[3][j], then for every pixel x
 * and channel c dst[3x+c] = the column sums at x-i-1, x-i, x+i, x+i+1
 * (clamped to 0 .. w-1) added; with rnd, dst = BLOOM_BOX_RND(dst) (the
 * sum / 16, half to even). Wrapping 32-bit arithmetic (no wrap happens for
 * samples <= LIN_MAX: sums <= 16 LIN_MAX < 2^32 - 8). */
typedef void (*xna_kawase_fn)(const uint32_t *const r[4], uint32_t *cs, uint32_t *dst, int w, int i,
                              bool rnd);
/* The screen combine as an addend, n samples: b = min(x[j], ONE),
 * x[j] = b - (low 32 bits of (s[j] b + ONE/2 - 1) >> F), in 32 bits. With
 * s <= ONE it is exact: s + x = b + ((s (ONE - b) + ONE/2) >> F). */
typedef void (*xna_screen_fn)(const uint32_t *s, uint32_t *x, int n);

void xna_kawase_c(const uint32_t *const r[4], uint32_t *cs, uint32_t *dst, int w, int i, bool rnd);
void xna_screen_c(const uint32_t *s, uint32_t *x, int n);
#if defined(BLOOM_SIMD_SSE2)
void xna_kawase_sse2(const uint32_t *const r[4], uint32_t *cs, uint32_t *dst, int w, int i, bool rnd);
void xna_screen_sse2(const uint32_t *s, uint32_t *x, int n);
#endif
#if defined(BLOOM_SIMD_AVX2)
void xna_kawase_avx2(const uint32_t *const r[4], uint32_t *cs, uint32_t *dst, int w, int i, bool rnd);
void xna_screen_avx2(const uint32_t *s, uint32_t *x, int n);
#endif
#if defined(BLOOM_SIMD_NEON)
void xna_kawase_neon(const uint32_t *const r[4], uint32_t *cs, uint32_t *dst, int w, int i, bool rnd);
void xna_screen_neon(const uint32_t *s, uint32_t *x, int n);
#endif

/* The edge columns of a Kawase pass (shared by every twin): the columns
 * 0 .. xa-1 and xb .. w-1 whose taps clamp, summed from cs into dst (not
 * rounded); xa .. xb-1 need no clamping (x-i-1 >= 0, x+i+1 <= w-1). */
static inline void xna_kawase_col(const uint32_t *cs, uint32_t *dst, int w, int i, int x)
{
    const int a = x - i - 1 < 0 ? 0 : x - i - 1, b = x - i < 0 ? 0 : x - i;
    const int c = x + i > w - 1 ? w - 1 : x + i, d = x + i + 1 > w - 1 ? w - 1 : x + i + 1;
    for (int ch = 0; ch < 3; ch++)
        dst[3 * x + ch] = cs[3 * a + ch] + cs[3 * b + ch] + cs[3 * c + ch] + cs[3 * d + ch];
}
static inline void xna_kawase_edges(const uint32_t *cs, uint32_t *dst, int w, int i, int *xa, int *xb)
{
    *xa = i + 1 < w ? i + 1 : w;
    *xb = w - i - 1 > *xa ? w - i - 1 : *xa;
    for (int x = 0; x < *xa; x++)
        xna_kawase_col(cs, dst, w, i, x);
    for (int x = *xb; x < w; x++)
        xna_kawase_col(cs, dst, w, i, x);
}
/* BLOOM_BOX_RND on the edge columns (the interior is the twins' own). */
static inline void xna_round_edges(uint32_t *dst, int w, int xa, int xb)
{
    for (int j = 0; j < 3 * xa; j++)
        dst[j] = BLOOM_BOX_RND(dst[j]);
    for (int j = 3 * xb; j < 3 * w; j++)
        dst[j] = BLOOM_BOX_RND(dst[j]);
}

/* The pair for an instruction set (the C pair for BLOOM_ISA_C or one this
 * build lacks). */
void xna_kernels(bloom_isa_t isa, xna_kawase_fn *kawase, xna_screen_fn *screen);

#endif
