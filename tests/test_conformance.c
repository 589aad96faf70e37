/* The core against the reference model: bit for bit against the bit-true
 * model everywhere, and within the error budget against the float
 * model on the random corpus and the real images (RGB888 output). */
#include <stdlib.h>

#include "conform.h"
#include "harness.h"
#include "imgframe.h"

typedef struct {
    const char *name;
    uint32_t threshold, knee, intensity, flags;
    int float_budget; /* assert peak <= 1, >= 99.9 % exact and the bias bound against float */
} params_t;

static const params_t PARAMS[] = {
    {"default", BLOOM_Q16(1.0), BLOOM_Q16(0.5), BLOOM_Q16(1.0), 0, 1},
    {"threshold 0.5", BLOOM_Q16(0.5), BLOOM_Q16(0.5), BLOOM_Q16(1.0), 0, 1},
    {"hard knee", BLOOM_Q16(0.6), 0, BLOOM_Q16(1.0), 0, 1},
    {"knee 1", BLOOM_Q16(0.6), BLOOM_ONE, BLOOM_Q16(1.0), 0, 1},
    {"linear", BLOOM_Q16(0.5), BLOOM_Q16(0.5), BLOOM_Q16(1.0), BLOOM_FLAG_LINEAR, 1},
    {"debug view", BLOOM_Q16(0.8), BLOOM_Q16(0.5), BLOOM_Q16(1.0), BLOOM_FLAG_DEBUG_VIEW, 1},
    {"threshold 0", 0, BLOOM_Q16(0.5), BLOOM_Q16(0.3), 0, 0},
    {"intensity 0", BLOOM_Q16(0.5), BLOOM_Q16(0.5), 0, 0, 1},
    {"intensity 10", BLOOM_Q16(0.5), BLOOM_Q16(0.5), BLOOM_MAX_INTENSITY, 0, 0},
    {"threshold 256", BLOOM_MAX_THRESHOLD, BLOOM_Q16(0.5), BLOOM_Q16(1.0), 0, 1},
};
#define NPARAMS (sizeof PARAMS / sizeof PARAMS[0])

static const bloom_format_t FMT_PAIRS[][2] = {
    {BLOOM_FMT_RGB888, BLOOM_FMT_RGB888},   {BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565},
    {BLOOM_FMT_RGB565, BLOOM_FMT_XRGB8888}, {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16},
    {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGB888},
};

/* The budget against the float model holds for the default
 * precision; builds with fewer fraction bits (BLOOM_LIN_BITS) only print it. */
static int float_budget(void)
{
    return BLOOM_LIN_BITS == 20;
}

static void apply(bloom_config_t *c, const params_t *p)
{
    c->threshold = p->threshold;
    c->soft_knee = p->knee;
    c->intensity = p->intensity;
    c->flags = p->flags;
}

/* Random frames: every size, level count, parameter set, format pair. */
static void test_random(void)
{
    const int sizes[][2] = {{1, 1},   {1, 13}, {13, 1},    {2, 2},     {3, 5},    {17, 9},
                            {64, 48}, {80, 3}, {257, 131}, {131, 257}, {300, 200}};
    errstat_t budget;
    memset(&budget, 0, sizeof budget);
    long long bt_diff = 0, untouched = 0, untouched_changed = 0;
    int runs = 0, model_ok = 1;
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        const int w = sizes[si][0], h = sizes[si][1];
        const int big = w * h > 20000;
        for (int lv = 1; lv <= 16; lv += big ? 5 : 1) {
            for (size_t pi = 0; pi < NPARAMS; pi++) {
                for (size_t fi = 0; fi < sizeof FMT_PAIRS / sizeof FMT_PAIRS[0]; fi++) {
                    if (big && (fi + pi + (size_t)lv) % 3)
                        continue; /* big frames: a third of the combinations */
                    bloom_config_t c;
                    bloom_config_default(&c, w, h);
                    c.levels = lv;
                    apply(&c, &PARAMS[pi]);
                    c.in_fmt = FMT_PAIRS[fi][0];
                    c.out_fmt = FMT_PAIRS[fi][1];
                    frame_t src =
                        frame_random(&c, c.in_fmt, (uint32_t)(si * 1000 + pi * 31 + fi + (size_t)lv));
                    conform_t r = conform_run(&c, &src);
                    frame_free(&src);
                    runs++;
                    model_ok &= r.ok;
                    bt_diff += r.bittrue_diff;
                    CHECKF(r.bittrue_diff == 0, "%dx%d L%d %s fmt %d->%d: %lld samples differ from bit-true",
                           w, h, lv, PARAMS[pi].name, c.in_fmt, c.out_fmt, r.bittrue_diff);
                    untouched += r.untouched;
                    untouched_changed += r.untouched_changed;
                    if (PARAMS[pi].float_budget && c.out_fmt == BLOOM_FMT_RGB888)
                        errstat_merge(&budget, &r.vs_float);
                }
            }
        }
    }
    CHECK(model_ok);
    printf("random corpus: %d runs, %lld samples differ from the bit-true model\n", runs, bt_diff);
    errstat_print("random corpus vs float (RGB888 out)", &budget);
    printf("random corpus: %lld samples with B == 0, %lld changed\n", untouched, untouched_changed);
    if (float_budget()) {
        CHECK(budget.peak <= 1);
        CHECK(errstat_exact_pct(&budget) >= 99.9);
        CHECKF(fabs(errstat_mean(&budget)) <= ERR_BIAS_MAX, "signed mean %+.5f", errstat_mean(&budget));
    }
    CHECK(untouched > 0 && untouched_changed == 0);
}

static void test_images(void)
{
    const char *dir = getenv("BLOOM_DATA_DIR");
    const char *names[] = {"rocket_floodlights.ppm", "hubble_deep_field.ppm", "studio_lamps.pfm",
                           "hall_lamps.pfm"};
    errstat_t all;
    memset(&all, 0, sizeof all);
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char path[512], err[512];
        snprintf(path, sizeof path, "%s/%s", dir ? dir : "tests/data", names[i]);
        img_t im;
        if (img_read(path, &im, err, sizeof err) != 0) {
            CHECKF(0, "%s", err);
            continue;
        }
        frame_t src = frame_from_img(&im);
        const bloom_format_t fmt = src.fmt;
        bloom_config_t c;
        bloom_config_default(&c, im.width, im.height);
        c.in_fmt = fmt;
        c.out_fmt = BLOOM_FMT_RGB888;
        if (fmt == BLOOM_FMT_RGBQ16)
            c.threshold = BLOOM_Q16(2.0); /* HDR: lamps only */
        conform_t r = conform_run(&c, &src);
        CHECK(r.ok);
        CHECKF(r.bittrue_diff == 0, "%s: %lld samples differ from bit-true", names[i], r.bittrue_diff);
        char what[128];
        snprintf(what, sizeof what, "%s vs float", names[i]);
        errstat_print(what, &r.vs_float);
        if (float_budget()) {
            CHECK(r.vs_float.peak <= 1);
            CHECK(errstat_exact_pct(&r.vs_float) >= 99.9);
            CHECKF(fabs(errstat_mean(&r.vs_float)) <= ERR_BIAS_MAX, "%s: signed mean %+.5f", names[i],
                   errstat_mean(&r.vs_float));
        }
        if (fmt == BLOOM_FMT_RGB888)
            CHECK(r.untouched_changed == 0);
        errstat_merge(&all, &r.vs_float);
        frame_free(&src);
        img_free(&im);
    }
    errstat_print("real images vs float (RGB888 out)", &all);
}

/* Random content at deep pyramids: frames large enough to build 8
 * and 10 levels (requests up to 16), bit-exact and within the budget. The
 * model is the cost: three frames. */
static void test_deep(void)
{
    const struct {
        int w, h, levels;
        bloom_format_t in, out;
    } cases[] = {
        {600, 520, 8, BLOOM_FMT_RGB888, BLOOM_FMT_RGB888},
        {1030, 1030, 12, BLOOM_FMT_RGB565, BLOOM_FMT_XRGB8888},
        {2100, 1100, 16, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB888},
    };
    errstat_t all;
    memset(&all, 0, sizeof all);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        bloom_config_t c;
        bloom_config_default(&c, cases[i].w, cases[i].h);
        c.levels = cases[i].levels;
        c.in_fmt = cases[i].in;
        c.out_fmt = cases[i].out;
        c.threshold = BLOOM_Q16(0.7);
        bloom_info_t info;
        CHECK(bloom_query(&c, &info) == BLOOM_OK);
        frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(77 + i));
        conform_t r = conform_run(&c, &src);
        frame_free(&src);
        CHECK(r.ok);
        CHECKF(r.bittrue_diff == 0, "%dx%d L%d: %lld samples differ from bit-true", c.width, c.height,
               info.levels, r.bittrue_diff);
        CHECK(info.levels == (i == 0 ? 8 : 10)); /* ceil(w / 2^k) >= 2 on both sides */
        char what[96];
        snprintf(what, sizeof what, "deep %dx%d, %d levels vs float", c.width, c.height, info.levels);
        errstat_print(what, &r.vs_float);
        if (float_budget()) {
            CHECK(r.vs_float.peak <= 1);
            CHECK(errstat_exact_pct(&r.vs_float) >= 99.5);
            CHECK(fabs(errstat_mean(&r.vs_float)) <= ERR_BIAS_MAX);
        }
    }
}

int main(void)
{
    test_random();
    test_images();
    test_deep();
    return harness_finish();
}
