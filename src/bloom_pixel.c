/* Pixel formats: decode a pixel to Q16.16 linear samples, encode back to
 * codes (sim/docs/fixed-point.md steps 1 and 7). Internal samples: Q12.20. */
#include <string.h>

#include "bloom_internal.h"

static inline uint32_t dec_linear(uint32_t c, uint32_t n)
{
    return (c * BLOOM_LIN_ONE + (n - 1u) / 2u) / n; /* n is a constant per call site */
}

/* Number of c in 1..n with v >= t[c]: a binary search over the thresholds. */
static inline uint32_t enc_srgb(uint32_t v, const uint32_t *t, uint32_t n)
{
    uint32_t c = 0;
    for (uint32_t step = (n + 1u) >> 1; step; step >>= 1)
        if (c + step <= n && v >= t[c + step])
            c += step;
    return c;
}

static inline uint32_t enc_linear(uint32_t v, uint32_t n)
{
    if (v > BLOOM_LIN_ONE)
        v = BLOOM_LIN_ONE;
    return (v * n + (BLOOM_LIN_ONE >> 1)) >> BLOOM_LIN_BITS;
}

void bloom_pixel_decode(bloom_format_t fmt, bool linear, const uint8_t *p, uint32_t rgb[3])
{
    uint32_t r, g, b;
    switch (fmt) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565: {
        uint32_t w = (uint32_t)p[0] | ((uint32_t)p[1] << 8);
        r = w >> 11;
        g = (w >> 5) & 63u;
        b = w & 31u;
        if (linear) {
            rgb[0] = dec_linear(r, 31);
            rgb[1] = dec_linear(g, 63);
            rgb[2] = dec_linear(b, 31);
        } else {
            rgb[0] = bloom_srgb_dec5[r];
            rgb[1] = bloom_srgb_dec6[g];
            rgb[2] = bloom_srgb_dec5[b];
        }
        return;
    }
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16: {
        uint32_t w[3];
        memcpy(w, p, sizeof w);
        for (int c = 0; c < 3; c++)
            rgb[c] = (w[c] > BLOOM_MAX_LINEAR ? BLOOM_MAX_LINEAR : w[c]) << 4;
        return;
    }
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        r = p[2];
        g = p[1];
        b = p[0];
        break;
#endif
    default: /* BLOOM_FMT_RGB888 */
        r = p[0];
        g = p[1];
        b = p[2];
        break;
    }
    if (linear) {
        rgb[0] = dec_linear(r, 255);
        rgb[1] = dec_linear(g, 255);
        rgb[2] = dec_linear(b, 255);
    } else {
        rgb[0] = bloom_srgb_dec8[r];
        rgb[1] = bloom_srgb_dec8[g];
        rgb[2] = bloom_srgb_dec8[b];
    }
}

void bloom_pixel_encode(bloom_format_t fmt, bool linear, const uint32_t v[3], uint8_t *p)
{
    switch (fmt) {
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565: {
        uint32_t r, g, b;
        if (linear) {
            r = enc_linear(v[0], 31);
            g = enc_linear(v[1], 63);
            b = enc_linear(v[2], 31);
        } else {
            r = enc_srgb(v[0], bloom_srgb_enc5, 31);
            g = enc_srgb(v[1], bloom_srgb_enc6, 63);
            b = enc_srgb(v[2], bloom_srgb_enc5, 31);
        }
        uint32_t w = (r << 11) | (g << 5) | b;
        p[0] = (uint8_t)w;
        p[1] = (uint8_t)(w >> 8);
        return;
    }
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16: {
        uint32_t w[3];
        for (int c = 0; c < 3; c++) {
            uint32_t q = (v[c] >> 4) + ((v[c] >> 3) & 1u); /* round to Q16.16 */
            w[c] = q > BLOOM_MAX_LINEAR ? BLOOM_MAX_LINEAR : q;
        }
        memcpy(p, w, sizeof w);
        return;
    }
#endif
    default:
        break;
    }
    uint32_t c8[3];
    for (int c = 0; c < 3; c++)
        c8[c] = linear ? enc_linear(v[c], 255) : enc_srgb(v[c], bloom_srgb_enc8, 255);
#if BLOOM_USE_XRGB8888
    if (fmt == BLOOM_FMT_XRGB8888) {
        p[0] = (uint8_t)c8[2];
        p[1] = (uint8_t)c8[1];
        p[2] = (uint8_t)c8[0];
        p[3] = 0xFF;
        return;
    }
#endif
    p[0] = (uint8_t)c8[0];
    p[1] = (uint8_t)c8[1];
    p[2] = (uint8_t)c8[2];
}
