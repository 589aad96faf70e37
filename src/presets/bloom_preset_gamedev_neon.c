/* NEON twins (aarch64) of the gamedev preset's dark-block test and Gaussian passes
 * (bloom_preset_gamedev_k.h), bit-identical to gd_gauss_v_c and
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

void gd_bright_neon(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c)
{
    const uint8x16_t cv = vdupq_n_u8((uint8_t)(c > 255u ? 255u : c));
    int i = 0;
    for (; i + 16 <= n; i += 16) {
        const uint8x16_t m = vmaxq_u8(vmaxq_u8(vld1q_u8(s[0] + i), vld1q_u8(s[1] + i)),
                                      vmaxq_u8(vld1q_u8(s[2] + i), vld1q_u8(s[3] + i)));
        vst1q_u8(b + i, vqsubq_u8(m, cv));
    }
    if (i < n) {
        const uint8_t *const t[4] = {s[0] + i, s[1] + i, s[2] + i, s[3] + i};
        gd_bright_c(t, b + i, n - i, c);
    }
}

void gd_gauss_v_neon(const uint32_t *const a[9], uint32_t *dst, int m)
{
    const uint32_t *a0 = a[0], *a1 = a[1], *a2 = a[2], *a3 = a[3], *a4 = a[4], *a5 = a[5], *a6 = a[6],
                   *a7 = a[7], *a8 = a[8];
    int i = 0;
    for (; i + 4 <= m; i += 4)
        vst1q_u32(dst + i, gauss4(vld1q_u32(a4 + i), vaddq_u32(vld1q_u32(a3 + i), vld1q_u32(a5 + i)),
                                  vaddq_u32(vld1q_u32(a2 + i), vld1q_u32(a6 + i)),
                                  vaddq_u32(vld1q_u32(a1 + i), vld1q_u32(a7 + i)),
                                  vaddq_u32(vld1q_u32(a0 + i), vld1q_u32(a8 + i))));
    if (i < m) {
        const uint32_t *const t[9] = {a0 + i, a1 + i, a2 + i, a3 + i, a4 + i, a5 + i, a6 + i, a7 + i, a8 + i};
        gd_gauss_v_c(t, dst + i, m - i);
    }
}

void gd_gauss_h_neon(const uint32_t *v, uint32_t *dst, int i0, int i1)
{
    int i = i0;
    for (; i + 4 <= i1; i += 4) {
        const uint32_t *p = v + i;
        vst1q_u32(dst + i, gauss4(vld1q_u32(p), vaddq_u32(vld1q_u32(p - 3), vld1q_u32(p + 3)),
                                  vaddq_u32(vld1q_u32(p - 6), vld1q_u32(p + 6)),
                                  vaddq_u32(vld1q_u32(p - 9), vld1q_u32(p + 9)),
                                  vaddq_u32(vld1q_u32(p - 12), vld1q_u32(p + 12))));
    }
    if (i < i1)
        gd_gauss_h_c(v, dst, i, i1);
}

void gd_lut8_neon(const uint8_t *s, const uint32_t *tab, uint8_t *d, int n)
{
    uint8_t b[256];
    if (!gd_lut_bytes(s, tab, d, n, b))
        return;
    const uint8x16x4_t q0 = vld1q_u8_x4(b), q1 = vld1q_u8_x4(b + 64), q2 = vld1q_u8_x4(b + 128),
                       q3 = vld1q_u8_x4(b + 192);
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
