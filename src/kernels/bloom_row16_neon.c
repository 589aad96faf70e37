/* NEON twins of the 16-bit row kernels (bloom_row16.c; aarch64), picked
 * with the NEON kernel set (bloom_row16.c's dispatch). Same bits as the C
 * kernels (tests/test_s16.c holds them equal; test-cross runs it):
 *
 *   narrow16   D_1 narrowed half to even (and with the level's D row
 *              added), 8 samples a step
 *   vtent16w   the vertical tent of 16-bit rows into 32-bit sums
 *   box16      the box of four 16-bit rows, into 16-bit samples or (wide)
 *              32-bit ones, 4 output pixels a step: vld3 splits the rows
 *              into R, G, B planes, the four rows' column sums are formed
 *              widened to 32 bits (<< sh), pairs of columns added by
 *              vpaddq, and output x is pair x plus pair x + 1 (columns
 *              2x - 1 .. 2x + 2), rounded as the 32-bit box rounds
 *   il16       the tent's last pass: even and odd columns zipped into
 *              pixel order plus the level's D row, as 16-bit samples
 *
 * Sums below 2^32 as in C (box sums < 2^20 << 9, tents < 2^19 << 9), and
 * the narrowing to 16 bits keeps the low half, as C's casts do. */
#include "bloom_kernels.h"

#if defined(BLOOM_SIMD_NEON) && BLOOM_USE_S16
#include "bloom_simd4.h" /* bloom_or_lanes4, bloom_box_rnd4 */

/* Rows of 8 or more samples end with one more vector over the last 8 (the
 * output never aliases the input, so the overlap writes the same values
 * again): no scalar tail. */
static inline int last8(int i, int n)
{
    return i < n && n >= 8 ? n - 8 : i;
}

/* (v + h + ((v >> sh) & 1)) >> sh, nsh = -sh (vshlq shifts right by it). */
static inline uint32x4_t narrow4(uint32x4_t v, uint32x4_t h, int32x4_t nsh)
{
    const uint32x4_t odd = vandq_u32(vshlq_u32(v, nsh), vdupq_n_u32(1));
    return vshlq_u32(vaddq_u32(vaddq_u32(v, h), odd), nsh);
}

uint32_t bloom_row_narrow16_neon(const uint32_t *src, uint16_t *dst, int n, int sh)
{
    const uint32x4_t h = vdupq_n_u32((1u << (sh - 1)) - 1u);
    const int32x4_t nsh = vdupq_n_s32(-sh);
    uint32x4_t any = vdupq_n_u32(0);
    int i = 0;
    for (; i < n; i += 8) {
        if (i + 8 > n && (i = last8(i, n)) + 8 != n)
            break;
        const uint32x4_t r0 = narrow4(vld1q_u32(src + i), h, nsh),
                         r1 = narrow4(vld1q_u32(src + i + 4), h, nsh);
        any = vorrq_u32(any, vorrq_u32(r0, r1));
        vst1q_u16(dst + i, vcombine_u16(vmovn_u32(r0), vmovn_u32(r1)));
    }
    uint32_t a = bloom_or_lanes4(any);
    if (i < n)
        a |= bloom_row_narrow16_c(src + i, dst + i, n - i, sh);
    return a;
}

void bloom_row_narrow16_add_neon(const uint32_t *src, const uint16_t *add, uint16_t *dst, int n, int sh)
{
    const uint32x4_t h = vdupq_n_u32((1u << (sh - 1)) - 1u);
    const int32x4_t nsh = vdupq_n_s32(-sh);
    int i = 0;
    for (; i < n; i += 8) {
        if (i + 8 > n && (i = last8(i, n)) + 8 != n)
            break;
        const uint32x4_t r0 = narrow4(vld1q_u32(src + i), h, nsh),
                         r1 = narrow4(vld1q_u32(src + i + 4), h, nsh);
        uint16x8_t r = vcombine_u16(vmovn_u32(r0), vmovn_u32(r1));
        if (add) /* modulo 2^16 as C's cast of the sum */
            r = vaddq_u16(r, vld1q_u16(add + i));
        vst1q_u16(dst + i, r);
    }
    if (i < n)
        bloom_row_narrow16_add_c(src + i, add ? add + i : NULL, dst + i, n - i, sh);
}

/* ((3a + 4b + c) << sh + BLOOM_VT_RND) >> 3 of four widened samples. */
static inline uint32x4_t vt4(uint16x4_t a, uint16x4_t b, uint16x4_t c, int32x4_t vsh)
{
    const uint32x4_t s = vaddw_u16(vmlal_n_u16(vmull_n_u16(a, 3), b, 4), c);
    return vshrq_n_u32(vaddq_u32(vshlq_u32(s, vsh), vdupq_n_u32(BLOOM_VT_RND)), 3);
}

uint32_t bloom_row_vtent16w_neon(const uint16_t *a, const uint16_t *b, const uint16_t *c, uint32_t *dst,
                                 int n, int sh)
{
    const int32x4_t vsh = vdupq_n_s32(sh);
    uint32x4_t any = vdupq_n_u32(0);
    int i = 0;
    for (; i < n; i += 8) {
        if (i + 8 > n && (i = last8(i, n)) + 8 != n)
            break;
        const uint16x8_t va = vld1q_u16(a + i), vb = vld1q_u16(b + i), vc = vld1q_u16(c + i);
        const uint32x4_t s0 = vt4(vget_low_u16(va), vget_low_u16(vb), vget_low_u16(vc), vsh);
        const uint32x4_t s1 = vt4(vget_high_u16(va), vget_high_u16(vb), vget_high_u16(vc), vsh);
        vst1q_u32(dst + i, s0);
        vst1q_u32(dst + i + 4, s1);
        any = vorrq_u32(any, vorrq_u32(s0, s1));
    }
    uint32_t r = bloom_or_lanes4(any);
    if (i < n)
        r |= bloom_row_vtent16w_c(a + i, b + i, c + i, dst + i, n - i, sh);
    return r;
}

/* Per plane, the pair sums of columns (p, p + 1), (p + 2, p + 3), ...,
 * (p + 6, p + 7) of the four rows, widened by sh; c3 = 3 p. */
static inline void pairs8(const uint16_t *const s[4], size_t c3, int32x4_t vsh, uint32x4_t pr[3])
{
    const uint16x8x3_t r0 = vld3q_u16(s[0] + c3), r1 = vld3q_u16(s[1] + c3), r2 = vld3q_u16(s[2] + c3),
                       r3 = vld3q_u16(s[3] + c3);
    for (int ch = 0; ch < 3; ch++) {
        const uint32x4_t lo = vaddq_u32(vaddl_u16(vget_low_u16(r0.val[ch]), vget_low_u16(r1.val[ch])),
                                        vaddl_u16(vget_low_u16(r2.val[ch]), vget_low_u16(r3.val[ch])));
        const uint32x4_t hi =
            vaddq_u32(vaddl_high_u16(r0.val[ch], r1.val[ch]), vaddl_high_u16(r2.val[ch], r3.val[ch]));
        pr[ch] = vshlq_u32(vpaddq_u32(lo, hi), vsh);
    }
}

/* Both boxes (d16 or d32 is NULL): blocks of 4 output pixels from x = 1
 * (no clamp on the left); block x reads source pixels 2x - 1 .. 2x + 14
 * (the next block's first pair), so it needs 2x + 14 <= sw - 1. The edges
 * and the tail in C. */
static void box16(const uint16_t *const s[4], uint16_t *d16, uint32_t *d32, int dw, int sw, int sh)
{
    void *dst = d16 ? (void *)d16 : (void *)d32;
    const int xa = 1;
    int nb = 0;
    if (sw >= 17)
        nb = imin((dw - xa) / 4, ((sw - 15) / 2 - xa) / 4 + 1);
    if (nb <= 0) {
        bloom_row_box16_range_c(s, dst, !d16, 0, dw, sw, sh);
        return;
    }
    bloom_row_box16_range_c(s, dst, !d16, 0, xa, sw, sh);
    const int32x4_t vsh = vdupq_n_s32(sh);
    uint32x4_t cur[3], nxt[3];
    pairs8(s, (size_t)(2 * xa - 1) * 3u, vsh, cur);
    for (int k = 0; k < nb; k++) {
        const int x = xa + 4 * k;
        pairs8(s, (size_t)(2 * x + 7) * 3u, vsh, nxt);
        uint32x4x3_t r;
        for (int ch = 0; ch < 3; ch++) {
            r.val[ch] = bloom_box_rnd4(vaddq_u32(cur[ch], vextq_u32(cur[ch], nxt[ch], 1)));
            cur[ch] = nxt[ch];
        }
        if (d16) {
            const uint16x4x3_t q = {{vmovn_u32(r.val[0]), vmovn_u32(r.val[1]), vmovn_u32(r.val[2])}};
            vst3_u16(d16 + 3 * x, q);
        } else {
            vst3q_u32(d32 + 3 * x, r);
        }
    }
    bloom_row_box16_range_c(s, dst, !d16, xa + 4 * nb, dw, sw, sh);
}

void bloom_row_box16_neon(const uint16_t *const s[4], uint16_t *dst, int dw, int sw)
{
    box16(s, dst, NULL, dw, sw, 0);
}

void bloom_row_box16w_neon(const uint16_t *const s[4], uint32_t *dst, int dw, int sw, int sh)
{
    box16(s, NULL, dst, dw, sw, sh);
}

void bloom_row_il16_neon(const uint32_t *e, const uint32_t *o, const uint16_t *add, uint16_t *dst, int np)
{
    int x = 0;
    for (; x + 8 <= np; x += 8) { /* 8 pixels: columns x / 2 .. x / 2 + 3 of each half */
        const uint32x4x3_t ev = vld3q_u32(e + 3 * (x >> 1)), ov = vld3q_u32(o + 3 * (x >> 1));
        uint16x4x3_t lo, hi;
        for (int c = 0; c < 3; c++) {
            lo.val[c] = vmovn_u32(vzip1q_u32(ev.val[c], ov.val[c]));
            hi.val[c] = vmovn_u32(vzip2q_u32(ev.val[c], ov.val[c]));
        }
        if (add) { /* modulo 2^16 as C's cast of the sum */
            const uint16x4x3_t a0 = vld3_u16(add + 3 * x), a1 = vld3_u16(add + 3 * x + 12);
            for (int c = 0; c < 3; c++) {
                lo.val[c] = vadd_u16(lo.val[c], a0.val[c]);
                hi.val[c] = vadd_u16(hi.val[c], a1.val[c]);
            }
        }
        vst3_u16(dst + 3 * x, lo);
        vst3_u16(dst + 3 * x + 12, hi);
    }
    bloom_row_il16_c(e, o, add, dst, x, np);
}

#else
typedef int bloom_row16_neon_empty_t; /* (not aarch64, or 16-bit samples compiled out) */
#endif
