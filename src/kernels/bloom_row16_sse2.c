/* SSE2 twins of the 16-bit row kernels (bloom_row16.c; x86-64, where SSE2
 * is baseline): the narrowing of D_1 and the vertical tent of 16-bit rows,
 * eight samples a step, and the box (into 16-bit or widened 32-bit
 * samples), a pixel pair a step. Same bits as the C kernels (tests/test_s16.c holds
 * them equal on every rounding case); picked with the SSE2 or AVX2 kernel
 * set (bloom_row16_k). Empty on other targets. */
#include "bloom_kernels.h"

#if defined(BLOOM_SIMD_SSE2) && BLOOM_USE_S16
#include "bloom_simd4.h" /* bloom_or_lanes4, bloom_box_rnd4 */

#include <string.h>

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

/* Four 16-bit samples at p in 32-bit lanes. */
static inline __m128i ld4x16(const uint16_t *p)
{
    return _mm_unpacklo_epi16(_mm_loadl_epi64((const __m128i *)(const void *)p), _mm_setzero_si128());
}

/* The column sum of the four rows at sample i, widened (lane 3: the next
 * sample): < 4 * 2^16, << sh (<= 9) < 2^27. */
static inline __m128i col16(const uint16_t *const s[4], size_t i, __m128i cnt)
{
    const __m128i c = _mm_add_epi32(_mm_add_epi32(ld4x16(s[0] + i), ld4x16(s[1] + i)),
                                    _mm_add_epi32(ld4x16(s[2] + i), ld4x16(s[3] + i)));
    return _mm_sll_epi32(c, cnt);
}

/* [e0 e1 e2 o0]: shufps moves the bits untouched (as bloom_row_sse2.c). */
static inline __m128i pack_lo(__m128i e, __m128i o)
{
    const __m128 ef = _mm_castsi128_ps(e);
    const __m128 t = _mm_shuffle_ps(ef, _mm_castsi128_ps(o), _MM_SHUFFLE(0, 0, 2, 2));
    return _mm_castps_si128(_mm_shuffle_ps(ef, t, _MM_SHUFFLE(2, 0, 1, 0)));
}

/* Both boxes (d16 or d32 is NULL) in pixel pairs from x = 1, as the 32-bit
 * box's SSE2 twin (bloom_row_simd.h, box_any: the same reads, one sample
 * past the pairs' columns); the edges and the tail in C. */
static void box16(const uint16_t *const s[4], uint16_t *d16, uint32_t *d32, int dw, int sw, int sh)
{
    void *dst = d16 ? (void *)d16 : (void *)d32;
    const int xa = 1;
    int np = 0;
    if (sw >= 8 && dw >= 3) {
        const int xlast = (sw - 6) / 2;
        np = (xlast - xa) / 2 + 1 < (dw - xa) / 2 ? (xlast - xa) / 2 + 1 : (dw - xa) / 2;
        np = np < 0 ? 0 : np;
    }
    if (np == 0) {
        bloom_row_box16_range_c(s, dst, !d16, 0, dw, sw, sh);
        return;
    }
    bloom_row_box16_range_c(s, dst, !d16, 0, xa, sw, sh);
    const __m128i cnt = _mm_cvtsi32_si128(d16 ? 0 : sh), bias = _mm_set1_epi32(32768);
    const __m128i flip = _mm_set1_epi16(-32768);
    size_t c = (size_t)(2 * xa - 1) * 3u, at = (size_t)xa * 3u;
    __m128i a = _mm_add_epi32(col16(s, c, cnt), col16(s, c + 3u, cnt)); /* columns 2x-1, 2x */
    for (int i = 0; i < np; i++, c += 12u, at += 6u) {
        const __m128i b = _mm_add_epi32(col16(s, c + 6u, cnt), col16(s, c + 9u, cnt));
        const __m128i e = bloom_box_rnd4(_mm_add_epi32(a, b));
        a = _mm_add_epi32(col16(s, c + 12u, cnt), col16(s, c + 15u, cnt));
        const __m128i o = bloom_box_rnd4(_mm_add_epi32(b, a));
        const __m128i lo = pack_lo(e, o), hi = _mm_srli_si128(o, 4); /* [e0 e1 e2 o0], [o1 o2 . .] */
        if (d16) { /* each at most 65535: the signed pack of v - 32768, the sign bit back */
            const __m128i p =
                _mm_xor_si128(_mm_packs_epi32(_mm_sub_epi32(lo, bias), _mm_sub_epi32(hi, bias)), flip);
            _mm_storel_epi64((__m128i *)(void *)(d16 + at), p);
            const uint32_t tail = (uint32_t)_mm_cvtsi128_si32(_mm_srli_si128(p, 8));
            memcpy(d16 + at + 4, &tail, sizeof tail);
        } else {
            _mm_storeu_si128((__m128i *)(void *)(d32 + at), lo);
            _mm_storel_epi64((__m128i *)(void *)(d32 + at + 4), hi);
        }
    }
    bloom_row_box16_range_c(s, dst, !d16, xa + 2 * np, dw, sw, sh);
}

void bloom_row_box16_sse2(const uint16_t *const s[4], uint16_t *dst, int dw, int sw)
{
    box16(s, dst, NULL, dw, sw, 0);
}

void bloom_row_box16w_sse2(const uint16_t *const s[4], uint32_t *dst, int dw, int sw, int sh)
{
    box16(s, NULL, dst, dw, sw, sh);
}
#else
typedef int bloom_row16_sse2_empty_t; /* (no SSE2, or 16-bit samples compiled out) */
#endif
