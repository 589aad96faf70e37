/* dual_vs_gauss: the Arm guide's claim that dual filtering costs about a
 * fourteenth of a Gaussian blur of similar reach at 1080p, measured.
 *
 * - Reach: a point of light pushed through the arm preset (RGBQ16, threshold
 *   0, intensity 1, tint white, debug view: the output is B) at the frame
 *   size and depth under test; the standard deviation of that point-spread
 *   function per axis, averaged (RMS) over a few positions (the pyramid is
 *   not shift-invariant). "Similar reach" = a Gaussian of that sigma.
 * - The Gaussian pipeline: the same prefilter (Rec.709 luminance, Q16
 *   weights, soft knee on one channel) at full resolution, a separable
 *   integer Gaussian (Q16 weights summing to 65536, radius ceil(3 sigma),
 *   clamped edges) horizontally then vertically on the one-channel plane,
 *   the same composite and encode. Plain C, no SIMD, like the arm preset.
 * - Timing: the arm engine (bloom_process) and the Gaussian pipeline on the
 *   same RGB888 scene (sim/bench/scene.h), interleaved, median of repeats;
 *   also the default preset for scale. With --once NAME the program runs one
 *   pipeline once (for callgrind: make dual-vs-gauss toggles collection on
 *   run_arm / run_gauss / run_default).
 *
 * Usage: dual_vs_gauss [--size WxH] [--levels N] [--repeats N] [--once arm|gauss|default] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bloom.h"
#include "bloom_kernels.h"
#include "bloom_pixel.h"
#include "scene.h"

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    return p;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_d(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_d);
    return n & 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

typedef struct {
    bloom_t *b;
    void *ws;
} eng_t;

static eng_t eng_new(const bloom_config_t *c)
{
    eng_t e;
    const size_t n = bloom_workspace_size(c);
    e.ws = NULL;
    if (!n || posix_memalign(&e.ws, 64, n) || bloom_init(&e.b, e.ws, n, c) != BLOOM_OK) {
        fprintf(stderr, "bloom_init failed\n");
        exit(2);
    }
    return e;
}

/* ---- reach of the dual-filter pyramid --------------------------------- */

static void psf_sigma(int w, int h, int levels, double *sx, double *sy, double *mass)
{
    bloom_config_t c;
    bloom_config_default(&c, w, h);
    bloom_config_preset(&c, BLOOM_PRESET_ARM);
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
    c.threshold = 0;
    c.soft_knee = 0;
    c.intensity = BLOOM_ONE;
    c.levels = levels;
    c.flags |= BLOOM_FLAG_DEBUG_VIEW;
    eng_t e = eng_new(&c);
    const size_t stride = (size_t)w * 12u;
    uint32_t *in = xmalloc(stride * (size_t)h), *out = xmalloc(stride * (size_t)h);
    const int pos[][2] = {{w / 2, h / 2},           {w / 2 + 1, h / 2 + 1}, {w / 2 + 7, h / 2 - 5},
                          {w / 2 + 13, h / 2 + 10}, {w / 3 + 3, h / 3 + 2}, {w / 3 + 16, h / 3 + 9}};
    const int np = (int)(sizeof pos / sizeof pos[0]);
    double vx = 0, vy = 0, m = 0;
    for (int p = 0; p < np; p++) {
        memset(in, 0, stride * (size_t)h);
        const uint32_t v = BLOOM_MAX_LINEAR; /* 256.0 in one pixel */
        uint32_t *px = in + ((size_t)pos[p][1] * (size_t)w + (size_t)pos[p][0]) * 3u;
        px[0] = px[1] = px[2] = v;
        bloom_process(e.b, in, (ptrdiff_t)stride, out, (ptrdiff_t)stride);
        double s = 0, mx = 0, my = 0, qx = 0, qy = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                const double b = out[((size_t)y * (size_t)w + (size_t)x) * 3u];
                s += b;
                mx += b * x;
                my += b * y;
            }
        mx /= s;
        my /= s;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                const double b = out[((size_t)y * (size_t)w + (size_t)x) * 3u];
                qx += b * (x - mx) * (x - mx);
                qy += b * (y - my) * (y - my);
            }
        vx += qx / s;
        vy += qy / s;
        m += s / (double)v;
    }
    *sx = sqrt(vx / np);
    *sy = sqrt(vy / np);
    *mass = m / np;
    free(in);
    free(out);
    free(e.ws);
}

/* ---- the Gaussian pipeline --------------------------------------------- */

typedef struct {
    int w, h, R;
    uint32_t wt[1024]; /* Q16 weights of taps -R .. R */
    uint32_t *p, *t;   /* full-resolution planes: prefiltered, horizontal pass */
    uint32_t *pad;     /* a padded row */
    uint64_t *acc;     /* vertical accumulators */
    uint32_t *v;       /* composite row, 3 words per pixel */
    bloom_knee_t kn;
    uint32_t I;
} gauss_t;

static void gauss_init(gauss_t *g, int w, int h, double sigma, const bloom_config_t *c, uint32_t I_q)
{
    g->w = w;
    g->h = h;
    g->R = (int)ceil(3.0 * sigma);
    if (g->R > 511)
        g->R = 511;
    double sum = 0, f[1024];
    for (int i = -g->R; i <= g->R; i++)
        sum += f[i + g->R] = exp(-(double)i * i / (2.0 * sigma * sigma));
    uint32_t tot = 0;
    for (int i = 0; i <= 2 * g->R; i++)
        tot += g->wt[i] = (uint32_t)floor(f[i] / sum * 65536.0 + 0.5);
    g->wt[g->R] += 65536u - tot; /* exactly 65536 */
    g->p = xmalloc((size_t)w * (size_t)h * 4u);
    g->t = xmalloc((size_t)w * (size_t)h * 4u);
    g->pad = xmalloc(((size_t)w + 2u * (size_t)g->R) * 4u);
    g->acc = xmalloc((size_t)w * 8u);
    g->v = xmalloc((size_t)w * 12u);
    g->kn.t = c->threshold << BLOOM_Q16_SHIFT;
    g->kn.k = (uint32_t)(((uint64_t)g->kn.t * c->soft_knee + 32768u) >> 16);
    g->I = I_q;
}

static __attribute__((noinline)) void run_gauss(gauss_t *g, const uint8_t *src, uint8_t *dst)
{
    const int w = g->w, h = g->h, R = g->R;
    const uint32_t t = g->kn.t, k = g->kn.k, cut = t > k ? t - k : 0u, hi = t + k;
    /* prefilter: luminance and the one-channel knee, full resolution */
    for (int y = 0; y < h; y++) {
        const uint8_t *s = src + (size_t)y * (size_t)w * 3u;
        uint32_t *p = g->p + (size_t)y * (size_t)w;
        for (int x = 0; x < w; x++) {
            const uint32_t yv = (uint32_t)((13933u * (uint64_t)bloom_srgb_dec8[s[3 * x]] +
                                            46871u * (uint64_t)bloom_srgb_dec8[s[3 * x + 1]] +
                                            4732u * (uint64_t)bloom_srgb_dec8[s[3 * x + 2]] + 32768u) >>
                                           16);
            uint32_t o;
            if (yv <= cut) {
                o = 0;
            } else if (yv >= hi) {
                o = yv - t;
            } else {
                const uint64_t xx = yv - cut;
                const uint32_t soft = (uint32_t)((xx * xx + 2u * (uint64_t)k) / (4u * (uint64_t)k));
                o = yv > t && yv - t > soft ? yv - t : soft;
            }
            p[x] = o;
        }
    }
    /* horizontal */
    for (int y = 0; y < h; y++) {
        const uint32_t *p = g->p + (size_t)y * (size_t)w;
        uint32_t *q = g->t + (size_t)y * (size_t)w;
        for (int i = 0; i < R; i++) {
            g->pad[i] = p[0];
            g->pad[R + w + i] = p[w - 1];
        }
        memcpy(g->pad + R, p, (size_t)w * 4u);
        for (int x = 0; x < w; x++) {
            const uint32_t *a = g->pad + x;
            uint64_t s = 0;
            for (int i = 0; i <= 2 * R; i++)
                s += (uint64_t)g->wt[i] * a[i];
            q[x] = (uint32_t)((s + 32768u) >> 16);
        }
    }
    /* vertical, then composite and encode */
    for (int y = 0; y < h; y++) {
        memset(g->acc, 0, (size_t)w * 8u);
        for (int i = -R; i <= R; i++) {
            const int yy = y + i < 0 ? 0 : y + i >= h ? h - 1 : y + i;
            const uint32_t *r = g->t + (size_t)yy * (size_t)w;
            const uint64_t wi = g->wt[i + R];
            for (int x = 0; x < w; x++)
                g->acc[x] += wi * r[x];
        }
        const uint8_t *s = src + (size_t)y * (size_t)w * 3u;
        bloom_decode_row(BLOOM_FMT_RGB888, false, s, g->v, w);
        for (int x = 0; x < w; x++) {
            const uint64_t b = (g->acc[x] + 32768u) >> 16;
            const uint64_t pb = (g->I * b + 32768u) >> 16;
            for (int c = 0; c < 3; c++) {
                const uint64_t v = g->v[3 * x + c] + pb;
                g->v[3 * x + c] = v > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)v;
            }
        }
        bloom_encode_row(BLOOM_FMT_RGB888, false, g->v, dst + (size_t)y * (size_t)w * 3u, w);
    }
}

/* Not tail calls, not folded together: callgrind toggles on these names. */
static volatile int sink;

static __attribute__((noinline)) void run_arm(eng_t *e, const uint8_t *src, uint8_t *dst, int w)
{
    sink = sink + 1 + (int)bloom_process(e->b, src, (ptrdiff_t)w * 3, dst, (ptrdiff_t)w * 3);
}

static __attribute__((noinline)) void run_default(eng_t *e, const uint8_t *src, uint8_t *dst, int w)
{
    sink = sink + 2 + (int)bloom_process(e->b, src, (ptrdiff_t)w * 3, dst, (ptrdiff_t)w * 3);
}

int main(int argc, char **argv)
{
    int w = 1920, h = 1080, levels = 5, repeats = 7;
    const char *once = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--size") && i + 1 < argc && sscanf(argv[i + 1], "%dx%d", &w, &h) == 2)
            i++;
        else if (!strcmp(argv[i], "--levels") && i + 1 < argc)
            levels = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--repeats") && i + 1 < argc)
            repeats = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--once") && i + 1 < argc)
            once = argv[++i];
        else {
            fprintf(stderr, "usage: %s [--size WxH] [--levels N] [--repeats N] [--once arm|gauss|default]\n",
                    argv[0]);
            return 2;
        }
    }
    if (repeats < 1 || repeats > 101)
        repeats = 7;
    double sx, sy, mass;
    psf_sigma(w, h, levels, &sx, &sy, &mass);
    const double sigma = sqrt(0.5 * (sx * sx + sy * sy));

    bloom_config_t ca, cu;
    bloom_config_default(&cu, w, h);
    cu.levels = levels;
    cu.threshold = BLOOM_Q16(0.6);
    cu.intensity = BLOOM_Q16(1.5);
    ca = cu;
    bloom_config_preset(&ca, BLOOM_PRESET_ARM);
    ca.levels = levels;
    ca.threshold = cu.threshold;
    ca.intensity = cu.intensity;
    bloom_info_t ia;
    if (bloom_query(&ca, &ia) != BLOOM_OK)
        return 2;
    eng_t ea = eng_new(&ca), eu = eng_new(&cu);
    gauss_t g;
    gauss_init(&g, w, h, sigma, &ca, ia.intensity_q);

    uint8_t *src = xmalloc((size_t)w * (size_t)h * 3u), *dst = xmalloc((size_t)w * (size_t)h * 3u);
    char err[256];
    if (scene_make(SCENE_IMAGE_DEFAULT, w, h, src, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (once) {
        if (!strcmp(once, "arm"))
            run_arm(&ea, src, dst, w);
        else if (!strcmp(once, "gauss"))
            run_gauss(&g, src, dst);
        else if (!strcmp(once, "default"))
            run_default(&eu, src, dst, w);
        else
            return 2;
        printf("%s once at %dx%d, %d levels (sigma %.2f, Gaussian radius %d)\n", once, w, h, ia.levels, sigma,
               g.R);
        return 0;
    }
    printf("dual_vs_gauss %dx%d, %d levels (requested %d), RGB888 sRGB scene\n", w, h, ia.levels, levels);
    printf("arm point-spread function: sigma x %.2f, y %.2f px (RMS over 6 positions), mass %.4f\n", sx, sy,
           mass);
    printf("Gaussian of equal sigma %.2f: radius %d, %d taps per pass, 2 passes at full resolution\n", sigma,
           g.R, 2 * g.R + 1);
    double *ta = xmalloc((size_t)repeats * sizeof(double)), *tg = xmalloc((size_t)repeats * sizeof(double)),
           *tu = xmalloc((size_t)repeats * sizeof(double));
    run_arm(&ea, src, dst, w); /* warm-up */
    run_gauss(&g, src, dst);
    run_default(&eu, src, dst, w);
    for (int r = 0; r < repeats; r++) {
        double t0 = now();
        run_arm(&ea, src, dst, w);
        double t1 = now();
        run_gauss(&g, src, dst);
        double t2 = now();
        run_default(&eu, src, dst, w);
        double t3 = now();
        ta[r] = t1 - t0;
        tg[r] = t2 - t1;
        tu[r] = t3 - t2;
    }
    const double ma = median(ta, repeats), mg = median(tg, repeats), mu = median(tu, repeats);
    printf("median of %d: arm %.2f ms, Gaussian %.2f ms, default preset %.2f ms\n", repeats, 1e3 * ma,
           1e3 * mg, 1e3 * mu);
    printf("time ratio Gaussian / arm: %.1f x (arm / default preset: %.2f)\n", mg / ma, ma / mu);
    free(ta);
    free(tg);
    free(tu);
    free(src);
    free(dst);
    free(ea.ws);
    free(eu.ws);
    return 0;
}
