/* bloom_cam: Linux framebuffer output. 16 bpp RGB565 and 32 bpp XRGB8888;
 * anything else is refused by name (cam_fb_format). Double-buffered with
 * FBIOPAN_DISPLAY when the virtual screen holds two pages, each pan after
 * the vertical blank where the driver waits for it (FBIO_WAITFORVSYNC);
 * the pan offsets and the var screeninfo found at start are put back by
 * cam_fb_close. The VT is kept in KD_GRAPHICS while drawing (cam_vt_*). */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <linux/kd.h>

#include "cam.h"

static int fb_fail(const char *call)
{
    fprintf(stderr, "%s: %s: %s\n", CAM_PROG, call, strerror(errno));
    return -1;
}

static void set_layout(struct fb_var_screeninfo *v, int bpp)
{
    v->bits_per_pixel = (uint32_t)bpp;
    v->grayscale = 0;
    v->nonstd = 0;
    v->transp.offset = v->transp.length = 0;
    v->red.msb_right = v->green.msb_right = v->blue.msb_right = 0;
    if (bpp == 16) {
        v->red.offset = 11, v->red.length = 5;
        v->green.offset = 5, v->green.length = 6;
        v->blue.offset = 0, v->blue.length = 5;
    } else {
        v->red.offset = 16, v->red.length = 8;
        v->green.offset = 8, v->green.length = 8;
        v->blue.offset = 0, v->blue.length = 8;
    }
}

/* The screen's layout is one the engine cannot write: ask the driver for
 * RGB565 or XRGB8888 (same depth first). 1 when the driver switched (the
 * caller checks what it switched to; cam_fb_close puts the old var back). */
static int try_layout(cam_fb_t *fb, struct fb_fix_screeninfo *fix, struct fb_var_screeninfo *var)
{
    const int first = var->bits_per_pixel == 32 ? 32 : 16;
    for (int k = 0; k < 2; k++) {
        struct fb_var_screeninfo v = fb->saved_var;
        set_layout(&v, k == 0 ? first : 48 - first);
        v.activate = FB_ACTIVATE_NOW;
        if (cam_xioctl(fb->fd, FBIOPUT_VSCREENINFO, &v))
            continue;
        fb->changed_var = 2; /* the layout: put the old var back on close */
        if (cam_xioctl(fb->fd, FBIOGET_VSCREENINFO, var) || cam_xioctl(fb->fd, FBIOGET_FSCREENINFO, fix))
            return 0;
        cam_fb_layout_t l = {var->bits_per_pixel, var->grayscale,   var->nonstd,
                             var->red.offset,     var->red.length,  var->green.offset,
                             var->green.length,   var->blue.offset, var->blue.length};
        char why[64];
        if (cam_fb_format(&l, why, sizeof why))
            return 1;
    }
    return 0;
}

int cam_fb_open(cam_fb_t *fb, const char *path, int w, int h)
{
    memset(fb, 0, sizeof *fb);
    fb->fd = -1;
    fb->pages = 1;
    if (!strcmp(path, "none")) {
        fb->xres = w;
        fb->yres = h;
        fb->bpp = 4;
        fb->line_length = 4 * w;
        fb->format = BLOOM_FMT_XRGB8888;
        fb->mem_len = (size_t)fb->line_length * (size_t)h;
        fb->mem = calloc(1, fb->mem_len);
        snprintf(fb->id, sizeof fb->id, "none");
        if (!fb->mem) {
            fprintf(stderr, "%s: off-screen surface: out of memory\n", CAM_PROG);
            return -1;
        }
        return 0;
    }

    fb->fd = open(path, O_RDWR | O_CLOEXEC);
    if (fb->fd < 0) {
        fprintf(stderr, "%s: open %s: %s\n", CAM_PROG, path, strerror(errno));
        return -1;
    }
    struct fb_fix_screeninfo fix;
    struct fb_var_screeninfo var;
    if (cam_xioctl(fb->fd, FBIOGET_FSCREENINFO, &fix))
        return fb_fail("FBIOGET_FSCREENINFO");
    if (cam_xioctl(fb->fd, FBIOGET_VSCREENINFO, &var))
        return fb_fail("FBIOGET_VSCREENINFO");
    fb->saved_var = var;
    memcpy(fb->id, fix.id, sizeof fix.id);
    fb->id[16] = '\0';

    if (fix.type != FB_TYPE_PACKED_PIXELS || fix.visual != FB_VISUAL_TRUECOLOR) {
        fprintf(stderr,
                "%s: FBIOGET_FSCREENINFO: %s (%s) is not packed-pixel true colour "
                "(type %u, visual %u)\n",
                CAM_PROG, path, fb->id, (unsigned)fix.type, (unsigned)fix.visual);
        return -1;
    }
    cam_fb_layout_t l = {var.bits_per_pixel, var.grayscale,   var.nonstd,
                         var.red.offset,     var.red.length,  var.green.offset,
                         var.green.length,   var.blue.offset, var.blue.length};
    char why[64];
    fb->format = cam_fb_format(&l, why, sizeof why);
    if (!fb->format && try_layout(fb, &fix, &var))
        fb->format = cam_fb_format(&(cam_fb_layout_t){var.bits_per_pixel, var.grayscale, var.nonstd,
                                                      var.red.offset, var.red.length, var.green.offset,
                                                      var.green.length, var.blue.offset, var.blue.length},
                                   why, sizeof why);
    if (!fb->format) {
        fprintf(stderr,
                "%s: FBIOGET_VSCREENINFO: %s (%s) is %s; only 16 bpp RGB565 and "
                "32 bpp XRGB8888 are supported (and the driver would not switch)\n",
                CAM_PROG, path, fb->id, why);
        return -1;
    }
    fb->bpp = (int)var.bits_per_pixel / 8;
    fb->xres = (int)var.xres;
    fb->yres = (int)var.yres;
    fb->line_length = (int)fix.line_length;
    if (fb->line_length < fb->xres * fb->bpp || (size_t)fix.line_length * var.yres_virtual > fix.smem_len ||
        var.xres_virtual < var.xres || var.yres_virtual < var.yres) {
        fprintf(stderr,
                "%s: FBIOGET_FSCREENINFO: %s: inconsistent geometry "
                "(line_length %u, virtual %ux%u, smem_len %u)\n",
                CAM_PROG, path, (unsigned)fix.line_length, (unsigned)var.xres_virtual,
                (unsigned)var.yres_virtual, (unsigned)fix.smem_len);
        return -1;
    }
    fb->mem_len = fix.smem_len;
    void *m = mmap(NULL, fb->mem_len, PROT_READ | PROT_WRITE, MAP_SHARED, fb->fd, 0);
    if (m == MAP_FAILED) {
        fb->mem = NULL;
        return fb_fail("mmap framebuffer");
    }
    fb->mem = m;
    fb->xoffset = var.xoffset;
    fb->yoffset = var.yoffset;
    /* Two pages side by side vertically: pan between them. */
    if (var.yres_virtual >= 2 * var.yres && var.xoffset + var.xres <= var.xres_virtual && fix.ypanstep != 0) {
        fb->pages = 2;
        fb->page = var.yoffset >= var.yres ? 0 : 1; /* draw the page not on show */
        fb->vsync = 1;
    }
    /* Start from black: the frame may not cover the screen. */
    for (int p = 0; p < fb->pages; p++) {
        unsigned y0 = fb->pages == 2 ? (unsigned)p * var.yres : var.yoffset;
        for (unsigned y = 0; y < var.yres; y++)
            memset(fb->mem + (size_t)(y0 + y) * fix.line_length + (size_t)var.xoffset * fb->bpp, 0,
                   (size_t)fb->xres * (size_t)fb->bpp);
    }
    return 0;
}

uint8_t *cam_fb_draw_page(cam_fb_t *fb)
{
    if (fb->drm)
        return cam_drm_draw_page(fb);
    size_t y0 = fb->pages == 2 ? (size_t)fb->page * (size_t)fb->yres : fb->saved_var.yoffset;
    return fb->mem + y0 * (size_t)fb->line_length + (size_t)fb->saved_var.xoffset * fb->bpp;
}

int cam_fb_show(cam_fb_t *fb)
{
    if (fb->drm)
        return cam_drm_show(fb);
    if (fb->pages != 2)
        return 0;
    /* the new page from the next frame on, not half-way down this one; a
     * driver without the ioctl (vfb, some DRM fbdev emulations) says so
     * once and is not asked again */
    if (fb->vsync) {
        uint32_t crtc = 0;
        if (cam_xioctl(fb->fd, FBIO_WAITFORVSYNC, &crtc))
            fb->vsync = 0;
    }
    struct fb_var_screeninfo v = fb->saved_var;
    v.yoffset = (uint32_t)(fb->page * fb->yres);
    if (cam_xioctl(fb->fd, FBIOPAN_DISPLAY, &v))
        return fb_fail("FBIOPAN_DISPLAY");
    fb->yoffset = v.yoffset;
    if (!fb->changed_var)
        fb->changed_var = 1;
    fb->page ^= 1;
    return 0;
}

const char *cam_fb_buffering(const cam_fb_t *fb)
{
    return fb->drm          ? "two dumb buffers flipped on the vertical blank"
           : fb->pages == 2 ? "double-buffered"
                            : "single-buffered";
}

void cam_fb_close(cam_fb_t *fb)
{
    if (fb->drm) {
        cam_drm_close(fb);
        return;
    }
    if (fb->fd < 0) {
        free(fb->mem); /* the off-screen surface, or NULL */
        fb->mem = NULL;
        return;
    }
    if (fb->changed_var) {
        struct fb_var_screeninfo v = fb->saved_var;
        v.activate = FB_ACTIVATE_NOW;
        if (cam_xioctl(fb->fd, FBIOPAN_DISPLAY, &v))
            fb_fail("FBIOPAN_DISPLAY (restoring)");
        struct fb_var_screeninfo now;
        if (!cam_xioctl(fb->fd, FBIOGET_VSCREENINFO, &now) &&
            (fb->changed_var == 2 || now.xres != v.xres || now.yres != v.yres ||
             now.bits_per_pixel != v.bits_per_pixel || now.yres_virtual != v.yres_virtual) &&
            cam_xioctl(fb->fd, FBIOPUT_VSCREENINFO, &v))
            fb_fail("FBIOPUT_VSCREENINFO (restoring)");
        fb->changed_var = 0;
    }
    if (fb->mem)
        munmap(fb->mem, fb->mem_len);
    fb->mem = NULL;
    close(fb->fd);
    fb->fd = -1;
}

void cam_vt_graphics(cam_vt_t *vt, const char *path, int quiet)
{
    vt->fd = -1;
    vt->changed = 0;
    if (!strcmp(path, "off"))
        return;
    vt->fd = open(path, O_RDWR | O_NOCTTY | O_CLOEXEC);
    int mode = 0;
    if (vt->fd < 0 || ioctl(vt->fd, KDGETMODE, &mode) ||
        (mode != KD_GRAPHICS && ioctl(vt->fd, KDSETMODE, KD_GRAPHICS))) {
        if (!quiet)
            fprintf(stderr, "%s: --vt %s: %s: the console may draw over the video\n", CAM_PROG, path,
                    strerror(errno));
        if (vt->fd >= 0)
            close(vt->fd);
        vt->fd = -1;
        return;
    }
    vt->saved_mode = mode;
    vt->changed = mode != KD_GRAPHICS;
    if (!quiet)
        fprintf(stderr, "%s: --vt %s: graphics mode while drawing (%s before)\n", CAM_PROG, path,
                mode == KD_TEXT       ? "text"
                : mode == KD_GRAPHICS ? "graphics"
                                      : "another mode");
}

void cam_vt_restore(cam_vt_t *vt)
{
    if (vt->fd < 0)
        return;
    /* back to text: fbcon repaints the console it kept */
    if (vt->changed && ioctl(vt->fd, KDSETMODE, vt->saved_mode))
        fprintf(stderr, "%s: KDSETMODE (restoring the console): %s\n", CAM_PROG, strerror(errno));
    close(vt->fd);
    vt->fd = -1;
    vt->changed = 0;
}
