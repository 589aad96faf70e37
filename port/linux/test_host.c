/* bloom_cam host tests: the parts that need no device. Option parsing,
 * YUYV/GREY row conversion (bit-identical to the simulator's rule, within one
 * code of the real BT.601 formula), the framebuffer layout check, the
 * placement arithmetic, and the line-buffer feed (one converted row at a
 * time, BLOOM_FLAG_COPY_SOURCE) against a whole converted frame, the
 * button's debounce; test_conv.c (the capture formats) and test_dequeue.c
 * (the capture faults) add their checks to the closing line. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <linux/videodev2.h>

#include "cam.h"
#include "harness.h"
#include "sim.h"

static int parse(cam_opts_t *o, char *err, const char *a0, const char *a1, const char *a2, const char *a3)
{
    char *argv[6] = {(char *)"bloom_cam", (char *)a0, (char *)a1, (char *)a2, (char *)a3, NULL};
    int argc = 1;
    while (argc < 5 && argv[argc])
        argc++;
    err[0] = '\0';
    return cam_parse_opts(o, argc, argv, err, 256);
}

static void test_opts(void)
{
    cam_opts_t o;
    char err[256];
    CHECKF(parse(&o, err, NULL, NULL, NULL, NULL) == 0, "no options: %s", err);
    CHECKF(!strcmp(o.device, "/dev/video0") && !strcmp(o.fb, "/dev/fb0") && o.width == 640 &&
               o.height == 480 && o.format == CAM_FMT_AUTO && o.fps == 0 && o.levels == 5 &&
               o.threshold == BLOOM_Q16(1.0) && o.knee == BLOOM_Q16(0.5) && o.intensity == BLOOM_Q16(1.0) &&
               o.frames == 0 && o.buffers == 4 && o.mode == CAM_MODE_BLOOM && !o.stats && !o.record &&
               o.threads == 0 && o.reconnect_s == 30 && o.latest == 1 && o.debounce_ms == 30,
           "defaults");
    CHECKF(parse(&o, err, "--reconnect", "off", "--latest=off", NULL) == 0 && o.reconnect_s == 0 && !o.latest,
           "--reconnect off --latest off: %s", err);
    CHECKF(parse(&o, err, "--reconnect=5", "--debounce", "0", NULL) == 0 && o.reconnect_s == 5 &&
               o.debounce_ms == 0,
           "--reconnect 5 --debounce 0: %s", err);

    char *argv[] = {"bloom_cam",
                    "--device",
                    "/dev/video3",
                    "--fb=/dev/fb1",
                    "--size",
                    "320x240",
                    "--format=rgb24",
                    "--levels",
                    "3",
                    "--threshold=0.8",
                    "--knee",
                    "0.25",
                    "--intensity",
                    "1.5",
                    "--frames",
                    "10",
                    "--stats",
                    "--record",
                    "out.raw",
                    "--mode=bloom-only",
                    "--buffers",
                    "3",
                    "--timeout=500",
                    "-q",
                    NULL};
    int argc = (int)(sizeof argv / sizeof argv[0]) - 1;
    int r = cam_parse_opts(&o, argc, argv, err, sizeof err);
    CHECKF(r == 0, "full command line: %s", err);
    CHECKF(!strcmp(o.device, "/dev/video3") && !strcmp(o.fb, "/dev/fb1") && o.width == 320 &&
               o.height == 240 && o.format == CAM_FMT_RGB24 && o.levels == 3 &&
               o.threshold == BLOOM_Q16(0.8) && o.knee == BLOOM_Q16(0.25) && o.intensity == BLOOM_Q16(1.5) &&
               o.frames == 10 && o.stats && !strcmp(o.record, "out.raw") && o.mode == CAM_MODE_BLOOM_ONLY &&
               o.buffers == 3 && o.timeout_ms == 500 && o.quiet,
           "full command line values");
    CHECKF(parse(&o, err, "--format", "grey", NULL, NULL) == 0 && o.format == CAM_FMT_GREY, "grey");
    CHECKF(parse(&o, err, "--help", NULL, NULL, NULL) == 1, "help");
    static const char *const thr[] = {"0", "1", "3", "64"};
    for (int k = 0; k < 4; k++) /* 0: the online CPUs, resolved when the capture size is known */
        CHECKF(parse(&o, err, "--threads", thr[k], NULL, NULL) == 0 && o.threads == atoi(thr[k]),
               "--threads %s: %s", thr[k], err);
    CHECKF(parse(&o, err, "--threads=2", "--format", "grey", NULL) == 0 && o.threads == 2, "--threads=2");
    CHECKF(parse(&o, err, NULL, NULL, NULL, NULL) == 0 && o.sample_bits == 32, "sample bits: 32 by default");
    bloom_config_t sc;
    CHECKF(parse(&o, err, "--sample-bits", "16", NULL, NULL) == 0 && o.sample_bits == 16,
           "--sample-bits 16: %s", err);
    cam_opts_config(&o, 64, 48, &sc);
    CHECK(sc.sample_bits == 16 && bloom_query(&sc, NULL) == BLOOM_OK);

    static const struct {
        const char *a0, *a1, *a2, *a3, *msg;
    } bad[] = {
        {"--format", "h264", NULL, NULL, "'h264' is not auto, rgb24, yuyv, uyvy"},
        {"--size", "641x480", "--format", "uyvy", "uyvy needs an even width, not 641"},
        {"--fps", "0", NULL, NULL, "--fps: '0' is not 1..1000"},
        {"--size", "640", NULL, NULL, "--size: '640' is not WxH"},
        {"--size", "0x0", NULL, NULL, "--size: '0x0'"},
        {"--levels", "0", NULL, NULL, "--levels: '0' is not 1..16"},
        {"--levels", "17", NULL, NULL, "--levels"},
        {"--sample-bits", "24", NULL, NULL, "--sample-bits: '24' is not 16 or 32"},
        {"--sample-bits", "16", "--preset", "cod", "sample_bits must be 16 or 32"},
        {"--threshold", "300", NULL, NULL, "--threshold: '300' is not 0..256"},
        {"--knee", "1.5", NULL, NULL, "--knee"},
        {"--intensity", "-1", NULL, NULL, "--intensity"},
        {"--intensity", "nan", NULL, NULL, "--intensity"},
        {"--buffers", "1", NULL, NULL, "--buffers: '1' is not 2..16"},
        {"--threads", "65", NULL, NULL, "--threads: '65' is not 0..64 (0: the online CPUs)"},
        {"--threads", "-1", NULL, NULL, "--threads: '-1' is not 0..64"},
        {"--threads", "two", NULL, NULL, "--threads: 'two' is not 0..64"},
        {"--threads", "2.5", NULL, NULL, "--threads: '2.5' is not 0..64"},
        {"--threads=", NULL, NULL, NULL, "--threads: '' is not 0..64"},
        {"--threads", NULL, NULL, NULL, "--threads needs a value"},
        {"--frames", "x", NULL, NULL, "--frames"},
        {"--reconnect", "soon", NULL, NULL, "--reconnect: 'soon' is not off, on or 1..31536000 seconds"},
        {"--reconnect", "0", NULL, NULL, "--reconnect: '0'"},
        {"--latest", "yes", NULL, NULL, "--latest: 'yes' is not on or off"},
        {"--debounce", "-5", NULL, NULL, "--debounce: '-5' is not 0..10000 ms"},
        {"--mode", "glow", NULL, NULL, "--mode"},
        {"--device", NULL, NULL, NULL, "--device needs a value"},
        {"--bogus", NULL, NULL, NULL, "unknown option '--bogus'"},
        {"--gpio-frame", "gpiochip0", NULL, NULL, "is not CHIP:LINE"},
        {"--gpio-frame", "gpiochip0:3", NULL, NULL, "built without libgpiod"},
        {"--gpio-button=gpiochip1:BTN", NULL, NULL, NULL, "built without libgpiod"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        r = parse(&o, err, bad[i].a0, bad[i].a1, bad[i].a2, bad[i].a3);
        CHECKF(r == -1 && strstr(err, bad[i].msg), "%s %s: got %d '%s', want '%s'", bad[i].a0,
               bad[i].a1 ? bad[i].a1 : "", r, err, bad[i].msg);
    }
    CHECKF(parse(&o, err, "--size", "641x480", "--format", "rgb24") == 0 && o.width == 641,
           "odd width for rgb24");
}

static void test_yuv(void)
{
    /* Every Y'CbCr triple: equal to the simulator's rule, and within one
     * code of the real limited-range BT.601 formula. */
    long mism = 0, far = 0;
    for (int y = 0; y < 256; y++)
        for (int cb = 0; cb < 256; cb++)
            for (int cr = 0; cr < 256; cr++) {
                uint8_t a[3];
                uint32_t s[3];
                cam_ycbcr_to_rgb(y, cb, cr, a);
                sim_ycbcr_to_rgb(y, cb, cr, 0, s);
                mism += a[0] != s[0] || a[1] != s[1] || a[2] != s[2];
                if (((y ^ cb ^ cr) & 7) == 0) {
                    const double yy = (y - 16) * 255.0 / 219.0, u = (cb - 128) * 255.0 / 224.0,
                                 v = (cr - 128) * 255.0 / 224.0;
                    const double rf[3] = {yy + 1.402 * v,
                                          yy - 0.114 * 1.772 / 0.587 * u - 0.299 * 1.402 / 0.587 * v,
                                          yy + 1.772 * u};
                    for (int c = 0; c < 3; c++) {
                        double e = rf[c] < 0 ? 0 : rf[c] > 255 ? 255 : rf[c];
                        far += fabs(a[c] - e) > 1.0;
                    }
                }
            }
    CHECKF(mism == 0, "%ld Y'CbCr triples differ from sim_ycbcr_to_rgb", mism);
    CHECKF(far == 0, "%ld channels more than one code from the BT.601 formula", far);

    enum { W = 38 };
    uint8_t yuyv[2 * W], rgb[3 * W + 3], grey[W];
    unsigned seed = 12345;
    for (int i = 0; i < 2 * W; i++) {
        seed = seed * 1103515245u + 12345u;
        yuyv[i] = (uint8_t)(seed >> 16);
    }
    memcpy(grey, yuyv, W);
    rgb[3 * W] = 0xA5;
    cam_yuyv_row_to_rgb888(yuyv, rgb, W);
    int bad = 0;
    for (int x = 0; x < W; x++) {
        uint8_t e[3];
        const uint8_t *p = yuyv + (x / 2) * 4;
        cam_ycbcr_to_rgb(p[(x & 1) * 2], p[1], p[3], e);
        bad += memcmp(e, rgb + 3 * x, 3) != 0;
    }
    CHECKF(bad == 0 && rgb[3 * W] == 0xA5, "YUYV row: %d pixels wrong or overrun", bad);
    cam_grey_row_to_rgb888(grey, rgb, W);
    bad = 0;
    for (int x = 0; x < W; x++)
        bad += rgb[3 * x] != grey[x] || rgb[3 * x + 1] != grey[x] || rgb[3 * x + 2] != grey[x];
    CHECKF(bad == 0 && rgb[3 * W] == 0xA5, "GREY row: %d pixels wrong or overrun", bad);
}

static void test_fb_format(void)
{
    static const struct {
        cam_fb_layout_t l;
        bloom_format_t want;
        const char *why;
    } t[] = {
        {{16, 0, 0, 11, 5, 5, 6, 0, 5}, BLOOM_FMT_RGB565, ""},
        {{32, 0, 0, 16, 8, 8, 8, 0, 8}, BLOOM_FMT_XRGB8888, ""},
        {{16, 0, 0, 0, 5, 5, 6, 11, 5}, (bloom_format_t)0, "16 bpp BGR565"},
        {{16, 0, 0, 10, 5, 5, 5, 0, 5}, (bloom_format_t)0, "16 bpp RGB555"},
        {{32, 0, 0, 0, 8, 8, 8, 16, 8}, (bloom_format_t)0, "32 bpp XBGR8888"},
        {{32, 0, 0, 24, 8, 16, 8, 8, 8}, (bloom_format_t)0, "32 bpp R24:8 G16:8 B8:8"},
        {{24, 0, 0, 16, 8, 8, 8, 0, 8}, (bloom_format_t)0, "24 bpp"},
        {{8, 0, 0, 0, 8, 0, 8, 0, 8}, (bloom_format_t)0, "8 bpp"},
        {{8, 1, 0, 0, 8, 0, 8, 0, 8}, (bloom_format_t)0, "8 bpp greyscale"},
        {{16, 0, 1, 11, 5, 5, 6, 0, 5}, (bloom_format_t)0, "non-standard pixel format 1"},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        char why[64] = "";
        bloom_format_t f = cam_fb_format(&t[i].l, why, sizeof why);
        CHECKF(f == t[i].want && (f || !strcmp(why, t[i].why)), "layout %zu: format %d '%s'", i, (int)f, why);
    }
}

static void test_place(void)
{
    static const struct {
        int fw, fh, sw, sh;
        cam_place_t want;
    } t[] = {
        {640, 480, 640, 480, {0, 0, 0, 0, 640, 480}},      {640, 480, 800, 600, {80, 60, 0, 0, 640, 480}},
        {320, 240, 1024, 768, {352, 264, 0, 0, 320, 240}}, {641, 481, 800, 600, {79, 59, 0, 0, 641, 481}},
        {1280, 720, 640, 480, {0, 0, 320, 120, 640, 480}}, {1280, 240, 640, 480, {0, 120, 320, 0, 640, 240}},
        {320, 720, 640, 480, {160, 0, 0, 120, 320, 480}},  {641, 480, 640, 480, {0, 0, 0, 0, 640, 480}},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        cam_place_t p;
        cam_place(t[i].fw, t[i].fh, t[i].sw, t[i].sh, &p);
        CHECKF(!memcmp(&p, &t[i].want, sizeof p), "%dx%d on %dx%d: dst %d,%d src %d,%d size %dx%d", t[i].fw,
               t[i].fh, t[i].sw, t[i].sh, p.dst_x, p.dst_y, p.src_x, p.src_y, p.w, p.h);
    }
}

/* The camera tool's YUYV path: one converted row in a line buffer at a time,
 * the engine copying what it keeps, must equal the whole frame converted
 * first and run through bloom_process (pointer mode). */
static void test_line_feed(void)
{
    enum { W = 96, H = 72 };
    static uint8_t yuyv[H][2 * W], rgb[H][3 * W], line[3 * W];
    static uint16_t out_a[H][W], out_b[H][W];
    unsigned seed = 99;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < 2 * W; x++) {
            seed = seed * 1103515245u + 12345u;
            int v = (int)(seed >> 16) & 255;
            if ((x & 1) == 0) /* luma: a few bright spots */
                v = ((x / 2 - 30) * (x / 2 - 30) + (y - 20) * (y - 20) < 60) ? 235 : v / 3;
            yuyv[y][x] = (uint8_t)v;
        }
    for (int y = 0; y < H; y++)
        cam_yuyv_row_to_rgb888(yuyv[y], rgb[y], W);

    bloom_config_t cfg;
    bloom_config_default(&cfg, W, H);
    cfg.out_fmt = BLOOM_FMT_RGB565;
    cfg.threshold = BLOOM_Q16(0.6);
    size_t n1 = bloom_workspace_size(&cfg);
    void *ws1 = aligned_alloc(64, (n1 + 63) / 64 * 64);
    bloom_t *b1;
    CHECKF(bloom_init(&b1, ws1, n1, &cfg) == BLOOM_OK, "init pointer mode");
    CHECKF(bloom_process(b1, rgb, sizeof rgb[0], out_a, sizeof out_a[0]) == BLOOM_OK, "process");

    cfg.flags |= BLOOM_FLAG_COPY_SOURCE;
    size_t n2 = bloom_workspace_size(&cfg);
    void *ws2 = aligned_alloc(64, (n2 + 63) / 64 * 64);
    bloom_t *b2;
    CHECKF(bloom_init(&b2, ws2, n2, &cfg) == BLOOM_OK, "init copy mode");
    int bad = bloom_begin(b2) != BLOOM_OK;
    for (int y = 0; y < H; y++) {
        cam_yuyv_row_to_rgb888(yuyv[y], line, W);
        memset(rgb[y], 0, sizeof rgb[y]); /* nothing may read the frame copy */
        bad |= bloom_push_row(b2, line) != BLOOM_OK;
        memset(line, 0x5A, sizeof line); /* nor the line buffer after the push */
        while (bloom_pull_row(b2, out_b[bloom_rows_out(b2)]) == BLOOM_OK)
            ;
    }
    while (bloom_pull_row(b2, out_b[bloom_rows_out(b2)]) == BLOOM_OK)
        ;
    CHECKF(!bad && bloom_rows_out(b2) == H, "line feed ran");
    CHECKF(!memcmp(out_a, out_b, sizeof out_a), "line-buffer feed differs from the whole frame");
    int glow = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            glow |= out_a[y][x] != 0;
    CHECKF(glow, "the test frame is all black");
    free(ws1);
    free(ws2);
}

/* The button's debounce: the first edge counts, then one at least MS after
 * the last counted; 0 counts every edge. */
static void test_debounce(void)
{
    int64_t last = INT64_MIN;
    const int64_t ms = 1000000;
    int got = cam_debounce(&last, 5 * ms, 30);
    got += cam_debounce(&last, 6 * ms, 30);  /* bounce */
    got += cam_debounce(&last, 34 * ms, 30); /* 29 ms after the press: still a bounce */
    got += cam_debounce(&last, 35 * ms, 30); /* 30 ms: a press */
    got += cam_debounce(&last, 90 * ms, 30);
    CHECKF(got == 3 && last == 90 * ms, "debounce 30 ms: %d presses (3 expected)", got);
    last = INT64_MIN;
    got = cam_debounce(&last, 1, 0) + cam_debounce(&last, 1, 0) + cam_debounce(&last, 2, 0);
    CHECKF(got == 3, "debounce 0: %d presses of 3 edges", got);
}

/* --preset and its options: the preset's defaults, then the options given;
 * unknown and compiled-out names refused with the list of what this build
 * has; options of another preset refused; a preset that needs its plane
 * refused without --aux; the --aux PGM reader (8/16-bit, rescaled maxval,
 * wrong size, not a PGM). */
static void test_presets(void)
{
    cam_opts_t o;
    char err[256];
    CHECKF(parse(&o, err, "--preset", "unity", NULL, NULL) == 0 && o.preset == BLOOM_PRESET_UNITY &&
               o.levels == 5 && o.threshold == BLOOM_Q16(1.0) && o.aux_fmt == BLOOM_AUX_NONE,
           "--preset unity: %s", err);
    CHECKF(parse(&o, err, "--preset", "bogus", NULL, NULL) == -1 &&
               strstr(err, "--preset: unknown preset 'bogus' (this build has: unity"),
           "unknown preset: '%s'", err);
    CHECKF(parse(&o, err, "--preset=", NULL, NULL, NULL) == -1 && strstr(err, "unknown preset ''"),
           "empty preset: '%s'", err);
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        const char *name = bloom_preset_name((bloom_preset_t)p);
        int r = parse(&o, err, "--preset", name, NULL, NULL);
        if (!bloom_preset_available((bloom_preset_t)p)) {
            CHECKF(r == -1 && strstr(err, "compiled out") && strstr(err, "this build has: unity"),
                   "compiled-out %s: '%s'", name, err);
            continue;
        }
        /* available: runs as it is, or says which plane it lacks */
        bloom_config_t d; /* at the default --size: some defaults depend on the size */
        bloom_config_default(&d, 640, 480);
        bloom_config_preset(&d, (bloom_preset_t)p);
        CHECKF(r == 0 || (strstr(err, bloom_status_str(BLOOM_E_AUX)) && strstr(err, "--aux FILE")),
               "--preset %s: %d '%s'", name, r, err);
        if (r == 0) {
            CHECKF(o.preset == (bloom_preset_t)p && o.levels == d.levels && o.threshold == d.threshold &&
                       o.intensity == d.intensity && !memcmp(&o.params, &d.p, sizeof d.p),
                   "--preset %s takes the preset's defaults", name);
            /* at run time, the defaults of the capture's own size */
            bloom_config_t c, e;
            bloom_config_default(&e, 40, 6);
            bloom_config_preset(&e, (bloom_preset_t)p);
            cam_opts_config(&o, 40, 6, &c);
            CHECKF(c.preset == e.preset && !memcmp(&c.p, &e.p, sizeof e.p) && c.flags == e.flags,
                   "--preset %s: the configuration for a 40x6 capture", name);
        }
    }
    CHECKF(parse(&o, err, "--passes", "3", NULL, NULL) == -1 &&
               strstr(err, "--passes applies to the xna preset, not unity"),
           "option of another preset: '%s'", err);
    CHECKF(parse(&o, err, "--aux", "d.pgm", NULL, NULL) == -1 && strstr(err, "--aux applies to"),
           "--aux with unity: '%s'", err);
    CHECKF(parse(&o, err, "--tint", "1,2,3", "--preset", "cod") == -1, "bad tint");
#if BLOOM_USE_ARM
    CHECKF(parse(&o, err, "--preset", "arm", "--baked", NULL) == -1 &&
               strstr(err, bloom_status_str(BLOOM_E_AUX)) && strstr(err, "baked bloom map with --aux FILE"),
           "arm --baked without --aux: '%s'", err);
    CHECKF(parse(&o, err, "--preset", "arm", "--aux", "mask.pgm") == 0 && o.aux_fmt == BLOOM_AUX_U8,
           "arm with a mask: '%s'", err);
    CHECKF(parse(&o, err, "--preset", "arm", NULL, NULL) == 0 && o.aux_fmt == BLOOM_AUX_NONE,
           "arm without a mask: '%s'", err);
#endif
#if BLOOM_USE_ATTENUATION
    CHECKF(parse(&o, err, "--preset", "attenuation", NULL, NULL) == -1 &&
               strstr(err, bloom_status_str(BLOOM_E_AUX)) && strstr(err, "depth plane with --aux FILE"),
           "attenuation without --aux: '%s'", err);
    {
        char *argv[] = {"bloom_cam", "--attenuation", "0.5",         "--preset", "attenuation",
                        "--aux",     "depth.pgm",     "--threshold", "0.7",      "--max-reduction=0.125",
                        NULL};
        CHECKF(cam_parse_opts(&o, 10, argv, err, sizeof err) == 0 && o.preset == BLOOM_PRESET_ATTENUATION &&
                   o.params.attenuation == BLOOM_Q16(0.5) && o.params.max_reduction == BLOOM_Q16(0.125) &&
                   o.threshold == BLOOM_Q16(0.7) && !strcmp(o.aux, "depth.pgm") && o.aux_fmt == BLOOM_AUX_U8,
               "attenuation options in any order: '%s'", err);
        bloom_config_t c;
        cam_opts_config(&o, 64, 48, &c);
        CHECK(c.preset == BLOOM_PRESET_ATTENUATION && c.p.attenuation == BLOOM_Q16(0.5) &&
              c.p.max_reduction == BLOOM_Q16(0.125) && c.threshold == BLOOM_Q16(0.7) &&
              c.aux_fmt == BLOOM_AUX_U8);
    }
#endif

    /* the PGM reader */
    char dir[] = "/tmp/bloom_cam_auxXXXXXX", path[64];
    CHECK(mkdtemp(dir) != NULL);
    static const struct {
        const char *name, *data;
        size_t len;
        int w, h;
        const char *err; /* NULL: loads */
        bloom_aux_format_t fmt;
        uint8_t s0, s1;
    } files[] = {
        {"a8.pgm", "P5\n2 1\n255\n\x00\xff", 13, 2, 1, NULL, BLOOM_AUX_U8, 0, 255},
        {"a4.pgm", "P5 # comment\n2 1 15\n\x0f\x07", 22, 2, 1, NULL, BLOOM_AUX_U8, 255, 119},
        {"a16.pgm", "P5\n1 1\n65535\n\x12\x34", 15, 1, 1, NULL, BLOOM_AUX_U16, 0x34, 0x12},
        {"size.pgm", "P5\n2 1\n255\n\x00\xff", 13, 4, 3, "the plane is 2x1 but the capture is 4x3",
         BLOOM_AUX_U8, 0, 0},
        {"ppm.ppm", "P6\n1 1\n255\nabc", 14, 1, 1, "not a binary PGM", BLOOM_AUX_U8, 0, 0},
        {"short.pgm", "P5\n2 2\n255\nab", 13, 2, 2, "truncated", BLOOM_AUX_U8, 0, 0},
        {"over.pgm", "P5\n1 1\n9\n\x0a", 10, 1, 1, "above maxval", BLOOM_AUX_U8, 0, 0},
    };
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, files[i].name);
        FILE *f = fopen(path, "wb");
        size_t len = files[i].len;
        CHECK(f && fwrite(files[i].data, 1, len, f) == len);
        if (f)
            fclose(f);
        bloom_aux_format_t fmt = BLOOM_AUX_NONE;
        uint8_t *data = NULL;
        int r = cam_aux_load(path, files[i].w, files[i].h, &fmt, &data, err, sizeof err);
        if (files[i].err)
            CHECKF(r == -1 && !data && strstr(err, path) && strstr(err, files[i].err), "%s: %d '%s'",
                   files[i].name, r, err);
        else
            CHECKF(r == 0 && data && fmt == files[i].fmt && data[0] == files[i].s0 && data[1] == files[i].s1,
                   "%s: %d '%s' %d %d", files[i].name, r, err, data ? data[0] : -1, data ? data[1] : -1);
        free(data);
        remove(path);
    }
    uint8_t *none = NULL;
    bloom_aux_format_t nf;
    CHECK(cam_aux_load("/nonexistent/d.pgm", 1, 1, &nf, &none, err, sizeof err) == -1 &&
          strstr(err, "--aux /nonexistent/d.pgm: No such file") != NULL);
    rmdir(dir);
}

void test_conv(int *pass, int *fail);    /* test_conv.c: the capture formats */
void test_dequeue(int *pass, int *fail); /* test_dequeue.c: the capture faults */

int main(void)
{
    test_opts();
    test_presets();
    test_yuv();
    test_fb_format();
    test_place();
    test_line_feed();
    test_debounce();
    test_dequeue(&harness_pass, &harness_fail);
    test_conv(&harness_pass, &harness_fail);
    printf("bloom_cam host tests: options, presets and --aux, Y'CbCr rows, framebuffer layouts, placement, "
           "line feed,\n"
           "  capture faults (EINTR, EAGAIN, ENODEV, timeout, a source change: fatal, with their kind; short "
           "bytesused,\n"
           "  V4L2_BUF_FLAG_ERROR: requeued and counted), --latest, the button's debounce;\n"
           "  test_conv.c: every capture format and Y'CbCr rule against bloom_sim's reader, --format auto\n");
    return harness_finish();
}
