/* The gamedev preset against its models (sim/model/model_gamedev.c): bit-exact to
 * the bit-true model over a grid of sizes, requested levels, format pairs,
 * flags and parameters (extremes included) and on real images; error
 * statistics against the float model. Properties: nothing below the
 * threshold blooms (the output is then Reinhard + gamma of the scene),
 * the Gaussian keeps a flat field flat, codes stay in range at the worst
 * case, the output is monotone in the strength. Bad parameters refused; the
 * row interface. sim/docs/presets/gamedev.md. */
#include <stdlib.h>

#include "harness.h"
#include "imgframe.h"
#include "preset_conform.h"

#if BLOOM_USE_GAMEDEV
static bloom_config_t gd_config(int w, int h)
{
    bloom_config_t c;
    bloom_config_default(&c, w, h);
    bloom_config_preset(&c, BLOOM_PRESET_GAMEDEV);
    return c;
}

/* Peak error against the float model, by output kind (sim/docs/presets/gamedev.md,
 * "Error"): 8-bit gamma output, the other code outputs, and Q16 output. */
static errstat_t e8, e_other, e_q16, e8_strong;

static void grid(void)
{
    static const int sizes[][2] = {{1, 1},  {2, 2},   {3, 5},   {7, 3},   {6, 8},
                                   {16, 9}, {33, 17}, {64, 48}, {97, 61}, {100, 70}};
    /* threshold, strength */
    static const uint32_t params[][2] = {{BLOOM_Q16(0.75), BLOOM_ONE},     {0, BLOOM_ONE},
                                         {BLOOM_Q16(0.3), BLOOM_Q16(2.5)}, {BLOOM_Q16(0.5), 0},
                                         {BLOOM_Q16(0.1), 16u << 16},      {BLOOM_Q16(2.0), BLOOM_Q16(4.0)},
                                         {256u << 16, BLOOM_ONE}};
    static const bloom_format_t fmt[4] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                          BLOOM_FMT_RGBQ16};
    static const uint32_t flagsets[] = {0, BLOOM_FLAG_LINEAR, BLOOM_FLAG_DEBUG_VIEW, BLOOM_FLAG_COPY_SOURCE};
    static const int levels[] = {1, 3, 7};
    long long diff = 0;
    int runs = 0, failed = 0, seed = 0;
    /* every size x every format pair (4 x 4) x three of the parameter sets,
     * rotating, so each pair meets every set over the sizes */
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (size_t f = 0; f < 16; f++)
            for (size_t j = 0; j < 3; j++) {
                const size_t pi = (s + f + 3 * j) % (sizeof params / sizeof params[0]);
                seed++;
                const uint32_t flags = flagsets[(s + j + f) % 4];
                const int lv = levels[(s + 2 * j + f) % 3];
                bloom_config_t c = gd_config(sizes[s][0], sizes[s][1]);
                c.levels = lv;
                c.in_fmt = fmt[f / 4];
                c.out_fmt = fmt[f % 4];
                c.threshold = params[pi][0];
                c.p.strength = params[pi][1];
                c.flags = flags;
                frame_t src = frame_random(&c, c.in_fmt, (uint32_t)seed);
                preset_conform_t r = preset_conform(&c, &src, NULL, 0);
                if (!r.ok)
                    fprintf(stderr, "gamedev: run failed at %dx%d params %zu fmts %zu\n", c.width, c.height,
                            pi, f);
                if (r.bittrue_diff)
                    fprintf(stderr,
                            "gamedev: %lld samples differ from the bit-true model at %dx%d params %zu fmts "
                            "%zu flags %u\n",
                            r.bittrue_diff, c.width, c.height, pi, f, flags);
                failed += !r.ok;
                diff += r.bittrue_diff;
                if (c.out_fmt == BLOOM_FMT_RGBQ16)
                    errstat_merge(&e_q16, &r.vs_float);
                else if (c.out_fmt != BLOOM_FMT_RGB888 || (flags & BLOOM_FLAG_LINEAR))
                    errstat_merge(&e_other, &r.vs_float);
                else if (c.p.strength > 4u * BLOOM_ONE)
                    errstat_merge(&e8_strong, &r.vs_float);
                else
                    errstat_merge(&e8, &r.vs_float);
                runs++;
                frame_free(&src);
            }
    CHECKF(failed == 0, "gamedev: engine and models ran (%d of %d failed)", failed, runs);
    CHECKF(diff == 0, "gamedev: bit-exact to the bit-true model over %d runs (%lld samples differ)", runs,
           diff);
}

/* Real images: the rocket (8-bit sRGB) and the hall (HDR PFM), both ways. */
static void real_images(void)
{
    static const char *const names[] = {"rocket_floodlights.ppm", "hall_lamps.pfm"};
    for (int i = 0; i < 2; i++) {
        frame_t src;
        if (!imgframe_load(names[i], &src)) {
            CHECKF(0, "real image %s readable", names[i]);
            continue;
        }
        bloom_config_t c = gd_config(src.w, src.h);
        c.in_fmt = src.fmt;
        if (i == 1)
            c.threshold = BLOOM_ONE; /* the article's HDR threshold */
        for (int o = 0; o < 2; o++) {
            c.out_fmt = o ? BLOOM_FMT_RGBQ16 : BLOOM_FMT_RGB888;
            preset_conform_t r = preset_conform(&c, &src, NULL, 0);
            CHECKF(r.ok && r.bittrue_diff == 0, "gamedev %s -> %s: bit-exact (%lld differ)", names[i],
                   o ? "RGBQ16" : "RGB888", r.bittrue_diff);
            char what[80];
            snprintf(what, sizeof what, "gamedev %.12s %s vs float", names[i], o ? "Q16" : "888");
            errstat_print(what, &r.vs_float);
            errstat_merge(o ? &e_q16 : &e8, &r.vs_float);
        }
        frame_free(&src);
    }
}

/* Dark HDR scenes (most samples 2^-8 .. 2^-15 of a random value up to 4.0,
 * one in 50 pixels bright, up to 20.0), where the gamma curve and the
 * strength amplify the bloom's rounding the most: every output format, a
 * linear and a gamma run, strengths 1, 4 and 16. */
static errstat_t dark_code, dark_q16_low, dark_q16_high;

static void dark_hdr(void)
{
    static const bloom_format_t of[] = {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGB888, BLOOM_FMT_RGB565};
    static const uint32_t strengths[] = {BLOOM_ONE, 4u << 16, 16u << 16};
    long long diff = 0;
    int failed = 0;
    for (int o = 0; o < 3; o++)
        for (int si = 0; si < 3; si++)
            for (int seed = 1; seed <= 24; seed++) {
                const int w = 5 + seed % 37, h = 4 + (seed * 7) % 41;
                bloom_config_t c = gd_config(w, h);
                c.in_fmt = BLOOM_FMT_RGBQ16;
                c.out_fmt = of[o];
                c.p.strength = strengths[si];
                c.threshold = (uint32_t)(seed % 4) * BLOOM_Q16(0.05);
                c.flags = seed & 1 ? BLOOM_FLAG_LINEAR : 0;
                frame_t src = frame_random(&c, c.in_fmt, (uint32_t)seed);
                uint32_t rs = (uint32_t)seed;
                for (int y = 0; y < h; y++)
                    for (int x = 0; x < w; x++) {
                        uint32_t v[3];
                        uint8_t *px = src.p + (size_t)y * src.stride + (size_t)x * 12u;
                        memcpy(v, px, 12);
                        const int keep = rng_next(&rs) % 50u == 0;
                        for (int k = 0; k < 3; k++)
                            v[k] = keep ? v[k] * (uint32_t)(seed % 5 + 1) : v[k] >> (8 + seed % 8);
                        memcpy(px, v, 12);
                    }
                preset_conform_t r = preset_conform(&c, &src, NULL, 0);
                failed += !r.ok;
                diff += r.bittrue_diff;
                errstat_merge(o ? &dark_code : si < 2 ? &dark_q16_low : &dark_q16_high, &r.vs_float);
                frame_free(&src);
            }
    CHECKF(failed == 0 && diff == 0, "gamedev dark HDR scenes: bit-exact (%d failed, %lld differ)", failed,
           diff);
}

/* The float-model figures, asserted (sim/docs/presets/gamedev.md, "Error"). */
static void error_bounds(void)
{
    errstat_print("gamedev 888 gamma, strength <= 4", &e8);
    errstat_print("gamedev 888 gamma, strength 16", &e8_strong);
    errstat_print("gamedev 565/XRGB/linear outputs", &e_other);
    errstat_print("gamedev RGBQ16 out (Q16 LSB)", &e_q16);
    errstat_print("gamedev dark HDR, 888/565 out", &dark_code);
    errstat_print("gamedev dark HDR, Q16 out, s <= 4", &dark_q16_low);
    errstat_print("gamedev dark HDR, Q16 out, s = 16", &dark_q16_high);
#if BLOOM_LIN_BITS == 20 /* the figures of Q12.20; fewer bits: printed only */
    CHECKF(e8.peak <= 1, "gamedev: 8-bit peak %d LSB against the float model (strength <= 4)", e8.peak);
    CHECKF(e_other.peak <= 1, "gamedev: 565/XRGB/linear peak %d LSB", e_other.peak);
    CHECKF(e8_strong.peak <= 1, "gamedev: 8-bit peak %d LSB at strength 16", e8_strong.peak);
    CHECKF(e_q16.peak <= 1 && dark_q16_low.peak <= 1,
           "gamedev: RGBQ16 out peak %d / %d Q16 LSB (strength <= 4)", e_q16.peak, dark_q16_low.peak);
    CHECKF(dark_code.peak <= 1, "gamedev: dark HDR scenes, code outputs peak %d LSB", dark_code.peak);
    /* strength 16 multiplies the bloom's Q12.20 rounding by 16: one Q16 LSB
     * is 16 Q12.20 LSB (sim/docs/presets/gamedev.md, "Error") */
    CHECKF(dark_q16_high.peak <= 2, "gamedev: RGBQ16 out peak %d Q16 LSB at strength 16", dark_q16_high.peak);
#endif
}

/* Expected code of a linear c (Q(32-F).F integer) by the recipe's formula. */
static uint32_t tonemap_code(double c, int n)
{
    const double r = c / (c + (double)(1u << BLOOM_LIN_BITS)), e = floor(pow(r, 1.0 / 2.2) * n + 0.5);
    return (uint32_t)(e > n ? n : e);
}

/* Below the threshold nothing blooms: with t = 1.0 no 8-bit pixel has L > t
 * (white has L = 1.0 exactly), so the output is Reinhard + gamma of the
 * decoded scene, and the debug view is black. Every source row is dark
 * (the dark cut is t): the output rows come from the per-code table (the
 * frame is wide enough for it, 211 >= 81). */
static void below_threshold(void)
{
    bloom_config_t c = gd_config(211, 43);
    c.threshold = BLOOM_ONE;
    c.p.strength = 16u << 16;
    frame_t src = frame_random(&c, c.in_fmt, 77);
    /* white corner block, to have L = t exactly somewhere */
    for (int y = 0; y < 10; y++)
        memset(src.p + (size_t)y * src.stride, 255, 30);
    frame_t out = run_engine(&c, &src);
    int bad = 0;
    for (int y = 0; y < c.height; y++)
        for (int x = 0; x < c.width; x++)
            for (int ch = 0; ch < 3; ch++) {
                const uint32_t code = src.p[(size_t)y * src.stride + (size_t)x * 3u + (size_t)ch];
                const double s = bloom_model_decode(1, 0, code, 255, BLOOM_LIN_BITS);
                bad += out.p[(size_t)y * out.stride + (size_t)x * 3u + (size_t)ch] != tonemap_code(s, 255);
            }
    CHECKF(bad == 0, "gamedev: below threshold the output is Reinhard + gamma of the scene (%d differ)", bad);
    c.flags = BLOOM_FLAG_DEBUG_VIEW;
    frame_t dbg = run_engine(&c, &src);
    frame_t black = frame_alloc(c.width, c.height, c.out_fmt, 0);
    CHECKF(frame_equal(&dbg, &black), "gamedev: below threshold the debug view is black");
    frame_free(&black);
    frame_free(&dbg);
    frame_free(&out);
    frame_free(&src);
}

/* A flat field stays flat: every level equals D1 = v * f, the Gaussian and
 * the tent return it unchanged, so B = 3 * D1 and every pixel has the same
 * value, c = v + strength * 3 * D1 (computed here from the integer recipe). */
static void flat_field(void)
{
    const uint32_t v = 3u << 16; /* 3.0 linear */
    bloom_config_t c = gd_config(45, 37);
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
    c.threshold = BLOOM_ONE;
    c.p.strength = BLOOM_Q16(0.5);
    frame_t src = frame_q16_fill(45, 37, v);
    frame_t out = run_engine(&c, &src);
    /* D1 = (V * f + 2^31) >> 32, f = round(n * 2^32 / d), n and d = 10000 (V - T)
     * and 10000 V halved until d < 2^32 */
    const uint64_t V = (uint64_t)v << (BLOOM_LIN_BITS - 16), T = 1u << BLOOM_LIN_BITS;
    uint64_t n = 10000u * (V - T), dd = 10000u * V;
    while (dd > 0xFFFFFFFFu) {
        n >>= 1;
        dd >>= 1;
    }
    const uint64_t f = ((n << 32) + dd / 2) / dd, d1 = (V * f + 0x80000000u) >> 32;
    const uint64_t cc = V + ((c.p.strength * 3u * d1 + 32768u) >> 16);
    const uint32_t want = (uint32_t)(((cc << 17) + cc + T) / (2u * (cc + T)));
    int bad = 0;
    for (int y = 0; y < 37; y++)
        for (int x = 0; x < 45; x++)
            bad += frame_get_q16(&out, x, y) != want;
    CHECKF(bad == 0, "gamedev: a flat field stays flat (%d of %d pixels off %u)", bad, 45 * 37, want);
    frame_free(&out);
    frame_free(&src);
}

/* The worst case of every intermediate: every input word at the largest
 * linear value (clamped from 0xFFFFFFFF), threshold 0, strength 16, three
 * levels. c = S + 16 * 3 * M passes 2^32 (the composite is 64-bit and the
 * Q16 tone map takes its long-division path); RGBQ16 output does not
 * saturate, so an overflow could not hide. Bit-exact with the model; codes
 * in range. */
static void worst_case(void)
{
    bloom_config_t c = gd_config(40, 36);
    c.in_fmt = BLOOM_FMT_RGBQ16;
    c.threshold = 0;
    c.p.strength = 16u << 16;
    frame_t src = frame_q16_fill(40, 36, 0xFFFFFFFFu);
    frame_t r8 = frame_random(&c, BLOOM_FMT_RGBQ16, 3);
    for (int y = 0; y < 36; y += 2) /* and a random half, for non-flat sums */
        memcpy(src.p + (size_t)y * src.stride, r8.p + (size_t)y * r8.stride, 40 * 12);
    for (int o = 0; o < 3; o++) {
        c.out_fmt = o == 0 ? BLOOM_FMT_RGBQ16 : o == 1 ? BLOOM_FMT_RGB888 : BLOOM_FMT_RGB565;
        preset_conform_t r = preset_conform(&c, &src, NULL, 0);
        CHECKF(r.ok && r.bittrue_diff == 0, "gamedev worst case (out fmt %d): bit-exact (%lld differ)",
               c.out_fmt, r.bittrue_diff);
    }
    c.out_fmt = BLOOM_FMT_RGBQ16;
    frame_t out = run_engine(&c, &src);
    uint32_t mx = 0;
    for (int y = 0; y < 36; y++)
        for (int x = 0; x < 40; x++)
            for (int ch = 0; ch < 3; ch++) {
                uint32_t q;
                memcpy(&q, out.p + (size_t)y * out.stride + (size_t)x * 12u + 4u * (size_t)ch, 4);
                mx = q > mx ? q : mx;
            }
    CHECKF(mx <= 65536u && mx > 65000u, "gamedev: tone-mapped Q16 output at most 1.0 (max %u)", mx);
    c.out_fmt = BLOOM_FMT_RGB888;
    frame_t o8 = run_engine(&c, &src);
    int not_white = 0;
    for (size_t i = 0; i < (size_t)40 * 3u; i++)
        not_white += frame_byte(&o8, i) != 255;
    CHECKF(not_white == 0, "gamedev: 8-bit output saturates at 255, never wraps");
    frame_free(&o8);
    frame_free(&out);
    frame_free(&r8);
    frame_free(&src);
}

/* Monotone in the strength: no output code decreases when it grows. */
static void monotone_strength(void)
{
    static const uint32_t st[] = {0, BLOOM_Q16(0.25), BLOOM_ONE, BLOOM_Q16(1.5), 4u << 16, 16u << 16};
    bloom_config_t c = gd_config(61, 47);
    c.threshold = BLOOM_Q16(0.4);
    frame_t src = frame_random(&c, c.in_fmt, 21);
    frame_t prev = run_engine(&c, &src);
    c.p.strength = st[0];
    frame_free(&prev);
    prev = run_engine(&c, &src);
    int down = 0, up = 0;
    for (size_t k = 1; k < sizeof st / sizeof st[0]; k++) {
        c.p.strength = st[k];
        frame_t cur = run_engine(&c, &src);
        for (size_t i = 0; i < (size_t)c.width * (size_t)c.height * 3u; i++) {
            down += frame_byte(&cur, i) < frame_byte(&prev, i);
            up += frame_byte(&cur, i) > frame_byte(&prev, i);
        }
        frame_free(&prev);
        prev = cur;
    }
    CHECKF(down == 0 && up > 0, "gamedev: monotone in strength (%d codes went down, %d up)", down, up);
    frame_free(&prev);
    frame_free(&src);
}

/* cfg->levels is ignored (always 3 levels when the frame allows); info. */
static void levels_and_info(void)
{
    bloom_config_t c = gd_config(80, 60);
    frame_t src = frame_random(&c, c.in_fmt, 4);
    c.levels = 1;
    frame_t a = run_engine(&c, &src);
    c.levels = 9;
    frame_t b = run_engine(&c, &src);
    CHECKF(frame_equal(&a, &b), "gamedev: cfg->levels does not change the output");
    bloom_info_t info;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    CHECKF(info.levels == 3 && info.level_w[3] == 10 && info.level_h[3] == 8, "gamedev: 3 levels (%d)",
           info.levels);
    CHECK(info.knee_q == 0 && info.intensity_q == c.p.strength);
    c.intensity = 7u << 16; /* ignored */
    c.soft_knee = BLOOM_ONE;
    frame_t d = run_engine(&c, &src);
    CHECKF(frame_equal(&a, &d), "gamedev: intensity and soft knee are ignored");
    c.flags = BLOOM_FLAG_NO_SIMD | BLOOM_FLAG_NO_SKIP; /* the C tent: the same bits */
    frame_t e = run_engine(&c, &src);
    CHECKF(frame_equal(&a, &e), "gamedev: BLOOM_FLAG_NO_SIMD gives the same output");
    frame_free(&e);
    c.flags = 0;
    bloom_config_t s = gd_config(3, 3);
    CHECK(bloom_query(&s, &info) == BLOOM_OK && info.levels == 1);
    s = gd_config(8, 8);
    CHECK(bloom_query(&s, &info) == BLOOM_OK && info.levels == 2);
    /* workspace at the default levels (sim/docs/presets/gamedev.md) */
    static const int ws[][2] = {{1920, 1080}, {320, 240}};
    for (int i = 0; i < 2; i++) {
        s = gd_config(ws[i][0], ws[i][1]);
        CHECK(bloom_query(&s, &info) == BLOOM_OK);
        printf(
            "gamedev %dx%d RGB888: workspace %zu bytes, latency %d rows, source rows %d, rings L1 %zu L2 %zu "
            "L3 %zu\n",
            ws[i][0], ws[i][1], info.workspace_bytes, info.latency_rows, info.source_rows, info.ring_bytes[1],
            info.ring_bytes[2], info.ring_bytes[3]);
        s.flags = BLOOM_FLAG_COPY_SOURCE;
        CHECK(bloom_query(&s, &info) == BLOOM_OK);
        printf("gamedev %dx%d RGB888 COPY_SOURCE: workspace %zu bytes\n", ws[i][0], ws[i][1],
               info.workspace_bytes);
    }
    frame_free(&a);
    frame_free(&b);
    frame_free(&d);
    frame_free(&src);
}

static void bad_params(void)
{
    bloom_config_t c = gd_config(64, 48);
    bloom_info_t info;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    c.p.strength = (16u << 16) + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_STRENGTH);
    CHECK(bloom_workspace_size(&c) == 0);
    c.p.strength = 16u << 16;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    static const uint32_t foreign[] = {BLOOM_FLAG_SATURATE, BLOOM_FLAG_BAKED, BLOOM_FLAG_ADDITIVE};
    for (int i = 0; i < 3; i++) {
        c.flags = foreign[i];
        CHECK(bloom_query(&c, &info) == BLOOM_E_FLAGS);
    }
    c.flags = 1u << 20;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FLAGS);
    c.flags = BLOOM_FLAG_LINEAR | BLOOM_FLAG_DEBUG_VIEW | BLOOM_FLAG_COPY_SOURCE | BLOOM_FLAG_NO_SKIP |
              BLOOM_FLAG_NO_SIMD;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    c.flags = 0;
    c.aux_fmt = BLOOM_AUX_U8;
    CHECK(bloom_query(&c, &info) == BLOOM_E_AUX);
    c.aux_fmt = (bloom_aux_format_t)9;
    CHECK(bloom_query(&c, &info) == BLOOM_E_AUX);
    c.aux_fmt = BLOOM_AUX_NONE;
    c.threshold = BLOOM_MAX_THRESHOLD + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_THRESHOLD);
    c.threshold = BLOOM_MAX_THRESHOLD;
    c.intensity = BLOOM_MAX_INTENSITY + 1u; /* ignored by the preset, still range-checked */
    CHECK(bloom_query(&c, &info) == BLOOM_E_INTENSITY);
    c.intensity = 0;
    c.levels = 0;
    CHECK(bloom_query(&c, &info) == BLOOM_E_LEVELS);
    c.levels = 3;
    c.width = 0;
    CHECK(bloom_query(&c, &info) == BLOOM_E_SIZE);
    c.width = 64;
    c.out_fmt = (bloom_format_t)0;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FORMAT);
}

/* Row interface (preset_check_rows): BUSY once the source ring's rows are
 * all pushed. */
static void rows(void)
{
    bloom_config_t c = gd_config(50, 90);
    c.threshold = BLOOM_Q16(0.3);
    frame_t src = frame_random(&c, c.in_fmt, 8);
    const rows_check_t rc = preset_check_rows(&c, &src, NULL, 0);
    CHECKF(rc.busy > 0 && rc.pushed_before_pull == rc.source_rows,
           "gamedev rows: BUSY after %d rows (source_rows %d)", rc.pushed_before_pull, rc.source_rows);
    frame_free(&src);
}
#endif

int main(void)
{
#if BLOOM_USE_GAMEDEV
    grid();
    real_images();
    dark_hdr();
    error_bounds();
    below_threshold();
    flat_field();
    worst_case();
    monotone_strength();
    levels_and_info();
    bad_params();
    rows();
#else
    SKIP("gamedev preset: compiled out (BLOOM_USE_GAMEDEV=0)");
#endif
    return harness_finish();
}
