/* bloom_cam host tests of the capture formats (part of test_cam_host; its
 * closing line counts these): every Y'CbCr rule (BT.601 and BT.709,
 * limited and full range) equal to the simulator's for every triple and
 * within one code of the real formula, with known values (black, white,
 * the primaries); every format's rows (cam_cap_row: packed 4:2:2, NV..
 * 4:2:0 and 4:2:2 single-planar and in two planes, RGB565, with padded
 * rows and odd widths) equal to what bloom_sim's raw reader makes of the
 * same bytes written to a file, fed to the engine as RGB888 (the QEMU
 * cases' comparison, here on random bytes); the edge pixels; the
 * colorimetry defaults of V4L2; --format auto's rule; the multi-planar
 * dequeue (data_offset, two buffers, short planes) through the ioctl seam. */
#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <linux/videodev2.h>

#include "cam.h"
#include "harness.h"
#include "sim.h"

void test_conv(int *pass, int *fail);

static void rules(void)
{
    static const double kr[2] = {0.299, 0.2126}, kb[2] = {0.114, 0.0722};
    for (int r = 0; r < 4; r++) {
        const int bt709 = r >> 1, full = r & 1;
        const cam_ycc_t *m = cam_ycc(bt709, full);
        long mism = 0, far = 0;
        for (int y = 0; y < 256; y++)
            for (int cb = 0; cb < 256; cb += 1 + (y & 1))
                for (int cr = 0; cr < 256; cr += 1 + (y & 1)) {
                    uint8_t a[3];
                    uint32_t s[3];
                    cam_ycc_to_rgb(m, y, cb, cr, a);
                    sim_ycbcr_to_rgb(y, cb, cr, (bt709 ? SIM_YCC_709 : 0) | (full ? SIM_YCC_FULL : 0), s);
                    mism += a[0] != s[0] || a[1] != s[1] || a[2] != s[2];
                    const double ys = full ? 1.0 : 255.0 / 219.0, cs = full ? 1.0 : 255.0 / 224.0;
                    const double yy = (y - (full ? 0 : 16)) * ys, u = (cb - 128) * cs, v = (cr - 128) * cs;
                    const double kg = 1 - kr[bt709] - kb[bt709];
                    const double e[3] = {yy + 2 * (1 - kr[bt709]) * v,
                                         yy - 2 * kb[bt709] * (1 - kb[bt709]) / kg * u -
                                             2 * kr[bt709] * (1 - kr[bt709]) / kg * v,
                                         yy + 2 * (1 - kb[bt709]) * u};
                    for (int c = 0; c < 3; c++)
                        far += fabs(a[c] - (e[c] < 0 ? 0 : e[c] > 255 ? 255 : e[c])) > 1.0;
                }
        CHECKF(mism == 0, "rule %s %s: %ld triples differ from sim_ycbcr_to_rgb", bt709 ? "709" : "601",
               full ? "full" : "limited", mism);
        CHECKF(far == 0, "rule %s %s: %ld channels more than one code from the real formula",
               bt709 ? "709" : "601", full ? "full" : "limited", far);
    }
    /* known values: each rule's black, white, mid grey and primaries, their
     * Y'CbCr rounded to 8 bits (so within a code of the R'G'B' they came
     * from), and two out of gamut (clamped) */
    static const struct {
        int bt709, full, y, cb, cr;
        uint8_t rgb[3];
    } k[] = {
        {0, 0, 16, 128, 128, {0, 0, 0}},        {0, 0, 235, 128, 128, {255, 255, 255}},
        {0, 0, 126, 128, 128, {128, 128, 128}}, {0, 0, 81, 90, 240, {254, 0, 0}},
        {0, 0, 145, 54, 34, {0, 255, 1}},       {0, 0, 41, 240, 110, {0, 0, 255}},
        {0, 1, 0, 128, 128, {0, 0, 0}},         {0, 1, 255, 128, 128, {255, 255, 255}},
        {0, 1, 128, 128, 128, {128, 128, 128}}, {0, 1, 76, 85, 255, {254, 0, 0}},
        {0, 1, 150, 44, 21, {0, 255, 1}},       {0, 1, 29, 255, 107, {0, 0, 254}},
        {1, 0, 16, 128, 128, {0, 0, 0}},        {1, 0, 235, 128, 128, {255, 255, 255}},
        {1, 0, 126, 128, 128, {128, 128, 128}}, {1, 0, 63, 102, 240, {255, 1, 0}},
        {1, 0, 173, 42, 26, {0, 255, 1}},       {1, 0, 32, 240, 118, {1, 0, 255}},
        {1, 1, 0, 128, 128, {0, 0, 0}},         {1, 1, 255, 128, 128, {255, 255, 255}},
        {1, 1, 128, 128, 128, {128, 128, 128}}, {1, 1, 54, 99, 255, {254, 0, 0}},
        {1, 1, 182, 30, 12, {0, 255, 0}},       {1, 1, 18, 255, 116, {0, 0, 254}},
        {0, 0, 0, 0, 0, {0, 136, 0}},           {0, 0, 255, 255, 255, {255, 125, 255}}, /* clamped */
    };
    for (size_t i = 0; i < sizeof k / sizeof k[0]; i++) {
        uint8_t a[3];
        cam_ycc_to_rgb(cam_ycc(k[i].bt709, k[i].full), k[i].y, k[i].cb, k[i].cr, a);
        CHECKF(!memcmp(a, k[i].rgb, 3), "known value %zu: BT.%s %s (%d %d %d) gave %d %d %d, not %d %d %d", i,
               k[i].bt709 ? "709" : "601", k[i].full ? "full" : "limited", k[i].y, k[i].cb, k[i].cr, a[0],
               a[1], a[2], k[i].rgb[0], k[i].rgb[1], k[i].rgb[2]);
    }
    /* RGB565: every code, round half up of c * 255 / max */
    long bad = 0;
    for (unsigned w = 0; w < 65536; w++) {
        const uint8_t in[2] = {(uint8_t)w, (uint8_t)(w >> 8)};
        uint8_t o[3];
        cam_rgb565_row_to_rgb888(in, o, 1);
        const unsigned c[3] = {w >> 11, (w >> 5) & 63, w & 31}, mx[3] = {31, 63, 31};
        for (int j = 0; j < 3; j++)
            bad += o[j] != (unsigned)floor(c[j] * 255.0 / mx[j] + 0.5);
    }
    CHECKF(bad == 0, "RGB565: %ld channels not round(c * 255 / max)", bad);
}

/* A capture of format fourcc, w x h, rows padded to bpl, as v4l2.c would
 * set it (single-planar, or two planes: the chroma in its own buffer). */
typedef struct {
    uint32_t fourcc;
    sim_raw_fmt_t raw;
    int w, h, pad, two;
} fcase_t;

static void one_format(const fcase_t *t, int bt709, int full)
{
    const cam_fmt_t *f = cam_fmt_of_fourcc(t->fourcc);
    cam_v4l2_t c;
    memset(&c, 0, sizeof c);
    c.width = t->w;
    c.height = t->h;
    c.pixelformat = t->fourcc;
    c.bt709 = bt709;
    c.full = full;
    const size_t row = f->chroma >= 0 ? (size_t)(t->w + (t->w & 1)) : (size_t)((t->w + 1) / 2 * 2) * f->bpp;
    c.bytesperline = (uint32_t)(row + (size_t)t->pad);
    const size_t crow = f->chroma >= 0 ? (size_t)((t->h + f->chroma) >> f->chroma) : 0;
    const size_t n = c.bytesperline * ((size_t)t->h + crow);
    uint8_t *buf = malloc(n), *chroma2 = NULL, *rgb = malloc((size_t)t->w * 3 + 1);
    uint8_t *eng = malloc((size_t)t->w * (size_t)t->h * 3);
    unsigned seed = (unsigned)t->fourcc ^ (unsigned)(t->w * 131 + t->h);
    for (size_t i = 0; buf && i < n; i++) {
        seed = seed * 1103515245u + 12345u;
        buf[i] = (uint8_t)(seed >> 16);
    }
    if (buf && t->two) { /* the second plane elsewhere, the same bytes */
        chroma2 = malloc(c.bytesperline * crow);
        if (chroma2)
            memcpy(chroma2, buf + c.bytesperline * (size_t)t->h, c.bytesperline * crow);
    }
    char path[] = "/tmp/test_conv_XXXXXX", err[256] = "";
    const int fd = mkstemp(path);
    int ok = buf && rgb && eng && (!t->two || chroma2) && fd >= 0 && write(fd, buf, n) == (ssize_t)n;
    if (fd >= 0)
        close(fd);
    sim_input_opts_t o;
    memset(&o, 0, sizeof o);
    o.raw_fmt = t->raw;
    o.raw_w = t->w;
    o.raw_h = t->h;
    o.raw_stride = c.bytesperline;
    o.raw_ycc = (bt709 ? SIM_YCC_709 : 0) | (full ? SIM_YCC_FULL : 0);
    sim_source_t *s = NULL;
    sim_frame_t fr;
    memset(&fr, 0, sizeof fr);
    ok = ok && sim_source_open(&s, path, &o, err, sizeof err) == 0 &&
         sim_source_read(s, &fr, err, sizeof err) == 1;
    if (ok)
        sim_to_engine(&fr, BLOOM_FMT_RGB888, 0, eng);
    long diff = 0, over = 0;
    for (int y = 0; ok && y < t->h; y++) {
        rgb[(size_t)t->w * 3] = 0xA5;
        cam_cap_row(&c, buf, chroma2, y, rgb);
        diff += memcmp(rgb, eng + (size_t)y * (size_t)t->w * 3, (size_t)t->w * 3) != 0;
        over += rgb[(size_t)t->w * 3] != 0xA5;
    }
    CHECKF(ok && diff == 0 && over == 0,
           "%s %dx%d%s%s BT.%s %s: %ld rows differ from bloom_sim's reader, %ld overrun%s%s", f->name, t->w,
           t->h, t->pad ? " padded" : "", t->two ? " (two planes)" : "", bt709 ? "709" : "601",
           full ? "full" : "limited", diff, over, err[0] ? ": " : "", err);
    sim_source_close(s);
    sim_frame_free(&fr);
    remove(path);
    free(buf);
    free(chroma2);
    free(rgb);
    free(eng);
}

static void formats(void)
{
    static const fcase_t t[] = {
        {V4L2_PIX_FMT_YUYV, SIM_RAW_YUYV, 10, 3, 4, 0},    {V4L2_PIX_FMT_UYVY, SIM_RAW_UYVY, 10, 3, 0, 0},
        {V4L2_PIX_FMT_YVYU, SIM_RAW_YVYU, 8, 4, 6, 0},     {V4L2_PIX_FMT_NV12, SIM_RAW_NV12, 9, 5, 0, 0},
        {V4L2_PIX_FMT_NV12, SIM_RAW_NV12, 8, 4, 8, 0},     {V4L2_PIX_FMT_NV21, SIM_RAW_NV21, 7, 3, 2, 0},
        {V4L2_PIX_FMT_NV16, SIM_RAW_NV16, 9, 3, 0, 0},     {V4L2_PIX_FMT_NV61, SIM_RAW_NV61, 6, 2, 4, 0},
        {V4L2_PIX_FMT_NV12M, SIM_RAW_NV12, 9, 5, 3, 1},    {V4L2_PIX_FMT_NV21M, SIM_RAW_NV21, 8, 2, 0, 1},
        {V4L2_PIX_FMT_NV16M, SIM_RAW_NV16, 5, 3, 0, 1},    {V4L2_PIX_FMT_NV61M, SIM_RAW_NV61, 6, 3, 2, 1},
        {V4L2_PIX_FMT_RGB565, SIM_RAW_RGB565, 5, 3, 2, 0}, {V4L2_PIX_FMT_GREY, SIM_RAW_GREY, 5, 2, 3, 0},
        {V4L2_PIX_FMT_RGB24, SIM_RAW_RGB24, 4, 2, 1, 0},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
        for (int r = 0; r < 4; r++)
            if (r == 0 || cam_fmt_of_fourcc(t[i].fourcc)->chroma >= 0 || t[i].raw == SIM_RAW_YUYV ||
                t[i].raw == SIM_RAW_UYVY || t[i].raw == SIM_RAW_YVYU)
                one_format(&t[i], r >> 1, r & 1);

    /* edge pixels: an odd NV row's last pixel has a pair of its own; an
     * odd packed row's last pixel is its group's first; nothing written
     * past width * 3 */
    const cam_ycc_t *m = cam_ycc(0, 1);
    const uint8_t y3[3] = {10, 20, 30}, uv[4] = {128, 128, 200, 60};
    uint8_t o[10], e[3];
    memset(o, 0xA5, sizeof o);
    cam_nv_row_to_rgb888(m, 0, y3, uv, o, 3);
    cam_ycc_to_rgb(m, 30, 200, 60, e);
    CHECKF(!memcmp(o + 6, e, 3) && o[9] == 0xA5 && o[0] == 10 && o[3] == 20, "NV12 odd width: last pixel");
    const uint8_t g[8] = {40, 128, 50, 128, 60, 100, 70, 150};
    memset(o, 0xA5, sizeof o);
    cam_packed422_row_to_rgb888(m, CAM_422_YUYV, g, o, 3);
    cam_ycc_to_rgb(m, 60, 100, 150, e);
    CHECKF(!memcmp(o + 6, e, 3) && o[9] == 0xA5 && o[0] == 40 && o[3] == 50, "YUYV odd width: last pixel");
    memset(o, 0xA5, sizeof o);
    cam_packed422_row_to_rgb888(m, CAM_422_UYVY, g, o, 2); /* U Y0 V Y1: 40 is U, 128 Y0 */
    cam_ycc_to_rgb(m, 128, 40, 50, e);
    CHECKF(!memcmp(o, e, 3) && o[6] == 0xA5, "UYVY byte order");
}

static void colorimetry(void)
{
    static const struct {
        uint32_t cs, enc, q;
        int bt709, full, noted;
    } t[] = {
        {V4L2_COLORSPACE_DEFAULT, V4L2_YCBCR_ENC_DEFAULT, V4L2_QUANTIZATION_DEFAULT, 0, 0, 0},
        {V4L2_COLORSPACE_SRGB, V4L2_YCBCR_ENC_DEFAULT, V4L2_QUANTIZATION_DEFAULT, 0, 0, 0},
        {V4L2_COLORSPACE_SMPTE170M, V4L2_YCBCR_ENC_DEFAULT, V4L2_QUANTIZATION_DEFAULT, 0, 0, 0},
        {V4L2_COLORSPACE_REC709, V4L2_YCBCR_ENC_DEFAULT, V4L2_QUANTIZATION_DEFAULT, 1, 0, 0},
        {V4L2_COLORSPACE_JPEG, V4L2_YCBCR_ENC_DEFAULT, V4L2_QUANTIZATION_DEFAULT, 0, 1, 0},
        {V4L2_COLORSPACE_SRGB, V4L2_YCBCR_ENC_709, V4L2_QUANTIZATION_FULL_RANGE, 1, 1, 0},
        {V4L2_COLORSPACE_REC709, V4L2_YCBCR_ENC_601, V4L2_QUANTIZATION_LIM_RANGE, 0, 0, 0},
        {V4L2_COLORSPACE_SRGB, V4L2_YCBCR_ENC_XV709, V4L2_QUANTIZATION_DEFAULT, 1, 0, 0},
        {V4L2_COLORSPACE_BT2020, V4L2_YCBCR_ENC_DEFAULT, V4L2_QUANTIZATION_DEFAULT, 1, 0, 1},
        {V4L2_COLORSPACE_SMPTE240M, V4L2_YCBCR_ENC_DEFAULT, V4L2_QUANTIZATION_DEFAULT, 1, 0, 1},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        int b = -1, f = -1;
        const char *note = cam_colorimetry(t[i].cs, t[i].enc, t[i].q, &b, &f);
        CHECKF(b == t[i].bt709 && f == t[i].full && (note[0] != 0) == t[i].noted,
               "colorimetry %zu (colorspace %u, encoding %u, quantization %u): bt709 %d full %d note '%s'", i,
               (unsigned)t[i].cs, (unsigned)t[i].enc, (unsigned)t[i].q, b, f, note);
    }
}

static void choice(void)
{
    const cam_fmt_t *yuyv = cam_fmt_of_fourcc(V4L2_PIX_FMT_YUYV),
                    *nv12 = cam_fmt_of_fourcc(V4L2_PIX_FMT_NV12),
                    *rgb24 = cam_fmt_of_fourcc(V4L2_PIX_FMT_RGB24),
                    *grey = cam_fmt_of_fourcc(V4L2_PIX_FMT_GREY),
                    *nv12m = cam_fmt_of_fourcc(V4L2_PIX_FMT_NV12M);
    /* rank alone; the size first; then the frame rate; nothing to convert */
    const cam_fmt_cand_t a[] = {{grey, 1, 1}, {nv12, 1, 1}, {yuyv, 1, 1}, {rgb24, 1, 1}};
    CHECK(cam_fmt_best(a, 4) == 3);
    const cam_fmt_cand_t b[] = {{rgb24, 0, 1}, {nv12, 1, 0}, {yuyv, 1, 0}};
    CHECK(cam_fmt_best(b, 3) == 2);
    const cam_fmt_cand_t c[] = {{rgb24, 1, 0}, {yuyv, 1, 0}, {nv12, 1, 1}};
    CHECK(cam_fmt_best(c, 3) == 2);
    const cam_fmt_cand_t d[] = {{nv12m, 1, 1}, {nv12, 1, 1}};
    CHECK(cam_fmt_best(d, 2) == 1); /* one buffer before two */
    const cam_fmt_cand_t e[] = {{NULL, 1, 1}};
    CHECK(cam_fmt_best(e, 1) == -1 && cam_fmt_best(e, 0) == -1);
    CHECK(cam_fmt_of_fourcc(V4L2_PIX_FMT_H264) ==
          NULL); /* compressed, not decoded (MJPEG is: test_mjpeg.c) */
    CHECK(!strcmp(cam_fmt_of_opt(CAM_FMT_NV16M)->raw, "nv16") && cam_fmt_of_opt(CAM_FMT_NV16M)->planes == 2);
}

/* The multi-planar dequeue through the ioctl/poll seam: each plane's data
 * after its data_offset, the chroma in the second buffer, a plane whose
 * bytesused cannot hold its rows after the offset flagged short (and
 * requeued). */
static uint32_t mp_used[2], mp_off[2];
static int mp_qbufs, mp_bad_type, mp_planes = 2;
static int mp_ioctl(int fd, unsigned long req, void *arg)
{
    (void)fd;
    struct v4l2_buffer *b = arg;
    mp_bad_type |=
        b->type != V4L2_BUF_TYPE_VIDEO_CAPTURE_MPLANE || b->length != (uint32_t)mp_planes || !b->m.planes;
    if (req == (unsigned long)VIDIOC_QBUF) {
        mp_qbufs++;
        return 0;
    }
    if (req != (unsigned long)VIDIOC_DQBUF)
        return -1;
    b->index = 1;
    b->sequence = 7;
    for (int p = 0; p < 2 && b->m.planes; p++) {
        b->m.planes[p].bytesused = mp_used[p];
        b->m.planes[p].data_offset = mp_off[p];
    }
    return 0;
}
static int mp_poll(struct pollfd *fds, nfds_t n, int timeout_ms, const sigset_t *mask)
{
    (void)n, (void)timeout_ms, (void)mask;
    fds[0].revents = POLLIN;
    return 1;
}

static void mplane_dequeue(void)
{
    enum { W = 8, H = 4 };
    static uint8_t luma[2][W * H * 3 / 2 + 128], chroma[2][W * H / 2];
    cam_v4l2_t c;
    memset(&c, 0, sizeof c);
    c.fd = -1;
    c.ioctl_fn = mp_ioctl;
    c.poll_fn = mp_poll;
    c.width = W;
    c.height = H;
    c.pixelformat = V4L2_PIX_FMT_NV12M;
    c.mplane = 1;
    c.nplanes = 2;
    c.bytesperline = c.bytesperline2 = W;
    c.plane_bytes[0] = W * H;
    c.plane_bytes[1] = W * H / 2;
    c.nbufs = 2;
    for (int i = 0; i < 2; i++) {
        c.bufs[i].start = luma[i];
        c.bufs[i].length = sizeof luma[i];
        c.bufs[i].start2 = chroma[i];
        c.bufs[i].length2 = sizeof chroma[i];
    }
    c.streaming = 1;
    cam_frame_t f;
    mp_used[0] = 128 + W * H, mp_off[0] = 128, mp_used[1] = W * H / 2, mp_off[1] = 0;
    int r = cam_v4l2_dequeue(&c, 100, -1, NULL, &f);
    CHECKF(r == 0 && f.index == 1 && f.data == luma[1] + 128 && f.data2 == chroma[1] &&
               f.bad == CAM_BAD_NONE && f.bytesused == 128 + W * H + W * H / 2 && !mp_bad_type,
           "two planes, data_offset 128: %d, index %d, bad %d", r, f.index, f.bad);
    mp_used[1] = W * H / 2 - 1; /* the chroma plane one byte short */
    mp_qbufs = 0;
    r = cam_v4l2_dequeue(&c, 100, -1, NULL, &f);
    CHECKF(r == 2 && f.bad == CAM_BAD_SHORT && mp_qbufs == 1, "short chroma plane: %d, bad %d, %d requeued",
           r, f.bad, mp_qbufs);
    mp_used[1] = W * H / 2, mp_used[0] = W * H + 100, mp_off[0] = 128; /* the offset eats the rows */
    r = cam_v4l2_dequeue(&c, 100, -1, NULL, &f);
    CHECKF(r == 2 && f.bad == CAM_BAD_SHORT, "data_offset past the rows: %d, bad %d", r, f.bad);
    /* one plane (NV12 through the multi-planar API): the chroma after the luma */
    c.nplanes = mp_planes = 1;
    c.pixelformat = V4L2_PIX_FMT_NV12;
    c.plane_bytes[0] = W * H * 3 / 2;
    c.plane_bytes[1] = 0;
    mp_used[0] = 128 + W * H * 3 / 2, mp_off[0] = 128;
    r = cam_v4l2_dequeue(&c, 100, -1, NULL, &f);
    CHECKF(r == 0 && f.data == luma[1] + 128 && f.data2 == luma[1] + 128 + W * H && !mp_bad_type,
           "one plane: %d, bad %d", r, f.bad);
}

void test_conv(int *pass, int *fail)
{
    rules();
    formats();
    colorimetry();
    choice();
    mplane_dequeue();
    *pass += harness_pass;
    *fail += harness_fail;
}
