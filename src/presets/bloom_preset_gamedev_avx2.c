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
 *   (these three: bloom_preset_gamedev_simd.h on 8 lanes, the body of the
 *   SSE2 and NEON twins too)
 *
 *   lut8              the per-code table of rows without bloom, 32 bytes at
 *                     a time with no gather: the table as 16 rows of 16
 *                     bytes, each looked up by the low nibble (VPSHUFB),
 *                     the right row picked by the high nibble's bits in a
 *                     tree of blends (VPBLENDVB)
 *
 * The tone curve stays C: twins by table gathers took fewer instructions
 * but more time on the CPU this was measured on (an AMD EPYC: 1080p scene
 * 8.8 ms with them, 6.4 without; a dark frame 3.6 against 1.8).
 *
 * Empty on other targets. */
#include "bloom_preset_gamedev_k.h"

#if BLOOM_USE_GAMEDEV && defined(BLOOM_SIMD_AVX2) && !BLOOM_SMALL

#include "bloom_avx2.h" /* from here on compiled for AVX2 */

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

/* gd_bright, gd_gauss_v, gd_gauss_h: bloom_preset_gamedev_simd.h on 8 lanes */
#define VT __m256i
#define VB __m256i
#define W 8
#define LDV LD8
#define STV ST8
#define LDB LD8
#define STB ST8
#define ADDV _mm256_add_epi32
#define GAUSSV gauss8
#define DUPB(c) _mm256_set1_epi8((char)(c))
#define MAXB _mm256_max_epu8
#define SUBSB _mm256_subs_epu8
#define GD_FN(f) f##_avx2
#include "bloom_preset_gamedev_simd.h"

void gd_lut8_avx2(const uint8_t *s, const uint8_t *tab, uint8_t *d, int n)
{
    __m256i row[16]; /* row h: codes 16 h .. 16 h + 15, in both lanes */
    for (int h = 0; h < 16; h++)
        row[h] = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)(const void *)(tab + 16 * h)));
    const __m256i low = _mm256_set1_epi8(0x0F);
    int i = 0;
    for (; i + 32 <= n; i += 32) {
        const __m256i x = LD8(s + i), lo = _mm256_and_si256(x, low);
        /* bit 4 + k of each code at bit 7 of its byte, which VPBLENDVB
         * reads (a 16-bit shift moves bits into the next byte's low bits
         * only) */
        const __m256i k0 = _mm256_slli_epi16(x, 3), k1 = _mm256_slli_epi16(x, 2),
                      k2 = _mm256_slli_epi16(x, 1);
        /* depth first, so that few values are live at once; a chunk whose
         * codes are all below 64 (or 128) needs only the first 4 (8) rows
         * of the table: dark frames and dark parts of a frame take 4
         * shuffles and 3 blends for 32 codes instead of 16 and 15 */
#define LUT_PAIR(h)                                                                                          \
    _mm256_blendv_epi8(_mm256_shuffle_epi8(row[h], lo), _mm256_shuffle_epi8(row[(h) + 1], lo), k0)
#define LUT_QUAD(h) _mm256_blendv_epi8(LUT_PAIR(h), LUT_PAIR((h) + 2), k1)
#define LUT_OCT(h) _mm256_blendv_epi8(LUT_QUAD(h), LUT_QUAD((h) + 4), k2)
        if (_mm256_testz_si256(x, _mm256_set1_epi8((char)0xC0)))
            ST8(d + i, LUT_QUAD(0));
        else if (_mm256_testz_si256(x, _mm256_set1_epi8((char)0x80)))
            ST8(d + i, LUT_OCT(0));
        else
            ST8(d + i, _mm256_blendv_epi8(LUT_OCT(0), LUT_OCT(8), x));
#undef LUT_PAIR
#undef LUT_QUAD
#undef LUT_OCT
    }
    if (i < n)
        gd_lut8_c(s + i, tab, d + i, n - i);
}

#include "bloom_avx2_end.h"

#else
typedef int bloom_preset_gamedev_avx2_empty; /* ISO C wants a declaration in every file */
#endif
