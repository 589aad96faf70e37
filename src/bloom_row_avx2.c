/* AVX2 twins of the fast output path's kernels (x86-64 with GCC or clang),
 * chosen at bloom_init when the CPU and the OS support AVX2
 * (bloom_cpu_avx2: CPUID leaf 7 and XGETBV), never when BLOOM_FLAG_NO_AVX2
 * or BLOOM_FLAG_NO_SIMD is set. Same bits as the C kernels; every function
 * here is compiled for AVX2 through a target pragma, so the rest of the
 * core stays baseline x86-64 and the file needs no special flags.
 *
 *   vtent, htent_eo   the flat kernels of bloom_row_simd.h on 8 lanes
 *   tent              whole rows through vtent, htent_eo and an interleave
 *                     of the even and odd columns by lane permutes
 *   encode_eo         decode + composite + sRGB encode of RGB888 -> RGB888
 *                     and XRGB8888 -> XRGB8888 in 8-pixel groups, one
 *                     sample per 32-bit lane: the source code's linear
 *                     value and the encoder's two table reads are gathers
 *                     (and the bloom sample for XRGB8888; RGB888
 *                     interleaves it by permutes) (the tables of bloom_tables.c; the
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
#include <string.h>

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

/* dst[i] = (3 a[i] + 4 b[i] + c[i] + 4) >> 3 in wrapping 32-bit lanes
 * (bloom_internal.h); returns the OR of every dst[i], and the OR of every
 * input in *in_or (the sums are exact when it is below 2^29). */
static uint32_t vtent8(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n,
                       uint32_t *in_or)
{
    const __m256i k4 = _mm256_set1_epi32(4);
    __m256i any = _mm256_setzero_si256(), in = _mm256_setzero_si256();
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i va = LD8(a + i), vb = LD8(b + i), vc = LD8(c + i);
        const __m256i t = _mm256_add_epi32(_mm256_add_epi32(va, _mm256_slli_epi32(va, 1)), _mm256_slli_epi32(vb, 2));
        const __m256i s = _mm256_srli_epi32(_mm256_add_epi32(t, _mm256_add_epi32(vc, k4)), 3);
        ST8(dst + i, s);
        any = _mm256_or_si256(any, s);
        in = _mm256_or_si256(in, _mm256_or_si256(va, _mm256_or_si256(vb, vc)));
    }
    if (i < n && n >= 8) { /* the last 8 again (dst is not an input) */
        i = n - 8;
        const __m256i va = LD8(a + i), vb = LD8(b + i), vc = LD8(c + i);
        const __m256i t = _mm256_add_epi32(_mm256_add_epi32(va, _mm256_slli_epi32(va, 1)), _mm256_slli_epi32(vb, 2));
        const __m256i s = _mm256_srli_epi32(_mm256_add_epi32(t, _mm256_add_epi32(vc, k4)), 3);
        ST8(dst + i, s);
        any = _mm256_or_si256(any, s);
        in = _mm256_or_si256(in, _mm256_or_si256(va, _mm256_or_si256(vb, vc)));
        i = n;
    }
    uint32_t r = or_lanes8(any), ri = or_lanes8(in);
    for (; i < n; i++) {
        dst[i] = (3u * a[i] + 4u * b[i] + c[i] + 4u) >> 3;
        r |= dst[i];
        ri |= a[i] | b[i] | c[i];
    }
    *in_or = ri;
    return r;
}

uint32_t bloom_row_vtent_avx2(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n)
{
    uint32_t in;
    return vtent8(a, b, c, dst, n, &in);
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

/* The 24 samples of 8 pixels (4 even/odd pairs, R G B each) in pixel
 * order, from the even columns' e[0..11] and the odd columns' o[0..11]. */
static inline void il24(const uint32_t *e, const uint32_t *o, __m256i v[3])
{
    const __m256i e0 = LD8(e), e4 = LD8(e + 4), o0 = LD8(o), o4 = LD8(o + 4);
#define PERM(x, a, b, c, d, e_, f, g, h) _mm256_permutevar8x32_epi32((x), _mm256_setr_epi32(a, b, c, d, e_, f, g, h))
    v[0] = _mm256_blend_epi32(PERM(e0, 0, 1, 2, 0, 0, 0, 3, 4), PERM(o0, 0, 0, 0, 0, 1, 2, 0, 0), 0x38);
    v[1] = _mm256_blend_epi32(PERM(e4, 1, 0, 0, 0, 2, 3, 4, 0), PERM(o0, 0, 3, 4, 5, 0, 0, 0, 6), 0x8E);
    v[2] = _mm256_blend_epi32(PERM(e4, 0, 0, 5, 6, 7, 0, 0, 0), PERM(o4, 3, 4, 0, 0, 0, 5, 6, 7), 0xE3);
#undef PERM
}

/* dst pixels 0 .. n-1 = even/odd columns e, o interleaved, plus add (if
 * not NULL; add may equal dst). */
static void il_add(const uint32_t *e, const uint32_t *o, const uint32_t *add, uint32_t *dst, int n)
{
    int x = 0;
    for (; x + 8 <= n; x += 8, e += 12, o += 12, dst += 24) {
        __m256i v[3];
        il24(e, o, v);
        if (add) {
            for (int j = 0; j < 3; j++)
                v[j] = _mm256_add_epi32(v[j], LD8(add + 8 * j));
            add += 24;
        }
        for (int j = 0; j < 3; j++)
            ST8(dst + 8 * j, v[j]);
    }
    for (int i = 0; x < n; x++, i++) { /* pixel x: column i / 2 of e or o */
        const uint32_t *p = (i & 1 ? o : e) + 3 * (i >> 1);
        for (int c = 0; c < 3; c++, dst++)
            *dst = p[c] + (add ? *add++ : 0u);
    }
}

/* Level-(k+1) columns per chunk of the tent (stack: 3 x 32 words). */
#define TENT_CH 32

/* bloom_row_tent_sse2_any through the flat kernels, for whole rows
 * (x0 = 0, n = 2 sw or 2 sw - 1): per chunk of low-resolution columns the
 * vertical tent (edges replicated), the horizontal tent into even and odd
 * columns, then interleaved with add. A chunk whose rows hold a value of
 * 2^29 or more (the flat sums could wrap) takes the exact SSE2 tent. */
void bloom_row_tent_avx2(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                         int n, int sw)
{
    if (x0 != 0 || sw < 2 || sw != (n + 1) / 2) {
        bloom_row_tent_sse2_any(u, odd, add, dst, x0, n, sw);
        return;
    }
    const uint32_t *ua = odd ? u[2] : u[0], *ub = u[1], *uc = odd ? u[0] : u[2];
    uint32_t vb[3 * (TENT_CH + 2)], eo[6 * TENT_CH];
    for (int m0 = 0; m0 < sw; m0 += TENT_CH) {
        const int nn = imin(TENT_CH, sw - m0), np = imin(2 * nn, n - 2 * m0);
        const int lo = m0 > 0 ? m0 - 1 : 0, hi = imin(m0 + nn, sw - 1); /* columns read */
        uint32_t *v0 = vb + (size_t)(lo - m0 + 1) * 3u, in;
        const size_t c0 = (size_t)lo * 3u;
        vtent8(ua + c0, ub + c0, uc + c0, v0, 3 * (hi - lo + 1), &in);
        if (in >> 29) {
            bloom_row_tent_sse2_any(u, odd, add ? add + (size_t)m0 * 6u : NULL, dst + (size_t)m0 * 6u, 2 * m0, np, sw);
            continue;
        }
        if (m0 == 0)
            memcpy(vb, vb + 3, 3u * sizeof *vb);
        if (m0 + nn == sw)
            memcpy(vb + 3 * (nn + 1), vb + 3 * nn, 3u * sizeof *vb);
        bloom_row_htent_eo_avx2(vb + 3, eo, eo + 3 * TENT_CH, 3 * nn);
        il_add(eo, eo + 3 * TENT_CH, add ? add + (size_t)m0 * 6u : NULL, dst + (size_t)m0 * 6u, np);
    }
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

/* One vector of samples: the codes of the 8 source bytes at p decoded and
 * added to the bloom b, encoded. */
static inline __m256i eo_lanes(const uint8_t *p, __m256i b)
{
    const __m256i code = _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)p));
    const __m256i s = _mm256_i32gather_epi32((const int *)(const void *)bloom_srgb_dec8, code, 4);
    return enc8_lanes(_mm256_add_epi32(s, b));
}

/* The bloom of a vector from the group's base e at the lanes' indices. */
static inline __m256i gather_b(const uint32_t *e, __m256i idx)
{
    return _mm256_i32gather_epi32((const int *)(const void *)e, idx, 4);
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
    /* XRGB8888 gathers the bloom: o as a word offset from e, if it is one
     * the indices can hold */
    const uintptr_t pe = (uintptr_t)e, po = (uintptr_t)o;
    const uintptr_t gap = po >= pe ? po - pe : pe - po;
    if (debug || !(rgb || xrgb) || (xrgb && (gap % sizeof *e || gap / sizeof *e > (1u << 24))) || n < 8) {
        bloom_encode_eo(in_fmt, out_fmt, debug, src, e, o, dst, n);
        return;
    }
    const int d = (int)(gap / sizeof *e) * (po >= pe ? 1 : -1);
    const int g = n / 8; /* groups of 8 pixels: 12 bloom samples of e and of o each */
    if (rgb) {
        for (int j = 0; j < g; j++, src += 24, dst += 24, e += 12, o += 12) {
            __m256i b[3];
            il24(e, o, b);
            const __m256i c = eo_lanes(src + 16, b[2]);
            const __m256i x = pack4(eo_lanes(src, b[0]), eo_lanes(src + 8, b[1]), c, c);
            _mm_storeu_si128((__m128i *)(void *)dst, _mm256_castsi256_si128(x));
            _mm_storel_epi64((__m128i *)(void *)(dst + 16), _mm256_extracti128_si256(x, 1));
        }
    } else {
        const __m256i i0 = idx_vec(0, 4, d), i1 = idx_vec(8, 4, d), i2 = idx_vec(16, 4, d),
                      i3 = idx_vec(24, 4, d);
        const __m256i xff = _mm256_set1_epi32((int)0xFF000000u);
        for (int j = 0; j < g; j++, src += 32, dst += 32, e += 12) {
            const __m256i x = pack4(eo_lanes(src, gather_b(e, i0)), eo_lanes(src + 8, gather_b(e, i1)),
                                    eo_lanes(src + 16, gather_b(e, i2)), eo_lanes(src + 24, gather_b(e, i3)));
            ST8(dst, _mm256_or_si256(x, xff));
        }
    }
    if (n > 8 * g)
        bloom_encode_eo(in_fmt, out_fmt, false, src, e, rgb ? o : o + 12 * g, dst, n - 8 * g);
}

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#else
typedef int bloom_row_avx2_empty; /* ISO C wants a declaration in every file */
#endif
