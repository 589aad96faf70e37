/* AVX2 twins of the arm preset's row kernels (bloom_preset_arm.h; x86-64
 * with GCC or clang), the set the engine's AVX2 kernels go with
 * (g->kern.isa, chosen at bloom_init from the CPU). The vertical halves
 * and the up filter's horizontal half on 8 lanes, the same arithmetic as
 * the SSE2 twins (bloom_preset_arm_sse2.c: the up sums split as 64 h + l,
 * exact in 32-bit lanes); the down filter's horizontal half is the SSE2
 * one (its deinterleave does not pay on 8 lanes). Every function after the
 * target pragma is compiled for AVX2: the file needs no special flags. */
#include "bloom_preset_arm.h"

#if BLOOM_USE_ARM && defined(BLOOM_SIMD_AVX2)
#include <immintrin.h>

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

#define LD(p) _mm256_loadu_si256((const __m256i *)(const void *)(p))
#define ST(p, v) _mm256_storeu_si256((__m256i *)(void *)(p), (v))

static inline uint32_t or_lanes(__m256i v)
{
    __m128i x = _mm_or_si128(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    x = _mm_or_si128(x, _mm_shuffle_epi32(x, _MM_SHUFFLE(1, 0, 3, 2)));
    x = _mm_or_si128(x, _mm_shuffle_epi32(x, _MM_SHUFFLE(2, 3, 0, 1)));
    return (uint32_t)_mm_cvtsi128_si32(x);
}

static void down_v_avx2(const uint32_t *s0, const uint32_t *s1, const uint32_t *s2, const uint32_t *s3,
                        uint32_t *c4, uint32_t *c2, int n)
{
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i mid = _mm256_add_epi32(LD(s1 + i), LD(s2 + i));
        ST(c2 + i, mid);
        ST(c4 + i, _mm256_add_epi32(mid, _mm256_add_epi32(LD(s0 + i), LD(s3 + i))));
    }
    if (i < n)
        bloom_arm_kern_sse2.down_v(s0 + i, s1 + i, s2 + i, s3 + i, c4 + i, c2 + i, n - i);
}

static uint32_t down_h_avx2(const uint32_t *c4, const uint32_t *c2, uint32_t *dst, int n)
{
    return bloom_arm_kern_sse2.down_h(c4, c2, dst, n);
}

static void up_v_avx2(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, uint32_t *a, uint32_t *v,
                      int n)
{
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i p = LD(u0 + i), m = LD(u1 + i), q = LD(u2 + i);
        const __m256i m3 = _mm256_add_epi32(_mm256_slli_epi32(m, 1), m);
        ST(a + i, _mm256_add_epi32(p, m3));
        ST(v + i, _mm256_add_epi32(_mm256_add_epi32(_mm256_slli_epi32(p, 1), p),
                                   _mm256_add_epi32(_mm256_slli_epi32(m, 2), q)));
    }
    if (i < n)
        bloom_arm_kern_sse2.up_v(u0 + i, u1 + i, u2 + i, a + i, v + i, n - i);
}

#define X3(x) _mm256_add_epi32(_mm256_slli_epi32((x), 1), (x))
#define X11(x) _mm256_add_epi32(_mm256_add_epi32(_mm256_slli_epi32((x), 3), _mm256_slli_epi32((x), 1)), (x))
#define X28(x) _mm256_sub_epi32(_mm256_slli_epi32((x), 5), _mm256_slli_epi32((x), 2))

static inline __m256i div3(__m256i q)
{
    const __m256i k = _mm256_set1_epi32((int)0xAAAAAAABu);
    const __m256i e = _mm256_srli_epi64(_mm256_mul_epu32(q, k), 33);
    const __m256i o = _mm256_srli_epi64(_mm256_mul_epu32(_mm256_srli_epi64(q, 32), k), 33);
    return _mm256_or_si256(e, _mm256_slli_epi64(o, 32));
}

static uint32_t up_h_avx2(const uint32_t *a, const uint32_t *v, uint32_t *dst, int np)
{
    const __m256i m63 = _mm256_set1_epi32(63), k96 = _mm256_set1_epi32(96);
    __m256i any = _mm256_setzero_si256();
    int i = 0;
    for (; i + 8 <= np; i += 8) { /* reads a, v [i .. i + 9] */
        const __m256i a0 = LD(a + i), a1 = LD(a + i + 1), a2 = LD(a + i + 2);
        const __m256i v0 = LD(v + i), v1 = LD(v + i + 1), v2 = LD(v + i + 2);
        const __m256i ah0 = _mm256_srli_epi32(a0, 6), ah1 = _mm256_srli_epi32(a1, 6);
        const __m256i ah2 = _mm256_srli_epi32(a2, 6), vh0 = _mm256_srli_epi32(v0, 6);
        const __m256i vh1 = _mm256_srli_epi32(v1, 6), vh2 = _mm256_srli_epi32(v2, 6);
        const __m256i al0 = _mm256_and_si256(a0, m63), al1 = _mm256_and_si256(a1, m63);
        const __m256i al2 = _mm256_and_si256(a2, m63), vl0 = _mm256_and_si256(v0, m63);
        const __m256i vl1 = _mm256_and_si256(v1, m63), vl2 = _mm256_and_si256(v2, m63);
        const __m256i h1 = _mm256_add_epi32(X28(ah1), X3(vh1)), l1 = _mm256_add_epi32(X28(al1), X3(vl1));
        const __m256i he = _mm256_add_epi32(_mm256_add_epi32(h1, X11(ah0)), _mm256_add_epi32(ah2, vh0));
        const __m256i le = _mm256_add_epi32(_mm256_add_epi32(l1, X11(al0)),
                                            _mm256_add_epi32(al2, _mm256_add_epi32(vl0, k96)));
        const __m256i ho = _mm256_add_epi32(_mm256_add_epi32(h1, X11(ah2)), _mm256_add_epi32(ah0, vh2));
        const __m256i lo = _mm256_add_epi32(_mm256_add_epi32(l1, X11(al2)),
                                            _mm256_add_epi32(al0, _mm256_add_epi32(vl2, k96)));
        const __m256i e = div3(_mm256_add_epi32(he, _mm256_srli_epi32(le, 6)));
        const __m256i o = div3(_mm256_add_epi32(ho, _mm256_srli_epi32(lo, 6)));
        const __m256i p = _mm256_unpacklo_epi32(e, o), q = _mm256_unpackhi_epi32(e, o);
        ST(dst + 2 * i, _mm256_permute2x128_si256(p, q, 0x20));
        ST(dst + 2 * i + 8, _mm256_permute2x128_si256(p, q, 0x31));
        any = _mm256_or_si256(any, _mm256_or_si256(e, o));
    }
    uint32_t r = or_lanes(any);
    if (i < np)
        r |= bloom_arm_kern_sse2.up_h(a + i, v + i, dst + 2 * i, np - i);
    return r;
}

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

const bloom_arm_kern_t bloom_arm_kern_avx2 = {down_v_avx2, down_h_avx2, up_v_avx2, up_h_avx2, "avx2"};

#else
typedef int bloom_preset_arm_avx2_unused_t;
#endif
