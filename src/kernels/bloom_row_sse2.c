/* SSE2 twins of the hot row kernels (x86-64, where SSE2 is baseline: no
 * run-time detection). Same bits as the C kernels of bloom_row.c; the
 * kernels are written once in bloom_row_simd.h. Empty on other targets. */
#include "bloom_kernels.h"

#if defined(BLOOM_SIMD_SSE2)
#include <string.h>

#include "bloom_simd4.h" /* LD4, ST4, bloom_box_rnd4 */

typedef __m128i VT;
#define LD2(p) _mm_loadl_epi64((const __m128i *)(const void *)(p))
#define ST2(p, v) _mm_storel_epi64((__m128i *)(void *)(p), (v))
#define ADD(a, b) _mm_add_epi32((a), (b))
#define AND(a, b) _mm_and_si128((a), (b))
#define OR(a, b) _mm_or_si128((a), (b))
#define SHL(a, n) _mm_slli_epi32((a), (n))
#define SHR(a, n) _mm_srli_epi32((a), (n))
#define DUP(c) _mm_set1_epi32((int)(c))
#define ADD_SHR3(acc, v) _mm_add_epi32((acc), _mm_srli_epi32((v), 3))

/* [e0 e1 e2 o0]: shufps moves the bits untouched. */
static inline __m128i pack_lo(__m128i e, __m128i o)
{
    const __m128 ef = _mm_castsi128_ps(e);
    const __m128 t = _mm_shuffle_ps(ef, _mm_castsi128_ps(o), _MM_SHUFFLE(0, 0, 2, 2)); /* e2 e2 o0 o0 */
    return _mm_castps_si128(_mm_shuffle_ps(ef, t, _MM_SHUFFLE(2, 0, 1, 0)));
}
#define PACK_LO(e, o) pack_lo((e), (o))
#define PACK_HI(o) _mm_srli_si128((o), 4)
#define OR_LANES(v) bloom_or_lanes4(v)

/* Whether a byte of the 30 at s[r] + off (r = 0..3) exceeds c (reads 32). */
static inline int bright30(const uint8_t *const s[4], size_t off, uint32_t c)
{
    __m128i a = LD4(s[0] + off), b = LD4(s[0] + off + 16);
    for (int r = 1; r < 4; r++) {
        a = _mm_max_epu8(a, LD4(s[r] + off));
        b = _mm_max_epu8(b, LD4(s[r] + off + 16));
    }
    b = _mm_and_si128(b, _mm_set_epi32(0x0000FFFF, -1, -1, -1));                    /* bytes 30, 31 out */
    const __m128i over = _mm_subs_epu8(_mm_max_epu8(a, b), _mm_set1_epi8((char)c)); /* 0 where <= c */
    return _mm_movemask_epi8(_mm_cmpeq_epi8(over, _mm_setzero_si128())) != 0xFFFF;
}
#define BRIGHT30(s, off, c) bright30((s), (off), (c))

/* The same over the 40 bytes of ten XRGB8888 pixels, X bytes out (reads 48). */
static inline int bright40x(const uint8_t *const s[4], size_t off, uint32_t c)
{
    __m128i a = LD4(s[0] + off), b = LD4(s[0] + off + 16), d = LD4(s[0] + off + 32);
    for (int r = 1; r < 4; r++) {
        a = _mm_max_epu8(a, LD4(s[r] + off));
        b = _mm_max_epu8(b, LD4(s[r] + off + 16));
        d = _mm_max_epu8(d, LD4(s[r] + off + 32));
    }
    const __m128i rgb = _mm_set1_epi32(0x00FFFFFF);    /* little-endian: X is the high byte */
    d = _mm_and_si128(d, _mm_set_epi32(0, 0, -1, -1)); /* bytes 40..47 out */
    const __m128i m = _mm_and_si128(_mm_max_epu8(_mm_max_epu8(a, b), d), rgb);
    const __m128i over = _mm_subs_epu8(m, _mm_set1_epi8((char)c));
    return _mm_movemask_epi8(_mm_cmpeq_epi8(over, _mm_setzero_si128())) != 0xFFFF;
}
#define BRIGHT40X(s, off, c) bright40x((s), (off), (c))

/* Whether a 5/6/5 field of the ten RGB565 pixels at s[r] + off (r = 0..3)
 * exceeds its dark code (reads 32 bytes): a saturating subtract of the
 * field's largest dark value leaves non-zero only above it. */
static inline int bright20_565(const uint8_t *const s[4], size_t off, uint32_t c5, uint32_t c6)
{
    const __m128i lr = _mm_set1_epi16((short)((c5 << 11) | 0x7FFu)), lg = _mm_set1_epi16((short)(c6 << 5));
    const __m128i lb = _mm_set1_epi16((short)c5), mg = _mm_set1_epi16(0x07E0), mb = _mm_set1_epi16(31);
    const __m128i keep2 = _mm_set_epi32(0, 0, 0, -1); /* words 8, 9 of the ten */
    __m128i o = _mm_setzero_si128();
    for (int r = 0; r < 4; r++) {
        const __m128i a = LD4(s[r] + off), b = _mm_and_si128(LD4(s[r] + off + 16), keep2);
        o = _mm_or_si128(o, _mm_or_si128(_mm_subs_epu16(a, lr), _mm_subs_epu16(b, lr)));
        o = _mm_or_si128(o, _mm_or_si128(_mm_subs_epu16(_mm_and_si128(a, mg), lg),
                                         _mm_subs_epu16(_mm_and_si128(b, mg), lg)));
        o = _mm_or_si128(o, _mm_or_si128(_mm_subs_epu16(_mm_and_si128(a, mb), lb),
                                         _mm_subs_epu16(_mm_and_si128(b, mb), lb)));
    }
    return _mm_movemask_epi8(_mm_cmpeq_epi8(o, _mm_setzero_si128())) != 0xFFFF;
}
#define BRIGHT20_565(s, off, c5, c6) bright20_565((s), (off), (c5), (c6))

#include "bloom_row_simd.h"

void bloom_row_box_sse2_any(const uint32_t *const s[4], uint32_t *dst, int dw, int sw)
{
    box_any(s, dst, dw, sw);
}

void bloom_row_tent_sse2_any(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                             int n, int sw)
{
    tent_any(u, odd, add, dst, x0, n, sw);
}

/* Lanes 0 and 2 of bl and sv (as 64-bit lanes): ((I bl + 32768) >> 16) + sv,
 * saturated to 2^32 - 1 in the low 32 bits. */
static inline __m128i comp2(__m128i bl, __m128i sv, __m128i I, __m128i rnd, __m128i zero)
{
    __m128i v = _mm_srli_epi64(_mm_add_epi64(_mm_mul_epu32(bl, I), rnd), 16);
    v = _mm_add_epi64(v, sv);
    /* high half non-zero: low half becomes all ones */
    const __m128i big = _mm_cmpeq_epi32(_mm_srli_epi64(v, 32), zero); /* low dword: ones if fits */
    return _mm_or_si128(v, _mm_andnot_si128(big, _mm_set1_epi32(-1)));
}

void bloom_row_composite_sse2_any(uint32_t *bl, const uint32_t *sv, int n, uint32_t intensity)
{
    const __m128i I = _mm_set1_epi32((int)intensity), rnd = _mm_set1_epi64x(32768);
    const __m128i zero = _mm_setzero_si128(), lo32 = _mm_set1_epi64x(0xFFFFFFFFll);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m128i b = LD4(bl + i), s = LD4(sv + i);
        const __m128i r02 = comp2(b, _mm_and_si128(s, lo32), I, rnd, zero);
        const __m128i r13 = comp2(_mm_srli_epi64(b, 32), _mm_srli_epi64(s, 32), I, rnd, zero);
        ST4(bl + i, _mm_or_si128(_mm_and_si128(r02, lo32), _mm_slli_epi64(r13, 32)));
    }
    if (i < n)
        bloom_row_composite_c(bl + i, sv + i, n - i, intensity);
}

#if !BLOOM_SMALL
bool bloom_row_d1_sse2(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                       int sw, const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp)
{
#if BLOOM_USE_RGB888 || BLOOM_USE_XRGB8888 || BLOOM_USE_RGB565
    return d1_any(s, fmt, linear, dst, dw, sw, kn, dk, kp);
#else
    return bloom_row_d1_c(s, fmt, linear, dst, dw, sw, kn, dk, kp);
#endif
}

uint32_t bloom_row_vtent_sse2(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n)
{
    return vtent_flat(a, b, c, dst, n);
}

uint32_t bloom_row_htent_eo_sse2(const uint32_t *v, uint32_t *e, uint32_t *o, int n)
{
    return htent_eo_flat(v, e, o, n);
}

/* x = low 32 bits of (I x + 32768) >> 16: even and odd lanes through
 * pmuludq, the low dwords put back together. */
void bloom_row_scale_sse2(uint32_t *x, int n, uint32_t intensity)
{
    const __m128i I = _mm_set1_epi32((int)intensity), rnd = _mm_set1_epi64x(32768);
    const __m128i lo32 = _mm_set1_epi64x(0xFFFFFFFFll);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m128i v = LD4(x + i);
        const __m128i ev = _mm_srli_epi64(_mm_add_epi64(_mm_mul_epu32(v, I), rnd), 16);
        const __m128i od = _mm_srli_epi64(_mm_add_epi64(_mm_mul_epu32(_mm_srli_epi64(v, 32), I), rnd), 16);
        ST4(x + i, _mm_or_si128(_mm_and_si128(ev, lo32), _mm_slli_epi64(od, 32)));
    }
    if (i < n)
        bloom_row_scale_c(x + i, n - i, intensity);
}
#endif

#if !BLOOM_SMALL
/* dark_blocks of bloom_row_avx2.c, 64 bytes at a time. */
static BLOOM_ALWAYS_INLINE bool dark_blocks(const uint8_t *p, int nb, bool x4, uint8_t c8, uint8_t *copy,
                                            bool store)
{
    const __m128i c = _mm_set1_epi8((char)c8), zero = _mm_setzero_si128();
    const __m128i keep = _mm_set1_epi32(x4 ? 0x00FFFFFF : -1);
    for (int i = 0;; i += 64) {
        if (i > nb - 64)
            i = nb - 64;
        const __m128i a = LD4(p + i), b = LD4(p + i + 16), e = LD4(p + i + 32), f = LD4(p + i + 48);
        const __m128i m = _mm_and_si128(_mm_max_epu8(_mm_max_epu8(a, b), _mm_max_epu8(e, f)), keep);
        if (_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_subs_epu8(m, c), zero)) != 0xFFFF)
            return false;
        if (store) { /* (a constant in each caller) */
            ST4(copy + i, a);
            ST4(copy + i + 16, b);
            ST4(copy + i + 32, e);
            ST4(copy + i + 48, f);
        }
        if (i == nb - 64)
            return true;
    }
}

/* bloom_row_dark by dark_blocks; rows of one to four vectors by one
 * vector at a time, other formats and shorter rows to the C test. */
bool bloom_row_dark_sse2(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d)
{
    const bool x4 = fmt == BLOOM_FMT_XRGB8888;
    const int nb = bloom_dark_row_bytes(fmt, n);
    if (nb < 16)
        return bloom_row_dark(fmt, p, n, d);
    if (nb >= 64)
        return dark_blocks(p, nb, x4, d->c8, NULL, false);
    __m128i m = LD4(p); /* (the arm preset's dark blocks: about 100 bytes) */
    for (int i = 16; i < nb - 16; i += 16)
        m = _mm_max_epu8(m, LD4(p + i));
    m = _mm_and_si128(_mm_max_epu8(m, LD4(p + nb - 16)), _mm_set1_epi32(x4 ? 0x00FFFFFF : -1));
    const __m128i over = _mm_subs_epu8(m, _mm_set1_epi8((char)(uint8_t)d->c8));
    return _mm_movemask_epi8(_mm_cmpeq_epi8(over, _mm_setzero_si128())) == 0xFFFF;
}

/* bloom_row_dark_copy (bloom_dark_copy_fn) by dark_blocks. */
bool bloom_row_dark_copy_sse2(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d,
                              uint8_t *copy)
{
    const int nb = bloom_dark_row_bytes(fmt, n);
    if (nb < 64)
        return bloom_row_dark_copy(fmt, p, n, d, copy);
    return dark_blocks(p, nb, fmt == BLOOM_FMT_XRGB8888, d->c8, copy, true);
}
#endif

#else
typedef int bloom_row_sse2_empty; /* ISO C wants a declaration in every file */
#endif
