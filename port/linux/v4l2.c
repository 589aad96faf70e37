/* bloom_cam: V4L2 capture with mmap streaming. Every failure prints
 * "bloom_cam: CALL: reason" once; cam_v4l2_close undoes whatever was done
 * (STREAMOFF, munmap, REQBUFS 0, close) and is safe to call at any point. */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
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

static int sys_fail(const char *call)
{
    fprintf(stderr, "%s: %s: %s\n", CAM_PROG, call, strerror(errno));
    return -1;
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
    memset(c, 0, sizeof *c);
    c->ioctl_fn = sys_ioctl;
    c->poll_fn = poll;
    c->fd = open(dev, O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (c->fd < 0) {
        fprintf(stderr, "%s: open %s: %s\n", CAM_PROG, dev, strerror(errno));
        return -1;
    }

    struct v4l2_capability cap;
    memset(&cap, 0, sizeof cap);
    if (xioctl(c, VIDIOC_QUERYCAP, &cap))
        return sys_fail("VIDIOC_QUERYCAP");
    uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    snprintf(c->card, sizeof c->card, "%s", (const char *)cap.card);
    snprintf(c->driver, sizeof c->driver, "%s", (const char *)cap.driver);
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE)) {
        fprintf(stderr, "%s: VIDIOC_QUERYCAP: %s is not a single-planar video capture device\n", CAM_PROG,
                dev);
        return -1;
    }
    if (!(caps & V4L2_CAP_STREAMING)) {
        fprintf(stderr, "%s: VIDIOC_QUERYCAP: %s does not support streaming I/O\n", CAM_PROG, dev);
        return -1;
    }

    struct v4l2_format f;
    memset(&f, 0, sizeof f);
    f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    f.fmt.pix.width = (uint32_t)w;
    f.fmt.pix.height = (uint32_t)h;
    f.fmt.pix.pixelformat = fourcc_of(fmt);
    f.fmt.pix.field = V4L2_FIELD_NONE;
    if (xioctl(c, VIDIOC_S_FMT, &f))
        return sys_fail("VIDIOC_S_FMT");
    /* What the driver chose is what counts. */
    if (f.fmt.pix.pixelformat != fourcc_of(fmt)) {
        fprintf(stderr, "%s: VIDIOC_S_FMT: %s does not deliver %s\n", CAM_PROG, dev, cam_format_name(fmt));
        return -1;
    }
    if (f.fmt.pix.field != V4L2_FIELD_NONE && f.fmt.pix.field != V4L2_FIELD_ANY) {
        fprintf(stderr, "%s: VIDIOC_S_FMT: interlaced field order %u is not supported\n", CAM_PROG,
                (unsigned)f.fmt.pix.field);
        return -1;
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
        fprintf(stderr, "%s: VIDIOC_S_FMT: unusable format %dx%d, bytesperline %u, sizeimage %u\n", CAM_PROG,
                c->width, c->height, (unsigned)c->bytesperline, (unsigned)c->sizeimage);
        return -1;
    }

    struct v4l2_requestbuffers rb;
    memset(&rb, 0, sizeof rb);
    rb.count = (uint32_t)nbufs;
    rb.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    rb.memory = V4L2_MEMORY_MMAP;
    if (xioctl(c, VIDIOC_REQBUFS, &rb))
        return sys_fail("VIDIOC_REQBUFS");
    if (rb.count < 2 || rb.count > CAM_MAX_BUFFERS) {
        fprintf(stderr, "%s: VIDIOC_REQBUFS: the driver gave %u buffers (2..%d needed)\n", CAM_PROG,
                (unsigned)rb.count, CAM_MAX_BUFFERS);
        c->nbufs = (int)(rb.count > CAM_MAX_BUFFERS ? 0 : rb.count);
        return -1;
    }
    c->nbufs = (int)rb.count;
    for (int i = 0; i < c->nbufs; i++) {
        struct v4l2_buffer b = mmap_buffer(i);
        if (xioctl(c, VIDIOC_QUERYBUF, &b))
            return sys_fail("VIDIOC_QUERYBUF");
        if (b.length < c->sizeimage) {
            fprintf(stderr, "%s: VIDIOC_QUERYBUF: buffer %d holds %u bytes, a frame %u\n", CAM_PROG, i,
                    (unsigned)b.length, (unsigned)c->sizeimage);
            return -1;
        }
        void *p = mmap(NULL, b.length, PROT_READ | PROT_WRITE, MAP_SHARED, c->fd, b.m.offset);
        if (p == MAP_FAILED)
            return sys_fail("mmap");
        c->bufs[i].start = p;
        c->bufs[i].length = b.length;
    }
    return 0;
}

static int queue(cam_v4l2_t *c, int index)
{
    struct v4l2_buffer b = mmap_buffer(index);
    if (xioctl(c, VIDIOC_QBUF, &b))
        return sys_fail("VIDIOC_QBUF");
    return 0;
}

int cam_v4l2_start(cam_v4l2_t *c)
{
    for (int i = 0; i < c->nbufs; i++)
        if (queue(c, i))
            return -1;
    enum v4l2_buf_type t = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (xioctl(c, VIDIOC_STREAMON, &t))
        return sys_fail("VIDIOC_STREAMON");
    c->streaming = 1;
    return 0;
}

int cam_v4l2_dequeue(cam_v4l2_t *c, int timeout_ms, int extra_fd, int *extra_ready, cam_frame_t *f)
{
    for (;;) {
        struct pollfd p[2] = {{c->fd, POLLIN, 0}, {extra_fd, POLLIN, 0}};
        int r = c->poll_fn(p, extra_fd >= 0 ? 2 : 1, timeout_ms);
        if (r < 0) {
            if (errno == EINTR)
                return 1; /* the caller looks at its signal flag */
            return sys_fail("poll");
        }
        if (r == 0) {
            fprintf(stderr, "%s: poll: no frame from the device within %d ms\n", CAM_PROG, timeout_ms);
            return -1;
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
                fprintf(stderr, "%s: poll: the device reports an error (revents 0x%x)\n", CAM_PROG,
                        (unsigned)p[0].revents);
                return -1;
            }
            return sys_fail("VIDIOC_DQBUF");
        }
        if (b.index >= (uint32_t)c->nbufs) {
            fprintf(stderr, "%s: VIDIOC_DQBUF: buffer index %u out of range\n", CAM_PROG, (unsigned)b.index);
            return -1;
        }
        f->index = (int)b.index;
        f->sequence = b.sequence;
        f->bytesused = b.bytesused;
        f->data = c->bufs[b.index].start;
        if (b.flags & V4L2_BUF_FLAG_ERROR) {
            fprintf(stderr, "%s: VIDIOC_DQBUF: buffer %u (sequence %u) flagged V4L2_BUF_FLAG_ERROR\n",
                    CAM_PROG, (unsigned)b.index, (unsigned)b.sequence);
            return -1;
        }
        if (b.bytesused < c->bytesperline * (uint32_t)c->height) {
            fprintf(stderr, "%s: VIDIOC_DQBUF: short frame: %u bytes, %u expected (sequence %u)\n", CAM_PROG,
                    (unsigned)b.bytesused, (unsigned)(c->bytesperline * (uint32_t)c->height),
                    (unsigned)b.sequence);
            return -1;
        }
        return 0;
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
            sys_fail("VIDIOC_STREAMOFF");
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
