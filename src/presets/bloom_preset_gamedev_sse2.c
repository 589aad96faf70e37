/* SSE2 twins of the gamedev preset's dark-block test and Gaussian passes
 * (bloom_preset_gamedev_k.h): bloom_preset_gamedev_simd.h on 4 lanes, with
 * the 9-tap sum gauss4 below, bit-identical to gd_gauss_v_c and
 * gd_gauss_h_c: the pairs are added in 32-bit lanes (< 2^29), the products
 * and their sum in 64-bit lanes by PMULUDQ (even lanes, then the odd ones
 * shifted down), the result (sum + 2^23) >> 24 < 2^28 put back in its
 * 32-bit lane. Empty on other targets. */
#include "bloom_preset_gamedev_k.h"
#include "bloom_simd4.h"

#if BLOOM_USE_GAMEDEV && defined(BLOOM_SIMD_SSE2) && !BLOOM_SMALL
#include <emmintrin.h>

/* (W0 c + W1 p1 + W2 p2 + W3 p3 + W4 p4 + 2^23) >> 24 in four 32-bit lanes. */
static inline __m128i gauss4(__m128i c, __m128i p1, __m128i p2, __m128i p3, __m128i p4)
{
    const __m128i w0 = _mm_set1_epi32((int)GW0), w1 = _mm_set1_epi32((int)GW1), w2 = _mm_set1_epi32((int)GW2),
                  w3 = _mm_set1_epi32((int)GW3), w4 = _mm_set1_epi32((int)GW4);
    const __m128i half = _mm_set1_epi64x(GHALF);
    __m128i e = _mm_add_epi64(_mm_mul_epu32(c, w0), half);
    e = _mm_add_epi64(e, _mm_mul_epu32(p1, w1));
    e = _mm_add_epi64(e, _mm_mul_epu32(p2, w2));
    e = _mm_add_epi64(e, _mm_mul_epu32(p3, w3));
    e = _mm_add_epi64(e, _mm_mul_epu32(p4, w4));
    __m128i o = _mm_add_epi64(_mm_mul_epu32(_mm_srli_epi64(c, 32), w0), half);
    o = _mm_add_epi64(o, _mm_mul_epu32(_mm_srli_epi64(p1, 32), w1));
    o = _mm_add_epi64(o, _mm_mul_epu32(_mm_srli_epi64(p2, 32), w2));
    o = _mm_add_epi64(o, _mm_mul_epu32(_mm_srli_epi64(p3, 32), w3));
    o = _mm_add_epi64(o, _mm_mul_epu32(_mm_srli_epi64(p4, 32), w4));
    /* even: the low half of sum >> 24; odd: the low half of sum >> 24 put
     * in the high half, (sum << 8) with the low half cleared (the uint32_t
     * of the C kernel, also for sums past 2^56) */
    const __m128i hi = _mm_set1_epi64x((long long)0xFFFFFFFF00000000ull);
    return _mm_or_si128(_mm_andnot_si128(hi, _mm_srli_epi64(e, GQ)),
                        _mm_and_si128(_mm_slli_epi64(o, 32 - GQ), hi));
}

/* gd_bright, gd_gauss_v, gd_gauss_h: bloom_preset_gamedev_simd.h on 4 lanes */
#define VT __m128i
#define VB __m128i
#define W 4
#define LDV LD4
#define STV ST4
#define LDB LD4
#define STB ST4
#define ADDV _mm_add_epi32
#define GAUSSV gauss4
#define DUPB(c) _mm_set1_epi8((char)(c))
#define MAXB _mm_max_epu8
#define SUBSB _mm_subs_epu8
#define GD_FN(f) f##_sse2
#include "bloom_preset_gamedev_simd.h"

#else
typedef int bloom_preset_gamedev_sse2_empty; /* ISO C wants a declaration in every file */
#endif
