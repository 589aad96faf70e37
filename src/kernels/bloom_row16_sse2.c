/* SSE2 twins of the 16-bit row kernels (bloom_row16.c; x86-64, where SSE2
 * is baseline): the narrowing of D_1 and the vertical tent of 16-bit rows,
 * eight samples a step. Same bits as the C kernels (tests/test_s16.c holds
 * them equal on every rounding case); picked with the SSE2 or AVX2 kernel
 * set (bloom_row16_k). Empty on other targets. */
#include "bloom_kernels.h"

#if defined(BLOOM_SIMD_SSE2) && BLOOM_USE_S16
#include "bloom_simd4.h" /* bloom_or_lanes4 */

/* Four samples narrowed half to even: (v + h + ((v >> sh) & 1)) >> sh. */
static inline __m128i narrow4(__m128i v, __m128i h, __m128i one, __m128i cnt)
{
    const __m128i odd = _mm_and_si128(_mm_srl_epi32(v, cnt), one);
    return _mm_srl_epi32(_mm_add_epi32(_mm_add_epi32(v, h), odd), cnt);
}

uint32_t bloom_row_narrow16_sse2(const uint32_t *src, uint16_t *dst, int n, int sh)
{
    const __m128i h = _mm_set1_epi32((int)((1u << (sh - 1)) - 1u)), one = _mm_set1_epi32(1);
    const __m128i cnt = _mm_cvtsi32_si128(sh), bias = _mm_set1_epi32(32768), flip = _mm_set1_epi16(-32768);
    __m128i any = _mm_setzero_si128();
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m128i r0 = narrow4(_mm_loadu_si128((const __m128i *)(const void *)(src + i)), h, one, cnt);
        const __m128i r1 =
            narrow4(_mm_loadu_si128((const __m128i *)(const void *)(src + i + 4)), h, one, cnt);
        any = _mm_or_si128(any, _mm_or_si128(r0, r1));
        /* 0 .. 65535 to uint16: the signed pack of v - 32768, then the sign bit back */
        const __m128i p = _mm_packs_epi32(_mm_sub_epi32(r0, bias), _mm_sub_epi32(r1, bias));
        _mm_storeu_si128((__m128i *)(void *)(dst + i), _mm_xor_si128(p, flip));
    }
    uint32_t a = bloom_or_lanes4(any);
    if (i < n)
        a |= bloom_row_narrow16_c(src + i, dst + i, n - i, sh);
    return a;
}

uint32_t bloom_row_vtent16w_sse2(const uint16_t *a, const uint16_t *b, const uint16_t *c, uint32_t *dst,
                                 int n, int sh)
{
    const __m128i z = _mm_setzero_si128(), rnd = _mm_set1_epi32((int)BLOOM_VT_RND);
    const __m128i cnt = _mm_cvtsi32_si128(sh);
    __m128i any = z;
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m128i va = _mm_loadu_si128((const __m128i *)(const void *)(a + i));
        const __m128i vb = _mm_loadu_si128((const __m128i *)(const void *)(b + i));
        const __m128i vc = _mm_loadu_si128((const __m128i *)(const void *)(c + i));
        __m128i half[2][3] = {
            {_mm_unpacklo_epi16(va, z), _mm_unpacklo_epi16(vb, z), _mm_unpacklo_epi16(vc, z)},
            {_mm_unpackhi_epi16(va, z), _mm_unpackhi_epi16(vb, z), _mm_unpackhi_epi16(vc, z)}};
        for (int k = 0; k < 2; k++) {
            const __m128i *x = half[k];
            /* 3a + 4b + c < 2^19, << sh < 2^28 */
            __m128i s = _mm_add_epi32(_mm_add_epi32(x[0], _mm_slli_epi32(x[0], 1)),
                                      _mm_add_epi32(_mm_slli_epi32(x[1], 2), x[2]));
            s = _mm_srli_epi32(_mm_add_epi32(_mm_sll_epi32(s, cnt), rnd), 3);
            _mm_storeu_si128((__m128i *)(void *)(dst + i + 4 * k), s);
            any = _mm_or_si128(any, s);
        }
    }
    uint32_t r = bloom_or_lanes4(any);
    if (i < n)
        r |= bloom_row_vtent16w_c(a + i, b + i, c + i, dst + i, n - i, sh);
    return r;
}
#else
typedef int bloom_row16_sse2_empty_t; /* (no SSE2, or 16-bit samples compiled out) */
#endif
