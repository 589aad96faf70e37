/* The level-1 box from the source rows (sim/docs/fixed-point.md step 2):
 * each source pixel decoded (sRGB table or linear) and summed 4 x 4 into
 * a D_1 pixel, rounded. The size build's version decodes per pixel; the
 * others per channel in pair sums, for a range of D_1 columns, with or
 * without the sums kept from the row before (bloom_d1_keep_t). */
#include <string.h>

#include "bloom_kernels.h"
#include "bloom_pixel.h"

#if BLOOM_SMALL
/* One decoded pixel; fmt and lin are constants after inlining. */
static BLOOM_ALWAYS_INLINE void dec_px(bloom_format_t fmt, bool lin, const uint8_t *p, uint32_t *o)
{
    switch (fmt) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        BLOOM_DEC_RGB565(p, o, lin);
        return;
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16:
        BLOOM_DEC_RGBQ16(p, o);
        return;
#endif
#if BLOOM_USE_RGBF32
    case BLOOM_FMT_RGBF32:
        BLOOM_DEC_RGBF32(p, o);
        return;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        BLOOM_DEC_XRGB8888(p, o, lin);
        return;
#endif
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        BLOOM_DEC_RGB888(p, o, lin);
        return;
#endif
    default: /* refused by bloom_query */
        o[0] = o[1] = o[2] = 0;
        return;
    }
}

static BLOOM_ALWAYS_INLINE void colsum4_src(const uint8_t *const s[4], bloom_format_t fmt, bool lin,
                                            size_t off, uint32_t out[3])
{
    uint32_t a[3], b[3], c[3], d[3];
    dec_px(fmt, lin, s[0] + off, a);
    dec_px(fmt, lin, s[1] + off, b);
    dec_px(fmt, lin, s[2] + off, c);
    dec_px(fmt, lin, s[3] + off, d);
    for (int ch = 0; ch < 3; ch++)
        out[ch] = a[ch] + b[ch] + c[ch] + d[ch];
}

static BLOOM_ALWAYS_INLINE void box_src(const uint8_t *const s[4], bloom_format_t fmt, bool lin, size_t bpp,
                                        uint32_t *dst, int dw, int sw)
{
    uint32_t a[3], b[3], c[3], d[3];
    colsum4_src(s, fmt, lin, 0, a); /* column 2x-1 = -1 clamps to 0 */
    b[0] = a[0];
    b[1] = a[1];
    b[2] = a[2];
    for (int x = 0; x < dw; x++, dst += 3) {
        colsum4_src(s, fmt, lin, (size_t)imin(2 * x + 1, sw - 1) * bpp, c);
        colsum4_src(s, fmt, lin, (size_t)imin(2 * x + 2, sw - 1) * bpp, d);
        for (int ch = 0; ch < 3; ch++) {
            dst[ch] = BLOOM_BOX_RND(a[ch] + b[ch] + c[ch] + d[ch]);
            a[ch] = c[ch];
            b[ch] = d[ch];
        }
    }
}
#else
/* Channel ch (0 R, 1 G, 2 B) of the pixel at p, decoded; fmt, lin and ch
 * are constants after inlining, so the sums below stay in registers. */
static BLOOM_ALWAYS_INLINE uint32_t dec_ch(bloom_format_t fmt, bool lin, const uint8_t *p, int ch)
{
    switch (fmt) {
    case BLOOM_FMT_RGB565: {
        const uint32_t w = (uint32_t)p[0] | ((uint32_t)p[1] << 8);
        if (ch == 1)
            return lin ? bloom_dec_linear((w >> 5) & 63u, 63) : bloom_srgb_dec6[(w >> 5) & 63u];
        const uint32_t c = ch == 0 ? w >> 11 : w & 31u;
        return lin ? bloom_dec_linear(c, 31) : bloom_srgb_dec5[c];
    }
    case BLOOM_FMT_RGBQ16: {
        uint32_t w;
        memcpy(&w, p + 4 * ch, 4);
        return (w > BLOOM_MAX_LINEAR ? BLOOM_MAX_LINEAR : w) << BLOOM_Q16_SHIFT;
    }
    case BLOOM_FMT_RGBF32: {
        uint32_t w;
        memcpy(&w, p + 4 * ch, 4);
        return bloom_f32_to_lin(w);
    }
    case BLOOM_FMT_XRGB8888:
        return lin ? bloom_dec_linear(p[2 - ch], 255) : bloom_srgb_dec8[p[2 - ch]];
    default:
        return lin ? bloom_dec_linear(p[ch], 255) : bloom_srgb_dec8[p[ch]];
    }
}

/* Channel ch summed over the four rows and two columns at byte offsets oa, ob. */
static BLOOM_ALWAYS_INLINE uint32_t pair_ch(const uint8_t *s0, const uint8_t *s1, const uint8_t *s2,
                                            const uint8_t *s3, bloom_format_t fmt, bool lin, size_t oa,
                                            size_t ob, int ch)
{
    return ((dec_ch(fmt, lin, s0 + oa, ch) + dec_ch(fmt, lin, s1 + oa, ch)) +
            (dec_ch(fmt, lin, s2 + oa, ch) + dec_ch(fmt, lin, s3 + oa, ch))) +
           ((dec_ch(fmt, lin, s0 + ob, ch) + dec_ch(fmt, lin, s1 + ob, ch)) +
            (dec_ch(fmt, lin, s2 + ob, ch) + dec_ch(fmt, lin, s3 + ob, ch)));
}

static BLOOM_ALWAYS_INLINE void pair_src(const uint8_t *s0, const uint8_t *s1, const uint8_t *s2,
                                         const uint8_t *s3, bloom_format_t fmt, bool lin, size_t oa,
                                         size_t ob, uint32_t out[3])
{
    out[0] = pair_ch(s0, s1, s2, s3, fmt, lin, oa, ob, 0);
    out[1] = pair_ch(s0, s1, s2, s3, fmt, lin, oa, ob, 1);
    out[2] = pair_ch(s0, s1, s2, s3, fmt, lin, oa, ob, 2);
}

/* The same sums (the box is exact in 32 bits), grouped by column pairs:
 * P(j) = columns 2j-1 and 2j, clamped; D(x) = (P(x) + P(x+1)) / 16, half to even.
 * The pairs with no clamp run without bound tests. */
static BLOOM_ALWAYS_INLINE void box_src_range(const uint8_t *const s[4], bloom_format_t fmt, bool lin,
                                              size_t bpp, uint32_t *dst, int xa, int dw, int sw)
{
    const uint8_t *s0 = s[0], *s1 = s[1], *s2 = s[2], *s3 = s[3];
    uint32_t p[3], q[3];
    /* columns 2 xa - 1 (-1 clamps to 0) and 2 xa */
    pair_src(s0, s1, s2, s3, fmt, lin, (size_t)imin(imax(2 * xa - 1, 0), sw - 1) * bpp,
             (size_t)imin(2 * xa, sw - 1) * bpp, p);
    /* pair j = x + 1 needs no clamp while 2 (x + 1) <= sw - 1 */
    const int xe = imin(dw, (sw - 1) / 2);
    int x = xa;
    dst += (size_t)xa * 3u;
    {
        uint32_t p0 = p[0], p1 = p[1], p2 = p[2];
        const size_t c0 = (size_t)(2 * xa + 1) * bpp; /* column 2x + 1 */
        const uint8_t *a0 = s0 + c0, *a1 = s1 + c0, *a2 = s2 + c0, *a3 = s3 + c0;
        for (; x < xe; x++, dst += 3, a0 += 2 * bpp, a1 += 2 * bpp, a2 += 2 * bpp, a3 += 2 * bpp) {
            const uint32_t q0 = pair_ch(a0, a1, a2, a3, fmt, lin, 0, bpp, 0);
            const uint32_t q1 = pair_ch(a0, a1, a2, a3, fmt, lin, 0, bpp, 1);
            const uint32_t q2 = pair_ch(a0, a1, a2, a3, fmt, lin, 0, bpp, 2);
            dst[0] = BLOOM_BOX_RND(p0 + q0);
            dst[1] = BLOOM_BOX_RND(p1 + q1);
            dst[2] = BLOOM_BOX_RND(p2 + q2);
            p0 = q0;
            p1 = q1;
            p2 = q2;
        }
        p[0] = p0;
        p[1] = p1;
        p[2] = p2;
    }
    for (; x < dw; x++, dst += 3) {
        pair_src(s0, s1, s2, s3, fmt, lin, (size_t)imin(2 * x + 1, sw - 1) * bpp,
                 (size_t)imin(2 * x + 2, sw - 1) * bpp, q);
        for (int ch = 0; ch < 3; ch++) {
            dst[ch] = BLOOM_BOX_RND(p[ch] + q[ch]);
            p[ch] = q[ch];
        }
    }
}

static BLOOM_ALWAYS_INLINE void box_src(const uint8_t *const s[4], bloom_format_t fmt, bool lin, size_t bpp,
                                        uint32_t *dst, int dw, int sw)
{
    box_src_range(s, fmt, lin, bpp, dst, 0, dw, sw);
}

/* Channel ch over two rows and two columns at byte offsets oa, ob. */
static BLOOM_ALWAYS_INLINE uint32_t half_ch(const uint8_t *r0, const uint8_t *r1, bloom_format_t fmt,
                                            bool lin, size_t oa, size_t ob, int ch)
{
    return (dec_ch(fmt, lin, r0 + oa, ch) + dec_ch(fmt, lin, r1 + oa, ch)) +
           (dec_ch(fmt, lin, r0 + ob, ch) + dec_ch(fmt, lin, r1 + ob, ch));
}

/* Pair sums of columns at byte offsets oa, ob (pair j: k = sum + 3j,
 * t = tag + j) into q: the upper half (rows s0, s1) kept by row y - 1 where
 * *t says so, else decoded; the lower half (s2, s3) decoded and kept. */
static BLOOM_ALWAYS_INLINE void kept_pair(const uint8_t *s0, const uint8_t *s1, const uint8_t *s2,
                                          const uint8_t *s3, bloom_format_t fmt, bool lin, size_t oa,
                                          size_t ob, uint32_t *k, int32_t *t, int32_t y, uint32_t q[3])
{
    const uint32_t l0 = half_ch(s2, s3, fmt, lin, oa, ob, 0), l1 = half_ch(s2, s3, fmt, lin, oa, ob, 1),
                   l2 = half_ch(s2, s3, fmt, lin, oa, ob, 2);
    if (*t == y) {
        q[0] = k[0] + l0;
        q[1] = k[1] + l1;
        q[2] = k[2] + l2;
    } else {
        q[0] = half_ch(s0, s1, fmt, lin, oa, ob, 0) + l0;
        q[1] = half_ch(s0, s1, fmt, lin, oa, ob, 1) + l1;
        q[2] = half_ch(s0, s1, fmt, lin, oa, ob, 2) + l2;
    }
    k[0] = l0;
    k[1] = l1;
    k[2] = l2;
    *t = y + 1;
}

/* box_src_range with the kept sums (bloom_d1_keep_t), pair by pair as
 * there: P(j) = upper + lower halves, D(x) = (P(x) + P(x+1)) / 16. The
 * same sums in another order: exact, the same bits. */
static BLOOM_ALWAYS_INLINE void box_src_kept(const uint8_t *const s[4], bloom_format_t fmt, bool lin,
                                             size_t bpp, uint32_t *dst, int xa, int dw, int sw,
                                             bloom_d1_keep_t *kp)
{
    const uint8_t *s0 = s[0], *s1 = s[1], *s2 = s[2], *s3 = s[3];
    uint32_t *sum = kp->sum;
    int32_t *tag = kp->tag;
    const int32_t y = kp->y;
    uint32_t p[3], q[3];
    /* pair xa: columns 2 xa - 1 (-1 clamps to 0) and 2 xa */
    kept_pair(s0, s1, s2, s3, fmt, lin, (size_t)imin(imax(2 * xa - 1, 0), sw - 1) * bpp,
              (size_t)imin(2 * xa, sw - 1) * bpp, sum + 3 * (size_t)xa, tag + xa, y, p);
    /* pair j = x + 1 needs no clamp while 2 (x + 1) <= sw - 1 */
    const int xe = imin(dw, (sw - 1) / 2);
    int x = xa;
    size_t oa = (size_t)(2 * xa + 1) * bpp; /* column 2x + 1 */
    for (; x < xe; x++, oa += 2 * bpp) {
        kept_pair(s0, s1, s2, s3, fmt, lin, oa, oa + bpp, sum + 3 * (size_t)(x + 1), tag + x + 1, y, q);
        uint32_t *d = dst + 3 * (size_t)x;
        d[0] = BLOOM_BOX_RND(p[0] + q[0]);
        d[1] = BLOOM_BOX_RND(p[1] + q[1]);
        d[2] = BLOOM_BOX_RND(p[2] + q[2]);
        p[0] = q[0];
        p[1] = q[1];
        p[2] = q[2];
    }
    for (; x < dw; x++) {
        kept_pair(s0, s1, s2, s3, fmt, lin, (size_t)imin(2 * x + 1, sw - 1) * bpp,
                  (size_t)imin(2 * x + 2, sw - 1) * bpp, sum + 3 * (size_t)(x + 1), tag + x + 1, y, q);
        for (int ch = 0; ch < 3; ch++) {
            dst[3 * x + ch] = BLOOM_BOX_RND(p[ch] + q[ch]);
            p[ch] = q[ch];
        }
    }
}

/* One of the two, by kp (fmt, lin, bpp constants after inlining). */
static BLOOM_ALWAYS_INLINE void box_src_any(const uint8_t *const s[4], bloom_format_t fmt, bool lin,
                                            size_t bpp, uint32_t *dst, int xa, int xb, int sw,
                                            bloom_d1_keep_t *kp)
{
    /* (kept sums for the 8-bit formats only, as the engine carves them:
     * the others' copies would be code no frame runs) */
    if ((fmt == BLOOM_FMT_RGB888 || fmt == BLOOM_FMT_XRGB8888) && kp)
        box_src_kept(s, fmt, lin, bpp, dst, xa, xb, sw, kp);
    else
        box_src_range(s, fmt, lin, bpp, dst, xa, xb, sw);
}

void bloom_row_box_src_kept_c(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst,
                              int xa, int xb, int sw, bloom_d1_keep_t *kp)
{
    if (xa >= xb)
        return;
    switch (fmt) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        if (linear)
            box_src_any(s, BLOOM_FMT_RGB565, true, 2, dst, xa, xb, sw, kp);
        else
            box_src_any(s, BLOOM_FMT_RGB565, false, 2, dst, xa, xb, sw, kp);
        return;
#endif
#if BLOOM_USE_RGBQ16 || BLOOM_USE_RGBF32 /* (the full build: size does not matter here) */
    case BLOOM_FMT_RGBQ16:
        box_src_any(s, BLOOM_FMT_RGBQ16, false, 12, dst, xa, xb, sw, kp);
        return;
    case BLOOM_FMT_RGBF32:
        box_src_any(s, BLOOM_FMT_RGBF32, false, 12, dst, xa, xb, sw, kp);
        return;
#endif
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        if (linear)
            box_src_any(s, BLOOM_FMT_RGB888, true, 3, dst, xa, xb, sw, kp);
        else
            box_src_any(s, BLOOM_FMT_RGB888, false, 3, dst, xa, xb, sw, kp);
        return;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        if (linear)
            box_src_any(s, BLOOM_FMT_XRGB8888, true, 4, dst, xa, xb, sw, kp);
        else
            box_src_any(s, BLOOM_FMT_XRGB8888, false, 4, dst, xa, xb, sw, kp);
        return;
#endif
    default: /* refused by bloom_query */
        (void)s, (void)linear, (void)dst, (void)sw, (void)kp;
        return;
    }
}

void bloom_row_box_src_range_c(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst,
                               int xa, int xb, int sw)
{
    bloom_row_box_src_kept_c(s, fmt, linear, dst, xa, xb, sw, NULL);
}
#endif

void bloom_row_box_src_c(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                         int sw)
{
    switch (fmt) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        if (linear)
            box_src(s, BLOOM_FMT_RGB565, true, 2, dst, dw, sw);
        else
            box_src(s, BLOOM_FMT_RGB565, false, 2, dst, dw, sw);
        return;
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16:
        box_src(s, BLOOM_FMT_RGBQ16, false, 12, dst, dw, sw);
        return;
#endif
#if BLOOM_USE_RGBF32
    case BLOOM_FMT_RGBF32:
        box_src(s, BLOOM_FMT_RGBF32, false, 12, dst, dw, sw);
        return;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        if (linear)
            box_src(s, BLOOM_FMT_XRGB8888, true, 4, dst, dw, sw);
        else
            box_src(s, BLOOM_FMT_XRGB8888, false, 4, dst, dw, sw);
        return;
#endif
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        if (linear)
            box_src(s, BLOOM_FMT_RGB888, true, 3, dst, dw, sw);
        else
            box_src(s, BLOOM_FMT_RGB888, false, 3, dst, dw, sw);
        return;
#endif
    default: /* refused by bloom_query */
        return;
    }
}
