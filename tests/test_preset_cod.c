/* The cod preset against its models (sim/docs/presets/cod.md): bit-exact to
 * the bit-true model over a grid of sizes, depths, format pairs and
 * parameter sets (extremes included) and on real images; error statistics
 * against the float model; the firefly property of the Karis average; the
 * energy-conserving composite (never brighter, a flat field stays flat);
 * weights 0 give the input back; the worst case of every intermediate;
 * parameters refused; the row interface; BLOOM_FLAG_KEEP_LEVELS. The reach
 * of L levels: test_preset_cod_reach.c. */
#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "harness.h"
#include "imgframe.h"
#include "model_cod.h"
#include "preset_conform.h"

#if BLOOM_USE_COD
/* Parameter sets of the grid. */
enum { P_NATURAL, P_OLD_SCHOOL, P_FULL, P_ZERO, P_SCREEN_BLUR, P_DEBUG_LINEAR, P_COUNT };

static void set_params(bloom_config_t *c, int set, int levels)
{
    bloom_config_preset(c, BLOOM_PRESET_COD);
    c->levels = levels;
    bloom_info_t info;
    bloom_query(c, &info);
    const int L = info.levels;
    switch (set) {
    case P_NATURAL:
        bloom_cod_weights(&bloom_cod_natural, L, c->p.level_weight);
        break;
    case P_OLD_SCHOOL: /* additive, threshold 0.6, softness 0.2, a warm tint */
        bloom_cod_weights(&bloom_cod_old_school, L, c->p.level_weight);
        c->flags |= BLOOM_FLAG_ADDITIVE;
        c->threshold = BLOOM_Q16(0.6);
        c->soft_knee = BLOOM_Q16(0.2);
        c->p.tint[0] = BLOOM_ONE;
        c->p.tint[1] = BLOOM_Q16(0.8);
        c->p.tint[2] = BLOOM_Q16(0.55);
        break;
    case P_FULL: /* every weight at 1.0, additive: the largest sums */
        for (int k = 0; k < BLOOM_MAX_LEVELS; k++)
            c->p.level_weight[k] = BLOOM_ONE;
        c->flags |= BLOOM_FLAG_ADDITIVE;
        c->threshold = BLOOM_Q16(0.25);
        c->soft_knee = BLOOM_ONE;
        break;
    case P_ZERO: /* every weight 0: the input comes back */
        memset(c->p.level_weight, 0, sizeof c->p.level_weight);
        break;
    case P_SCREEN_BLUR: /* Bevy's SCREEN_BLUR, tint with a zero channel */
        bloom_cod_weights(&bloom_cod_screen_blur, L, c->p.level_weight);
        c->p.tint[0] = BLOOM_Q16(0.3);
        c->p.tint[1] = 0;
        c->p.tint[2] = BLOOM_Q16(0.999);
        break;
    default: /* debug view of a linear pipeline, energy-conserving, c_0 = 1 */
        bloom_cod_weights(&bloom_cod_natural, L, c->p.level_weight);
        c->p.level_weight[0] = BLOOM_ONE;
        c->flags |= BLOOM_FLAG_DEBUG_VIEW | BLOOM_FLAG_LINEAR;
        c->threshold = BLOOM_Q16(0.1);
        c->soft_knee = BLOOM_Q16(0.5);
        break;
    }
}

static int out_class(bloom_format_t f)
{
    return f == BLOOM_FMT_RGBQ16 ? 2 : f == BLOOM_FMT_RGB565 ? 1 : 0;
}

static void grid(void)
{
    static const int sizes[][2] = {{1, 1}, {2, 2}, {3, 5}, {7, 2}, {16, 9}, {33, 17}, {64, 48}, {100, 70}};
    static const bloom_format_t fmts[][2] = {
        {BLOOM_FMT_RGB888, BLOOM_FMT_RGB888}, {BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888},
        {BLOOM_FMT_RGB565, BLOOM_FMT_RGB565}, {BLOOM_FMT_RGB565, BLOOM_FMT_RGB888},
        {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16}, {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGB888},
        {BLOOM_FMT_RGB888, BLOOM_FMT_RGBQ16}, {BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565}};
    static const int levels[] = {1, 2, 3, 5, 8};
    const int nf = (int)(sizeof fmts / sizeof fmts[0]);
    errstat_t cls[3][2][2]; /* output class x HDR input x knee active */
    memset(cls, 0, sizeof cls);
    long long diff = 0;
    int runs = 0, failed = 0;
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (int set = 0; set < P_COUNT; set++)
            for (size_t li = 0; li < sizeof levels / sizeof levels[0]; li++)
                for (int fi = 0; fi < 3; fi++) {
                    const int f = (int)((s * 3 + (size_t)set * 5 + li * 2 + (size_t)fi * 3) % (size_t)nf);
                    bloom_config_t c;
                    bloom_config_default(&c, sizes[s][0], sizes[s][1]);
                    c.in_fmt = fmts[f][0];
                    c.out_fmt = fmts[f][1];
                    set_params(&c, set, levels[li]);
                    if (fi & 1)
                        c.flags |= BLOOM_FLAG_COPY_SOURCE;
                    frame_t src = frame_random(
                        &c, c.in_fmt, (uint32_t)(s * 1000 + (size_t)set * 100 + li * 10 + (size_t)fi));
                    preset_conform_t r = preset_conform(&c, &src, NULL, 0);
                    failed += !r.ok;
                    diff += r.bittrue_diff;
                    if (r.bittrue_diff)
                        fprintf(stderr, "cod %dx%d set %d levels %d fmt %d: %lld differ\n", c.width, c.height,
                                set, levels[li], f, r.bittrue_diff);
                    errstat_merge(&cls[out_class(c.out_fmt)][c.in_fmt == BLOOM_FMT_RGBQ16][c.threshold > 0],
                                  &r.vs_float);
                    if (getenv("COD_VERBOSE") && r.vs_float.peak > 1)
                        printf("peak %d: %dx%d set %d levels %d fmt %d\n", r.vs_float.peak, c.width, c.height,
                               set, levels[li], f);
                    runs++;
                    frame_free(&src);
                }
    CHECKF(failed == 0, "cod: engine and models ran (%d of %d failed)", failed, runs);
    CHECKF(diff == 0, "cod: bit-exact to the bit-true model over %d runs (%lld samples differ)", runs, diff);
    static const char *const oname[3] = {"8-bit", "RGB565", "RGBQ16"};
    errstat_t low; /* 8-bit and RGB565 out, everything */
    memset(&low, 0, sizeof low);
    for (int o = 0; o < 3; o++)
        for (int hdr = 0; hdr < 2; hdr++)
            for (int kn = 0; kn < 2; kn++) {
                if (!cls[o][hdr][kn].n)
                    continue;
                char what[80];
                snprintf(what, sizeof what, "cod vs float, %s out, %s in, knee %s", oname[o],
                         hdr ? "HDR" : "LDR", kn ? "on" : "off");
                errstat_print(what, &cls[o][hdr][kn]);
                if (o < 2)
                    errstat_merge(&low, &cls[o][hdr][kn]);
            }
    CHECKF(low.peak <= 1, "cod: 8-bit and RGB565 out within 1 LSB of the float model (%d)", low.peak);
    CHECKF(cls[2][0][0].peak <= 1 && cls[2][1][0].peak <= 1,
           "cod: RGBQ16 out without the knee within 1 LSB (%d, %d)", cls[2][0][0].peak, cls[2][1][0].peak);
    /* with the knee: its Q16 factor (the default engine's knee, fixed-point.md
     * step 3) is off by up to 2^-17 of the signal, and the additive sets sum
     * that error over up to 8 levels at weight 1.0 (cod.md) */
    CHECKF(cls[2][0][1].peak <= 3 && cls[2][1][1].peak <= 3,
           "cod: RGBQ16 out with the knee within 3 LSB (%d, %d)", cls[2][0][1].peak, cls[2][1][1].peak);
}

/* Real images: the photograph (RGB888) and an HDR scene (RGBQ16 in, both
 * outputs), defaults and the additive old-school set. */
static void real_images(void)
{
    static const char *const names[] = {"rocket_floodlights.ppm", "hall_lamps.pfm"};
    for (size_t i = 0; i < 2; i++) {
        frame_t src;
        if (!imgframe_load(names[i], &src)) {
            CHECKF(0, "real image %s readable", names[i]);
            continue;
        }
        for (int set = 0; set < 2; set++) {
            bloom_config_t c;
            bloom_config_default(&c, src.w, src.h);
            c.in_fmt = src.fmt;
            c.out_fmt = set == 0 ? src.fmt : BLOOM_FMT_RGB888;
            set_params(&c, set == 0 ? P_NATURAL : P_OLD_SCHOOL, 6);
            preset_conform_t r = preset_conform(&c, &src, NULL, 0);
            char what[96];
            snprintf(what, sizeof what, "cod %s %s vs float", names[i], set ? "old-school" : "natural");
            CHECK(r.ok);
            CHECKF(r.bittrue_diff == 0, "%s: bit-exact (%lld differ)", what, r.bittrue_diff);
            errstat_print(what, &r.vs_float);
            CHECKF(r.vs_float.peak <= (c.out_fmt == BLOOM_FMT_RGBQ16 && c.in_fmt == BLOOM_FMT_RGBQ16 ? 2 : 1),
                   "%s: peak %d", what, r.vs_float.peak);
        }
        frame_free(&src);
    }
}

/* The bloom term (debug view, RGBQ16 out, linear units) of a 64 x 64 frame
 * at background level bg with a hot pixel of value v at (x, y) (v = 0: none):
 * engine (how 0), or the float model with the Karis average (1) or without
 * (2). Sum and peak. */
typedef struct {
    double sum, peak;
    double *img;
} bloom_img_t;

static bloom_img_t hot_pixel(uint32_t bg, int x, int y, uint32_t v, int how)
{
    const int w = 64, h = 64;
    bloom_config_t c;
    bloom_config_default(&c, w, h);
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
    set_params(&c, P_NATURAL, 5);
    c.flags |= BLOOM_FLAG_DEBUG_VIEW;
    frame_t src = frame_q16_fill(w, h, bg);
    if (v)
        frame_set_q16(&src, x, y, v);
    bloom_img_t r = {0, 0, (double *)xmalloc((size_t)w * (size_t)h * sizeof(double))};
    if (how == 0) {
        frame_t out = run_engine(&c, &src);
        for (int j = 0; j < h; j++)
            for (int i = 0; i < w; i++)
                r.img[j * w + i] = frame_get_q16(&out, i, j) / 65536.0;
        frame_free(&out);
    } else {
        bloom_model_preset_args_t a;
        memset(&a, 0, sizeof a);
        a.cfg = &c;
        a.src = frame_codes(&src);
        double *val = (double *)xmalloc((size_t)w * (size_t)h * 3u * sizeof(double));
        a.dst_value = val;
        bloom_model_cod_ex(&a, how == 1);
        for (int i = 0; i < w * h; i++)
            r.img[i] = val[3 * i];
        free(val);
        free((void *)a.src);
    }
    for (int i = 0; i < w * h; i++) {
        r.sum += r.img[i];
        r.peak = r.img[i] > r.peak ? r.img[i] : r.peak;
    }
    frame_free(&src);
    return r;
}

/* Fireflies (cod.md). (1) A hot pixel moved by one pixel on black: the
 * 13-tap's two phases are mirror images of each other, so the bloom's sum
 * and peak stay the same with or without the Karis average (measured, to
 * the last digit). (2) The flicker the Karis average is for: a hot pixel
 * that appears for one frame (an aliased specular highlight). The bloom it
 * adds -- sum, and the largest change of one pixel -- with the Karis
 * average (engine and float model) and without it (float model, plain
 * 13-tap on level 1), on black and on a grey background, at 64.0 and 256.0. */
static void firefly(void)
{
    const char *names[3] = {"engine (Karis)", "float model, Karis", "float, no Karis"};
    for (int how = 0; how < 3; how += 2) {
        bloom_img_t a = hot_pixel(0, 31, 31, 64u << 16, how), b = hot_pixel(0, 32, 31, 64u << 16, how),
                    d = hot_pixel(0, 32, 32, 64u << 16, how);
        printf("firefly moved, %-18s: bloom sum %.5f / %.5f / %.5f, peak %.6f / %.6f / %.6f at (31,31) / "
               "(32,31) / "
               "(32,32)\n",
               names[how], a.sum, b.sum, d.sum, a.peak, b.peak, d.peak);
        CHECKF(fabs(a.sum - b.sum) < 1e-3 * a.sum && fabs(a.sum - d.sum) < 1e-3 * a.sum &&
                   fabs(a.peak - b.peak) < 1e-3 * a.peak && fabs(a.peak - d.peak) < 1e-3 * a.peak,
               "firefly moved by one pixel: same sum and peak (%s)", names[how]);
        free(a.img);
        free(b.img);
        free(d.img);
    }
    static const uint32_t bgs[2] = {0, BLOOM_Q16(0.25)}, hot[2] = {64u << 16, (1u << 24) - 1u};
    for (int bi = 0; bi < 2; bi++)
        for (int hi = 0; hi < 2; hi++) {
            double add[3], dmax[3];
            for (int how = 0; how < 3; how++) {
                bloom_img_t base = hot_pixel(bgs[bi], 0, 0, 0, how),
                            on = hot_pixel(bgs[bi], 31, 31, hot[hi], how);
                add[how] = on.sum - base.sum;
                dmax[how] = 0;
                for (int i = 0; i < 64 * 64; i++)
                    dmax[how] = fmax(dmax[how], on.img[i] - base.img[i]);
                free(base.img);
                free(on.img);
            }
            printf("firefly %6.2f on %.2f: bloom added %.4f (engine) %.4f (model, Karis) %.4f (no Karis), "
                   "x%.2f; "
                   "largest pixel change %.5f / %.5f / %.5f, x%.2f\n",
                   hot[hi] / 65536.0, bgs[bi] / 65536.0, add[0], add[1], add[2], add[2] / add[0], dmax[0],
                   dmax[1], dmax[2], dmax[2] / dmax[0]);
            CHECKF(add[0] * 1.5 < add[2] && dmax[0] * 1.2 < dmax[2],
                   "firefly %.1f on %.2f: the Karis average adds less bloom (%.4f vs %.4f) and a lower peak "
                   "(%.5f vs %.5f)",
                   hot[hi] / 65536.0, bgs[bi] / 65536.0, add[0], add[2], dmax[0], dmax[2]);
        }
}

/* Energy conservation: inputs <= 1.0, any weights and tint, energy-conserving
 * composite: every output <= 1.0; a flat field stays flat. */
static void energy(void)
{
    int over = 0, runs = 0, notflat = 0;
    for (int t = 0; t < 12; t++) {
        bloom_config_t c;
        bloom_config_default(&c, 37 + 5 * t, 23 + 3 * t);
        c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
        set_params(&c, P_NATURAL, 1 + t % 7);
        uint32_t s = (uint32_t)t * 77u + 3u;
        for (int k = 0; k < BLOOM_MAX_LEVELS; k++)
            c.p.level_weight[k] = t % 3 == 0 ? BLOOM_ONE : rng_next(&s) % (BLOOM_ONE + 1u);
        for (int ch = 0; ch < 3; ch++)
            c.p.tint[ch] = t % 3 == 0 ? BLOOM_ONE : rng_next(&s) % (BLOOM_ONE + 1u);
        c.threshold = t % 2 ? BLOOM_Q16(0.3) : 0;
        c.soft_knee = BLOOM_Q16(0.5);
        frame_t src = frame_alloc(c.width, c.height, BLOOM_FMT_RGBQ16, 0);
        for (int y = 0; y < c.height; y++)
            for (int x = 0; x < c.width; x++) { /* sparse bright spots at 1.0, the rest random <= 1 */
                uint32_t px[3];
                for (int ch = 0; ch < 3; ch++)
                    px[ch] = rng_next(&s) % 7u == 0 ? BLOOM_ONE : rng_next(&s) % (BLOOM_ONE + 1u);
                memcpy(src.p + (size_t)y * src.stride + (size_t)x * 12u, px, 12);
            }
        frame_t out = run_engine(&c, &src);
        uint32_t *o = frame_codes(&out);
        for (size_t i = 0; i < (size_t)c.width * (size_t)c.height * 3u; i++)
            over += o[i] > BLOOM_ONE;
        free(o);
        frame_free(&out);
        frame_free(&src);
        /* flat fields: 1.0, 0.37 and 200.0 */
        static const uint32_t flat[3] = {BLOOM_ONE, BLOOM_Q16(0.37), 200u << 16};
        for (int fl = 0; fl < 3; fl++) {
            frame_t f = frame_q16_fill(c.width, c.height, flat[fl]);
            frame_t fo = run_engine(&c, &f);
            uint32_t *q = frame_codes(&fo);
            for (size_t i = 3; i < (size_t)c.width * (size_t)c.height * 3u; i++)
                notflat += q[i] != q[i % 3];
            /* with tint 1 the flat field comes back unchanged */
            if (c.p.tint[0] == BLOOM_ONE && c.p.tint[1] == BLOOM_ONE && c.p.tint[2] == BLOOM_ONE &&
                c.threshold == 0)
                notflat += !frame_equal(&f, &fo);
            free(q);
            frame_free(&fo);
            frame_free(&f);
        }
        runs++;
    }
    CHECKF(over == 0, "energy-conserving: no output above 1.0 with inputs <= 1.0 (%d over, %d runs)", over,
           runs);
    CHECKF(notflat == 0, "energy-conserving: flat fields stay flat (%d samples differ)", notflat);
}

/* Weights 0: output = input (decode/encode) in every format pair, both modes. */
static void weights_zero(void)
{
    static const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                          BLOOM_FMT_RGBQ16};
    int bad = 0;
    for (int f = 0; f < 4; f++)
        for (int add = 0; add < 2; add++) {
            bloom_config_t c;
            bloom_config_default(&c, 45, 31);
            c.in_fmt = c.out_fmt = fmts[f];
            set_params(&c, P_ZERO, 4);
            if (add)
                c.flags |= BLOOM_FLAG_ADDITIVE;
            c.flags |= f & 1 ? BLOOM_FLAG_LINEAR : 0;
            for (int k = 1; k < BLOOM_MAX_LEVELS; k++) /* only c_0 matters */
                c.p.level_weight[k] = BLOOM_Q16(0.5);
            frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(f * 2 + add));
            frame_t out = run_engine(&c, &src);
            uint32_t *ci = frame_codes(&src), *co = frame_codes(&out);
            bad += memcmp(ci, co, (size_t)c.width * (size_t)c.height * 3u * sizeof *ci) != 0;
            free(ci);
            free(co);
            frame_free(&src);
            frame_free(&out);
        }
    CHECKF(bad == 0, "c_0 = 0: output = input in every format, both composites (%d differ)", bad);
}

/* The worst case of every intermediate (cod.md): the largest input (2^24 - 1
 * in RGBQ16, near it with variation so that the Karis weights differ), the
 * deepest pyramid 1024 x 1024 allows (9 levels), every weight 1.0, additive
 * (U up to 9 M), the bloom term seen through a tiny tint so that the output
 * does not saturate; and energy-conserving at 512 x 512 (8 levels).
 * Bit-exact with the bit-true model, which computes the sums exactly. */
static void worst_case(void)
{
    for (int mode = 0; mode < 2; mode++) {
        bloom_config_t c;
        const int side = mode == 0 ? 1024 : 512; /* 9 levels (additive); 8 */
        bloom_config_default(&c, side, side);
        c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
        set_params(&c, P_FULL, mode == 0 ? 9 : 8);
        c.threshold = 0;
        if (mode == 0) { /* additive, debug view through f = 1 */
            c.flags |= BLOOM_FLAG_DEBUG_VIEW;
            c.p.tint[0] = c.p.tint[1] = c.p.tint[2] = 1;
        } else {
            c.flags &= ~(uint32_t)BLOOM_FLAG_ADDITIVE;
        }
        frame_t src = frame_alloc(c.width, c.height, BLOOM_FMT_RGBQ16, 0);
        uint32_t s = 99u + (uint32_t)mode;
        for (int y = 0; y < c.height; y++)
            for (int x = 0; x < c.width; x++) {
                uint32_t px[3];
                for (int ch = 0; ch < 3; ch++)
                    px[ch] =
                        (x + y) % 5 == 0 ? BLOOM_MAX_LINEAR : BLOOM_MAX_LINEAR - (rng_next(&s) & 0xFFFFFu);
                if (x % 7 == 3)
                    px[0] = px[1] = px[2] = 0xFFFFFFFFu; /* clamped on read */
                memcpy(src.p + (size_t)y * src.stride + (size_t)x * 12u, px, 12);
            }
        bloom_info_t info;
        CHECK(bloom_query(&c, &info) == BLOOM_OK && info.levels == (mode == 0 ? 9 : 8));
        frame_t out = run_engine(&c, &src);
        uint32_t *core = frame_codes(&out), *in = frame_codes(&src);
        const size_t n = (size_t)c.width * (size_t)c.height * 3u;
        uint32_t *bt = (uint32_t *)xmalloc(n * sizeof *bt);
        bloom_model_preset_args_t a;
        memset(&a, 0, sizeof a);
        a.cfg = &c;
        a.bittrue = 1;
        a.src = in;
        a.dst_codes = bt;
        CHECK(bloom_model_cod(&a) == info.levels);
        long long diff = 0;
        uint32_t mx = 0;
        for (size_t i = 0; i < n; i++) {
            diff += core[i] != bt[i];
            mx = core[i] > mx ? core[i] : mx;
        }
        CHECKF(diff == 0, "worst case (%s): bit-exact with the exact model (%lld differ, largest output %u)",
               mode ? "energy-conserving" : "additive, U up to 9 M", diff, mx);
        if (mode == 0) /* output = tent(U_1) / 2^24 in Q16: above 2048 means U_1 above 8 x 2^28 > 2^31 */
            CHECKF(mx > 2048u, "worst case: tent(U_1) reached %u / 256 x 2^28", mx);
        free(core);
        free(in);
        free(bt);
        frame_free(&out);
        frame_free(&src);
    }
}

static void bad_params(void)
{
    bloom_config_t c;
    bloom_info_t info;
    bloom_config_default(&c, 64, 48);
    CHECK(bloom_config_preset(&c, BLOOM_PRESET_COD) == BLOOM_OK);
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    CHECK(bloom_preset_available(BLOOM_PRESET_COD));
    CHECK(bloom_preset_from_name("cod") == BLOOM_PRESET_COD);
    const bloom_config_t good = c;
    c.p.level_weight[0] = BLOOM_ONE + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_WEIGHT);
    c = good;
    c.p.level_weight[BLOOM_MAX_LEVELS - 1] = 0xFFFFFFFFu;
    CHECK(bloom_query(&c, &info) == BLOOM_E_WEIGHT);
    c = good;
    c.p.tint[2] = BLOOM_ONE + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_TINT);
    c = good;
    c.flags |= BLOOM_FLAG_SATURATE;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FLAGS);
    c = good;
    c.flags |= BLOOM_FLAG_BAKED;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FLAGS);
    c = good;
    c.aux_fmt = BLOOM_AUX_U8;
    CHECK(bloom_query(&c, &info) == BLOOM_E_AUX);
    c.aux_fmt = (bloom_aux_format_t)9;
    CHECK(bloom_query(&c, &info) == BLOOM_E_AUX);
    c = good;
    c.threshold = BLOOM_MAX_THRESHOLD + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_THRESHOLD);
    c = good;
    c.soft_knee = BLOOM_ONE + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_KNEE);
    c = good;
    c.levels = 0;
    CHECK(bloom_query(&c, &info) == BLOOM_E_LEVELS);
    c = good;
    c.flags |= BLOOM_FLAG_ADDITIVE | BLOOM_FLAG_DEBUG_VIEW | BLOOM_FLAG_LINEAR;
    c.p.level_weight[3] = BLOOM_ONE;
    c.p.tint[0] = BLOOM_ONE;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    /* the defaults: Bevy's NATURAL for the level count the size gives
     * (bloom_config_preset starts from 5 levels) */
    int bad = 0, seen[BLOOM_MAX_LEVELS + 1] = {0};
    for (int sz = 1; sz <= 160; sz += 3) {
        bloom_config_t d;
        bloom_config_default(&d, sz, sz + 2);
        bloom_config_preset(&d, BLOOM_PRESET_COD);
        bloom_info_t di;
        bad += bloom_query(&d, &di) != BLOOM_OK;
        uint32_t w[BLOOM_MAX_LEVELS];
        bloom_cod_weights(&bloom_cod_natural, di.levels, w);
        bad += memcmp(w, d.p.level_weight, sizeof w) != 0;
        bad += d.threshold != 0 || d.soft_knee != 0 || d.p.tint[1] != BLOOM_ONE;
        seen[di.levels] = 1;
    }
    bad += !(seen[1] && seen[2] && seen[3] && seen[4] && seen[5]);
    CHECKF(bad == 0, "cod defaults: threshold 0, tint 1, Bevy NATURAL weights for the frame's L (%d bad)",
           bad);
}

/* Row interface (preset_check_rows). */
static void rows(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 41, 29);
    set_params(&c, P_OLD_SCHOOL, 3);
    frame_t src = frame_random(&c, c.in_fmt, 5);
    preset_check_rows(&c, &src, NULL, 0);
    frame_free(&src);
}

/* BLOOM_FLAG_KEEP_LEVELS: the up pass reads every level through its delay
 * line instead of computing D_1 .. D_R again; the same bytes as without it
 * at every level count, both composites, 8-bit and HDR formats, every kernel
 * set, with more workspace from 2 levels on (at 1 nothing is recomputed;
 * the decoded source's ring, at dark cut 0, is all it adds); the row
 * interface on one of them, and at a threshold (the source read by D_1). */
static void keep_levels(void)
{
    static const int sizes[][2] = {{41, 29}, {97, 61}, {200, 130}, {333, 77}, {300, 300}};
    static const uint32_t sets[3] = {0, BLOOM_FLAG_NO_AVX2, BLOOM_FLAG_NO_SIMD};
    int same = 0, runs = 0, grew = 0, deeper = 0;
    for (int L = 1; L <= 8; L++)
        for (int si = 0; si < 5; si++) {
            bloom_config_t c;
            bloom_config_default(&c, sizes[si][0], sizes[si][1]);
            set_params(&c, (L + si) % 2 ? P_NATURAL : P_OLD_SCHOOL, L);
            if ((L + si) % 3 == 0)
                c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
            c.flags |= sets[(L + 2 * si) % 3];
            bloom_info_t a, b;
            if (bloom_query(&c, &a) != BLOOM_OK) /* too many levels for the size */
                continue;
            frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(L * 13 + si));
            frame_t ref = run_engine(&c, &src);
            c.flags |= BLOOM_FLAG_KEEP_LEVELS;
            CHECK(bloom_query(&c, &b) == BLOOM_OK);
            frame_t out = run_engine(&c, &src);
            same += frame_equal(&out, &ref);
            runs++;
            deeper += L >= 2;
            grew += L >= 2 ? b.workspace_bytes > a.workspace_bytes : b.workspace_bytes >= a.workspace_bytes;
            frame_free(&out);
            frame_free(&ref);
            frame_free(&src);
        }
    CHECKF(runs >= 30 && same == runs, "keep levels: the same bytes as recomputing them (%d of %d)", same,
           runs);
    CHECKF(grew == runs, "keep levels: more workspace from 2 levels on, no less at 1 (%d of %d; %d deeper)",
           grew, runs, deeper);
    bloom_config_t c;
    bloom_config_default(&c, 97, 61);
    set_params(&c, P_NATURAL, 5);
    c.flags |= BLOOM_FLAG_KEEP_LEVELS;
    frame_t src = frame_random(&c, c.in_fmt, 77);
    preset_check_rows(&c, &src, NULL, 0);
    c.threshold = BLOOM_Q16(0.5);
    preset_check_rows(&c, &src, NULL, 0);
    frame_free(&src);
    bloom_config_default(&c, 64, 48); /* the default preset refuses it */
    c.flags |= BLOOM_FLAG_KEEP_LEVELS;
    CHECK(bloom_query(&c, NULL) == BLOOM_E_FLAGS);
}
#endif

static void timed(const char *what, void (*fn)(void))
{
    const clock_t t0 = clock();
    fn();
    if (getenv("COD_VERBOSE"))
        printf("%s: %.2f s\n", what, (double)(clock() - t0) / CLOCKS_PER_SEC);
}

int main(void)
{
    /* bloom_levels_for_radius exists in every build */
    CHECK(bloom_levels_for_radius(1) >= 1);
#if BLOOM_USE_COD
    timed("bad_params", bad_params);
    timed("grid", grid);
    timed("real_images", real_images);
    timed("firefly", firefly);
    timed("energy", energy);
    timed("weights_zero", weights_zero);
    timed("rows", rows);
    timed("keep_levels", keep_levels);
    timed("worst_case", worst_case);
#else
    SKIP("cod preset: compiled out (BLOOM_USE_COD=0)");
#endif
    return harness_finish();
}
