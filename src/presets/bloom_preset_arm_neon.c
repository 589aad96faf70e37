/* NEON twins of the arm preset's row kernels (bloom_preset_arm.h;
 * aarch64): bloom_preset_arm_simd.h on 4 lanes, with the operations below.
 * Same bits as the C kernels (bloom_preset_arm_kern.c; the template says
 * why): q / 3 by a 32 x 32 -> 64 multiply (UMULL), the multiply-adds by
 * MLA, the deinterleave and interleave of the horizontal halves by LD2 and
 * ST2. The 8-bit luminance and output stay C (table reads).
 * Empty on other targets. */
#include "bloom_preset_arm.h"

#if BLOOM_USE_ARM && defined(BLOOM_SIMD_NEON)
#include "bloom_simd4.h" /* bloom_or_lanes4 (and arm_neon.h) */

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

/* e0 o0 e1 o1 .. e3 o3 at p */
static inline void st2(uint32_t *p, uint32x4_t e, uint32x4_t o)
{
    uint32x4x2_t eo;
    eo.val[0] = e;
    eo.val[1] = o;
    vst2q_u32(p, eo);
}

/* down_v, down_h, up_v, up_h, max3: bloom_preset_arm_simd.h on 4 lanes */
#define VT uint32x4_t
#define W 4
#define LDV vld1q_u32
#define STV vst1q_u32
#define ADDV vaddq_u32
#define ANDV vandq_u32
#define ORV vorrq_u32
#define SHLV vshlq_n_u32
#define SHRV vshrq_n_u32
#define DUPV vdupq_n_u32
#define MLAV vmlaq_n_u32
#define SUM5 sum5
#define DIV3 div3
#define MAXV vmaxq_u32
#define MAX_LANES vmaxvq_u32
#define OR_LANES bloom_or_lanes4
#define ST2V st2
#define VT2 uint32x4x2_t
#define LD2V vld2q_u32
#define ARM_TAIL bloom_arm_kern_c
#define ARM_FN(f) f##_neon
#include "bloom_preset_arm_simd.h"

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
