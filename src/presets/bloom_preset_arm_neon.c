/* NEON twins of the arm preset's row kernels (bloom_preset_arm.h;
 * aarch64). Same bits as the C kernels (bloom_preset_arm_kern.c), the same
 * arithmetic as the SSE2 twins (bloom_preset_arm_sse2.c: the up sums split
 * as 64 h + l, exact in 32-bit lanes; q / 3 by a 32 x 32 -> 64 multiply).
 * Empty on other targets. */
#include "bloom_preset_arm.h"

#if BLOOM_USE_ARM && defined(BLOOM_SIMD_NEON)
#include <arm_neon.h>

static inline uint32_t or_lanes(uint32x4_t v)
{
    const uint32x2_t t = vorr_u32(vget_low_u32(v), vget_high_u32(v));
    return vget_lane_u32(t, 0) | vget_lane_u32(t, 1);
}

static void down_v_neon(const uint32_t *s0, const uint32_t *s1, const uint32_t *s2, const uint32_t *s3,
                        uint32_t *c4, uint32_t *c2, int n)
{
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const uint32x4_t mid = vaddq_u32(vld1q_u32(s1 + i), vld1q_u32(s2 + i));
        vst1q_u32(c2 + i, mid);
        vst1q_u32(c4 + i, vaddq_u32(mid, vaddq_u32(vld1q_u32(s0 + i), vld1q_u32(s3 + i))));
    }
    if (i < n)
        bloom_arm_kern_c.down_v(s0 + i, s1 + i, s2 + i, s3 + i, c4 + i, c2 + i, n - i);
}

static uint32_t down_h_neon(const uint32_t *c4, const uint32_t *c2, uint32_t *dst, int n)
{
    const uint32x4_t k7 = vdupq_n_u32(7), k1 = vdupq_n_u32(1);
    uint32x4_t any = vdupq_n_u32(0);
    int x = 0;
    for (; x + 4 <= n; x += 4) { /* reads c4, c2 [2x .. 2x + 9] */
        const uint32x4x2_t a0 = vld2q_u32(c4 + 2 * x), a2 = vld2q_u32(c4 + 2 * x + 2);
        const uint32x4x2_t b0 = vld2q_u32(c2 + 2 * x), b2 = vld2q_u32(c2 + 2 * x + 2);
        const uint32x4_t s16 = vaddq_u32(vaddq_u32(a0.val[0], a0.val[1]), vaddq_u32(a2.val[0], a2.val[1]));
        const uint32x4_t cc = vaddq_u32(b0.val[1], b2.val[0]);
        const uint32x4_t y = vaddq_u32(vshrq_n_u32(s16, 1), vshlq_n_u32(cc, 1));
        const uint32x4_t t = vandq_u32(vorrq_u32(vshrq_n_u32(y, 4), s16), k1);
        const uint32x4_t d = vshrq_n_u32(vaddq_u32(vaddq_u32(y, k7), t), 4);
        vst1q_u32(dst + x, d);
        any = vorrq_u32(any, d);
    }
    uint32_t r = or_lanes(any);
    if (x < n)
        r |= bloom_arm_kern_c.down_h(c4 + 2 * x, c2 + 2 * x, dst + x, n - x);
    return r;
}

static void up_v_neon(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, uint32_t *a, uint32_t *v,
                      int n)
{
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const uint32x4_t p = vld1q_u32(u0 + i), m = vld1q_u32(u1 + i), q = vld1q_u32(u2 + i);
        vst1q_u32(a + i, vmlaq_n_u32(p, m, 3));
        vst1q_u32(v + i, vmlaq_n_u32(vmlaq_n_u32(q, m, 4), p, 3));
    }
    if (i < n)
        bloom_arm_kern_c.up_v(u0 + i, u1 + i, u2 + i, a + i, v + i, n - i);
}

/* floor(q / 3) per lane, q < 2^31: (q * 0xAAAAAAAB) >> 33. */
static inline uint32x4_t div3(uint32x4_t q)
{
    const uint32x2_t k = vdup_n_u32(0xAAAAAAABu);
    const uint64x2_t lo = vshrq_n_u64(vmull_u32(vget_low_u32(q), k), 33);
    const uint64x2_t hi = vshrq_n_u64(vmull_u32(vget_high_u32(q), k), 33);
    return vcombine_u32(vmovn_u64(lo), vmovn_u64(hi));
}

/* 11 x0 + 28 x1 + x2 + y0 + 3 y1 on 32-bit lanes (no wrap: arm.md). */
static inline uint32x4_t sum5(uint32x4_t x0, uint32x4_t x1, uint32x4_t x2, uint32x4_t y0, uint32x4_t y1)
{
    return vmlaq_n_u32(vmlaq_n_u32(vmlaq_n_u32(vaddq_u32(x2, y0), x0, 11), x1, 28), y1, 3);
}

static uint32_t up_h_neon(const uint32_t *a, const uint32_t *v, uint32_t *dst, int np)
{
    const uint32x4_t m63 = vdupq_n_u32(63), k96 = vdupq_n_u32(96);
    uint32x4_t any = vdupq_n_u32(0);
    int i = 0;
    for (; i + 4 <= np; i += 4) { /* reads a, v [i .. i + 5] */
        const uint32x4_t a0 = vld1q_u32(a + i), a1 = vld1q_u32(a + i + 1), a2 = vld1q_u32(a + i + 2);
        const uint32x4_t v0 = vld1q_u32(v + i), v1 = vld1q_u32(v + i + 1), v2 = vld1q_u32(v + i + 2);
        const uint32x4_t ah0 = vshrq_n_u32(a0, 6), ah1 = vshrq_n_u32(a1, 6), ah2 = vshrq_n_u32(a2, 6);
        const uint32x4_t vh0 = vshrq_n_u32(v0, 6), vh1 = vshrq_n_u32(v1, 6), vh2 = vshrq_n_u32(v2, 6);
        const uint32x4_t al0 = vandq_u32(a0, m63), al1 = vandq_u32(a1, m63), al2 = vandq_u32(a2, m63);
        const uint32x4_t vl0 = vandq_u32(v0, m63), vl1 = vandq_u32(v1, m63), vl2 = vandq_u32(v2, m63);
        const uint32x4_t qe = vaddq_u32(sum5(ah0, ah1, ah2, vh0, vh1),
                                        vshrq_n_u32(vaddq_u32(sum5(al0, al1, al2, vl0, vl1), k96), 6));
        const uint32x4_t qo = vaddq_u32(sum5(ah2, ah1, ah0, vh2, vh1),
                                        vshrq_n_u32(vaddq_u32(sum5(al2, al1, al0, vl2, vl1), k96), 6));
        uint32x4x2_t eo;
        eo.val[0] = div3(qe);
        eo.val[1] = div3(qo);
        vst2q_u32(dst + 2 * i, eo);
        any = vorrq_u32(any, vorrq_u32(eo.val[0], eo.val[1]));
    }
    uint32_t r = or_lanes(any);
    if (i < np)
        r |= bloom_arm_kern_c.up_h(a + i, v + i, dst + 2 * i, np - i);
    return r;
}

static uint32_t max3_neon(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, int n)
{
    if (n < 4)
        return bloom_arm_kern_c.max3(u0, u1, u2, n);
    uint32x4_t m = vdupq_n_u32(0);
    for (int i = 0;; i += 4) {
        if (i + 4 > n) /* the last 4 again */
            i = n - 4;
        m = vmaxq_u32(m, vmaxq_u32(vld1q_u32(u0 + i), vmaxq_u32(vld1q_u32(u1 + i), vld1q_u32(u2 + i))));
        if (i + 4 >= n)
            break;
    }
    return vmaxvq_u32(m);
}

static void lum8_neon(const uint8_t *p, uint32_t *c4, uint32_t *c2, int n, bool x4, int i)
{
    bloom_arm_kern_c.lum8(p, c4, c2, n, x4, i); /* the decode is table reads */
}

#if !BLOOM_SMALL
static void out8_neon(const uint8_t *src, const uint32_t *b, const uint32_t f[3], uint8_t *dst, int n,
                      bool x4)
{
    bloom_arm_kern_c.out8(src, b, f, dst, n, x4); /* the encode is table reads */
}
#endif

const bloom_arm_kern_t bloom_arm_kern_neon = {
    down_v_neon, down_h_neon, up_v_neon, up_h_neon, max3_neon, lum8_neon, BLOOM_ARM_OUT8(out8_neon), "neon"};

#else
typedef int bloom_preset_arm_neon_unused_t;
#endif
