/* bloom_cam: the capture formats — which fourccs are converted and how
 * (cam_conv.c's rows), the Y'CbCr rule of a driver's colorimetry, and the
 * choice of --format auto. Pure: no device here (v4l2.c asks the driver). */
#include <stdio.h>
#include <string.h>

#include <linux/videodev2.h>

#include "cam.h"

/* Best first for --format auto (rank): full chroma before 4:2:2 before
 * 4:2:0, 8 bits per sample before RGB565's 5/6/5, GREY (no colour) and
 * then the compressed MJPEG and JPEG last;
 * packed before semi-planar at equal sampling, one buffer before two. The
 * ...M fourccs exist only on multi-planar devices. */
static const cam_fmt_t fmts[] = {
    {"rgb24", "rgb24", V4L2_PIX_FMT_RGB24, CAM_FMT_RGB24, 1, 3, -1, 0},
    {"yuyv", "yuyv", V4L2_PIX_FMT_YUYV, CAM_FMT_YUYV, 1, 2, -1, 1},
    {"uyvy", "uyvy", V4L2_PIX_FMT_UYVY, CAM_FMT_UYVY, 1, 2, -1, 2},
    {"yvyu", "yvyu", V4L2_PIX_FMT_YVYU, CAM_FMT_YVYU, 1, 2, -1, 3},
    {"nv16", "nv16", V4L2_PIX_FMT_NV16, CAM_FMT_NV16, 1, 1, 0, 4},
    {"nv61", "nv61", V4L2_PIX_FMT_NV61, CAM_FMT_NV61, 1, 1, 0, 5},
    {"nv16m", "nv16", V4L2_PIX_FMT_NV16M, CAM_FMT_NV16M, 2, 1, 0, 6},
    {"nv61m", "nv61", V4L2_PIX_FMT_NV61M, CAM_FMT_NV61M, 2, 1, 0, 7},
    {"nv12", "nv12", V4L2_PIX_FMT_NV12, CAM_FMT_NV12, 1, 1, 1, 8},
    {"nv21", "nv21", V4L2_PIX_FMT_NV21, CAM_FMT_NV21, 1, 1, 1, 9},
    {"nv12m", "nv12", V4L2_PIX_FMT_NV12M, CAM_FMT_NV12M, 2, 1, 1, 10},
    {"nv21m", "nv21", V4L2_PIX_FMT_NV21M, CAM_FMT_NV21M, 2, 1, 1, 11},
    {"rgb565", "rgb565", V4L2_PIX_FMT_RGB565, CAM_FMT_RGB565, 1, 2, -1, 12},
    {"grey", "grey", V4L2_PIX_FMT_GREY, CAM_FMT_GREY, 1, 1, -1, 13},
    /* compressed (bpp 0): decoded, not converted (cam_mjpeg.c); last, since
     * a camera's JPEG has lost detail and costs a decode, yet chosen where
     * it is the one format offering the size or the rate (USB webcams'
     * large sizes) */
    {"mjpeg", "mjpeg", V4L2_PIX_FMT_MJPEG, CAM_FMT_MJPEG, 1, 0, -1, 14},
    {"jpeg", "mjpeg", V4L2_PIX_FMT_JPEG, CAM_FMT_JPEG, 1, 0, -1, 15},
};
enum { NFMTS = sizeof fmts / sizeof fmts[0] };

const cam_fmt_t *cam_fmt_of_fourcc(uint32_t fourcc)
{
    for (int i = 0; i < NFMTS; i++)
        if (fmts[i].fourcc == fourcc)
            return &fmts[i];
    return NULL;
}

const cam_fmt_t *cam_fmt_of_opt(enum cam_pixfmt f)
{
    for (int i = 0; i < NFMTS; i++)
        if (fmts[i].opt == f)
            return &fmts[i];
    return NULL;
}

/* V4L2's defaults (videodev2.h, the colorspaces chapter): an encoding
 * DEFAULT is the colorspace's (V4L2_MAP_YCBCR_ENC_DEFAULT: BT.709 for
 * REC709 and DCI-P3, else BT.601 but for BT.2020 and SMPTE 240M), a
 * quantization DEFAULT is full range for the JPEG colorspace, else limited
 * (V4L2_MAP_QUANTIZATION_DEFAULT for Y'CbCr). xvYCC is its matrix in
 * limited range; BT.2020 and SMPTE 240M are converted with BT.709's matrix
 * (the nearest of the two here), and said. */
const char *cam_colorimetry(uint32_t colorspace, uint32_t ycbcr_enc, uint32_t quantization, int *bt709,
                            int *full)
{
    const char *note = "";
    if (ycbcr_enc == V4L2_YCBCR_ENC_DEFAULT)
        ycbcr_enc = V4L2_MAP_YCBCR_ENC_DEFAULT(colorspace);
    if (quantization == V4L2_QUANTIZATION_DEFAULT)
        quantization = V4L2_MAP_QUANTIZATION_DEFAULT(0, colorspace, ycbcr_enc);
    switch (ycbcr_enc) {
    case V4L2_YCBCR_ENC_601:
    case V4L2_YCBCR_ENC_XV601:
        *bt709 = 0;
        break;
    case V4L2_YCBCR_ENC_709:
    case V4L2_YCBCR_ENC_XV709:
        *bt709 = 1;
        break;
    case V4L2_YCBCR_ENC_BT2020:
    case V4L2_YCBCR_ENC_BT2020_CONST_LUM:
        *bt709 = 1;
        note = " (the driver's BT.2020 converted as BT.709)";
        break;
    case V4L2_YCBCR_ENC_SMPTE240M:
        *bt709 = 1;
        note = " (the driver's SMPTE 240M converted as BT.709)";
        break;
    default:
        *bt709 = 0;
        note = " (an unknown Y'CbCr encoding converted as BT.601)";
        break;
    }
    *full = quantization == V4L2_QUANTIZATION_FULL_RANGE;
    return note;
}

int cam_fmt_best(const cam_fmt_cand_t *c, int n)
{
    int best = -1;
    for (int i = 0; i < n; i++) {
        if (!c[i].f)
            continue;
        if (best < 0) {
            best = i;
            continue;
        }
        const cam_fmt_cand_t *a = &c[i], *b = &c[best];
        if (a->size_ok != b->size_ok ? a->size_ok > b->size_ok
            : a->fps_ok != b->fps_ok ? a->fps_ok > b->fps_ok
                                     : a->f->rank < b->f->rank)
            best = i;
    }
    return best;
}

void cam_cap_row(const cam_v4l2_t *c, const uint8_t *data, const uint8_t *data2, int y, uint8_t *dst)
{
    const uint8_t *row = data + (size_t)y * c->bytesperline;
    const cam_ycc_t *m = cam_ycc(c->bt709, c->full);
    const cam_fmt_t *f = cam_fmt_of_fourcc(c->pixelformat);
    const uint32_t pf = c->pixelformat;
    if (f && f->chroma >= 0) { /* NV..: Cb Cr (or Cr Cb) pairs on the chroma rows */
        const uint32_t bpl2 = c->bytesperline2 ? c->bytesperline2 : c->bytesperline;
        if (!data2)
            data2 = data + (size_t)c->bytesperline * (size_t)c->height;
        const int vu = pf == V4L2_PIX_FMT_NV21 || pf == V4L2_PIX_FMT_NV21M || pf == V4L2_PIX_FMT_NV61 ||
                       pf == V4L2_PIX_FMT_NV61M;
        cam_nv_row_to_rgb888(m, vu, row, data2 + (size_t)(y >> f->chroma) * bpl2, dst, c->width);
        return;
    }
    switch (pf) {
    case V4L2_PIX_FMT_YUYV:
        cam_packed422_row_to_rgb888(m, CAM_422_YUYV, row, dst, c->width);
        break;
    case V4L2_PIX_FMT_UYVY:
        cam_packed422_row_to_rgb888(m, CAM_422_UYVY, row, dst, c->width);
        break;
    case V4L2_PIX_FMT_YVYU:
        cam_packed422_row_to_rgb888(m, CAM_422_YVYU, row, dst, c->width);
        break;
    case V4L2_PIX_FMT_RGB565:
        cam_rgb565_row_to_rgb888(row, dst, c->width);
        break;
    case V4L2_PIX_FMT_GREY:
        cam_grey_row_to_rgb888(row, dst, c->width);
        break;
    default: /* RGB24 */
        memcpy(dst, row, (size_t)c->width * 3);
        break;
    }
}
