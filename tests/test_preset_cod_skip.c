/* cod's zero-row shortcuts (sim/docs/presets/cod.md, "Skipping"): frames
 * with black and dark bands, a black half, all black, one hot pixel on
 * black, in the parameter sets of tests/test_preset_cod.c, against the
 * bit-true model (which takes no shortcut) and BLOOM_FLAG_NO_SKIP. Apart
 * from test_preset_cod.c to keep both files short. */
#include <stdlib.h>

#include "harness.h"
#include "model_cod.h"
#include "preset_conform.h"

#if BLOOM_USE_COD
enum { P_NATURAL, P_OLD_SCHOOL, P_FULL, P_ZERO, P_DEBUG_LINEAR, P_COUNT };

static void set_params(bloom_config_t *c, int set, int levels)
{
    bloom_config_preset(c, BLOOM_PRESET_COD);
    c->levels = levels;
    bloom_info_t info;
    bloom_query(c, &info);
    bloom_cod_weights(set == P_OLD_SCHOOL ? &bloom_cod_old_school : &bloom_cod_natural, info.levels,
                      c->p.level_weight);
    if (set == P_OLD_SCHOOL || set == P_FULL) {
        c->flags |= BLOOM_FLAG_ADDITIVE;
        c->threshold = BLOOM_Q16(set == P_FULL ? 0.25 : 0.6);
        c->soft_knee = set == P_FULL ? BLOOM_ONE : BLOOM_Q16(0.2);
        c->p.tint[1] = BLOOM_Q16(0.8);
    }
    if (set == P_FULL)
        for (int k = 0; k < BLOOM_MAX_LEVELS; k++)
            c->p.level_weight[k] = BLOOM_ONE;
    if (set == P_ZERO)
        memset(c->p.level_weight, 0, sizeof c->p.level_weight);
    if (set == P_DEBUG_LINEAR) {
        c->p.level_weight[0] = BLOOM_ONE;
        c->flags |= BLOOM_FLAG_DEBUG_VIEW | BLOOM_FLAG_LINEAR;
        c->threshold = BLOOM_Q16(0.1);
        c->soft_knee = BLOOM_Q16(0.5);
    }
}

/* Zero rows (cod.md, "Skipping"): frames with black and dark bands, a black
 * half, all black, one hot pixel on black, in every parameter set (the knee
 * sets make rows at or below t - k dark), so the skipped nodes, the
 * zero-tent blends and the copied output rows all run: bit-exact with the
 * bit-true model, which takes no shortcut, and equal to BLOOM_FLAG_NO_SKIP;
 * half of them with BLOOM_FLAG_KEEP_LEVELS (the decoded source's zero rows). */
static void skipping(void)
{
    static const int sizes[][2] = {{33, 17}, {64, 48}, {100, 70}};
    static const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                          BLOOM_FMT_RGBQ16};
    long long diff = 0, vs_noskip = 0;
    int runs = 0, failed = 0;
    for (int s = 0; s < 3; s++)
        for (int pat = 0; pat < 4; pat++)
            for (int set = 0; set < P_COUNT; set++)
                for (int lv = 2; lv <= 5; lv += 3) {
                    bloom_config_t c;
                    bloom_config_default(&c, sizes[s][0], sizes[s][1]);
                    c.in_fmt = fmts[(s + pat + set) % 4];
                    c.out_fmt = fmts[(s + 2 * pat + set + lv) % 4];
                    set_params(&c, set, lv);
                    if (set == P_NATURAL && pat == 0) /* energy-conserving with a knee: scaled rows */
                        c.threshold = BLOOM_Q16(0.5), c.soft_knee = BLOOM_Q16(0.3);
                    if ((s + pat + set + lv) % 2) /* half with the levels kept (and Dec at cut 0) */
                        c.flags |= BLOOM_FLAG_KEEP_LEVELS;
                    frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(s * 100 + pat * 10 + set + lv));
                    for (int y = 0; y < c.height; y++) {
                        uint8_t *row = src.p + (size_t)y * src.stride;
                        const size_t nb = (size_t)c.width * (size_t)src.bpp;
                        const int black = pat == 2 || (pat == 1 && y < c.height / 2) ||
                                          (pat == 0 && y % 12 < 4) || (pat == 3 && y != c.height / 2);
                        if (black)
                            memset(row, 0, nb);
                        else if (pat == 0 && y % 12 < 8) /* dark: low bits only */
                            for (size_t i = 0; i < nb; i++)
                                row[i] &= c.in_fmt == BLOOM_FMT_RGBQ16 ? (i % 4 == 1 ? 0x3F
                                                                          : i % 4    ? 0
                                                                                     : 0xFF)
                                                                       : 0x1F;
                        else if (pat == 3) {
                            memset(row, 0, nb);
                            memset(row + (size_t)(c.width / 2) * (size_t)src.bpp, 0xFF,
                                   c.in_fmt == BLOOM_FMT_RGBQ16 ? 10u : (size_t)src.bpp);
                        }
                    }
                    preset_conform_t r = preset_conform(&c, &src, NULL, 0);
                    failed += !r.ok;
                    diff += r.bittrue_diff;
                    frame_t a = run_engine(&c, &src);
                    c.flags |= BLOOM_FLAG_NO_SKIP;
                    frame_t b = run_engine(&c, &src);
                    vs_noskip += !frame_equal(&a, &b);
                    frame_free(&a);
                    frame_free(&b);
                    frame_free(&src);
                    runs++;
                }
    CHECKF(failed == 0, "skipping: engine and models ran (%d of %d failed)", failed, runs);
    CHECKF(diff == 0,
           "skipping: dark and black frames bit-exact to the bit-true model over %d runs (%lld differ)", runs,
           diff);
    CHECKF(vs_noskip == 0, "skipping: the same bytes as BLOOM_FLAG_NO_SKIP (%lld of %d runs differ)",
           vs_noskip, runs);
}

#endif

int main(void)
{
#if BLOOM_USE_COD
    skipping();
#else
    SKIP("cod preset: compiled out (BLOOM_USE_COD=0)");
#endif
    return harness_finish();
}
