/* AVX2 twins of the 16-bit row kernels (bloom_row16.c), picked with the
 * AVX2 kernel set (bloom_row16_k.c's dispatch). Same bits as the C kernels:
 *
 *   narrow16   D_1 narrowed half to even, 8 samples a step (and with the
 *              level's D row added: the tent out of the first 32-bit level)
 *   vtent16w   the vertical tent of 16-bit rows into 32-bit sums, 8 a step
 *   box16      the box of four 16-bit rows, into 16-bit samples or (wide)
 *              32-bit ones: column sums widened to 32 bits (<< sh), then
 *              the 32-bit box's horizontal pass (bloom_box_block8), so the
 *              sums and their rounding are the 32-bit box's
 *   il16       the tent's last pass: even and odd columns interleaved
 *              (il24) plus the level's D row, stored as 16-bit samples
 *
 * Every 32-bit lane below holds a value under 2^31 (sim/docs/fixed-point.md,
 * "16-bit samples": box sums < 2^20 << 9, results < 2^16), so the signed
 * packs (_mm_packus_epi32) see non-negative values and keep them. */
#include "bloom_kernels.h"

#if defined(BLOOM_SIMD_AVX2) && BLOOM_USE_S16
#include "bloom_avx2.h" /* from here on compiled for AVX2 */

/* 8 lanes (each < 2^16) stored as 8 uint16. */
static inline void st8x16(uint16_t *d, __m256i v)
{
    const __m128i p = _mm_packus_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    _mm_storeu_si128((__m128i *)(void *)d, p);
}

/* 8 uint16 widened to 8 lanes. */
static inline __m256i ld8x16(const uint16_t *p)
{
    return _mm256_cvtepu16_epi32(_mm_loadu_si128((const __m128i *)(const void *)p));
}

/* Rows of 8 or more samples end with one more vector over the last 8 (the
 * output never aliases the input, so the overlap writes the same values
 * again): no scalar tail. */
static inline int last8(int i, int n)
{
    return i < n && n >= 8 ? n - 8 : i;
}

/* 8 samples narrowed half to even: (v + h + ((v >> sh) & 1)) >> sh. */
static inline __m256i narrow8(const uint32_t *src, __m256i h, __m128i cnt)
{
    const __m256i v = LD8(src);
    const __m256i odd = _mm256_and_si256(_mm256_srl_epi32(v, cnt), _mm256_set1_epi32(1));
    return _mm256_srl_epi32(_mm256_add_epi32(_mm256_add_epi32(v, h), odd), cnt);
}

uint32_t bloom_row_narrow16_avx2(const uint32_t *src, uint16_t *dst, int n, int sh)
{
    const __m256i h = _mm256_set1_epi32((int)((1u << (sh - 1)) - 1u));
    const __m128i cnt = _mm_cvtsi32_si128(sh);
    __m256i any = _mm256_setzero_si256();
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i r = narrow8(src + i, h, cnt);
        any = _mm256_or_si256(any, r);
        st8x16(dst + i, r);
    }
    if ((i = last8(i, n)) + 8 == n) {
        const __m256i r = narrow8(src + i, h, cnt);
        any = _mm256_or_si256(any, r);
        st8x16(dst + i, r);
        i = n;
    }
    uint32_t a = or_lanes8(any);
    if (i < n)
        a |= bloom_row_narrow16_c(src + i, dst + i, n - i, sh);
    return a;
}

void bloom_row_narrow16_add_avx2(const uint32_t *src, const uint16_t *add, uint16_t *dst, int n, int sh)
{
    const __m256i h = _mm256_set1_epi32((int)((1u << (sh - 1)) - 1u));
    const __m128i cnt = _mm_cvtsi32_si128(sh);
    int i = 0;
    for (; i < n; i += 8) {
        if (i + 8 > n && (i = last8(i, n)) + 8 != n)
            break;
        const __m256i r = narrow8(src + i, h, cnt); /* + add: U_k < 2^16 (the format's bound) */
        st8x16(dst + i, add ? _mm256_add_epi32(r, ld8x16(add + i)) : r);
    }
    if (i < n)
        bloom_row_narrow16_add_c(src + i, add ? add + i : NULL, dst + i, n - i, sh);
}

uint32_t bloom_row_vtent16w_avx2(const uint16_t *a, const uint16_t *b, const uint16_t *c, uint32_t *dst,
                                 int n, int sh)
{
    const __m256i rnd = _mm256_set1_epi32((int)BLOOM_VT_RND);
    const __m128i cnt = _mm_cvtsi32_si128(sh);
    __m256i any = _mm256_setzero_si256();
    int i = 0;
    for (; i < n; i += 8) { /* 3a + 4b + c < 2^19, << sh < 2^28 */
        if (i + 8 > n && (i = last8(i, n)) + 8 != n)
            break;
        const __m256i va = ld8x16(a + i), vb = ld8x16(b + i), vc = ld8x16(c + i);
        __m256i s = _mm256_add_epi32(_mm256_add_epi32(va, _mm256_slli_epi32(va, 1)),
                                     _mm256_add_epi32(_mm256_slli_epi32(vb, 2), vc));
        s = _mm256_srli_epi32(_mm256_add_epi32(_mm256_sll_epi32(s, cnt), rnd), 3);
        ST8(dst + i, s);
        any = _mm256_or_si256(any, s);
    }
    uint32_t r = or_lanes8(any);
    if (i < n)
        r |= bloom_row_vtent16w_c(a + i, b + i, c + i, dst + i, n - i, sh);
    return r;
}

/* Both boxes (d16 or d32 is NULL): blocks of 8 pixels from x = 1 (no clamp
 * on the left), as bloom_row_box_avx2; the edges and the tail in C. */
static void box16(const uint16_t *const s[4], uint16_t *d16, uint32_t *d32, int dw, int sw, int sh)
{
    void *dst = d16 ? (void *)d16 : (void *)d32;
    const int xa = 1;
    int nb = 0;
    if (dw >= xa + 8 && 3 * sw >= 6 * xa + 63)
        nb = imin((dw - xa) / 8, (3 * sw - 63 - 6 * xa) / 48 + 1);
    if (nb <= 0) {
        bloom_row_box16_range_c(s, dst, !d16, 0, dw, sw, sh);
        return;
    }
    bloom_row_box16_range_c(s, dst, !d16, 0, xa, sw, sh);
    const __m128i cnt = _mm_cvtsi32_si128(sh);
    uint32_t v[BLOOM_BOX_CHUNK * 48 + 16];
    for (int j = 0; j < nb; j += BLOOM_BOX_CHUNK) {
        const int k = imin(BLOOM_BOX_CHUNK, nb - j), x = xa + 8 * j;
        const size_t b = (size_t)(6 * x - 3);
        const int nv = (48 * (k - 1) + 59 + 7) / 8;
        for (int i = 0; i < nv; i++) { /* column sums < 2^18, << sh (sh 0 into 16-bit samples) */
            const size_t o = b + 8u * (size_t)i;
            const __m256i cs = _mm256_add_epi32(_mm256_add_epi32(ld8x16(s[0] + o), ld8x16(s[1] + o)),
                                                _mm256_add_epi32(ld8x16(s[2] + o), ld8x16(s[3] + o)));
            ST8(v + 8 * i, _mm256_sll_epi32(cs, cnt));
        }
        for (int q = 0; q < k; q++) {
            __m256i o[3];
            bloom_box_block8(v + 48 * q, o);
            const size_t at = 3u * (size_t)(x + 8 * q);
            if (d16) {
                st8x16(d16 + at, o[0]);
                st8x16(d16 + at + 8, o[1]);
                st8x16(d16 + at + 16, o[2]);
            } else {
                ST8(d32 + at, o[0]);
                ST8(d32 + at + 8, o[1]);
                ST8(d32 + at + 16, o[2]);
            }
        }
    }
    bloom_row_box16_range_c(s, dst, !d16, xa + 8 * nb, dw, sw, sh);
}

void bloom_row_box16_avx2(const uint16_t *const s[4], uint16_t *dst, int dw, int sw)
{
    box16(s, dst, NULL, dw, sw, 0);
}

void bloom_row_box16w_avx2(const uint16_t *const s[4], uint32_t *dst, int dw, int sw, int sh)
{
    box16(s, NULL, dst, dw, sw, sh);
}

void bloom_row_il16_avx2(const uint32_t *e, const uint32_t *o, const uint16_t *add, uint16_t *dst, int np)
{
    int x = 0;
    for (; x + 8 <= np; x += 8) { /* 8 pixels: columns x / 2 .. x / 2 + 3 of each half */
        __m256i v[3];
        il24(e + 3 * (x >> 1), o + 3 * (x >> 1), v);
        for (int j = 0; j < 3; j++) {
            const __m256i t = add ? _mm256_add_epi32(v[j], ld8x16(add + 3 * x + 8 * j)) : v[j];
            st8x16(dst + 3 * x + 8 * j, t);
        }
    }
    bloom_row_il16_c(e, o, add, dst, x, np);
}

#include "bloom_avx2_end.h"
#else
typedef int bloom_row16_avx2_empty_t; /* (no AVX2, or 16-bit samples compiled out) */
#endif
