/* bloom_cam: what a V4L2 device is asked for, and what its answers mean
 * (v4l2.c opens and streams): --format auto's choice among what the device
 * offers (VIDIOC_ENUM_FMT, its sizes and frame rates), the planes' sizes
 * of the format S_FMT set, and --fps. Every ioctl goes through the seam
 * in cam_v4l2_t (test_host.c scripts it). */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include <linux/videodev2.h>

#include "cam.h"

/* Whether the device offers fourcc at w x h (VIDIOC_ENUM_FRAMESIZES; a
 * driver without it: yes, S_FMT will adjust). */
static int size_offered(cam_v4l2_t *c, uint32_t fourcc, int w, int h)
{
    struct v4l2_frmsizeenum s;
    for (uint32_t i = 0;; i++) {
        memset(&s, 0, sizeof s);
        s.index = i;
        s.pixel_format = fourcc;
        if (cam_v4l2_ioctl(c, VIDIOC_ENUM_FRAMESIZES, &s))
            return i == 0;
        if (s.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
            if (s.discrete.width == (uint32_t)w && s.discrete.height == (uint32_t)h)
                return 1;
            continue;
        }
        const struct v4l2_frmsize_stepwise *t = &s.stepwise;
        const uint32_t sw = t->step_width ? t->step_width : 1, sh = t->step_height ? t->step_height : 1;
        return (uint32_t)w >= t->min_width && (uint32_t)w <= t->max_width && (uint32_t)h >= t->min_height &&
               (uint32_t)h <= t->max_height && ((uint32_t)w - t->min_width) % sw == 0 &&
               ((uint32_t)h - t->min_height) % sh == 0;
    }
}

/* Whether fps is offered at fourcc, w x h (VIDIOC_ENUM_FRAMEINTERVALS; a
 * driver without it: yes). */
static int fps_offered(cam_v4l2_t *c, uint32_t fourcc, int w, int h, int fps)
{
    struct v4l2_frmivalenum s;
    for (uint32_t i = 0; fps > 0; i++) {
        memset(&s, 0, sizeof s);
        s.index = i;
        s.pixel_format = fourcc;
        s.width = (uint32_t)w;
        s.height = (uint32_t)h;
        if (cam_v4l2_ioctl(c, VIDIOC_ENUM_FRAMEINTERVALS, &s))
            return i == 0;
        const uint64_t f = (uint64_t)fps;
        if (s.type == V4L2_FRMIVAL_TYPE_DISCRETE) { /* an interval num/den s: fps = den/num */
            if (s.discrete.numerator && f * s.discrete.numerator == s.discrete.denominator)
                return 1;
            continue;
        }
        const struct v4l2_fract *lo = &s.stepwise.min, *hi = &s.stepwise.max;
        return f * lo->numerator <= lo->denominator && hi->denominator <= f * hi->numerator;
    }
    return 1;
}

/* --format auto: the best of what VIDIOC_ENUM_FMT lists (cam_fmt_best),
 * said on one line. 0 when there is none to convert (message printed). */
uint32_t cam_v4l2_choose_format(cam_v4l2_t *c, const char *dev, int w, int h, int fps)
{
    cam_fmt_cand_t cand[32];
    char offered[200] = "", usable[160] = ""; /* every fourcc (printable), the names converted */
    int n = 0, others = 0;
    for (uint32_t i = 0; n < 32; i++) {
        struct v4l2_fmtdesc d;
        memset(&d, 0, sizeof d);
        d.index = i;
        d.type = cam_v4l2_buf_type(c);
        if (cam_v4l2_ioctl(c, VIDIOC_ENUM_FMT, &d))
            break;
        char cc[5];
        for (int j = 0; j < 4; j++) { /* the big-endian flag (bit 31) and spaces shown as they read */
            const char ch = (char)((d.pixelformat >> (8 * j)) & 0x7f);
            cc[j] = ch > ' ' && ch < 127 ? ch : ch == ' ' ? '\0' : '?';
        }
        cc[4] = '\0';
        size_t k = strlen(offered);
        snprintf(offered + k, sizeof offered - k, "%s%s", k ? " " : "", cc);
        const cam_fmt_t *f = cam_fmt_of_fourcc(d.pixelformat);
        if (!f || (f->planes == 2 && !c->mplane) || (f->bpp && (d.flags & V4L2_FMT_FLAG_COMPRESSED))) {
            others++;
            continue;
        }
        k = strlen(usable);
        snprintf(usable + k, sizeof usable - k, "%s%s", k ? " " : "", f->name);
        cand[n].f = f;
        cand[n].size_ok = size_offered(c, f->fourcc, w, h);
        cand[n].fps_ok = fps_offered(c, f->fourcc, w, h, fps);
        n++;
    }
    const int b = cam_fmt_best(cand, n);
    if (b < 0) {
        cam_v4l2_say(c, "VIDIOC_ENUM_FMT: %s offers %s: none of them converted here (--format)", dev,
                     offered[0] ? offered : "no format");
        return 0;
    }
    if (!c->quiet) {
        fprintf(stderr, "%s: --format auto: %s of %s (and %d formats not converted here; %dx%d %s", CAM_PROG,
                cand[b].f->name, usable, others, w, h,
                cand[b].size_ok ? "offered" : "not offered: the driver's nearest");
        if (fps)
            fprintf(stderr, ", %d fps %s", fps, cand[b].fps_ok ? "offered" : "not offered");
        fputs(")\n", stderr);
    }
    return cand[b].f->fourcc;
}

/* The planes' sizes of the format in force, from S_FMT's answer: 0, or -1
 * (message said) when the driver's numbers cannot hold a frame. */
int cam_v4l2_layout(cam_v4l2_t *c, const cam_fmt_t *f, const struct v4l2_format *fm)
{
    uint32_t size[2] = {0, 0};
    if (c->mplane) {
        const struct v4l2_pix_format_mplane *mp = &fm->fmt.pix_mp;
        c->nplanes = mp->num_planes;
        c->bytesperline = mp->plane_fmt[0].bytesperline;
        c->bytesperline2 = mp->num_planes == 2 ? mp->plane_fmt[1].bytesperline : 0;
        size[0] = mp->plane_fmt[0].sizeimage;
        size[1] = mp->num_planes == 2 ? mp->plane_fmt[1].sizeimage : 0;
        c->sizeimage = size[0] + size[1];
        if (mp->num_planes != f->planes) {
            cam_v4l2_say(c, "VIDIOC_S_FMT: %s in %u planes, not %d", f->name, (unsigned)mp->num_planes,
                         f->planes);
            return -1;
        }
    } else {
        c->nplanes = 1;
        c->bytesperline = fm->fmt.pix.bytesperline;
        c->sizeimage = size[0] = fm->fmt.pix.sizeimage;
    }
    const uint32_t minline = (uint32_t)c->width * (uint32_t)f->bpp;
    if (!f->bpp) /* compressed: no rows, a frame is what bytesused says (cam_mjpeg.c checks it) */
        c->bytesperline = 0;
    if (c->bytesperline < minline)
        c->bytesperline = minline; /* some drivers leave it 0 */
    const uint32_t luma = c->bytesperline * (uint32_t)c->height;
    c->plane_bytes[0] = luma;
    c->plane_bytes[1] = 0;
    if (f->chroma >= 0) { /* NV..: the chroma rows, in the first plane or the second */
        const uint32_t rows = ((uint32_t)c->height + (uint32_t)f->chroma) >> f->chroma;
        if (c->bytesperline2 < minline + (minline & 1))
            c->bytesperline2 = c->nplanes == 2 ? minline + (minline & 1) : c->bytesperline;
        c->plane_bytes[c->nplanes - 1] += c->bytesperline2 * rows;
    }
    for (int p = 0; p < c->nplanes; p++)
        if (size[p] < c->plane_bytes[p]) {
            cam_v4l2_say(
                c,
                "VIDIOC_S_FMT: unusable format %dx%d %s, bytesperline %u, plane %d of %u bytes (%u needed)",
                c->width, c->height, f->name, (unsigned)c->bytesperline, p, (unsigned)size[p],
                (unsigned)c->plane_bytes[p]);
            return -1;
        }
    return 0;
}

/* --fps: VIDIOC_S_PARM; what the driver set is kept (c->fps), a driver
 * without frame rates is said, not refused. */
void cam_v4l2_set_fps(cam_v4l2_t *c, int fps)
{
    struct v4l2_streamparm sp;
    memset(&sp, 0, sizeof sp);
    sp.type = cam_v4l2_buf_type(c);
    sp.parm.capture.timeperframe.numerator = 1;
    sp.parm.capture.timeperframe.denominator = (uint32_t)fps;
    if (cam_v4l2_ioctl(c, VIDIOC_S_PARM, &sp) || !(sp.parm.capture.capability & V4L2_CAP_TIMEPERFRAME)) {
        if (!c->quiet)
            fprintf(stderr, "%s: --fps %d: the driver sets no frame rate (VIDIOC_S_PARM: %s)\n", CAM_PROG,
                    fps, errno ? strerror(errno) : "no V4L2_CAP_TIMEPERFRAME");
        return;
    }
    const struct v4l2_fract *t = &sp.parm.capture.timeperframe;
    c->fps = t->numerator ? (int)((t->denominator + t->numerator / 2) / t->numerator) : 0;
}
