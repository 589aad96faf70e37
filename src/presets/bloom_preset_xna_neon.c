/* NEON twins of the xna preset's kernels (bloom_preset_xna.h), aarch64
 * only. Same bits as xna_kawase_c and xna_screen_c (tests/test_simd_xna.c
 * under aarch64 emulation). Empty on other targets. */
#include "bloom_preset_xna.h"
#include "bloom_simd4.h"

#if BLOOM_USE_XNA && defined(BLOOM_SIMD_NEON)

/* the Kawase sums: bloom_preset_xna_simd.h on 4 lanes */
#define VT uint32x4_t
#define W 4
#define LDV vld1q_u32
#define STV vst1q_u32
#define ADDV vaddq_u32
#define RNDV bloom_box_rnd4
#define XNA_KAWASE xna_kawase_neon
#include "bloom_preset_xna_simd.h"
#undef VT
#undef W
#undef LDV
#undef STV
#undef ADDV
#undef RNDV
#undef XNA_KAWASE

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
