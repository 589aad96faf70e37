/* The float-model budget of every preset in every output format: peak,
 * % exact and the signed mean (with the counts above and below), on a
 * random corpus and on each real image of tests/data, each asserted
 * (bounds below): peak, % exact, and the signed mean, so that no
 * one-sided error can hide in a mean of absolute errors.
 * The bit-exact checks against the bit-true models are in the preset tests
 * and test_conformance; here the bit-true difference is only counted (it
 * must be 0 too). */
#include <stdlib.h>

#include "imgframe.h"
#include "preset_conform.h"

static const bloom_format_t OUTS[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                      BLOOM_FMT_RGBQ16};
static const char *const OUT_NAME[] = {"RGB888", "XRGB8888", "RGB565", "RGBQ16"};
static const char *const IMAGES[] = {"rocket_floodlights.ppm", "hubble_deep_field.ppm", "studio_lamps.pfm",
                                     "hall_lamps.pfm"};
#define NIMG (sizeof IMAGES / sizeof IMAGES[0])

/* Bounds at the presets' defaults, measured when the bias was removed
 * (make test prints the figures): 8/6/5-bit codes peak 1 LSB, at least
 * the preset's floor of % exact (99.92 .. 99.97, README's presets table),
 * |signed mean| <= 0.0015 LSB (ERR_BIAS_MAX); RGBQ16 words
 * (LSB 2^-16, 1/16 of the internal Q12.20 step) peak 2, at least 95.5 %
 * exact, |signed mean| <= 0.03 LSB. The RGBQ16 bound is looser because its
 * LSB is so fine: what is left there (up to 0.015, a quarter of an internal
 * LSB) comes from rounding values whose fractions are not uniform (a glow
 * fading into black) and, on random frames, changes sign from seed to
 * seed; the one-sided rounding that was removed had put +0.47 there. */
static int peak_bound(bloom_format_t out)
{
    return out == BLOOM_FMT_RGBQ16 ? 2 : 1;
}
/* Code outputs: the floor README's presets table prints, per preset (the
 * lowest % exact measured over the corpora and the three code formats,
 * rounded down). */
static double exact_floor(bloom_preset_t p, bloom_format_t out)
{
    static const double floors[BLOOM_PRESET_COUNT] = {
        [BLOOM_PRESET_UNITY] = 99.92,       [BLOOM_PRESET_GAMEDEV] = 99.95, [BLOOM_PRESET_XNA] = 99.97,
        [BLOOM_PRESET_ATTENUATION] = 99.93, [BLOOM_PRESET_ARM] = 99.96,     [BLOOM_PRESET_COD] = 99.92};
    return out == BLOOM_FMT_RGBQ16 ? 95.5 : floors[p];
}
static double bias_bound(bloom_format_t out)
{
    return out == BLOOM_FMT_RGBQ16 ? 0.03 : ERR_BIAS_MAX;
}

/* A depth plane for the attenuation preset: a ramp, and a flat third at
 * the middle depth (a flat depth puts one rounding of the factor on every
 * pixel there: the case that showed the Q16 factor's bias). */
static uint8_t *depth_plane(int w, int h)
{
    uint8_t *d = (uint8_t *)xmalloc((size_t)w * (size_t)h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            d[(size_t)y * (size_t)w + (size_t)x] =
                (uint8_t)(x < w / 3 ? 128 : (x * 255) / (w > 1 ? w - 1 : 1));
    return d;
}

typedef struct {
    errstat_t e;
    long long bt_diff;
    int runs;
} acc_t;

static void run_one(acc_t *a, const bloom_config_t *c, const frame_t *src)
{
    uint8_t *aux = NULL;
    if (c->aux_fmt == BLOOM_AUX_U8)
        aux = depth_plane(c->width, c->height);
    preset_conform_t r = preset_conform(c, src, aux, c->width);
    free(aux);
    CHECKF(r.ok, "%s: engine or model failed", bloom_preset_name(c->preset));
    errstat_merge(&a->e, &r.vs_float);
    a->bt_diff += r.bittrue_diff;
    a->runs++;
}

static void config_for(bloom_config_t *c, bloom_preset_t p, int w, int h, bloom_format_t in,
                       bloom_format_t out)
{
    bloom_config_default(c, w, h);
    bloom_config_preset(c, p);
    c->in_fmt = in;
    c->out_fmt = out;
    if (p == BLOOM_PRESET_ATTENUATION)
        c->aux_fmt = BLOOM_AUX_U8;
    if ((in == BLOOM_FMT_RGBQ16 || in == BLOOM_FMT_RGBF32) && p != BLOOM_PRESET_XNA &&
        p != BLOOM_PRESET_GAMEDEV)
        c->threshold = BLOOM_Q16(2.0); /* HDR: the lamps only, as test_conformance */
}

static void verdict_at(const char *what, bloom_format_t out, const acc_t *a, double floor, double bias)
{
    errstat_print(what, &a->e);
    CHECKF(a->bt_diff == 0, "%s: %lld samples differ from the bit-true model", what, a->bt_diff);
    CHECKF(a->e.peak <= peak_bound(out), "%s: peak %d above %d", what, a->e.peak, peak_bound(out));
    CHECKF(errstat_exact_pct(&a->e) >= floor, "%s: %.3f%% exact below %.2f%%", what, errstat_exact_pct(&a->e),
           floor);
    CHECKF(fabs(errstat_mean(&a->e)) <= bias, "%s: signed mean %+.5f LSB beyond %.4f", what,
           errstat_mean(&a->e), bias);
}
static void verdict(const char *what, bloom_preset_t p, bloom_format_t out, const acc_t *a)
{
    verdict_at(what, out, a, exact_floor(p, out), bias_bound(out));
}

/* HDR words above the largest linear sample (2^24 - 1, 256.0) clamped as
 * the engine clamps them on input (fixed-point.md): the float model keeps
 * them, so a light brighter than 256 would measure the documented
 * saturation, not the rounding. */
static long long clamp_hdr(frame_t *f)
{
    long long n = 0;
    if (f->fmt != BLOOM_FMT_RGBQ16)
        return 0;
    for (int y = 0; y < f->h; y++)
        for (int i = 0; i < f->w * 3; i++) {
            uint32_t v;
            uint8_t *p = f->p + (size_t)y * f->stride + 4u * (size_t)i;
            memcpy(&v, p, 4);
            if (v > BLOOM_MAX_LINEAR) {
                v = BLOOM_MAX_LINEAR;
                memcpy(p, &v, 4);
                n++;
            }
        }
    return n;
}

/* Dark HDR scenes: the lamps' rooms at an exposure where most of the
 * light is far below 1.0, at thresholds 0 and 1.0 (the presets that take
 * one), read as linear floats (RGBF32, the engine's step 2^-20) and
 * asserted as every other input; the same floats as RGBQ16 words (step
 * 2^-16) are printed beside them: against the float model on the floats,
 * that format's quantization at the foot of the sRGB curve is one-sided
 * (fixed-point.md, "Linear input"), which is why RGBF32 exists. */
static const struct {
    const char *img;
    double scale;
} DARK[] = {{"hall_lamps.pfm", 1.0 / 64}, {"studio_lamps.pfm", 1.0 / 256}};

/* The default preset on the floats rounded to RGBQ16 words, against the
 * float model on the floats themselves: printed, not asserted (it is the
 * input format's step, not the engine's rounding). */
static void q16_beside(const frame_t *f, int thr, const char *what)
{
    frame_t q = frame_alloc(f->w, f->h, BLOOM_FMT_RGBQ16, 0), out;
    for (int y = 0; y < f->h; y++)
        for (int i = 0; i < 3 * f->w; i++) {
            float v;
            memcpy(&v, f->p + (size_t)y * f->stride + 4u * (size_t)i, 4);
            const uint32_t w = (uint32_t)((double)v * 65536.0 + 0.5);
            memcpy(q.p + (size_t)y * q.stride + 4u * (size_t)i, &w, 4);
        }
    bloom_config_t c;
    config_for(&c, BLOOM_PRESET_UNITY, f->w, f->h, BLOOM_FMT_RGBF32, BLOOM_FMT_RGB888);
    c.threshold = thr ? BLOOM_Q16(1.0) : 0;
    int smax[3], dmax[3];
    fmt_max(BLOOM_FMT_RGBF32, smax);
    fmt_max(BLOOM_FMT_RGB888, dmax);
    bloom_model_params_t pf;
    model_params(&c, 0, &pf);
    c.in_fmt = BLOOM_FMT_RGBQ16;
    const size_t n = (size_t)f->w * (size_t)f->h * 3u;
    uint32_t *in = frame_codes(f), *fl = (uint32_t *)xmalloc(n * sizeof *fl);
    if (core_output(&c, &q, NULL, 0, &out) == BLOOM_OK &&
        bloom_model_run(&pf, in, smax, fl, dmax, NULL) > 0) {
        uint32_t *core = frame_codes(&out);
        errstat_t e;
        memset(&e, 0, sizeof e);
        for (size_t i = 0; i < n; i++)
            errstat_add(&e, (long long)core[i] - (long long)fl[i]);
        errstat_print(what, &e);
        free(core);
        frame_free(&out);
    }
    free(in);
    free(fl);
    frame_free(&q);
}

static void dark_hdr(bloom_preset_t p)
{
    const char *pn = bloom_preset_name(p);
    for (size_t d = 0; d < sizeof DARK / sizeof DARK[0]; d++) {
        frame_t f;
        CHECKF(imgframe_load_f32(DARK[d].img, DARK[d].scale, &f), "%s: cannot be read", DARK[d].img);
        if (!f.p)
            continue;
        for (int ti = 0; ti < 2; ti++) {
            if (ti == 1 && (p == BLOOM_PRESET_XNA || p == BLOOM_PRESET_GAMEDEV))
                break;                          /* their thresholds are their own (presets.md) */
            for (size_t o = 0; o < 3; o += 2) { /* RGB888 and RGB565 (XRGB8888 has RGB888's codes) */
                char what[128];
                acc_t a;
                memset(&a, 0, sizeof a);
                bloom_config_t c;
                config_for(&c, p, f.w, f.h, BLOOM_FMT_RGBF32, OUTS[o]);
                if (p != BLOOM_PRESET_XNA && p != BLOOM_PRESET_GAMEDEV)
                    c.threshold = ti ? BLOOM_Q16(1.0) : 0;
                run_one(&a, &c, &f);
                snprintf(what, sizeof what, "%s %s x1/%g t%d RGBF32 -> %s", pn, DARK[d].img,
                         1.0 / DARK[d].scale, ti, OUT_NAME[o]);
                /* Dark scenes put most samples at the foot of the curve, where
                 * a code is a few internal LSB wide: fewer exact (floors
                 * measured, rounded down). gamedev's pure 2.2 power has its
                 * first 8-bit threshold at (0.5/255)^2.2 = 1.1e-6, 1.2 LSB of
                 * Q12.20: floats that dark round coarsely there, one-sided
                 * (+0.0098 measured on studio at 1/256); its bound is that,
                 * the others' is ERR_BIAS_MAX. */
                const int gd = p == BLOOM_PRESET_GAMEDEV;
                verdict_at(what, OUTS[o], &a, gd ? 98.5 : 99.85, gd ? 0.011 : ERR_BIAS_MAX);
                if (p == BLOOM_PRESET_UNITY && o == 0) {
                    snprintf(what, sizeof what, "(not asserted) the same floats as RGBQ16 words -> RGB888");
                    q16_beside(&f, ti, what);
                }
            }
        }
        frame_free(&f);
    }
}

int main(void)
{
    frame_t img[NIMG];
    int have[NIMG];
    for (size_t i = 0; i < NIMG; i++) {
        have[i] = imgframe_load(IMAGES[i], &img[i]);
        CHECKF(have[i], "%s: cannot be read", IMAGES[i]);
        const long long n = have[i] ? clamp_hdr(&img[i]) : 0;
        if (n)
            printf("%s: %lld samples above 256.0 clamped to it (as the engine reads them)\n", IMAGES[i], n);
    }
    const int sizes[][2] = {{64, 48}, {257, 131}, {300, 200}};
    const bloom_format_t ins[] = {BLOOM_FMT_RGB888, BLOOM_FMT_RGB565, BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBF32};
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p))
            continue;
        const char *pn = bloom_preset_name((bloom_preset_t)p);
        for (size_t o = 0; o < sizeof OUTS / sizeof OUTS[0]; o++) {
            char what[96];
            acc_t a;
            memset(&a, 0, sizeof a);
            for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
                for (size_t ii = 0; ii < sizeof ins / sizeof ins[0]; ii++) {
                    bloom_config_t c;
                    config_for(&c, (bloom_preset_t)p, sizes[si][0], sizes[si][1], ins[ii], OUTS[o]);
                    frame_t src =
                        frame_random(&c, c.in_fmt, (uint32_t)(p * 977 + (int)si * 31 + (int)ii * 7));
                    run_one(&a, &c, &src);
                    frame_free(&src);
                }
            snprintf(what, sizeof what, "%s random -> %s", pn, OUT_NAME[o]);
            verdict(what, (bloom_preset_t)p, OUTS[o], &a);
            if (o == 0)
                dark_hdr((bloom_preset_t)p);
            for (size_t i = 0; i < NIMG; i++) {
                if (!have[i])
                    continue;
                memset(&a, 0, sizeof a);
                bloom_config_t c;
                config_for(&c, (bloom_preset_t)p, img[i].w, img[i].h, img[i].fmt, OUTS[o]);
                run_one(&a, &c, &img[i]);
                snprintf(what, sizeof what, "%s %s -> %s", pn, IMAGES[i], OUT_NAME[o]);
                verdict(what, (bloom_preset_t)p, OUTS[o], &a);
            }
        }
    }
    for (size_t i = 0; i < NIMG; i++)
        if (have[i])
            frame_free(&img[i]);
    return harness_finish();
}
