/* bloom_cam: camera -> bloom -> framebuffer. The frame loop: dequeue a
 * capture buffer, raise the frame-sync line, feed the rows to the engine
 * (YUYV and GREY converted one row at a time into a line buffer, the engine
 * copying what it keeps; RGB24 rows straight from the capture buffer), pull
 * output rows straight into the framebuffer page being drawn, drop the line,
 * pan, requeue. With --threads N > 1 the frame goes whole through a pool of
 * strip engines instead (cam_mt.c). All memory is taken before the first
 * frame. */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <linux/videodev2.h>

#include "bloom_mt.h"
#include "cam.h"

static volatile sig_atomic_t stop_signal;

static void on_signal(int sig)
{
    stop_signal = sig;
}

typedef struct {
    cam_opts_t o;
    cam_v4l2_t cap;
    cam_fb_t fb;
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
} cam_t;

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static int write_all(int fd, const uint8_t *p, size_t n)
{
    while (n) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

static int make_engines(cam_t *c)
{
    if (c->o.aux) { /* the preset's plane, the capture's size (known after S_FMT) */
        char err[512];
        bloom_aux_format_t f;
        if (cam_aux_load(c->o.aux, c->cap.width, c->cap.height, &f, &c->aux, err, sizeof err)) {
            fprintf(stderr, "%s: %s\n", CAM_PROG, err);
            return -1;
        }
        c->o.aux_fmt = f;
        c->aux_stride = (size_t)c->cap.width * (f == BLOOM_AUX_U16 ? 2u : 1u);
    }
    { /* --threads: 0 the online CPUs; a frame too small for them gets fewer */
        bloom_config_t cfg;
        cam_opts_config(&c->o, c->cap.width, c->cap.height, &cfg);
        c->threads = bloom_mt_tiles_for(&cfg, c->o.threads ? c->o.threads : bloom_mt_cpus());
        if (c->threads > 1 && cam_mt_frames(&c->mt, &c->cap, &c->fb, &c->place))
            return -1;
    }
    for (int m = 0; m < CAM_MODE_COUNT; m++) {
        bloom_config_t cfg;
        cam_opts_config(&c->o, c->cap.width, c->cap.height, &cfg);
        cfg.in_fmt = BLOOM_FMT_RGB888;
        cfg.out_fmt = c->fb.format;
        if (c->cap.pixelformat != V4L2_PIX_FMT_RGB24)
            cfg.flags |= BLOOM_FLAG_COPY_SOURCE;
        if (m == CAM_MODE_BLOOM_ONLY)
            cfg.flags |= BLOOM_FLAG_DEBUG_VIEW;
        if (m == CAM_MODE_OFF) { /* the default pipeline with B = 0 on every row: the
                                    source, re-encoded, whatever the preset */
            bloom_config_default(&cfg, c->cap.width, c->cap.height);
            cfg.in_fmt = BLOOM_FMT_RGB888;
            cfg.out_fmt = c->fb.format;
            if (c->cap.pixelformat != V4L2_PIX_FMT_RGB24)
                cfg.flags |= BLOOM_FLAG_COPY_SOURCE;
            cfg.levels = c->o.levels;
            cfg.threshold = BLOOM_MAX_THRESHOLD;
            cfg.soft_knee = 0;
            cfg.intensity = 0;
        }
        bloom_info_t info;
        bloom_status_t st = bloom_query(&cfg, &info);
        if (st != BLOOM_OK && m == CAM_MODE_BLOOM_ONLY && c->o.mode != CAM_MODE_BLOOM_ONLY) {
            if (!c->o.quiet)
                fprintf(stderr, "%s: preset %s: no bloom-only view (%s); the button skips it\n", CAM_PROG,
                        bloom_preset_name(cfg.preset), bloom_status_str(st));
            continue;
        }
        if (st != BLOOM_OK) {
            fprintf(stderr, "%s: bloom_query (preset %s%s): %s\n", CAM_PROG, bloom_preset_name(cfg.preset),
                    m == CAM_MODE_BLOOM_ONLY ? ", bloom-only" : "", bloom_status_str(st));
            return -1;
        }
        c->eng_aux[m] = cfg.aux_fmt != BLOOM_AUX_NONE;
        if (c->threads > 1) { /* whole frames: nothing to copy */
            size_t bytes;
            cfg.flags &= ~(uint32_t)BLOOM_FLAG_COPY_SOURCE;
            if (cam_mt_mode(&c->mt, (enum cam_mode)m, &cfg, c->threads, c->eng_aux[m] ? c->aux : NULL,
                            c->aux_stride, &bytes))
                return -1;
            if (m == CAM_MODE_BLOOM && !c->o.quiet)
                fprintf(stderr,
                        "%s: engine: preset %s%s%s, %d levels, %d threads (%d %s), workspace %zu bytes, "
                        "frame buffers %zu bytes (in: %s, out: %s)\n",
                        CAM_PROG, bloom_preset_name(cfg.preset), c->o.aux ? ", aux plane " : "",
                        c->o.aux ? c->o.aux : "", info.levels, c->threads, c->mt.tiles,
                        c->cap.width / c->mt.tiles >= BLOOM_MT_MIN_STRIP ? "strips" : "tiles", bytes,
                        c->mt.frame_bytes, c->mt.rgb ? "an RGB888 frame" : "the capture read in place",
                        c->mt.out ? "a frame, the shown part copied" : "straight to the page");
            continue;
        }
        size_t n = (info.workspace_bytes + 63) / 64 * 64;
        c->ws[m] = aligned_alloc(64, n);
        if (!c->ws[m]) {
            fprintf(stderr, "%s: workspace of %zu bytes: out of memory\n", CAM_PROG, n);
            return -1;
        }
        st = bloom_init(&c->eng[m], c->ws[m], n, &cfg);
        if (st != BLOOM_OK) {
            fprintf(stderr, "%s: bloom_init: %s\n", CAM_PROG, bloom_status_str(st));
            return -1;
        }
        if (m == CAM_MODE_BLOOM && !c->o.quiet)
            fprintf(stderr,
                    "%s: engine: preset %s%s%s, %d levels, 1 thread (row by row), workspace %zu bytes, "
                    "latency %d rows%s\n",
                    CAM_PROG, bloom_preset_name(cfg.preset), c->o.aux ? ", aux plane " : "",
                    c->o.aux ? c->o.aux : "", info.levels, info.workspace_bytes, info.latency_rows,
                    (cfg.flags & BLOOM_FLAG_COPY_SOURCE) ? ", source rows copied" : "");
    }
    return 0;
}

/* Output row r of the frame: straight into the page when the screen shows
 * all of it, else into the scratch row (then the shown part is copied). */
static uint8_t *out_row(cam_t *c, uint8_t *page, int r, int *via_scratch)
{
    const cam_place_t *p = &c->place;
    int shown = r >= p->src_y && r < p->src_y + p->h;
    if (shown && p->src_x == 0 && p->w == c->cap.width) {
        *via_scratch = 0;
        return page + (size_t)(p->dst_y + r - p->src_y) * (size_t)c->fb.line_length +
               (size_t)p->dst_x * (size_t)c->fb.bpp;
    }
    *via_scratch = shown;
    return c->scratch;
}

static int pull_rows(cam_t *c, bloom_t *b, uint8_t *page)
{
    for (;;) {
        int r = bloom_rows_out(b), via;
        uint8_t *dst = out_row(c, page, r, &via);
        bloom_status_t st = bloom_pull_row(b, dst);
        if (st == BLOOM_AGAIN || st == BLOOM_DONE)
            return 0;
        if (st != BLOOM_OK) {
            fprintf(stderr, "%s: bloom_pull_row: %s\n", CAM_PROG, bloom_status_str(st));
            return -1;
        }
        if (via)
            memcpy(page + (size_t)(c->place.dst_y + r - c->place.src_y) * (size_t)c->fb.line_length +
                       (size_t)c->place.dst_x * (size_t)c->fb.bpp,
                   c->scratch + (size_t)c->place.src_x * (size_t)c->fb.bpp,
                   (size_t)c->place.w * (size_t)c->fb.bpp);
    }
}

static int process(cam_t *c, enum cam_mode mode, const uint8_t *data, uint8_t *page)
{
    bloom_t *b = c->eng[mode];
    const uint8_t *aux = c->eng_aux[mode] ? c->aux : NULL;
    bloom_status_t st = bloom_begin(b);
    for (int y = 0; y < c->cap.height && st == BLOOM_OK; y++) {
        const uint8_t *src = data + (size_t)y * c->cap.bytesperline;
        if (c->cap.pixelformat == V4L2_PIX_FMT_YUYV) {
            cam_yuyv_row_to_rgb888(src, c->line, c->cap.width);
            src = c->line;
        } else if (c->cap.pixelformat == V4L2_PIX_FMT_GREY) {
            cam_grey_row_to_rgb888(src, c->line, c->cap.width);
            src = c->line;
        }
        const uint8_t *arow = aux ? aux + (size_t)y * c->aux_stride : NULL;
        st = arow ? bloom_push_row_aux(b, src, arow) : bloom_push_row(b, src);
        if (st == BLOOM_E_BUSY) { /* cannot happen when pulling after each push */
            if (pull_rows(c, b, page))
                return -1;
            st = arow ? bloom_push_row_aux(b, src, arow) : bloom_push_row(b, src);
        }
        if (st == BLOOM_OK && pull_rows(c, b, page))
            return -1;
    }
    if (st != BLOOM_OK) {
        fprintf(stderr, "%s: bloom_push_row: %s\n", CAM_PROG, bloom_status_str(st));
        return -1;
    }
    return pull_rows(c, b, page);
}

static void stats_line(const char *what, long frames, long dropped, double t0, double t1, double proc_sum,
                       double proc_min, double proc_max)
{
    double el = t1 - t0;
    fprintf(stderr,
            "%s: %s: %ld frames, %.2f fps, %ld dropped, processing %.2f ms/frame "
            "(min %.2f, max %.2f)\n",
            CAM_PROG, what, frames, el > 0 ? (double)frames / el : 0.0, dropped,
            frames ? proc_sum * 1e3 / (double)frames : 0.0, frames ? proc_min * 1e3 : 0.0, proc_max * 1e3);
}

static int run(cam_t *c)
{
    int fault = 0;
    long frames = 0, dropped = 0, win_frames = 0, win_dropped = 0;
    uint32_t last_seq = 0;
    double t_start = 0, t_win = 0, psum = 0, pmin = 1e9, pmax = 0;
    double wsum = 0, wmin = 1e9, wmax = 0;
    enum cam_mode mode = c->o.mode;
    const int bfd = cam_gpio_button_fd(c->gpio);

    if (cam_v4l2_start(&c->cap))
        return -1;
    while (!stop_signal && (c->o.frames == 0 || frames < c->o.frames)) {
        cam_frame_t f;
        int button = 0;
        int r = cam_v4l2_dequeue(&c->cap, c->o.timeout_ms, bfd, &button, &f);
        if (button) {
            int n = cam_gpio_button_presses(c->gpio);
            if (n) {
                for (int k = 0; k < n; k++) /* skipping a mode the preset cannot show */
                    do
                        mode = (enum cam_mode)(((int)mode + 1) % CAM_MODE_COUNT);
                    while (!c->eng[mode] && !c->mt.mt[mode]);
                if (!c->o.quiet)
                    fprintf(stderr, "%s: mode %s\n", CAM_PROG, cam_mode_name(mode));
            }
        }
        if (r == 1)
            continue; /* a signal: the loop condition decides */
        if (r < 0) {
            fault = 1;
            break;
        }
        if (frames == 0) {
            t_start = t_win = now_s();
        } else if (f.sequence > last_seq + 1) {
            dropped += (long)(f.sequence - last_seq - 1);
            win_dropped += (long)(f.sequence - last_seq - 1);
        }
        last_seq = f.sequence;
        if (c->rec_fd >= 0 &&
            write_all(c->rec_fd, f.data, (size_t)c->cap.bytesperline * (size_t)c->cap.height)) {
            fprintf(stderr, "%s: write %s: %s\n", CAM_PROG, c->o.record, strerror(errno));
            fault = 1;
            cam_v4l2_requeue(&c->cap, &f);
            break;
        }

        uint8_t *page = cam_fb_draw_page(&c->fb);
        cam_gpio_frame(c->gpio, 1);
        double p0 = now_s();
        int pr = c->threads > 1 ? cam_mt_process(&c->mt, mode, &c->cap, f.data, &c->fb, &c->place, page)
                                : process(c, mode, f.data, page);
        double dt = now_s() - p0;
        cam_gpio_frame(c->gpio, 0);
        c->last_page = page;
        if (pr || cam_fb_show(&c->fb) || cam_v4l2_requeue(&c->cap, &f)) {
            fault = 1;
            break;
        }
        frames++;
        win_frames++;
        psum += dt;
        wsum += dt;
        pmin = dt < pmin ? dt : pmin;
        wmin = dt < wmin ? dt : wmin;
        pmax = dt > pmax ? dt : pmax;
        wmax = dt > wmax ? dt : wmax;
        if (c->o.stats) {
            double t = now_s();
            if (t - t_win >= 1.0) {
                stats_line("last second", win_frames, win_dropped, t_win, t, wsum, wmin, wmax);
                t_win = t;
                win_frames = win_dropped = 0;
                wsum = wmax = 0;
                wmin = 1e9;
            }
        }
    }
    if (stop_signal && !c->o.quiet)
        fprintf(stderr, "%s: stopping on %s\n", CAM_PROG, stop_signal == SIGINT ? "SIGINT" : "SIGTERM");
    if (c->o.stats || !c->o.quiet)
        stats_line("total", frames, dropped, t_start, frames ? now_s() : t_start, psum, pmin, pmax);
    return fault ? -1 : 0;
}

static int dump_fb(cam_t *c)
{
    int fd = open(c->o.dump_fb, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    int bad = fd < 0;
    for (int y = 0; !bad && c->last_page && y < c->place.h; y++)
        bad = write_all(fd,
                        c->last_page + (size_t)(c->place.dst_y + y) * c->fb.line_length +
                            (size_t)c->place.dst_x * c->fb.bpp,
                        (size_t)c->place.w * (size_t)c->fb.bpp);
    if (fd >= 0 && close(fd))
        bad = 1;
    if (bad)
        fprintf(stderr, "%s: --dump-fb %s: %s\n", CAM_PROG, c->o.dump_fb, strerror(errno));
    return bad ? -1 : 0;
}

int main(int argc, char **argv)
{
    static cam_t c;
    char err[256];
    c.cap.fd = -1;
    c.fb.fd = -1;
    c.rec_fd = -1;
    int pr = cam_parse_opts(&c.o, argc, argv, err, sizeof err);
    if (pr == 1) {
        cam_usage(stdout);
        return 0;
    }
    if (pr < 0) {
        fprintf(stderr, "%s: %s\n", CAM_PROG, err);
        cam_usage(stderr);
        return 2;
    }

    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal; /* no SA_RESTART: poll returns EINTR */
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);

    int status = 1;
    if (cam_v4l2_open(&c.cap, c.o.device, c.o.width, c.o.height, c.o.format, c.o.buffers))
        goto out;
    if (cam_fb_open(&c.fb, c.o.fb, c.cap.width, c.cap.height))
        goto out;
    if (cam_gpio_open(&c.gpio, &c.o.gpio_frame, &c.o.gpio_button))
        goto out;
    cam_place(c.cap.width, c.cap.height, c.fb.xres, c.fb.yres, &c.place);
    c.line = malloc((size_t)c.cap.width * 3);
    c.scratch = malloc((size_t)c.cap.width * 4);
    if (!c.line || !c.scratch) {
        fprintf(stderr, "%s: out of memory\n", CAM_PROG);
        goto out;
    }
    if (make_engines(&c))
        goto out;
    if (c.o.record) {
        c.rec_fd = open(c.o.record, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (c.rec_fd < 0) {
            fprintf(stderr, "%s: open %s: %s\n", CAM_PROG, c.o.record, strerror(errno));
            goto out;
        }
    }
    if (!c.o.quiet)
        fprintf(stderr,
                "%s: %s (%s, %s): %dx%d %s, bytesperline %u, sizeimage %u, %d buffers\n"
                "%s: %s (%s): %dx%d %s, line_length %d, %s; frame at %d,%d, %dx%d shown from %d,%d\n",
                CAM_PROG, c.o.device, c.cap.driver, c.cap.card, c.cap.width, c.cap.height,
                cam_format_name(c.o.format), (unsigned)c.cap.bytesperline, (unsigned)c.cap.sizeimage,
                c.cap.nbufs, CAM_PROG, c.o.fb, c.fb.id, c.fb.xres, c.fb.yres,
                c.fb.format == BLOOM_FMT_RGB565 ? "RGB565" : "XRGB8888", c.fb.line_length,
                c.fb.pages == 2 ? "double-buffered" : "single-buffered", c.place.dst_x, c.place.dst_y,
                c.place.w, c.place.h, c.place.src_x, c.place.src_y);
    status = run(&c) ? 1 : 0;
    if (c.o.dump_fb && dump_fb(&c))
        status = 1;
out:
    cam_v4l2_close(&c.cap);
    cam_fb_close(&c.fb);
    cam_gpio_close(c.gpio);
    if (c.rec_fd >= 0 && close(c.rec_fd)) {
        fprintf(stderr, "%s: close %s: %s\n", CAM_PROG, c.o.record, strerror(errno));
        status = 1;
    }
    cam_mt_close(&c.mt);
    for (int m = 0; m < CAM_MODE_COUNT; m++)
        free(c.ws[m]);
    free(c.line);
    free(c.scratch);
    free(c.aux);
    return status;
}
