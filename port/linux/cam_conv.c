/* bloom_cam: the pure parts — camera rows to the engine's RGB888 input, the
 * framebuffer layout check and the placement of a frame on the screen.
 *
 * YUYV follows the simulator's rule (sim/docs/simulator.md, "Y'CbCr ->
 * R'G'B' in integers"): BT.601 limited range, coefficients round(x * 65536),
 * each channel clamp((t + 32768) >> 16, 0, 255). GREY is full range,
 * R = G = B = Y. So a frame recorded with --record and run through
 * bloom_sim gives the same engine input, hence the same output. The other
 * Y'CbCr layouts (packed 4:2:2 in any byte order, NV.. semi-planar) take
 * the same rule with the coefficients of the driver's matrix and range
 * (ycc_rules: BT.601 or BT.709, limited or full; bloom_sim --raw-ycbcr),
 * chroma shared by the pixels it covers (nearest, no interpolation);
 * RGB565 codes are widened as bloom_sim converts codes between ranges,
 * round half up of c * 255 / (2^n - 1).
 *
 * RGB888 -> YUYV (the GStreamer element's YUY2 output) follows bloom_sim's
 * Y4M writer (sim/docs/simulator.md, "Y4M output"), BT.601 limited range:
 * Y = (16829 R + 33039 G + 6416 B + 16 * 65536 + 32768) >> 16 per pixel;
 * U, V = 128 + round(sum / (n * 65536)) of -9714 R - 19070 G + 28784 B and
 * 28784 R - 24103 G - 4681 B over the pair's n = 2 pixels (n = 1 for the
 * last pixel of an odd row). Neutral greys (R = G = B) go through YUYV ->
 * RGB888 -> YUYV unchanged. */
#include <stdio.h>
#include <string.h>

#include "cam.h"

static uint8_t clamp8(int32_t t) /* t already holds the + 1/2 */
{
    if (t < 0)
        return 0;
    t >>= 16;
    return (uint8_t)(t > 255 ? 255 : t);
}

/* [bt709][full]: limited range scales Y' by 255/219 and chroma by 255/224;
 * R' = Y' + 2(1-Kr) V, G' = Y' - 2Kb(1-Kb)/Kg U - 2Kr(1-Kr)/Kg V,
 * B' = Y' + 2(1-Kb) U, Kg = 1 - Kr - Kb; each coefficient round(x * 65536). */
static const cam_ycc_t ycc_rules[2][2] = {
    {{76309, 16, 104597, 25675, 53279, 132201}, {65536, 0, 91881, 22553, 46802, 116130}},
    {{76309, 16, 117489, 13975, 34925, 138438}, {65536, 0, 103206, 12276, 30679, 121609}},
};

const cam_ycc_t *cam_ycc(int bt709, int full)
{
    return &ycc_rules[bt709 != 0][full != 0];
}

void cam_ycc_to_rgb(const cam_ycc_t *m, int y, int cb, int cr, uint8_t rgb[3])
{
    const int32_t u = cb - 128, v = cr - 128;
    const int32_t yy = m->y * (y - m->y0) + 32768;
    rgb[0] = clamp8(yy + m->rv * v);
    rgb[1] = clamp8(yy - m->gu * u - m->gv * v);
    rgb[2] = clamp8(yy + m->bu * u);
}

void cam_ycbcr_to_rgb(int y, int cb, int cr, uint8_t rgb[3])
{
    cam_ycc_to_rgb(&ycc_rules[0][0], y, cb, cr, rgb);
}

void cam_yuyv_row_to_rgb888(const uint8_t *src, uint8_t *dst, int width)
{
    for (int x = 0; x + 1 < width; x += 2, src += 4, dst += 6) {
        cam_ycbcr_to_rgb(src[0], src[1], src[3], dst);
        cam_ycbcr_to_rgb(src[2], src[1], src[3], dst + 3);
    }
}

void cam_packed422_row_to_rgb888(const cam_ycc_t *m, int order, const uint8_t *src, uint8_t *dst, int width)
{
    /* where Y0, Cb and Cr are in the group (Y1 two bytes after Y0) */
    static const uint8_t at[4][3] = {{0, 1, 3}, {1, 0, 2}, {0, 3, 1}, {1, 2, 0}};
    const uint8_t *o = at[order & 3];
    for (int x = 0; x < width; x++, dst += 3) {
        const uint8_t *g = src + 4 * (x >> 1);
        cam_ycc_to_rgb(m, g[o[0] + 2 * (x & 1)], g[o[1]], g[o[2]], dst);
    }
}

void cam_nv_row_to_rgb888(const cam_ycc_t *m, int vu, const uint8_t *y, const uint8_t *uv, uint8_t *dst,
                          int width)
{
    const int cb = vu ? 1 : 0, cr = 1 - cb;
    for (int x = 0; x < width; x++, dst += 3) {
        const uint8_t *c = uv + 2 * (x >> 1);
        cam_ycc_to_rgb(m, y[x], c[cb], c[cr], dst);
    }
}

void cam_rgb565_row_to_rgb888(const uint8_t *src, uint8_t *dst, int width)
{
    for (int x = 0; x < width; x++, src += 2, dst += 3) {
        const unsigned w = (unsigned)src[0] | (unsigned)src[1] << 8;
        dst[0] = (uint8_t)(((w >> 11) * 255u + 15u) / 31u);
        dst[1] = (uint8_t)((((w >> 5) & 63u) * 255u + 31u) / 63u);
        dst[2] = (uint8_t)(((w & 31u) * 255u + 15u) / 31u);
    }
}

static uint8_t rgb_to_y(const uint8_t *p)
{
    return (uint8_t)((16829 * p[0] + 33039 * p[1] + 6416 * p[2] + (16 << 16) + 32768) >> 16);
}

/* 128 + round(sum / (n * 65536)); the biased sum is positive */
static uint8_t chroma(int32_t sum, int32_t n)
{
    const int32_t one = n * 65536;
    return (uint8_t)((sum + 128 * one + one / 2) / one);
}

void cam_rgb888_row_to_yuyv(const uint8_t *src, uint8_t *dst, int width)
{
    for (int x = 0; x < width; x += 2, src += 6, dst += 4) {
        const int n = x + 1 < width ? 2 : 1;
        int32_t su = 0, sv = 0;
        for (int i = 0; i < n; i++) {
            const uint8_t *p = src + 3 * i;
            su += -9714 * p[0] - 19070 * p[1] + 28784 * p[2];
            sv += 28784 * p[0] - 24103 * p[1] - 4681 * p[2];
        }
        dst[0] = rgb_to_y(src);
        dst[1] = chroma(su, n);
        dst[2] = rgb_to_y(src + 3 * (n - 1));
        dst[3] = chroma(sv, n);
    }
}

void cam_grey_row_to_rgb888(const uint8_t *src, uint8_t *dst, int width)
{
    for (int x = 0; x < width; x++, dst += 3)
        dst[0] = dst[1] = dst[2] = src[x];
}

bloom_format_t cam_fb_format(const cam_fb_layout_t *l, char *why, size_t whylen)
{
    if (l->nonstd) {
        snprintf(why, whylen, "non-standard pixel format %u", (unsigned)l->nonstd);
        return (bloom_format_t)0;
    }
    if (l->grayscale) {
        snprintf(why, whylen, "%u bpp greyscale", (unsigned)l->bits_per_pixel);
        return (bloom_format_t)0;
    }
    if (l->bits_per_pixel == 16) {
        if (l->red_off == 11 && l->red_len == 5 && l->green_off == 5 && l->green_len == 6 &&
            l->blue_off == 0 && l->blue_len == 5)
            return BLOOM_FMT_RGB565;
        if (l->blue_off == 11 && l->blue_len == 5 && l->green_off == 5 && l->green_len == 6 &&
            l->red_off == 0 && l->red_len == 5)
            snprintf(why, whylen, "16 bpp BGR565");
        else if (l->red_len == 5 && l->green_len == 5 && l->blue_len == 5)
            snprintf(why, whylen, "16 bpp RGB555");
        else
            snprintf(why, whylen, "16 bpp R%u:%u G%u:%u B%u:%u", (unsigned)l->red_off, (unsigned)l->red_len,
                     (unsigned)l->green_off, (unsigned)l->green_len, (unsigned)l->blue_off,
                     (unsigned)l->blue_len);
        return (bloom_format_t)0;
    }
    if (l->bits_per_pixel == 32) {
        if (l->red_off == 16 && l->red_len == 8 && l->green_off == 8 && l->green_len == 8 &&
            l->blue_off == 0 && l->blue_len == 8)
            return BLOOM_FMT_XRGB8888;
        if (l->blue_off == 16 && l->red_off == 0 && l->red_len == 8)
            snprintf(why, whylen, "32 bpp XBGR8888");
        else
            snprintf(why, whylen, "32 bpp R%u:%u G%u:%u B%u:%u", (unsigned)l->red_off, (unsigned)l->red_len,
                     (unsigned)l->green_off, (unsigned)l->green_len, (unsigned)l->blue_off,
                     (unsigned)l->blue_len);
        return (bloom_format_t)0;
    }
    snprintf(why, whylen, "%u bpp", (unsigned)l->bits_per_pixel);
    return (bloom_format_t)0;
}

static void place_axis(int f, int s, int *dst, int *src, int *n)
{
    if (f <= s) { /* centre */
        *dst = (s - f) / 2;
        *src = 0;
        *n = f;
    } else { /* crop around the centre */
        *dst = 0;
        *src = (f - s) / 2;
        *n = s;
    }
}

void cam_place(int fw, int fh, int sw, int sh, cam_place_t *p)
{
    place_axis(fw, sw, &p->dst_x, &p->src_x, &p->w);
    place_axis(fh, sh, &p->dst_y, &p->src_y, &p->h);
}
