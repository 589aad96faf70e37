/* The host tests' JPEG frames (test_mjpeg.c, test_cam_mt.c): libjpeg's
 * own encoder, as a camera's MJPEG. */
#ifndef CAM_TEST_JPEG_H
#define CAM_TEST_JPEG_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <jpeglib.h>

/* libjpeg's encoder, standard Huffman tables (no optimize_coding, as
 * cameras use them). sub 1: 4:4:4, 2: 4:2:0; grey: one component. The
 * JPEG is malloc'd (*out). Rows of stride bytes. */
static inline size_t test_jpeg_encode(const uint8_t *rgb, int w, int h, size_t stride, int quality, int sub,
                                      int grey, unsigned char **out)
{
    struct jpeg_compress_struct ci;
    struct jpeg_error_mgr jerr;
    unsigned long len = 0;
    *out = NULL;
    ci.err = jpeg_std_error(&jerr);
    jpeg_create_compress(&ci);
    jpeg_mem_dest(&ci, out, &len);
    ci.image_width = (JDIMENSION)w;
    ci.image_height = (JDIMENSION)h;
    ci.input_components = 3;
    ci.in_color_space = JCS_RGB;
    jpeg_set_defaults(&ci);
    if (grey)
        jpeg_set_colorspace(&ci, JCS_GRAYSCALE);
    jpeg_set_quality(&ci, quality, TRUE);
    ci.comp_info[0].h_samp_factor = ci.comp_info[0].v_samp_factor = sub;
    jpeg_start_compress(&ci, TRUE);
    while (ci.next_scanline < ci.image_height) {
        JSAMPROW r = (JSAMPROW)(rgb + (size_t)ci.next_scanline * stride);
        jpeg_write_scanlines(&ci, &r, 1);
    }
    jpeg_finish_compress(&ci);
    jpeg_destroy_compress(&ci);
    return len;
}

#endif
