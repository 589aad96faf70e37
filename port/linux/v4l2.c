/* bloom_cam: V4L2 capture with mmap streaming, single-planar or through
 * the multi-planar API (one plane, or two for the NV..M formats); the
 * format asked (--format) or chosen (auto: v4l2_fmt.c); --fps. Every
 * failure prints "bloom_cam: CALL: reason" once; cam_v4l2_close undoes whatever was done
 * (STREAMOFF, munmap, REQBUFS 0, close) and is safe to call at any point. */
#define _GNU_SOURCE /* ppoll(2), in glibc beside POSIX 2008 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <linux/videodev2.h>

#include "cam.h"

static int sys_ioctl(int fd, unsigned long req, void *arg)
{
    return ioctl(fd, req, arg);
}

int cam_xioctl(int fd, unsigned long req, void *arg)
{
    int r;
    do
        r = ioctl(fd, req, arg);
    while (r == -1 && errno == EINTR);
    return r;
}

int cam_v4l2_ioctl(cam_v4l2_t *c, unsigned long req, void *arg)
{
    int r;
    do
        r = c->ioctl_fn(c->fd, req, arg);
    while (r == -1 && errno == EINTR);
    return r;
}

static int sys_ppoll(struct pollfd *fds, nfds_t nfds, int timeout_ms, const sigset_t *mask)
{
    const struct timespec t = {timeout_ms / 1000, (long)(timeout_ms % 1000) * 1000000L};
    return ppoll(fds, nfds, timeout_ms < 0 ? NULL : &t, mask);
}

void cam_v4l2_say(cam_v4l2_t *c, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->msg, sizeof c->msg, fmt, ap);
    va_end(ap);
    if (!c->quiet)
        fprintf(stderr, "%s: %s\n", CAM_PROG, c->msg);
}

static int sys_fail(cam_v4l2_t *c, const char *call)
{
    cam_v4l2_say(c, "%s: %s", call, strerror(errno));
    return -1;
}

/* A fault of kind `lost` (CAM_LOST_*), its message printed already. */
static int lost(cam_v4l2_t *c, int kind)
{
    c->lost = kind;
    return -1;
}
/* A system call failed: the device's fault (gone, or failing). */
static int dev_fail(cam_v4l2_t *c, const char *call)
{
    sys_fail(c, call);
    return lost(c, CAM_LOST_DEVICE);
}

/* A buffer descriptor and its planes (the multi-planar API points into
 * p): built in place, never copied. */
typedef struct {
    struct v4l2_buffer b;
    struct v4l2_plane p[2];
} vbuf_t;

/* Y'CbCr: a matrix and a range apply (RGB565, RGB24 and GREY have none) */
static int is_ycc(const cam_fmt_t *f)
{
    return f->chroma >= 0 || (f->bpp == 2 && f->opt != CAM_FMT_RGB565);
}

uint32_t cam_v4l2_buf_type(const cam_v4l2_t *c)
{
    return c->mplane ? V4L2_BUF_TYPE_VIDEO_CAPTURE_MPLANE : V4L2_BUF_TYPE_VIDEO_CAPTURE;
}

static int nplanes(const cam_v4l2_t *c)
{
    return c->nplanes == 2 ? 2 : 1;
}

/* An mmap capture buffer descriptor, index set, everything else zero. */
static void mmap_buffer(const cam_v4l2_t *c, vbuf_t *v, int index)
{
    memset(v, 0, sizeof *v);
    v->b.type = cam_v4l2_buf_type(c);
    v->b.memory = V4L2_MEMORY_MMAP;
    v->b.index = (uint32_t)index;
    if (c->mplane) {
        v->b.m.planes = v->p;
        v->b.length = (uint32_t)nplanes(c);
    }
}

int cam_v4l2_open(cam_v4l2_t *c, const char *dev, int w, int h, enum cam_pixfmt fmt, int fps, int nbufs)
{
    const sigset_t *mask = c->wait_mask; /* (the caller's, kept) */
    const int quiet = c->quiet;
    memset(c, 0, sizeof *c);
    c->wait_mask = mask;
    c->quiet = quiet;
    c->ioctl_fn = sys_ioctl;
    c->poll_fn = sys_ppoll;
    c->ycc_note = "";
    c->fd = open(dev, O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (c->fd < 0) {
        cam_v4l2_say(c, "open %s: %s", dev, strerror(errno));
        return lost(c, CAM_LOST_DEVICE);
    }

    struct v4l2_capability cap;
    memset(&cap, 0, sizeof cap);
    if (cam_v4l2_ioctl(c, VIDIOC_QUERYCAP, &cap)) { /* ENOTTY: not a V4L2 device at all (the wrong path) */
        if (errno == ENOTTY || errno == EINVAL)
            return sys_fail(c, "VIDIOC_QUERYCAP"), lost(c, CAM_LOST_CONFIG);
        return dev_fail(c, "VIDIOC_QUERYCAP");
    }
    uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    snprintf(c->card, sizeof c->card, "%s", (const char *)cap.card);
    snprintf(c->driver, sizeof c->driver, "%s", (const char *)cap.driver);
    if (!(caps & (V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_VIDEO_CAPTURE_MPLANE))) {
        cam_v4l2_say(c, "VIDIOC_QUERYCAP: %s is not a video capture device", dev);
        return lost(c, CAM_LOST_CONFIG);
    }
    c->mplane = !(caps & V4L2_CAP_VIDEO_CAPTURE); /* single-planar when it offers both */
    if (!(caps & V4L2_CAP_STREAMING)) {
        cam_v4l2_say(c, "VIDIOC_QUERYCAP: %s does not support streaming I/O", dev);
        return lost(c, CAM_LOST_CONFIG);
    }

    const cam_fmt_t *want = cam_fmt_of_opt(fmt);
    if (want && want->planes == 2 && !c->mplane) {
        cam_v4l2_say(c, "--format %s: %s is single-planar (two-plane formats need the multi-planar API)",
                     want->name, dev);
        return lost(c, CAM_LOST_CONFIG);
    }
    const uint32_t fourcc = want ? want->fourcc : cam_v4l2_choose_format(c, dev, w, h, fps);
    if (!fourcc)
        return lost(c, CAM_LOST_CONFIG);
    const cam_fmt_t *f = cam_fmt_of_fourcc(fourcc);
    struct v4l2_format fm;
    memset(&fm, 0, sizeof fm);
    fm.type = cam_v4l2_buf_type(c);
    if (c->mplane) {
        fm.fmt.pix_mp.width = (uint32_t)w;
        fm.fmt.pix_mp.height = (uint32_t)h;
        fm.fmt.pix_mp.pixelformat = fourcc;
        fm.fmt.pix_mp.field = V4L2_FIELD_NONE;
        fm.fmt.pix_mp.num_planes = (uint8_t)f->planes;
    } else {
        fm.fmt.pix.width = (uint32_t)w;
        fm.fmt.pix.height = (uint32_t)h;
        fm.fmt.pix.pixelformat = fourcc;
        fm.fmt.pix.field = V4L2_FIELD_NONE;
    }
    if (cam_v4l2_ioctl(c, VIDIOC_S_FMT, &fm))
        return errno == EINVAL ? (sys_fail(c, "VIDIOC_S_FMT"), lost(c, CAM_LOST_CONFIG))
                               : dev_fail(c, "VIDIOC_S_FMT");
    /* What the driver chose is what counts (the two layouts share these
     * fields' places only in part: read each from its own). */
    const uint32_t got = c->mplane ? fm.fmt.pix_mp.pixelformat : fm.fmt.pix.pixelformat;
    const uint32_t field = c->mplane ? fm.fmt.pix_mp.field : fm.fmt.pix.field;
    if (got != fourcc) {
        cam_v4l2_say(c, "VIDIOC_S_FMT: %s does not deliver %s", dev, f->name);
        return lost(c, CAM_LOST_CONFIG);
    }
    if (field != V4L2_FIELD_NONE && field != V4L2_FIELD_ANY) {
        cam_v4l2_say(c, "VIDIOC_S_FMT: interlaced field order %u is not supported", (unsigned)field);
        return lost(c, CAM_LOST_CONFIG);
    }
    c->width = (int)(c->mplane ? fm.fmt.pix_mp.width : fm.fmt.pix.width);
    c->height = (int)(c->mplane ? fm.fmt.pix_mp.height : fm.fmt.pix.height);
    c->pixelformat = got;
    if (is_ycc(f) && c->mplane)
        c->ycc_note = cam_colorimetry(fm.fmt.pix_mp.colorspace, fm.fmt.pix_mp.ycbcr_enc,
                                      fm.fmt.pix_mp.quantization, &c->bt709, &c->full);
    else if (is_ycc(f))
        c->ycc_note = cam_colorimetry(fm.fmt.pix.colorspace, fm.fmt.pix.ycbcr_enc, fm.fmt.pix.quantization,
                                      &c->bt709, &c->full);
    if (c->width < 2 || c->height < 1 || c->width > BLOOM_MAX_DIM || c->height > BLOOM_MAX_DIM ||
        (is_ycc(f) && f->chroma < 0 && (c->width & 1))) { /* packed 4:2:2: whole pairs */
        cam_v4l2_say(c, "VIDIOC_S_FMT: unusable format %dx%d %s", c->width, c->height, f->name);
        return lost(c, CAM_LOST_CONFIG);
    }
    if (cam_v4l2_layout(c, f, &fm))
        return lost(c, CAM_LOST_CONFIG);
    if (!f->bpp && cam_mjpeg_open(&c->jpeg, c->width, c->height)) {
        cam_v4l2_say(c, "MJPEG decoder: out of memory");
        return lost(c, CAM_LOST_DEVICE);
    }
    if (fps > 0)
        cam_v4l2_set_fps(c, fps);

    struct v4l2_requestbuffers rb;
    memset(&rb, 0, sizeof rb);
    rb.count = (uint32_t)nbufs;
    rb.type = cam_v4l2_buf_type(c);
    rb.memory = V4L2_MEMORY_MMAP;
    if (cam_v4l2_ioctl(c, VIDIOC_REQBUFS, &rb))
        return dev_fail(c, "VIDIOC_REQBUFS");
    if (rb.count < 2 || rb.count > CAM_MAX_BUFFERS) {
        cam_v4l2_say(c, "VIDIOC_REQBUFS: the driver gave %u buffers (2..%d needed)", (unsigned)rb.count,
                     CAM_MAX_BUFFERS);
        c->nbufs = (int)(rb.count > CAM_MAX_BUFFERS ? 0 : rb.count);
        return lost(c, CAM_LOST_CONFIG);
    }
    c->nbufs = (int)rb.count;
    for (int i = 0; i < c->nbufs; i++) {
        vbuf_t v;
        mmap_buffer(c, &v, i);
        if (cam_v4l2_ioctl(c, VIDIOC_QUERYBUF, &v.b))
            return dev_fail(c, "VIDIOC_QUERYBUF");
        for (int p = 0; p < nplanes(c); p++) {
            const uint32_t len = c->mplane ? v.p[p].length : v.b.length;
            const uint32_t off = c->mplane ? v.p[p].m.mem_offset : v.b.m.offset;
            if (len < c->plane_bytes[p]) {
                cam_v4l2_say(c, "VIDIOC_QUERYBUF: buffer %d plane %d holds %u bytes, a frame %u", i, p,
                             (unsigned)len, (unsigned)c->plane_bytes[p]);
                return lost(c, CAM_LOST_CONFIG);
            }
            void *m = mmap(NULL, len, PROT_READ | PROT_WRITE, MAP_SHARED, c->fd, off);
            if (m == MAP_FAILED)
                return dev_fail(c, "mmap");
            if (p == 0) {
                c->bufs[i].start = m;
                c->bufs[i].length = len;
            } else {
                c->bufs[i].start2 = m;
                c->bufs[i].length2 = len;
            }
        }
    }
    return 0;
}

void cam_v4l2_describe(const cam_v4l2_t *c, char *buf, size_t len)
{
    const cam_fmt_t *f = cam_fmt_of_fourcc(c->pixelformat);
    int k =
        snprintf(buf, len, "%s, bytesperline %u, sizeimage %u, %d buffers, %.4s%s%s", f ? f->raw : "?",
                 (unsigned)c->bytesperline, (unsigned)c->sizeimage, c->nbufs, (const char *)&c->pixelformat,
                 nplanes(c) == 2 ? " in 2 planes" : "", c->mplane ? " (multi-planar API)" : "");
    if (k > 0 && (size_t)k < len && f && is_ycc(f))
        k += snprintf(buf + k, len - (size_t)k, ", ycbcr %s-%s%s", c->bt709 ? "bt709" : "bt601",
                      c->full ? "full" : "limited", c->ycc_note);
    if (k > 0 && (size_t)k < len && c->fps)
        snprintf(buf + k, len - (size_t)k, ", %d fps", c->fps);
}

static int queue(cam_v4l2_t *c, int index)
{
    vbuf_t v;
    mmap_buffer(c, &v, index);
    if (cam_v4l2_ioctl(c, VIDIOC_QBUF, &v.b))
        return dev_fail(c, "VIDIOC_QBUF");
    return 0;
}

int cam_v4l2_start(cam_v4l2_t *c)
{
    for (int i = 0; i < c->nbufs; i++)
        if (queue(c, i))
            return -1;
    /* A source change (a resolution or signal change on HDMI or analogue
     * inputs, a sensor reconfigured) is an event; a driver without sources
     * that change refuses the subscription, and that is fine. */
    struct v4l2_event_subscription sub;
    memset(&sub, 0, sizeof sub);
    sub.type = V4L2_EVENT_SOURCE_CHANGE;
    c->events = !cam_v4l2_ioctl(c, VIDIOC_SUBSCRIBE_EVENT, &sub);
    enum v4l2_buf_type t = (enum v4l2_buf_type)cam_v4l2_buf_type(c);
    if (cam_v4l2_ioctl(c, VIDIOC_STREAMON, &t))
        return dev_fail(c, "VIDIOC_STREAMON");
    c->streaming = 1;
    return 0;
}

/* POLLPRI: an event is pending. 0 when it was not a source change, -1
 * (CAM_LOST_SOURCE) when it was. */
static int event(cam_v4l2_t *c)
{
    struct v4l2_event ev;
    memset(&ev, 0, sizeof ev);
    if (cam_v4l2_ioctl(c, VIDIOC_DQEVENT, &ev) || ev.type != V4L2_EVENT_SOURCE_CHANGE)
        return 0;
    cam_v4l2_say(c, "the source changed (changes 0x%x): negotiating the format again",
                 (unsigned)ev.u.src_change.changes);
    return lost(c, CAM_LOST_SOURCE);
}

/* The buffer just dequeued as a frame: 0, 2 when it is bad (requeued), -1
 * on a fault. Each plane's data starts at its data_offset (multi-planar)
 * and must hold the plane's bytes after it. */
static int take(cam_v4l2_t *c, const vbuf_t *v, cam_frame_t *f)
{
    const struct v4l2_buffer *b = &v->b;
    if (b->index >= (uint32_t)c->nbufs) {
        cam_v4l2_say(c, "VIDIOC_DQBUF: buffer index %u out of range", (unsigned)b->index);
        return lost(c, CAM_LOST_DEVICE);
    }
    const cam_vbuf_t *m = &c->bufs[b->index];
    f->index = (int)b->index;
    f->sequence = b->sequence;
    f->bytesused = 0;
    int shortf = 0;
    const uint8_t *start[2] = {m->start, m->start2}, *plane[2] = {NULL, NULL};
    const size_t mlen[2] = {m->length, m->length2};
    const uint32_t luma = c->bytesperline * (uint32_t)c->height;
    for (int p = 0; p < nplanes(c); p++) {
        const uint32_t used = c->mplane ? v->p[p].bytesused : b->bytesused;
        const uint32_t off = c->mplane ? v->p[p].data_offset : 0;
        const uint32_t need = c->plane_bytes[p] ? c->plane_bytes[p] : luma; /* (set by hand: packed) */
        f->bytesused += used;
        shortf |= off > used || used - off < need || (size_t)off + need > mlen[p];
        plane[p] = start[p] && off <= mlen[p] ? start[p] + off : start[p];
        if (p == 0) /* what the driver wrote after data_offset, inside the mapping */
            f->len = off > used || off > mlen[0] ? 0 : (used < mlen[0] ? used : (uint32_t)mlen[0]) - off;
    }
    f->data = plane[0];
    f->data2 = nplanes(c) == 2 ? plane[1] : c->plane_bytes[0] > luma ? plane[0] + luma : NULL;
    f->bad = (b->flags & V4L2_BUF_FLAG_ERROR) ? CAM_BAD_FLAGGED : shortf ? CAM_BAD_SHORT : CAM_BAD_NONE;
    if (!f->bad)
        return 0;
    return queue(c, f->index) ? -1 : 2;
}

int cam_v4l2_dequeue(cam_v4l2_t *c, int timeout_ms, int extra_fd, int *extra_ready, cam_frame_t *f)
{
    for (;;) {
        struct pollfd p[2] = {{c->fd, (short)(POLLIN | (c->events ? POLLPRI : 0)), 0}, {extra_fd, POLLIN, 0}};
        int r = c->poll_fn(p, extra_fd >= 0 ? 2 : 1, timeout_ms, c->wait_mask);
        if (r < 0) {
            if (errno == EINTR)
                return 1; /* the caller looks at its signal flag */
            return dev_fail(c, "poll");
        }
        if (r == 0) {
            cam_v4l2_say(c, "poll: no frame from the device within %d ms", timeout_ms);
            return lost(c, CAM_LOST_TIMEOUT);
        }
        if (extra_fd >= 0 && (p[1].revents & POLLIN))
            *extra_ready = 1;
        if ((p[0].revents & POLLPRI) && event(c))
            return -1;
        if (!(p[0].revents & ~POLLPRI))
            continue; /* only the button, or another event: wait again */
        /* POLLERR: DQBUF tells why (ENODEV after a disconnect, EPIPE, ...) */

        vbuf_t v;
        mmap_buffer(c, &v, 0);
        if (cam_v4l2_ioctl(c, VIDIOC_DQBUF, &v.b)) {
            if (errno == EAGAIN && !(p[0].revents & (POLLERR | POLLHUP | POLLNVAL)))
                continue; /* nothing after all: wait again */
            if (errno == EAGAIN) {
                cam_v4l2_say(c, "poll: the device reports an error (revents 0x%x)", (unsigned)p[0].revents);
                return lost(c, CAM_LOST_DEVICE);
            }
            return dev_fail(c, "VIDIOC_DQBUF");
        }
        return take(c, &v, f);
    }
}

int cam_v4l2_latest(cam_v4l2_t *c, cam_frame_t *f, long *skipped, long bad[3])
{
    for (;;) {
        vbuf_t v;
        mmap_buffer(c, &v, 0);
        if (cam_v4l2_ioctl(c, VIDIOC_DQBUF, &v.b)) { /* the descriptor is non-blocking */
            if (errno == EAGAIN)
                return 0; /* f is the newest */
            const int e = errno;
            queue(c, f->index);
            errno = e;
            return dev_fail(c, "VIDIOC_DQBUF");
        }
        cam_frame_t next;
        memset(&next, 0, sizeof next);
        const int r = take(c, &v, &next);
        if (r < 0) {
            queue(c, f->index);
            return -1;
        }
        if (r == 2) { /* bad, requeued: f stays the newest good one */
            bad[next.bad]++;
            continue;
        }
        if (queue(c, f->index)) /* the older frame goes back, unshown */
            return -1;
        (*skipped)++;
        *f = next;
    }
}

int cam_v4l2_requeue(cam_v4l2_t *c, const cam_frame_t *f)
{
    return queue(c, f->index);
}

void cam_v4l2_close(cam_v4l2_t *c)
{
    if (c->fd <= 0 && !c->nbufs)
        return;
    if (c->streaming) {
        enum v4l2_buf_type t = (enum v4l2_buf_type)cam_v4l2_buf_type(c);
        if (cam_v4l2_ioctl(c, VIDIOC_STREAMOFF, &t) && errno != ENODEV)
            sys_fail(c, "VIDIOC_STREAMOFF");
        c->streaming = 0;
    }
    for (int i = 0; i < c->nbufs; i++) {
        if (c->bufs[i].start)
            munmap(c->bufs[i].start, c->bufs[i].length);
        if (c->bufs[i].start2)
            munmap(c->bufs[i].start2, c->bufs[i].length2);
        c->bufs[i].start = c->bufs[i].start2 = NULL;
    }
    if (c->nbufs && c->fd > 0) {
        struct v4l2_requestbuffers rb;
        memset(&rb, 0, sizeof rb);
        rb.type = cam_v4l2_buf_type(c);
        rb.memory = V4L2_MEMORY_MMAP;
        cam_v4l2_ioctl(c, VIDIOC_REQBUFS, &rb); /* may fail after a disconnect */
    }
    c->nbufs = 0;
    cam_mjpeg_close(c->jpeg);
    c->jpeg = NULL;
    if (c->fd > 0)
        close(c->fd);
    c->fd = -1;
}
