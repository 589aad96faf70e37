/* The arm preset (sim/docs/presets/arm.md) against its models: bit-exact to
 * the bit-true model over a grid of sizes, depths, format pairs, parameters,
 * masks and baked maps; error statistics against the float model; real
 * images; the preset's properties (mask of zeros, full mask, zero map, flat
 * field, one-channel rings); the worst case of the overflow proof; bad
 * parameters; the row interface. */
#include <stdlib.h>

#include "harness.h"
#include "imgframe.h"
#include "preset_conform.h"

#if BLOOM_USE_ARM
typedef struct {
    uint32_t threshold, knee, intensity, tint[3];
} arm_params_t;

static const arm_params_t params[] = {
    {BLOOM_Q16(0.5), BLOOM_Q16(0.5), BLOOM_ONE, {BLOOM_ONE, BLOOM_ONE, BLOOM_ONE}},
    {0, 0, BLOOM_Q16(0.6), {BLOOM_ONE, BLOOM_ONE, BLOOM_ONE}},              /* everything blooms */
    {BLOOM_ONE, BLOOM_ONE, BLOOM_Q16(2.0), {BLOOM_ONE, BLOOM_Q16(0.5), 0}}, /* full soft knee, warm tint */
    {BLOOM_Q16(0.2), 0, BLOOM_Q16(0.3), {BLOOM_Q16(0.3), BLOOM_Q16(0.77), BLOOM_ONE}},     /* hard knee */
    {BLOOM_Q16(0.8), BLOOM_Q16(0.25), 10u * BLOOM_ONE, {BLOOM_ONE, BLOOM_ONE, BLOOM_ONE}}, /* intensity 10 */
};
#define NPARAMS (sizeof params / sizeof params[0])

static const bloom_format_t fmts[][2] = {
    {BLOOM_FMT_RGB888, BLOOM_FMT_RGB888}, {BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888},
    {BLOOM_FMT_RGB565, BLOOM_FMT_RGB565}, {BLOOM_FMT_RGB565, BLOOM_FMT_XRGB8888},
    {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16}, {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGB888},
    {BLOOM_FMT_RGB888, BLOOM_FMT_RGBQ16},
};
#define NFMTS (sizeof fmts / sizeof fmts[0])

static const int sizes[][2] = {{1, 1},   {2, 2},   {3, 5},   {7, 3},   {16, 9},
                               {33, 17}, {64, 48}, {97, 61}, {100, 70}};
#define NSIZES (sizeof sizes / sizeof sizes[0])

/* The bound of arm.md ("error against the float model") on RGBQ16 output
 * words (2^-16), for linear intensity I, largest input channel c, depth L:
 * per unit of I the Q16 luminance weights (5.3e-6 c), the Q16 mask (7.63e-6
 * c, with a mask), 2L + 3 roundings of half a Q12.20 step and the float
 * knee's epsilon (1e-5); plus B times the rounding of I * tint (2.29e-5 c);
 * plus one word for the two output roundings. */
static double q16_bound(double I, double c, int L, int mask)
{
    const double per_i = 5.3e-6 * c + (mask ? 7.63e-6 * c : 0.0) + (2.0 * L + 3.0) * ldexp(1.0, -21) + 1e-5;
    return 65536.0 * (I * per_i + 2.29e-5 * c) + 1.0;
}

static void set_params(bloom_config_t *c, const arm_params_t *p)
{
    c->threshold = p->threshold;
    c->soft_knee = p->knee;
    c->intensity = p->intensity;
    memcpy(c->p.tint, p->tint, sizeof c->p.tint);
}

/* Error buckets against the float model: 8-bit codes (RGB888/XRGB8888),
 * RGB565 codes, RGBQ16 words; and intensity 10 (8-bit) on its own. */
typedef struct {
    errstat_t c8, c565, q16, c8_hi, q16_hi;
    long long diff;
    int runs, failed;
} tally_t;

static void tally(tally_t *t, const bloom_config_t *c, const preset_conform_t *r, int hi)
{
    t->runs++;
    t->failed += !r->ok;
    t->diff += r->bittrue_diff;
    errstat_t *e = c->out_fmt == BLOOM_FMT_RGBQ16   ? (hi ? &t->q16_hi : &t->q16)
                   : c->out_fmt == BLOOM_FMT_RGB565 ? &t->c565
                   : hi                             ? &t->c8_hi
                                                    : &t->c8;
    errstat_merge(e, &r->vs_float);
}

static void grid_bloom(void)
{
    tally_t t;
    memset(&t, 0, sizeof t);
    static const int depths[] = {1, 2, 3, 5, 8};
    for (size_t s = 0; s < NSIZES; s++)
        for (size_t d = 0; d < sizeof depths / sizeof depths[0]; d++)
            for (size_t f = 0; f < NFMTS; f++) {
                const size_t pi = (s + d + f) % NPARAMS, variant = (s * 3 + d + f) % 6;
                bloom_config_t c;
                bloom_config_default(&c, sizes[s][0], sizes[s][1]);
                bloom_config_preset(&c, BLOOM_PRESET_ARM);
                c.levels = depths[d];
                c.in_fmt = fmts[f][0];
                c.out_fmt = fmts[f][1];
                set_params(&c, &params[pi]);
                /* masks: none, U8, U16; flags: linear, debug view, copy source */
                c.aux_fmt = variant % 3 == 0   ? BLOOM_AUX_NONE
                            : variant % 3 == 1 ? BLOOM_AUX_U8
                                               : BLOOM_AUX_U16;
                if (variant == 4)
                    c.flags |= BLOOM_FLAG_LINEAR;
                if (variant == 5)
                    c.flags |= BLOOM_FLAG_DEBUG_VIEW;
                if (d & 1)
                    c.flags |= BLOOM_FLAG_COPY_SOURCE;
                if ((s + f) % 4 == 3)
                    c.flags |= BLOOM_FLAG_NO_SKIP;
                frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(s * 101 + d * 13 + f * 3 + 1));
                ptrdiff_t as = 0;
                void *aux =
                    c.aux_fmt ? aux_plane(c.width, c.height, c.aux_fmt, (uint32_t)(s + f), &as) : NULL;
                preset_conform_t r = preset_conform(&c, &src, aux, as);
                tally(&t, &c, &r, params[pi].intensity > 4u * BLOOM_ONE);
                free(aux);
                frame_free(&src);
            }
    CHECKF(t.failed == 0, "arm: engine and models ran (%d of %d failed)", t.failed, t.runs);
    CHECKF(t.diff == 0, "arm: bit-exact to the bit-true model over %d runs (%lld samples differ)", t.runs,
           t.diff);
    errstat_print("arm vs float (8-bit out)", &t.c8);
    errstat_print("arm vs float (8-bit out, I = 10)", &t.c8_hi);
    errstat_print("arm vs float (RGB565 out)", &t.c565);
    errstat_print("arm vs float (RGBQ16 out, LSB 2^-16)", &t.q16);
    errstat_print("arm vs float (RGBQ16 out, I = 10)", &t.q16_hi);
    CHECKF(t.c8.peak <= 1, "arm: 8-bit peak %d LSB against the float model", t.c8.peak);
    CHECKF(t.c565.peak <= 1, "arm: RGB565 peak %d LSB against the float model", t.c565.peak);
    CHECKF(t.c8_hi.peak <= 1, "arm: 8-bit peak %d LSB at intensity 10", t.c8_hi.peak);
    /* RGBQ16 words (2^-16 steps): the bound of arm.md with inputs <= 4.0,
     * L <= 8, a mask, I <= 4.95 (intensity 2) and I = 223.8 (intensity 10) */
    const double b_lo = q16_bound(4.95, 4.0, 8, 1), b_hi = q16_bound(223.8, 4.0, 8, 1);
    printf("arm RGBQ16 bounds: %.0f words (I <= 4.95), %.0f words (I = 223.8)\n", b_lo, b_hi);
    CHECKF(t.q16.peak <= b_lo, "arm: RGBQ16 peak %d (2^-16) against the float model", t.q16.peak);
    CHECKF(t.q16_hi.peak <= b_hi, "arm: RGBQ16 peak %d (2^-16) at intensity 10", t.q16_hi.peak);
}

static void grid_baked(void)
{
    static const uint32_t strengths[] = {0, BLOOM_ONE, 16u * BLOOM_ONE, BLOOM_Q16(0.37), BLOOM_Q16(3.3)};
    tally_t t;
    memset(&t, 0, sizeof t);
    for (size_t s = 0; s < NSIZES; s++)
        for (size_t si = 0; si < sizeof strengths / sizeof strengths[0]; si++)
            for (size_t f = 0; f < NFMTS; f++) {
                bloom_config_t c;
                bloom_config_default(&c, sizes[s][0], sizes[s][1]);
                bloom_config_preset(&c, BLOOM_PRESET_ARM);
                c.flags |= BLOOM_FLAG_BAKED | ((s + f) % 4 == 1 ? BLOOM_FLAG_DEBUG_VIEW : 0) |
                           ((s + si) % 5 == 2 ? BLOOM_FLAG_LINEAR : 0);
                c.in_fmt = fmts[f][0];
                c.out_fmt = fmts[f][1];
                c.p.strength = strengths[si];
                c.aux_fmt = (s + si + f) & 1 ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
                frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(s * 31 + si * 7 + f));
                ptrdiff_t as;
                void *aux = aux_plane(c.width, c.height, c.aux_fmt, (uint32_t)(s * 5 + si), &as);
                preset_conform_t r = preset_conform(&c, &src, aux, as);
                tally(&t, &c, &r, 0);
                free(aux);
                frame_free(&src);
            }
    CHECKF(t.failed == 0, "arm baked: engine and models ran (%d of %d failed)", t.failed, t.runs);
    CHECKF(t.diff == 0, "arm baked: bit-exact over %d runs (%lld samples differ)", t.runs, t.diff);
    errstat_print("arm baked vs float (8-bit out)", &t.c8);
    errstat_print("arm baked vs float (RGB565 out)", &t.c565);
    errstat_print("arm baked vs float (RGBQ16 out)", &t.q16);
    CHECKF(t.c8.peak <= 1, "arm baked: 8-bit peak %d LSB", t.c8.peak);
    CHECKF(t.c565.peak <= 1, "arm baked: RGB565 peak %d LSB", t.c565.peak);
    /* the Q16 map and factor roundings: up to S * (strength + 1) / 2 words, + 1 (arm.md) */
    CHECKF(t.q16.peak <= 35, "arm baked: RGBQ16 peak %d (2^-16)", t.q16.peak);
}

/* Real images: the rocket with a mask (left half may not bloom), the HDR
 * studio lamps into 8-bit, the hall lamps into RGBQ16. */
static void real_images(void)
{
    static const struct {
        const char *name;
        uint32_t threshold;
        bloom_format_t out;
        int mask;
    } imgs[] = {{"rocket_floodlights.ppm", BLOOM_Q16(0.6), BLOOM_FMT_RGB888, 1},
                {"rocket_floodlights.ppm", BLOOM_Q16(0.6), BLOOM_FMT_RGB888, 0},
                {"studio_lamps.pfm", 2u * BLOOM_ONE, BLOOM_FMT_RGB888, 0},
                {"hall_lamps.pfm", BLOOM_ONE, BLOOM_FMT_RGBQ16, 1}};
    for (size_t i = 0; i < sizeof imgs / sizeof imgs[0]; i++) {
        frame_t src;
        if (!imgframe_load(imgs[i].name, &src)) {
            CHECKF(0, "real image %s readable", imgs[i].name);
            continue;
        }
        bloom_config_t c;
        bloom_config_default(&c, src.w, src.h);
        bloom_config_preset(&c, BLOOM_PRESET_ARM);
        c.in_fmt = src.fmt;
        c.out_fmt = imgs[i].out;
        c.threshold = imgs[i].threshold;
        c.intensity = BLOOM_Q16(1.5);
        uint8_t *mask = NULL;
        if (imgs[i].mask) {
            c.aux_fmt = BLOOM_AUX_U8;
            mask = (uint8_t *)xmalloc((size_t)src.w * (size_t)src.h);
            for (int y = 0; y < src.h; y++)
                for (int x = 0; x < src.w; x++)
                    mask[(size_t)y * (size_t)src.w + (size_t)x] =
                        (uint8_t)(x < src.w / 2 ? 0 : 255 * (y % 7) / 6);
        }
        preset_conform_t r = preset_conform(&c, &src, mask, src.w);
        CHECK(r.ok);
        CHECKF(r.bittrue_diff == 0, "arm %s: bit-exact (%lld differ)", imgs[i].name, r.bittrue_diff);
        char what[80];
        snprintf(what, sizeof what, "arm %s%s vs float", imgs[i].name, mask ? " +mask" : "");
        errstat_print(what, &r.vs_float);
        if (c.out_fmt == BLOOM_FMT_RGBQ16) {
            double cmax = 0; /* largest input channel, clamped at 256 as decoded */
            for (int y = 0; y < src.h; y++)
                for (int x = 0; x < src.w; x++) {
                    uint32_t px[3];
                    memcpy(px, src.p + (size_t)y * src.stride + (size_t)x * 12u, sizeof px);
                    for (int ch = 0; ch < 3; ch++)
                        cmax = px[ch] / 65536.0 > cmax ? px[ch] / 65536.0 : cmax;
                }
            cmax = cmax > 256.0 ? 256.0 : cmax;
            bloom_info_t info;
            bloom_query(&c, &info);
            const double bnd = q16_bound(info.intensity_q / 65536.0, cmax, info.levels, mask != NULL);
            printf("arm %s: RGBQ16 bound %.0f words (largest input %.2f)\n", imgs[i].name, bnd, cmax);
            CHECKF(r.vs_float.peak <= bnd, "arm %s: RGBQ16 peak %d (bound %.0f)", imgs[i].name,
                   r.vs_float.peak, bnd);
        } else
            CHECKF(r.vs_float.peak <= 1, "arm %s: peak %d LSB", imgs[i].name, r.vs_float.peak);
        free(mask);
        frame_free(&src);
    }
}

/* Same channel codes (the X byte of XRGB8888 is written as 0xFF). */
static int same_codes(const frame_t *a, const frame_t *b)
{
    uint32_t *ca = frame_codes(a), *cb = frame_codes(b);
    const int same =
        a->w == b->w && a->h == b->h && !memcmp(ca, cb, (size_t)a->w * (size_t)a->h * 3u * sizeof *ca);
    free(ca);
    free(cb);
    return same;
}

/* Mask of zeros: no bloom (8-bit sRGB output = input codes); full mask (U8
 * 255, U16 65535) = no mask; baked map of zeros = input. */
static void masks_and_maps(void)
{
    static const bloom_format_t f8[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565};
    for (size_t f = 0; f < 3; f++) {
        bloom_config_t c;
        bloom_config_default(&c, 45, 31);
        bloom_config_preset(&c, BLOOM_PRESET_ARM);
        c.in_fmt = c.out_fmt = f8[f];
        c.threshold = 0; /* everything would bloom */
        c.intensity = 3u * BLOOM_ONE;
        frame_t src = frame_random(&c, c.in_fmt, (uint32_t)f + 40u);
        uint16_t *m16 = (uint16_t *)xmalloc(45 * 31 * 2);
        uint8_t *m8 = (uint8_t *)xmalloc(45 * 31);
        /* zeros */
        memset(m8, 0, 45 * 31);
        memset(m16, 0, 45 * 31 * 2);
        c.aux_fmt = BLOOM_AUX_U8;
        frame_t o = run_engine_aux(&c, &src, m8, 45);
        CHECKF(same_codes(&o, &src), "mask of zeros (U8, format %d): output = input", (int)c.in_fmt);
        frame_free(&o);
        c.aux_fmt = BLOOM_AUX_U16;
        o = run_engine_aux(&c, &src, m16, 90);
        CHECKF(same_codes(&o, &src), "mask of zeros (U16): output = input");
        frame_free(&o);
        /* full = none */
        bloom_config_t n = c;
        n.aux_fmt = BLOOM_AUX_NONE;
        frame_t ref = run_engine(&n, &src);
        CHECK(!same_codes(&ref, &src)); /* there is bloom to mask */
        memset(m8, 255, 45 * 31);
        for (int i = 0; i < 45 * 31; i++)
            m16[i] = 65535;
        c.aux_fmt = BLOOM_AUX_U8;
        o = run_engine_aux(&c, &src, m8, 45);
        CHECKF(frame_equal(&o, &ref), "full mask (U8) = no mask");
        frame_free(&o);
        c.aux_fmt = BLOOM_AUX_U16;
        o = run_engine_aux(&c, &src, m16, 90);
        CHECKF(frame_equal(&o, &ref), "full mask (U16) = no mask");
        frame_free(&o);
        /* the zero-chunk shortcut changes no bit */
        bloom_config_t ns = n;
        ns.flags |= BLOOM_FLAG_NO_SKIP;
        frame_t o2 = run_engine(&ns, &src);
        CHECKF(frame_equal(&o2, &ref), "BLOOM_FLAG_NO_SKIP gives the same bytes");
        frame_free(&o2);
        /* baked, map of zeros, any strength */
        c.flags |= BLOOM_FLAG_BAKED;
        c.p.strength = 16u * BLOOM_ONE;
        memset(m16, 0, 45 * 31 * 2);
        o = run_engine_aux(&c, &src, m16, 90);
        CHECKF(same_codes(&o, &src), "baked map of zeros = input");
        frame_free(&o);
        /* and a map of ones with strength 0 */
        c.aux_fmt = BLOOM_AUX_U8;
        c.p.strength = 0;
        o = run_engine_aux(&c, &src, m8, 45);
        CHECKF(same_codes(&o, &src), "baked strength 0 = input");
        frame_free(&o);
        frame_free(&ref);
        frame_free(&src);
        free(m8);
        free(m16);
    }
}

/* The dual kernels sum to one: a flat grey RGBQ16 field with threshold 0,
 * intensity 1 and the debug view comes out as itself (Y of grey = grey,
 * down and up keep a flat field exactly, I*B = B), at every depth; up to
 * the largest value (the worst case of every sum in arm.md). */
static void flat_field(void)
{
    static const uint32_t vals[] = {1, 12345, BLOOM_ONE, 3u * BLOOM_ONE + 77u, BLOOM_MAX_LINEAR};
    static const int fs[][2] = {{1, 1}, {5, 3}, {64, 64}, {97, 61}};
    int bad = 0, runs = 0;
    for (size_t s = 0; s < 4; s++)
        for (size_t v = 0; v < sizeof vals / sizeof vals[0]; v++)
            for (int levels = 1; levels <= 7; levels += 3) {
                bloom_config_t c;
                bloom_config_default(&c, fs[s][0], fs[s][1]);
                bloom_config_preset(&c, BLOOM_PRESET_ARM);
                c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
                c.threshold = 0;
                c.intensity = BLOOM_ONE;
                c.levels = levels;
                c.flags |= BLOOM_FLAG_DEBUG_VIEW;
                frame_t src = frame_q16_fill(c.width, c.height, vals[v]);
                frame_t o = run_engine(&c, &src);
                bad += !frame_equal(&o, &src);
                runs++;
                frame_free(&o);
                frame_free(&src);
            }
    CHECKF(bad == 0, "flat grey field stays flat through the dual pyramid (%d of %d runs differ)", bad, runs);
}

/* Worst case of the overflow proof (arm.md): every input word at the
 * largest value (and above: clamped), threshold 0, deep pyramid; intensity
 * 10 and the debug view at intensity 0.3 and 1 (not saturated, so a wrapped
 * sum would show); baked with strength 16 and 0.9. Bit-exact with the
 * model, which computes exactly. */
static void worst_case(void)
{
    for (int mode = 0; mode < 5; mode++) {
        bloom_config_t c;
        bloom_config_default(&c, 256, 160);
        bloom_config_preset(&c, BLOOM_PRESET_ARM);
        c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
        c.threshold = 0;
        c.levels = 8;
        c.aux_fmt = BLOOM_AUX_U16;
        c.intensity = mode == 0 ? 10u * BLOOM_ONE : mode == 1 ? BLOOM_Q16(0.3) : BLOOM_ONE;
        if (mode >= 1)
            c.flags |= BLOOM_FLAG_DEBUG_VIEW;
        if (mode >= 3) {
            c.flags |= BLOOM_FLAG_BAKED;
            c.p.strength = mode == 3 ? 16u * BLOOM_ONE : BLOOM_Q16(0.9);
        }
        frame_t src = frame_q16_fill(c.width, c.height, 0xFFFFFFFFu);
        /* a few dark pixels so the pyramid is not flat */
        for (int i = 0; i < 40; i++)
            frame_set_q16(&src, (i * 37) % 256, (i * 53) % 160, (uint32_t)i * 1000u);
        uint16_t *m = (uint16_t *)xmalloc(256 * 160 * 2);
        for (int i = 0; i < 256 * 160; i++)
            m[i] = 65535;
        preset_conform_t r = preset_conform(&c, &src, m, 512);
        CHECK(r.ok);
        CHECKF(r.bittrue_diff == 0, "worst case mode %d: bit-exact (%lld differ)", mode, r.bittrue_diff);
        free(m);
        frame_free(&src);
    }
}

/* floor(q / 3) = (q * 0xAAAAAAAB) >> 33 for every q < 2^30 (the range of
 * q = (S + 96) >> 6, S <= 192 M); the proof for all of uint32 is in arm.md. */
static void div3(void)
{
    uint32_t bad = 0;
    for (uint32_t q = 0; q < (1u << 30); q++)
        bad += (uint32_t)(((uint64_t)q * 0xAAAAAAABu) >> 33) != q / 3u;
    for (uint32_t q = 0xFFFFFFFFu; q > 0xFFFF0000u; q--)
        bad += (uint32_t)(((uint64_t)q * 0xAAAAAAABu) >> 33) != q / 3u;
    CHECKF(bad == 0, "q * 0xAAAAAAAB >> 33 = q / 3 for q < 2^30 and the top 2^16 (%u differ)", bad);
}

/* Ring bytes: the one-channel pyramid against the default's 3 channels. */
static void rings(void)
{
    static const int rs[][2] = {{320, 240}, {640, 480}, {1920, 1080}};
    for (size_t s = 0; s < 3; s++) {
        bloom_config_t u, a;
        bloom_config_default(&u, rs[s][0], rs[s][1]);
        a = u;
        bloom_config_preset(&a, BLOOM_PRESET_ARM);
        bloom_info_t iu, ia;
        CHECK(bloom_query(&u, &iu) == BLOOM_OK && bloom_query(&a, &ia) == BLOOM_OK);
        CHECK(iu.levels == ia.levels);
        size_t su = 0, sa = 0;
        for (int k = 1; k <= iu.levels; k++) {
            su += iu.ring_bytes[k];
            sa += ia.ring_bytes[k];
        }
        printf("rings %dx%d L=%d: arm %zu B, default %zu B (ratio %.3f); workspace arm %zu B, default %zu B; "
               "latency arm %d, default %d rows\n",
               rs[s][0], rs[s][1], ia.levels, sa, su, (double)sa / (double)su, ia.workspace_bytes,
               iu.workspace_bytes, ia.latency_rows, iu.latency_rows);
        CHECKF(3 * sa <= su, "arm rings (%zu B) at most a third of the default's (%zu B) at %dx%d", sa, su,
               rs[s][0], rs[s][1]);
        /* baked: no pyramid at all */
        a.flags |= BLOOM_FLAG_BAKED;
        a.aux_fmt = BLOOM_AUX_U8;
        CHECK(bloom_query(&a, &ia) == BLOOM_OK);
        size_t sb = 0;
        for (int k = 0; k <= ia.levels; k++)
            sb += ia.ring_bytes[k];
        CHECKF(sb == 0 && ia.latency_rows == 0, "baked: no rings (%zu B), no latency (%d)", sb,
               ia.latency_rows);
        printf("baked %dx%d: workspace %zu B, source rows %d\n", rs[s][0], rs[s][1], ia.workspace_bytes,
               ia.source_rows);
    }
}

static void bad_params(void)
{
    bloom_config_t c;
    bloom_info_t info;
    bloom_config_default(&c, 64, 48);
    CHECK(bloom_config_preset(&c, BLOOM_PRESET_ARM) == BLOOM_OK);
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    CHECK(c.aux_fmt == BLOOM_AUX_NONE && c.p.tint[0] == BLOOM_ONE && c.p.tint[2] == BLOOM_ONE);
    const bloom_config_t ok = c;
    for (int ch = 0; ch < 3; ch++) {
        c = ok;
        c.p.tint[ch] = BLOOM_ONE + 1u;
        CHECK(bloom_query(&c, &info) == BLOOM_E_TINT);
        c.p.tint[ch] = BLOOM_ONE;
        CHECK(bloom_query(&c, &info) == BLOOM_OK);
    }
    c = ok;
    c.p.strength = 16u * BLOOM_ONE + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_STRENGTH);
    c.p.strength = 16u * BLOOM_ONE;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    c = ok;
    c.flags |= BLOOM_FLAG_SATURATE;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FLAGS);
    c = ok;
    c.flags |= BLOOM_FLAG_ADDITIVE;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FLAGS);
    c = ok;
    c.flags |= 1u << 12;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FLAGS);
    c = ok;
    c.flags |= BLOOM_FLAG_BAKED; /* the map is the aux plane: required */
    CHECK(bloom_query(&c, &info) == BLOOM_E_AUX);
    c.aux_fmt = BLOOM_AUX_U16;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    c = ok;
    c.aux_fmt = (bloom_aux_format_t)5;
    CHECK(bloom_query(&c, &info) == BLOOM_E_AUX);
    c.aux_fmt = BLOOM_AUX_U8;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    c = ok;
    c.levels = 0;
    CHECK(bloom_query(&c, &info) == BLOOM_E_LEVELS);
    c = ok;
    c.threshold = BLOOM_MAX_THRESHOLD + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_THRESHOLD);
    c = ok;
    c.width = 0;
    CHECK(bloom_query(&c, &info) == BLOOM_E_SIZE);
    CHECK(bloom_workspace_size(&c) == 0);
}

/* Row interface with a mask (preset_check_rows): the ring fills after
 * more than one row pushed without pulling. */
static void row_interface(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 40, 30);
    bloom_config_preset(&c, BLOOM_PRESET_ARM);
    c.threshold = BLOOM_Q16(0.3);
    c.aux_fmt = BLOOM_AUX_U8;
    c.levels = 3;
    frame_t src = frame_random(&c, c.in_fmt, 5);
    uint8_t *mask = (uint8_t *)xmalloc(40 * 30);
    for (int i = 0; i < 40 * 30; i++)
        mask[i] = (uint8_t)(i % 251);
    const rows_check_t rc = preset_check_rows(&c, &src, mask, 40);
    CHECKF(rc.busy > 0 && rc.pushed_before_pull > 1,
           "ring fills after %d rows pushed without pulling (%d BUSY)", rc.pushed_before_pull, rc.busy);
    frame_free(&src);
    free(mask);
}
/* Skipping (arm.md): frames mostly at or below the dark codes, with a few
 * bright spots, so that dark source rows and blocks, zero rows of every
 * level, zero and bounded output chunks all occur. Bit-exact with the
 * bit-true model, and the same bytes with BLOOM_FLAG_NO_SKIP and
 * BLOOM_FLAG_NO_SIMD. */
static void dark_frames(void)
{
    static const bloom_format_t f[][2] = {{BLOOM_FMT_RGB888, BLOOM_FMT_RGB888},
                                          {BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888},
                                          {BLOOM_FMT_RGB565, BLOOM_FMT_RGB565},
                                          {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGB888}};
    static const int sz[][2] = {{61, 47}, {200, 90}, {131, 64}};
    int runs = 0, failed = 0, differ = 0;
    long long diff = 0;
    for (size_t k = 0; k < 4 * 3 * 4; k++) {
        const size_t fi = k % 4, si = (k / 4) % 3, var = k / 12;
        bloom_config_t c;
        bloom_config_default(&c, sz[si][0], sz[si][1]);
        bloom_config_preset(&c, BLOOM_PRESET_ARM);
        c.in_fmt = f[fi][0];
        c.out_fmt = f[fi][1];
        c.threshold = BLOOM_Q16(0.6);
        c.levels = var == 3 ? 3 : 5;
        if (var == 1)
            c.flags |= BLOOM_FLAG_DEBUG_VIEW;
        if (var == 2) {
            c.p.tint[1] = BLOOM_Q16(0.5);
            c.intensity = BLOOM_Q16(2.0);
        }
        if (var == 3)
            c.aux_fmt = BLOOM_AUX_U8;
        frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(k + 900));
        /* dark: every byte scaled to a quarter (RGBQ16 words to 1/64);
         * then two bright spots */
        for (int y = 0; y < c.height; y++)
            for (size_t i = 0; i < (size_t)c.width * (size_t)src.bpp; i++) {
                uint8_t *q = src.p + (size_t)y * src.stride + i;
                *q = c.in_fmt == BLOOM_FMT_RGBQ16   ? (i % 4 >= 2 ? 0 : (uint8_t)(*q >> 2))
                     : c.in_fmt == BLOOM_FMT_RGB565 ? (uint8_t)(*q & 0x18)
                                                    : (uint8_t)(*q >> 2);
            }
        for (int s = 0; s < 2; s++) {
            const int cx = (int)((k * 37 + (size_t)s * 53) % (size_t)c.width), cy = (s + 1) * c.height / 3;
            for (int y = cy - 2; y <= cy + 2; y++)
                for (int x = cx - 2; x <= cx + 2; x++)
                    if (x >= 0 && y >= 0 && x < c.width && y < c.height)
                        memset(src.p + (size_t)y * src.stride + (size_t)x * (size_t)src.bpp,
                               c.in_fmt == BLOOM_FMT_RGBQ16 ? 0x7F : 0xFF, (size_t)src.bpp);
        }
        ptrdiff_t as = 0;
        void *aux = c.aux_fmt ? aux_plane(c.width, c.height, c.aux_fmt, (uint32_t)k, &as) : NULL;
        preset_conform_t r = preset_conform(&c, &src, aux, as);
        runs++;
        failed += !r.ok;
        diff += r.bittrue_diff;
        bloom_config_t ns = c, nv = c;
        ns.flags |= BLOOM_FLAG_NO_SKIP;
        nv.flags |= BLOOM_FLAG_NO_SIMD;
        frame_t o = aux ? run_engine_aux(&c, &src, aux, as) : run_engine(&c, &src);
        frame_t o1 = aux ? run_engine_aux(&ns, &src, aux, as) : run_engine(&ns, &src);
        frame_t o2 = aux ? run_engine_aux(&nv, &src, aux, as) : run_engine(&nv, &src);
        differ += !frame_equal(&o, &o1) || !frame_equal(&o, &o2);
        frame_free(&o);
        frame_free(&o1);
        frame_free(&o2);
        free(aux);
        frame_free(&src);
    }
    CHECKF(failed == 0, "arm dark frames: engine and models ran (%d of %d failed)", failed, runs);
    CHECKF(diff == 0, "arm dark frames: bit-exact to the bit-true model (%lld samples differ)", diff);
    CHECKF(differ == 0, "arm dark frames: NO_SKIP and NO_SIMD give the same bytes (%d of %d differ)", differ,
           runs);
}
#endif

int main(void)
{
#if BLOOM_USE_ARM
    bad_params();
    masks_and_maps();
    flat_field();
    rings();
    row_interface();
    grid_bloom();
    dark_frames();
    grid_baked();
    real_images();
    worst_case();
    div3();
#else
    SKIP("arm preset: compiled out (BLOOM_USE_ARM=0)");
#endif
    return harness_finish();
}
