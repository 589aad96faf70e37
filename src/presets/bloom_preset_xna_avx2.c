/* AVX2 twins of the xna preset's kernels (bloom_preset_xna.h), compiled
 * for AVX2 by a target pragma (the rest of the core stays baseline
 * x86-64), picked when the engine's kernel set is AVX2 (ctx->kern.isa:
 * bloom_cpu_avx2, not BLOOM_FLAG_NO_AVX2 or NO_SIMD). Same bits as
 * xna_kawase_c and xna_screen_c (tests/test_simd_xna.c). */
#include "bloom_preset_xna.h"

#if BLOOM_USE_XNA && defined(BLOOM_SIMD_AVX2)

#include "bloom_avx2.h" /* from here on compiled for AVX2 */

/* the Kawase sums: bloom_preset_xna_simd.h on 8 lanes */
#define VT __m256i
#define W 8
#define LDV LD8
#define STV ST8
#define ADDV _mm256_add_epi32
#define RNDV bloom_box_rnd8
#define XNA_KAWASE xna_kawase_avx2
#include "bloom_preset_xna_simd.h"
#undef VT
#undef W
#undef LDV
#undef STV
#undef ADDV
#undef RNDV
#undef XNA_KAWASE

void xna_screen_avx2(const uint32_t *s, uint32_t *x, int n)
{
    const __m256i one = _mm256_set1_epi32((int)BLOOM_LIN_ONE);
    const __m256i c = _mm256_set1_epi64x((long long)((BLOOM_LIN_ONE >> 1) - 1u));
    int j = 0;
    for (; j + 8 <= n; j += 8) {
        const __m256i sv = LD8(s + j), b = _mm256_min_epu32(LD8(x + j), one);
        const __m256i pe = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(sv, b), c), BLOOM_LIN_BITS);
        const __m256i po = _mm256_srli_epi64(
            _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(sv, 32), _mm256_srli_epi64(b, 32)), c),
            BLOOM_LIN_BITS);
        const __m256i p = _mm256_blend_epi32(pe, _mm256_slli_epi64(po, 32), 0xAA);
        ST8(x + j, _mm256_sub_epi32(b, p));
    }
    if (j < n)
        xna_screen_c(s + j, x + j, n - j);
}

#include "bloom_avx2_end.h"

#else
typedef int bloom_preset_xna_avx2_unused_t;
#endif
