/* bloom_cam --threads: the whole-frame path (cam_mt.c) on the real pool of
 * port/threads, against the untiled engine. For each capture format (YUYV,
 * RGB24, GREY; bytesperline padded), screen format (RGB565, XRGB8888;
 * line_length padded), placement (centred: straight to the page; cropped
 * on either axis or both: through the output frame) and mode (bloom,
 * bloom-only, off, a preset reading an aux plane) on 2, 3 and 4 threads (4:
 * a 2 x 2 grid, the strips would be under 64 columns), the whole page must
 * equal the untiled engine's frame placed by cam_place, the bytes around
 * the shown rectangle untouched; an MJPEG capture decoded into the frame
 * (a frame cut short drawing nothing). And the refusals (a configuration, a plane
 * the preset does not read) name the call, the threads and the status. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <jpeglib.h>
#include <linux/videodev2.h>

#include "bloom_mt.h"
#include "cam.h"
#include "harness.h"
#include "test_jpeg.h"

enum { W = 200, H = 60, PAD = 24, CANARY = 0xA5 };

static uint8_t cap_buf[H * (2 * W + PAD)], cap_rgb[H * (3 * W + PAD)], cap_grey[H * (W + PAD)];
static uint8_t rgb[H * 3 * W];
static uint16_t aux[H * W];

/* A capture of each format: a dim noise floor with a few bright blobs. */
static void make_captures(void)
{
    unsigned seed = 7;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            seed = seed * 1103515245u + 12345u;
            const int blob = (x % 67 - 30) * (x % 67 - 30) + (y - 25) * (y - 25) < 50;
            const int v = blob ? 240 : (int)(seed >> 16) % 90;
            uint8_t *p = cap_rgb + (size_t)y * (3 * W + PAD) + 3 * x;
            p[0] = (uint8_t)v;
            p[1] = (uint8_t)(blob ? 230 : (int)(seed >> 8) % 80);
            p[2] = (uint8_t)(blob ? 200 : (int)(seed >> 4) % 70);
            cap_grey[(size_t)y * (W + PAD) + x] = (uint8_t)v;
            uint8_t *q = cap_buf + (size_t)y * (2 * W + PAD) + 2 * x;
            q[0] = (uint8_t)(blob ? 235 : 16 + v / 3);
            q[1] = (uint8_t)(128 + (int)(seed >> 20) % 40 - 20);
            aux[y * W + x] = (uint16_t)(x * 65535 / (W - 1));
        }
}

static void set_cap(cam_v4l2_t *cap, uint32_t pixfmt)
{
    memset(cap, 0, sizeof *cap);
    cap->width = W;
    cap->height = H;
    cap->pixelformat = pixfmt;
    cap->bytesperline = pixfmt == V4L2_PIX_FMT_YUYV    ? 2 * W + PAD
                        : pixfmt == V4L2_PIX_FMT_RGB24 ? 3 * W + PAD
                                                       : W + PAD;
}

static const uint8_t *cap_data(uint32_t pixfmt)
{
    return pixfmt == V4L2_PIX_FMT_YUYV ? cap_buf : pixfmt == V4L2_PIX_FMT_RGB24 ? cap_rgb : cap_grey;
}

/* The capture as the row path feeds it: each row converted to RGB888. */
static void convert(const cam_v4l2_t *cap, const uint8_t *data)
{
    for (int y = 0; y < H; y++) {
        const uint8_t *s = data + (size_t)y * cap->bytesperline;
        uint8_t *d = rgb + (size_t)y * 3 * W;
        if (cap->pixelformat == V4L2_PIX_FMT_YUYV)
            cam_yuyv_row_to_rgb888(s, d, W);
        else if (cap->pixelformat == V4L2_PIX_FMT_GREY)
            cam_grey_row_to_rgb888(s, d, W);
        else
            memcpy(d, s, 3 * W);
    }
}

/* The untiled engine's frame for cfg, placed on page as p says. */
static int reference(const bloom_config_t *cfg, const cam_fb_t *fb, const cam_place_t *p, uint8_t *page)
{
    const size_t bpp = (size_t)fb->bpp;
    bloom_info_t info;
    if (bloom_query(cfg, &info) != BLOOM_OK)
        return -1;
    void *ws = malloc(info.workspace_bytes);
    uint8_t *out = malloc((size_t)W * H * bpp);
    bloom_t *b;
    int bad = !ws || !out || bloom_init(&b, ws, info.workspace_bytes, cfg) != BLOOM_OK ||
              (cfg->aux_fmt != BLOOM_AUX_NONE && bloom_set_aux(b, aux, W * 2) != BLOOM_OK) ||
              bloom_process(b, rgb, 3 * W, out, (ptrdiff_t)(W * bpp)) != BLOOM_OK;
    for (int y = 0; !bad && y < p->h; y++)
        memcpy(page + (size_t)(p->dst_y + y) * (size_t)fb->line_length + (size_t)p->dst_x * bpp,
               out + ((size_t)(p->src_y + y) * W + (size_t)p->src_x) * bpp, (size_t)p->w * bpp);
    free(ws);
    free(out);
    return bad ? -1 : 0;
}

static void set_fb(cam_fb_t *fb, bloom_format_t f, int xres, int yres)
{
    memset(fb, 0, sizeof *fb);
    fb->format = f;
    fb->bpp = bloom_format_bpp(f);
    fb->xres = xres;
    fb->yres = yres;
    fb->line_length = xres * fb->bpp + PAD;
    fb->mem_len = (size_t)fb->line_length * (size_t)yres;
}

/* The mode's configuration as make_engines builds it for the pool. */
static int mode_cfg(int mode, bloom_format_t out, bloom_config_t *cfg)
{
    bloom_config_default(cfg, W, H);
    cfg->in_fmt = BLOOM_FMT_RGB888;
    cfg->out_fmt = out;
    cfg->threshold = BLOOM_Q16(0.6);
    cfg->intensity = BLOOM_Q16(1.5);
    if (mode == 1)
        cfg->flags |= BLOOM_FLAG_DEBUG_VIEW;
    if (mode == 2) { /* off */
        cfg->threshold = BLOOM_MAX_THRESHOLD;
        cfg->soft_knee = 0;
        cfg->intensity = 0;
    }
    if (mode == 3) { /* a preset with a 16-bit plane */
        if (!bloom_preset_available(BLOOM_PRESET_ATTENUATION))
            return -1;
        bloom_config_preset(cfg, BLOOM_PRESET_ATTENUATION);
        cfg->aux_fmt = BLOOM_AUX_U16;
        cfg->in_fmt = BLOOM_FMT_RGB888;
        cfg->out_fmt = out;
    }
    return 0;
}

static void test_frames(void)
{
    static const uint32_t pix[] = {V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_RGB24, V4L2_PIX_FMT_GREY};
    static const bloom_format_t fbf[] = {BLOOM_FMT_RGB565, BLOOM_FMT_XRGB8888};
    static const int screen[][2] = {{W + 40, H + 10}, {W - 50, H - 20}, {W - 3, H + 4}, {W, H - 7}};
    static const char *const mode_name[] = {"bloom", "bloom-only", "off", "attenuation+aux"};
    int glow = 0, runs = 0;
    make_captures();
    for (size_t f = 0; f < sizeof pix / sizeof pix[0]; f++)
        for (size_t o = 0; o < sizeof fbf / sizeof fbf[0]; o++)
            for (size_t s = 0; s < sizeof screen / sizeof screen[0]; s++)
                for (int n = 2; n <= 4; n++) {
                    cam_v4l2_t cap;
                    cam_fb_t fb;
                    cam_place_t p;
                    cam_mt_t t;
                    memset(&t, 0, sizeof t);
                    set_cap(&cap, pix[f]);
                    set_fb(&fb, fbf[o], screen[s][0], screen[s][1]);
                    cam_place(W, H, fb.xres, fb.yres, &p);
                    uint8_t *page = malloc(fb.mem_len), *want = malloc(fb.mem_len);
                    CHECK(page && want && cam_mt_frames(&t, &cap, &fb, &p) == 0);
                    const int whole = s == 0;
                    CHECKF((t.out == NULL) == whole && (t.rgb == NULL) == (pix[f] == V4L2_PIX_FMT_RGB24),
                           "frame buffers: out %p rgb %p, screen %dx%d", (void *)t.out, (void *)t.rgb,
                           fb.xres, fb.yres);
                    bloom_config_t cfg[CAM_MODE_COUNT + 1];
                    int have[CAM_MODE_COUNT + 1];
                    for (int m = 0; m <= CAM_MODE_COUNT; m++) {
                        size_t bytes = 0;
                        have[m] = mode_cfg(m, fbf[o], &cfg[m]) == 0;
                        if (!have[m] || m == CAM_MODE_COUNT)
                            continue; /* cam_mt_t holds one pool per mode: the preset below */
                        CHECKF(cam_mt_mode(&t, (enum cam_mode)m, &cfg[m], n, NULL, 0, &bytes) == 0 &&
                                   bytes == bloom_mt_size(&cfg[m], n) && t.tiles == n,
                               "pool %d of %d threads: %zu bytes, %d tiles", m, n, bytes, t.tiles);
                    }
                    convert(&cap, cap_data(pix[f]));
                    for (int m = 0; m <= CAM_MODE_COUNT && page && want; m++) {
                        if (!have[m])
                            continue;
                        if (m == CAM_MODE_COUNT) { /* the aux plane through bloom_mt_set_aux */
                            size_t bytes;
                            bloom_mt_free(t.mt[0]);
                            free(t.buf[0]);
                            t.mt[0] = NULL;
                            t.buf[0] = NULL;
                            CHECK(cam_mt_mode(&t, CAM_MODE_BLOOM, &cfg[m], n, (const uint8_t *)aux, W * 2,
                                              &bytes) == 0);
                        }
                        memset(page, CANARY, fb.mem_len);
                        memset(want, CANARY, fb.mem_len);
                        const enum cam_mode em = m == CAM_MODE_COUNT ? CAM_MODE_BLOOM : (enum cam_mode)m;
                        CHECK(reference(&cfg[m], &fb, &p, want) == 0);
                        CHECK(t.mt[em] &&
                              cam_mt_process(&t, em, &cap, &(cam_frame_t){.data = cap_data(pix[f])}, &fb, &p,
                                             page) == 0);
                        CHECKF(!memcmp(page, want, fb.mem_len),
                               "%s capture, %s screen %dx%d (shown %dx%d from %d,%d), %s, %d threads: the "
                               "page differs from the untiled engine's",
                               pix[f] == V4L2_PIX_FMT_YUYV    ? "YUYV"
                               : pix[f] == V4L2_PIX_FMT_RGB24 ? "RGB24"
                                                              : "GREY",
                               fbf[o] == BLOOM_FMT_RGB565 ? "RGB565" : "XRGB8888", fb.xres, fb.yres, p.w, p.h,
                               p.src_x, p.src_y, mode_name[m], n);
                        for (size_t i = 0; m == 0 && i < fb.mem_len; i++)
                            glow |= page[i] != CANARY && page[i] != 0;
                        runs++;
                    }
                    cam_mt_close(&t);
                    CHECK(!t.mt[0] && !t.rgb && !t.out);
                    free(page);
                    free(want);
                }
    CHECKF(glow, "the test frames show nothing");
    printf("cam_mt: %d frames on 2..4 threads, each page = the untiled engine's, placed\n", runs);
}

/* cam_mt_mode with stderr captured into msg. */
static int mode_msg(cam_mt_t *t, const bloom_config_t *cfg, const uint8_t *plane, size_t *bytes, char *msg,
                    size_t len)
{
    FILE *tmp = tmpfile();
    int saved = dup(2);
    fflush(stderr);
    if (tmp)
        dup2(fileno(tmp), 2);
    const int r = cam_mt_mode(t, CAM_MODE_BLOOM_ONLY, cfg, 2, plane, W * 2, bytes);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    msg[0] = '\0';
    if (tmp) {
        rewind(tmp);
        msg[fread(msg, 1, len - 1, tmp)] = '\0';
        fclose(tmp);
    }
    return r;
}

/* A refusal names the call, the thread count, the preset and view, and the
 * status: a configuration the engine refuses, a plane it does not read. */
static void test_refused(void)
{
    bloom_config_t cfg;
    mode_cfg(1, BLOOM_FMT_RGB565, &cfg);
    cfg.levels = 0;
    cam_mt_t t;
    memset(&t, 0, sizeof t);
    char msg[512], want[256];
    size_t bytes = 1;
    int r = mode_msg(&t, &cfg, NULL, &bytes, msg, sizeof msg);
    snprintf(want, sizeof want, "bloom_cam: bloom_mt_size (2 threads, preset unity, bloom-only): %s",
             bloom_mt_status_str(bloom_query(&cfg, &(bloom_info_t){0})));
    CHECKF(r == -1 && bytes == 0 && !t.mt[CAM_MODE_BLOOM_ONLY] && strstr(msg, want), "got %d '%s', want '%s'",
           r, msg, want);
    mode_cfg(1, BLOOM_FMT_RGB565, &cfg); /* unity reads no plane */
    r = mode_msg(&t, &cfg, (const uint8_t *)aux, &bytes, msg, sizeof msg);
    snprintf(want, sizeof want, "bloom_cam: bloom_mt_set_aux (2 threads, preset unity, bloom-only): %s",
             bloom_mt_status_str(BLOOM_E_AUX));
    CHECKF(r == -1 && strstr(msg, want), "got %d '%s', want '%s'", r, msg, want);
    CHECKF(!strcmp(bloom_mt_status_str(BLOOM_MT_E_THREAD),
                   "a pool thread could not be created (pthread_create)"),
           "BLOOM_MT_E_THREAD: %s", bloom_mt_status_str(BLOOM_MT_E_THREAD));
    cam_mt_close(&t); /* joins the pool the plane was refused by */
}

/* cap_rgb as a camera's MJPEG frame (libjpeg, 4:2:0, quality 90); *out
 * malloc'd. */
static size_t encode_mjpeg(unsigned char **out)
{
    return test_jpeg_encode(cap_rgb, W, H, 3 * W + PAD, 90, 2, 0, out);
}

/* MJPEG on threads: decoded into the RGB888 frame, then the strips; equal
 * to the untiled engine on the decoded frame. A frame cut short returns 2
 * and leaves the page as it was (nothing drawn); the next is drawn. */
static void test_mjpeg(void)
{
    cam_v4l2_t cap;
    cam_fb_t fb;
    cam_place_t p;
    cam_mt_t t;
    bloom_config_t cfg;
    size_t bytes;
    memset(&t, 0, sizeof t);
    memset(&cap, 0, sizeof cap);
    cap.width = W;
    cap.height = H;
    cap.pixelformat = V4L2_PIX_FMT_MJPEG;
    CHECK(cam_mjpeg_open(&cap.jpeg, W, H) == 0);
    set_fb(&fb, BLOOM_FMT_XRGB8888, W, H);
    cam_place(W, H, fb.xres, fb.yres, &p);
    mode_cfg(0, BLOOM_FMT_XRGB8888, &cfg);
    uint8_t *page = malloc(fb.mem_len), *want = malloc(fb.mem_len);
    unsigned char *jpg;
    const size_t len = encode_mjpeg(&jpg);
    CHECK(page && want && cam_mt_frames(&t, &cap, &fb, &p) == 0 && t.rgb &&
          cam_mt_mode(&t, CAM_MODE_BLOOM, &cfg, 2, NULL, 0, &bytes) == 0);
    /* the reference's input: the same JPEG decoded row by row into rgb */
    CHECK(cam_mjpeg_begin(cap.jpeg, jpg, len) == 0);
    for (int y = 0; y < H; y++)
        CHECK(cam_mjpeg_row(cap.jpeg, rgb + (size_t)y * 3 * W) == 0);
    CHECK(cam_mjpeg_end(cap.jpeg) == 0);
    memset(want, CANARY, fb.mem_len);
    CHECK(reference(&cfg, &fb, &p, want) == 0);
    cam_frame_t cut = {.data = jpg, .len = len / 2}, whole = {.data = jpg, .len = len};
    for (int k = 0; k < 2 && page && want; k++) {
        memset(page, CANARY, fb.mem_len);
        const int r = cam_mt_process(&t, CAM_MODE_BLOOM, &cap, &cut, &fb, &p, page);
        size_t drawn = 0;
        for (size_t i = 0; i < fb.mem_len; i++)
            drawn += page[i] != CANARY;
        CHECKF(r == 2 && drawn == 0, "MJPEG cut at %zu of %zu bytes on 2 threads: %d, %zu bytes drawn",
               len / 2, len, r, drawn);
        CHECKF(
            cam_mt_process(&t, CAM_MODE_BLOOM, &cap, &whole, &fb, &p, page) == 0 &&
                !memcmp(page, want, fb.mem_len),
            "MJPEG on 2 threads (round %d): the page differs from the untiled engine's on the decoded frame",
            k);
    }
    free(jpg);
    free(page);
    free(want);
    cam_mt_close(&t);
    cam_mjpeg_close(cap.jpeg);
}

int main(void)
{
    test_frames();
    test_refused();
    test_mjpeg();
    printf("bloom_cam --threads: whole frames on the pool (cam_mt.c) against the untiled engine\n");
    return harness_finish();
}
