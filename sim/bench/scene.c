/* The benchmark scene (scene.h). Everything here is setup, never timed. */
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imgio.h"

const char scene_description[] =
    "stretched bilinearly to the frame size, plus 24 generated light spots "
    "(saturated or near-white discs of radius 0.3 % to 1.2 % of the width with a linear "
    "falloff to twice that radius, placed by a fixed pseudo-random sequence in "
    "frame-relative coordinates, so every size shows the same picture)";

static uint32_t lcg_next(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8; /* 24 bits */
}

static double lcg_unit(uint32_t *s)
{
    return (double)lcg_next(s) / 16777216.0;
}

static uint8_t u8_round(double v)
{
    if (v <= 0.0)
        return 0;
    if (v >= 255.0)
        return 255;
    return (uint8_t)(v + 0.5);
}

/* Bilinear resample of a packed 3-channel 8-bit image, pixel centres aligned. */
/* Destination pixel i of n, sampled from a row (or column) of ns: the two
 * source neighbours (edges clamped) and the weight of the second. */
static double src_pos(int i, int ns, int n, int *i0, int *i1)
{
    double f = ((double)i + 0.5) * ns / n - 0.5;
    if (f < 0.0)
        f = 0.0;
    *i0 = (int)f;
    if (*i0 > ns - 1)
        *i0 = ns - 1;
    *i1 = *i0 + 1 < ns ? *i0 + 1 : ns - 1;
    return f - *i0;
}

static void stretch(const uint8_t *s, int sw, int sh, uint8_t *d, int w, int h)
{
    for (int y = 0; y < h; y++) {
        int y0, y1;
        const double ay = src_pos(y, sh, h, &y0, &y1);
        for (int x = 0; x < w; x++) {
            int x0, x1;
            const double ax = src_pos(x, sw, w, &x0, &x1);
            for (int c = 0; c < 3; c++) {
                const double a = s[((size_t)y0 * (size_t)sw + (size_t)x0) * 3u + (size_t)c];
                const double b = s[((size_t)y0 * (size_t)sw + (size_t)x1) * 3u + (size_t)c];
                const double e = s[((size_t)y1 * (size_t)sw + (size_t)x0) * 3u + (size_t)c];
                const double f = s[((size_t)y1 * (size_t)sw + (size_t)x1) * 3u + (size_t)c];
                const double top = a + (b - a) * ax, bot = e + (f - e) * ax;
                d[((size_t)y * (size_t)w + (size_t)x) * 3u + (size_t)c] = u8_round(top + (bot - top) * ay);
            }
        }
    }
}

static void spots(uint8_t *rgb, int w, int h)
{
    static const uint8_t palette[6][3] = {
        {255, 255, 255}, {255, 200, 120}, {120, 220, 255}, {255, 80, 60}, {140, 255, 120}, {255, 170, 40},
    };
    uint32_t seed = 0x2545F491u;
    for (int i = 0; i < SCENE_SPOTS; i++) {
        const double cx = (0.03 + 0.94 * lcg_unit(&seed)) * w;
        const double cy = (0.03 + 0.94 * lcg_unit(&seed)) * h;
        double r = (0.003 + 0.009 * lcg_unit(&seed)) * w;
        if (r < 1.0)
            r = 1.0;
        const uint8_t *col = palette[i % 6];
        const int x0 = (int)floor(cx - 2 * r), x1 = (int)ceil(cx + 2 * r);
        const int y0 = (int)floor(cy - 2 * r), y1 = (int)ceil(cy + 2 * r);
        for (int y = y0 < 0 ? 0 : y0; y <= y1 && y < h; y++)
            for (int x = x0 < 0 ? 0 : x0; x <= x1 && x < w; x++) {
                const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
                const double d = sqrt(dx * dx + dy * dy);
                if (d >= 2 * r)
                    continue;
                const double t = d <= r ? 0.0 : (d - r) / r; /* 0 = spot colour */
                uint8_t *p = rgb + ((size_t)y * (size_t)w + (size_t)x) * 3u;
                for (int c = 0; c < 3; c++)
                    p[c] = u8_round(col[c] * (1.0 - t) + p[c] * t);
            }
    }
}

int scene_make(const char *image_path, int w, int h, uint8_t *rgb, char *err, size_t errlen)
{
    img_t im;
    if (img_read(image_path, &im, err, errlen))
        return -1;
    if (!im.u16) {
        snprintf(err, errlen, "%s: the scene needs an integer (PPM/PGM) image", image_path);
        img_free(&im);
        return -1;
    }
    const size_t n = (size_t)im.width * (size_t)im.height;
    uint8_t *src = malloc(n * 3u);
    if (!src) {
        snprintf(err, errlen, "out of memory");
        img_free(&im);
        return -1;
    }
    const unsigned mv = (unsigned)im.maxval;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            const unsigned v = im.u16[i * (size_t)im.channels + (size_t)(im.channels == 3 ? c : 0)];
            src[i * 3u + (size_t)c] = (uint8_t)((v * 255u + mv / 2u) / mv);
        }
    stretch(src, im.width, im.height, rgb, w, h);
    free(src);
    img_free(&im);
    spots(rgb, w, h);
    return 0;
}

int scene_convert(const uint8_t *rgb, int w, int h, bloom_format_t fmt, uint8_t *dst, size_t stride)
{
    for (int y = 0; y < h; y++) {
        const uint8_t *s = rgb + (size_t)y * (size_t)w * 3u;
        uint8_t *d = dst + (size_t)y * stride;
        switch (fmt) {
        case BLOOM_FMT_RGB888:
            memcpy(d, s, (size_t)w * 3u);
            break;
        case BLOOM_FMT_XRGB8888:
            for (int x = 0; x < w; x++) {
                d[4 * x + 0] = s[3 * x + 2];
                d[4 * x + 1] = s[3 * x + 1];
                d[4 * x + 2] = s[3 * x + 0];
                d[4 * x + 3] = 0xFF;
            }
            break;
        case BLOOM_FMT_RGB565:
            for (int x = 0; x < w; x++) {
                const unsigned r = (s[3 * x + 0] * 31u + 127u) / 255u;
                const unsigned g = (s[3 * x + 1] * 63u + 127u) / 255u;
                const unsigned b = (s[3 * x + 2] * 31u + 127u) / 255u;
                const unsigned v = (r << 11) | (g << 5) | b;
                d[2 * x + 0] = (uint8_t)(v & 0xFFu);
                d[2 * x + 1] = (uint8_t)(v >> 8);
            }
            break;
        default:
            return -1;
        }
    }
    return 0;
}

/* "WxH,WxH,..." into w[], h[] (at most max); "none" is 0 sizes; -1 on a
 * malformed list or a size outside 1..BLOOM_MAX_DIM. */
int scene_parse_sizes(const char *s, int *w, int *h, int max)
{
    int n = 0;
    if (!strcmp(s, "none"))
        return 0;
    while (*s) {
        char *end;
        long a = strtol(s, &end, 10);
        if (*end != 'x')
            return -1;
        long b = strtol(end + 1, &end, 10);
        if (a < 1 || b < 1 || a > BLOOM_MAX_DIM || b > BLOOM_MAX_DIM || n == max)
            return -1;
        w[n] = (int)a;
        h[n] = (int)b;
        n++;
        if (*end == ',')
            end++;
        else if (*end)
            return -1;
        s = end;
    }
    return n;
}
