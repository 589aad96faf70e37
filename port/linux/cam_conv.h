/* The camera tool's row converters (cam_conv.c), on their own so that the
 * GStreamer element (port/gstreamer) builds them from the same source
 * without the rest of cam.h. BT.601 limited range both ways, in the
 * simulator's integers (sim/docs/simulator.md): Y'CbCr -> R'G'B' as
 * bloom_sim reads YUYV, R'G'B' -> Y'CbCr as bloom_sim writes Y4M. */
#ifndef BLOOM_CAM_CONV_H
#define BLOOM_CAM_CONV_H

#include <stdint.h>

/* One row of YUYV (BT.601 limited range, the simulator's integer rule) to
 * RGB888; width even. */
void cam_yuyv_row_to_rgb888(const uint8_t *src, uint8_t *dst, int width);
/* One row of RGB888 to YUYV (Y0 U Y1 V per pixel pair), BT.601 limited
 * range by bloom_sim's Y4M rule: Y of each pixel, U and V of the pair's
 * two pixels averaged (a 2x1 block). An odd width: the last pair is the
 * last pixel alone, its Y written twice (dst holds (width + 1) / 2 * 4
 * bytes). */
void cam_rgb888_row_to_yuyv(const uint8_t *src, uint8_t *dst, int width);
/* One row of GREY (full range) to RGB888. */
void cam_grey_row_to_rgb888(const uint8_t *src, uint8_t *dst, int width);
/* BT.601 limited-range Y'CbCr to R'G'B' codes (used by the row function). */
void cam_ycbcr_to_rgb(int y, int cb, int cr, uint8_t rgb[3]);

#endif
