/* bloom_bench: the engine side by side with the memory floor, OpenCV 4 and
 * the float model (issue 7, item 1). `make bench` runs it; see
 * sim/bench/method.md (appended to sim/docs/bench.md) for what each row is.
 *
 *   bloom_bench [--csv PATH] [--md PATH] [--image PPM] [--sizes WxH,...]
 *               [--model-sizes WxH,...|none] [--runs N] [--warmup N]
 *               [--ring-mb N] [--quick]
 *
 * Nothing here asserts a time: the program measures, prints and writes the
 * table; only a failing call (a status other than BLOOM_OK, an OpenCV
 * exception, out of memory) makes it exit non-zero. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench.h"
#include "bench_cv.h"
#include "bloom.h"
#include "bloom_model.h"
#include "scene.h"
#include "variants.h"
#include "timing.h"

row_t rows[MAX_ROWS];
int nrows;

/* ---- small helpers ------------------------------------------------------ */

void die(const char *fmt, const char *arg)
{
    fprintf(stderr, "bloom_bench: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n");
    exit(1);
}

void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p)
        die("out of memory (%s)", "malloc");
    return p;
}

row_t *new_row(int w, int h, const char *group, const char *name)
{
    if (nrows == MAX_ROWS)
        die("too many rows (%s)", name);
    row_t *r = &rows[nrows++];
    memset(r, 0, sizeof *r);
    r->w = w;
    r->h = h;
    r->group = group;
    snprintf(r->name, sizeof r->name, "%s", name);
    r->threads = 1;
    r->agree_max = -1;
    return r;
}

/* Row r against the engine's output a (r's output b): max absolute
 * difference, % of equal bytes, mean of a - b and the bytes above / below. */
static void agreement(const uint8_t *a, const uint8_t *b, size_t n, row_t *r)
{
    size_t same = 0;
    long long sum = 0, above = 0, below = 0;
    int m = 0;
    for (size_t i = 0; i < n; i++) {
        const int s = a[i] - b[i], d = s < 0 ? -s : s;
        if (d > m)
            m = d;
        same += d == 0;
        sum += s;
        above += s > 0;
        below += s < 0;
    }
    r->agree_max = m;
    r->agree_exact = n ? 100.0 * (double)same / (double)n : 100.0;
    r->agree_signed = n ? (double)sum / (double)n : 0.0;
    r->agree_above = above;
    r->agree_below = below;
}

/* ---- the variants --------------------------------------------------------- */

typedef struct {
    size_t bytes;
} floor_ctx_t;

static int run_memcpy(void *ctx, const uint8_t *src, uint8_t *dst)
{
    memcpy(dst, src, ((floor_ctx_t *)ctx)->bytes);
    return 0;
}

/* The trivial read-modify-write pass: every byte inverted in place, eight
 * at a time (the frame slots are page-aligned). */
static int run_rmw(void *ctx, const uint8_t *src, uint8_t *dst)
{
    (void)src;
    const size_t n = ((floor_ctx_t *)ctx)->bytes;
    size_t i = 0;
    for (; i + 8u <= n; i += 8u) {
        uint64_t v;
        memcpy(&v, dst + i, 8u);
        v = ~v;
        memcpy(dst + i, &v, 8u);
    }
    for (; i < n; i++)
        dst[i] = (uint8_t)(255u - dst[i]);
    return 0;
}

typedef struct {
    bloom_t *b;
    ptrdiff_t in_stride, out_stride;
} engine_ctx_t;

static int run_engine(void *ctx, const uint8_t *src, uint8_t *dst)
{
    engine_ctx_t *e = ctx;
    const bloom_status_t st = bloom_process(e->b, src, e->in_stride, dst, e->out_stride);
    if (st != BLOOM_OK) {
        fprintf(stderr, "bloom_bench: bloom_process: %s\n", bloom_status_str(st));
        return 1;
    }
    return 0;
}

typedef struct {
    bcv_ctx_t *c;
    int kind;
    size_t stride;
} cv_ctx_t;

static int run_cv(void *ctx, const uint8_t *src, uint8_t *dst)
{
    cv_ctx_t *c = ctx;
    if (bcv_run(c->c, c->kind, src, c->stride, dst, c->stride)) {
        fprintf(stderr, "bloom_bench: OpenCV: %s\n", bcv_error());
        return 1;
    }
    return 0;
}

/* OpenCV rows: threads 0 = sequential (cv::setNumThreads(0)), -1 = default. */
static const struct {
    const char *name;
    int kind, threads;
} cv_rows[] = {
    {"OpenCV same algorithm: boxFilter + decimate", BCV_SAME_BOXFILTER, 0},
    {"OpenCV same algorithm: boxFilter + decimate", BCV_SAME_BOXFILTER, -1},
    {"OpenCV same algorithm: INTER_AREA + 2x2 box", BCV_SAME_AREA, 0},
    {"OpenCV same algorithm: INTER_AREA + 2x2 box", BCV_SAME_AREA, -1},
    {"OpenCV tutorial: resize + threshold + GaussianBlur + addWeighted", BCV_TUTORIAL, 0},
    {"OpenCV tutorial: resize + threshold + GaussianBlur + addWeighted", BCV_TUTORIAL, -1},
};
#define N_CV_ROWS ((int)(sizeof cv_rows / sizeof cv_rows[0]))

const char *bench_cv_row_name(int i)
{
    return cv_rows[i].name;
}

/* Sigma of the tutorial's Gaussian, full-resolution pixels: the standard
 * deviation per axis of the engine's own bloom for a single bright pixel at
 * 5 levels (measured with the float model: 15.06 px). */
#define TUTORIAL_SIGMA 15.0

/* ---- one frame size --------------------------------------------------------- */

size_info_t size_info[MAX_SIZES];
int opencv_threads_default = 0;

static int fmt_bytes(bloom_format_t f, int w, int h)
{
    return bloom_format_bpp(f) * w * h;
}

static void bench_size(int si, int w, int h, const opts_t *o, ring_t *ring)
{
    char err[512];
    const size_t n = (size_t)w * (size_t)h, rgb_bytes = n * 3u;
    uint8_t *scene = xmalloc(rgb_bytes);
    if (scene_make(o->image, w, h, scene, err, sizeof err))
        die("%s", err);
    const int first_row = nrows;

    /* Engine reference (first table row) on the scene, outside the ring. */
    bloom_config_t cfg0;
    if (bench_engine_config(&bench_engines[0], w, h, &cfg0))
        die("the first engine row (%s) must not be skipped", bench_engines[0].name);
    bloom_info_t info0;
    bloom_status_t st = bloom_query(&cfg0, &info0);
    if (st != BLOOM_OK)
        die("bloom_query: %s", bloom_status_str(st));
    if (cfg0.in_fmt != BLOOM_FMT_RGB888 || cfg0.out_fmt != BLOOM_FMT_RGB888)
        die("the first engine row (%s) must be RGB888->RGB888: it is the reference", bench_engines[0].name);
    uint8_t *ref = xmalloc(rgb_bytes), *out = xmalloc(rgb_bytes);
    {
        void *ws = xmalloc(info0.workspace_bytes);
        bloom_t *b;
        if ((st = bloom_init(&b, ws, info0.workspace_bytes, &cfg0)) != BLOOM_OK ||
            (st = bloom_process(b, scene, w * 3, ref, w * 3)) != BLOOM_OK)
            die("engine: %s", bloom_status_str(st));
        free(ws);
        if (bench_engines[0].teardown)
            bench_engines[0].teardown();
    }
    const double t = cfg0.threshold / 65536.0, s = cfg0.soft_knee / 65536.0;
    const double I = bloom_srgb_to_linear(cfg0.intensity / 65536.0);
    {
        size_t active = 0, changed = 0;
        for (size_t i = 0; i < n; i++) {
            int m = scene[3 * i];
            m = scene[3 * i + 1] > m ? scene[3 * i + 1] : m;
            m = scene[3 * i + 2] > m ? scene[3 * i + 2] : m;
            active += bloom_srgb_to_linear(m / 255.0) > t - t * s;
        }
        for (size_t i = 0; i < rgb_bytes; i++)
            changed += ref[i] != scene[i];
        size_info[si].active_src_pct = 100.0 * (double)active / (double)n;
        size_info[si].changed_out_pct = 100.0 * (double)changed / (double)rgb_bytes;
        size_info[si].levels = info0.levels;
    }
    printf("\n== %dx%d: L = %d levels, %.2f %% of source pixels above the knee's lower edge, "
           "bloom changes %.2f %% of the output bytes\n",
           w, h, info0.levels, size_info[si].active_src_pct, size_info[si].changed_out_pct);
    fflush(stdout);

    /* The floor. */
    ring_prepare(ring, scene, rgb_bytes, rgb_bytes, BLOOM_FMT_RGB888, n);
    floor_ctx_t fc = {rgb_bytes};
    row_t *r = new_row(w, h, "floor", "cold memcpy of the RGB888 frame");
    if (measure(ring, run_memcpy, &fc, o->warm, o->runs, r))
        exit(1);
    r = new_row(w, h, "floor", "read-modify-write pass (invert the frame in place)");
    if (measure(ring, run_rmw, &fc, o->warm, o->runs, r))
        exit(1);

    /* The engine rows. */
    for (int i = 0; i < bench_engine_count; i++) {
        const bench_engine_t *e = &bench_engines[i];
        r = new_row(w, h, "engine", e->name);
        bloom_config_t cfg;
        if (bench_engine_config(e, w, h, &cfg)) {
            snprintf(r->note, sizeof r->note, "skipped: not available");
            continue;
        }
        bloom_info_t info;
        if ((st = bloom_query(&cfg, &info)) != BLOOM_OK)
            die("bloom_query: %s", bloom_status_str(st));
        const size_t in_b = (size_t)fmt_bytes(cfg.in_fmt, w, h), out_b = (size_t)fmt_bytes(cfg.out_fmt, w, h);
        uint8_t *frame = xmalloc(in_b);
        if (scene_convert(scene, w, h, cfg.in_fmt, frame, (size_t)bloom_format_bpp(cfg.in_fmt) * (size_t)w))
            die("the scene has no %s input", e->name);
        ring_prepare(ring, frame, in_b, in_b > out_b ? in_b : out_b, cfg.in_fmt, n);
        void *ws = xmalloc(info.workspace_bytes);
        bloom_t *b;
        if ((st = bloom_init(&b, ws, info.workspace_bytes, &cfg)) != BLOOM_OK)
            die("bloom_init: %s", bloom_status_str(st));
        if (bench_engine_attach(b, &cfg))
            die("aux plane for %s", e->name);
        engine_ctx_t ec = {b, (ptrdiff_t)bloom_format_bpp(cfg.in_fmt) * w,
                           (ptrdiff_t)bloom_format_bpp(cfg.out_fmt) * w};
        if (measure(ring, run_engine, &ec, o->warm, o->runs, r))
            exit(1);
        if (e->teardown)
            e->teardown();
        snprintf(r->note, sizeof r->note, "workspace %zu bytes", info.workspace_bytes);
        free(ws);
        free(frame);
    }

    /* OpenCV. */
    bcv_params_t p;
    memset(&p, 0, sizeof p);
    p.levels = info0.levels;
    for (int k = 0; k <= info0.levels; k++) {
        p.level_w[k] = info0.level_w[k];
        p.level_h[k] = info0.level_h[k];
    }
    for (int c = 0; c < 256; c++)
        p.decode_lut[c] = (float)bloom_srgb_to_linear(c / 255.0);
    p.threshold = t;
    p.knee = t * s;
    p.intensity = I;
    p.tutorial_code = (int)(bloom_linear_to_srgb(t) * 255.0 + 0.5);
    p.tutorial_sigma = TUTORIAL_SIGMA;
    p.tutorial_weight = cfg0.intensity / 65536.0;
    bcv_ctx_t *cv = bcv_create(w, h, &p);
    if (!cv)
        die("OpenCV: %s", bcv_error());
    ring_prepare(ring, scene, rgb_bytes, rgb_bytes, BLOOM_FMT_RGB888, n);
    for (int i = 0; i < N_CV_ROWS; i++) {
        r = new_row(w, h, "opencv", cv_rows[i].name);
        r->threads = bcv_set_threads(cv_rows[i].threads);
        if (cv_rows[i].threads == 0)
            r->threads = 1; /* setNumThreads(0): sequential */
        else
            opencv_threads_default = r->threads;
        cv_ctx_t cc = {cv, cv_rows[i].kind, (size_t)w * 3u};
        if (measure(ring, run_cv, &cc, o->warm, o->runs, r))
            exit(1);
        if (run_cv(&cc, scene, out))
            exit(1);
        agreement(ref, out, rgb_bytes, r);
        printf("   %-66s %2d thr %9.3f ms\n", r->name, r->threads, r->median_ms);
        fflush(stdout);
    }
    bcv_set_threads(-1);

    /* Paired rounds of the contenders of the issue-7 targets (all RGB888,
     * one thread), OpenCV still set up. */
    {
        contender_t c[MAX_CONTENDERS];
        int nc = 0;
        c[nc++] = (contender_t){"cold memcpy of the RGB888 frame", run_memcpy, &fc};
        bloom_t *eb[3] = {NULL, NULL, NULL};
        void *ews[3] = {NULL, NULL, NULL};
        engine_ctx_t ectx[3];
        for (int i = 0, k = 0; i < bench_engine_count && k < 3; i++) {
            const bench_engine_t *e = &bench_engines[i];
            bloom_config_t cfg;
            /* the reference row, the RGB888 row without AVX2 if there is one,
             * and the 16-bit samples' RGB888 row (issue 21: both widths) */
            if (i > 0 && !(e->flags == BLOOM_FLAG_NO_AVX2 && !e->setup) &&
                strcmp(e->name, "RGB888->RGB888,s16"))
                continue;
            if (bench_engine_config(e, w, h, &cfg) || cfg.in_fmt != BLOOM_FMT_RGB888 ||
                cfg.out_fmt != BLOOM_FMT_RGB888)
                continue;
            bloom_info_t info;
            if ((st = bloom_query(&cfg, &info)) != BLOOM_OK)
                die("bloom_query: %s", bloom_status_str(st));
            ews[k] = xmalloc(info.workspace_bytes);
            if ((st = bloom_init(&eb[k], ews[k], info.workspace_bytes, &cfg)) != BLOOM_OK)
                die("bloom_init: %s", bloom_status_str(st));
            ectx[k] = (engine_ctx_t){eb[k], (ptrdiff_t)w * 3, (ptrdiff_t)w * 3};
            c[nc++] = (contender_t){e->name, run_engine, &ectx[k]};
            k++;
        }
        cv_ctx_t pc[3];
        static const int kinds[3] = {BCV_SAME_BOXFILTER, BCV_SAME_AREA, BCV_TUTORIAL};
        static const int names[3] = {0, 2, 4};
        bcv_set_threads(0);
        for (int i = 0; i < 3; i++) {
            pc[i] = (cv_ctx_t){cv, kinds[i], (size_t)w * 3u};
            c[nc++] = (contender_t){cv_rows[names[i]].name, run_cv, &pc[i]};
        }
        const int first_paired = nrows;
        paired(ring, c, nc, o->runs, w, h);
        bcv_set_threads(-1);
        for (int k = 0; k < 3; k++)
            free(ews[k]);
        bcv_destroy(cv);
        for (int i = first_paired; i < nrows; i++)
            printf("   paired: %-58s median %9.3f ms  x memcpy %7.2f  x engine %7.3f\n", rows[i].name,
                   rows[i].median_ms, rows[i].x_memcpy, rows[i].x_engine);
        fflush(stdout);
    }

    /* The float model, for scale, at the sizes asked for. */
    for (int m = 0; m < o->n_model; m++) {
        if (o->model_w[m] != w || o->model_h[m] != h)
            continue;
        r = new_row(w, h, "model", "float reference model (bloom_model_run, double)");
        uint32_t *codes = xmalloc(rgb_bytes * sizeof *codes), *oc = xmalloc(rgb_bytes * sizeof *oc);
        for (size_t i = 0; i < rgb_bytes; i++)
            codes[i] = scene[i];
        bloom_model_params_t mp;
        memset(&mp, 0, sizeof mp);
        mp.width = w;
        mp.height = h;
        mp.levels = cfg0.levels;
        mp.threshold = t;
        mp.soft_knee = s;
        mp.intensity = cfg0.intensity / 65536.0;
        const int mx[3] = {255, 255, 255};
        const double c0 = cpu_s(), t0 = bench_now_s();
        if (bloom_model_run(&mp, codes, mx, oc, mx, NULL) < 0)
            die("bloom_model_run failed (%s)", "bad arguments or out of memory");
        r->median_ms = r->min_ms = 1e3 * (bench_now_s() - t0);
        r->cpu_ms = 1e3 * (cpu_s() - c0);
        r->runs = 1;
        for (size_t i = 0; i < rgb_bytes; i++)
            out[i] = (uint8_t)oc[i];
        agreement(ref, out, rgb_bytes, r);
        snprintf(r->note, sizeof r->note, "one run, no warm-up");
        free(codes);
        free(oc);
    }

    /* Ratios. */
    const row_t *mcr = NULL, *enr = NULL;
    for (int i = first_row; i < nrows; i++) {
        if (!strcmp(rows[i].group, "floor") && !mcr)
            mcr = &rows[i];
        if (!strcmp(rows[i].group, "engine") && !enr && rows[i].runs)
            enr = &rows[i];
    }
    for (int i = first_row; i < nrows; i++) {
        row_t *q = &rows[i];
        if (!strcmp(q->group, "paired"))
            continue; /* their own ratios (paired()) */
        q->x_memcpy = q->x_engine = 0.0;
        q->xc_memcpy = q->xc_engine = -1.0;
        if (!q->runs)
            continue;
        if (mcr && mcr->median_ms > 0.0)
            q->x_memcpy = q->median_ms / mcr->median_ms;
        if (enr && enr->median_ms > 0.0)
            q->x_engine = q->median_ms / enr->median_ms;
        if (q->threads == 1 && mcr && mcr->cpu_ms > 0.0)
            q->xc_memcpy = q->cpu_ms / mcr->cpu_ms;
        if (q->threads == 1 && enr && enr->cpu_ms > 0.0)
            q->xc_engine = q->cpu_ms / enr->cpu_ms;
    }
    printf("   %-44s %3s %4s %10s %9s %9s %9s %8s %8s %9s %17s\n", "variant", "thr", "runs", "median ms",
           "CPU ms", "x memcpy", "x engine", "max LSB", "exact %", "signed", "above / below");
    for (int i = first_row; i < nrows; i++) {
        const row_t *q = &rows[i];
        char nm[45];
        snprintf(nm, sizeof nm, "%s", q->name);
        if (!q->runs) {
            printf("   %-44s %s\n", nm, q->note);
            continue;
        }
        printf("   %-44s %3d %4d %10.3f %9.3f %9.2f %9.3f", nm, q->threads, q->runs, q->median_ms, q->cpu_ms,
               q->x_memcpy, q->x_engine);
        if (q->agree_max >= 0)
            printf(" %8d %8.3f %+9.5f %8lld/%-8lld\n", q->agree_max, q->agree_exact, q->agree_signed,
                   q->agree_above, q->agree_below);
        else
            printf(" %8s %8s %9s %17s\n", "-", "-", "-", "-");
    }
    fflush(stdout);
    free(ref);
    free(out);
    free(scene);
}

/* ---- main ------------------------------------------------------------------------ */

int main(int argc, char **argv)
{
    const char *csv = "build/bench.csv", *md = "build/bench/results.md";
    int sw[MAX_SIZES] = {640, 1280, 1920}, sh[MAX_SIZES] = {480, 720, 1080}, nsizes = 3;
    long ring_mb = 0;
    opts_t o;
    memset(&o, 0, sizeof o);
    o.image = SCENE_IMAGE_DEFAULT;
    o.runs = 15;
    o.warm = 2;
    o.model_w[0] = 640;
    o.model_h[0] = 480;
    o.n_model = 1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--quick")) {
            o.runs = 3;
            o.warm = 1;
            continue;
        }
        if (!v)
            die("%s needs a value (see the top of sim/bench/bench.c)", a);
        i++;
        if (!strcmp(a, "--csv"))
            csv = v;
        else if (!strcmp(a, "--md"))
            md = v;
        else if (!strcmp(a, "--image"))
            o.image = v;
        else if (!strcmp(a, "--sizes")) {
            if ((nsizes = scene_parse_sizes(v, sw, sh, MAX_SIZES)) < 1)
                die("bad --sizes '%s' (WxH,WxH,...)", v);
        } else if (!strcmp(a, "--model-sizes")) {
            if ((o.n_model = scene_parse_sizes(v, o.model_w, o.model_h, MAX_SIZES)) < 0)
                die("bad --model-sizes '%s' (WxH,... or none)", v);
        } else if (!strcmp(a, "--runs")) {
            if ((o.runs = atoi(v)) < 1)
                die("bad --runs '%s'", v);
        } else if (!strcmp(a, "--warmup")) {
            if ((o.warm = atoi(v)) < 0)
                die("bad --warmup '%s'", v);
        } else if (!strcmp(a, "--ring-mb")) {
            if ((ring_mb = atol(v)) < 1)
                die("bad --ring-mb '%s'", v);
        } else
            die("unknown option %s", a);
    }

    bench_read_machine();
    load_start = loadavg1();
    time_t now = time(NULL);
    strftime(date_utc, sizeof date_utc, "%Y-%m-%d %H:%M UTC", gmtime(&now));
    size_t llc = llc_sysfs > llc_sysconf ? llc_sysfs : llc_sysconf;
    if (!llc)
        llc = (size_t)64 << 20; /* unknown: assume a large one */
    size_t ring_bytes = ring_mb ? (size_t)ring_mb << 20 : 4u * llc;
    size_t biggest = 0;
    for (int s = 0; s < nsizes; s++) {
        const size_t fb = (size_t)sw[s] * (size_t)sh[s] * 4u; /* XRGB8888 is the widest */
        if (fb > biggest)
            biggest = fb;
    }
    if (ring_bytes < 16u * biggest)
        ring_bytes = 16u * biggest;
    ring_bytes = (ring_bytes + ((size_t)1 << 20) - 1) & ~(((size_t)1 << 20) - 1);

    const char *cv_version = bcv_version(), *cv_parallel = bcv_parallel_framework();
    printf("bloom_bench: %s\n  CPU %s, %d CPUs online, LLC L%d %zu KiB (sysfs) / %zu KiB (sysconf)\n"
           "  rings 2 x %zu MiB; engine built by %s %s with %s\n  OpenCV %s (%s)\n",
           date_utc, cpu_model, ncpu, llc_level, llc_sysfs >> 10, llc_sysconf >> 10, ring_bytes >> 20,
           BENCH_CC, __VERSION__, BENCH_FLAGS, cv_version, cv_parallel);
    fflush(stdout);

    ring_t ring;
    memset(&ring, 0, sizeof ring);
    ring_alloc(&ring, ring_bytes);
    for (int s = 0; s < nsizes; s++)
        bench_size(s, sw[s], sh[s], &o, &ring);

    load_end = loadavg1();
    write_csv(csv);
    write_md(md, sw, sh, nsizes, &o, ring_bytes, cv_version, cv_parallel);
    printf("\nwrote %s and %s\n", csv, md);
    free(ring.src);
    free(ring.dst);
    return 0;
}
