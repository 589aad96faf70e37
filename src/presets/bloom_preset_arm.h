/* The arm preset's own row kernels (bloom_preset_arm_kern.c) and their SIMD
 * twins (bloom_preset_arm_sse2.c, _avx2.c, _neon.c; the ones that differ
 * only in lane width written once, bloom_preset_arm_simd.h), bit-identical
 * to the C ones (tests/test_simd_arm.c), picked by the engine's
 * instruction set (ctx->kern.isa). One-channel rows of Q12.20 samples
 * <= M = 2^28 - 16 (sim/docs/presets/arm.md, overflow). */
#ifndef BLOOM_PRESET_ARM_H
#define BLOOM_PRESET_ARM_H

#include "bloom_kernels.h"

#include <stddef.h>

typedef struct {
    /* Vertical half of the down filter: c2[i] = s1[i] + s2[i],
     * c4[i] = c2[i] + s0[i] + s3[i], i < n. */
    void (*down_v)(const uint32_t *s0, const uint32_t *s1, const uint32_t *s2, const uint32_t *s3,
                   uint32_t *c4, uint32_t *c2, int n);
    /* Horizontal half: dst[i] = (S16 + 4 C4) / 32 rounded half to even,
     * S16 = c4[2i] + .. + c4[2i+3], C4 = c2[2i+1] + c2[2i+2], i < n (reads
     * c4, c2 [0 .. 2n+1]). Returns the OR of dst[0 .. n-1]. */
    uint32_t (*down_h)(const uint32_t *c4, const uint32_t *c2, uint32_t *dst, int n);
    /* Vertical half of the up filter: a[i] = u0[i] + 3 u1[i],
     * v[i] = 3 u0[i] + 4 u1[i] + u2[i], i < n (u0 the row on the output
     * row's side). */
    void (*up_v)(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, uint32_t *a, uint32_t *v, int n);
    /* Horizontal half, np output pairs: dst[2i] = floor((S_e + 96) / 192),
     * S_e = 11 a[i] + 28 a[i+1] + a[i+2] + v[i] + 3 v[i+1], and dst[2i+1]
     * the mirror (reads a, v [0 .. np+1]). Returns the OR of dst[0 .. 2np-1]. */
    uint32_t (*up_h)(const uint32_t *a, const uint32_t *v, uint32_t *dst, int np);
    /* The largest of u0[i], u1[i], u2[i], i < n (0 when n < 1). */
    uint32_t (*max3)(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, int n);
    /* Luminance of n 8-bit sRGB pixels at p (RGB888, or XRGB8888 B G R X
     * with x4): Y = (WR R + WG G + WB B + 2^23) >> 24 of the decoded
     * samples (BLOOM_ARM_W*), summed into the column sums as source row i
     * of 4: i = 0: c4 = Y; 1: c4 += Y, c2 = Y; 2: c4 += Y, c2 += Y;
     * 3: c4 += Y (index x of p is index x of c4, c2). */
    void (*lum8)(const uint8_t *p, uint32_t *c4, uint32_t *c2, int n, bool x4, int i);
    /* 8-bit sRGB in and out of one format (RGB888, or XRGB8888 with x4, X
     * written 0xFF), n pixels: per sample of code c, P = min((f_c B + 2^15)
     * >> 16, 2^24) (f_c < 2^32: channels R, G, B; B = b[x]) and the code
     * enc(dec(c) + P) of the fast output path (BLOOM_FENC8: the codes of
     * bloom_encode_row). src may be dst. NULL in BLOOM_SMALL builds. */
    void (*out8)(const uint8_t *src, const uint32_t *b, const uint32_t f[3], uint8_t *dst, int n, bool x4);
    const char *name;
} bloom_arm_kern_t;

#if BLOOM_SMALL
#define BLOOM_ARM_OUT8(f) NULL
#else
#define BLOOM_ARM_OUT8(f) f
#endif

/* Rec.709 luminance weights, Q24: each the nearest integer to 2^24 times
 * the real weight (3566836.1, 11999064.9, 1211315.0), and they sum to 2^24
 * (grey stays grey). Q16 weights were off by up to 5.3e-6 of a sample,
 * which an intensity of 224 made tens of RGBQ16 LSB, one-sided. */
#define BLOOM_ARM_WR 3566836u
#define BLOOM_ARM_WG 11999065u
#define BLOOM_ARM_WB 1211315u

extern const bloom_arm_kern_t bloom_arm_kern_c;
#if defined(BLOOM_SIMD_SSE2)
extern const bloom_arm_kern_t bloom_arm_kern_sse2;
#endif
#if defined(BLOOM_SIMD_AVX2)
extern const bloom_arm_kern_t bloom_arm_kern_avx2;
#endif
#if defined(BLOOM_SIMD_NEON)
extern const bloom_arm_kern_t bloom_arm_kern_neon;
#endif
/* The set for an engine's instruction set (the C one for BLOOM_ISA_C). */
const bloom_arm_kern_t *bloom_arm_kern(bloom_isa_t isa);

#if BLOOM_USE_S16
/* 16-bit samples (arm.md, "16-bit samples"): on 8/6/5-bit input every
 * plane value below the source is at most the knee's peak P (the filters
 * average; the mask only lowers Y), held as v / 2^G in a uint16_t with
 * P 2^G < 2^16 (bloom_s16_frac(1, P): 15 at threshold 0, 18 at the
 * default's 1.0). The vertical halves of the filters and the maximum on
 * such rows (bloom_preset_arm_kern.c): down_v and max3 as above, up_v with
 * its sums << sh. */
void bloom_arm_down_v16(const uint16_t *s0, const uint16_t *s1, const uint16_t *s2, const uint16_t *s3,
                        uint32_t *c4, uint32_t *c2, int n);
void bloom_arm_up_v16(const uint16_t *u0, const uint16_t *u1, const uint16_t *u2, uint32_t *a, uint32_t *v,
                      int n, int sh);
uint32_t bloom_arm_max3_16(const uint16_t *u0, const uint16_t *u1, const uint16_t *u2, int n);
#endif

/* One output of the up filter from the five sums (q < 2^30 + 45). */
static inline uint32_t bloom_arm_div192(uint64_t s)
{
    const uint32_t q = (uint32_t)((s + 96u) >> 6);
    return (uint32_t)(((uint64_t)q * 0xAAAAAAABu) >> 33);
}

#endif
