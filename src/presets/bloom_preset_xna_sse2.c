/* SSE2 twins of the xna preset's kernels (bloom_preset_xna.h): the Kawase
 * sums with their rounding, and the screen combine as an addend. x86-64,
 * where SSE2 is baseline. Same bits as xna_kawase_c and xna_screen_c
 * (tests/test_simd_xna.c). Empty on other targets. */
#include "bloom_preset_xna.h"
#include "bloom_simd4.h"

#if BLOOM_USE_XNA && defined(BLOOM_SIMD_SSE2)

/* the Kawase sums: bloom_preset_xna_simd.h on 4 lanes */
#define VT __m128i
#define W 4
#define LDV LD4
#define STV ST4
#define ADDV _mm_add_epi32
#define RNDV bloom_box_rnd4
#define XNA_KAWASE xna_kawase_sse2
#include "bloom_preset_xna_simd.h"
#undef VT
#undef W
#undef LDV
#undef STV
#undef ADDV
#undef RNDV
#undef XNA_KAWASE

void xna_screen_sse2(const uint32_t *s, uint32_t *x, int n)
{
    const __m128i sign = _mm_set1_epi32((int)0x80000000u), one = _mm_set1_epi32((int)BLOOM_LIN_ONE);
    const __m128i c = _mm_set1_epi64x((long long)((BLOOM_LIN_ONE >> 1) - 1u));
    const __m128i lo = _mm_set1_epi64x(0xFFFFFFFFll);
    int j = 0;
    for (; j + 4 <= n; j += 4) {
        const __m128i v = LD4(x + j), sv = LD4(s + j);
        const __m128i gt = _mm_cmpgt_epi32(_mm_xor_si128(v, sign), _mm_xor_si128(one, sign));
        const __m128i b = _mm_or_si128(_mm_and_si128(gt, one), _mm_andnot_si128(gt, v)); /* min(v, ONE) */
        const __m128i pe = _mm_srli_epi64(_mm_add_epi64(_mm_mul_epu32(sv, b), c), BLOOM_LIN_BITS);
        const __m128i po = _mm_srli_epi64(
            _mm_add_epi64(_mm_mul_epu32(_mm_srli_epi64(sv, 32), _mm_srli_epi64(b, 32)), c), BLOOM_LIN_BITS);
        const __m128i p = _mm_or_si128(_mm_and_si128(pe, lo), _mm_slli_epi64(po, 32));
        ST4(x + j, _mm_sub_epi32(b, p));
    }
    if (j < n)
        xna_screen_c(s + j, x + j, n - j);
}

#else
typedef int bloom_preset_xna_sse2_unused_t;
#endif
