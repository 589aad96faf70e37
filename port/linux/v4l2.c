/* bloom_cam: V4L2 capture with mmap streaming. Every failure prints
 * "bloom_cam: CALL: reason" once; cam_v4l2_close undoes whatever was done
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

/* The device's ioctl through the seam in c, retried on EINTR. */
static int xioctl(cam_v4l2_t *c, unsigned long req, void *arg)
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

/* A message "bloom_cam: ...": kept in c->msg (the last one), printed unless
 * c->quiet (the attempts of a reconnection). */
__attribute__((format(printf, 2, 3))) static void say(cam_v4l2_t *c, const char *fmt, ...)
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
    say(c, "%s: %s", call, strerror(errno));
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

/* An mmap capture buffer descriptor, index set, everything else zero. */
static struct v4l2_buffer mmap_buffer(int index)
{
    struct v4l2_buffer b;
    memset(&b, 0, sizeof b);
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = (uint32_t)index;
    return b;
}

static uint32_t fourcc_of(enum cam_pixfmt f)
{
    switch (f) {
    case CAM_FMT_YUYV:
        return V4L2_PIX_FMT_YUYV;
    case CAM_FMT_RGB24:
        return V4L2_PIX_FMT_RGB24;
    case CAM_FMT_GREY:
        return V4L2_PIX_FMT_GREY;
    }
    return 0;
}

static int bytes_per_pixel(uint32_t fourcc)
{
    return fourcc == V4L2_PIX_FMT_YUYV ? 2 : fourcc == V4L2_PIX_FMT_RGB24 ? 3 : 1;
}

int cam_v4l2_open(cam_v4l2_t *c, const char *dev, int w, int h, enum cam_pixfmt fmt, int nbufs)
{
    const sigset_t *mask = c->wait_mask; /* (the caller's, kept) */
    const int quiet = c->quiet;
    memset(c, 0, sizeof *c);
    c->wait_mask = mask;
    c->quiet = quiet;
    c->ioctl_fn = sys_ioctl;
    c->poll_fn = sys_ppoll;
    c->fd = open(dev, O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (c->fd < 0) {
        say(c, "open %s: %s", dev, strerror(errno));
        return lost(c, CAM_LOST_DEVICE);
    }

    struct v4l2_capability cap;
    memset(&cap, 0, sizeof cap);
    if (xioctl(c, VIDIOC_QUERYCAP, &cap)) { /* ENOTTY: not a V4L2 device at all (the wrong path) */
        if (errno == ENOTTY || errno == EINVAL)
            return sys_fail(c, "VIDIOC_QUERYCAP"), lost(c, CAM_LOST_CONFIG);
        return dev_fail(c, "VIDIOC_QUERYCAP");
    }
    uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    snprintf(c->card, sizeof c->card, "%s", (const char *)cap.card);
    snprintf(c->driver, sizeof c->driver, "%s", (const char *)cap.driver);
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE)) {
        say(c, "VIDIOC_QUERYCAP: %s is not a single-planar video capture device", dev);
        return lost(c, CAM_LOST_CONFIG);
    }
    if (!(caps & V4L2_CAP_STREAMING)) {
        say(c, "VIDIOC_QUERYCAP: %s does not support streaming I/O", dev);
        return lost(c, CAM_LOST_CONFIG);
    }

    struct v4l2_format f;
    memset(&f, 0, sizeof f);
    f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    f.fmt.pix.width = (uint32_t)w;
    f.fmt.pix.height = (uint32_t)h;
    f.fmt.pix.pixelformat = fourcc_of(fmt);
    f.fmt.pix.field = V4L2_FIELD_NONE;
    if (xioctl(c, VIDIOC_S_FMT, &f))
        return errno == EINVAL ? (sys_fail(c, "VIDIOC_S_FMT"), lost(c, CAM_LOST_CONFIG))
                               : dev_fail(c, "VIDIOC_S_FMT");
    /* What the driver chose is what counts. */
    if (f.fmt.pix.pixelformat != fourcc_of(fmt)) {
        say(c, "VIDIOC_S_FMT: %s does not deliver %s", dev, cam_format_name(fmt));
        return lost(c, CAM_LOST_CONFIG);
    }
    if (f.fmt.pix.field != V4L2_FIELD_NONE && f.fmt.pix.field != V4L2_FIELD_ANY) {
        say(c, "VIDIOC_S_FMT: interlaced field order %u is not supported", (unsigned)f.fmt.pix.field);
        return lost(c, CAM_LOST_CONFIG);
    }
    c->width = (int)f.fmt.pix.width;
    c->height = (int)f.fmt.pix.height;
    c->pixelformat = f.fmt.pix.pixelformat;
    c->bytesperline = f.fmt.pix.bytesperline;
    c->sizeimage = f.fmt.pix.sizeimage;
    const uint32_t minline = (uint32_t)c->width * (uint32_t)bytes_per_pixel(c->pixelformat);
    if (c->bytesperline < minline)
        c->bytesperline = minline; /* some drivers leave it 0 */
    if (c->width < 2 || c->height < 1 || c->width > BLOOM_MAX_DIM || c->height > BLOOM_MAX_DIM ||
        (c->pixelformat == V4L2_PIX_FMT_YUYV && (c->width & 1)) ||
        c->sizeimage < c->bytesperline * (uint32_t)c->height) {
        say(c, "VIDIOC_S_FMT: unusable format %dx%d, bytesperline %u, sizeimage %u", c->width, c->height,
            (unsigned)c->bytesperline, (unsigned)c->sizeimage);
        return lost(c, CAM_LOST_CONFIG);
    }

    struct v4l2_requestbuffers rb;
    memset(&rb, 0, sizeof rb);
    rb.count = (uint32_t)nbufs;
    rb.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    rb.memory = V4L2_MEMORY_MMAP;
    if (xioctl(c, VIDIOC_REQBUFS, &rb))
        return dev_fail(c, "VIDIOC_REQBUFS");
    if (rb.count < 2 || rb.count > CAM_MAX_BUFFERS) {
        say(c, "VIDIOC_REQBUFS: the driver gave %u buffers (2..%d needed)", (unsigned)rb.count,
            CAM_MAX_BUFFERS);
        c->nbufs = (int)(rb.count > CAM_MAX_BUFFERS ? 0 : rb.count);
        return lost(c, CAM_LOST_CONFIG);
    }
    c->nbufs = (int)rb.count;
    for (int i = 0; i < c->nbufs; i++) {
        struct v4l2_buffer b = mmap_buffer(i);
        if (xioctl(c, VIDIOC_QUERYBUF, &b))
            return dev_fail(c, "VIDIOC_QUERYBUF");
        if (b.length < c->sizeimage) {
            say(c, "VIDIOC_QUERYBUF: buffer %d holds %u bytes, a frame %u", i, (unsigned)b.length,
                (unsigned)c->sizeimage);
            return lost(c, CAM_LOST_CONFIG);
        }
        void *p = mmap(NULL, b.length, PROT_READ | PROT_WRITE, MAP_SHARED, c->fd, b.m.offset);
        if (p == MAP_FAILED)
            return dev_fail(c, "mmap");
        c->bufs[i].start = p;
        c->bufs[i].length = b.length;
    }
    return 0;
}

static int queue(cam_v4l2_t *c, int index)
{
    struct v4l2_buffer b = mmap_buffer(index);
    if (xioctl(c, VIDIOC_QBUF, &b))
        return dev_fail(c, "VIDIOC_QBUF");
    return 0;
}

int cam_v4l2_start(cam_v4l2_t *c)
{
    for (int i = 0; i < c->nbufs; i++)
        if (queue(c, i))
            return -1;
    enum v4l2_buf_type t = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (xioctl(c, VIDIOC_STREAMON, &t))
        return dev_fail(c, "VIDIOC_STREAMON");
    c->streaming = 1;
    return 0;
}

/* The buffer just dequeued as a frame: 0, 2 when it is bad (requeued), -1
 * on a fault. */
static int take(cam_v4l2_t *c, const struct v4l2_buffer *b, cam_frame_t *f)
{
    if (b->index >= (uint32_t)c->nbufs) {
        say(c, "VIDIOC_DQBUF: buffer index %u out of range", (unsigned)b->index);
        return lost(c, CAM_LOST_DEVICE);
    }
    f->index = (int)b->index;
    f->sequence = b->sequence;
    f->bytesused = b->bytesused;
    f->data = c->bufs[b->index].start;
    f->bad = (b->flags & V4L2_BUF_FLAG_ERROR)                       ? CAM_BAD_FLAGGED
             : b->bytesused < c->bytesperline * (uint32_t)c->height ? CAM_BAD_SHORT
                                                                    : CAM_BAD_NONE;
    if (!f->bad)
        return 0;
    return queue(c, f->index) ? -1 : 2;
}

int cam_v4l2_dequeue(cam_v4l2_t *c, int timeout_ms, int extra_fd, int *extra_ready, cam_frame_t *f)
{
    for (;;) {
        struct pollfd p[2] = {{c->fd, POLLIN, 0}, {extra_fd, POLLIN, 0}};
        int r = c->poll_fn(p, extra_fd >= 0 ? 2 : 1, timeout_ms, c->wait_mask);
        if (r < 0) {
            if (errno == EINTR)
                return 1; /* the caller looks at its signal flag */
            return dev_fail(c, "poll");
        }
        if (r == 0) {
            say(c, "poll: no frame from the device within %d ms", timeout_ms);
            return lost(c, CAM_LOST_TIMEOUT);
        }
        if (extra_fd >= 0 && (p[1].revents & POLLIN))
            *extra_ready = 1;
        if (!p[0].revents)
            continue; /* only the button: wait again */
        /* POLLERR: DQBUF tells why (ENODEV after a disconnect, EPIPE, ...) */

        struct v4l2_buffer b = mmap_buffer(0);
        if (xioctl(c, VIDIOC_DQBUF, &b)) {
            if (errno == EAGAIN && !(p[0].revents & (POLLERR | POLLHUP | POLLNVAL)))
                continue; /* nothing after all: wait again */
            if (errno == EAGAIN) {
                say(c, "poll: the device reports an error (revents 0x%x)", (unsigned)p[0].revents);
                return lost(c, CAM_LOST_DEVICE);
            }
            return dev_fail(c, "VIDIOC_DQBUF");
        }
        return take(c, &b, f);
    }
}

int cam_v4l2_latest(cam_v4l2_t *c, cam_frame_t *f, long *skipped, long bad[3])
{
    for (;;) {
        struct v4l2_buffer b = mmap_buffer(0);
        if (xioctl(c, VIDIOC_DQBUF, &b)) { /* the descriptor is non-blocking */
            if (errno == EAGAIN)
                return 0; /* f is the newest */
            const int e = errno;
            queue(c, f->index);
            errno = e;
            return dev_fail(c, "VIDIOC_DQBUF");
        }
        cam_frame_t next;
        memset(&next, 0, sizeof next);
        const int r = take(c, &b, &next);
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
        enum v4l2_buf_type t = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (xioctl(c, VIDIOC_STREAMOFF, &t) && errno != ENODEV)
            sys_fail(c, "VIDIOC_STREAMOFF");
        c->streaming = 0;
    }
    for (int i = 0; i < c->nbufs; i++)
        if (c->bufs[i].start) {
            munmap(c->bufs[i].start, c->bufs[i].length);
            c->bufs[i].start = NULL;
        }
    if (c->nbufs && c->fd > 0) {
        struct v4l2_requestbuffers rb;
        memset(&rb, 0, sizeof rb);
        rb.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        rb.memory = V4L2_MEMORY_MMAP;
        xioctl(c, VIDIOC_REQBUFS, &rb); /* may fail after a disconnect */
    }
    c->nbufs = 0;
    if (c->fd > 0)
        close(c->fd);
    c->fd = -1;
}
