/* The report's inputs at any frame size (report.h). Setup only, never timed. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "imgio.h"
#include "report.h"
#include "scene.h"

int rin_nn(int x, int n, int s)
{
    const int i = (int)(((double)x + 0.5) * s / n);
    return i < s ? i : s - 1;
}

static int alloc_frame(rin_t *f, const char *name, int w, int h, bloom_format_t fmt)
{
    memset(f, 0, sizeof *f);
    snprintf(f->name, sizeof f->name, "%s", name);
    f->w = w;
    f->h = h;
    f->fmt = fmt;
    f->stride = (size_t)w * (size_t)bloom_format_bpp(fmt);
    f->bytes = f->stride * (size_t)h;
    f->p = rxmalloc(f->bytes);
    f->codes = rxmalloc((size_t)w * (size_t)h * 3u * sizeof *f->codes);
    f->src_max = fmt == BLOOM_FMT_RGBQ16 ? 0 : 255;
    return 0;
}

void rin_free(rin_t *f)
{
    free(f->p);
    free(f->codes);
    memset(f, 0, sizeof *f);
}

int rin_from_words(rin_t *f, const char *name, int w, int h, uint32_t *words)
{
    alloc_frame(f, name, w, h, BLOOM_FMT_RGBQ16);
    memcpy(f->p, words, f->bytes);
    free(f->codes);
    f->codes = words;
    return 0;
}

/* RGB888 bytes (packed) into the frame and its model codes. */
static void set_rgb(rin_t *f, const uint8_t *rgb)
{
    const size_t n = (size_t)f->w * (size_t)f->h * 3u;
    memcpy(f->p, rgb, n);
    for (size_t i = 0; i < n; i++)
        f->codes[i] = rgb[i];
}

/* A real image, nearest-neighbour to w x h: PPM to RGB888 (8-bit codes),
 * PFM to RGBQ16 through img_float_to_q16. */
static int from_file(rin_t *f, const char *name, const char *path, int w, int h, char *err, size_t errlen)
{
    img_t im;
    if (img_read(path, &im, err, errlen))
        return -1;
    alloc_frame(f, name, w, h, im.f32 ? BLOOM_FMT_RGBQ16 : BLOOM_FMT_RGB888);
    const unsigned mv = im.maxval > 0 ? (unsigned)im.maxval : 1u;
    for (int y = 0; y < h; y++) {
        const int sy = rin_nn(y, h, im.height);
        for (int x = 0; x < w; x++) {
            const int sx = rin_nn(x, w, im.width);
            const size_t si = ((size_t)sy * (size_t)im.width + (size_t)sx) * (size_t)im.channels;
            const size_t di = ((size_t)y * (size_t)w + (size_t)x) * 3u;
            for (int c = 0; c < 3; c++) {
                const size_t s = si + (size_t)(im.channels == 3 ? c : 0);
                if (im.f32) {
                    const uint32_t q = img_float_to_q16(im.f32[s]);
                    f->codes[di + (size_t)c] = q;
                    memcpy(f->p + 4u * (di + (size_t)c), &q, 4);
                } else {
                    const uint32_t v = (im.u16[s] * 255u + mv / 2u) / mv;
                    f->codes[di + (size_t)c] = v;
                    f->p[di + (size_t)c] = (uint8_t)v;
                }
            }
        }
    }
    img_free(&im);
    return 0;
}

/* A white disc of radius r (pixels) centred at (cx, cy). */
static void disc(uint8_t *rgb, int w, int h, double cx, double cy, double r)
{
    for (int y = (int)floor(cy - r); y <= (int)ceil(cy + r); y++)
        for (int x = (int)floor(cx - r); x <= (int)ceil(cx + r); x++) {
            const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
            if (x < 0 || y < 0 || x >= w || y >= h || dx * dx + dy * dy > r * r)
                continue;
            memset(rgb + ((size_t)y * (size_t)w + (size_t)x) * 3u, 255, 3);
        }
}

int rin_make(rin_t *f, const char *name, const char *data_dir, int w, int h, char *err, size_t errlen)
{
    static const struct {
        const char *name, *file;
    } files[] = {
        {"rocket", "rocket_floodlights.ppm"},
        {"hubble", "hubble_deep_field.ppm"},
        {"studio", "studio_lamps.pfm"},
        {"hall", "hall_lamps.pfm"},
    };
    char path[1024];
    memset(f, 0, sizeof *f);
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++)
        if (!strcmp(name, files[i].name)) {
            snprintf(path, sizeof path, "%s/%s", data_dir, files[i].file);
            return from_file(f, name, path, w, h, err, errlen);
        }
    const size_t n = (size_t)w * (size_t)h * 3u;
    uint8_t *rgb = rxmalloc(n);
    if (!strcmp(name, "scene") || !strcmp(name, "scene-hubble")) {
        snprintf(path, sizeof path, "%s/%s", data_dir,
                 strcmp(name, "scene") ? "hubble_deep_field.ppm" : "rocket_floodlights.ppm");
        if (scene_make(path, w, h, rgb, err, errlen)) {
            free(rgb);
            return -1;
        }
    } else if (!strcmp(name, "dark") || !strcmp(name, "sparse") || !strcmp(name, "grid")) {
        rin_t base;
        if (rin_make(&base, "rocket", data_dir, w, h, err, errlen)) {
            free(rgb);
            return -1;
        }
        for (size_t i = 0; i < n; i++) /* at most code 179, linear 0.45 */
            rgb[i] = (uint8_t)((base.p[i] * 7u + 5u) / 10u);
        rin_free(&base);
        if (!strcmp(name, "sparse")) {
            const double r = 0.005 * w < 2.0 ? 2.0 : 0.005 * w;
            disc(rgb, w, h, 0.6 * w, 0.35 * h, r);
        } else if (!strcmp(name, "grid")) {
            for (int y = 32; y < h + 32; y += 64)
                for (int x = 32; x < w + 32; x += 64)
                    disc(rgb, w, h, x < w ? x : w - 1, y < h ? y : h - 1, 6.0);
        }
    } else if (!strcmp(name, "point") || !strcmp(name, "hdr-point")) {
        memset(rgb, 0, n); /* black, a 3x3 block at the top value in the centre */
        for (int y = h / 2 - 1; y <= h / 2 + 1; y++)
            for (int x = w / 2 - 1; x <= w / 2 + 1; x++)
                if (x >= 0 && y >= 0 && x < w && y < h)
                    memset(rgb + ((size_t)y * (size_t)w + (size_t)x) * 3u, 255, 3);
        if (name[0] == 'h') {
            uint32_t *words = rxmalloc(n * 4u);
            for (size_t i = 0; i < n; i++)
                words[i] = rgb[i] ? BLOOM_MAX_LINEAR : 0u;
            free(rgb);
            return rin_from_words(f, name, w, h, words);
        }
    } else {
        snprintf(err, errlen, "unknown input '%s'", name);
        free(rgb);
        return -1;
    }
    alloc_frame(f, name, w, h, BLOOM_FMT_RGB888);
    set_rgb(f, rgb);
    free(rgb);
    return 0;
}
