/* NEON twins (aarch64) of the gamedev preset's dark-block test and Gaussian
 * passes (bloom_preset_gamedev_k.h): bloom_preset_gamedev_simd.h on 4
 * lanes, with the 9-tap sum gauss4 below, bit-identical to gd_gauss_v_c and
 * gd_gauss_h_c: the pairs in 32-bit lanes (< 2^29), products and sums by
 * UMULL / UMLAL into 64-bit lanes, the result (sum + 2^23) >> 24 < 2^28
 * narrowed back (SHRN). The per-code table of rows without bloom by TBL and
 * TBX on four 64-byte quarters of the table. The tone curve stays C here:
 * NEON has no gather.
 * Empty on other targets. */
#include "bloom_preset_gamedev_k.h"

#if BLOOM_USE_GAMEDEV && defined(BLOOM_SIMD_NEON) && !BLOOM_SMALL
#include <arm_neon.h>

/* (W0 c + W1 p1 + W2 p2 + W3 p3 + W4 p4 + 2^23) >> 24 in two 32-bit lanes. */
static inline uint32x2_t gauss2(uint32x2_t c, uint32x2_t p1, uint32x2_t p2, uint32x2_t p3, uint32x2_t p4)
{
    uint64x2_t s = vmlal_n_u32(vdupq_n_u64(GHALF), c, GW0);
    s = vmlal_n_u32(s, p1, GW1);
    s = vmlal_n_u32(s, p2, GW2);
    s = vmlal_n_u32(s, p3, GW3);
    s = vmlal_n_u32(s, p4, GW4);
    return vshrn_n_u64(s, GQ);
}

static inline uint32x4_t gauss4(uint32x4_t c, uint32x4_t p1, uint32x4_t p2, uint32x4_t p3, uint32x4_t p4)
{
    return vcombine_u32(
        gauss2(vget_low_u32(c), vget_low_u32(p1), vget_low_u32(p2), vget_low_u32(p3), vget_low_u32(p4)),
        gauss2(vget_high_u32(c), vget_high_u32(p1), vget_high_u32(p2), vget_high_u32(p3), vget_high_u32(p4)));
}

/* gd_bright, gd_gauss_v, gd_gauss_h: bloom_preset_gamedev_simd.h on 4 lanes */
#define VT uint32x4_t
#define VB uint8x16_t
#define W 4
#define LDV vld1q_u32
#define STV vst1q_u32
#define LDB vld1q_u8
#define STB vst1q_u8
#define ADDV vaddq_u32
#define GAUSSV gauss4
#define DUPB vdupq_n_u8
#define MAXB vmaxq_u8
#define SUBSB vqsubq_u8
#define GD_FN(f) f##_neon
#include "bloom_preset_gamedev_simd.h"

void gd_lut8_neon(const uint8_t *s, const uint8_t *tab, uint8_t *d, int n)
{
    const uint8x16x4_t q0 = vld1q_u8_x4(tab), q1 = vld1q_u8_x4(tab + 64), q2 = vld1q_u8_x4(tab + 128),
                       q3 = vld1q_u8_x4(tab + 192);
    int i = 0;
    for (; i + 16 <= n; i += 16) {
        /* TBL gives 0 and TBX keeps the lane for an index past 63: code
         * c is found in quarter c >> 6 at c - 64 (c >> 6) */
        const uint8x16_t x = vld1q_u8(s + i);
        uint8x16_t r = vqtbl4q_u8(q0, x);
        r = vqtbx4q_u8(r, q1, vsubq_u8(x, vdupq_n_u8(64)));
        r = vqtbx4q_u8(r, q2, vsubq_u8(x, vdupq_n_u8(128)));
        r = vqtbx4q_u8(r, q3, vsubq_u8(x, vdupq_n_u8(192)));
        vst1q_u8(d + i, r);
    }
    if (i < n)
        gd_lut8_c(s + i, tab, d + i, n - i);
}

#else
typedef int bloom_preset_gamedev_neon_empty; /* ISO C wants a declaration in every file */
#endif
