/* bloom_cam --threads N > 1: whole frames over a pool of strip engines
 * (port/threads/bloom_mt). A strip engine reads its halo from its
 * neighbours' source columns, so the whole source frame must be in memory:
 * captures other than RGB24 are converted once per frame into one RGB888
 * frame; an RGB24 capture is read where the driver put it (any
 * bytesperline: the engine takes a stride). The output goes straight into
 * the page when the screen shows the whole frame (the engine writes the
 * screen's own format at line_length, as the row path does, and a second
 * frame of memory and a copy are saved), else into an output frame whose
 * shown part is copied into the page. Neither source overlaps its
 * destination (a capture buffer, a malloc'd frame, the framebuffer), which
 * is all the strips need. */
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <linux/videodev2.h>

#include "bloom_mt.h"
#include "cam.h"

/* A whole shown frame is drawn straight into the page. */
static int shows_all(const cam_v4l2_t *cap, const cam_place_t *p)
{
    return p->src_x == 0 && p->src_y == 0 && p->w == cap->width && p->h == cap->height;
}

static void *alloc64(size_t n)
{
    return aligned_alloc(64, (n + 63) / 64 * 64);
}

int cam_mt_frames(cam_mt_t *t, const cam_v4l2_t *cap, const cam_fb_t *fb, const cam_place_t *p)
{
    const size_t w = (size_t)cap->width, h = (size_t)cap->height;
    if (cap->pixelformat != V4L2_PIX_FMT_RGB24) {
        t->rgb_stride = w * 3;
        t->rgb = alloc64(t->rgb_stride * h);
        if (!t->rgb) {
            fprintf(stderr, "%s: RGB888 frame of %zu bytes: out of memory\n", CAM_PROG, t->rgb_stride * h);
            return -1;
        }
        t->frame_bytes += t->rgb_stride * h;
    }
    if (!shows_all(cap, p)) {
        t->out_stride = w * (size_t)fb->bpp;
        t->out = alloc64(t->out_stride * h);
        if (!t->out) {
            fprintf(stderr, "%s: output frame of %zu bytes: out of memory\n", CAM_PROG, t->out_stride * h);
            return -1;
        }
        t->frame_bytes += t->out_stride * h;
    }
    return 0;
}

int cam_mt_mode(cam_mt_t *t, enum cam_mode m, const bloom_config_t *cfg, int n, const uint8_t *aux,
                size_t aux_stride, size_t *bytes)
{
    const char *pn = bloom_preset_name(cfg->preset), *view = m == CAM_MODE_BLOOM_ONLY ? ", bloom-only" : "";
    bloom_status_t st;
    *bytes = bloom_mt_size(cfg, n);
    if (!*bytes) { /* refused: bloom_mt_init says why before it looks at the buffer */
        unsigned char none;
        bloom_mt_t *dummy;
        st = bloom_mt_init(&dummy, &none, sizeof none, cfg, n);
        fprintf(stderr, "%s: bloom_mt_size (%d threads, preset %s%s): %s\n", CAM_PROG, n, pn, view,
                bloom_mt_status_str(st));
        return -1;
    }
    t->buf[m] = alloc64(*bytes);
    if (!t->buf[m]) {
        fprintf(stderr, "%s: %d strip engines of %zu bytes: out of memory\n", CAM_PROG, n, *bytes);
        return -1;
    }
    /* The pool threads inherit the mask: SIGINT and SIGTERM blocked there
     * go to the main thread, whose poll they must interrupt. */
    sigset_t stop, old;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop, &old);
    st = bloom_mt_init(&t->mt[m], t->buf[m], *bytes, cfg, n);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    const char *call = "bloom_mt_init";
    if (st == BLOOM_OK && aux) {
        call = "bloom_mt_set_aux";
        st = bloom_mt_set_aux(t->mt[m], aux, (ptrdiff_t)aux_stride);
    }
    if (st != BLOOM_OK) {
        fprintf(stderr, "%s: %s (%d threads, preset %s%s): %s\n", CAM_PROG, call, n, pn, view,
                bloom_mt_status_str(st));
        return -1;
    }
    t->tiles = bloom_mt_tiles(t->mt[m]);
    return 0;
}

int cam_mt_process(cam_mt_t *t, enum cam_mode m, const cam_v4l2_t *cap, const cam_frame_t *f,
                   const cam_fb_t *fb, const cam_place_t *p, uint8_t *page)
{
    const size_t ll = (size_t)fb->line_length, bpp = (size_t)fb->bpp;
    const uint8_t *src = f->data;
    ptrdiff_t src_stride = (ptrdiff_t)cap->bytesperline;
    if (t->rgb) { /* an MJPEG frame found bad is not drawn at all: the page keeps what it had */
        if (cam_cap_begin(cap, f))
            return 2;
        for (int y = 0; y < cap->height; y++)
            if (!cam_cap_next(cap, f, y, t->rgb + (size_t)y * t->rgb_stride))
                return 2;
        if (cam_cap_end(cap))
            return 2;
        src = t->rgb;
        src_stride = (ptrdiff_t)t->rgb_stride;
    }
    uint8_t *dst = t->out;
    ptrdiff_t dst_stride = (ptrdiff_t)t->out_stride;
    if (!dst) {
        dst = page + (size_t)p->dst_y * ll + (size_t)p->dst_x * bpp;
        dst_stride = (ptrdiff_t)ll;
    }
    const bloom_status_t st = bloom_mt_process(t->mt[m], src, src_stride, dst, dst_stride);
    if (st != BLOOM_OK) {
        fprintf(stderr, "%s: bloom_mt_process (%d threads): %s\n", CAM_PROG, t->tiles,
                bloom_mt_status_str(st));
        return -1;
    }
    for (int y = 0; t->out && y < p->h; y++)
        memcpy(page + (size_t)(p->dst_y + y) * ll + (size_t)p->dst_x * bpp,
               t->out + (size_t)(p->src_y + y) * t->out_stride + (size_t)p->src_x * bpp, (size_t)p->w * bpp);
    return 0;
}

void cam_mt_close(cam_mt_t *t)
{
    for (int m = 0; m < CAM_MODE_COUNT; m++) {
        bloom_mt_free(t->mt[m]);
        free(t->buf[m]);
    }
    free(t->rgb);
    free(t->out);
    memset(t, 0, sizeof *t);
}
