/* SSE2 twins of the arm preset's row kernels (bloom_preset_arm.h; x86-64,
 * where SSE2 is baseline). Same bits as the C kernels
 * (bloom_preset_arm_kern.c):
 *   - the down sums stay below 2^32 as in C (and wrap like C's uint32_t);
 *   - the up filter's sums S <= 192M, which C forms in 64 bits, are formed
 *     exactly in 32-bit lanes by splitting every input t as 64 h + l
 *     (l < 64): S + 96 = 64 Sh + (Sl + 96), so q = (S + 96) >> 6 =
 *     Sh + ((Sl + 96) >> 6), with Sh <= 3M < 2^30 and Sl + 96 < 2^12;
 *     q / 3 = (q * 0xAAAAAAAB) >> 33 by pmuludq (32 x 32 -> 64), as in C.
 * Empty on other targets. */
#include "bloom_preset_arm.h"

#if BLOOM_USE_ARM && defined(BLOOM_SIMD_SSE2)
#include "bloom_simd4.h"

#define LD(p) LD4(p)
#define ST(p, v) ST4(p, v)
#define EVENS(p, q)                                                                                          \
    _mm_castps_si128(_mm_shuffle_ps(_mm_castsi128_ps(p), _mm_castsi128_ps(q), _MM_SHUFFLE(2, 0, 2, 0)))
#define ODDS(p, q)                                                                                           \
    _mm_castps_si128(_mm_shuffle_ps(_mm_castsi128_ps(p), _mm_castsi128_ps(q), _MM_SHUFFLE(3, 1, 3, 1)))

static inline uint32_t or_lanes(__m128i v)
{
    v = _mm_or_si128(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(1, 0, 3, 2)));
    v = _mm_or_si128(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(2, 3, 0, 1)));
    return (uint32_t)_mm_cvtsi128_si32(v);
}

static void down_v_sse2(const uint32_t *s0, const uint32_t *s1, const uint32_t *s2, const uint32_t *s3,
                        uint32_t *c4, uint32_t *c2, int n)
{
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m128i mid = _mm_add_epi32(LD(s1 + i), LD(s2 + i));
        ST(c2 + i, mid);
        ST(c4 + i, _mm_add_epi32(mid, _mm_add_epi32(LD(s0 + i), LD(s3 + i))));
    }
    if (i < n)
        bloom_arm_kern_c.down_v(s0 + i, s1 + i, s2 + i, s3 + i, c4 + i, c2 + i, n - i);
}

static uint32_t down_h_sse2(const uint32_t *c4, const uint32_t *c2, uint32_t *dst, int n)
{
    const __m128i k7 = _mm_set1_epi32(7), k1 = _mm_set1_epi32(1);
    __m128i any = _mm_setzero_si128();
    int x = 0;
    for (; x + 4 <= n; x += 4) { /* reads c4, c2 [2x .. 2x + 9] */
        const uint32_t *a = c4 + 2 * x, *b = c2 + 2 * x;
        const __m128i a0 = LD(a), a4 = LD(a + 4), a2 = LD(a + 2), a6 = LD(a + 6);
        const __m128i s16 = _mm_add_epi32(_mm_add_epi32(EVENS(a0, a4), ODDS(a0, a4)),
                                          _mm_add_epi32(EVENS(a2, a6), ODDS(a2, a6)));
        const __m128i b0 = LD(b), b4 = LD(b + 4), b2 = LD(b + 2), b6 = LD(b + 6);
        const __m128i cc = _mm_add_epi32(ODDS(b0, b4), EVENS(b2, b6));
        const __m128i y = _mm_add_epi32(_mm_srli_epi32(s16, 1), _mm_slli_epi32(cc, 1));
        const __m128i t = _mm_and_si128(_mm_or_si128(_mm_srli_epi32(y, 4), s16), k1);
        const __m128i d = _mm_srli_epi32(_mm_add_epi32(_mm_add_epi32(y, k7), t), 4);
        ST(dst + x, d);
        any = _mm_or_si128(any, d);
    }
    uint32_t r = or_lanes(any);
    if (x < n)
        r |= bloom_arm_kern_c.down_h(c4 + 2 * x, c2 + 2 * x, dst + x, n - x);
    return r;
}

static void up_v_sse2(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, uint32_t *a, uint32_t *v,
                      int n)
{
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m128i p = LD(u0 + i), m = LD(u1 + i), q = LD(u2 + i);
        const __m128i m3 = _mm_add_epi32(_mm_slli_epi32(m, 1), m);
        ST(a + i, _mm_add_epi32(p, m3));
        ST(v + i,
           _mm_add_epi32(_mm_add_epi32(_mm_slli_epi32(p, 1), p), _mm_add_epi32(_mm_slli_epi32(m, 2), q)));
    }
    if (i < n)
        bloom_arm_kern_c.up_v(u0 + i, u1 + i, u2 + i, a + i, v + i, n - i);
}

#define X3(x) _mm_add_epi32(_mm_slli_epi32((x), 1), (x))
#define X11(x) _mm_add_epi32(_mm_add_epi32(_mm_slli_epi32((x), 3), _mm_slli_epi32((x), 1)), (x))
#define X28(x) _mm_sub_epi32(_mm_slli_epi32((x), 5), _mm_slli_epi32((x), 2))

/* floor(q / 3) per lane, q < 2^31: (q * 0xAAAAAAAB) >> 33. */
static inline __m128i div3(__m128i q)
{
    const __m128i k = _mm_set1_epi32((int)0xAAAAAAABu);
    const __m128i e = _mm_srli_epi64(_mm_mul_epu32(q, k), 33);
    const __m128i o = _mm_srli_epi64(_mm_mul_epu32(_mm_srli_epi64(q, 32), k), 33);
    return _mm_or_si128(e, _mm_slli_epi64(o, 32));
}

static uint32_t up_h_sse2(const uint32_t *a, const uint32_t *v, uint32_t *dst, int np)
{
    const __m128i m63 = _mm_set1_epi32(63), k96 = _mm_set1_epi32(96);
    __m128i any = _mm_setzero_si128();
    int i = 0;
    for (; i + 4 <= np; i += 4) { /* reads a, v [i .. i + 5] */
        const __m128i a0 = LD(a + i), a1 = LD(a + i + 1), a2 = LD(a + i + 2);
        const __m128i v0 = LD(v + i), v1 = LD(v + i + 1), v2 = LD(v + i + 2);
        const __m128i ah0 = _mm_srli_epi32(a0, 6), ah1 = _mm_srli_epi32(a1, 6), ah2 = _mm_srli_epi32(a2, 6);
        const __m128i vh0 = _mm_srli_epi32(v0, 6), vh1 = _mm_srli_epi32(v1, 6), vh2 = _mm_srli_epi32(v2, 6);
        const __m128i al0 = _mm_and_si128(a0, m63), al1 = _mm_and_si128(a1, m63),
                      al2 = _mm_and_si128(a2, m63);
        const __m128i vl0 = _mm_and_si128(v0, m63), vl1 = _mm_and_si128(v1, m63),
                      vl2 = _mm_and_si128(v2, m63);
        const __m128i h1 = _mm_add_epi32(X28(ah1), X3(vh1)), l1 = _mm_add_epi32(X28(al1), X3(vl1));
        const __m128i he = _mm_add_epi32(_mm_add_epi32(h1, X11(ah0)), _mm_add_epi32(ah2, vh0));
        const __m128i le =
            _mm_add_epi32(_mm_add_epi32(l1, X11(al0)), _mm_add_epi32(al2, _mm_add_epi32(vl0, k96)));
        const __m128i ho = _mm_add_epi32(_mm_add_epi32(h1, X11(ah2)), _mm_add_epi32(ah0, vh2));
        const __m128i lo =
            _mm_add_epi32(_mm_add_epi32(l1, X11(al2)), _mm_add_epi32(al0, _mm_add_epi32(vl2, k96)));
        const __m128i e = div3(_mm_add_epi32(he, _mm_srli_epi32(le, 6)));
        const __m128i o = div3(_mm_add_epi32(ho, _mm_srli_epi32(lo, 6)));
        ST(dst + 2 * i, _mm_unpacklo_epi32(e, o));
        ST(dst + 2 * i + 4, _mm_unpackhi_epi32(e, o));
        any = _mm_or_si128(any, _mm_or_si128(e, o));
    }
    uint32_t r = or_lanes(any);
    if (i < np)
        r |= bloom_arm_kern_c.up_h(a + i, v + i, dst + 2 * i, np - i);
    return r;
}

/* The samples are <= M < 2^31: the signed compare orders them. */
static inline __m128i max_s(__m128i a, __m128i b)
{
    const __m128i gt = _mm_cmpgt_epi32(a, b);
    return _mm_or_si128(_mm_and_si128(gt, a), _mm_andnot_si128(gt, b));
}

static uint32_t max3_sse2(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, int n)
{
    if (n < 4)
        return bloom_arm_kern_c.max3(u0, u1, u2, n);
    __m128i m = _mm_setzero_si128();
    for (int i = 0;; i += 4) {
        if (i + 4 > n) /* the last 4 again */
            i = n - 4;
        m = max_s(m, max_s(LD(u0 + i), max_s(LD(u1 + i), LD(u2 + i))));
        if (i + 4 >= n)
            break;
    }
    m = max_s(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = max_s(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(2, 3, 0, 1)));
    return (uint32_t)_mm_cvtsi128_si32(m);
}

static void lum8_sse2(const uint8_t *p, uint32_t *c4, uint32_t *c2, int n, bool x4, int i)
{
    bloom_arm_kern_c.lum8(p, c4, c2, n, x4, i); /* the decode is table reads */
}

#if !BLOOM_SMALL
static void out8_sse2(const uint8_t *src, const uint32_t *b, const uint32_t f[3], uint8_t *dst, int n,
                      bool x4)
{
    bloom_arm_kern_c.out8(src, b, f, dst, n, x4); /* the encode is table reads */
}
#endif

const bloom_arm_kern_t bloom_arm_kern_sse2 = {
    down_v_sse2, down_h_sse2, up_v_sse2, up_h_sse2, max3_sse2, lum8_sse2, BLOOM_ARM_OUT8(out8_sse2), "sse2"};

#else
typedef int bloom_preset_arm_sse2_unused_t;
#endif
