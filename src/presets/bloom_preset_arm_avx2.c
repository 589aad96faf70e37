/* AVX2 twins of the arm preset's row kernels (bloom_preset_arm.h; x86-64
 * with GCC or clang), the set the engine's AVX2 kernels go with
 * (ctx->kern.isa, chosen at bloom_init from the CPU). The vertical halves,
 * the up filter's horizontal half and the column maximum are
 * bloom_preset_arm_simd.h on 8 lanes, the body of the SSE2 and NEON twins
 * too (the up sums split as 64 h + l, exact in 32-bit lanes), their tails
 * to the SSE2 twins; the down filter's horizontal half is the SSE2 one
 * (its deinterleave does not pay on 8 lanes); the 8-bit luminance and
 * output by table gathers. Every function after the target pragma is
 * compiled for AVX2: the file needs no special flags. */
#include "bloom_preset_arm.h"
#include "bloom_pixel.h"

#if BLOOM_USE_ARM && defined(BLOOM_SIMD_AVX2)

#include "bloom_avx2.h" /* from here on compiled for AVX2 */

static uint32_t down_h_avx2(const uint32_t *c4, const uint32_t *c2, uint32_t *dst, int n)
{
    return bloom_arm_kern_sse2.down_h(c4, c2, dst, n);
}

#define X3(x) _mm256_add_epi32(_mm256_slli_epi32((x), 1), (x))
#define X4(x) _mm256_slli_epi32((x), 2)
#define X11(x) _mm256_add_epi32(_mm256_add_epi32(_mm256_slli_epi32((x), 3), _mm256_slli_epi32((x), 1)), (x))
#define X28(x) _mm256_sub_epi32(_mm256_slli_epi32((x), 5), _mm256_slli_epi32((x), 2))

static inline __m256i div3(__m256i q)
{
    const __m256i k = _mm256_set1_epi32((int)0xAAAAAAABu);
    const __m256i e = _mm256_srli_epi64(_mm256_mul_epu32(q, k), 33);
    const __m256i o = _mm256_srli_epi64(_mm256_mul_epu32(_mm256_srli_epi64(q, 32), k), 33);
    return _mm256_or_si256(e, _mm256_slli_epi64(o, 32));
}

static inline uint32_t max_lanes(__m256i m)
{
    __m128i x = _mm_max_epu32(_mm256_castsi256_si128(m), _mm256_extracti128_si256(m, 1));
    x = _mm_max_epu32(x, _mm_shuffle_epi32(x, _MM_SHUFFLE(1, 0, 3, 2)));
    x = _mm_max_epu32(x, _mm_shuffle_epi32(x, _MM_SHUFFLE(2, 3, 0, 1)));
    return (uint32_t)_mm_cvtsi128_si32(x);
}

/* e0 o0 e1 o1 .. e7 o7 at p (the unpacks work within 128-bit halves) */
static inline void st2(uint32_t *p, __m256i e, __m256i o)
{
    const __m256i lo = _mm256_unpacklo_epi32(e, o), hi = _mm256_unpackhi_epi32(e, o);
    ST8(p, _mm256_permute2x128_si256(lo, hi, 0x20));
    ST8(p + 8, _mm256_permute2x128_si256(lo, hi, 0x31));
}

/* down_v, up_v, up_h, max3: bloom_preset_arm_simd.h on 8 lanes (no LD2V:
 * down_h is the SSE2 one above); the tails to the SSE2 twins */
#define VT __m256i
#define W 8
#define LDV LD8
#define STV ST8
#define ADDV _mm256_add_epi32
#define ANDV _mm256_and_si256
#define ORV _mm256_or_si256
#define SHLV _mm256_slli_epi32
#define SHRV _mm256_srli_epi32
#define DUPV(c) _mm256_set1_epi32((int)(c))
/* the even and odd sums share 28 x1 + 3 y1 */
#define MLAV(a, x, k) _mm256_add_epi32((a), X##k(x))
#define SUM5(x0, x1, x2, y0, y1)                                                                             \
    _mm256_add_epi32(_mm256_add_epi32(_mm256_add_epi32(X28(x1), X3(y1)), X11(x0)),                           \
                     _mm256_add_epi32((x2), (y0)))
#define DIV3 div3
#define MAXV _mm256_max_epu32
#define MAX_LANES max_lanes
#define OR_LANES or_lanes8
#define ST2V st2
#define ARM_TAIL bloom_arm_kern_sse2
#define ARM_FN(f) f##_avx2
#include "bloom_preset_arm_simd.h"

/* The codes of 8 pixels at s, one per 32-bit lane, channels R, G, B:
 * XRGB8888 (B G R X) by shifts; RGB888 from the 24 bytes (two 16-byte
 * loads, bytes 0 .. 15 and 8 .. 23: pixels 0 .. 3 in the low half, 4 .. 7
 * at byte 4 of the high half) by byte shuffles. */
static inline void codes8(const uint8_t *s, bool x4, __m256i c[3])
{
    const __m256i ff = _mm256_set1_epi32(0xFF);
    if (x4) {
        const __m256i px = LD8(s);
        c[0] = _mm256_and_si256(_mm256_srli_epi32(px, 16), ff);
        c[1] = _mm256_and_si256(_mm256_srli_epi32(px, 8), ff);
        c[2] = _mm256_and_si256(px, ff);
        return;
    }
    const __m256i w =
        _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_loadu_si128((const __m128i *)(const void *)s)),
                                _mm_loadu_si128((const __m128i *)(const void *)(s + 8)), 1);
#define Z -1
    for (int k = 0; k < 3; k++) {
        const __m256i sh = _mm256_add_epi8(_mm256_setr_epi8(0, Z, Z, Z, 3, Z, Z, Z, 6, Z, Z, Z, 9, Z, Z, Z, 4,
                                                            Z, Z, Z, 7, Z, Z, Z, 10, Z, Z, Z, 13, Z, Z, Z),
                                           _mm256_and_si256(_mm256_set1_epi32(k), _mm256_set1_epi32(0xFF)));
        c[k] = _mm256_shuffle_epi8(w, sh);
    }
#undef Z
}

static inline __m256i gather(const uint32_t *tab, __m256i idx)
{
    return _mm256_i32gather_epi32((const int *)(const void *)tab, idx, 4);
}

/* Y of 8 decoded pixels: the 64-bit sums of bloom_arm_kern_c by pmuludq
 * on the even and odd lanes ((s >> 24) << 32 of an odd lane is
 * (s << 8) with its low word cleared: s < 2^53). */
static inline __m256i lum_vec(const __m256i d[3])
{
    const __m256i wr = _mm256_set1_epi32((int)BLOOM_ARM_WR), wg = _mm256_set1_epi32((int)BLOOM_ARM_WG),
                  wb = _mm256_set1_epi32((int)BLOOM_ARM_WB), h = _mm256_set1_epi64x(1 << 23);
    const __m256i se =
        _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epu32(d[0], wr), _mm256_mul_epu32(d[1], wg)),
                         _mm256_add_epi64(_mm256_mul_epu32(d[2], wb), h));
    const __m256i so =
        _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(d[0], 32), wr),
                                          _mm256_mul_epu32(_mm256_srli_epi64(d[1], 32), wg)),
                         _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(d[2], 32), wb), h));
    return _mm256_or_si256(
        _mm256_srli_epi64(se, 24),
        _mm256_and_si256(_mm256_slli_epi64(so, 8), _mm256_set1_epi64x((long long)~0xFFFFFFFFull)));
}

static void lum8_avx2(const uint8_t *p, uint32_t *c4, uint32_t *c2, int n, bool x4, int i)
{
    const size_t step = x4 ? 32u : 24u;
    int x = 0;
    for (; x + 8 <= n; x += 8, p += step) {
        __m256i c[3], d[3];
        codes8(p, x4, c);
        for (int k = 0; k < 3; k++)
            d[k] = gather(bloom_srgb_dec8, c[k]);
        const __m256i y = lum_vec(d);
        if (i == 0) {
            ST8(c4 + x, y);
        } else {
            ST8(c4 + x, _mm256_add_epi32(LD8(c4 + x), y));
            if (i == 1)
                ST8(c2 + x, y);
            else if (i == 2)
                ST8(c2 + x, _mm256_add_epi32(LD8(c2 + x), y));
        }
    }
    if (x < n)
        bloom_arm_kern_c.lum8(p, c4 + x, c2 + x, n - x, x4, i);
}

#if !BLOOM_SMALL
/* P = min((f B + 2^15) >> 16, 2^24) on 8 lanes: B first capped at the
 * least B' with P(B') >= 2^24 (then f B' < 2^40 + f, P(B') < 2^25 fits a
 * word), the products by pmuludq on the even and odd lanes. */
static inline __m256i pvec(__m256i b, __m256i f, __m256i cap)
{
    const __m256i k = _mm256_set1_epi64x(32768), top = _mm256_set1_epi32(1 << 24);
    b = _mm256_min_epu32(b, cap);
    const __m256i e = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(b, f), k), 16);
    const __m256i o = _mm256_and_si256(
        _mm256_slli_epi64(_mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(b, 32), f), k), 16),
        _mm256_set1_epi64x((long long)~0xFFFFFFFFull));
    return _mm256_min_epu32(_mm256_or_si256(e, o), top);
}

/* The 8 output codes of one channel: BLOOM_FENC8 by gathers (the bucket
 * table read as words at byte offsets, the low byte kept: v <= t[255], so
 * the word read ends inside the table, tests/test_simd_arm.c). */
static inline __m256i enc_vec(__m256i code, __m256i p)
{
    const __m256i top = _mm256_set1_epi32((int)bloom_srgb_enc8[255]);
    const __m256i v = _mm256_min_epu32(_mm256_add_epi32(gather(bloom_srgb_dec8, code), p), top);
    const __m256i c = _mm256_and_si256(_mm256_i32gather_epi32((const int *)(const void *)bloom_srgb_bkt8,
                                                              _mm256_srli_epi32(v, BLOOM_LIN_BITS - 12), 1),
                                       _mm256_set1_epi32(0xFF));
    const __m256i t = gather(bloom_srgb_enc8 + 1, c);
    return _mm256_sub_epi32(c, _mm256_cmpeq_epi32(_mm256_max_epu32(v, t), v)); /* + (v >= t) */
}

/* 8 pixels at a time: the source copied where every P_c <= max(A c, H0)
 * (BLOOM_KEEP8: the codes stay), else every sample encoded; codes packed
 * back by saturating packs (each <= 255) and a byte shuffle. */
static void out8_avx2(const uint8_t *src, const uint32_t *b, const uint32_t f[3], uint8_t *dst, int n,
                      bool x4)
{
    __m256i fv[3], cap[3];
    for (int c = 0; c < 3; c++) {
        const uint64_t lim = (1ull << 40) - 32768u; /* P >= 2^24 from B = ceil(lim / f) on */
        const uint64_t q = f[c] ? (lim + f[c] - 1u) / f[c] : 0xFFFFFFFFu;
        fv[c] = _mm256_set1_epi32((int)f[c]);
        cap[c] = _mm256_set1_epi32((int)(uint32_t)(q < 0xFFFFFFFFu ? q : 0xFFFFFFFFu));
    }
    const __m256i ka = _mm256_set1_epi32(BLOOM_KEEP8_A), kh = _mm256_set1_epi32(BLOOM_KEEP8_H0);
    const size_t step = x4 ? 32u : 24u;
    int x = 0;
    for (; x + 8 <= n; x += 8, src += step, dst += step) {
        const __m256i bv = LD8(b + x);
        __m256i code[3], p[3], keep = _mm256_set1_epi32(-1);
        codes8(src, x4, code);
        for (int c = 0; c < 3; c++) {
            p[c] = pvec(bv, fv[c], cap[c]);
            const __m256i lb = _mm256_max_epu32(_mm256_mullo_epi32(code[c], ka), kh);
            keep = _mm256_and_si256(keep, _mm256_cmpeq_epi32(_mm256_min_epu32(p[c], lb), p[c]));
        }
        const bool same = _mm256_movemask_epi8(keep) == -1; /* the bloom changes no code here */
        __m256i o[3];
        for (int c = 0; c < 3; c++)
            o[c] = same ? code[c] : enc_vec(code[c], p[c]);
        if (x4) {
            const __m256i px =
                _mm256_or_si256(_mm256_or_si256(_mm256_slli_epi32(o[0], 16), _mm256_slli_epi32(o[1], 8)),
                                _mm256_or_si256(o[2], _mm256_set1_epi32((int)0xFF000000u)));
            ST8(dst, px);
            continue;
        }
        if (same && src == dst)
            continue;
        /* bytes per half: R0..3 G0..3 B0..3 B0..3 (pixels 0..3, then 4..7) */
        const __m256i w =
            _mm256_packus_epi16(_mm256_packus_epi32(o[0], o[1]), _mm256_packus_epi32(o[2], o[2]));
#define Z -1
        const __m256i il =
            _mm256_shuffle_epi8(w, _mm256_setr_epi8(0, 4, 8, 1, 5, 9, 2, 6, 10, 3, 7, 11, Z, Z, Z, Z, 0, 4, 8,
                                                    1, 5, 9, 2, 6, 10, 3, 7, 11, Z, Z, Z, Z));
#undef Z
        const __m256i r = _mm256_permutevar8x32_epi32(il, _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 3, 7));
        _mm_storeu_si128((__m128i *)(void *)dst, _mm256_castsi256_si128(r));
        _mm_storel_epi64((__m128i *)(void *)(dst + 16), _mm256_extracti128_si256(r, 1));
    }
    if (x < n)
        bloom_arm_kern_c.out8(src, b + x, f, dst, n - x, x4);
}
#endif

#include "bloom_avx2_end.h"

const bloom_arm_kern_t bloom_arm_kern_avx2 = {
    down_v_avx2, down_h_avx2, up_v_avx2, up_h_avx2, max3_avx2, lum8_avx2, BLOOM_ARM_OUT8(out8_avx2), "avx2"};

#else
typedef int bloom_preset_arm_avx2_unused_t;
#endif
