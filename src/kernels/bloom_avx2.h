/* The start of a file's AVX2 code (kernels/bloom_row_avx2.c and the
 * presets' _avx2.c files), inside its BLOOM_SIMD_AVX2 guard: every function
 * up to bloom_avx2_end.h is compiled for AVX2 (a target pragma, so the rest
 * of the core stays baseline x86-64 and the file needs no special flags),
 * with the helpers these files share. Not a header to include twice. */
#include <immintrin.h>

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

#define LD8(p) _mm256_loadu_si256((const __m256i *)(const void *)(p))
#define ST8(p, v) _mm256_storeu_si256((__m256i *)(void *)(p), (v))
#define SET8(a, b, c, d, e, f, g, h) _mm256_setr_epi32(a, b, c, d, e, f, g, h)
/* 8 words of a table at 32-bit indices (a gather: on the CPU measured
 * here slower than 8 loads, although callgrind counts it as one) */
#define GATHER(base, idx) _mm256_i32gather_epi32((const int *)(const void *)(base), (idx), 4)
#define PERM(x, a, b, c, d, e, f, g, h) _mm256_permutevar8x32_epi32((x), SET8(a, b, c, d, e, f, g, h))

/* BLOOM_BOX_RND on 8 wrapping lanes: (s + 7 + ((s >> 4) & 1)) >> 4. */
static inline __m256i bloom_box_rnd8(__m256i s)
{
    const __m256i odd = _mm256_and_si256(_mm256_srli_epi32(s, 4), _mm256_set1_epi32(1));
    return _mm256_srli_epi32(_mm256_add_epi32(_mm256_add_epi32(s, _mm256_set1_epi32(7)), odd), 4);
}
