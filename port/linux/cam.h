/* bloom_cam: V4L2 camera -> bloom engine -> Linux framebuffer, with optional
 * GPIO frame-sync output and mode button (libgpiod v1).
 *
 * Modules: cam_opts.c (command line), cam_conv.c (row conversion, pure
 * framebuffer logic), cam_aux.c (the --aux plane of the presets), v4l2.c
 * (capture) and v4l2_fmt.c (its format negotiation), fbdev.c (output),
 * gpio.c (lines),
 * drm.c (DRM/KMS output, the choice of display), drm_pick.c (its pure rules),
 * main.c (frame loop, signals, statistics, recording), cam_mt.c (whole
 * frames on threads, --threads N > 1). Everything is allocated before the
 * first frame; the frame loop allocates nothing. */
#ifndef BLOOM_CAM_H
#define BLOOM_CAM_H

#include <stddef.h>
#include <stdint.h>

#include <poll.h>
#include <signal.h>

#include <linux/fb.h>

#include "bloom.h"

#define CAM_PROG "bloom_cam"
#define CAM_MAX_BUFFERS 16

/* ---- options (cam_opts.c) ------------------------------------------------ */
/* --format: auto (the default) or one of the formats of cam_fmt.c's table;
 * the ...M names ask for the two-plane variants (multi-planar devices). */
enum cam_pixfmt {
    CAM_FMT_AUTO = 0,
    CAM_FMT_YUYV,
    CAM_FMT_RGB24,
    CAM_FMT_GREY,
    CAM_FMT_UYVY,
    CAM_FMT_YVYU,
    CAM_FMT_NV12,
    CAM_FMT_NV21,
    CAM_FMT_NV16,
    CAM_FMT_NV61,
    CAM_FMT_RGB565,
    CAM_FMT_NV12M,
    CAM_FMT_NV21M,
    CAM_FMT_NV16M,
    CAM_FMT_NV61M,
    CAM_FMT_MJPEG,
    CAM_FMT_JPEG,
    CAM_FMT_COUNT
};
enum cam_mode { CAM_MODE_BLOOM = 0, CAM_MODE_OFF, CAM_MODE_BLOOM_ONLY, CAM_MODE_COUNT };
enum cam_display { CAM_DISPLAY_AUTO = 0, CAM_DISPLAY_FBDEV, CAM_DISPLAY_DRM };

typedef struct {
    char chip[64]; /* "gpiochip0", "0", or a chip label */
    char line[64]; /* offset ("17") or line name ("GPIO17") */
    int set;
} cam_gpio_spec_t;

typedef struct {
    const char *device;     /* --device, default /dev/video0 */
    const char *fb;         /* --fb, default /dev/fb0; "none": off-screen */
    const char *vt;         /* --vt, default /dev/tty0; "off": the console's mode is not touched */
    int width, height;      /* --size WxH, default 640x480 */
    enum cam_pixfmt format; /* --format, default auto */
    int fps;                /* --fps N (VIDIOC_S_PARM), 0: the driver's */
    bloom_preset_t preset;  /* --preset NAME, default unity */
    int levels;             /* bloom parameters: the preset's defaults (bloom_config_preset) */
    int sample_bits;        /* --sample-bits 16|32 (cfg.sample_bits), default 32 */
    uint32_t threshold, knee, intensity; /* Q16.16 */ /* unless given on the command line */
    bloom_preset_params_t params;       /* the preset's parameters, defaults (at --size) then the options */
    bloom_preset_params_t given_params; /* the preset options given (given_mask: CAM_P_*) */
    unsigned given_mask;
    int given_weights;          /* --weights: level_weight[0 .. given_weights-1] */
    uint32_t preset_flags;      /* BLOOM_FLAG_SATURATE / _BAKED / _ADDITIVE */
    bloom_aux_format_t aux_fmt; /* what the preset reads by default (U8 until --aux is read) */
    const char *aux;            /* --aux FILE: the preset's plane, read once after S_FMT */
    long frames;                /* --frames N, 0 = until a signal */
    int buffers;                /* --buffers N, 2..CAM_MAX_BUFFERS (default 4) */
    int timeout_ms;             /* --timeout MS for poll (default 2000) */
    long reconnect_s;           /* --reconnect S: how long to try to get a lost device back (0: off) */
    int latest;                 /* --latest on|off (default on) */
    int debounce_ms;            /* --debounce MS for --gpio-button (default 30) */
    int threads;                /* --threads N, 0 (default): the online CPUs; 1: the row path */
    enum cam_mode mode;         /* --mode bloom|off|bloom-only */
    int stats;                  /* --stats */
    int quiet;                  /* -q */
    const char *record;         /* --record FILE */
    const char *dump_fb;        /* --dump-fb FILE: the last frame shown, as drawn */
    cam_gpio_spec_t gpio_frame, gpio_button;
    enum cam_display display;  /* --display drm|fbdev|auto (default auto: cam_display_use_drm) */
    int fb_given;              /* --fb was given: auto means that framebuffer */
    const char *drm_card;      /* --drm-card PATH; NULL: the first /dev/dri/card* connected */
    int drm_w, drm_h;          /* --drm-mode WxH; 0: the connector's preferred mode */
    bloom_format_t drm_format; /* --drm-format; 0 (auto): XRGB8888, else RGB565 */
} cam_opts_t;

/* Parse argv into o (defaults first). Returns 0 to run, 1 when help was
 * printed, -1 on an error (message written to err, at most errlen bytes). */
int cam_parse_opts(cam_opts_t *o, int argc, char **argv, char *err, size_t errlen);
/* Writes a message into err (size errlen); returns -1 (cam_opts.c). */
int cam_errf(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
void cam_usage(void *stream);
const char *cam_format_name(enum cam_pixfmt f);
const char *cam_mode_name(enum cam_mode m);
/* The engine configuration of the options for a w x h RGB888 frame: the
 * preset's defaults for that size (some depend on it: cod's level weights),
 * then the options given. */
enum {
    CAM_P_STRENGTH = 1u,
    CAM_P_PASSES = 2u,
    CAM_P_ATTENUATION = 4u,
    CAM_P_MAX_REDUCTION = 8u,
    CAM_P_TINT = 16u
};
void cam_opts_config(const cam_opts_t *o, int w, int h, bloom_config_t *cfg);

/* ---- the aux plane (cam_aux.c) ------------------------------------------- */
/* Reads a binary PGM (P5): maxval <= 255 gives BLOOM_AUX_U8, above
 * BLOOM_AUX_U16 (native uint16_t); codes rescaled to 255 / 65535 when
 * maxval is below. The plane must be w x h (the capture size after
 * VIDIOC_S_FMT). Returns 0, or -1 with err naming the file and the
 * problem. *data is malloc'd (w * bytes per sample per row). */
int cam_aux_load(const char *path, int w, int h, bloom_aux_format_t *fmt, uint8_t **data, char *err,
                 size_t errlen);

/* ---- pure helpers (cam_conv.c) ------------------------------------------- */
/* The row converters (cam_conv.h: also built into the GStreamer element). */
#include "cam_conv.h"

/* What the framebuffer's layout is, from its var screeninfo fields. */
typedef struct {
    uint32_t bits_per_pixel, grayscale, nonstd;
    uint32_t red_off, red_len, green_off, green_len, blue_off, blue_len;
} cam_fb_layout_t;
/* The engine format that writes this layout, or 0 with why[] naming the
 * layout that is refused ("24 bpp", "16 bpp BGR565", ...). */
bloom_format_t cam_fb_format(const cam_fb_layout_t *l, char *why, size_t whylen);

/* Placement of a frame of fw x fh on a screen of sw x sh: centred when it
 * is smaller, cropped around the centre when it is larger (per axis). */
typedef struct {
    int dst_x, dst_y; /* where the first shown pixel goes on the screen */
    int src_x, src_y; /* first shown pixel of the frame */
    int w, h;         /* shown size */
} cam_place_t;
void cam_place(int fw, int fh, int sw, int sh, cam_place_t *p);

/* Exit statuses of bloom_cam (port/linux/README.md): a stop signal or the
 * frames asked for, 0; what a persistent failure was otherwise. */
enum {
    CAM_EXIT_OK = 0,
    CAM_EXIT_FAULT = 1,  /* anything else: --record, memory, the engine at run time */
    CAM_EXIT_CONFIG = 2, /* the options, or what they ask of the devices (a format, a GPIO line) */
    CAM_EXIT_DEVICE = 3, /* the camera was lost and did not come back (--reconnect) */
    CAM_EXIT_DISPLAY = 4 /* the framebuffer could not be opened or shown */
};

/* ---- capture formats (cam_fmt.c) ------------------------------------------ */
typedef struct {
    const char *name; /* --format NAME */
    const char *raw;  /* the layout --record writes, as bloom_sim --raw-format names it */
    uint32_t fourcc;  /* V4L2_PIX_FMT_* */
    enum cam_pixfmt opt;
    int planes; /* memory planes: 2 for the ...M variants (multi-planar API only) */
    int bpp;    /* bytes per pixel of the first plane (the luma of NV..); 0: compressed (MJPEG) */
    int chroma; /* NV..: the chroma rows' vertical shift (1: 4:2:0, 0: 4:2:2); -1 none */
    int rank;   /* --format auto: lower is better (README, formats) */
} cam_fmt_t;
const cam_fmt_t *cam_fmt_of_fourcc(uint32_t fourcc); /* NULL: not converted here */
const cam_fmt_t *cam_fmt_of_opt(enum cam_pixfmt f);
/* The rule a driver's colorimetry (v4l2_pix_format colorspace, ycbcr_enc,
 * quantization) asks for, V4L2's defaults for DEFAULT: *bt709 and *full
 * set; returns a note ("" or why an encoding was approximated). */
const char *cam_colorimetry(uint32_t colorspace, uint32_t ycbcr_enc, uint32_t quantization, int *bt709,
                            int *full);
/* --format auto: a format the device offers, with whether it offers the
 * size and the frame rate asked; the best index (cam_fmt_best's rule, README). */
typedef struct {
    const cam_fmt_t *f;
    int size_ok, fps_ok;
} cam_fmt_cand_t;
int cam_fmt_best(const cam_fmt_cand_t *c, int n);

/* ---- capture (v4l2.c, v4l2_fmt.c) ----------------------------------------- */
typedef struct {
    void *start;
    size_t length;
    void *start2; /* the second plane's mapping (two-plane formats) */
    size_t length2;
} cam_vbuf_t;

/* The system calls capture goes through: ioctl(2) and ppoll(2) unless a
 * test puts a scripted fake here (test_host.c); cam_v4l2_open sets the
 * defaults. The wait takes the signal mask to wait with (NULL: the
 * current one): the stop signals are blocked outside the wait and let
 * through only inside it, so one that comes between the loop's look at its
 * flag and the wait ends the wait (EINTR) instead of being lost until the
 * timeout. */
typedef int (*cam_ioctl_fn)(int fd, unsigned long req, void *arg);
typedef int (*cam_poll_fn)(struct pollfd *fds, nfds_t nfds, int timeout_ms, const sigset_t *mask);

typedef struct {
    int fd;
    cam_ioctl_fn ioctl_fn;
    cam_poll_fn poll_fn;
    int width, height;
    uint32_t pixelformat, bytesperline, sizeimage;
    int mplane;              /* the multi-planar API (V4L2_BUF_TYPE_VIDEO_CAPTURE_MPLANE) */
    int nplanes;             /* memory planes of the format (1 or 2; 0 read as 1) */
    uint32_t bytesperline2;  /* the chroma rows' (NV..: the second plane's, or bytesperline) */
    uint32_t plane_bytes[2]; /* what a frame's planes hold (bytesperline x rows each) */
    int bt709, full;         /* the Y'CbCr rule (cam_colorimetry), 0 0: BT.601 limited */
    const char *ycc_note;    /* why the driver's encoding was approximated, or "" */
    int fps;                 /* the frame rate in force after VIDIOC_S_PARM (0 unknown) */
    cam_vbuf_t bufs[CAM_MAX_BUFFERS];
    int nbufs, streaming;
    int events; /* subscribed to V4L2_EVENT_SOURCE_CHANGE (the driver has it) */
    char card[32], driver[16];
    const sigset_t *wait_mask; /* the signal mask inside the wait (NULL: the current one) */
    struct cam_mjpeg *jpeg;    /* MJPEG's decoder (cam_mjpeg.c), made by cam_v4l2_open; else NULL */
    int lost;                  /* after a -1: CAM_LOST_* (what kind of fault) */
    int quiet;                 /* keep messages in msg only (a reconnection's attempts) */
    char msg[200];             /* the last message */
} cam_v4l2_t;

/* What a fault was (cam_v4l2_t.lost): the device stopped delivering
 * (timeout), went away or failed (ENODEV, EIO, POLLERR, ...), refuses
 * what was asked of it (a configuration: no reconnection mends it), or its
 * source changed (V4L2_EVENT_SOURCE_CHANGE: the format must be negotiated
 * again, which the reconnection does by opening the device afresh). */
enum { CAM_LOST_NONE = 0, CAM_LOST_TIMEOUT, CAM_LOST_DEVICE, CAM_LOST_CONFIG, CAM_LOST_SOURCE };
/* A frame that came but cannot be shown (cam_frame_t.bad): requeued and
 * counted, never fatal. CAM_BAD_JPEG: an MJPEG frame libjpeg cannot
 * decode whole (found while it is processed: cam_cap_next). */
enum { CAM_BAD_NONE = 0, CAM_BAD_FLAGGED, CAM_BAD_SHORT, CAM_BAD_JPEG, CAM_BAD_KINDS };

typedef struct {
    int index;
    uint32_t sequence, bytesused;
    const uint8_t *data;  /* the first plane (after its data_offset) */
    const uint8_t *data2; /* the chroma plane of an NV.. format, else NULL */
    size_t len;           /* the first plane's bytes after data_offset (a JPEG's size) */
    int bad;              /* CAM_BAD_* (cam_v4l2_dequeue returned 2) */
} cam_frame_t;

/* Each returns 0, or -1 after printing "bloom_cam: CALL: reason" (and
 * c->lost says what kind). */
/* fmt CAM_FMT_AUTO: the best the device offers (cam_fmt_best); fps > 0:
 * asked with VIDIOC_S_PARM (a driver without it is told, not refused). */
int cam_v4l2_open(cam_v4l2_t *c, const char *dev, int w, int h, enum cam_pixfmt fmt, int fps, int nbufs);
/* The capture's row y as RGB888 (any format of the table): data the first
 * plane, data2 the chroma plane (NULL: right after the first, the
 * single-planar layout). RGB24 is copied. */
void cam_cap_row(const cam_v4l2_t *c, const uint8_t *data, const uint8_t *data2, int y, uint8_t *dst);
/* One frame's rows as RGB888, whatever the format: cam_cap_begin (0, or -1
 * when the frame is bad: an MJPEG frame whose header is damaged or of
 * another size), then cam_cap_next for y = 0, 1, ... in order (the row:
 * in the capture buffer for RGB24, else converted or decoded into line,
 * width x 3 bytes; NULL when the frame turns out bad), then cam_cap_end
 * (0, or -1: an MJPEG frame cut short or damaged after its last row).
 * Nothing is allocated per frame (cam_mjpeg.c). */
int cam_cap_begin(const cam_v4l2_t *c, const cam_frame_t *f);
const uint8_t *cam_cap_next(const cam_v4l2_t *c, const cam_frame_t *f, int y, uint8_t *line);
int cam_cap_end(const cam_v4l2_t *c);
/* The MJPEG decoder (cam_mjpeg.c, libjpeg's scanline API) for w x h frames:
 * open (0, or -1 out of memory), then per frame begin (the JPEG's bytes),
 * row (the next row, RGB888, into dst), end (read to the EOI); each 0, or
 * -1 when the frame is bad (why: what libjpeg said, "truncated (no EOI)",
 * or the size). A failure leaves it ready for the next frame. */
typedef struct cam_mjpeg cam_mjpeg_t;
int cam_mjpeg_open(cam_mjpeg_t **j, int w, int h);
int cam_mjpeg_begin(cam_mjpeg_t *j, const uint8_t *data, size_t len);
int cam_mjpeg_row(cam_mjpeg_t *j, uint8_t *dst);
int cam_mjpeg_end(cam_mjpeg_t *j);
const char *cam_mjpeg_why(const cam_mjpeg_t *j);
void cam_mjpeg_close(cam_mjpeg_t *j);
/* "nv12, bytesperline 320, sizeimage 115200, BT.601 limited range" and the
 * rest of the capture line main.c prints. */
void cam_v4l2_describe(const cam_v4l2_t *c, char *buf, size_t len);
int cam_v4l2_start(cam_v4l2_t *c);
/* Wait for and dequeue one frame: 0 got one, 1 interrupted by a signal
 * (nothing dequeued), 2 a bad frame (flagged V4L2_BUF_FLAG_ERROR or
 * short: f->bad says which, f->sequence its number; already requeued, no
 * message), -1 fault (message printed, c->lost says what kind). */
int cam_v4l2_dequeue(cam_v4l2_t *c, int timeout_ms, int extra_fd, int *extra_ready, cam_frame_t *f);
/* The newest frame ready (--latest): while another buffer is already
 * done, *f is requeued and that one taken instead, without waiting. Adds
 * the frames passed over to *skipped and the bad ones to bad[CAM_BAD_*].
 * 0, or -1 on a fault (as cam_v4l2_dequeue; *f is then requeued already). */
int cam_v4l2_latest(cam_v4l2_t *c, cam_frame_t *f, long *skipped, long bad[3]);
int cam_v4l2_requeue(cam_v4l2_t *c, const cam_frame_t *f);
void cam_v4l2_close(cam_v4l2_t *c); /* STREAMOFF, unmap, free buffers, close */
/* ioctl(2), retried while it fails with EINTR. */
int cam_xioctl(int fd, unsigned long req, void *arg);
/* Between v4l2.c and v4l2_fmt.c: the device's ioctl through the seam in c
 * (retried on EINTR); a message "bloom_cam: ..." kept in c->msg (the last
 * one) and printed unless c->quiet (a reconnection's attempts); the buffer
 * type of c's API; --format auto's fourcc (0: none usable, said); the
 * planes' sizes from S_FMT's answer (fm: a struct v4l2_format; 0, or -1
 * said when they cannot hold a frame); --fps by VIDIOC_S_PARM. */
struct v4l2_format;
int cam_v4l2_ioctl(cam_v4l2_t *c, unsigned long req, void *arg);
__attribute__((format(printf, 2, 3))) void cam_v4l2_say(cam_v4l2_t *c, const char *fmt, ...);
uint32_t cam_v4l2_buf_type(const cam_v4l2_t *c);
uint32_t cam_v4l2_choose_format(cam_v4l2_t *c, const char *dev, int w, int h, int fps);
int cam_v4l2_layout(cam_v4l2_t *c, const cam_fmt_t *f, const struct v4l2_format *fm);
void cam_v4l2_set_fps(cam_v4l2_t *c, int fps);

/* ---- what a run went through (cam_stats.c) -------------------------------- */
typedef struct {
    long frames, dropped, skipped, bad[CAM_BAD_KINDS], reconnects;
} cam_counts_t;
/* "bloom_cam: WHAT: N frames, ... N bad (F flagged, S short, J undecodable
 * JPEG), N reconnects" over t0..t1 (seconds), to stderr. */
void cam_stats_line(const char *what, const cam_counts_t *n, double t0, double t1, double proc_sum,
                    double proc_min, double proc_max);
/* A bad frame of kind CAM_BAD_* counted in n and win; the first of each
 * kind told (why: what was wrong with a JPEG), unless quiet. */
void cam_count_bad(cam_counts_t *n, cam_counts_t *win, int kind, uint32_t sequence, const char *why,
                   int quiet);

/* ---- framebuffer (fbdev.c) ------------------------------------------------- */
typedef struct {
    int fd;
    uint8_t *mem;
    size_t mem_len;
    int xres, yres, line_length, bpp; /* bytes per pixel */
    bloom_format_t format;
    int pages, page;                    /* 2 when double-buffering with FBIOPAN_DISPLAY */
    unsigned xoffset, yoffset;          /* of the page on show */
    int changed_var;                    /* var screeninfo changed, restore on close */
    int vsync;                          /* FBIO_WAITFORVSYNC before each pan (1 until it fails) */
    struct fb_var_screeninfo saved_var; /* as found */
    char id[17];
    struct cam_drm *drm; /* the DRM output (drm.c), NULL for the fbdev */
    char path[32];       /* what was opened (the fbdev, or the DRM card) */
} cam_fb_t;

/* path "none": an off-screen XRGB8888 surface of w x h (for measuring). */
int cam_fb_open(cam_fb_t *fb, const char *path, int w, int h);
uint8_t *cam_fb_draw_page(cam_fb_t *fb);          /* first byte of the page to draw */
int cam_fb_show(cam_fb_t *fb);                    /* pan to the page just drawn */
void cam_fb_close(cam_fb_t *fb);                  /* restore pan and var, unmap, close */
const char *cam_fb_buffering(const cam_fb_t *fb); /* "double-buffered", ... (the startup line) */

/* The console's VT while drawing (--vt, default /dev/tty0: the VT in the
 * foreground): KD_GRAPHICS, so that fbcon's cursor, kernel messages and a
 * getty do not draw over the video; the mode found is put back (and fbcon
 * repaints the console) by cam_vt_restore, on every exit path. A VT that
 * cannot be opened or switched (no VT, no permission, a serial console) is
 * said once and left alone: it is not an error. */
typedef struct {
    int fd;
    int saved_mode, changed;
} cam_vt_t;
void cam_vt_graphics(cam_vt_t *vt, const char *path, int quiet);
void cam_vt_restore(cam_vt_t *vt);

/* ---- DRM/KMS (drm.c; the pure rules in drm_pick.c) ------------------------
 * The screen is a cam_fb_t either way: cam_display_open fills it from a
 * DRM device (fb->drm set: two dumb buffers, flipped on the vertical blank)
 * or the fbdev, and cam_fb_draw_page / cam_fb_show / cam_fb_close go to
 * the one opened. */
struct cam_drm;
extern const int cam_drm_available; /* 0 when built without libdrm (drm_pick.c) */
/* The first /dev/dri/cardN with a connected connector, written to path;
 * NULL when none (or built without libdrm). */
const char *cam_drm_find(char *path, size_t len);
int cam_drm_open(cam_fb_t *fb, const char *card, int mode_w, int mode_h, bloom_format_t fmt, int quiet);
uint8_t *cam_drm_draw_page(cam_fb_t *fb); /* NULL when the last flip never completed */
int cam_drm_show(cam_fb_t *fb);
void cam_drm_close(cam_fb_t *fb);
long cam_drm_flips(const cam_fb_t *fb);

/* A connector's mode, as far as the choice needs it. */
typedef struct {
    int w, h, refresh, preferred;
} cam_drm_mode_t;
/* The mode to set: with want_w > 0 the first of that size (the preferred
 * one if it is that size, else the highest refresh); without, the
 * preferred, else the first listed. The index, or -1 (no mode of that size). */
int cam_drm_pick_mode(const cam_drm_mode_t *m, int n, int want_w, int want_h);
/* DRM fourccs (drm_fourcc.h's values, spelt here so the rules need no libdrm). */
#define CAM_FOURCC(a, b, c, d)                                                                               \
    ((uint32_t)(a) | ((uint32_t)(b) << 8) | ((uint32_t)(c) << 16) | ((uint32_t)(d) << 24))
#define CAM_DRM_XRGB8888 CAM_FOURCC('X', 'R', '2', '4')
#define CAM_DRM_RGB565 CAM_FOURCC('R', 'G', '1', '6')
/* The formats to try, best first, of those the plane offers (fmts): want
 * (0: XRGB8888 then RGB565) when offered. The count written to out (0..2). */
int cam_drm_pick_formats(const uint32_t *fmts, int n, bloom_format_t want, bloom_format_t out[2]);
/* Auto's rule: DRM with --display drm, fbdev with --display fbdev; auto
 * takes the fbdev when --fb was given, else DRM when a card has a connected
 * connector (drm_connected), else the fbdev. 1 DRM, 0 fbdev. */
int cam_display_use_drm(const cam_opts_t *o, int drm_connected);
/* The display's options (cam_parse_opts): 0 when name is not one of them,
 * 1 when taken, -1 on an error (err). */
int cam_display_opt(cam_opts_t *o, const char *name, const char *v, char *err, size_t errlen, int *drm_given);
/* Them together, after the rest: --drm-* ask for DRM (auto becomes drm), and
 * --fb for the fbdev. 0, or -1 on an error (err). */
int cam_display_check(cam_opts_t *o, int drm_given, char *err, size_t errlen);
/* The screen the options ask for (fbdev, DRM, or auto's choice by
 * cam_display_use_drm) for a w x h frame: 0, or -1 after a message. */
int cam_display_open(cam_fb_t *fb, const cam_opts_t *o, int w, int h);

/* ---- GPIO (gpio.c) ------------------------------------------------------- */
typedef struct cam_gpio cam_gpio_t;
extern const int cam_gpio_available; /* 0 when built without libgpiod */
/* Request the lines (either spec may be unset): 0, or -1 after a message. */
int cam_gpio_open(cam_gpio_t **g, const cam_gpio_spec_t *frame, const cam_gpio_spec_t *button,
                  int debounce_ms);
void cam_gpio_frame(cam_gpio_t *g, int high);
int cam_gpio_button_fd(cam_gpio_t *g); /* -1 without a button */
/* Read the pending edge events; returns how many presses (falling edges
 * at least the debounce time after the last press counted). */
int cam_gpio_button_presses(cam_gpio_t *g);
/* Whether an edge at t_ns (nanoseconds, one clock) counts as a press:
 * the first does, then only one at least ms after the last counted;
 * *last_ns is the last counted (start it at INT64_MIN). Pure. */
int cam_debounce(int64_t *last_ns, int64_t t_ns, int ms);
void cam_gpio_close(cam_gpio_t *g);

/* ---- whole frames on threads (cam_mt.c) ------------------------------------
 * --threads N > 1: each captured frame converted once into an RGB888 frame
 * (RGB24 captures read in place), rendered by a port/threads pool of N
 * strip engines per mode, straight into the page when the screen shows the
 * whole frame, else into an output frame whose shown part is copied. */
struct bloom_mt;
typedef struct {
    int tiles;                           /* of each pool (bloom_mt_tiles) */
    struct bloom_mt *mt[CAM_MODE_COUNT]; /* NULL: a mode the preset cannot show */
    void *buf[CAM_MODE_COUNT];           /* each pool's one buffer (bloom_mt_size) */
    uint8_t *rgb;                        /* the converted frame (all but RGB24); NULL for RGB24 */
    uint8_t *out;                        /* the output frame when the screen shows part of it */
    size_t rgb_stride, out_stride, frame_bytes;
} cam_mt_t;

/* The frame buffers for this capture and screen: 0, or -1 after a message. */
int cam_mt_frames(cam_mt_t *t, const cam_v4l2_t *cap, const cam_fb_t *fb, const cam_place_t *p);
/* Mode m's pool of n threads for cfg (RGB888 in, the screen's format out),
 * reading aux (row 0, stride) when not NULL; *bytes its buffer. 0, or -1
 * after a message naming the call and the status. */
int cam_mt_mode(cam_mt_t *t, enum cam_mode m, const bloom_config_t *cfg, int n, const uint8_t *aux,
                size_t aux_stride, size_t *bytes);
/* One captured frame (f, as cap describes it) in mode m onto page, placed
 * as p says. 0, 2 when the frame is bad (an undecodable MJPEG frame:
 * nothing drawn), or -1 after a message. */
int cam_mt_process(cam_mt_t *t, enum cam_mode m, const cam_v4l2_t *cap, const cam_frame_t *f,
                   const cam_fb_t *fb, const cam_place_t *p, uint8_t *page);
void cam_mt_close(cam_mt_t *t); /* joins every pool, frees everything; t zeroed */

/* ---- the program (main.c, cam_engines.c) ------------------------------------ */
/* bloom_cam's state: options, camera, screen, engines, buffers. */
typedef struct cam {
    cam_opts_t o;
    cam_v4l2_t cap;
    cam_fb_t fb;
    cam_vt_t vt;
    cam_gpio_t *gpio;
    bloom_t *eng[CAM_MODE_COUNT]; /* NULL: a mode the preset cannot show (skipped) */
    void *ws[CAM_MODE_COUNT];
    int eng_aux[CAM_MODE_COUNT]; /* the engine reads the aux plane with each row */
    uint8_t *aux;                /* --aux plane, capture size, read once */
    size_t aux_stride;
    uint8_t *line;    /* one converted source row (RGB888) */
    uint8_t *scratch; /* one output row the screen does not fully show */
    cam_place_t place;
    int rec_fd;
    uint8_t *last_page;
    int threads; /* tiles per frame: 1 the row path (eng), more the pools (mt) */
    cam_mt_t mt;
    int clear_pages; /* pages still to clear before drawing (a new capture size) */
} cam_t;

/* The engines of every mode (row path, or the pools with --threads), the
 * --aux plane, for the capture's size: 0, or -1 after a message. */
int cam_make_engines(cam_t *c);
/* The camera came back in another size (c->cap holds it): the engines,
 * pools, line buffers and placement made again for it, the screen's pages
 * cleared before they are drawn. 0, or -1 after a message (then the
 * program ends: CAM_EXIT_CONFIG). */
int cam_resize(cam_t *c);

#endif
