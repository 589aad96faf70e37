/* AVX2 twins of the fast output path's kernels (x86-64 with GCC or clang),
 * chosen at bloom_init when the CPU and the OS support AVX2
 * (bloom_cpu_avx2: CPUID leaf 7 and XGETBV), never when BLOOM_FLAG_NO_AVX2
 * or BLOOM_FLAG_NO_SIMD is set. Same bits as the C kernels; every function
 * here is compiled for AVX2 through a target pragma, so the rest of the
 * core stays baseline x86-64 and the file needs no special flags.
 *
 *   vtent, htent_eo   the flat kernels of bloom_row_simd.h on 8 lanes
 *   encode_eo         decode + composite + sRGB encode of RGB888 -> RGB888
 *                     and XRGB8888 -> XRGB8888 in 8-pixel groups, one
 *                     sample per 32-bit lane: the source code's linear
 *                     value, the bloom sample and the encoder's two table
 *                     reads are gathers (the tables of bloom_tables.c; the
 *                     bucket table is read as 32-bit words at byte offsets,
 *                     which stay inside it because the value is clamped to
 *                     the top threshold first: tests/test_simd.c checks the
 *                     highest offset read). Other format pairs, the debug
 *                     view and group tails go to bloom_encode_eo. */
#include "bloom_internal.h"
#include "bloom_pixel.h"

#if defined(BLOOM_SIMD_AVX2)
#include <cpuid.h>
#include <immintrin.h>

bool bloom_cpu_avx2(void)
{
    unsigned a, b, c, d;
    if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & (1u << 27)) || !(c & (1u << 28)))
        return false; /* no OSXSAVE or no AVX */
    unsigned lo, hi;
    __asm__ volatile("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
    (void)hi;
    if ((lo & 6u) != 6u) /* the OS saves neither XMM nor YMM state */
        return false;
    if (!__get_cpuid_count(7, 0, &a, &b, &c, &d))
        return false;
    return (b & (1u << 5)) != 0;
}

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

#define LD8(p) _mm256_loadu_si256((const __m256i *)(const void *)(p))
#define ST8(p, v) _mm256_storeu_si256((__m256i *)(void *)(p), (v))

static inline uint32_t or_lanes8(__m256i v)
{
    __m128i x = _mm_or_si128(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    x = _mm_or_si128(x, _mm_srli_si128(x, 8));
    x = _mm_or_si128(x, _mm_srli_si128(x, 4));
    return (uint32_t)_mm_cvtsi128_si32(x);
}

/* dst[i] = (3 a[i] + 4 b[i] + c[i] + 4) >> 3 (bloom_internal.h). */
uint32_t bloom_row_vtent_avx2(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n)
{
    const __m256i k4 = _mm256_set1_epi32(4);
    __m256i any = _mm256_setzero_si256();
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i va = LD8(a + i);
        const __m256i t = _mm256_add_epi32(_mm256_add_epi32(va, _mm256_slli_epi32(va, 1)),
                                           _mm256_slli_epi32(LD8(b + i), 2));
        const __m256i s = _mm256_srli_epi32(_mm256_add_epi32(t, _mm256_add_epi32(LD8(c + i), k4)), 3);
        ST8(dst + i, s);
        any = _mm256_or_si256(any, s);
    }
    uint32_t r = or_lanes8(any);
    if (i < n)
        r |= bloom_row_vtent_sse2(a + i, b + i, c + i, dst + i, n - i);
    return r;
}

/* e[i] = (3 v[i-3] + 4 v[i] + v[i+3] + 4) >> 3, o[i] = (v[i-3] + 4 v[i] + 3 v[i+3] + 4) >> 3. */
uint32_t bloom_row_htent_eo_avx2(const uint32_t *v, uint32_t *e, uint32_t *o, int n)
{
    const __m256i k4 = _mm256_set1_epi32(4);
    __m256i any = _mm256_setzero_si256();
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i p = LD8(v + i - 3), q = LD8(v + i + 3);
        const __m256i m = _mm256_add_epi32(_mm256_add_epi32(_mm256_slli_epi32(LD8(v + i), 2), k4),
                                           _mm256_add_epi32(p, q));
        const __m256i ev = _mm256_srli_epi32(_mm256_add_epi32(m, _mm256_slli_epi32(p, 1)), 3);
        const __m256i ov = _mm256_srli_epi32(_mm256_add_epi32(m, _mm256_slli_epi32(q, 1)), 3);
        ST8(e + i, ev);
        ST8(o + i, ov);
        any = _mm256_or_si256(any, _mm256_or_si256(ev, ov));
    }
    uint32_t r = or_lanes8(any);
    if (i < n)
        r |= bloom_row_htent_eo_sse2(v + i, e + i, o + i, n - i);
    return r;
}

/* The 8-bit sRGB code of each lane's Q12.20 value: enc_fast of
 * bloom_pixel.c (clamp to the top threshold t[255], the bucket's code c,
 * plus one where v >= t[c + 1]). The bucket byte is the low byte of the
 * 32-bit word gathered at its offset. */
static inline __m256i enc8_lanes(__m256i v)
{
    const __m256i top = _mm256_set1_epi32((int)bloom_srgb_enc8[255]), ff = _mm256_set1_epi32(0xFF);
    v = _mm256_min_epu32(v, top);
    const __m256i idx = _mm256_srli_epi32(v, BLOOM_LIN_BITS - 12);
    const __m256i c = _mm256_and_si256(_mm256_i32gather_epi32((const int *)(const void *)bloom_srgb_bkt8, idx, 1), ff);
    const __m256i t = _mm256_i32gather_epi32((const int *)(const void *)(bloom_srgb_enc8 + 1), c, 4);
    /* v >= t <=> v + 1 > t (both below 2^31): the compare gives -1 there */
    return _mm256_sub_epi32(c, _mm256_cmpgt_epi32(_mm256_add_epi32(v, _mm256_set1_epi32(1)), t));
}

/* One vector of samples: source codes at p (8 bytes), bloom gathered from
 * the group's base e at the lanes' indices. */
static inline __m256i eo_lanes(const uint8_t *p, const uint32_t *e, __m256i idx)
{
    const __m256i code = _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)p));
    const __m256i s = _mm256_i32gather_epi32((const int *)(const void *)bloom_srgb_dec8, code, 4);
    const __m256i b = _mm256_i32gather_epi32((const int *)(const void *)e, idx, 4);
    return enc8_lanes(_mm256_add_epi32(s, b));
}

/* Four vectors of values below 256 as 32 bytes in order. */
static inline __m256i pack4(__m256i a, __m256i b, __m256i c, __m256i d)
{
    const __m256i x = _mm256_packus_epi16(_mm256_packus_epi32(a, b), _mm256_packus_epi32(c, d));
    return _mm256_permutevar8x32_epi32(x, _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7));
}

/* Index of the bloom sample of flat byte k of an 8-pixel group (pixels of
 * bpp bytes, channel order R G B for RGB888, B G R X for XRGB8888), from
 * the group's even-pixel base e, with the odd pixels d words further on. */
static inline int eo_index(int k, int bpp, int d)
{
    const int x = k / bpp, j = k % bpp;
    const int ch = bpp == 3 ? j : j < 3 ? 2 - j : 0; /* X: any sample, replaced by 0xFF */
    return (x & 1 ? d : 0) + 3 * (x >> 1) + ch;
}

static inline __m256i idx_vec(int k0, int bpp, int d)
{
    return _mm256_setr_epi32(eo_index(k0, bpp, d), eo_index(k0 + 1, bpp, d), eo_index(k0 + 2, bpp, d),
                             eo_index(k0 + 3, bpp, d), eo_index(k0 + 4, bpp, d), eo_index(k0 + 5, bpp, d),
                             eo_index(k0 + 6, bpp, d), eo_index(k0 + 7, bpp, d));
}

void bloom_encode_eo_avx2(bloom_format_t in_fmt, bloom_format_t out_fmt, bool debug, const uint8_t *src,
                          const uint32_t *e, const uint32_t *o, uint8_t *dst, int n)
{
    const bool rgb = BLOOM_USE_RGB888 && in_fmt == BLOOM_FMT_RGB888 && out_fmt == BLOOM_FMT_RGB888;
    const bool xrgb = BLOOM_USE_XRGB8888 && in_fmt == BLOOM_FMT_XRGB8888 && out_fmt == BLOOM_FMT_XRGB8888;
    /* o as a word offset from e, if it is one the indices can hold */
    const uintptr_t pe = (uintptr_t)e, po = (uintptr_t)o;
    const uintptr_t gap = po >= pe ? po - pe : pe - po;
    if (debug || !(rgb || xrgb) || gap % sizeof *e || gap / sizeof *e > (1u << 24) || n < 8) {
        bloom_encode_eo(in_fmt, out_fmt, debug, src, e, o, dst, n);
        return;
    }
    const int d = (int)(gap / sizeof *e) * (po >= pe ? 1 : -1);
    const int g = n / 8; /* groups of 8 pixels: 12 bloom samples of e and of o each */
    if (rgb) {
        const __m256i i0 = idx_vec(0, 3, d), i1 = idx_vec(8, 3, d), i2 = idx_vec(16, 3, d);
        for (int j = 0; j < g; j++, src += 24, dst += 24, e += 12) {
            const __m256i a = eo_lanes(src, e, i0), b = eo_lanes(src + 8, e, i1), c = eo_lanes(src + 16, e, i2);
            const __m256i x = pack4(a, b, c, c);
            _mm_storeu_si128((__m128i *)(void *)dst, _mm256_castsi256_si128(x));
            _mm_storel_epi64((__m128i *)(void *)(dst + 16), _mm256_extracti128_si256(x, 1));
        }
    } else {
        const __m256i i0 = idx_vec(0, 4, d), i1 = idx_vec(8, 4, d), i2 = idx_vec(16, 4, d),
                      i3 = idx_vec(24, 4, d);
        const __m256i xff = _mm256_set1_epi32((int)0xFF000000u);
        for (int j = 0; j < g; j++, src += 32, dst += 32, e += 12) {
            const __m256i x = pack4(eo_lanes(src, e, i0), eo_lanes(src + 8, e, i1), eo_lanes(src + 16, e, i2),
                                    eo_lanes(src + 24, e, i3));
            ST8(dst, _mm256_or_si256(x, xff));
        }
    }
    if (n > 8 * g)
        bloom_encode_eo(in_fmt, out_fmt, false, src, e, o + 12 * g, dst, n - 8 * g);
}

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#else
typedef int bloom_row_avx2_empty; /* ISO C wants a declaration in every file */
#endif
