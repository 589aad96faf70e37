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
/* 8 words of a table at 32-bit indices, by 8 scalar loads: the AVX2
 * gather was slower than its eight loads on the CPU measured here (cod
 * preset, 1920x1080: 61 -> 45 ms a frame with this alone, sim/docs/presets/
 * cod.md "SIMD twins"), although callgrind counts a gather as one
 * instruction and these as about 25. */
#define GATHER(base, idx) bloom_gather8((const uint32_t *)(const void *)(base), (idx))
static inline __m256i bloom_gather8(const uint32_t *b, __m256i idx)
{
    uint32_t i[8];
    _mm256_storeu_si256((__m256i *)(void *)i, idx);
    return _mm256_setr_epi32((int)b[i[0]], (int)b[i[1]], (int)b[i[2]], (int)b[i[3]], (int)b[i[4]],
                             (int)b[i[5]], (int)b[i[6]], (int)b[i[7]]);
}
#define PERM(x, a, b, c, d, e, f, g, h) _mm256_permutevar8x32_epi32((x), SET8(a, b, c, d, e, f, g, h))

/* BLOOM_BOX_RND on 8 wrapping lanes: (s + 7 + ((s >> 4) & 1)) >> 4. */
static inline __m256i bloom_box_rnd8(__m256i s)
{
    const __m256i odd = _mm256_and_si256(_mm256_srli_epi32(s, 4), _mm256_set1_epi32(1));
    return _mm256_srli_epi32(_mm256_add_epi32(_mm256_add_epi32(s, _mm256_set1_epi32(7)), odd), 4);
}

/* The box's horizontal pass (bloom_row_box_avx2, and its 16-bit twins in
 * bloom_row16_avx2.c). Output pixel x, channel c is the rounded sum of the
 * column sums V (four rows added) at samples 6x - 3 + c + {0, 3, 6, 9}
 * (columns 2x - 1 .. 2x + 2). Per block of 8 pixels (24 samples, V from
 * w = V + base b = 6x - 3) the sums Y(r) = V(b + r) + V(b + r + 3) +
 * V(b + r + 6) + V(b + r + 9) are formed 8 at a time at r = 0, 8, 14, 24,
 * 31, 42 and the wanted r = 6m + c picked by permutes: fewer instructions
 * than the SSE2 twin's pairs. The sums are those of the C kernel (uint32,
 * below 2^32: bloom_row_simd.h), so the bits are. Reads w[0 .. 58]. V is
 * made once per chunk of BLOOM_BOX_CHUNK blocks into a stack row. */
#define BLOOM_BOX_CHUNK 16

static inline __m256i bloom_box_ysum(const uint32_t *v)
{
    return _mm256_add_epi32(_mm256_add_epi32(LD8(v), LD8(v + 3)), _mm256_add_epi32(LD8(v + 6), LD8(v + 9)));
}

/* Lanes of a by ia, and where the constant mask m_ has its bits, of b by
 * ib (a macro: the blend's mask must be a constant expression). */
#define PICK(a_, ia_, b_, ib_, m_)                                                                           \
    _mm256_blend_epi32(_mm256_permutevar8x32_epi32((a_), (ia_)), _mm256_permutevar8x32_epi32((b_), (ib_)),   \
                       (m_))

/* The 24 rounded sums of the block whose V starts at w. */
static inline __attribute__((always_inline)) void bloom_box_block8(const uint32_t *w, __m256i o[3])
{
    o[0] = bloom_box_rnd8(PICK(bloom_box_ysum(w), SET8(0, 1, 2, 6, 7, 0, 0, 0), bloom_box_ysum(w + 8),
                               SET8(0, 0, 0, 0, 0, 0, 4, 5), 0xE0));
    o[1] = bloom_box_rnd8(PICK(bloom_box_ysum(w + 14), SET8(0, 4, 5, 6, 0, 0, 0, 0), bloom_box_ysum(w + 24),
                               SET8(0, 0, 0, 0, 0, 1, 2, 6), 0xF0));
    o[2] = bloom_box_rnd8(PICK(bloom_box_ysum(w + 31), SET8(0, 1, 5, 6, 7, 0, 0, 0), bloom_box_ysum(w + 42),
                               SET8(0, 0, 0, 0, 0, 0, 1, 2), 0xE0));
}

/* The OR of the 8 lanes. */
static inline uint32_t or_lanes8(__m256i v)
{
    __m128i x = _mm_or_si128(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    x = _mm_or_si128(x, _mm_srli_si128(x, 8));
    x = _mm_or_si128(x, _mm_srli_si128(x, 4));
    return (uint32_t)_mm_cvtsi128_si32(x);
}

/* The 24 samples of 8 pixels (4 even/odd pairs, R G B each) in pixel
 * order, from the even columns' e[0..11] and the odd columns' o[0..11]. */
static inline void il24(const uint32_t *e, const uint32_t *o, __m256i v[3])
{
    const __m256i e0 = LD8(e), e4 = LD8(e + 4), o0 = LD8(o), o4 = LD8(o + 4);
    v[0] = _mm256_blend_epi32(PERM(e0, 0, 1, 2, 0, 0, 0, 3, 4), PERM(o0, 0, 0, 0, 0, 1, 2, 0, 0), 0x38);
    v[1] = _mm256_blend_epi32(PERM(e4, 1, 0, 0, 0, 2, 3, 4, 0), PERM(o0, 0, 3, 4, 5, 0, 0, 0, 6), 0x8E);
    v[2] = _mm256_blend_epi32(PERM(e4, 0, 0, 5, 6, 7, 0, 0, 0), PERM(o4, 3, 4, 0, 0, 0, 5, 6, 7), 0xE3);
}

#if BLOOM_USE_RGB888
/* 8 sRGB 8-bit codes at p decoded to Q12.20 (8 table loads, as GATHER). */
static inline __m256i dec8x8(const uint8_t *p)
{
    const uint32_t *d = bloom_srgb_dec8;
    return _mm256_setr_epi32((int)d[p[0]], (int)d[p[1]], (int)d[p[2]], (int)d[p[3]], (int)d[p[4]],
                             (int)d[p[5]], (int)d[p[6]], (int)d[p[7]]);
}
#endif
