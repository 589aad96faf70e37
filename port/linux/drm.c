/* bloom_cam: DRM/KMS output, and the choice between it and the fbdev
 * (cam_display_open). One connector, its CRTC and primary plane; two dumb
 * buffers, the engine writing the screen's format (XRGB8888 or RGB565)
 * straight into the one not on show, then drmModePageFlip to it on the
 * vertical blank; the next frame is drawn into the other buffer only once
 * the flip's event has come, so no frame is ever shown half-drawn. The
 * CRTC as found (drmModeGetCrtc) is set again by cam_drm_close, which the
 * one teardown of main.c runs on every exit path (stop signals included:
 * they only set a flag). cam_display_open (at the end) chooses this or
 * the fbdev, by drm_pick.c's rule.
 *
 * libdrm rather than the bare ioctls: Debian's libdrm-dev ships libdrm.a
 * (bookworm: /usr/lib/x86_64-linux-gnu/libdrm.a, needing only -lm), so the
 * static build for the test initramfs links it too. Built without libdrm
 * (CAM_NO_DRM), --display drm is refused and auto means the fbdev. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "cam.h"

#ifdef CAM_NO_DRM

int cam_drm_open(cam_fb_t *fb, const char *card, int mode_w, int mode_h, bloom_format_t fmt, int quiet)
{
    (void)fb, (void)card, (void)mode_w, (void)mode_h, (void)fmt, (void)quiet;
    fprintf(stderr, "%s: --display drm: built without libdrm (install libdrm-dev and rebuild)\n", CAM_PROG);
    return -1;
}
uint8_t *cam_drm_draw_page(cam_fb_t *fb)
{
    (void)fb;
    return NULL;
}
int cam_drm_show(cam_fb_t *fb)
{
    (void)fb;
    return -1;
}
void cam_drm_close(cam_fb_t *fb)
{
    (void)fb;
}
long cam_drm_flips(const cam_fb_t *fb)
{
    (void)fb;
    return 0;
}
const char *cam_drm_find(char *path, size_t len)
{
    (void)path, (void)len;
    return NULL;
}
#else
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

#include <xf86drm.h>
#include <xf86drmMode.h>

typedef struct {
    uint32_t handle, fb_id, pitch;
    uint64_t size;
    uint8_t *map;
} drm_buf_t;

struct cam_drm {
    int fd;
    uint32_t conn_id, crtc_id, fourcc;
    drmModeModeInfo mode;
    drmModeCrtc *saved; /* the CRTC as found: set again on close */
    int set;            /* our buffer is on the CRTC (restore on close) */
    drm_buf_t buf[2];
    int front;   /* the buffer on show */
    int pending; /* a flip asked for, its event not yet read */
    long flips;
};

static int drm_fail(const char *call)
{
    fprintf(stderr, "%s: %s: %s\n", CAM_PROG, call, strerror(errno));
    return -1;
}

/* The first connected connector with modes: its id, or 0. */
static uint32_t connected(int fd, drmModeRes *res)
{
    for (int i = 0; i < res->count_connectors; i++) {
        drmModeConnector *c = drmModeGetConnector(fd, res->connectors[i]);
        if (!c)
            continue;
        const uint32_t id = c->connection == DRM_MODE_CONNECTED && c->count_modes > 0 ? c->connector_id : 0;
        drmModeFreeConnector(c);
        if (id)
            return id;
    }
    return 0;
}

/* auto: the first /dev/dri/cardN with a connected connector (path), or NULL. */
const char *cam_drm_find(char *path, size_t len)
{
    for (int n = 0; n < 16; n++) {
        snprintf(path, len, "/dev/dri/card%d", n);
        int fd = open(path, O_RDWR | O_CLOEXEC);
        if (fd < 0)
            continue;
        drmModeRes *res = drmModeGetResources(fd); /* NULL: no KMS (a render-only GPU) */
        const uint32_t id = res ? connected(fd, res) : 0;
        drmModeFreeResources(res);
        close(fd);
        if (id)
            return path;
    }
    return NULL;
}

/* The CRTC for the connector: its encoder's current one, else the first
 * free one an encoder of it can drive. 0 when none. */
static uint32_t pick_crtc(int fd, drmModeRes *res, drmModeConnector *c, int *index)
{
    for (int pass = 0; pass < 2; pass++)
        for (int e = 0; e < c->count_encoders; e++) {
            drmModeEncoder *enc = drmModeGetEncoder(fd, c->encoders[e]);
            if (!enc)
                continue;
            for (int k = 0; k < res->count_crtcs; k++) {
                const int ok = pass == 0 ? enc->encoder_id == c->encoder_id && enc->crtc_id == res->crtcs[k]
                                         : (enc->possible_crtcs >> k) & 1u;
                if (ok) {
                    *index = k;
                    const uint32_t id = res->crtcs[k];
                    drmModeFreeEncoder(enc);
                    return id;
                }
            }
            drmModeFreeEncoder(enc);
        }
    return 0;
}

/* The formats the CRTC's primary plane scans out (up to max): the count. */
static int plane_formats(int fd, int crtc_index, uint32_t *out, int max)
{
    int n = 0;
    drmSetClientCap(fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1); /* the primary planes listed too */
    drmModePlaneRes *pr = drmModeGetPlaneResources(fd);
    for (uint32_t i = 0; pr && i < pr->count_planes && !n; i++) {
        drmModePlane *p = drmModeGetPlane(fd, pr->planes[i]);
        if (!p)
            continue;
        int primary = 0;
        drmModeObjectProperties *props = drmModeObjectGetProperties(fd, p->plane_id, DRM_MODE_OBJECT_PLANE);
        for (uint32_t j = 0; props && j < props->count_props; j++) {
            drmModePropertyRes *pp = drmModeGetProperty(fd, props->props[j]);
            if (pp && !strcmp(pp->name, "type") && props->prop_values[j] == DRM_PLANE_TYPE_PRIMARY)
                primary = 1;
            drmModeFreeProperty(pp);
        }
        drmModeFreeObjectProperties(props);
        if (primary && ((p->possible_crtcs >> crtc_index) & 1u))
            for (uint32_t j = 0; j < p->count_formats && n < max; j++)
                out[n++] = p->formats[j];
        drmModeFreePlane(p);
    }
    drmModeFreePlaneResources(pr);
    return n;
}

static void free_buf(int fd, drm_buf_t *b)
{
    if (b->map)
        munmap(b->map, b->size);
    if (b->fb_id)
        drmModeRmFB(fd, b->fb_id);
    if (b->handle) {
        struct drm_mode_destroy_dumb d = {.handle = b->handle};
        drmIoctl(fd, DRM_IOCTL_MODE_DESTROY_DUMB, &d);
    }
    memset(b, 0, sizeof *b);
}

static int make_buf(int fd, int w, int h, uint32_t fourcc, drm_buf_t *b)
{
    struct drm_mode_create_dumb cr = {.width = (uint32_t)w, .height = (uint32_t)h};
    cr.bpp = fourcc == CAM_DRM_RGB565 ? 16 : 32;
    if (drmIoctl(fd, DRM_IOCTL_MODE_CREATE_DUMB, &cr))
        return drm_fail("DRM_IOCTL_MODE_CREATE_DUMB");
    b->handle = cr.handle;
    b->pitch = cr.pitch;
    b->size = cr.size;
    const uint32_t handles[4] = {cr.handle}, pitches[4] = {cr.pitch}, offsets[4] = {0};
    if (drmModeAddFB2(fd, (uint32_t)w, (uint32_t)h, fourcc, handles, pitches, offsets, &b->fb_id, 0))
        return drm_fail("drmModeAddFB2");
    struct drm_mode_map_dumb m = {.handle = cr.handle};
    if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &m))
        return drm_fail("DRM_IOCTL_MODE_MAP_DUMB");
    void *p = mmap(NULL, cr.size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, (off_t)m.offset);
    if (p == MAP_FAILED)
        return drm_fail("mmap dumb buffer");
    b->map = p;
    memset(b->map, 0, cr.size); /* black: the frame may not cover the screen */
    return 0;
}

static void on_flip(int fd, unsigned seq, unsigned sec, unsigned usec, void *data)
{
    (void)fd, (void)seq, (void)sec, (void)usec;
    ((struct cam_drm *)data)->pending = 0;
}

/* Wait for the pending flip's event, ms at most. The stop signals stay
 * blocked here (they are let in only in the capture's wait): a flip takes
 * one frame period, and the run ends at the loop's next look at its flag. */
static int wait_flip(struct cam_drm *d, int ms)
{
    drmEventContext ev = {.version = 2, .page_flip_handler = on_flip};
    while (d->pending) {
        struct pollfd p = {.fd = d->fd, .events = POLLIN};
        int r = poll(&p, 1, ms);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0) {
            if (r == 0)
                fprintf(stderr, "%s: drmModePageFlip: no flip event within %d ms\n", CAM_PROG, ms);
            else
                drm_fail("poll (DRM event)");
            return -1;
        }
        if (drmHandleEvent(d->fd, &ev))
            return drm_fail("drmHandleEvent");
    }
    return 0;
}

int cam_drm_open(cam_fb_t *fb, const char *card, int mode_w, int mode_h, bloom_format_t fmt, int quiet)
{
    memset(fb, 0, sizeof *fb);
    fb->fd = -1;
    char found[32];
    if (!card && !(card = cam_drm_find(found, sizeof found))) {
        fprintf(stderr, "%s: --display drm: no /dev/dri/card* with a connected connector\n", CAM_PROG);
        return -1;
    }
    snprintf(fb->path, sizeof fb->path, "%s", card);
    struct cam_drm *d = calloc(1, sizeof *d);
    if (!d) {
        fprintf(stderr, "%s: out of memory\n", CAM_PROG);
        return -1;
    }
    fb->drm = d;
    d->fd = open(card, O_RDWR | O_CLOEXEC);
    if (d->fd < 0) {
        fprintf(stderr, "%s: open %s: %s\n", CAM_PROG, card, strerror(errno));
        return -1;
    }
    drmVersion *v = drmGetVersion(d->fd);
    snprintf(fb->id, sizeof fb->id, "%s", v && v->name ? v->name : "drm");
    drmFreeVersion(v);
    drmModeRes *res = drmModeGetResources(d->fd);
    if (!res) {
        fprintf(stderr, "%s: drmModeGetResources: %s (%s) has no modesetting: %s\n", CAM_PROG, card, fb->id,
                strerror(errno));
        return -1;
    }
    int st = -1, crtc_index = 0;
    drmModeConnector *c = NULL;
    d->conn_id = connected(d->fd, res);
    if (!d->conn_id || !(c = drmModeGetConnector(d->fd, d->conn_id))) {
        fprintf(stderr, "%s: %s (%s): no connected connector\n", CAM_PROG, card, fb->id);
        goto done;
    }
    cam_drm_mode_t modes[64];
    int nm = c->count_modes < 64 ? c->count_modes : 64;
    for (int i = 0; i < nm; i++)
        modes[i] = (cam_drm_mode_t){c->modes[i].hdisplay, c->modes[i].vdisplay, (int)c->modes[i].vrefresh,
                                    (c->modes[i].type & DRM_MODE_TYPE_PREFERRED) != 0};
    const int mi = cam_drm_pick_mode(modes, nm, mode_w, mode_h);
    if (mi < 0) {
        fprintf(stderr, "%s: --drm-mode %dx%d: connector %u of %s offers no such mode (%s", CAM_PROG, mode_w,
                mode_h, (unsigned)d->conn_id, card, nm ? "" : "none");
        for (int i = 0; i < nm && i < 12; i++)
            fprintf(stderr, "%s%dx%d", i ? ", " : "", modes[i].w, modes[i].h);
        fprintf(stderr, "%s)\n", nm > 12 ? ", ..." : "");
        goto done;
    }
    d->mode = c->modes[mi];
    d->crtc_id = pick_crtc(d->fd, res, c, &crtc_index);
    if (!d->crtc_id) {
        fprintf(stderr, "%s: %s (%s): no CRTC can drive connector %u\n", CAM_PROG, card, fb->id,
                (unsigned)d->conn_id);
        goto done;
    }
    uint32_t fmts[128];
    const int nf = plane_formats(d->fd, crtc_index, fmts, 128);
    bloom_format_t try[2];
    int nt = cam_drm_pick_formats(fmts, nf, fmt, try);
    if (nf == 0) /* no primary plane listed (an old kernel): try the formats */
        nt = cam_drm_pick_formats((const uint32_t[]){CAM_DRM_XRGB8888, CAM_DRM_RGB565}, 2, fmt, try);
    if (nt == 0) {
        fprintf(stderr, "%s: %s (%s): the primary plane scans out %s; bloom_cam writes XRGB8888 or RGB565\n",
                CAM_PROG, card, fb->id,
                fmt ? "neither of the formats asked for" : "neither XRGB8888 nor RGB565");
        goto done;
    }
    d->saved = drmModeGetCrtc(d->fd, d->crtc_id);
    if (!d->saved) {
        drm_fail("drmModeGetCrtc");
        goto done;
    }
    drmSetMaster(d->fd); /* the first opener is master already; fails when another program is */
    for (int k = 0; k < nt && st; k++) {
        const int w = d->mode.hdisplay, h = d->mode.vdisplay;
        d->fourcc = try[k] == BLOOM_FMT_RGB565 ? CAM_DRM_RGB565 : CAM_DRM_XRGB8888;
        if (make_buf(d->fd, w, h, d->fourcc, &d->buf[0]) || make_buf(d->fd, w, h, d->fourcc, &d->buf[1]))
            break;
        if (!drmModeSetCrtc(d->fd, d->crtc_id, d->buf[0].fb_id, 0, 0, &d->conn_id, 1, &d->mode)) {
            st = 0;
            fb->format = try[k];
            break;
        }
        const int e = errno;
        free_buf(d->fd, &d->buf[0]);
        free_buf(d->fd, &d->buf[1]);
        if (k + 1 < nt && e == EINVAL && !quiet) /* this mode cannot scan that format out (a pitch limit) */
            fprintf(stderr, "%s: drmModeSetCrtc: %s refused by %s at %dx%d: trying RGB565\n", CAM_PROG,
                    try[k] == BLOOM_FMT_RGB565 ? "RGB565" : "XRGB8888", fb->id, w, h);
        else if (k + 1 == nt || e != EINVAL) {
            errno = e;
            fprintf(stderr, "%s: drmModeSetCrtc: %s%s\n", CAM_PROG, strerror(e),
                    e == EACCES || e == EPERM ? " (another program, a compositor, is the DRM master)" : "");
            break;
        }
    }
    if (st)
        goto done;
    d->set = 1;
    fb->xres = d->mode.hdisplay;
    fb->yres = d->mode.vdisplay;
    fb->line_length = (int)d->buf[0].pitch;
    fb->bpp = d->fourcc == CAM_DRM_RGB565 ? 2 : 4;
    fb->pages = 2;
    fb->vsync = 1;
    d->front = 0;
    if (!quiet)
        fprintf(stderr,
                "%s: %s (%s): connector %u, CRTC %u, mode %s %dx%d@%d%s; CRTC as found: fb %u, %s%s\n",
                CAM_PROG, card, fb->id, (unsigned)d->conn_id, (unsigned)d->crtc_id, d->mode.name,
                d->mode.hdisplay, d->mode.vdisplay, (int)d->mode.vrefresh, mode_w ? "" : " (preferred)",
                (unsigned)d->saved->buffer_id, d->saved->mode_valid ? d->saved->mode.name : "no mode",
                d->saved->mode_valid ? "" : " (off)");
done:
    drmModeFreeConnector(c);
    drmModeFreeResources(res);
    return st;
}

uint8_t *cam_drm_draw_page(cam_fb_t *fb)
{
    struct cam_drm *d = fb->drm;
    if (d->pending && wait_flip(d, 1000)) /* the buffer to draw is on show until then */
        return NULL;
    return d->buf[d->front ^ 1].map;
}

int cam_drm_show(cam_fb_t *fb)
{
    struct cam_drm *d = fb->drm;
    const int back = d->front ^ 1;
    if (drmModePageFlip(d->fd, d->crtc_id, d->buf[back].fb_id, DRM_MODE_PAGE_FLIP_EVENT, d))
        return drm_fail("drmModePageFlip");
    d->pending = 1;
    d->front = back;
    d->flips++;
    return 0;
}

long cam_drm_flips(const cam_fb_t *fb)
{
    return fb->drm ? fb->drm->flips : 0;
}

void cam_drm_close(cam_fb_t *fb)
{
    struct cam_drm *d = fb->drm;
    if (!d)
        return;
    if (d->fd >= 0) {
        if (d->pending)
            wait_flip(d, 1000);
        if (d->set && d->saved) {
            drmModeCrtc *s = d->saved;
            /* the CRTC as found: its framebuffer and mode (the fbdev
             * emulation's, or another program's), or off */
            const int r =
                s->buffer_id && s->mode_valid
                    ? drmModeSetCrtc(d->fd, s->crtc_id, s->buffer_id, s->x, s->y, &d->conn_id, 1, &s->mode)
                    : drmModeSetCrtc(d->fd, s->crtc_id, 0, 0, 0, NULL, 0, NULL);
            if (r)
                drm_fail("drmModeSetCrtc (restoring the CRTC)");
        }
        free_buf(d->fd, &d->buf[0]);
        free_buf(d->fd, &d->buf[1]);
        close(d->fd);
    }
    drmModeFreeCrtc(d->saved);
    free(d);
    fb->drm = NULL;
    fb->fd = -1;
}
#endif

int cam_display_open(cam_fb_t *fb, const cam_opts_t *o, int w, int h)
{
    char found[32];
    const char *card = o->drm_card;
    int connected = 0;
    if (o->display == CAM_DISPLAY_AUTO && !o->fb_given) {
        card = cam_drm_find(found, sizeof found);
        connected = card != NULL;
    }
    if (cam_display_use_drm(o, connected))
        return cam_drm_open(fb, card, o->drm_w, o->drm_h, o->drm_format, o->quiet);
    if (cam_fb_open(fb, o->fb, w, h))
        return -1;
    snprintf(fb->path, sizeof fb->path, "%s", o->fb);
    return 0;
}
