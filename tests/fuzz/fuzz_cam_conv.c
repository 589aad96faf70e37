/* fuzz_cam_conv: bloom_cam's pure helpers (port/linux/cam_conv.c): the
 * YUYV and GREY row converters on rows of exactly their size (ASan sees
 * any byte past them), each pixel against the simulator's own BT.601 rule
 * (sim_ycbcr_to_rgb: bloom_sim must see the same input the camera ran);
 * the framebuffer layout check with every layout and message room; the
 * placement of a frame on a screen. */
#include "fuzz.h"
#include "sim.h"

#include "cam.h"

#include <stdlib.h>
#include <string.h>

static void rows(fz_in_t *in)
{
    const int w = 2 * (1 + (int)(fz_u8(in) % 64)); /* YUYV: even widths */
    uint8_t *yuyv = malloc((size_t)w * 2), *grey = malloc((size_t)w), *rgb = malloc((size_t)w * 3);
    for (int i = 0; i < 2 * w; i++)
        yuyv[i] = (uint8_t)fz_u8(in);
    for (int i = 0; i < w; i++)
        grey[i] = (uint8_t)fz_u8(in);
    cam_yuyv_row_to_rgb888(yuyv, rgb, w);
    for (int x = 0; x < w; x++) {
        uint32_t ref[3];
        const uint8_t *p = yuyv + 4 * (x / 2);
        sim_ycbcr_to_rgb(p[2 * (x % 2)], p[1], p[3], 0, ref);
        FZ_CHECKF(rgb[3 * x] == ref[0] && rgb[3 * x + 1] == ref[1] && rgb[3 * x + 2] == ref[2],
                  "pixel %d: YUYV %u %u %u -> %u %u %u, the simulator %u %u %u", x, p[2 * (x % 2)], p[1],
                  p[3], rgb[3 * x], rgb[3 * x + 1], rgb[3 * x + 2], ref[0], ref[1], ref[2]);
    }
    cam_grey_row_to_rgb888(grey, rgb, w);
    for (int x = 0; x < w; x++)
        FZ_CHECK(rgb[3 * x] == grey[x] && rgb[3 * x + 1] == grey[x] && rgb[3 * x + 2] == grey[x]);
    free(yuyv);
    free(grey);
    free(rgb);
}

static void layout(fz_in_t *in)
{
    cam_fb_layout_t l;
    const unsigned pick = fz_u8(in);
    l.bits_per_pixel = pick & 1 ? fz_u32(in) : (pick & 2 ? 16u : 32u);
    l.grayscale = pick & 4 ? fz_u32(in) : 0;
    l.nonstd = pick & 8 ? fz_u32(in) : 0;
    l.red_off = fz_u8(in) % 40;
    l.red_len = fz_u8(in) % 12;
    l.green_off = fz_u8(in) % 40;
    l.green_len = fz_u8(in) % 12;
    l.blue_off = fz_u8(in) % 40;
    l.blue_len = fz_u8(in) % 12;
    const size_t whylen = 1 + fz_u8(in) % 80;
    char *why = malloc(whylen);
    why[0] = 'x';
    const bloom_format_t f = cam_fb_format(&l, why, whylen);
    FZ_CHECK(f == 0 || f == BLOOM_FMT_RGB565 || f == BLOOM_FMT_XRGB8888);
    if (f == 0)
        FZ_CHECK(memchr(why, '\0', whylen) != NULL);
    if (f == BLOOM_FMT_RGB565)
        FZ_CHECK(l.bits_per_pixel == 16 && l.red_off == 11 && l.green_off == 5 && l.blue_off == 0);
    if (f == BLOOM_FMT_XRGB8888)
        FZ_CHECK(l.bits_per_pixel == 32 && l.red_off == 16 && l.green_off == 8 && l.blue_off == 0);
    free(why);
}

static void place(fz_in_t *in)
{
    const int fw = 1 + (int)(fz_u16(in) % BLOOM_MAX_DIM), fh = 1 + (int)(fz_u16(in) % BLOOM_MAX_DIM);
    const int sw = 1 + (int)(fz_u16(in) % 8192), sh = 1 + (int)(fz_u16(in) % 8192);
    cam_place_t p;
    cam_place(fw, fh, sw, sh, &p);
    FZ_CHECK(p.w == (fw < sw ? fw : sw) && p.h == (fh < sh ? fh : sh));
    FZ_CHECK(p.dst_x >= 0 && p.dst_y >= 0 && p.src_x >= 0 && p.src_y >= 0);
    FZ_CHECK(p.dst_x + p.w <= sw && p.dst_y + p.h <= sh && p.src_x + p.w <= fw && p.src_y + p.h <= fh);
    /* centred: the margins differ by at most one pixel */
    FZ_CHECK(abs((sw - p.w - p.dst_x) - p.dst_x) <= 1 && abs((fw - p.w - p.src_x) - p.src_x) <= 1);
    FZ_CHECK(abs((sh - p.h - p.dst_y) - p.dst_y) <= 1 && abs((fh - p.h - p.src_y) - p.src_y) <= 1);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in_t in = {data, size};
    while (in.n) {
        switch (fz_u8(&in) % 3) {
        case 0:
            rows(&in);
            break;
        case 1:
            layout(&in);
            break;
        default:
            place(&in);
            break;
        }
    }
    /* one pixel at a time too: every (Y, Cb, Cr) the input names */
    for (size_t i = 0; i + 2 < size; i += 3) {
        uint8_t rgb[3];
        uint32_t ref[3];
        cam_ycbcr_to_rgb(data[i], data[i + 1], data[i + 2], rgb);
        sim_ycbcr_to_rgb(data[i], data[i + 1], data[i + 2], 0, ref);
        FZ_CHECK(rgb[0] == ref[0] && rgb[1] == ref[1] && rgb[2] == ref[2]);
    }
    return 0;
}
