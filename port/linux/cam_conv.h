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

/* ---- every matrix and range (the capture formats beyond YUYV) ------------
 * A Y'CbCr -> R'G'B' rule: BT.601 (Kr 0.299, Kb 0.114) or BT.709 (Kr 0.2126,
 * Kb 0.0722), limited range (Y' 16..235, chroma 16..240) or full (0..255),
 * the coefficients round(x * 65536) in the table of cam_conv.c; each channel
 * clamp((t + 32768) >> 16, 0, 255), t the Q16 sum: round half up, the one
 * rounding rule (the simulator's, sim/sim_convert.c: bloom_sim
 * --raw-ycbcr). */
typedef struct {
    int32_t y, y0;      /* R'G'B' = y * (Y' - y0) + ... (Q16) */
    int32_t rv, gu, gv; /* R' += rv V, G' -= gu U + gv V (U = Cb - 128, V = Cr - 128) */
    int32_t bu;         /* B' += bu U */
} cam_ycc_t;
/* The rule of a matrix (0 BT.601, 1 BT.709) and range (0 limited, 1 full). */
const cam_ycc_t *cam_ycc(int bt709, int full);
void cam_ycc_to_rgb(const cam_ycc_t *m, int y, int cb, int cr, uint8_t rgb[3]);
/* Packed 4:2:2, two pixels in four bytes; the byte order of the group: */
enum { CAM_422_YUYV = 0, CAM_422_UYVY, CAM_422_YVYU, CAM_422_VYUY };
/* One row to RGB888. An odd width: the last pixel is its group's first
 * (src holds (width + 1) / 2 * 4 bytes). */
void cam_packed422_row_to_rgb888(const cam_ycc_t *m, int order, const uint8_t *src, uint8_t *dst, int width);
/* One row of a semi-planar format (NV12/NV21 4:2:0, NV16/NV61 4:2:2): the
 * luma row y and the chroma row that serves it (Cb Cr pairs; Cr Cb when
 * vu), each pair shared by two pixels; an odd width's last pixel has a
 * pair of its own ((width + 1) / 2 pairs). */
void cam_nv_row_to_rgb888(const cam_ycc_t *m, int vu, const uint8_t *y, const uint8_t *uv, uint8_t *dst,
                          int width);
/* One row of RGB565 (little-endian rrrrrggg gggbbbbb) to RGB888, each code
 * c of n bits to round half up of c * 255 / (2^n - 1) (bloom_sim's rule for
 * codes between ranges). */
void cam_rgb565_row_to_rgb888(const uint8_t *src, uint8_t *dst, int width);

#endif
