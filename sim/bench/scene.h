/* The benchmark scene: a real photograph from tests/data stretched to the
 * frame size, plus generated bright spots so that the bloom has work to do.
 * Shared by bloom_bench and bloom_icount (same pixels in both). */
#ifndef BENCH_SCENE_H
#define BENCH_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "bloom.h"

#define SCENE_IMAGE_DEFAULT "tests/data/rocket_floodlights.ppm"
#define SCENE_IMAGE_DEFAULT_ABOUT "640x427, 8-bit sRGB: a launch pad at dusk with floodlights"
#define SCENE_SPOTS 24

/* One-line description for the generated docs. */
extern const char scene_description[];

/* Fills rgb (w*h*3 bytes, RGB888, rows packed) with the scene built from the
 * 8-bit PPM/PGM at image_path. Returns 0, or -1 with a message in err. */
int scene_make(const char *image_path, int w, int h, uint8_t *rgb, char *err, size_t errlen);

/* Converts the RGB888 scene to fmt (RGB888, XRGB8888 or RGB565), rows
 * stride bytes apart. Returns 0, or -1 for a format it does not produce. */
int scene_convert(const uint8_t *rgb, int w, int h, bloom_format_t fmt, uint8_t *dst, size_t stride);

int scene_parse_sizes(const char *s, int *w, int *h, int max); /* "WxH,...", "none" */

#endif
