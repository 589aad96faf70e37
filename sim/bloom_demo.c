/* bloom_demo: one image through the fixed-point engine and the reference
 * model; writes before/after/bloom-only/side-by-side PPMs and prints the
 * error summary.
 *
 *   bloom_demo INPUT.ppm|INPUT.pfm OUTDIR [--levels N] [--threshold T]
 *              [--knee S] [--intensity I] [--linear]
 *
 * PPM input runs as RGB888 (sRGB); PFM as linear RGBQ16 (img_float_to_q16). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "bloom.h"
#include "bloom_model.h"
#include "imgio.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void die(const char *msg)
{
    fprintf(stderr, "bloom_demo: %s\n", msg);
    exit(1);
}

static void *xcalloc(size_t n)
{
    void *p = calloc(1, n ? n : 1);
    if (!p)
        die("out of memory");
    return p;
}

/* mkdir -p: every missing directory of path. */
static int mkdir_p(const char *path)
{
    char buf[1024];
    if (strlen(path) >= sizeof buf) {
        errno = ENAMETOOLONG;
        return -1;
    }
    strcpy(buf, path);
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0777) && errno != EEXIST)
                return -1;
            *p = '/';
        }
    return mkdir(buf, 0777) && errno != EEXIST ? -1 : 0;
}

static int parse_q16(const char *s, double lo, double hi, uint32_t *out)
{
    char *end;
    double v = strtod(s, &end);
    if (*end || !(v >= lo && v <= hi))
        return -1;
    *out = (uint32_t)(v * 65536.0 + 0.5);
    return 0;
}

/* Engine input buffer from the image; codes for the model. */
static uint8_t *to_engine(const img_t *im, bloom_format_t *fmt, uint32_t *codes)
{
    const size_t n = (size_t)im->width * (size_t)im->height;
    *fmt = im->f32 ? BLOOM_FMT_RGBQ16 : BLOOM_FMT_RGB888;
    uint8_t *buf = xcalloc(n * (size_t)bloom_format_bpp(*fmt));
    for (size_t i = 0; i < n; i++)
        for (int ch = 0; ch < 3; ch++) {
            size_t s = i * (size_t)im->channels + (size_t)(im->channels == 3 ? ch : 0);
            uint32_t v =
                im->f32 ? img_float_to_q16(im->f32[s])
                        : (uint32_t)((im->u16[s] * 255u + (unsigned)im->maxval / 2u) / (unsigned)im->maxval);
            codes[3 * i + (size_t)ch] = v;
            if (im->f32)
                memcpy(buf + 12 * i + 4 * (size_t)ch, &v, 4);
            else
                buf[3 * i + (size_t)ch] = (uint8_t)v;
        }
    return buf;
}

static void write_rgb(const char *dir, const char *name, const uint8_t *rgb, int w, int h)
{
    img_t im;
    char path[1024], err[512];
    if (img_alloc(&im, w, h, 3, 255))
        die("out of memory");
    for (size_t i = 0; i < (size_t)w * (size_t)h * 3u; i++)
        im.u16[i] = rgb[i];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (img_write_ppm(path, &im, err, sizeof err))
        die(err);
    printf("wrote %s\n", path);
    img_free(&im);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: bloom_demo INPUT.ppm|INPUT.pfm OUTDIR [--levels N] [--threshold T] "
                        "[--knee S] [--intensity I] [--linear]\n");
        return 2;
    }
    const char *in = argv[1], *outdir = argv[2];
    bloom_config_t c;
    bloom_config_default(&c, 1, 1);
    for (int i = 3; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : "";
        int bad = 0;
        if (!strcmp(a, "--linear")) {
            c.flags |= BLOOM_FLAG_LINEAR;
            continue;
        } else if (!strcmp(a, "--levels")) {
            c.levels = atoi(v);
        } else if (!strcmp(a, "--threshold")) {
            bad = parse_q16(v, 0, 256, &c.threshold);
        } else if (!strcmp(a, "--knee")) {
            bad = parse_q16(v, 0, 1, &c.soft_knee);
        } else if (!strcmp(a, "--intensity")) {
            bad = parse_q16(v, 0, 10, &c.intensity);
        } else {
            fprintf(stderr, "bloom_demo: unknown option %s\n", a);
            return 2;
        }
        if (bad) {
            fprintf(stderr, "bloom_demo: %s: bad value '%s'\n", a, v);
            return 2;
        }
        i++;
    }

    img_t im;
    char err[512];
    if (img_read(in, &im, err, sizeof err))
        die(err);
    if (mkdir_p(outdir)) {
        fprintf(stderr, "bloom_demo: %s: %s\n", outdir, strerror(errno));
        return 1;
    }
    const int w = im.width, h = im.height;
    const size_t n = (size_t)w * (size_t)h;
    c.width = w;
    c.height = h;
    uint32_t *codes = xcalloc(n * 3 * sizeof *codes);
    uint8_t *src = to_engine(&im, &c.in_fmt, codes);
    c.out_fmt = BLOOM_FMT_RGB888;
    if (c.in_fmt == BLOOM_FMT_RGBQ16 && c.threshold == BLOOM_ONE)
        c.threshold = 2u * BLOOM_ONE; /* HDR default: only the lamps */

    bloom_info_t info;
    bloom_status_t st = bloom_query(&c, &info);
    if (st != BLOOM_OK) {
        fprintf(stderr, "bloom_demo: configuration: %s\n", bloom_status_str(st));
        return 1;
    }
    void *ws = xcalloc(info.workspace_bytes + 8);
    bloom_t *b;
    if ((st = bloom_init(&b, ws, info.workspace_bytes, &c)) != BLOOM_OK)
        die(bloom_status_str(st));

    uint8_t *after = xcalloc(n * 3), *bloom_only = xcalloc(n * 3), *before = xcalloc(n * 3);
    const ptrdiff_t sstride = (ptrdiff_t)w * bloom_format_bpp(c.in_fmt);
    double best = 1e9;
    for (int run = 0; run < 5; run++) {
        double t0 = now_s();
        if ((st = bloom_process(b, src, sstride, after, (ptrdiff_t)w * 3)) != BLOOM_OK)
            die(bloom_status_str(st));
        double t = now_s() - t0;
        best = t < best ? t : best;
    }
    /* bloom-only view, and the input as shown (intensity 0) */
    bloom_config_t cv = c;
    cv.flags |= BLOOM_FLAG_DEBUG_VIEW;
    bloom_init(&b, ws, info.workspace_bytes, &cv);
    bloom_process(b, src, sstride, bloom_only, (ptrdiff_t)w * 3);
    cv = c;
    cv.intensity = 0;
    bloom_init(&b, ws, info.workspace_bytes, &cv);
    bloom_process(b, src, sstride, before, (ptrdiff_t)w * 3);

    /* the reference model, float and bit-true */
    bloom_model_params_t p;
    memset(&p, 0, sizeof p);
    p.width = w;
    p.height = h;
    p.levels = c.levels;
    p.linear = (c.flags & BLOOM_FLAG_LINEAR) != 0;
    p.threshold = c.threshold / 65536.0;
    p.soft_knee = c.soft_knee / 65536.0;
    p.intensity = c.intensity / 65536.0;
    bloom_model_quantize(&c, BLOOM_LIN_BITS, &p.threshold_q, &p.knee_q, &p.intensity_q);
    const int smax[3] = {c.in_fmt == BLOOM_FMT_RGBQ16 ? 0 : 255, c.in_fmt == BLOOM_FMT_RGBQ16 ? 0 : 255,
                         c.in_fmt == BLOOM_FMT_RGBQ16 ? 0 : 255};
    const int dmax[3] = {255, 255, 255};
    uint32_t *fl = xcalloc(n * 3 * sizeof *fl), *bt = xcalloc(n * 3 * sizeof *bt);
    double t0 = now_s();
    if (bloom_model_run(&p, codes, smax, fl, dmax, NULL) < 0)
        die("float model failed");
    double t_model = now_s() - t0;
    p.bittrue = 1;
    if (bloom_model_run(&p, codes, smax, bt, dmax, NULL) < 0)
        die("bit-true model failed");
    long long exact = 0, bt_diff = 0, peak = 0, above = 0, below = 0;
    double sum = 0, sq = 0, sgn = 0; /* |error| and signed: a bias hides in the first */
    for (size_t i = 0; i < n * 3; i++) {
        long long d = (long long)after[i] - (long long)fl[i];
        sgn += (double)d;
        above += d > 0;
        below += d < 0;
        d = d < 0 ? -d : d;
        exact += d == 0;
        peak = d > peak ? d : peak;
        sum += (double)d;
        sq += (double)(d * d);
        bt_diff += after[i] != bt[i];
    }

    uint8_t *side = xcalloc(n * 6);
    for (int y = 0; y < h; y++) {
        memcpy(side + (size_t)y * (size_t)w * 6, before + (size_t)y * (size_t)w * 3, (size_t)w * 3);
        memcpy(side + (size_t)y * (size_t)w * 6 + (size_t)w * 3, after + (size_t)y * (size_t)w * 3,
               (size_t)w * 3);
    }
    write_rgb(outdir, "before.ppm", before, w, h);
    write_rgb(outdir, "after.ppm", after, w, h);
    write_rgb(outdir, "bloom_only.ppm", bloom_only, w, h);
    write_rgb(outdir, "side_by_side.ppm", side, 2 * w, h);

    printf("%s: %dx%d %s, %d levels, threshold %.3f, knee %.3f, intensity %.3f\n", in, w, h,
           c.in_fmt == BLOOM_FMT_RGBQ16 ? "linear HDR (RGBQ16)" : "sRGB RGB888", info.levels,
           c.threshold / 65536.0, c.soft_knee / 65536.0, c.intensity / 65536.0);
    printf("workspace %zu bytes (%.2f%% of one RGB888 frame), latency %d rows\n", info.workspace_bytes,
           100.0 * (double)info.workspace_bytes / ((double)n * 3), info.latency_rows);
    printf("engine %.2f ms per frame (best of 5, one core); float model %.0f ms\n", best * 1e3,
           t_model * 1e3);
    printf("vs float model: peak %lld LSB, exact %.3f%%, signed mean %+.5f LSB (%lld above, %lld below), "
           "mean |e| %.5f LSB, MSE %.5f\n",
           peak, 100.0 * (double)exact / (double)(n * 3), sgn / (double)(n * 3), above, below,
           sum / (double)(n * 3), sq / (double)(n * 3));
    printf("vs bit-true model: %lld samples differ\n", bt_diff);
    free(side);
    free(fl);
    free(bt);
    free(after);
    free(bloom_only);
    free(before);
    free(ws);
    free(src);
    free(codes);
    img_free(&im);
    return bt_diff ? 1 : 0;
}
