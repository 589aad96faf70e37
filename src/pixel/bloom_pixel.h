/* The pixel formats (pixel/): the sRGB tables, the fixed-point helpers the
 * curves need, pixel access, and decoding one pixel of each format to
 * Q12.20 samples, inline, so that the row loops of bloom_pixel.c and
 * bloom_row.c specialize per format and curve (`lin` is a constant at every
 * call site). */
#ifndef BLOOM_PIXEL_H
#define BLOOM_PIXEL_H

#include <string.h>

#include "bloom_internal.h"

/* The largest internal sample: the API's largest linear value (decoding
 * clamps RGBQ16 words to it). */
#define BLOOM_LIN_MAX (BLOOM_MAX_LINEAR << BLOOM_Q16_SHIFT) /* 2^28 - 16 at 20 bits */

/* Internal -> Q16.16, round half to even (the value was rounded before:
 * half up here would put every tie on the same side). */
static inline uint32_t bloom_lin_to_q16(uint32_t v)
{
#if BLOOM_Q16_SHIFT == 0
    return v;
#else
    const uint32_t q = v >> BLOOM_Q16_SHIFT, r = v & ((1u << BLOOM_Q16_SHIFT) - 1u);
    const uint32_t h = 1u << (BLOOM_Q16_SHIFT - 1);
    return q + (uint32_t)(r > h || (r == h && (q & 1u)));
#endif
}

extern const uint32_t bloom_srgb_dec8[256], bloom_srgb_dec6[64], bloom_srgb_dec5[32];
extern const uint32_t bloom_srgb_enc8[256], bloom_srgb_enc6[64], bloom_srgb_enc5[32];
extern const uint8_t bloom_srgb_bkt8[4097], bloom_srgb_bkt6[1025], bloom_srgb_bkt5[513];
extern const uint8_t bloom_srgb_bkt8w[8192]; /* (gen_tables: the SIMD encoders' wide buckets) */

/* Largest codes (or Q16 word) that decode to a value the knee zeroes: a
 * source row with no channel above them is dark. An engine has one input
 * format, so for RGBF32 input q16 holds the bits of the largest such float
 * instead (positive floats order as their bits). */
typedef struct {
    uint32_t c8, c6, c5, q16;
} bloom_dark_t;

/* floor(n / d) where the quotient is known to fit in 32 bits: a native
 * divide on 64-bit hosts (inline: the knee calls it twice a pixel), the
 * shift-subtract loop elsewhere (no __aeabi_uldivmod on Cortex-M). */
#if UINTPTR_MAX > 0xFFFFFFFFu
static inline uint32_t bloom_div_u64_u32(uint64_t n, uint32_t d)
{
    return (uint32_t)(n / d);
}
#else
uint32_t bloom_div_u64_u32(uint64_t n, uint32_t d);
#endif
/* The portable shift-subtract loop behind it (tested against '/'). */
uint32_t bloom_div_u64_u32_loop(uint64_t n, uint32_t d);
/* srgb_to_linear of a gamma-space Q16.16 value, integer only. */
uint32_t bloom_srgb_to_linear_q16(uint32_t i);

/* Pixel access (bloom_pixel.c). */
void bloom_pixel_decode(bloom_format_t fmt, bool linear, const uint8_t *p, uint32_t rgb[3]);
/* Whether no channel of the n pixels exceeds the dark codes. */
bool bloom_row_dark(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d);
/* The same, the row's bytes copied to `copy` when it is dark (the C one of
 * bloom_dark_copy_fn, bloom_kernels.h: the frame call's dark rows). */
bool bloom_row_dark_copy(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d, uint8_t *copy);
void bloom_pixel_encode(bloom_format_t fmt, bool linear, const uint32_t v[3], uint8_t *p);

#if defined(__GNUC__) && !BLOOM_SMALL
#define BLOOM_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define BLOOM_ALWAYS_INLINE inline
#endif
#if defined(__GNUC__)
#define BLOOM_NOINLINE __attribute__((noinline))
#else
#define BLOOM_NOINLINE
#endif

/* Linear decode: round(c / n * 2^F); n is odd, so there is no tie. */
static inline uint32_t bloom_dec_linear(uint32_t c, uint32_t n)
{
    return (c * BLOOM_LIN_ONE + (n - 1u) / 2u) / n;
}

static inline void bloom_dec3(uint32_t r, uint32_t g, uint32_t b, uint32_t *o, bool lin)
{
    if (lin) {
        o[0] = bloom_dec_linear(r, 255);
        o[1] = bloom_dec_linear(g, 255);
        o[2] = bloom_dec_linear(b, 255);
    } else {
        o[0] = bloom_srgb_dec8[r];
        o[1] = bloom_srgb_dec8[g];
        o[2] = bloom_srgb_dec8[b];
    }
}

#define BLOOM_DEC_RGB888(p, o, lin) bloom_dec3((p)[0], (p)[1], (p)[2], (o), (lin))
#define BLOOM_DEC_XRGB8888(p, o, lin) bloom_dec3((p)[2], (p)[1], (p)[0], (o), (lin))

static inline void bloom_dec_rgb565(const uint8_t *p, uint32_t *o, bool lin)
{
    const uint32_t w = (uint32_t)p[0] | ((uint32_t)p[1] << 8);
    const uint32_t r = w >> 11, g = (w >> 5) & 63u, b = w & 31u;
    if (lin) {
        o[0] = bloom_dec_linear(r, 31);
        o[1] = bloom_dec_linear(g, 63);
        o[2] = bloom_dec_linear(b, 31);
    } else {
        o[0] = bloom_srgb_dec5[r];
        o[1] = bloom_srgb_dec6[g];
        o[2] = bloom_srgb_dec5[b];
    }
}
#define BLOOM_DEC_RGB565(p, o, lin) bloom_dec_rgb565((p), (o), (lin))

/* Linear Q16.16 words, clamped to the largest value, to Q12.20. */
static inline void bloom_dec_rgbq16(const uint8_t *p, uint32_t *o)
{
    uint32_t w[3];
    memcpy(w, p, sizeof w);
    for (int c = 0; c < 3; c++)
        o[c] = (w[c] > BLOOM_MAX_LINEAR ? BLOOM_MAX_LINEAR : w[c]) << BLOOM_Q16_SHIFT;
}
#define BLOOM_DEC_RGBQ16(p, o) bloom_dec_rgbq16((p), (o))

/* A linear IEEE-754 binary32 value, given by its bits, to Q(32-F).F with
 * integers only (no FPU at frame time): v * 2^F rounded half to even and
 * clamped to [0, BLOOM_LIN_MAX]. A normal v is m * 2^(e - 150) with the
 * 24-bit m (hidden bit set), so v * 2^F = m * 2^(e - 150 + F); from 256
 * up (and +Inf) the largest sample, as RGBQ16 clamps; negative values, -0,
 * NaN and subnormals (below 2^-126, far under half an LSB) give 0. The
 * positive bit patterns order as the values do, which the dark-row test
 * uses. Why the format exists: RGBQ16's step 2^-16 is coarse at the foot
 * of the sRGB curve (fixed-point.md, "Linear input"). */
static inline uint32_t bloom_f32_to_lin(uint32_t bits)
{
    if (bits >= 0x7F800000u) /* +Inf, NaN, and every negative value (sign bit) */
        return bits == 0x7F800000u ? BLOOM_LIN_MAX : 0;
    /* v * 2^F = m * 2^(t - 25) with t = e - 125 + F: one shift into 64
     * bits, then one rounding shift by 25 (half to even, no branch);
     * t <= 0 is below half an LSB (zero, subnormals), t > 32 far above 256 */
    const int t = (int)(bits >> 23) - 125 + BLOOM_LIN_BITS;
    if (t <= 0)
        return 0;
    if (t > 32)
        return BLOOM_LIN_MAX;
    const uint64_t v = (uint64_t)((bits & 0x7FFFFFu) | 0x800000u) << t;
    const uint64_t q = (v + (1u << 24) - 1u + ((v >> 25) & 1u)) >> 25;
    return q > BLOOM_LIN_MAX ? BLOOM_LIN_MAX : (uint32_t)q;
}

static inline void bloom_dec_rgbf32(const uint8_t *p, uint32_t *o)
{
    uint32_t w[3];
    memcpy(w, p, sizeof w);
    for (int c = 0; c < 3; c++)
        o[c] = bloom_f32_to_lin(w[c]);
}
#define BLOOM_DEC_RGBF32(p, o) bloom_dec_rgbf32((p), (o))

/* Rows: n pixels from src (packed) to dst (3 samples each) and back. */
void bloom_decode_row(bloom_format_t fmt, bool linear, const uint8_t *src, uint32_t *dst, int n);
void bloom_encode_row(bloom_format_t fmt, bool linear, const uint32_t *v, uint8_t *dst, int n);

#if !BLOOM_SMALL
/* The last step of the fast output path (bloom_row_out_k): output pixels
 * x = 0 .. n-1 get v = P + S, P = (x odd ? o : e)[3 (x >> 1) + ch] (the
 * bloom, already scaled by the intensity), S the decoded source pixel (0 in
 * the debug view), sRGB-encoded into dst. Formats RGB888, XRGB8888, RGB565
 * in and out (bloom_encode_eo_ok); P + S must not pass 2^32 - 1. Same
 * codes as bloom_decode_row + bloom_row_composite_c + bloom_encode_row. */
/* sRGB encode without the code bound test: v clamped to the top threshold
 * t[n] first, so the bucket code is at most n - 1 (the top threshold is not
 * at a bucket start: tests/test_simd.c checks it for the tables built in)
 * and t[c + 1] exists. Every v >= t[n] gives n, as the reference does. */
static BLOOM_ALWAYS_INLINE uint32_t bloom_enc_fast(uint32_t v, const uint8_t *bkt, int shift,
                                                   const uint32_t *t, uint32_t n)
{
    const uint32_t top = t[n], *next = t + 1;
    v = v < top ? v : top;
    const size_t c = bkt[v >> shift];
    return (uint32_t)c + (v >= next[c]);
}
#define BLOOM_FENC8(v) bloom_enc_fast(v, bloom_srgb_bkt8, BLOOM_LIN_BITS - 12, bloom_srgb_enc8, 255)
/* The same code for v < 2^BLOOM_LIN_BITS + t[255] with no clamp: the wide
 * buckets (codes capped at 254) cover twice the range. The SIMD encoders
 * clamp the bloom to t[255] = bloom_srgb_enc8[255] in vector lanes first, a
 * min per 8 samples instead of a compare and a move per sample (a bloom at
 * or above t[255] gives code 255 either way). */
static BLOOM_ALWAYS_INLINE uint32_t bloom_fenc8w(uint32_t v)
{
    const size_t c = bloom_srgb_bkt8w[v >> (BLOOM_LIN_BITS - 12)];
    return (uint32_t)c + (v >= bloom_srgb_enc8[c + 1]);
}

/* What the SIMD encoders (bloom_row_avx2.c, bloom_row_neon.c) take in
 * 8-pixel groups: the bytes per pixel, 3 for RGB888 -> RGB888 and 4 for
 * XRGB8888 -> XRGB8888; 0 sends the call to bloom_encode_eo (other format
 * pairs, the debug view, fewer than 8 pixels). */
static inline int bloom_eo_group_bpp(bloom_format_t in_fmt, bloom_format_t out_fmt, bool debug, int n)
{
    if (debug || n < 8 || in_fmt != out_fmt)
        return 0;
    if (BLOOM_USE_RGB888 && in_fmt == BLOOM_FMT_RGB888)
        return 3;
    if (BLOOM_USE_XRGB8888 && in_fmt == BLOOM_FMT_XRGB8888)
        return 4;
    return 0;
}

/* The scalar part of the SIMD encoders (bloom_row_avx2.c, bloom_row_neon.c):
 * 8 pixels whose bloom b is in the order of their bytes, each b at most
 * bloom_srgb_enc8[255] (clamped in lanes: bloom_fenc8w). RGB888:
 * dst[q] = enc(dec(src[q]) + b[q]) for the 24 bytes; XRGB8888 (B G R X):
 * the same for the colour bytes, X = 0xFF. Unrolled: 24 independent
 * table walks. */
#if defined(__clang__)
#define BLOOM_UNROLL _Pragma("clang loop unroll(full)")
#elif defined(__GNUC__)
#define BLOOM_UNROLL _Pragma("GCC unroll 24")
#else
#define BLOOM_UNROLL
#endif
static BLOOM_ALWAYS_INLINE void bloom_enc8_run24(const uint8_t *src, const uint32_t *b, uint8_t *dst)
{
    BLOOM_UNROLL
    for (int q = 0; q < 24; q++)
        dst[q] = (uint8_t)bloom_fenc8w(bloom_srgb_dec8[src[q]] + b[q]);
}
static BLOOM_ALWAYS_INLINE void bloom_enc8_xrgb8(const uint8_t *src, const uint32_t *b, uint8_t *dst)
{
    BLOOM_UNROLL
    for (int p = 0; p < 32; p += 4) {
        dst[p] = (uint8_t)bloom_fenc8w(bloom_srgb_dec8[src[p]] + b[p]);
        dst[p + 1] = (uint8_t)bloom_fenc8w(bloom_srgb_dec8[src[p + 1]] + b[p + 1]);
        dst[p + 2] = (uint8_t)bloom_fenc8w(bloom_srgb_dec8[src[p + 2]] + b[p + 2]);
        dst[p + 3] = 0xFF;
    }
}
bool bloom_encode_eo_ok(bloom_format_t in_fmt, bloom_format_t out_fmt, bool linear);
void bloom_encode_eo(bloom_format_t in_fmt, bloom_format_t out_fmt, bool debug, const uint8_t *src,
                     const uint32_t *e, const uint32_t *o, uint8_t *dst, int n);
/* The sRGB code of v by the bucket table with v clamped to the top
 * threshold first (no bound test on the code), and by the reference
 * encoder: tests compare them over every v. */
uint32_t bloom_enc_srgb_fast(uint32_t v, int bits);
uint32_t bloom_enc_srgb_ref(uint32_t v, int bits);
#endif

#endif
