/* Pixel formats: decode rows to Q12.20 linear samples, encode back to codes
 * (sim/docs/fixed-point.md steps 1 and 7). Each (format, curve) pair gets its
 * own loop so no per-pixel branch remains. */
#include <string.h>

#include "bloom_pixel.h"

/* sRGB encode: the code at the bucket start, then one compare against the
 * next threshold (gen_tables checks no bucket holds two thresholds). */
#if BLOOM_SMALL
/* The number of c in 1..n with v >= t[c], by binary search. */
static inline uint32_t enc_srgb(uint32_t v, const uint8_t *bkt, int shift, const uint32_t *t, uint32_t n)
{
    (void)bkt;
    (void)shift;
    uint32_t c = 0;
    for (uint32_t step = (n + 1u) >> 1; step; step >>= 1)
        if (c + step <= n && v >= t[c + step])
            c += step;
    return c;
}
#define BKT(name) NULL
#else
static inline uint32_t enc_srgb(uint32_t v, const uint8_t *bkt, int shift, const uint32_t *t, uint32_t n)
{
    if (v > BLOOM_LIN_ONE)
        v = BLOOM_LIN_ONE;
    uint32_t c = bkt[v >> shift];
    return c + (c < n && v >= t[c + 1]);
}
#define BKT(name) name
#endif

static inline uint32_t enc_linear(uint32_t v, uint32_t n)
{
    if (v > BLOOM_LIN_ONE)
        v = BLOOM_LIN_ONE;
    return (v * n + (BLOOM_LIN_ONE >> 1)) >> BLOOM_LIN_BITS;
}

#define ENC8(v, lin)                                                                                         \
    ((lin) ? enc_linear(v, 255)                                                                              \
           : enc_srgb(v, BKT(bloom_srgb_bkt8), BLOOM_LIN_BITS - 12, bloom_srgb_enc8, 255))
#define ENC6(v, lin)                                                                                         \
    ((lin) ? enc_linear(v, 63) : enc_srgb(v, BKT(bloom_srgb_bkt6), BLOOM_LIN_BITS - 10, bloom_srgb_enc6, 63))
#define ENC5(v, lin)                                                                                         \
    ((lin) ? enc_linear(v, 31) : enc_srgb(v, BKT(bloom_srgb_bkt5), BLOOM_LIN_BITS - 9, bloom_srgb_enc5, 31))

#if BLOOM_USE_RGBF32
/* Out of line: inlined twice (both curves) into decode_rows, it pushed this
 * file past gcc's inlining budget, and the 8-bit paths on 32-bit ARM lost
 * 3.6 % (make target-cost: armhf 1080p 377.6 instructions a pixel, 364.5
 * without it). */
BLOOM_NOINLINE static void decode_f32(const uint8_t *p, uint32_t *o, int n)
{
    for (int i = 0; i < n; i++, p += 12, o += 3)
        BLOOM_DEC_RGBF32(p, o);
}
#endif

/* One loop per format; `lin` is a constant at each call site, so the
 * compiler drops the other curve. */
static inline void decode_rows(bloom_format_t fmt, bool lin, const uint8_t *p, uint32_t *o, int n)
{
    switch (fmt) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        for (int i = 0; i < n; i++, p += 2, o += 3)
            BLOOM_DEC_RGB565(p, o, lin);
        return;
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16:
        for (int i = 0; i < n; i++, p += 12, o += 3)
            BLOOM_DEC_RGBQ16(p, o);
        return;
#endif
#if BLOOM_USE_RGBF32
    case BLOOM_FMT_RGBF32:
        decode_f32(p, o, n);
        return;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        for (int i = 0; i < n; i++, p += 4, o += 3)
            BLOOM_DEC_XRGB8888(p, o, lin);
        return;
#endif
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        for (int i = 0; i < n; i++, p += 3, o += 3)
            BLOOM_DEC_RGB888(p, o, lin);
        return;
#endif
    default: /* refused by bloom_query */
        return;
    }
}

void bloom_decode_row(bloom_format_t fmt, bool linear, const uint8_t *src, uint32_t *dst, int n)
{
    if (linear)
        decode_rows(fmt, true, src, dst, n);
    else
        decode_rows(fmt, false, src, dst, n);
}

static inline void encode_rows(bloom_format_t fmt, bool lin, const uint32_t *v, uint8_t *p, int n)
{
    switch (fmt) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        for (int i = 0; i < n; i++, p += 2, v += 3) {
            uint32_t w = (ENC5(v[0], lin) << 11) | (ENC6(v[1], lin) << 5) | ENC5(v[2], lin);
            p[0] = (uint8_t)w;
            p[1] = (uint8_t)(w >> 8);
        }
        return;
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16:
        for (int i = 0; i < n; i++, p += 12, v += 3) {
            uint32_t w[3];
            for (int c = 0; c < 3; c++) {
                uint32_t q = bloom_lin_to_q16(v[c]);
                w[c] = q > BLOOM_MAX_LINEAR ? BLOOM_MAX_LINEAR : q;
            }
            memcpy(p, w, sizeof w);
        }
        return;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        for (int i = 0; i < n; i++, p += 4, v += 3) {
            p[0] = (uint8_t)ENC8(v[2], lin);
            p[1] = (uint8_t)ENC8(v[1], lin);
            p[2] = (uint8_t)ENC8(v[0], lin);
            p[3] = 0xFF;
        }
        return;
#endif
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        for (int i = 0; i < n; i++, p += 3, v += 3) {
            p[0] = (uint8_t)ENC8(v[0], lin);
            p[1] = (uint8_t)ENC8(v[1], lin);
            p[2] = (uint8_t)ENC8(v[2], lin);
        }
        return;
#endif
    default: /* refused by bloom_query */
        return;
    }
}

void bloom_encode_row(bloom_format_t fmt, bool linear, const uint32_t *v, uint8_t *dst, int n)
{
    if (linear)
        encode_rows(fmt, true, v, dst, n);
    else
        encode_rows(fmt, false, v, dst, n);
}

void bloom_pixel_decode(bloom_format_t fmt, bool linear, const uint8_t *p, uint32_t rgb[3])
{
    bloom_decode_row(fmt, linear, p, rgb, 1);
}

void bloom_pixel_encode(bloom_format_t fmt, bool linear, const uint32_t v[3], uint8_t *p)
{
    bloom_encode_row(fmt, linear, v, p, 1);
}

#if !BLOOM_SMALL
#define FENC8(v) BLOOM_FENC8(v)
#define FENC6(v) bloom_enc_fast(v, bloom_srgb_bkt6, BLOOM_LIN_BITS - 10, bloom_srgb_enc6, 63)
#define FENC5(v) bloom_enc_fast(v, bloom_srgb_bkt5, BLOOM_LIN_BITS - 9, bloom_srgb_enc5, 31)

uint32_t bloom_enc_srgb_fast(uint32_t v, int bits)
{
    return bits == 8 ? FENC8(v) : bits == 6 ? FENC6(v) : FENC5(v);
}

uint32_t bloom_enc_srgb_ref(uint32_t v, int bits)
{
    return bits == 8 ? ENC8(v, false) : bits == 6 ? ENC6(v, false) : ENC5(v, false);
}

bool bloom_encode_eo_ok(bloom_format_t in_fmt, bloom_format_t out_fmt, bool linear)
{
    const bool in = (BLOOM_USE_RGB888 && in_fmt == BLOOM_FMT_RGB888) ||
                    (BLOOM_USE_XRGB8888 && in_fmt == BLOOM_FMT_XRGB8888) ||
                    (BLOOM_USE_RGB565 && in_fmt == BLOOM_FMT_RGB565);
    const bool out = (BLOOM_USE_RGB888 && out_fmt == BLOOM_FMT_RGB888) ||
                     (BLOOM_USE_XRGB8888 && out_fmt == BLOOM_FMT_XRGB8888) ||
                     (BLOOM_USE_RGB565 && out_fmt == BLOOM_FMT_RGB565);
    return in && out && !linear;
}

/* One output pixel: bloom b[0..2] + the source pixel at p, encoded at q.
 * fi, fo and dbg are constants after inlining. */
static BLOOM_ALWAYS_INLINE void eo_px(bloom_format_t fi, bloom_format_t fo, bool dbg, const uint8_t *p,
                                      const uint32_t *b, uint8_t *q)
{
    uint32_t v[3] = {b[0], b[1], b[2]};
    if (!dbg) {
        uint32_t s[3];
        if (fi == BLOOM_FMT_RGB565)
            BLOOM_DEC_RGB565(p, s, false);
        else if (fi == BLOOM_FMT_XRGB8888)
            BLOOM_DEC_XRGB8888(p, s, false);
        else
            BLOOM_DEC_RGB888(p, s, false);
        v[0] += s[0];
        v[1] += s[1];
        v[2] += s[2];
    }
    if (fo == BLOOM_FMT_RGB565) {
        const uint32_t w = (FENC5(v[0]) << 11) | (FENC6(v[1]) << 5) | FENC5(v[2]);
        q[0] = (uint8_t)w;
        q[1] = (uint8_t)(w >> 8);
    } else if (fo == BLOOM_FMT_XRGB8888) {
        q[0] = (uint8_t)FENC8(v[2]);
        q[1] = (uint8_t)FENC8(v[1]);
        q[2] = (uint8_t)FENC8(v[0]);
        q[3] = 0xFF;
    } else {
        q[0] = (uint8_t)FENC8(v[0]);
        q[1] = (uint8_t)FENC8(v[1]);
        q[2] = (uint8_t)FENC8(v[2]);
    }
}

static BLOOM_ALWAYS_INLINE void eo_loop(bloom_format_t fi, bloom_format_t fo, bool dbg, const uint8_t *p,
                                        const uint32_t *e, const uint32_t *o, uint8_t *q, int n)
{
    const size_t ib = fi == BLOOM_FMT_RGB565 ? 2u : fi == BLOOM_FMT_XRGB8888 ? 4u : 3u;
    const size_t ob = fo == BLOOM_FMT_RGB565 ? 2u : fo == BLOOM_FMT_XRGB8888 ? 4u : 3u;
    int x = 0;
    for (; x + 2 <= n; x += 2, p += 2 * ib, q += 2 * ob, e += 3, o += 3) {
        eo_px(fi, fo, dbg, p, e, q);
        eo_px(fi, fo, dbg, p + ib, o, q + ob);
    }
    if (x < n)
        eo_px(fi, fo, dbg, p, e, q);
}

/* The output format as a constant. */
static BLOOM_ALWAYS_INLINE void eo_out(bloom_format_t fi, bloom_format_t fo, bool dbg, const uint8_t *p,
                                       const uint32_t *e, const uint32_t *o, uint8_t *q, int n)
{
    switch (fo) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        eo_loop(fi, BLOOM_FMT_RGB565, dbg, p, e, o, q, n);
        return;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        eo_loop(fi, BLOOM_FMT_XRGB8888, dbg, p, e, o, q, n);
        return;
#endif
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        eo_loop(fi, BLOOM_FMT_RGB888, dbg, p, e, o, q, n);
        return;
#endif
    default: /* refused by bloom_encode_eo_ok */
        return;
    }
}

void bloom_encode_eo(bloom_format_t in_fmt, bloom_format_t out_fmt, bool debug, const uint8_t *src,
                     const uint32_t *e, const uint32_t *o, uint8_t *dst, int n)
{
    if (debug) { /* the source is not read: one loop per output format */
        eo_out(BLOOM_FMT_RGB888, out_fmt, true, src, e, o, dst, n);
        return;
    }
    switch (in_fmt) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        eo_out(BLOOM_FMT_RGB565, out_fmt, false, src, e, o, dst, n);
        return;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        eo_out(BLOOM_FMT_XRGB8888, out_fmt, false, src, e, o, dst, n);
        return;
#endif
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        eo_out(BLOOM_FMT_RGB888, out_fmt, false, src, e, o, dst, n);
        return;
#endif
    default: /* refused by bloom_encode_eo_ok */
        return;
    }
}
#endif

/* Largest byte of p[0..n): 32 lanes of fixed-count loops so that even
 * -O2's cheapest vectorizer turns them into byte-max instructions. */
static uint8_t max_bytes(const uint8_t *p, size_t n)
{
    uint8_t lane[32] = {0}, m = 0;
    size_t i = 0;
    for (; i + 32 <= n; i += 32)
        for (int j = 0; j < 32; j++)
            lane[j] = p[i + (size_t)j] > lane[j] ? p[i + (size_t)j] : lane[j];
    for (int j = 0; j < 32; j++)
        m = lane[j] > m ? lane[j] : m;
    for (; i < n; i++)
        m = p[i] > m ? p[i] : m;
    return m;
}

#if !BLOOM_SMALL && BLOOM_USE_XRGB8888
/* The same over XRGB8888 pixels, X bytes left out (masked to 0). */
static uint8_t max_bytes_xrgb(const uint8_t *p, size_t n)
{
    static const uint8_t msk[32] = {255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0,
                                    255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0};
    uint8_t lane[32] = {0}, m = 0;
    size_t i = 0;
    for (; i + 32 <= n; i += 32)
        for (int j = 0; j < 32; j++) {
            const uint8_t v = (uint8_t)(p[i + (size_t)j] & msk[j]);
            lane[j] = v > lane[j] ? v : lane[j];
        }
    for (int j = 0; j < 32; j++)
        m = lane[j] > m ? lane[j] : m;
    for (; i < n; i++)
        if ((i & 3u) != 3u)
            m = p[i] > m ? p[i] : m;
    return m;
}
#endif

#if !BLOOM_SMALL && BLOOM_USE_RGB565
/* Largest 5/6/5 fields of n RGB565 pixels, in 16 lanes per field. */
static void max_565(const uint8_t *p, int n, uint32_t *r, uint32_t *g, uint32_t *b)
{
    uint16_t lr[16] = {0}, lg[16] = {0}, lb[16] = {0};
    int i = 0;
    for (; i + 16 <= n; i += 16)
        for (int j = 0; j < 16; j++) {
            const uint16_t w = (uint16_t)(p[2 * (i + j)] | (p[2 * (i + j) + 1] << 8));
            const uint16_t wr = (uint16_t)(w >> 11), wg = (uint16_t)(w & 0x07E0u), wb = (uint16_t)(w & 31u);
            lr[j] = wr > lr[j] ? wr : lr[j];
            lg[j] = wg > lg[j] ? wg : lg[j];
            lb[j] = wb > lb[j] ? wb : lb[j];
        }
    uint32_t mr = 0, mg = 0, mb = 0;
    for (int j = 0; j < 16; j++) {
        mr = lr[j] > mr ? lr[j] : mr;
        mg = lg[j] > mg ? lg[j] : mg;
        mb = lb[j] > mb ? lb[j] : mb;
    }
    for (; i < n; i++) {
        const uint32_t w = (uint32_t)p[2 * i] | ((uint32_t)p[2 * i + 1] << 8);
        const uint32_t wr = w >> 11, wg = w & 0x07E0u, wb = w & 31u;
        mr = wr > mr ? wr : mr;
        mg = wg > mg ? wg : mg;
        mb = wb > mb ? wb : mb;
    }
    *r = mr;
    *g = mg >> 5;
    *b = mb;
}
#endif

/* Largest channel codes of a row against the dark codes. */
bool bloom_row_dark(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d)
{
    switch (fmt) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565: {
        uint32_t r = 0, g = 0, b = 0;
#if !BLOOM_SMALL
        max_565(p, n, &r, &g, &b);
#else
        for (int i = 0; i < n; i++) {
            const uint32_t w = (uint32_t)p[2 * i] | ((uint32_t)p[2 * i + 1] << 8);
            const uint32_t wr = w >> 11, wg = (w >> 5) & 63u, wb = w & 31u;
            r = wr > r ? wr : r;
            g = wg > g ? wg : g;
            b = wb > b ? wb : b;
        }
#endif
        return r <= d->c5 && g <= d->c6 && b <= d->c5;
    }
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16: {
        uint32_t m = 0;
        for (int i = 0; i < 3 * n; i++) {
            uint32_t w;
            memcpy(&w, p + 4 * i, 4);
            m = w > m ? w : m;
        }
        return m <= d->q16;
    }
#endif
#if BLOOM_USE_RGBF32
    case BLOOM_FMT_RGBF32: { /* positive bits order as the values; negative and NaN count as bright */
        uint32_t m = 0;
        for (int i = 0; i < 3 * n; i++) {
            uint32_t w;
            memcpy(&w, p + 4 * i, 4);
            m = w > m ? w : m;
        }
        return m <= d->q16; /* here the bits of a float (bloom_dark_t) */
    }
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888: {
#if !BLOOM_SMALL
        return max_bytes_xrgb(p, 4u * (size_t)n) <= d->c8;
#else
        if (max_bytes(p, 4u * (size_t)n) <= d->c8)
            return true; /* X bytes included: a bright X only costs the exact test */
        uint8_t m = 0;
        for (int i = 0; i < n; i++) {
            const uint8_t c = p[4 * i] > p[4 * i + 1] ? p[4 * i] : p[4 * i + 1];
            const uint8_t e = c > p[4 * i + 2] ? c : p[4 * i + 2];
            m = e > m ? e : m;
        }
        return m <= d->c8;
#endif
    }
#endif
    default:
        return max_bytes(p, 3u * (size_t)n) <= d->c8;
    }
}

#if !BLOOM_SMALL
bool bloom_row_dark_copy(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d, uint8_t *copy)
{
    if (!bloom_row_dark(fmt, p, n, d))
        return false;
    memcpy(copy, p, (size_t)n * (size_t)bloom_bpp(fmt));
    return true;
}
#endif

int bloom_format_bpp(bloom_format_t fmt)
{
    return bloom_bpp(fmt);
}
