/* The case tables of the stability matrix (stab.h): parameters at their
 * limits, HDR words beyond the representable range, non-finite float input,
 * degenerate frame shapes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bloom_model.h"
#include "imgio.h"
#include "stab.h"

#define ONE 65536u

/* ---- knee, threshold, intensity ---------------------------------------- */

void stab_params(FILE *md)
{
    (void)md;
    stab_table("Knee, threshold and intensity at their limits",
               "320x240 (nearest-neighbour), 5 levels. Threshold \"above max\" is just above the "
               "largest input: 1.0 + 2^-16 for the 8-bit photo (codes decode to at most 1.0), "
               "256.0 (the largest allowed) for the HDR one (inputs clamp to 255.99998). A soft "
               "knee k lets pixels from T - kT upwards through partially, so only the hard "
               "knee turns \"above max\" into no bloom at all (output = input).");
    static const char *ins[] = {"rocket", "studio"};
    for (int ii = 0; ii < 2; ii++) {
        rin_t in;
        stab_input(&in, ins[ii], 320, 240);
        const double above = in.fmt == BLOOM_FMT_RGBQ16 ? 256.0 : (ONE + 1.0) / ONE;
        const double ts[4] = {0.0, 0.6, 1.0, above};
        const double ks[3] = {0.0, 0.5, 1.0};
        char cas[96];
        bloom_config_t c;
        for (int ki = 0; ki < 3; ki++)
            for (int ti = 0; ti < 4; ti++) {
                stab_config(&c, &in, 5, ts[ti], ks[ki], 1.0, BLOOM_FMT_RGB888);
                snprintf(cas, sizeof cas, "knee %.1f, threshold %s", ks[ki],
                         ti == 3   ? "above max"
                         : ti == 0 ? "0"
                         : ti == 1 ? "0.6"
                                   : "1.0");
                const res_t r = stab_run(&in, &c, 0);
                stab_emit("params", cas, &in, &c, "5", &r, NULL);
            }
        const double is[2] = {0.0, 10.0};
        for (int i = 0; i < 2; i++) {
            stab_config(&c, &in, 5, 0.6, 0.5, is[i], BLOOM_FMT_RGB888);
            snprintf(cas, sizeof cas, "intensity %.1f (threshold 0.6)", is[i]);
            const res_t r = stab_run(&in, &c, 0);
            stab_emit("params", cas, &in, &c, "5", &r, NULL);
        }
        /* One step past each limit: refused, with the parameter named. */
        static const char *what[3] = {"threshold 256.0 + 2^-16", "knee 1.0 + 2^-16",
                                      "intensity 10.0 + 2^-16"};
        for (int i = 0; i < 3; i++) {
            stab_config(&c, &in, 5, 0.6, 0.5, 1.0, BLOOM_FMT_RGB888);
            if (i == 0)
                c.threshold = BLOOM_MAX_THRESHOLD + 1u;
            else if (i == 1)
                c.soft_knee = ONE + 1u;
            else
                c.intensity = BLOOM_MAX_INTENSITY + 1u;
            const res_t r = stab_run(&in, &c, 0);
            stab_emit("params", what[i], &in, &c, "5", &r, NULL);
        }
        rin_free(&in);
    }
}

/* ---- HDR words up to and beyond 2^24 - 1 ---------------------------------- */

/* 256x192 RGBQ16: a grey ramp 0..1.0 with five discs (radius 6) of
 * (v, v/2, v/4), or every word = v when flat. */
static void hdr_frame(rin_t *in, const char *name, int w, int h, uint32_t v, int flat)
{
    uint32_t *words = rxmalloc((size_t)w * (size_t)h * 3u * 4u);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint32_t *p = words + ((size_t)y * (size_t)w + (size_t)x) * 3u;
            const uint32_t g = w > 1 ? (uint32_t)((uint64_t)x * ONE / (uint64_t)(w - 1)) : 0u;
            p[0] = p[1] = p[2] = flat ? v : g;
            for (int d = 0; d < 5 && !flat; d++) {
                const double cx = w * (0.15 + 0.17 * d), cy = h * (0.3 + 0.1 * d);
                const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
                if (dx * dx + dy * dy <= 36.0) {
                    p[0] = v;
                    p[1] = v / 2u;
                    p[2] = v / 4u;
                }
            }
        }
    rin_from_words(in, name, w, h, words);
}

void stab_hdr(FILE *md)
{
    (void)md;
    stab_table("HDR input up to and beyond the largest representable value",
               "RGBQ16 input, 256x192: a grey ramp 0..1.0 with five discs of (v, v/2, v/4); "
               "threshold 1.0, soft knee 0.5, 5 levels. The engine clamps words above 2^24 - 1 "
               "(255.99998) on input; the model is given the same clamped words (the "
               "documented rule), and, in the notes, the words as they are (how much the clamp "
               "changes the picture). RGBQ16 output is compared in Q16.16 LSB (top code "
               "2^24 - 1), RGB888 output in 8-bit LSB. The last rows: every sample at the "
               "value, threshold 0, intensity 10, the deepest pyramid of 512x512.");
    static const struct {
        const char *name;
        uint32_t v;
    } vs[] = {
        {"disc 1.0", ONE},
        {"disc 16.0", 16u * ONE},
        {"disc 255.99998 (2^24-1)", BLOOM_MAX_LINEAR},
        {"disc 256.0 (2^24)", 1u << 24},
        {"disc 4096.0 (2^28)", 1u << 28},
        {"disc 65536.0 (2^32-1)", 0xFFFFFFFFu},
    };
    for (size_t vi = 0; vi < sizeof vs / sizeof vs[0]; vi++) {
        rin_t in;
        hdr_frame(&in, "ramp+discs", 256, 192, vs[vi].v, 0);
        for (int ii = 0; ii < 2; ii++)
            for (int oi = 0; oi < 2; oi++) {
                bloom_config_t c;
                char cas[96];
                const double I = ii ? 10.0 : 1.0;
                stab_config(&c, &in, 5, 1.0, 0.5, I, oi ? BLOOM_FMT_RGBQ16 : BLOOM_FMT_RGB888);
                snprintf(cas, sizeof cas, "%s, intensity %.0f", vs[vi].name, I);
                const res_t r = stab_run(&in, &c, 1);
                stab_emit("hdr", cas, &in, &c, "5", &r, NULL);
            }
        rin_free(&in);
    }
    const uint32_t flats[2] = {BLOOM_MAX_LINEAR, 0xFFFFFFFFu};
    for (int fi = 0; fi < 2; fi++) {
        rin_t in;
        hdr_frame(&in, "flat", 512, 512, flats[fi], 1);
        for (int oi = 0; oi < 2; oi++) {
            bloom_config_t c;
            stab_config(&c, &in, 16, 0.0, 0.5, 10.0, oi ? BLOOM_FMT_RGBQ16 : BLOOM_FMT_RGB888);
            const res_t r = stab_run(&in, &c, 1);
            stab_emit("hdr",
                      fi ? "every word 2^32-1, threshold 0, intensity 10"
                         : "every word 2^24-1, threshold 0, intensity 10",
                      &in, &c, "16", &r, NULL);
        }
        rin_free(&in);
    }
}

/* ---- NaN, Inf, negative float input ------------------------------------------ */

void stab_float(FILE *md)
{
    static const struct {
        const char *name;
        float v;
    } cls[] = {
        {"NaN", NAN},
        {"+Inf", INFINITY},
        {"-Inf", -INFINITY},
        {"-1.0", -1.0f},
        {"-0.0", -0.0f},
        {"denormal 1e-40", 1e-40f},
        {"1e-6 (below 2^-17)", 1e-6f},
        {"255.99998", 255.99998f},
        {"256.0", 256.0f},
        {"1e30", 1e30f},
    };
    enum { NCLS = sizeof cls / sizeof cls[0] };
    const int w = 256, h = 192;
    long long count[NCLS] = {0};
    uint32_t *words = rxmalloc((size_t)w * (size_t)h * 3u * 4u);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int ch = 0; ch < 3; ch++) {
                float v = 4.0f * (float)x / (float)(w - 1) * (float)(ch + 1) / 3.0f;
                if ((x * 7 + y * 13) % 11 == 0 && (x + y) % 3 == ch) {
                    const int k = (x / 11 + y) % NCLS;
                    v = cls[k].v;
                    count[k]++;
                }
                words[((size_t)y * (size_t)w + (size_t)x) * 3u + (size_t)ch] = img_float_to_q16(v);
            }
    fprintf(md, "\n### NaN, Inf and negative float input\n\nFloat (PFM) samples enter as RGBQ16 "
                "through `img_float_to_q16` (sim/imgio.h): NaN, negative and zero -> 0, at or "
                "above 256.0 and +Inf -> 2^24 - 1, otherwise round half up of v * 65536. "
                "A 256x192 float ramp (0..4.0) with the special values below sprinkled into "
                "single channels:\n\n| float sample | count | word | as linear value |\n"
                "|---|---:|---:|---:|\n");
    for (int k = 0; k < NCLS; k++) {
        const uint32_t q = img_float_to_q16(cls[k].v);
        fprintf(md, "| %s | %lld | %u | %.6f |\n", cls[k].name, count[k], (unsigned)q, q / 65536.0);
    }
    stab_table("NaN, Inf and negative float input: error",
               "Threshold 1.0, soft knee 0.5, 5 levels; the real PFM files at their own size. The "
               "model sees the same words (the rule is applied before both).");
    rin_t in;
    rin_from_words(&in, "float specials", w, h, words);
    for (int oi = 0; oi < 2; oi++) {
        bloom_config_t c;
        stab_config(&c, &in, 5, 1.0, 0.5, 1.0, oi ? BLOOM_FMT_RGBQ16 : BLOOM_FMT_RGB888);
        const res_t r = stab_run(&in, &c, 0);
        stab_emit("float", "synthetic NaN/Inf/negative", &in, &c, "5", &r, NULL);
    }
    rin_free(&in);
    static const char *files[2][2] = {{"hall", "hall_lamps.pfm"}, {"studio", "studio_lamps.pfm"}};
    for (int fi = 0; fi < 2; fi++) {
        char path[1024], err[512], note[160];
        img_t im;
        snprintf(path, sizeof path, "%s/%s", stab_data_dir, files[fi][1]);
        if (img_read(path, &im, err, sizeof err))
            rdie("%s", err);
        long long neg = 0, nan = 0, inf = 0, big = 0;
        const size_t n = (size_t)im.width * (size_t)im.height * (size_t)im.channels;
        for (size_t i = 0; i < n; i++) {
            const float v = im.f32[i];
            nan += isnan(v);
            inf += isinf(v);
            neg += v < 0.0f;
            big += v >= 256.0f;
        }
        snprintf(note, sizeof note, "file samples: %lld negative, %lld NaN, %lld Inf, %lld >= 256", neg, nan,
                 inf, big);
        stab_input(&in, files[fi][0], im.width, im.height);
        for (int oi = 0; oi < 2; oi++) {
            bloom_config_t c;
            stab_config(&c, &in, 5, 1.0, 0.5, 1.0, oi ? BLOOM_FMT_RGBQ16 : BLOOM_FMT_RGB888);
            const res_t r = stab_run(&in, &c, 0);
            stab_emit("float", files[fi][1], &in, &c, "5", &r, note);
        }
        rin_free(&in);
        img_free(&im);
    }
}

/* ---- frame shapes: deep pyramids on thin frames, 1-pixel frames ---------------- */

static void rgb_flat(rin_t *in, const char *name, int w, int h, uint8_t code)
{
    char err[512];
    if (rin_make(in, "dark", stab_data_dir, w, h, err, sizeof err))
        rdie("%s", err);
    snprintf(in->name, sizeof in->name, "%s", name);
    memset(in->p, code, in->bytes);
    for (size_t i = 0; i < in->bytes; i++)
        in->codes[i] = code;
}

void stab_shapes(FILE *md)
{
    (void)md;
    stab_table("Deep pyramids on thin frames, 1-pixel frames",
               "Every level count N = 1..16 on each frame; rows group the counts that build "
               "the same pyramid (L: a level needs both sides >= 2, level 1 always exists). "
               "Threshold 0.6, soft knee 0.5, intensity 1 and 10. `scene` is the benchmark "
               "scene (sim/bench/scene.c) at the frame size; `white`/`grey` are flat codes "
               "255/128.");
    static const struct {
        const char *input;
        int w, h;
    } fr[] = {
        {"scene", 16, 4000}, {"scene", 4000, 16}, {"studio", 16, 4000}, {"studio", 4000, 16},
        {"scene", 2, 8192},  {"scene", 8192, 2},  {"white", 1, 1},      {"grey", 1, 1},
        {"scene", 1, 1000},  {"scene", 1000, 1},  {"scene", 2, 2},      {"scene", 3, 3},
    };
    for (size_t fi = 0; fi < sizeof fr / sizeof fr[0]; fi++) {
        rin_t in;
        if (!strcmp(fr[fi].input, "white") || !strcmp(fr[fi].input, "grey"))
            rgb_flat(&in, fr[fi].input, fr[fi].w, fr[fi].h, fr[fi].input[0] == 'w' ? 255 : 128);
        else
            stab_input(&in, fr[fi].input, fr[fi].w, fr[fi].h);
        for (int ii = 0; ii < 2; ii++) {
            const double I = ii ? 10.0 : 1.0;
            res_t prev;
            bloom_config_t c;
            int from = 1;
            for (int n = 1; n <= BLOOM_MAX_LEVELS + 1; n++) {
                res_t r;
                memset(&r, 0, sizeof r);
                if (n <= BLOOM_MAX_LEVELS) {
                    stab_config(&c, &in, n, 0.6, 0.5, I, BLOOM_FMT_RGB888);
                    r = stab_run(&in, &c, 0);
                }
                /* a group ends where the pyramid (or the result) changes */
                if (n > 1 && (n > BLOOM_MAX_LEVELS || r.built != prev.built || r.st != prev.st ||
                              r.s.sum_sq != prev.s.sum_sq)) {
                    char lv[16], cas[64];
                    snprintf(lv, sizeof lv, from == n - 1 ? "%d" : "%d-%d", from, n - 1);
                    snprintf(cas, sizeof cas, "%dx%d, intensity %.0f", fr[fi].w, fr[fi].h, I);
                    stab_config(&c, &in, n - 1, 0.6, 0.5, I, BLOOM_FMT_RGB888);
                    stab_emit("shapes", cas, &in, &c, lv, &prev, NULL);
                    from = n;
                }
                prev = r;
            }
        }
        rin_free(&in);
    }
}

/* ---- the stiffest case: a light on black at the largest intensity ------------ */

/* Largest |B_engine - B_exact| in units of 2^-F over the samples whose exact
 * output is below the top code (I*B < 1: only those can be off), from the
 * model's bit-true (= the engine's integers) and float pyramids. */
static double bloom_error(const rin_t *in, const bloom_config_t *c)
{
    bloom_info_t info;
    if (bloom_query(c, &info) != BLOOM_OK)
        rdie("bloom_query");
    bloom_model_params_t p;
    memset(&p, 0, sizeof p);
    p.width = c->width;
    p.height = c->height;
    p.levels = c->levels;
    p.threshold = c->threshold / 65536.0;
    p.soft_knee = c->soft_knee / 65536.0;
    p.intensity = c->intensity / 65536.0;
    p.threshold_q = info.threshold_q;
    p.knee_q = info.knee_q;
    p.intensity_q = info.intensity_q;
    p.lin_bits = BLOOM_LIN_BITS;
    const int sm[3] = {in->src_max, in->src_max, in->src_max};
    bloom_model_pyramid_t ex, bt;
    if (bloom_model_pyramid(&p, in->codes, sm, &ex) < 0)
        rdie("model pyramid");
    p.bittrue = 1;
    if (bloom_model_pyramid(&p, in->codes, sm, &bt) < 0)
        rdie("bit-true pyramid");
    const double one = ldexp(1.0, BLOOM_LIN_BITS), I = bloom_srgb_to_linear(p.intensity);
    double worst = 0.0;
    for (size_t i = 0; i < (size_t)in->w * (size_t)in->h * 3u; i++)
        if (I * ex.B.px[i] < 1.0 && fabs(bt.B.px[i] - ex.B.px[i] * one) > worst)
            worst = fabs(bt.B.px[i] - ex.B.px[i] * one);
    bloom_model_pyramid_free(&ex);
    bloom_model_pyramid_free(&bt);
    return worst;
}

/* Worst case of |B_engine - B_exact| in units of 2^-F by construction, for
 * L levels, where the output is below the top code (sim/docs/report.md, the
 * derivation): e1 = 3.625 at level 1, + 1/2 per box level, + 1 per tent. */
static double db_worst(int L, double I)
{
    return 3.625 * L + L * (L - 1) / 4.0 + L + ldexp(1.0, BLOOM_LIN_BITS - 25) / (I > 0.0 ? I : 1.0);
}

/* 8-bit output bound: dB times I, + 1 for the roundings of S and P, + the
 * intensity's own quantization (half a Q16 LSB times B < 1/I), through the
 * steepest slope of the sRGB encoder. */
static int code_bound(double db, double I)
{
    const double dv = (I * db + 1.0) / ldexp(1.0, BLOOM_LIN_BITS) + (I > 0.0 ? 0.5 / 65536.0 / I : 0.0);
    return 1 + (int)floor(255.0 * 12.92 * dv);
}

void stab_stress(FILE *md)
{
    int within = 1;
    char path[1024], tmp[1100];
    snprintf(path, sizeof path, "%s/stress_f%d.csv", stab_out_dir, BLOOM_LIN_BITS);
    FILE *f = ropen(path, tmp, sizeof tmp);
    fprintf(f, "F,input,width,height,levels,levels_built,peak,mean,exact_pct,db,bound,worst_case_bound,"
               "signed_mean,n_above,n_below\n");
    stab_table(
        "The stiffest case: a light on black at the largest intensity",
        "A 3x3 light (1.0 in RGB888, 255.99998 in RGBQ16) on black and the 24 lights on "
        "the Hubble field, intensity 10.0 (linear I = 223.8), threshold 0.6, soft knee "
        "0.5, every level the frame builds (N above the last row builds the same "
        "pyramid). Notes: `dB` is the largest error of the bloom term B where the "
        "output is below the top code, in units of 2^-F (bit-true against exact "
        "pyramid of the model); `bound` is 1 + floor(3295 * ((I * dB + 1) * 2^-F + "
        "2^-17 / I)): 3295 = 255 * 12.92 codes per unit of linear light is the steepest "
        "slope of the sRGB encoder (at black), + 1 covers the roundings of S and P, "
        "2^-17 / I the quantized intensity (correctly rounded: within half a Q16 LSB) times B < 1 / I.");
    static const struct {
        const char *input;
        int w, h;
    } cs[] = {{"point", 1024, 768}, {"hdr-point", 1024, 768}, {"scene-hubble", 1024, 768}};
    for (size_t ci = 0; ci < sizeof cs / sizeof cs[0]; ci++) {
        rin_t in;
        stab_input(&in, cs[ci].input, cs[ci].w, cs[ci].h);
        for (int n = 1; n <= BLOOM_MAX_LEVELS; n++) {
            bloom_config_t c;
            bloom_info_t info;
            stab_config(&c, &in, n, 0.6, 0.5, 10.0, BLOOM_FMT_RGB888);
            if (bloom_query(&c, &info) != BLOOM_OK || info.levels < n)
                break;
            const res_t r = stab_run(&in, &c, 0);
            const double db = bloom_error(&in, &c), I = info.intensity_q / 65536.0;
            char note[128], lv[8];
            snprintf(note, sizeof note, "dB = %.1f, bound %d LSB", db, code_bound(db, I));
            within &= r.s.peak <= code_bound(db, I);
            /* the bias fields last: plots.gp reads columns 5, 7 and 11 */
            fprintf(f, "%d,%s,%d,%d,%d,%d,%lld,%.6f,%.4f,%.3f,%d,%d,%.6f,%lld,%lld\n", BLOOM_LIN_BITS,
                    in.name, in.w, in.h, n, r.built, r.s.peak, rstat_mean(&r.s), rstat_exact(&r.s), db,
                    code_bound(db, I), code_bound(db_worst(r.built, I), I), rstat_signed_mean(&r.s),
                    r.s.above, r.s.below);
            snprintf(lv, sizeof lv, "%d", n);
            stab_emit("stress", "intensity 10", &in, &c, lv, &r, note);
        }
        rin_free(&in);
    }
    rclose(f, tmp, path);
    fprintf(md,
            "\nEvery row's peak is %s the bound computed from its own dB.\n\n"
            "Worst case by construction (F = %d): dB <= 3.625 L + L(L-1)/4 + L + "
            "2^(F-17)/I, and the output bound above with it:\n\n| L | dB worst case | "
            "bound at intensity 1 | 3 | 5 | 10 |\n|---:|---:|---:|---:|---:|---:|\n",
            within ? "within" : "**not within**", BLOOM_LIN_BITS);
    const double is[4] = {1.0, 3.0, 5.0, 10.0};
    for (int L = 1; L <= BLOOM_MAX_LEVELS; L++) {
        fprintf(md, "| %d | %.1f |", L, db_worst(L, 1.0));
        for (int i = 0; i < 4; i++) {
            const double I = bloom_srgb_to_linear(is[i]);
            fprintf(md, " %d |", code_bound(db_worst(L, I), I));
        }
        fprintf(md, "\n");
    }
}
