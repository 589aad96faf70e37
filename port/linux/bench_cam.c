/* make bench-cam: bloom_cam's two frame paths on this machine, no device.
 * A YUYV frame to an XRGB8888 page (the screen larger: straight to the
 * page) row by row as main.c feeds it (one converted row in a line buffer,
 * BLOOM_FLAG_COPY_SOURCE, rows pulled into the page), against cam_mt.c's
 * whole frame on N threads (conversion, bloom_mt_process). Paired rounds:
 * each round times one frame of each path, the order alternating; the
 * speed-up is the median of the rounds' own ratios, so a busy moment of the
 * machine hits both sides of its round. Usage: bench_cam [WxH ...] [-t N] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <linux/videodev2.h>

#include "bloom_mt.h"
#include "cam.h"
#include "timing.h"

enum { ROUNDS = 41 };

static uint8_t *row_at(const cam_fb_t *fb, const cam_place_t *p, uint8_t *page, int r)
{
    return page + (size_t)(p->dst_y + r) * (size_t)fb->line_length + (size_t)p->dst_x * (size_t)fb->bpp;
}

/* main.c's process() for YUYV, whole screen shown. */
static void row_path(bloom_t *b, const cam_v4l2_t *cap, const uint8_t *yuyv, uint8_t *line,
                     const cam_fb_t *fb, const cam_place_t *p, uint8_t *page)
{
    bloom_begin(b);
    for (int y = 0; y < cap->height; y++) {
        cam_yuyv_row_to_rgb888(yuyv + (size_t)y * cap->bytesperline, line, cap->width);
        bloom_push_row(b, line);
        while (bloom_pull_row(b, row_at(fb, p, page, bloom_rows_out(b))) == BLOOM_OK)
            ;
    }
    while (bloom_pull_row(b, row_at(fb, p, page, bloom_rows_out(b))) == BLOOM_OK)
        ;
}

static int bench(int w, int h, int n)
{
    cam_v4l2_t cap;
    memset(&cap, 0, sizeof cap);
    cap.width = w;
    cap.height = h;
    cap.pixelformat = V4L2_PIX_FMT_YUYV;
    cap.bytesperline = (uint32_t)(2 * w);
    cam_fb_t fb;
    memset(&fb, 0, sizeof fb);
    fb.xres = w + 64;
    fb.yres = h + 64;
    fb.bpp = 4;
    fb.line_length = 4 * fb.xres;
    fb.format = BLOOM_FMT_XRGB8888;
    cam_place_t p;
    cam_place(w, h, fb.xres, fb.yres, &p);
    uint8_t *yuyv = malloc((size_t)cap.bytesperline * (size_t)h), *line = malloc((size_t)w * 3),
            *page = calloc(1, (size_t)fb.line_length * (size_t)fb.yres);
    bloom_config_t cfg, rcfg;
    bloom_config_default(&cfg, w, h);
    cfg.in_fmt = BLOOM_FMT_RGB888;
    cfg.out_fmt = BLOOM_FMT_XRGB8888;
    cfg.threshold = BLOOM_Q16(0.6);
    rcfg = cfg;
    rcfg.flags |= BLOOM_FLAG_COPY_SOURCE;
    const size_t rbytes = bloom_workspace_size(&rcfg);
    void *ws = malloc(rbytes);
    bloom_t *b;
    cam_mt_t t;
    memset(&t, 0, sizeof t);
    size_t mbytes = 0;
    int bad = !yuyv || !line || !page || !ws || bloom_init(&b, ws, rbytes, &rcfg) != BLOOM_OK ||
              cam_mt_frames(&t, &cap, &fb, &p) || cam_mt_mode(&t, CAM_MODE_BLOOM, &cfg, n, NULL, 0, &mbytes);
    double row[ROUNDS], mt[ROUNDS], ratio[ROUNDS];
    for (int y = 0; !bad && y < h; y++) /* dim noise, a grid of bright squares */
        for (int x = 0; x < w; x++) {
            uint8_t *q = yuyv + (size_t)y * cap.bytesperline + 2 * (size_t)x;
            const unsigned hash = ((unsigned)x * 2654435761u) ^ ((unsigned)y * 40503u);
            q[0] = (uint8_t)(x % 97 < 12 && y % 89 < 12 ? 235 : 16 + (hash >> 24) % 80);
            q[1] = (uint8_t)(108 + (hash >> 16) % 40);
        }
    for (int r = 0; !bad && r < ROUNDS; r++) {
        for (int k = 0; k < 2; k++) {
            const int threaded = (k + r) & 1;
            const double t0 = bench_now_s();
            if (threaded)
                bad |= cam_mt_process(&t, CAM_MODE_BLOOM, &cap, &(cam_frame_t){.data = yuyv}, &fb, &p, page);
            else
                row_path(b, &cap, yuyv, line, &fb, &p, page);
            *(threaded ? &mt[r] : &row[r]) = bench_now_s() - t0;
        }
        ratio[r] = row[r] / mt[r];
    }
    if (!bad) {
        qsort(row, ROUNDS, sizeof row[0], bench_cmp_double);
        qsort(mt, ROUNDS, sizeof mt[0], bench_cmp_double);
        qsort(ratio, ROUNDS, sizeof ratio[0], bench_cmp_double);
        printf("| %dx%d | %.2f | %.2f (%d threads) | %.2fx | %zu | %zu + %zu |\n", w, h,
               row[ROUNDS / 2] * 1e3, mt[ROUNDS / 2] * 1e3, t.tiles, ratio[ROUNDS / 2], rbytes, mbytes,
               t.frame_bytes);
    }
    cam_mt_close(&t);
    free(ws);
    free(yuyv);
    free(line);
    free(page);
    return bad ? -1 : 0;
}

int main(int argc, char **argv)
{
    int n = 0, sizes = 0, bad = 0;
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], "-t") && i + 1 < argc)
            n = atoi(argv[++i]);
    n = n > 0 ? n : bloom_mt_cpus();
    printf("bloom_cam frame paths, YUYV -> XRGB8888, median of %d paired rounds, %d online CPUs\n\n", ROUNDS,
           bloom_mt_cpus());
    printf(
        "| frame | row by row, ms | whole frame, ms | speed-up | row engine, bytes | pool + frames, bytes |\n"
        "|---|---|---|---|---|---|\n");
    for (int i = 1; i < argc; i++) {
        int w, h;
        if (!strcmp(argv[i], "-t")) {
            i++;
        } else if (sscanf(argv[i], "%dx%d", &w, &h) == 2 && w >= 2 && h >= 1 && !(w & 1)) {
            bad |= bench(w, h, n);
            sizes++;
        } else {
            fprintf(stderr, "bench_cam: '%s' is not an even WxH\n", argv[i]);
            return 2;
        }
    }
    if (!sizes) {
        bad |= bench(640, 480, n);
        bad |= bench(1920, 1080, n);
    }
    return bad ? 1 : 0;
}
