/* SSE2 twins of the arm preset's row kernels (bloom_preset_arm.h; x86-64,
 * where SSE2 is baseline): bloom_preset_arm_simd.h on 4 lanes, with the
 * operations below. Same bits as the C kernels (bloom_preset_arm_kern.c;
 * the template says why): q / 3 = (q * 0xAAAAAAAB) >> 33 by pmuludq
 * (32 x 32 -> 64), as in C; the maximum by a signed compare (samples
 * <= M < 2^31). The 8-bit luminance and output stay C (table reads).
 * Empty on other targets. */
#include "bloom_preset_arm.h"

#if BLOOM_USE_ARM && defined(BLOOM_SIMD_SSE2)
#include "bloom_simd4.h"

/* The even and the odd words of p[0 .. 7] (the deinterleave of NEON's
 * vld2q_u32). */
typedef struct {
    __m128i val[2];
} arm_m128x2_t;
static inline arm_m128x2_t ld2(const uint32_t *p)
{
    const __m128 lo = _mm_castsi128_ps(LD4(p)), hi = _mm_castsi128_ps(LD4(p + 4));
    const arm_m128x2_t r = {{_mm_castps_si128(_mm_shuffle_ps(lo, hi, _MM_SHUFFLE(2, 0, 2, 0))),
                             _mm_castps_si128(_mm_shuffle_ps(lo, hi, _MM_SHUFFLE(3, 1, 3, 1)))}};
    return r;
}

#define X3(x) _mm_add_epi32(_mm_slli_epi32((x), 1), (x))
#define X4(x) _mm_slli_epi32((x), 2)
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

/* The samples are <= M < 2^31: the signed compare orders them. */
static inline __m128i max_s(__m128i a, __m128i b)
{
    const __m128i gt = _mm_cmpgt_epi32(a, b);
    return _mm_or_si128(_mm_and_si128(gt, a), _mm_andnot_si128(gt, b));
}

static inline uint32_t max_lanes(__m128i m)
{
    m = max_s(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = max_s(m, _mm_shuffle_epi32(m, _MM_SHUFFLE(2, 3, 0, 1)));
    return (uint32_t)_mm_cvtsi128_si32(m);
}

/* e0 o0 e1 o1 .. e3 o3 at p */
static inline void st2(uint32_t *p, __m128i e, __m128i o)
{
    ST4(p, _mm_unpacklo_epi32(e, o));
    ST4(p + 4, _mm_unpackhi_epi32(e, o));
}

/* down_v, down_h, up_v, up_h, max3: bloom_preset_arm_simd.h on 4 lanes */
#define VT __m128i
#define W 4
#define LDV LD4
#define STV ST4
#define ADDV _mm_add_epi32
#define ANDV _mm_and_si128
#define ORV _mm_or_si128
#define SHLV _mm_slli_epi32
#define SHRV _mm_srli_epi32
#define DUPV(c) _mm_set1_epi32((int)(c))
/* the even and odd sums share 28 x1 + 3 y1 */
#define MLAV(a, x, k) _mm_add_epi32((a), X##k(x))
#define SUM5(x0, x1, x2, y0, y1)                                                                             \
    _mm_add_epi32(_mm_add_epi32(_mm_add_epi32(X28(x1), X3(y1)), X11(x0)), _mm_add_epi32((x2), (y0)))
#define DIV3 div3
#define MAXV max_s
#define MAX_LANES max_lanes
#define OR_LANES bloom_or_lanes4
#define ST2V st2
#define VT2 arm_m128x2_t
#define LD2V ld2
#define ARM_TAIL bloom_arm_kern_c
#define ARM_FN(f) f##_sse2
#include "bloom_preset_arm_simd.h"

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
