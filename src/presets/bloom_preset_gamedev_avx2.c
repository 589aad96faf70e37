/* AVX2 twins of the gamedev preset's kernels (bloom_preset_gamedev_k.h),
 * bit-identical to the C ones, used when the engine picked its AVX2 set
 * (bloom_cpu_avx2 at bloom_init). Every function after the target pragma is
 * compiled for AVX2; the rest of the core stays baseline x86-64.
 *
 *   bright            the dark-block test: the 4 rows' byte maximum minus
 *                     the dark code, saturated (VPMAXUB, VPSUBUSB)
 *   gauss_v, gauss_h  the 9-tap passes of gd_gauss_*_c on 8 lanes: pairs in
 *                     32-bit lanes, products and sums in 64-bit lanes
 *                     (VPMULUDQ, even lanes and odd lanes shifted down)
 *   tone8             the 8-bit tone curve: composite in 64-bit lanes,
 *                     the bucket key by an exact int-to-float conversion,
 *                     the bucket and the two threshold compares by gathers
 *   lut8              rows without bloom: a byte row through the per-code
 *                     table by gathers
 *
 * Empty on other targets. */
#include "bloom_preset_gamedev_k.h"

#if BLOOM_USE_GAMEDEV && defined(BLOOM_SIMD_AVX2) && !BLOOM_SMALL
#include <immintrin.h>

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

#define LD8(p) _mm256_loadu_si256((const __m256i *)(const void *)(p))
#define ST8(p, v) _mm256_storeu_si256((__m256i *)(void *)(p), (v))

/* (W0 c + W1 p1 + W2 p2 + W3 p3 + W4 p4 + 2^23) >> 24 in eight 32-bit lanes
 * (the SSE2 twin's gauss4 on 8 lanes). */
static inline __m256i gauss8(__m256i c, __m256i p1, __m256i p2, __m256i p3, __m256i p4)
{
    const __m256i w0 = _mm256_set1_epi32((int)GW0), w1 = _mm256_set1_epi32((int)GW1),
                  w2 = _mm256_set1_epi32((int)GW2), w3 = _mm256_set1_epi32((int)GW3),
                  w4 = _mm256_set1_epi32((int)GW4);
    const __m256i half = _mm256_set1_epi64x(GHALF);
    __m256i e = _mm256_add_epi64(_mm256_mul_epu32(c, w0), half);
    e = _mm256_add_epi64(e, _mm256_mul_epu32(p1, w1));
    e = _mm256_add_epi64(e, _mm256_mul_epu32(p2, w2));
    e = _mm256_add_epi64(e, _mm256_mul_epu32(p3, w3));
    e = _mm256_add_epi64(e, _mm256_mul_epu32(p4, w4));
    __m256i o = _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(c, 32), w0), half);
    o = _mm256_add_epi64(o, _mm256_mul_epu32(_mm256_srli_epi64(p1, 32), w1));
    o = _mm256_add_epi64(o, _mm256_mul_epu32(_mm256_srli_epi64(p2, 32), w2));
    o = _mm256_add_epi64(o, _mm256_mul_epu32(_mm256_srli_epi64(p3, 32), w3));
    o = _mm256_add_epi64(o, _mm256_mul_epu32(_mm256_srli_epi64(p4, 32), w4));
    /* even lanes: sum >> 24; odd lanes: (sum >> 24) << 32 = sum << 8 with
     * the low half dropped by the blend (sum < 2^52) */
    return _mm256_blend_epi32(_mm256_srli_epi64(e, GQ), _mm256_slli_epi64(o, 32 - GQ), 0xAA);
}

void gd_bright_avx2(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c)
{
    const __m256i cv = _mm256_set1_epi8((char)(c > 255u ? 255u : c));
    int i = 0;
    for (; i + 32 <= n; i += 32) {
        const __m256i m = _mm256_max_epu8(_mm256_max_epu8(LD8(s[0] + i), LD8(s[1] + i)),
                                          _mm256_max_epu8(LD8(s[2] + i), LD8(s[3] + i)));
        ST8(b + i, _mm256_subs_epu8(m, cv));
    }
    if (i < n) {
        const uint8_t *const t[4] = {s[0] + i, s[1] + i, s[2] + i, s[3] + i};
        gd_bright_c(t, b + i, n - i, c);
    }
}

void gd_gauss_v_avx2(const uint32_t *const a[9], uint32_t *dst, int m)
{
    const uint32_t *a0 = a[0], *a1 = a[1], *a2 = a[2], *a3 = a[3], *a4 = a[4], *a5 = a[5], *a6 = a[6],
                   *a7 = a[7], *a8 = a[8];
    int i = 0;
    for (; i + 8 <= m; i += 8)
        ST8(dst + i,
            gauss8(LD8(a4 + i), _mm256_add_epi32(LD8(a3 + i), LD8(a5 + i)),
                   _mm256_add_epi32(LD8(a2 + i), LD8(a6 + i)), _mm256_add_epi32(LD8(a1 + i), LD8(a7 + i)),
                   _mm256_add_epi32(LD8(a0 + i), LD8(a8 + i))));
    if (i < m) {
        const uint32_t *const t[9] = {a0 + i, a1 + i, a2 + i, a3 + i, a4 + i, a5 + i, a6 + i, a7 + i, a8 + i};
        gd_gauss_v_c(t, dst + i, m - i);
    }
}

void gd_gauss_h_avx2(const uint32_t *v, uint32_t *dst, int i0, int i1)
{
    int i = i0;
    for (; i + 8 <= i1; i += 8) {
        const uint32_t *p = v + i;
        ST8(dst + i,
            gauss8(LD8(p), _mm256_add_epi32(LD8(p - 3), LD8(p + 3)), _mm256_add_epi32(LD8(p - 6), LD8(p + 6)),
                   _mm256_add_epi32(LD8(p - 9), LD8(p + 9)), _mm256_add_epi32(LD8(p - 12), LD8(p + 12))));
    }
    if (i < i1)
        gd_gauss_h_c(v, dst, i, i1);
}

/* The tone curve on 8 samples: S (decoded) and b (the bloom) to codes.
 *   P = (s b + 2^15) >> 16 in 64-bit lanes (s b < 2^52), capped at CAP =
 *       2^30 >> (20 - F); c' = min(S + P, CAP) (S < 2^28: no wrap) and v =
 *       c' << (20 - F). Every threshold t[1 .. n] is below 2^30 = CAP <<
 *       (20 - F), so v counts the same thresholds as gd_to_q20(S + P): both
 *       are at least 2^30 when c >= CAP, and equal otherwise.
 *   key: v below 64 is its own key; above, v as a float (exact: v < 2^24,
 *       or v with its low 8 bits cleared, at most 23 significant bits when
 *       v < 2^31, which changes no bit the key reads) has the exponent e
 *       and the five bits after the leading one in bits 18 .. 30: key =
 *       (bits >> 18) - 127 * 32 + 64 - 6 * 32. v <= 2^30: key <= 832, so
 *       the 4-byte gather of the byte table stays inside its 896 entries.
 *   k = bk[key], then twice k += t[k + 1] <= v (unsigned: max(t, v) == v). */
static inline __m256i tone8v(__m256i S, __m256i b, __m256i sv, const uint32_t *t, const uint8_t *bk)
{
    const __m256i r15 = _mm256_set1_epi64x(32768), cap64 = _mm256_set1_epi64x(1ll << (10 + BLOOM_LIN_BITS));
    const __m256i cap = _mm256_set1_epi32(1 << (10 + BLOOM_LIN_BITS));
    __m256i pe = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(b, sv), r15), 16);
    __m256i po = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(b, 32), sv), r15), 16);
    pe = _mm256_blendv_epi8(pe, cap64, _mm256_cmpgt_epi64(pe, cap64));
    po = _mm256_blendv_epi8(po, cap64, _mm256_cmpgt_epi64(po, cap64));
    const __m256i p = _mm256_blend_epi32(pe, _mm256_slli_epi64(po, 32), 0xAA);
    __m256i v = _mm256_min_epu32(_mm256_add_epi32(S, p), cap);
    v = _mm256_slli_epi32(v, 20 - BLOOM_LIN_BITS);
    const __m256i big = _mm256_cmpgt_epi32(v, _mm256_set1_epi32(0xFFFFFF));
    const __m256i vx = _mm256_andnot_si256(_mm256_and_si256(big, _mm256_set1_epi32(0xFF)), v);
    const __m256i fb = _mm256_castps_si256(_mm256_cvtepi32_ps(vx));
    const __m256i kf = _mm256_sub_epi32(_mm256_srli_epi32(fb, 18), _mm256_set1_epi32(127 * 32 - 64 + 6 * 32));
    const __m256i small = _mm256_cmpgt_epi32(_mm256_set1_epi32(64), v);
    const __m256i key = _mm256_blendv_epi8(kf, v, small);
    const int *ti = (const int *)(const void *)t;
    __m256i k = _mm256_and_si256(_mm256_i32gather_epi32((const int *)(const void *)bk, key, 1),
                                 _mm256_set1_epi32(0xFF));
    const __m256i one = _mm256_set1_epi32(1);
    __m256i tk = _mm256_i32gather_epi32(ti, _mm256_add_epi32(k, one), 4);
    k = _mm256_sub_epi32(k, _mm256_cmpeq_epi32(_mm256_max_epu32(tk, v), v));
    tk = _mm256_i32gather_epi32(ti, _mm256_add_epi32(k, one), 4);
    return _mm256_sub_epi32(k, _mm256_cmpeq_epi32(_mm256_max_epu32(tk, v), v));
}

void gd_tone8_avx2(const uint32_t *bl, const uint32_t *sv, const uint8_t *sc, const uint32_t *dec,
                   uint8_t *out, int n, uint32_t s, const uint32_t *t, const uint8_t *bk)
{
    const __m256i s64 = _mm256_set1_epi64x((long long)s);
    /* byte 0 of each 32-bit lane to bytes 0 .. 3 of each 128-bit half, then
     * the two halves' first words together */
    const __m256i pick = _mm256_setr_epi8(0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 4,
                                          8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
    const __m256i join = _mm256_setr_epi32(0, 4, 1, 1, 1, 1, 1, 1);
    const int *di = (const int *)(const void *)dec;
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i S =
            sc ? _mm256_i32gather_epi32(
                     di, _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)(sc + i))), 4)
               : LD8(sv + i);
        const __m256i k = tone8v(S, LD8(bl + i), s64, t, bk);
        const __m256i by = _mm256_permutevar8x32_epi32(_mm256_shuffle_epi8(k, pick), join);
        _mm_storel_epi64((__m128i *)(void *)(out + i), _mm256_castsi256_si128(by));
    }
    if (i < n)
        gd_tone8_c(bl + i, sv ? sv + i : NULL, sc ? sc + i : NULL, dec, out + i, n - i, s, t, bk);
}

/* 8 bytes at a time: their table words gathered, byte 0 of each packed
 * (loaded before they are stored: d may equal s). */
void gd_lut8_avx2(const uint8_t *s, const uint32_t *tab, uint8_t *d, int n)
{
    const __m256i pick = _mm256_setr_epi8(0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 4,
                                          8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
    const __m256i join = _mm256_setr_epi32(0, 4, 1, 1, 1, 1, 1, 1);
    const int *ti = (const int *)(const void *)tab;
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i c = _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)(s + i)));
        const __m256i k = _mm256_i32gather_epi32(ti, c, 4);
        const __m256i by = _mm256_permutevar8x32_epi32(_mm256_shuffle_epi8(k, pick), join);
        _mm_storel_epi64((__m128i *)(void *)(d + i), _mm256_castsi256_si128(by));
    }
    if (i < n)
        gd_lut8_c(s + i, tab, d + i, n - i);
}

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#else
typedef int bloom_preset_gamedev_avx2_empty; /* ISO C wants a declaration in every file */
#endif
