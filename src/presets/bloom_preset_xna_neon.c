/* NEON twins of the xna preset's kernels (bloom_preset_xna.h), aarch64
 * only. Same bits as xna_kawase_c and xna_screen_c (tests/test_simd_xna.c
 * under aarch64 emulation). Empty on other targets. */
#include "bloom_preset_xna.h"

#if BLOOM_USE_XNA && defined(BLOOM_SIMD_NEON)
#include <arm_neon.h>

static inline uint32x4_t box_rnd4(uint32x4_t s)
{
    const uint32x4_t odd = vandq_u32(vshrq_n_u32(s, 4), vdupq_n_u32(1));
    return vshrq_n_u32(vaddq_u32(vaddq_u32(s, vdupq_n_u32(7)), odd), 4);
}

void xna_kawase_neon(const uint32_t *const r[4], uint32_t *cs, uint32_t *dst, int w, int i, bool rnd)
{
    const int cnt = 3 * w;
    const uint32_t *r0 = r[0], *r1 = r[1], *r2 = r[2], *r3 = r[3];
    int j = 0;
    for (; j + 4 <= cnt; j += 4)
        vst1q_u32(cs + j, vaddq_u32(vaddq_u32(vld1q_u32(r0 + j), vld1q_u32(r1 + j)),
                                    vaddq_u32(vld1q_u32(r2 + j), vld1q_u32(r3 + j))));
    for (; j < cnt; j++)
        cs[j] = r0[j] + r1[j] + r2[j] + r3[j];
    int xa, xb;
    xna_kawase_edges(cs, dst, w, i, &xa, &xb);
    if (rnd)
        xna_round_edges(dst, w, xa, xb);
    const int o1 = 3 * i + 3, o2 = 3 * i, end = 3 * xb;
    for (j = 3 * xa; j + 4 <= end; j += 4) {
        const uint32x4_t s = vaddq_u32(vaddq_u32(vld1q_u32(cs + j - o1), vld1q_u32(cs + j - o2)),
                                       vaddq_u32(vld1q_u32(cs + j + o2), vld1q_u32(cs + j + o1)));
        vst1q_u32(dst + j, rnd ? box_rnd4(s) : s);
    }
    for (; j < end; j++) {
        const uint32_t s = cs[j - o1] + cs[j - o2] + cs[j + o2] + cs[j + o1];
        dst[j] = rnd ? BLOOM_BOX_RND(s) : s;
    }
}

void xna_screen_neon(const uint32_t *s, uint32_t *x, int n)
{
    const uint32x4_t one = vdupq_n_u32(BLOOM_LIN_ONE);
    const uint64x2_t c = vdupq_n_u64((BLOOM_LIN_ONE >> 1) - 1u);
    int j = 0;
    for (; j + 4 <= n; j += 4) {
        const uint32x4_t sv = vld1q_u32(s + j), b = vminq_u32(vld1q_u32(x + j), one);
        const uint64x2_t pl = vaddq_u64(vmull_u32(vget_low_u32(sv), vget_low_u32(b)), c);
        const uint64x2_t ph = vaddq_u64(vmull_high_u32(sv, b), c);
        /* vshrn keeps the low 32 bits of each shifted product */
        const uint32x4_t p = vcombine_u32(vshrn_n_u64(pl, BLOOM_LIN_BITS), vshrn_n_u64(ph, BLOOM_LIN_BITS));
        vst1q_u32(x + j, vsubq_u32(b, p));
    }
    if (j < n)
        xna_screen_c(s + j, x + j, n - j);
}

#else
typedef int bloom_preset_xna_neon_unused_t;
#endif
