/* 16-bit samples (cfg.sample_bits = 16; sim/docs/fixed-point.md, "16-bit
 * samples"): the error against the float model on the random corpus and
 * the real 8-bit images, unity at 3, 5 and 8 levels, attenuation, arm and
 * xna,
 * asserted (peak, % exact, signed mean) and printed; the bit-true
 * difference counted (0). A test of its own: the float model on the
 * images is slow under emulation (tests/cross.mk skips it there; test_s16
 * holds the engine to the bit-true model on ARM). */
#include <stdlib.h>

#include "imgframe.h"
#include "preset_conform.h"

#define S16_PEAK 2 /* issue 21: peak <= 2 LSB of 8/6/5-bit output (measured: 1) */
/* The signed mean: issue 21's 0.0015 (ERR_BIAS_MAX, the 32-bit path's
 * bound). Met because only levels 1 and 2 are 16-bit (BLOOM_S16_LEVELS):
 * with every level 16-bit, the deep levels' boxes and tents rounded a
 * glow's faint tail at 2^-G and lost up to 0.0143 LSB on hubble_deep_field
 * (fixed-point.md, "16-bit samples"). */
#define S16_BIAS_MAX ERR_BIAS_MAX

typedef struct {
    errstat_t e;
    long long bt;
} acc_t;

static void budget(const char *what, const acc_t *a, double floor)
{
    errstat_print(what, &a->e);
    CHECKF(a->bt == 0, "%s: %lld samples off the bit-true model", what, a->bt);
    CHECKF(a->e.peak <= S16_PEAK, "%s: peak %d above %d", what, a->e.peak, S16_PEAK);
    CHECKF(errstat_exact_pct(&a->e) >= floor, "%s: %.3f%% exact below %.2f%%", what, errstat_exact_pct(&a->e),
           floor);
    CHECKF(fabs(errstat_mean(&a->e)) <= S16_BIAS_MAX, "%s: signed mean %+.5f LSB beyond %.4f", what,
           errstat_mean(&a->e), S16_BIAS_MAX);
}

static void add(acc_t *a, const bloom_config_t *c, const frame_t *src)
{
    preset_conform_t pc = preset_conform(c, src, NULL, 0);
    CHECKF(pc.ok, "%dx%d: engine or model failed", c->width, c->height);
    errstat_merge(&a->e, &pc.vs_float);
    a->bt += pc.bittrue_diff;
}

/* The floors of % exact: measured (make test prints them), rounded down
 * (random RGB888 99.838 %, hubble_deep_field RGB888 99.432 %). */
#define FLOOR_RANDOM 99.8
#define FLOOR_IMAGE 99.4

/* The 16-bit path of a preset other than unity at its defaults (cfg set
 * but for sizes and formats) over the random corpus and the two images. */
static void preset_budget(bloom_preset_t p, const frame_t img[2], const int have[2],
                          const char *const images[2])
{
    static const bloom_format_t outs[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565};
    static const char *const oname[] = {"RGB888", "XRGB8888", "RGB565"};
    const int sizes[][2] = {{64, 48}, {257, 131}, {300, 200}};
    for (size_t o = 0; o < 3; o++) {
        char what[96];
        acc_t a;
        memset(&a, 0, sizeof a);
        for (size_t si = 0; si < 3; si++)
            for (int in = 0; in < 2; in++) {
                bloom_config_t c;
                bloom_config_default(&c, sizes[si][0], sizes[si][1]);
                bloom_config_preset(&c, p);
                c.sample_bits = 16;
                c.in_fmt = in ? BLOOM_FMT_RGB565 : BLOOM_FMT_RGB888;
                c.out_fmt = outs[o];
                frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(si * 31 + (size_t)in * 7));
                add(&a, &c, &src);
                c.threshold = 0; /* everything blooms: the coarsest G */
                add(&a, &c, &src);
                frame_free(&src);
            }
        snprintf(what, sizeof what, "%s s16 random (its threshold and 0) -> %s", bloom_preset_name(p),
                 oname[o]);
        budget(what, &a, FLOOR_RANDOM);
        for (int i = 0; i < 2; i++) {
            if (!have[i])
                continue;
            memset(&a, 0, sizeof a);
            bloom_config_t c;
            bloom_config_default(&c, img[i].w, img[i].h);
            bloom_config_preset(&c, p);
            c.sample_bits = 16;
            c.in_fmt = img[i].fmt;
            c.out_fmt = outs[o];
            if (i == 0)
                c.threshold = BLOOM_Q16(0.6);
            add(&a, &c, &img[i]);
            snprintf(what, sizeof what, "%s s16 %s -> %s", bloom_preset_name(p), images[i], oname[o]);
            budget(what, &a, FLOOR_IMAGE);
        }
    }
}

static void error_budget(void)
{
    static const bloom_format_t outs[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565};
    static const char *const oname[] = {"RGB888", "XRGB8888", "RGB565"};
    static const char *const images[] = {"rocket_floodlights.ppm", "hubble_deep_field.ppm"};
    frame_t img[2];
    int have[2];
    for (int i = 0; i < 2; i++) {
        have[i] = imgframe_load(images[i], &img[i]);
        CHECKF(have[i], "%s: cannot be read", images[i]);
    }
    const int sizes[][2] = {{64, 48}, {257, 131}, {300, 200}};
    for (size_t o = 0; o < 3; o++) {
        char what[96];
        acc_t a;
        memset(&a, 0, sizeof a);
        for (size_t si = 0; si < 3; si++)
            for (int in = 0; in < 2; in++) {
                bloom_config_t c;
                bloom_config_default(&c, sizes[si][0], sizes[si][1]);
                c.sample_bits = 16;
                c.in_fmt = in ? BLOOM_FMT_RGB565 : BLOOM_FMT_RGB888;
                c.out_fmt = outs[o];
                frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(si * 31 + (size_t)in * 7));
                add(&a, &c, &src);
                frame_free(&src);
            }
        snprintf(what, sizeof what, "unity s16 random -> %s", oname[o]);
        budget(what, &a, FLOOR_RANDOM);
        for (int i = 0; i < 2; i++) {
            if (!have[i])
                continue;
            memset(&a, 0, sizeof a);
            for (int lv = 0; lv < 3; lv++) { /* the default's 5 levels, and G = 14 and G = 12 */
                static const int levels[] = {5, 3, 8};
                bloom_config_t c;
                bloom_config_default(&c, img[i].w, img[i].h);
                c.sample_bits = 16;
                c.levels = levels[lv];
                c.in_fmt = img[i].fmt;
                c.out_fmt = outs[o];
                if (i == 0)
                    c.threshold = BLOOM_Q16(0.6); /* make demo's settings for the rocket */
                add(&a, &c, &img[i]);
            }
            snprintf(what, sizeof what, "unity s16 %s (3, 5, 8 levels) -> %s", images[i], oname[o]);
            budget(what, &a, FLOOR_IMAGE);
            /* attenuation at its defaults over a depth ramp */
            memset(&a, 0, sizeof a);
            bloom_config_t c;
            bloom_config_default(&c, img[i].w, img[i].h);
            bloom_config_preset(&c, BLOOM_PRESET_ATTENUATION);
            c.sample_bits = 16;
            c.in_fmt = img[i].fmt;
            c.out_fmt = outs[o];
            if (i == 0)
                c.threshold = BLOOM_Q16(0.6);
            ptrdiff_t astride;
            void *aux = aux_plane(c.width, c.height, c.aux_fmt, 5u, &astride);
            preset_conform_t pc = preset_conform(&c, &img[i], aux, astride);
            free(aux);
            CHECKF(pc.ok, "attenuation %s: engine or model failed", images[i]);
            errstat_merge(&a.e, &pc.vs_float);
            a.bt += pc.bittrue_diff;
            snprintf(what, sizeof what, "attenuation s16 %s -> %s", images[i], oname[o]);
            budget(what, &a, FLOOR_IMAGE);
        }
    }
#if BLOOM_USE_ARM
    preset_budget(BLOOM_PRESET_ARM, img, have, images);
#endif
#if BLOOM_USE_XNA
    preset_budget(BLOOM_PRESET_XNA, img, have, images);
#endif
    for (int i = 0; i < 2; i++)
        if (have[i])
            frame_free(&img[i]);
}

int main(void)
{
#if !BLOOM_USE_S16
    SKIP("16-bit samples: compiled out (BLOOM_USE_S16 0)");
#else
    error_budget();
#endif
    return harness_finish();
}
