/* Helpers the 4-lane twins share (SSE2 on x86-64, NEON on aarch64): the
 * presets' and the core's own (one template, bloom_row_simd.h, with its
 * operation layer in bloom_row_sse2.c and bloom_row_neon.c), for the files
 * inside their BLOOM_SIMD_SSE2 / BLOOM_SIMD_NEON guards. */
#ifndef BLOOM_SIMD4_H
#define BLOOM_SIMD4_H

#include "bloom_kernels.h"

#if defined(BLOOM_SIMD_SSE2)
#include <emmintrin.h>
#define LD4(p) _mm_loadu_si128((const __m128i *)(const void *)(p))
#define ST4(p, v) _mm_storeu_si128((__m128i *)(void *)(p), (v))
/* BLOOM_BOX_RND on 4 wrapping lanes: (s + 7 + ((s >> 4) & 1)) >> 4. */
static inline __m128i bloom_box_rnd4(__m128i s)
{
    const __m128i odd = _mm_and_si128(_mm_srli_epi32(s, 4), _mm_set1_epi32(1));
    return _mm_srli_epi32(_mm_add_epi32(_mm_add_epi32(s, _mm_set1_epi32(7)), odd), 4);
}
/* The OR of the 4 lanes (the twins' "any non-zero"). */
static inline uint32_t bloom_or_lanes4(__m128i v)
{
    v = _mm_or_si128(v, _mm_srli_si128(v, 8));
    v = _mm_or_si128(v, _mm_srli_si128(v, 4));
    return (uint32_t)_mm_cvtsi128_si32(v);
}
#elif defined(BLOOM_SIMD_NEON)
#include <arm_neon.h>
#define LD4(p) vld1q_u32(p)
#define ST4(p, v) vst1q_u32((p), (v))
static inline uint32x4_t bloom_box_rnd4(uint32x4_t s)
{
    const uint32x4_t odd = vandq_u32(vshrq_n_u32(s, 4), vdupq_n_u32(1));
    return vshrq_n_u32(vaddq_u32(vaddq_u32(s, vdupq_n_u32(7)), odd), 4);
}
/* The OR of the 4 lanes (the twins' "any non-zero"). */
static inline uint32_t bloom_or_lanes4(uint32x4_t v)
{
    const uint32x2_t t = vorr_u32(vget_low_u32(v), vget_high_u32(v));
    return vget_lane_u32(t, 0) | vget_lane_u32(t, 1);
}
#endif

#endif
