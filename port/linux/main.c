/* bloom_cam: camera -> bloom -> framebuffer. The frame loop: dequeue a
 * capture buffer, raise the frame-sync line, feed the rows to the engine
 * (every format but RGB24 converted one row at a time into a line buffer, the engine
 * copying what it keeps; RGB24 rows straight from the capture buffer), pull
 * output rows straight into the framebuffer page being drawn, drop the line,
 * pan, requeue. With --threads N > 1 the frame goes whole through a pool of
 * strip engines instead (cam_mt.c). All memory is taken before the first
 * frame. */
#define _GNU_SOURCE /* ppoll(2), in glibc beside POSIX 2008 */
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

static int process(cam_t *c, enum cam_mode mode, const cam_frame_t *f, uint8_t *page)
{
    bloom_t *b = c->eng[mode];
    const uint8_t *aux = c->eng_aux[mode] ? c->aux : NULL;
    if (cam_cap_begin(&c->cap, f))
        return 2; /* an MJPEG frame found bad: not shown (what was drawn is on the page not on show) */
    bloom_status_t st = bloom_begin(b);
    for (int y = 0; y < c->cap.height && st == BLOOM_OK; y++) {
        const uint8_t *src = cam_cap_next(&c->cap, f, y, c->line);
        if (!src)
            return 2;
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
    return pull_rows(c, b, page) ? -1 : cam_cap_end(&c->cap) ? 2 : 0;
}

static const char *signal_name(int sig)
{
    switch (sig) {
    case SIGINT:
        return "SIGINT";
    case SIGHUP:
        return "SIGHUP";
    case SIGQUIT:
        return "SIGQUIT";
    case SIGPIPE:
        return "SIGPIPE";
    default:
        return "SIGTERM";
    }
}

/* Sleep ms, or less when a stop signal comes (the mask lets them in). */
static void nap(cam_t *c, int ms)
{
    const struct timespec t = {ms / 1000, (long)(ms % 1000) * 1000000L};
    ppoll(NULL, 0, &t, c->cap.wait_mask);
}

/* The camera was lost (c->cap.lost): close it and open it again by its
 * path (a /dev/v4l/by-id link follows the device across re-enumeration),
 * backing off from 100 ms to 2 s between attempts, until --reconnect
 * seconds after lost_at, when the last good frame was followed by the
 * first fault (a device that opens but never delivers counts as lost
 * all along). When it comes back in another format (a source change, a
 * camera plugged in again with other defaults), the engines are made again
 * for it (cam_resize), unless an --aux plane or a --record file holds the
 * old size: then it must come back as it was. 0 when it streams again, 1
 * on a stop signal, CAM_EXIT_DEVICE when it did not come back,
 * CAM_EXIT_CONFIG when the new size cannot be taken. */
static int reconnect(cam_t *c, double lost_at)
{
    const int w = c->cap.width, h = c->cap.height;
    const uint32_t pf = c->cap.pixelformat, bpl = c->cap.bytesperline;
    char why[sizeof c->cap.msg]; /* the fault that brought us here, then each attempt's */
    snprintf(why, sizeof why, "%s", c->cap.msg);
    cam_v4l2_close(&c->cap); /* every handle closed: vivid, uvcvideo let the device go */
    const double give_up = lost_at + (double)c->o.reconnect_s;
    int delay = 100, status = 1;
    c->cap.quiet = 1;
    while (!stop_signal) {
        if (now_s() >= give_up) { /* it opens, perhaps, but no frame came for that long */
            fprintf(stderr, "%s: reconnect: %s did not come back within %ld s (last: %s)\n", CAM_PROG,
                    c->o.device, c->o.reconnect_s, why);
            status = CAM_EXIT_DEVICE;
            break;
        }
        if (!c->o.quiet && delay == 100)
            fprintf(stderr, "%s: reconnect: %s lost, trying for %.1f s more\n", CAM_PROG, c->o.device,
                    give_up - now_s());
        nap(c, delay);
        if (stop_signal)
            break;
        int ok = !cam_v4l2_open(&c->cap, c->o.device, c->o.width, c->o.height, c->o.format, c->o.fps,
                                c->o.buffers);
        const int other = ok && (c->cap.width != w || c->cap.height != h || c->cap.pixelformat != pf ||
                                 c->cap.bytesperline != bpl);
        if (other && (c->o.aux || c->rec_fd >= 0)) {
            snprintf(c->cap.msg, sizeof c->cap.msg,
                     "came back as %dx%d, bytesperline %u, not %dx%d, %u (the size --%s was made for)",
                     c->cap.width, c->cap.height, (unsigned)c->cap.bytesperline, w, h, (unsigned)bpl,
                     c->o.aux ? "aux" : "record");
            ok = 0;
        } else if (other && cam_resize(c)) {
            status = CAM_EXIT_CONFIG;
            break;
        }
        if (ok && !cam_v4l2_start(&c->cap)) {
            if (!c->o.quiet)
                fprintf(stderr, "%s: reconnect: %s streams again\n", CAM_PROG, c->o.device);
            status = 0;
            break;
        }
        snprintf(why, sizeof why, "%s", c->cap.msg);
        cam_v4l2_close(&c->cap);
        delay = delay < 1000 ? delay * 2 : 2000;
    }
    c->cap.quiet = 0;
    return status;
}

/* The frame loop. Returns the exit status (CAM_EXIT_*). */
static int run(cam_t *c)
{
    int status = CAM_EXIT_OK;
    cam_counts_t n, win;
    memset(&n, 0, sizeof n);
    memset(&win, 0, sizeof win);
    uint32_t last_seq = 0;
    int have_seq = 0;
    double lost_at = 0; /* the first fault since the last good frame (0: none) */
    double t_start = 0, t_win = 0, psum = 0, pmin = 1e9, pmax = 0;
    double wsum = 0, wmin = 1e9, wmax = 0;
    enum cam_mode mode = c->o.mode;
    const int bfd = cam_gpio_button_fd(c->gpio);

    if (cam_v4l2_start(&c->cap))
        return c->cap.lost == CAM_LOST_CONFIG ? CAM_EXIT_CONFIG : CAM_EXIT_DEVICE;
    while (!stop_signal && (c->o.frames == 0 || n.frames < c->o.frames)) {
        cam_frame_t f;
        int button = 0;
        int r = cam_v4l2_dequeue(&c->cap, c->o.timeout_ms, bfd, &button, &f);
        if (button) {
            int k = cam_gpio_button_presses(c->gpio);
            if (k) {
                for (int i = 0; i < k; i++) /* skipping a mode the preset cannot show */
                    do
                        mode = (enum cam_mode)(((int)mode + 1) % CAM_MODE_COUNT);
                    while (!c->eng[mode] && !c->mt.mt[mode]);
                if (!c->o.quiet)
                    fprintf(stderr, "%s: mode %s\n", CAM_PROG, cam_mode_name(mode));
            }
        }
        if (r == 1)
            continue; /* a signal: the loop condition decides */
        if (r == 2) { /* flagged or short: requeued, counted, the run goes on */
            cam_count_bad(&n, &win, f.bad, f.sequence, NULL, c->o.quiet);
            continue;
        }
        if (r == 0 && c->o.latest) {
            const long sk = n.skipped, b1 = n.bad[1], b2 = n.bad[2];
            r = cam_v4l2_latest(&c->cap, &f, &n.skipped, n.bad);
            win.skipped += n.skipped - sk;
            win.bad[1] += n.bad[1] - b1;
            win.bad[2] += n.bad[2] - b2;
        }
        if (r < 0) {
            if (c->cap.lost == CAM_LOST_CONFIG || !c->o.reconnect_s) {
                status = c->cap.lost == CAM_LOST_CONFIG ? CAM_EXIT_CONFIG : CAM_EXIT_DEVICE;
                break;
            }
            if (lost_at == 0)
                lost_at = now_s();
            const int rc = reconnect(c, lost_at);
            if (rc == 1)
                break; /* a stop signal while trying */
            if (rc) {
                status = rc;
                break;
            }
            n.reconnects++;
            win.reconnects++;
            have_seq = 0; /* its sequence numbers start again */
            continue;
        }
        lost_at = 0;
        if (n.frames == 0)
            t_start = t_win = now_s();
        /* frames the driver dropped, and ours skipped: modulo 2^32 (the
         * sequence number wraps) */
        const uint32_t gap = f.sequence - last_seq;
        if (have_seq && gap > 1u && gap < 0x80000000u) {
            n.dropped += (long)(gap - 1u);
            win.dropped += (long)(gap - 1u);
        }
        last_seq = f.sequence;
        have_seq = 1;
        if (c->rec_fd >= 0 &&
            (write_all(c->rec_fd, f.data, c->cap.plane_bytes[0]) || /* then a second plane */
             write_all(c->rec_fd, f.data2, c->cap.plane_bytes[1]))) {
            if (errno == EPIPE) { /* the reader of --record went away: SIGPIPE (blocked) says stop */
                stop_signal = SIGPIPE;
            } else {
                fprintf(stderr, "%s: write %s: %s\n", CAM_PROG, c->o.record, strerror(errno));
                status = CAM_EXIT_FAULT;
            }
            cam_v4l2_requeue(&c->cap, &f);
            break;
        }

        uint8_t *page = cam_fb_draw_page(&c->fb);
        if (!page) { /* DRM: the last flip never completed */
            cam_v4l2_requeue(&c->cap, &f);
            status = CAM_EXIT_DISPLAY;
            break;
        }
        if (c->clear_pages > 0) { /* a new capture size: the old frame's border goes */
            for (int y = 0; y < c->fb.yres; y++)
                memset(page + (size_t)y * (size_t)c->fb.line_length, 0,
                       (size_t)c->fb.xres * (size_t)c->fb.bpp);
            c->clear_pages--;
        }
        cam_gpio_frame(c->gpio, 1);
        double p0 = now_s();
        int pr = c->threads > 1 ? cam_mt_process(&c->mt, mode, &c->cap, &f, &c->fb, &c->place, page)
                                : process(c, mode, &f, page);
        double dt = now_s() - p0;
        cam_gpio_frame(c->gpio, 0);
        if (pr == 2) { /* undecodable JPEG: requeued, counted, the page not shown */
            cam_count_bad(&n, &win, CAM_BAD_JPEG, f.sequence, cam_mjpeg_why(c->cap.jpeg), c->o.quiet);
            if (cam_v4l2_requeue(&c->cap, &f) && !c->o.reconnect_s) {
                status = CAM_EXIT_DEVICE;
                break;
            }
            continue;
        }
        c->last_page = page;
        if (pr) {
            status = CAM_EXIT_FAULT;
            break;
        }
        if (cam_fb_show(&c->fb)) {
            status = CAM_EXIT_DISPLAY;
            break;
        }
        if (cam_v4l2_requeue(&c->cap, &f)) { /* lost: the next dequeue sees it too */
            if (!c->o.reconnect_s) {
                status = CAM_EXIT_DEVICE;
                break;
            }
        }
        n.frames++;
        win.frames++;
        psum += dt;
        wsum += dt;
        pmin = dt < pmin ? dt : pmin;
        wmin = dt < wmin ? dt : wmin;
        pmax = dt > pmax ? dt : pmax;
        wmax = dt > wmax ? dt : wmax;
        if (c->o.stats) {
            double t = now_s();
            if (t - t_win >= 1.0) {
                cam_stats_line("last second", &win, t_win, t, wsum, wmin, wmax);
                t_win = t;
                memset(&win, 0, sizeof win);
                wsum = wmax = 0;
                wmin = 1e9;
            }
        }
    }
    if (stop_signal && !c->o.quiet)
        fprintf(stderr, "%s: stopping on %s\n", CAM_PROG, signal_name(stop_signal));
    if (c->o.stats || !c->o.quiet)
        cam_stats_line("total", &n, t_start, n.frames ? now_s() : t_start, psum, pmin, pmax);
    return status;
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
    c.vt.fd = -1;
    c.rec_fd = -1;
    int pr = cam_parse_opts(&c.o, argc, argv, err, sizeof err);
    if (pr == 1) {
        cam_usage(stdout);
        return 0;
    }
    if (pr < 0) {
        fprintf(stderr, "%s: %s\n", CAM_PROG, err);
        cam_usage(stderr);
        return CAM_EXIT_CONFIG;
    }

    /* The stop signals (a dropped SSH session's SIGHUP, SIGQUIT, SIGPIPE
     * from a --record pipe whose reader went away, SIGINT, SIGTERM) set the
     * flag and end the run through the one teardown below. They are blocked
     * but inside the waits (ppoll with wait_mask), so none falls between the
     * loop's look at the flag and the wait; the pool's threads, started
     * later, inherit the block. */
    static const int stops[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE};
    static sigset_t wait_mask;
    sigset_t block;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal; /* no SA_RESTART: the wait returns EINTR */
    sigemptyset(&sa.sa_mask);
    sigemptyset(&block);
    for (size_t i = 0; i < sizeof stops / sizeof stops[0]; i++) {
        sigaction(stops[i], &sa, NULL);
        sigaddset(&block, stops[i]);
    }
    sigprocmask(SIG_BLOCK, &block, &wait_mask);
    for (size_t i = 0; i < sizeof stops / sizeof stops[0]; i++)
        sigdelset(&wait_mask, stops[i]);
    c.cap.wait_mask = &wait_mask;

    int status = CAM_EXIT_FAULT;
    if (cam_v4l2_open(&c.cap, c.o.device, c.o.width, c.o.height, c.o.format, c.o.fps, c.o.buffers)) {
        status = c.cap.lost == CAM_LOST_CONFIG ? CAM_EXIT_CONFIG : CAM_EXIT_DEVICE;
        goto out;
    }
    if (c.o.record && c.cap.jpeg) { /* a frame found bad half-way would be half-recorded */
        fprintf(stderr, "%s: --record: not with MJPEG capture (frames are decoded row by row)\n", CAM_PROG);
        status = CAM_EXIT_CONFIG;
        goto out;
    }
    if (cam_display_open(&c.fb, &c.o, c.cap.width, c.cap.height)) {
        status = CAM_EXIT_DISPLAY;
        goto out;
    }
    if (strcmp(c.o.fb, "none"))
        cam_vt_graphics(&c.vt, c.o.vt, c.o.quiet);
    if (cam_gpio_open(&c.gpio, &c.o.gpio_frame, &c.o.gpio_button, c.o.debounce_ms)) {
        status = CAM_EXIT_CONFIG;
        goto out;
    }
    cam_place(c.cap.width, c.cap.height, c.fb.xres, c.fb.yres, &c.place);
    c.line = malloc((size_t)c.cap.width * 3);
    c.scratch = malloc((size_t)c.cap.width * 4);
    if (!c.line || !c.scratch) {
        fprintf(stderr, "%s: out of memory\n", CAM_PROG);
        status = CAM_EXIT_FAULT;
        goto out;
    }
    if (cam_make_engines(&c)) {
        status = CAM_EXIT_CONFIG;
        goto out;
    }
    if (c.o.record) {
        c.rec_fd = open(c.o.record, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (c.rec_fd < 0) {
            fprintf(stderr, "%s: open %s: %s\n", CAM_PROG, c.o.record, strerror(errno));
            goto out;
        }
    }
    char desc[200];
    cam_v4l2_describe(&c.cap, desc, sizeof desc);
    if (!c.o.quiet)
        fprintf(stderr,
                "%s: %s (%s, %s): %dx%d %s\n"
                "%s: %s (%s): %dx%d %s, line_length %d, %s; frame at %d,%d, %dx%d shown from %d,%d\n",
                CAM_PROG, c.o.device, c.cap.driver, c.cap.card, c.cap.width, c.cap.height, desc, CAM_PROG,
                c.fb.path, c.fb.id, c.fb.xres, c.fb.yres,
                c.fb.format == BLOOM_FMT_RGB565 ? "RGB565" : "XRGB8888", c.fb.line_length,
                cam_fb_buffering(&c.fb), c.place.dst_x, c.place.dst_y, c.place.w, c.place.h, c.place.src_x,
                c.place.src_y);
    status = run(&c);
    if (c.fb.drm && !c.o.quiet)
        fprintf(stderr, "%s: %ld page flips (drmModePageFlip), each drawn after the last one's event\n",
                CAM_PROG, cam_drm_flips(&c.fb));
    else if (c.fb.pages == 2 && !c.o.quiet)
        fprintf(stderr, "%s: pages shown %s\n", CAM_PROG,
                c.fb.vsync ? "after the vertical blank (FBIO_WAITFORVSYNC)"
                           : "without waiting for the vertical blank (the driver refused FBIO_WAITFORVSYNC)");
    if (c.o.dump_fb && dump_fb(&c) && !status)
        status = CAM_EXIT_FAULT;
out:
    cam_v4l2_close(&c.cap);
    cam_fb_close(&c.fb);
    cam_vt_restore(&c.vt);
    cam_gpio_close(c.gpio);
    if (c.rec_fd >= 0 && close(c.rec_fd)) {
        fprintf(stderr, "%s: close %s: %s\n", CAM_PROG, c.o.record, strerror(errno));
        status = status ? status : CAM_EXIT_FAULT;
    }
    cam_mt_close(&c.mt);
    for (int m = 0; m < CAM_MODE_COUNT; m++)
        free(c.ws[m]);
    free(c.line);
    free(c.scratch);
    free(c.aux);
    return status;
}
