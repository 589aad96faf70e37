/* SSE2 twins of the gamedev preset's dark-block test and Gaussian passes (bloom_preset_gamedev_k.h),
 * bit-identical to gd_gauss_v_c and gd_gauss_h_c: the pairs are added in
 * 32-bit lanes (< 2^29), the products and their sum in 64-bit lanes by
 * PMULUDQ (even lanes, then the odd ones shifted down), the result
 * (sum + 2^23) >> 24 < 2^28 put back in its 32-bit lane. Empty on other
 * targets. */
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

void gd_bright_sse2(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c)
{
    const __m128i cv = _mm_set1_epi8((char)(c > 255u ? 255u : c));
    int i = 0;
    for (; i + 16 <= n; i += 16) {
        const __m128i m = _mm_max_epu8(_mm_max_epu8(LD4(s[0] + i), LD4(s[1] + i)),
                                       _mm_max_epu8(LD4(s[2] + i), LD4(s[3] + i)));
        ST4(b + i, _mm_subs_epu8(m, cv));
    }
    if (i < n) {
        const uint8_t *const t[4] = {s[0] + i, s[1] + i, s[2] + i, s[3] + i};
        gd_bright_c(t, b + i, n - i, c);
    }
}

void gd_gauss_v_sse2(const uint32_t *const a[9], uint32_t *dst, int m)
{
    const uint32_t *a0 = a[0], *a1 = a[1], *a2 = a[2], *a3 = a[3], *a4 = a[4], *a5 = a[5], *a6 = a[6],
                   *a7 = a[7], *a8 = a[8];
    int i = 0;
    for (; i + 4 <= m; i += 4)
        ST4(dst + i, gauss4(LD4(a4 + i), _mm_add_epi32(LD4(a3 + i), LD4(a5 + i)),
                            _mm_add_epi32(LD4(a2 + i), LD4(a6 + i)), _mm_add_epi32(LD4(a1 + i), LD4(a7 + i)),
                            _mm_add_epi32(LD4(a0 + i), LD4(a8 + i))));
    if (i < m) {
        const uint32_t *const t[9] = {a0 + i, a1 + i, a2 + i, a3 + i, a4 + i, a5 + i, a6 + i, a7 + i, a8 + i};
        gd_gauss_v_c(t, dst + i, m - i);
    }
}

void gd_gauss_h_sse2(const uint32_t *v, uint32_t *dst, int i0, int i1)
{
    int i = i0;
    for (; i + 4 <= i1; i += 4) {
        const uint32_t *p = v + i;
        ST4(dst + i,
            gauss4(LD4(p), _mm_add_epi32(LD4(p - 3), LD4(p + 3)), _mm_add_epi32(LD4(p - 6), LD4(p + 6)),
                   _mm_add_epi32(LD4(p - 9), LD4(p + 9)), _mm_add_epi32(LD4(p - 12), LD4(p + 12))));
    }
    if (i < i1)
        gd_gauss_h_c(v, dst, i, i1);
}

#else
typedef int bloom_preset_gamedev_sse2_empty; /* ISO C wants a declaration in every file */
#endif
