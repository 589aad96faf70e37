/* A decoded image file as an engine frame: PPM/PGM as RGB888 (8-bit codes;
 * other maxvals rescaled), PFM as RGBQ16 through img_float_to_q16's rule.
 * The format is in the returned frame's fmt. */
#ifndef BLOOM_IMGFRAME_H
#define BLOOM_IMGFRAME_H

#include "imgio.h"
#include "testutil.h"

static inline frame_t frame_from_img(const img_t *im)
{
    frame_t f = frame_alloc(im->width, im->height, im->f32 ? BLOOM_FMT_RGBQ16 : BLOOM_FMT_RGB888, 0);
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++)
            for (int ch = 0; ch < 3; ch++) {
                size_t i = ((size_t)y * (size_t)im->width + (size_t)x) * (size_t)im->channels +
                           (size_t)(im->channels == 3 ? ch : 0);
                uint8_t *p = f.p + (size_t)y * f.stride + (size_t)x * (size_t)f.bpp;
                if (im->f32) {
                    uint32_t q = img_float_to_q16(im->f32[i]);
                    memcpy(p + 4 * ch, &q, 4);
                } else {
                    p[ch] = (uint8_t)(im->u16[i] * 255u / (unsigned)im->maxval);
                }
            }
    return f;
}

/* tests/data/<name> (or $BLOOM_DATA_DIR/<name>) decoded; 0 (with a
 * message) if it cannot be read. */
static inline int imgframe_read(const char *name, img_t *im)
{
    const char *dir = getenv("BLOOM_DATA_DIR");
    char path[512], err[512];
    snprintf(path, sizeof path, "%s/%s", dir ? dir : "tests/data", name);
    if (img_read(path, im, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 0;
    }
    return 1;
}

/* The same as a frame. */
static inline int imgframe_load(const char *name, frame_t *out)
{
    img_t im;
    if (!imgframe_read(name, &im))
        return 0;
    *out = frame_from_img(&im);
    img_free(&im);
    return 1;
}

/* A float image (PFM) times an exposure scale as an RGBF32 frame; values
 * are kept below 256 (the engine's largest sample; the float model would
 * not clamp them) and negative ones at 0. 0 if it is not a float image. */
static inline int imgframe_load_f32(const char *name, double scale, frame_t *out)
{
    img_t im;
    if (!imgframe_read(name, &im))
        return 0;
    if (!im.f32) {
        fprintf(stderr, "%s: not a float image\n", name);
        img_free(&im);
        return 0;
    }
    *out = frame_alloc(im.width, im.height, BLOOM_FMT_RGBF32, 0);
    for (int y = 0; y < im.height; y++)
        for (int x = 0; x < im.width; x++)
            for (int ch = 0; ch < 3; ch++) {
                const size_t i = ((size_t)y * (size_t)im.width + (size_t)x) * (size_t)im.channels +
                                 (size_t)(im.channels == 3 ? ch : 0);
                float v = (float)(im.f32[i] * scale);
                v = v > 0.0f ? (v < 255.99998f ? v : 255.99998f) : 0.0f;
                memcpy(out->p + (size_t)y * out->stride + (size_t)x * 12u + 4u * (size_t)ch, &v, 4);
            }
    img_free(&im);
    return 1;
}

#endif
