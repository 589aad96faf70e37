/* NEON twins of the hot row kernels (aarch64). Same bits as the C kernels
 * of bloom_row.c; the kernels are written once in bloom_row_simd.h. Empty
 * on other targets. */
#include "bloom_kernels.h"
#include "bloom_pixel.h"

#if defined(BLOOM_SIMD_NEON)
#include <string.h>

#include "bloom_simd4.h" /* LD4, ST4, bloom_box_rnd4 */

typedef uint32x4_t VT;
#define LD2(p) vcombine_u32(vld1_u32(p), vdup_n_u32(0))
#define ST2(p, v) vst1_u32((p), vget_low_u32(v))
#define ADD(a, b) vaddq_u32((a), (b))
#define AND(a, b) vandq_u32((a), (b))
#define OR(a, b) vorrq_u32((a), (b))
#define OR_LANES(v) bloom_or_lanes4(v)
#define SHL(a, n) vshlq_n_u32((a), (n))
#define SHR(a, n) vshrq_n_u32((a), (n))
#define DUP(c) vdupq_n_u32(c)
#define ADD_SHR3(acc, v) vsraq_n_u32((acc), (v), 3)
#define PACK_LO(e, o) vsetq_lane_u32(vgetq_lane_u32((o), 0), (e), 3)
#define PACK_HI(o) vextq_u32((o), (o), 1)

/* Whether a byte of the 30 at s[r] + off (r = 0..3) exceeds c (reads 32). */
static inline int bright30(const uint8_t *const s[4], size_t off, uint32_t c)
{
    uint8x16_t a = vld1q_u8(s[0] + off), b = vld1q_u8(s[0] + off + 16);
    for (int r = 1; r < 4; r++) {
        a = vmaxq_u8(a, vld1q_u8(s[r] + off));
        b = vmaxq_u8(b, vld1q_u8(s[r] + off + 16));
    }
    static const uint8_t keep[16] = {255, 255, 255, 255, 255, 255, 255, 255,
                                     255, 255, 255, 255, 255, 255, 0,   0};
    b = vandq_u8(b, vld1q_u8(keep)); /* bytes 30, 31 out */
    return vmaxvq_u8(vmaxq_u8(a, b)) > c;
}
#define BRIGHT30(s, off, c) bright30((s), (off), (c))

/* The same over the 40 bytes of ten XRGB8888 pixels, X bytes out (reads 48). */
static inline int bright40x(const uint8_t *const s[4], size_t off, uint32_t c)
{
    uint8x16_t a = vld1q_u8(s[0] + off), b = vld1q_u8(s[0] + off + 16), d = vld1q_u8(s[0] + off + 32);
    for (int r = 1; r < 4; r++) {
        a = vmaxq_u8(a, vld1q_u8(s[r] + off));
        b = vmaxq_u8(b, vld1q_u8(s[r] + off + 16));
        d = vmaxq_u8(d, vld1q_u8(s[r] + off + 32));
    }
    static const uint8_t rgb[16] = {255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0};
    static const uint8_t lo8[16] = {255, 255, 255, 0, 255, 255, 255, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    d = vandq_u8(d, vld1q_u8(lo8)); /* bytes 40..47 out */
    return vmaxvq_u8(vandq_u8(vmaxq_u8(a, b), vld1q_u8(rgb))) > c || vmaxvq_u8(d) > c;
}
#define BRIGHT40X(s, off, c) bright40x((s), (off), (c))

/* Whether a 5/6/5 field of the ten RGB565 pixels at s[r] + off (r = 0..3)
 * exceeds its dark code (reads 32 bytes; the words are little-endian, as
 * the format). */
static inline int bright20_565(const uint8_t *const s[4], size_t off, uint32_t c5, uint32_t c6)
{
    const uint16x8_t lr = vdupq_n_u16((uint16_t)((c5 << 11) | 0x7FFu)), lg = vdupq_n_u16((uint16_t)(c6 << 5));
    const uint16x8_t lb = vdupq_n_u16((uint16_t)c5), mg = vdupq_n_u16(0x07E0), mb = vdupq_n_u16(31);
    static const uint16_t k2[8] = {0xFFFF, 0xFFFF, 0, 0, 0, 0, 0, 0}; /* words 8, 9 of the ten */
    const uint16x8_t keep2 = vld1q_u16(k2);
    uint16x8_t o = vdupq_n_u16(0);
    for (int r = 0; r < 4; r++) {
        const uint16x8_t a = vreinterpretq_u16_u8(vld1q_u8(s[r] + off));
        const uint16x8_t b = vandq_u16(vreinterpretq_u16_u8(vld1q_u8(s[r] + off + 16)), keep2);
        o = vorrq_u16(o, vorrq_u16(vqsubq_u16(a, lr), vqsubq_u16(b, lr)));
        o = vorrq_u16(o, vorrq_u16(vqsubq_u16(vandq_u16(a, mg), lg), vqsubq_u16(vandq_u16(b, mg), lg)));
        o = vorrq_u16(o, vorrq_u16(vqsubq_u16(vandq_u16(a, mb), lb), vqsubq_u16(vandq_u16(b, mb), lb)));
    }
    return vmaxvq_u16(o) != 0;
}
#define BRIGHT20_565(s, off, c5, c6) bright20_565((s), (off), (c5), (c6))

#include "bloom_row_simd.h"

void bloom_row_box_neon_any(const uint32_t *const s[4], uint32_t *dst, int dw, int sw)
{
    box_any(s, dst, dw, sw);
}

void bloom_row_tent_neon_any(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                             int n, int sw)
{
    tent_any(u, odd, add, dst, x0, n, sw);
}

/* ((I bl + 32768) >> 16) + sv: a rounding shift-accumulate in 64 bits,
 * then a saturating narrow to 32 bits. */
void bloom_row_composite_neon_any(uint32_t *bl, const uint32_t *sv, int n, uint32_t intensity)
{
    const uint32x2_t I = vdup_n_u32(intensity);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const uint32x4_t b = vld1q_u32(bl + i), s = vld1q_u32(sv + i);
        const uint64x2_t lo = vrsraq_n_u64(vmovl_u32(vget_low_u32(s)), vmull_u32(vget_low_u32(b), I), 16);
        const uint64x2_t hi = vrsraq_n_u64(vmovl_u32(vget_high_u32(s)), vmull_u32(vget_high_u32(b), I), 16);
        vst1q_u32(bl + i, vcombine_u32(vqmovn_u64(lo), vqmovn_u64(hi)));
    }
    if (i < n)
        bloom_row_composite_c(bl + i, sv + i, n - i, intensity);
}

#if !BLOOM_SMALL
bool bloom_row_d1_neon(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                       int sw, const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp)
{
#if BLOOM_USE_RGB888 || BLOOM_USE_XRGB8888 || BLOOM_USE_RGB565
    return d1_any(s, fmt, linear, dst, dw, sw, kn, dk, kp);
#else
    return bloom_row_d1_c(s, fmt, linear, dst, dw, sw, kn, dk, kp);
#endif
}

uint32_t bloom_row_vtent_neon(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n)
{
    return vtent_flat(a, b, c, dst, n);
}

uint32_t bloom_row_htent_eo_neon(const uint32_t *v, uint32_t *e, uint32_t *o, int n)
{
    return htent_eo_flat(v, e, o, n);
}

/* vtent_flat that also ORs its inputs into *in_or (bloom_row_tent_flat). */
static uint32_t vtent_in(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n,
                         uint32_t *in_or)
{
    uint32x4_t any = vdupq_n_u32(0), in = vdupq_n_u32(0);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const uint32x4_t va = vld1q_u32(a + i), vb = vld1q_u32(b + i), vc = vld1q_u32(c + i);
        const uint32x4_t t = vaddq_u32(vaddq_u32(va, vshlq_n_u32(va, 1)), vshlq_n_u32(vb, 2));
        const uint32x4_t r = vshrq_n_u32(vaddq_u32(t, vaddq_u32(vc, vdupq_n_u32(BLOOM_VT_RND))), 3);
        vst1q_u32(dst + i, r);
        any = vorrq_u32(any, r);
        in = vorrq_u32(in, vorrq_u32(va, vorrq_u32(vb, vc)));
    }
    uint32_t ri = bloom_or_lanes4(in), r = bloom_or_lanes4(any);
    for (; i < n; i++) {
        dst[i] = (3u * a[i] + 4u * b[i] + c[i] + BLOOM_VT_RND) >> 3;
        r |= dst[i];
        ri |= a[i] | b[i] | c[i];
    }
    *in_or = ri;
    return r;
}

/* bloom_row_il_add_c over the first 8 nb pixels: the R, G, B planes of
 * the even and the odd columns (vld3) zipped into pixel order, stored by
 * vst3. */
static void il_add_blocks(const uint32_t *e, const uint32_t *o, const uint32_t *add, uint32_t *dst, int nb)
{
    for (; nb > 0; nb--, e += 12, o += 12, dst += 24) {
        const uint32x4x3_t ev = vld3q_u32(e), ov = vld3q_u32(o);
        uint32x4x3_t lo, hi;
        for (int c = 0; c < 3; c++) {
            lo.val[c] = vzip1q_u32(ev.val[c], ov.val[c]);
            hi.val[c] = vzip2q_u32(ev.val[c], ov.val[c]);
        }
        if (add) {
            const uint32x4x3_t a0 = vld3q_u32(add), a1 = vld3q_u32(add + 12);
            for (int c = 0; c < 3; c++) {
                lo.val[c] = vaddq_u32(lo.val[c], a0.val[c]);
                hi.val[c] = vaddq_u32(hi.val[c], a1.val[c]);
            }
            add += 24;
        }
        vst3q_u32(dst, lo);
        vst3q_u32(dst + 12, hi);
    }
}

/* bloom_row_il_add_c in groups of 8 pixels. */
static void il_add(const uint32_t *e, const uint32_t *o, const uint32_t *add, uint32_t *dst, int n)
{
    bloom_il_add_by8(il_add_blocks, e, o, add, dst, n);
}

void bloom_row_tent_neon_flat(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                              int n, int sw)
{
    bloom_row_tent_flat(u, odd, add, dst, x0, n, sw, vtent_in, bloom_row_htent_eo_neon, il_add,
                        bloom_row_tent_neon_any);
}

/* All ones in the lanes whose code c the bloom b cannot change
 * (b <= max(BLOOM_KEEP8_A c, BLOOM_KEEP8_H0), bloom_kernels.h). */
static inline uint32x4_t keep4(uint32x4_t c, uint32x4_t b)
{
    return vcleq_u32(b, vmaxq_u32(vmulq_n_u32(c, BLOOM_KEEP8_A), vdupq_n_u32(BLOOM_KEEP8_H0)));
}

/* The 8 codes of a plane (pixels 0..7) as two vectors of 32-bit lanes. */
static inline void widen8(uint8x8_t p, uint32x4_t *lo, uint32x4_t *hi)
{
    const uint16x8_t w = vmovl_u8(p);
    *lo = vmovl_u16(vget_low_u16(w));
    *hi = vmovl_high_u16(w);
}

/* The fused composite and encode (bloom_encode_eo) in groups of 8 pixels,
 * RGB888 -> RGB888 and XRGB8888 -> XRGB8888: the bloom's R, G, B planes
 * of the even and odd columns zipped into pixel order; a group where the
 * bloom changes no code is the source copied, the others are encoded
 * sample by sample (the table reads stay scalar). */
void bloom_encode_eo_neon(bloom_format_t in_fmt, bloom_format_t out_fmt, bool debug, const uint8_t *src,
                          const uint32_t *e, const uint32_t *o, uint8_t *dst, int n)
{
    const int gbpp = bloom_eo_group_bpp(in_fmt, out_fmt, debug, n);
    if (!gbpp) {
        bloom_encode_eo(in_fmt, out_fmt, debug, src, e, o, dst, n);
        return;
    }
    const bool rgb = gbpp == 3, xrgb = gbpp == 4;
    const int g = n / 8;
    const size_t bpp = (size_t)gbpp;
    uint32_t bb[32];
    const uint32x4_t top = vdupq_n_u32(bloom_srgb_enc8[255]);
    for (int j = 0; j < g; j++, src += 8 * bpp, dst += 8 * bpp, e += 12, o += 12) {
        const uint32x4x3_t ev = vld3q_u32(e), ov = vld3q_u32(o);
        uint32x4_t blo[3], bhi[3]; /* R, G, B of pixels 0..3 and 4..7 */
        for (int c = 0; c < 3; c++) {
            blo[c] = vzip1q_u32(ev.val[c], ov.val[c]);
            bhi[c] = vzip2q_u32(ev.val[c], ov.val[c]);
        }
        uint8x8_t code[3]; /* R, G, B planes of the source */
        uint8x8x4_t px;
        if (rgb) {
            const uint8x8x3_t p3 = vld3_u8(src);
            for (int c = 0; c < 3; c++)
                code[c] = p3.val[c];
        } else {
            px = vld4_u8(src); /* B G R X */
            for (int c = 0; c < 3; c++)
                code[c] = px.val[2 - c];
        }
        uint32x4_t keep = vdupq_n_u32(0xFFFFFFFFu);
        for (int c = 0; c < 3; c++) {
            uint32x4_t clo, chi;
            widen8(code[c], &clo, &chi);
            keep = vandq_u32(keep, vandq_u32(keep4(clo, blo[c]), keep4(chi, bhi[c])));
        }
        if (vminvq_u32(keep) == 0xFFFFFFFFu) { /* the bloom changes no code here */
            if (xrgb) {
                px.val[3] = vdup_n_u8(0xFF);
                vst4_u8(dst, px);
            } else if (src != dst) {
                memcpy(dst, src, 24);
            }
            continue;
        }
        for (int c = 0; c < 3; c++) { /* (bloom_fenc8w) */
            blo[c] = vminq_u32(blo[c], top);
            bhi[c] = vminq_u32(bhi[c], top);
        }
        if (rgb) {
            const uint32x4x3_t lo = {{blo[0], blo[1], blo[2]}}, hi = {{bhi[0], bhi[1], bhi[2]}};
            vst3q_u32(bb, lo);
            vst3q_u32(bb + 12, hi);
            bloom_enc8_run24(src, bb, dst);
        } else {
            const uint32x4x4_t lo = {{blo[2], blo[1], blo[0], blo[0]}},
                               hi = {{bhi[2], bhi[1], bhi[0], bhi[0]}};
            vst4q_u32(bb, lo);
            vst4q_u32(bb + 16, hi);
            bloom_enc8_xrgb8(src, bb, dst);
        }
    }
    if (n > 8 * g)
        bloom_encode_eo(in_fmt, out_fmt, false, src, e, o, dst, n - 8 * g);
}

/* x = low 32 bits of (I x + 32768) >> 16: a widening multiply, then a
 * rounding narrowing shift (truncating, as the C twin's cast). */
void bloom_row_scale_neon(uint32_t *x, int n, uint32_t intensity)
{
    const uint32x2_t I = vdup_n_u32(intensity);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const uint32x4_t v = vld1q_u32(x + i);
        const uint32x2_t lo = vrshrn_n_u64(vmull_u32(vget_low_u32(v), I), 16);
        const uint32x2_t hi = vrshrn_n_u64(vmull_u32(vget_high_u32(v), I), 16);
        vst1q_u32(x + i, vcombine_u32(lo, hi));
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
    const uint8x16_t keep = vreinterpretq_u8_u32(vdupq_n_u32(x4 ? 0x00FFFFFFu : 0xFFFFFFFFu));
    for (int i = 0;; i += 64) {
        if (i > nb - 64)
            i = nb - 64;
        const uint8x16_t a = vld1q_u8(p + i), b = vld1q_u8(p + i + 16), e = vld1q_u8(p + i + 32),
                         f = vld1q_u8(p + i + 48);
        if (vmaxvq_u8(vandq_u8(vmaxq_u8(vmaxq_u8(a, b), vmaxq_u8(e, f)), keep)) > c8)
            return false;
        if (store) { /* (a constant in each caller) */
            vst1q_u8(copy + i, a);
            vst1q_u8(copy + i + 16, b);
            vst1q_u8(copy + i + 32, e);
            vst1q_u8(copy + i + 48, f);
        }
        if (i == nb - 64)
            return true;
    }
}

/* bloom_row_dark by dark_blocks; rows of one to four vectors by one
 * vector at a time, other formats and shorter rows to the C test. */
bool bloom_row_dark_neon(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d)
{
    const bool x4 = fmt == BLOOM_FMT_XRGB8888;
    const int nb = bloom_dark_row_bytes(fmt, n);
    if (nb < 16)
        return bloom_row_dark(fmt, p, n, d);
    if (nb >= 64)
        return dark_blocks(p, nb, x4, d->c8, NULL, false);
    uint8x16_t m = vld1q_u8(p); /* (the arm preset's dark blocks: about 100 bytes) */
    for (int i = 16; i < nb - 16; i += 16)
        m = vmaxq_u8(m, vld1q_u8(p + i));
    m = vandq_u8(vmaxq_u8(m, vld1q_u8(p + nb - 16)),
                 vreinterpretq_u8_u32(vdupq_n_u32(x4 ? 0x00FFFFFFu : 0xFFFFFFFFu)));
    return vmaxvq_u8(m) <= d->c8;
}

/* bloom_row_dark_copy (bloom_dark_copy_fn) by dark_blocks. */
bool bloom_row_dark_copy_neon(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d,
                              uint8_t *copy)
{
    const int nb = bloom_dark_row_bytes(fmt, n);
    if (nb < 64)
        return bloom_row_dark_copy(fmt, p, n, d, copy);
    return dark_blocks(p, nb, fmt == BLOOM_FMT_XRGB8888, d->c8, copy, true);
}
#endif

#else
typedef int bloom_row_neon_empty; /* ISO C wants a declaration in every file */
#endif
