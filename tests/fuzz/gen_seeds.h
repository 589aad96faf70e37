/* tests/fuzz/gen_seeds.c: the seed corpora's generator. */
#ifndef BLOOM_GEN_SEEDS_H
#define BLOOM_GEN_SEEDS_H

#include <stddef.h>
#include <stdint.h>

/* PNG of rgb (8-bit RGB, w*h*3) as colour type color at depth (1..16). */
int gs_png(const char *path, const uint8_t *rgb, int w, int h, int color, int depth, int interlace);
/* JPEG of rgb: grey, progressive, arithmetic coding, 4:2:0 (else 4:4:4), restart interval. */
int gs_jpeg(const char *path, const uint8_t *rgb, int w, int h, int grey, int progressive, int arith,
            int subsample, int restart);
/* OpenEXR of rgb (3 floats per pixel); nch 1 (Y), 3 or 4 (RGBA); comp an exr_compression_t;
 * tile 0 for scanlines. -1 when built without OpenEXR. */
int gs_exr(const char *path, const float *rgb, int w, int h, int nch, int half, int comp, int tile);

/* Writes CORPUS/target/name (gen_seeds.c). */
void gs_put(const char *target, const char *name, const void *data, size_t len);
/* The seeds of fuzz_api, fuzz_cam_opts and fuzz_cam_conv (gen_seeds_api.c). */
void gs_seeds_api(void);

#endif
