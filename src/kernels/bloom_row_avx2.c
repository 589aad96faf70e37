/* AVX2 twins of the fast output path's kernels and of the tent (x86-64
 * with GCC or clang), chosen at bloom_init when the CPU and the OS support
 * AVX2 (bloom_cpu_avx2: CPUID leaves 1 and 7, XGETBV), never with
 * BLOOM_FLAG_NO_AVX2 or BLOOM_FLAG_NO_SIMD. Same bits as the C kernels;
 * every function after the target pragma is compiled for AVX2, so the rest
 * of the core stays baseline x86-64 and the file needs no special flags.
 *
 *   d1                level-1 box and knee with 8-pixel dark blocks
 *   box               box down (levels 2 ..) in blocks of 8 pixels
 *   dark              the dark-row test of pushed source rows
 *   vtent, htent_eo   the flat kernels of bloom_row_simd.h on 8 lanes
 *   tent              whole rows through vtent, htent_eo and an interleave
 *                     of the even and odd columns by lane permutes
 *   encode_eo         decode + composite + sRGB encode of RGB888 -> RGB888
 *                     and XRGB8888 -> XRGB8888 in 8-pixel groups: the
 *                     groups whose codes the bloom cannot change copied,
 *                     the others encoded sample by sample */
#include "bloom_kernels.h"
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

#include "bloom_avx2.h" /* from here on compiled for AVX2 */

/* dst[i] = (3 a[i] + 4 b[i] + c[i] + 4) >> 3 in wrapping 32-bit lanes
 * (bloom_kernels.h); returns the OR of every dst[i], and the OR of every
 * input in *in_or (the sums are exact when it is below 2^29). */
/* One vector of vtent8 at i: stored, ORed into *any (and its inputs into
 * *in when in_or). */
static inline __attribute__((always_inline)) void vtent_vec(const uint32_t *a, const uint32_t *b,
                                                            const uint32_t *c, uint32_t *dst, int i,
                                                            __m256i *any, __m256i *in, bool in_or)
{
    const __m256i va = LD8(a + i), vb = LD8(b + i), vc = LD8(c + i);
    const __m256i t =
        _mm256_add_epi32(_mm256_add_epi32(va, _mm256_slli_epi32(va, 1)), _mm256_slli_epi32(vb, 2));
    const __m256i s =
        _mm256_srli_epi32(_mm256_add_epi32(t, _mm256_add_epi32(vc, _mm256_set1_epi32(BLOOM_VT_RND))), 3);
    ST8(dst + i, s);
    *any = _mm256_or_si256(*any, s);
    if (in_or)
        *in = _mm256_or_si256(*in, _mm256_or_si256(va, _mm256_or_si256(vb, vc)));
}

static inline __attribute__((always_inline)) uint32_t
vtent8(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n, uint32_t *in_or)
{
    __m256i any = _mm256_setzero_si256(), in = _mm256_setzero_si256();
    int i = 0;
    for (; i + 8 <= n; i += 8)
        vtent_vec(a, b, c, dst, i, &any, &in, in_or != NULL);
    if (i < n && n >= 8) { /* the last 8 again (dst is not an input) */
        vtent_vec(a, b, c, dst, n - 8, &any, &in, in_or != NULL);
        i = n;
    }
    uint32_t r = or_lanes8(any), ri = or_lanes8(in);
    for (; i < n; i++) { /* n < 8 */
        dst[i] = (3u * a[i] + 4u * b[i] + c[i] + BLOOM_VT_RND) >> 3;
        r |= dst[i];
        ri |= a[i] | b[i] | c[i];
    }
    if (in_or)
        *in_or = ri;
    return r;
}

uint32_t bloom_row_vtent_avx2(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n)
{
    return vtent8(a, b, c, dst, n, NULL);
}

/* e[i] = (3 v[i-3] + 4 v[i] + v[i+3] + 3) >> 3, o[i] = (v[i-3] + 4 v[i] + 3 v[i+3] + 3) >> 3
 * (the horizontal pass rounds half down: bloom_kernels.h), samples i .. i + 7:
 * their OR. */
static inline __m256i htent_eo8(const uint32_t *v, uint32_t *e, uint32_t *o, int i)
{
    const __m256i k4 = _mm256_set1_epi32(BLOOM_HT_RND);
    const __m256i p = LD8(v + i - 3), q = LD8(v + i + 3);
    const __m256i m =
        _mm256_add_epi32(_mm256_add_epi32(_mm256_slli_epi32(LD8(v + i), 2), k4), _mm256_add_epi32(p, q));
    const __m256i ev = _mm256_srli_epi32(_mm256_add_epi32(m, _mm256_slli_epi32(p, 1)), 3);
    const __m256i ov = _mm256_srli_epi32(_mm256_add_epi32(m, _mm256_slli_epi32(q, 1)), 3);
    ST8(e + i, ev);
    ST8(o + i, ov);
    return _mm256_or_si256(ev, ov);
}

uint32_t bloom_row_htent_eo_avx2(const uint32_t *v, uint32_t *e, uint32_t *o, int n)
{
    __m256i any = _mm256_setzero_si256();
    int i = 0;
    for (; i + 8 <= n; i += 8)
        any = _mm256_or_si256(any, htent_eo8(v, e, o, i));
    if (i < n && n >= 8) /* the tail: a block overlapping the last (e, o are not v) */
        any = _mm256_or_si256(any, htent_eo8(v, e, o, n - 8));
    else if (i < n)
        return bloom_row_htent_eo_sse2(v + i, e + i, o + i, n - i);
    return or_lanes8(any);
}

/* bloom_row_il_add_c over the first 8 nb pixels (e and o alternate from
 * their first column). */
static void il_add_blocks(const uint32_t *e, const uint32_t *o, const uint32_t *add, uint32_t *dst, int nb)
{
    for (; nb > 0; nb--, e += 12, o += 12, dst += 24) {
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
}

/* bloom_row_il_add_c in groups of 8 pixels. */
static void il_add(const uint32_t *e, const uint32_t *o, const uint32_t *add, uint32_t *dst, int n)
{
    bloom_il_add_by8(il_add_blocks, e, o, add, dst, n);
}

static uint32_t vtent_in(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n,
                         uint32_t *in_or)
{
    return vtent8(a, b, c, dst, n, in_or);
}

/* bloom_row_tent_sse2_any through the flat kernels for whole rows. */
void bloom_row_tent_avx2(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                         int n, int sw)
{
    bloom_row_tent_flat(u, odd, add, dst, x0, n, sw, vtent_in, bloom_row_htent_eo_avx2, il_add,
                        bloom_row_tent_sse2_any);
}

/* ---- level-1 row: box from the source and knee, dark blocks skipped ------ */

/* Whether a colour byte of the 18 pixels of bpp bytes at s[r] + off
 * (r = 0..3) exceeds c: RGB888 54 bytes (reads 64), XRGB8888 72 bytes with
 * the X bytes left out (reads 96). */
static inline bool bright18(const uint8_t *const s[4], size_t off, bool x8, __m256i c)
{
    const int nv = x8 ? 3 : 2;
    __m256i m[3];
    for (int k = 0; k < nv; k++) {
        m[k] = LD8(s[0] + off + 32u * (size_t)k);
        for (int r = 1; r < 4; r++)
            m[k] = _mm256_max_epu8(m[k], LD8(s[r] + off + 32u * (size_t)k));
    }
    __m256i a;
    if (x8) { /* bytes 72..95 out, X bytes (the high byte of each word) out */
        const __m256i keep3 = _mm256_setr_epi32(0x00FFFFFF, 0x00FFFFFF, 0, 0, 0, 0, 0, 0);
        a = _mm256_max_epu8(_mm256_max_epu8(m[0], m[1]), _mm256_and_si256(m[2], keep3));
        a = _mm256_and_si256(a, _mm256_set1_epi32(0x00FFFFFF));
    } else { /* bytes 54..63 out */
        const __m256i keep2 = _mm256_setr_epi32(-1, -1, -1, -1, -1, 0x0000FFFF, 0, 0);
        a = _mm256_max_epu8(m[0], _mm256_and_si256(m[1], keep2));
    }
    return !_mm256_testz_si256(_mm256_subs_epu8(a, c), _mm256_set1_epi8(-1));
}

/* bloom_row_d1_sse2 in blocks of 8 level-1 pixels (RGB888 and XRGB8888;
 * the others go to the SSE2 twin): a block whose 4 x 18 source pixels have
 * no colour code above the dark code is written as zeros, the others run
 * the C box and knee in runs. */
bool bloom_row_d1_avx2(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                       int sw, const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp)
{
    const bool x8 = BLOOM_USE_XRGB8888 && fmt == BLOOM_FMT_XRGB8888;
    if (!(BLOOM_USE_RGB888 && fmt == BLOOM_FMT_RGB888) && !x8)
        return bloom_row_d1_sse2(s, fmt, linear, dst, dw, sw, kn, dk, kp);
    const size_t bpp = x8 ? 4u : 3u, rd = x8 ? 96u : 64u, row = (size_t)sw * bpp;
    const __m256i c = _mm256_set1_epi8((char)dk->c8), zero = _mm256_setzero_si256();
    bool any = false;
    int run = 0; /* first pixel not written yet */
    int x = 1;
    for (; x + 8 <= dw && (size_t)(2 * x - 1) * bpp + rd <= row; x += 8) {
        if (bright18(s, (size_t)(2 * x - 1) * bpp, x8, c))
            continue; /* computed with its run */
        if (run < x) {
            bloom_row_box_src_kept_c(s, fmt, linear, dst, run, x, sw, kp);
            any = bloom_row_knee_c(dst + (size_t)run * 3u, x - run, kn) || any;
        }
        uint32_t *d = dst + (size_t)x * 3u;
        ST8(d, zero);
        ST8(d + 8, zero);
        ST8(d + 16, zero);
        run = x + 8;
    }
    if (run < dw) {
        bloom_row_box_src_kept_c(s, fmt, linear, dst, run, dw, sw, kp);
        any = bloom_row_knee_c(dst + (size_t)run * 3u, dw - run, kn) || any;
    }
    return any;
}

/* The codes of the 8 source bytes at p, one per lane. */
static inline __m256i codes8(const uint8_t *p)
{
    return _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)p));
}

/* All ones in the lanes whose code the bloom b cannot change: b at most
 * max(BLOOM_KEEP8_A c, BLOOM_KEEP8_H0) (bloom_kernels.h). */
static inline __m256i keep8(__m256i code, __m256i b)
{
    const __m256i lb = _mm256_max_epu32(_mm256_mullo_epi32(code, _mm256_set1_epi32(BLOOM_KEEP8_A)),
                                        _mm256_set1_epi32(BLOOM_KEEP8_H0));
    return _mm256_cmpeq_epi32(_mm256_min_epu32(b, lb), b);
}

/* The bloom of the 32 bytes of 8 XRGB8888 pixels (B G R X each) as four
 * vectors, from e[0..11] and o[0..11]; the X lanes hold a copy of R. */
static inline void il32x(const uint32_t *e, const uint32_t *o, __m256i v[4])
{
    const __m256i e0 = LD8(e), e3 = LD8(e + 3), e4 = LD8(e + 4), o0 = LD8(o), o3 = LD8(o + 3),
                  o4 = LD8(o + 4);
    v[0] = _mm256_blend_epi32(PERM(e0, 2, 1, 0, 0, 0, 0, 0, 0), PERM(o0, 0, 0, 0, 0, 2, 1, 0, 0), 0xF0);
    v[1] = _mm256_blend_epi32(PERM(e3, 2, 1, 0, 0, 0, 0, 0, 0), PERM(o3, 0, 0, 0, 0, 2, 1, 0, 0), 0xF0);
    v[2] = _mm256_blend_epi32(PERM(e4, 4, 3, 2, 2, 0, 0, 0, 0), PERM(o4, 0, 0, 0, 0, 4, 3, 2, 2), 0xF0);
    v[3] = _mm256_blend_epi32(PERM(e4, 7, 6, 5, 5, 0, 0, 0, 0), PERM(o4, 0, 0, 0, 0, 7, 6, 5, 5), 0xF0);
}

/* The fused composite and encode in groups of 8 pixels: the bloom
 * interleaved into pixel order by permutes; a group where the bloom
 * changes no code (keep8 in every lane) is the source copied; the others
 * are encoded sample by sample (the table reads stay scalar: on the CPU
 * this was measured on, AVX2 gathers were slower than scalar loads). */
void bloom_encode_eo_avx2(bloom_format_t in_fmt, bloom_format_t out_fmt, bool debug, const uint8_t *src,
                          const uint32_t *e, const uint32_t *o, uint8_t *dst, int n)
{
    const int gbpp = bloom_eo_group_bpp(in_fmt, out_fmt, debug, n);
    if (!gbpp) {
        bloom_encode_eo(in_fmt, out_fmt, debug, src, e, o, dst, n);
        return;
    }
    const bool rgb = gbpp == 3; /* else XRGB8888 */
    const int g = n / 8;        /* groups of 8 pixels: 12 bloom samples of e and of o each */
    uint32_t bb[32];
    const __m256i top = _mm256_set1_epi32((int)bloom_srgb_enc8[255]); /* (bloom_fenc8w) */
    if (rgb) {
        for (int j = 0; j < g; j++, src += 24, dst += 24, e += 12, o += 12) {
            __m256i b[3];
            il24(e, o, b);
            const __m256i keep =
                _mm256_and_si256(_mm256_and_si256(keep8(codes8(src), b[0]), keep8(codes8(src + 8), b[1])),
                                 keep8(codes8(src + 16), b[2]));
            if (_mm256_movemask_epi8(keep) == -1) { /* the bloom changes no code here */
                if (src != dst)
                    memcpy(dst, src, 24);
                continue;
            }
            for (int k = 0; k < 3; k++)
                ST8(bb + 8 * k, _mm256_min_epu32(b[k], top));
            bloom_enc8_run24(src, bb, dst);
        }
    } else {
        const __m256i xlanes = _mm256_setr_epi32(0, 0, 0, -1, 0, 0, 0, -1);
        for (int j = 0; j < g; j++, src += 32, dst += 32, e += 12, o += 12) {
            __m256i b[4];
            il32x(e, o, b);
            __m256i keep = _mm256_set1_epi32(-1);
            for (int k = 0; k < 4; k++) /* the X lanes count as kept */
                keep = _mm256_and_si256(keep, _mm256_or_si256(keep8(codes8(src + 8 * k), b[k]), xlanes));
            if (_mm256_movemask_epi8(keep) != -1) {
                for (int k = 0; k < 4; k++)
                    ST8(bb + 8 * k, _mm256_min_epu32(b[k], top));
                bloom_enc8_xrgb8(src, bb, dst);
            } else { /* the bloom changes no code here: the source, X = 0xFF */
                ST8(dst, _mm256_or_si256(LD8(src), _mm256_set1_epi32((int)0xFF000000u)));
            }
        }
    }
    if (n > 8 * g)
        bloom_encode_eo(in_fmt, out_fmt, false, src, e, o, dst, n - 8 * g);
}

/* ---- box down (levels 2 ..): column sums, then four of them ------------- */

/* k <= BLOOM_BOX_CHUNK blocks of 8 pixels from x >= 1 (no clamp on the
 * left): reads V from b = 6x - 3 up to b + 48 (k - 1) + 58, made 8 at a
 * time, so sources up to 6x + 48 (k - 1) + 62. */
static void box_blocks(const uint32_t *const s[4], uint32_t *dst, int x, int k)
{
    uint32_t v[BLOOM_BOX_CHUNK * 48 + 16];
    const size_t b = (size_t)(6 * x - 3);
    const int nv = (48 * (k - 1) + 59 + 7) / 8;
    for (int i = 0; i < nv; i++) {
        const size_t o = b + 8u * (size_t)i;
        ST8(v + 8 * i, _mm256_add_epi32(_mm256_add_epi32(LD8(s[0] + o), LD8(s[1] + o)),
                                        _mm256_add_epi32(LD8(s[2] + o), LD8(s[3] + o))));
    }
    uint32_t *d = dst + 3u * (size_t)x;
    for (int q = 0; q < k; q++, d += 24) {
        __m256i o[3];
        bloom_box_block8(v + 48 * q, o);
        ST8(d, o[0]);
        ST8(d + 8, o[1]);
        ST8(d + 16, o[2]);
    }
}

void bloom_row_box_avx2(const uint32_t *const s[4], uint32_t *dst, int dw, int sw)
{
    /* blocks start at x = 1 (no clamp on the left) and read sources up to
     * 6x + 62 < 3 sw (the last block x <= xr) */
    const int xa = 1, xr = (3 * sw - 63) / 6;
    int nb = 0;
    if (dw >= xa + 8 && xr >= xa)
        nb = imin((dw - xa) / 8, (xr - xa) / 8 + 1);
    if (nb <= 0) {
        bloom_row_box_sse2_any(s, dst, dw, sw);
        return;
    }
    bloom_row_box_range_c(s, dst, 0, xa, sw);
    for (int j = 0; j < nb; j += BLOOM_BOX_CHUNK)
        box_blocks(s, dst, xa + 8 * j, imin(BLOOM_BOX_CHUNK, nb - j));
    int x = xa + 8 * nb;
    /* the tail (a tile's rows end anywhere): one more block, overlapping
     * the last, as far right as it reads inside the row; pixels written
     * twice get the same value (dst is not an input) */
    const int xo = imin(dw - 8, xr);
    if (xo > x - 8) {
        box_blocks(s, dst, xo, 1);
        x = xo + 8;
    }
    bloom_row_box_range_c(s, dst, x, dw, sw);
}

/* The dark-row test of RGB888 and XRGB8888 rows (X bytes cleared) of at
 * least 128 bytes, 128 at a time in address order, the last block ending
 * at the row's end (a whole number of pixels from the start: XRGB's lanes
 * stay pixels). A block with a bright byte ends it: the row is not dark,
 * and the rest of it is not read here. copy: each block found dark stored
 * there (bloom_dark_copy_fn: a dark row is then one pass over its bytes,
 * as in a copy; the test and then a copy from the cache took a cold 1080p
 * frame a fifth more time here). In order, because the row comes from
 * memory (the test is its first reader): a first load at its end cost a
 * cold frame 40 % more time than loads that the hardware prefetcher
 * follows. */
static BLOOM_ALWAYS_INLINE bool dark_blocks(const uint8_t *p, int nb, bool x4, uint8_t c8, uint8_t *copy,
                                            bool store)
{
    const __m256i c = _mm256_set1_epi8((char)c8), keep = _mm256_set1_epi32(x4 ? 0x00FFFFFF : -1);
    for (int i = 0;; i += 128) {
        if (i > nb - 128)
            i = nb - 128;
        const __m256i a = LD8(p + i), b = LD8(p + i + 32), e = LD8(p + i + 64), f = LD8(p + i + 96);
        const __m256i m =
            _mm256_and_si256(_mm256_max_epu8(_mm256_max_epu8(a, b), _mm256_max_epu8(e, f)), keep);
        const __m256i over = _mm256_subs_epu8(m, c);
        if (!_mm256_testz_si256(over, over))
            return false;
        if (store) { /* (a constant in each caller) */
            ST8(copy + i, a);
            ST8(copy + i + 32, b);
            ST8(copy + i + 64, e);
            ST8(copy + i + 96, f);
        }
        if (i == nb - 128)
            return true;
    }
}

/* bloom_row_dark by dark_blocks; rows of one to four vectors by one
 * vector at a time, other formats and shorter rows to the C test. */
bool bloom_row_dark_avx2(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d)
{
    const bool x4 = fmt == BLOOM_FMT_XRGB8888;
    const int nb = bloom_dark_row_bytes(fmt, n);
    if (nb < 32)
        return bloom_row_dark(fmt, p, n, d);
    if (nb >= 128)
        return dark_blocks(p, nb, x4, d->c8, NULL, false);
    /* (the arm preset's dark blocks: about 100 bytes) */
    __m256i m = LD8(p);
    for (int i = 32; i < nb - 32; i += 32)
        m = _mm256_max_epu8(m, LD8(p + i));
    m = _mm256_and_si256(_mm256_max_epu8(m, LD8(p + nb - 32)), _mm256_set1_epi32(x4 ? 0x00FFFFFF : -1));
    const __m256i over = _mm256_subs_epu8(m, _mm256_set1_epi8((char)(uint8_t)d->c8));
    return _mm256_testz_si256(over, over) != 0;
}

/* bloom_row_dark_copy (bloom_dark_copy_fn) by dark_blocks. */
bool bloom_row_dark_copy_avx2(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d,
                              uint8_t *copy)
{
    const int nb = bloom_dark_row_bytes(fmt, n);
    if (nb < 128)
        return bloom_row_dark_copy(fmt, p, n, d, copy);
    return dark_blocks(p, nb, fmt == BLOOM_FMT_XRGB8888, d->c8, copy, true);
}

#include "bloom_avx2_end.h"

#else
typedef int bloom_row_avx2_empty; /* ISO C wants a declaration in every file */
#endif
