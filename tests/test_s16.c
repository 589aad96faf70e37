/* 16-bit samples (cfg.sample_bits = 16; sim/docs/fixed-point.md, "16-bit
 * samples"): what is refused and why; the 16-bit kernels against their C
 * twins; the engine bit for bit against the bit-true model with the same
 * option over random configurations (sizes, level counts, formats, flags,
 * tiles, attenuation's plane, arm with and without its mask, xna's passes,
 * C and SIMD kernels); the worst case pushed
 * through (every sample at 1.0, threshold 0, as deep as the frame goes, the
 * largest intensity); the workspace each width needs and its static bound.
 * The error against the float model is tests/test_s16_budget.c. */
#include <stdlib.h>

#include "bloom_kernels.h"
#include "imgframe.h"
#include "preset_conform.h"

static void refusals(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 64, 48);
    CHECK(c.sample_bits == 32);
    c.sample_bits = 0; /* zero is 32 too (configurations made by memset) */
    CHECK(bloom_query(&c, NULL) == BLOOM_OK);
    const int bad[] = {1, 8, 15, 17, 24, 31, 33, 64, -16};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        c.sample_bits = bad[i];
        CHECKF(bloom_query(&c, NULL) == BLOOM_E_SAMPLE_BITS, "sample_bits %d refused", bad[i]);
    }
    c.sample_bits = 16;
    CHECK(bloom_query(&c, NULL) == BLOOM_OK);
    bloom_info_t info;
    /* the default threshold 1.0, knee 0.5: D_1 <= 0.125, 5 * 0.125 < 1: G = 16 */
    CHECK(bloom_query(&c, &info) == BLOOM_OK && info.sample_bits == 16 && info.sample_frac == 16);
    /* HDR input reaches 256.0: more than 16-bit rows hold (no silent clamp) */
    const bloom_format_t hdr[] = {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBF32};
    for (size_t i = 0; i < 2; i++) {
        bloom_config_t h = c;
        h.in_fmt = hdr[i];
        CHECKF(bloom_query(&h, NULL) == BLOOM_E_SAMPLE_BITS, "16-bit samples on %s input refused",
               hdr[i] == BLOOM_FMT_RGBQ16 ? "RGBQ16" : "RGBF32");
    }
    bloom_config_t q = c; /* RGBQ16 output is made from S + I*B: taken */
    q.out_fmt = BLOOM_FMT_RGBQ16;
    CHECK(bloom_query(&q, NULL) == BLOOM_OK);
    for (int p = 1; p < BLOOM_PRESET_COUNT; p++) { /* gamedev, cod: 32-bit stages only */
        bloom_config_t o;
        bloom_config_default(&o, 64, 48);
        if (bloom_config_preset(&o, (bloom_preset_t)p) != BLOOM_OK)
            continue;
        o.sample_bits = 16;
        const bloom_status_t want =
            p == BLOOM_PRESET_ATTENUATION || p == BLOOM_PRESET_ARM || p == BLOOM_PRESET_XNA
                ? BLOOM_OK
                : BLOOM_E_SAMPLE_BITS;
        CHECKF(bloom_query(&o, NULL) == want, "%s with 16-bit samples: %s expected",
               bloom_preset_name((bloom_preset_t)p), bloom_status_str(want));
    }
    CHECK(strstr(bloom_status_str(BLOOM_E_SAMPLE_BITS), "16") != NULL);
#if BLOOM_USE_ARM
    bloom_config_t ab; /* arm's baked map has no pyramid: nothing to hold in 16 bits */
    bloom_config_default(&ab, 64, 48);
    bloom_config_preset(&ab, BLOOM_PRESET_ARM);
    ab.sample_bits = 16;
    /* G: every value at most the knee's peak, whatever the level count */
    CHECK(bloom_query(&ab, &info) == BLOOM_OK && info.sample_bits == 16 && info.sample_frac == 19);
    ab.threshold = 0;
    ab.levels = 16;
    CHECK(bloom_query(&ab, &info) == BLOOM_OK && info.sample_frac == 15);
    ab.flags |= BLOOM_FLAG_BAKED;
    ab.aux_fmt = BLOOM_AUX_U8;
    CHECK(bloom_query(&ab, NULL) == BLOOM_E_SAMPLE_BITS);
#endif
    /* G by level count at threshold 0 (D_1 up to 1.0): L * 2^G < 2^16 */
    const int want[][2] = {{1, 15}, {2, 14}, {3, 14}, {4, 13}, {7, 13}, {8, 12}, {13, 12}};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        bloom_config_t l;
        bloom_config_default(&l, 1 << 15 > BLOOM_MAX_DIM ? BLOOM_MAX_DIM : 1 << 15, 2);
        l.width = l.height = BLOOM_MAX_DIM;
        l.levels = want[i][0];
        l.threshold = 0;
        l.sample_bits = 16;
        CHECKF(
            bloom_query(&l, &info) == BLOOM_OK && info.levels == want[i][0] && info.sample_frac == want[i][1],
            "%d levels: G = %d (got %d levels, G %d)", want[i][0], want[i][1], info.levels, info.sample_frac);
    }
}

/* Random configurations, engine against the bit-true model. */
static void bit_exact(void)
{
    static const bloom_format_t fin[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565};
    static const bloom_format_t fout[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                          BLOOM_FMT_RGBQ16};
    uint32_t s = 16;
    long long diff = 0;
    int runs = 0, tiles = 0;
    int per[BLOOM_PRESET_COUNT] = {0};
    for (int it = 0; it < 300; it++) {
        bloom_config_t c;
        const int w = 1 + (int)(rng_next(&s) % 90), h = 1 + (int)(rng_next(&s) % 70);
        bloom_config_default(&c, w, h);
        c.sample_bits = 16;
        c.levels = 1 + (int)(rng_next(&s) % 16);
        c.in_fmt = fin[rng_next(&s) % 3];
        c.out_fmt = fout[rng_next(&s) % 4];
        const uint32_t r = rng_next(&s);
        c.threshold = r & 1 ? 0 : (rng_next(&s) % (3u << 16));
        c.soft_knee = rng_next(&s) % (BLOOM_ONE + 1);
        c.intensity = r & 2 ? BLOOM_MAX_INTENSITY : rng_next(&s) % (4u << 16);
        c.flags = (r & 4 ? BLOOM_FLAG_LINEAR : 0) | (r & 8 ? BLOOM_FLAG_DEBUG_VIEW : 0) |
                  (r & 16 ? BLOOM_FLAG_NO_SIMD : 0) | (r & 32 ? BLOOM_FLAG_NO_SKIP : 0) |
                  (r & 64 ? BLOOM_FLAG_COPY_SOURCE : 0) | (r & 128 ? BLOOM_FLAG_NO_AVX2 : 0);
        void *aux = NULL;
        ptrdiff_t astride = 0;
        if (r & 1024) { /* attenuation: the same stages, D_1 times a depth factor */
            bloom_config_preset(&c, BLOOM_PRESET_ATTENUATION);
            c.aux_fmt = r & 2048 ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
            aux = aux_plane(w, h, c.aux_fmt, (uint32_t)it, &astride);
        } else if (BLOOM_USE_XNA && (r & 16384)) { /* xna: 16-bit H, Q and passes, 32-bit last pass */
            bloom_config_preset(&c, BLOOM_PRESET_XNA);
            c.threshold = r & 1 ? 0 : rng_next(&s) % BLOOM_ONE;
            c.p.passes = 1 + (int)(rng_next(&s) % 8);
            c.flags |= r & 2048 ? BLOOM_FLAG_SATURATE : 0;
        } else if (BLOOM_USE_ARM && (r & 4096)) { /* arm: one channel, its own filters; a mask or not */
            bloom_config_preset(&c, BLOOM_PRESET_ARM);
            c.p.tint[0] = rng_next(&s) % (BLOOM_ONE + 1);
            if (r & 2048) {
                c.aux_fmt = r & 8192 ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
                aux = aux_plane(w, h, c.aux_fmt, (uint32_t)it, &astride);
            }
        }
        frame_t src = frame_random(&c, c.in_fmt, (uint32_t)it);
        if (r & 256) { /* dark rows and dark blocks: the skip paths */
            for (int y = 0; y < h; y++)
                if ((y / 5) % 2)
                    memset(src.p + (size_t)y * src.stride, 0, (size_t)w * (size_t)src.bpp);
        }
        preset_conform_t pc = preset_conform(&c, &src, aux, astride);
        CHECKF(pc.ok, "%dx%d, %d levels: engine or model failed", w, h, c.levels);
        CHECKF(pc.bittrue_diff == 0, "%dx%d, %d levels, flags %x: %lld samples off the bit-true model", w, h,
               c.levels, (unsigned)c.flags, pc.bittrue_diff);
        diff += pc.bittrue_diff;
        runs++;
        per[c.preset]++;
        /* a tile of the same frame: the bits of the whole frame there */
        if (w > 2 && h > 2 && (r & 512) && !aux) {
            frame_t whole = run_engine(&c, &src);
            bloom_config_t t = c;
            t.tile_x = (int)(rng_next(&s) % (uint32_t)(w - 1));
            t.tile_y = (int)(rng_next(&s) % (uint32_t)(h - 1));
            t.tile_w = 1 + (int)(rng_next(&s) % (uint32_t)(w - t.tile_x));
            t.tile_h = 1 + (int)(rng_next(&s) % (uint32_t)(h - t.tile_y));
            frame_t part = frame_alloc(w, h, c.out_fmt, 0);
            bloom_t *b = NULL;
            const size_t need = bloom_workspace_size(&t);
            void *ws = xmalloc(need + 8);
            bloom_status_t st = bloom_init(&b, ws, need, &t);
            if (st == BLOOM_OK)
                st = bloom_process(b, src.p, (ptrdiff_t)src.stride, part.p, (ptrdiff_t)part.stride);
            CHECKF(st == BLOOM_OK, "tile: %s", bloom_status_str(st));
            int same = 1;
            const size_t bpp = (size_t)bloom_format_bpp(c.out_fmt);
            for (int y = t.tile_y; y < t.tile_y + t.tile_h; y++)
                same &= !memcmp(part.p + (size_t)y * part.stride + (size_t)t.tile_x * bpp,
                                whole.p + (size_t)y * whole.stride + (size_t)t.tile_x * bpp,
                                (size_t)t.tile_w * bpp);
            CHECKF(same, "tile %d,%d %dx%d of %dx%d, %d levels: not the whole frame's bits", t.tile_x,
                   t.tile_y, t.tile_w, t.tile_h, w, h, c.levels);
            tiles++;
            free(ws);
            frame_free(&part);
            frame_free(&whole);
        }
        frame_free(&src);
        free(aux);
    }
    printf("bit-true: %d random configurations (unity %d, attenuation %d, arm %d, xna %d), %lld samples off "
           "the model; %d tiles against their frames\n",
           runs, per[BLOOM_PRESET_UNITY], per[BLOOM_PRESET_ATTENUATION], per[BLOOM_PRESET_ARM],
           per[BLOOM_PRESET_XNA], diff, tiles);
}

/* The 16-bit kernels' twins of a kernel set (AVX2 and SSE2 on x86-64;
 * elsewhere the C ones against themselves, and test-cross runs this on ARM)
 * and the flat tent against the C tent, on random rows, every rounding
 * residue and the largest values the format's bound allows. */
static void twins_of(uint32_t flags)
{
    bloom_kernels_t simd, c;
    bloom_kernels_select(&simd, flags);
    bloom_kernels_select(&c, BLOOM_FLAG_NO_SIMD);
    uint32_t s = 99;
    long bad = 0, cases = 0;
    for (int it = 0; it < 400; it++) {
        const int n = 1 + (int)(rng_next(&s) % 200), sh = 1 + (int)(rng_next(&s) % 9);
        uint32_t src[600], w32a[600], w32b[600];
        uint16_t a[600], b[600], cc[600], d1[600], d2[600], add[600];
        for (int i = 0; i < 3 * n; i++) { /* narrowed values within 0 .. 65535 */
            const uint32_t top = (65535u << sh) + (1u << (sh - 1)) - 1u;
            const uint32_t r = rng_next(&s);
            src[i] = r & 1 ? top - (r >> 24) : (r >> 8) % (top + 1u);
            a[i] = (uint16_t)(it & 1 ? 65535u - (rng_next(&s) & 15u) : rng_next(&s));
            b[i] = (uint16_t)rng_next(&s);
            cc[i] = (uint16_t)(it & 2 ? 65535u : rng_next(&s));
            add[i] = (uint16_t)(rng_next(&s) & 4095u);
        }
        const uint32_t o1 = bloom_row_narrow16_k(&simd, src, d1, 3 * n, sh),
                       o2 = bloom_row_narrow16_c(src, d2, 3 * n, sh);
        bad += o1 != o2 || memcmp(d1, d2, (size_t)(3 * n) * 2u);
        for (int i = 0; i < 3 * n; i++) /* narrowed + add stays within 16 bits: the format's bound */
            src[i] = src[i] >> 1;
        bloom_row_narrow16_add_k(&simd, src, it & 1 ? add : NULL, d1, 3 * n, sh);
        bloom_row_narrow16_add_c(src, it & 1 ? add : NULL, d2, 3 * n, sh);
        bad += memcmp(d1, d2, (size_t)(3 * n) * 2u) != 0;
        const uint32_t v1 = bloom_row_vtent16w_k(&simd, a, b, cc, w32a, 3 * n, sh - 1),
                       v2 = bloom_row_vtent16w_c(a, b, cc, w32b, 3 * n, sh - 1);
        bad += v1 != v2 || memcmp(w32a, w32b, (size_t)(3 * n) * 4u);
        { /* the boxes: n source pixels into (n + 1) / 2, both outputs */
            const uint16_t *const rows[4] = {a, b, cc, add};
            const int dw = (n + 1) / 2;
            bloom_row_box16_k(&simd, rows, d1, false, dw, n, 0);
            bloom_row_box16_c(rows, d2, dw, n);
            bad += memcmp(d1, d2, (size_t)(3 * dw) * 2u) != 0;
            bloom_row_box16_k(&simd, rows, w32a, true, dw, n, sh - 1);
            bloom_row_box16w_c(rows, w32b, dw, n, sh - 1);
            bad += memcmp(w32a, w32b, (size_t)(3 * dw) * 4u) != 0;
        }
        /* the flat tent: sw low-resolution columns, a row of 2 sw or 2 sw - 1 */
        const int sw = 1 + n / 2, w = 2 * sw - (it & 4 ? 1 : 0);
        if (3 * w <= 600) {
            for (int i = 0; i < 3 * sw; i++) { /* U values of a 16-bit ring (<= 65535 - 4095 with add) */
                a[i] = (uint16_t)(a[i] % 61440u);
                b[i] = (uint16_t)(b[i] % 61440u);
                cc[i] = (uint16_t)(cc[i] % 61440u);
            }
            const uint16_t *const u[3] = {a, b, cc};
            for (int k = 0; k < 2; k++) {
                const bloom_kernels_t *ks[2] = {&simd, &c};
                bloom_row_tent16_k(ks[k], u, it & 8 ? 1 : 0, it & 16 ? add : NULL, d1, w, sw);
                bloom_row_tent16_c(u, it & 8 ? 1 : 0, it & 16 ? add : NULL, d2, 0, w, sw);
                bad += memcmp(d1, d2, (size_t)(3 * w) * 2u) != 0;
            }
        }
        cases++;
    }
    CHECKF(bad == 0, "16-bit kernels (%s): %ld of %ld cases differ from C", simd.name, bad, cases);
    printf("16-bit kernels, %s against C: %ld random cases, narrowing (with add), vertical tent, boxes, flat "
           "tent: "
           "%ld differ\n",
           simd.name, cases, bad);
}

static void twins(void)
{
    twins_of(0);
#if defined(__x86_64__)
    twins_of(BLOOM_FLAG_NO_AVX2); /* the SSE2 set */
#endif
}

/* Every sample at 1.0, threshold 0 (everything blooms), as deep as each
 * frame goes: U_1 reaches L * 2^G, the bound of the format; bit-exact with
 * the model, which computes without wrapping. */
static void worst_case(void)
{
    const int sizes[][3] = {{1024, 4, 2}, {256, 256, 8}, {8192, 8, 3}, {2048, 2048, 11}};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        for (int k = 0; k < 2; k++) {
            bloom_config_t c;
            bloom_config_default(&c, sizes[i][0], sizes[i][1]);
            c.sample_bits = 16;
            c.levels = 16;
            c.threshold = 0;
            c.intensity = k ? BLOOM_Q16(0.3) : BLOOM_MAX_INTENSITY;
            c.flags = BLOOM_FLAG_DEBUG_VIEW; /* I*B alone: a wrapped sum could not hide under S */
            c.out_fmt = BLOOM_FMT_RGBQ16;
            if (sizes[i][0] * sizes[i][1] > 1 << 20) { /* (the model's doubles: keep it small) */
                c.width = 2048;
                c.height = 512;
            }
            bloom_info_t info;
            CHECK(bloom_query(&c, &info) == BLOOM_OK);
            frame_t src = frame_alloc(c.width, c.height, BLOOM_FMT_RGB888, 255);
            preset_conform_t pc = preset_conform(&c, &src, NULL, 0);
            CHECKF(pc.ok && pc.bittrue_diff == 0, "%dx%d white, %d levels (G %d), intensity %s: %lld off",
                   c.width, c.height, info.levels, info.sample_frac, k ? "0.3" : "10", pc.bittrue_diff);
            frame_free(&src);
        }
    }
}

/* The arm preset's worst case: white frames at threshold 0 (D_1 at the
 * knee's peak, G = 15), every level count, intensity 10 and full tint. */
static void worst_case_arm(void)
{
#if BLOOM_USE_ARM
    for (int L = 1; L <= 16; L += 3) {
        bloom_config_t c;
        bloom_config_default(&c, 300, 130);
        bloom_config_preset(&c, BLOOM_PRESET_ARM);
        c.sample_bits = 16;
        c.levels = L;
        c.threshold = 0;
        c.intensity = BLOOM_MAX_INTENSITY;
        c.flags = BLOOM_FLAG_DEBUG_VIEW;
        c.out_fmt = BLOOM_FMT_RGBQ16;
        bloom_info_t info;
        CHECK(bloom_query(&c, &info) == BLOOM_OK && info.sample_frac == 15);
        frame_t src = frame_alloc(c.width, c.height, BLOOM_FMT_RGB888, 255);
        preset_conform_t pc = preset_conform(&c, &src, NULL, 0);
        CHECKF(pc.ok && pc.bittrue_diff == 0, "arm white, %d levels: %lld off", info.levels, pc.bittrue_diff);
        frame_free(&src);
    }
#endif
}

/* xna's worst case: white frames where Q's narrowing rounds up most
 * against the range restore (threshold 1 - 3/65536: 43 690 in a 16-bit
 * pass), and at threshold 0, 1 - 1/65536 and 1 - 2/65536; one to three
 * passes, SATURATE or not, intensity 10. */
static void worst_case_xna(void)
{
#if BLOOM_USE_XNA
    const uint32_t th[] = {0, BLOOM_ONE - 1u, BLOOM_ONE - 2u, BLOOM_ONE - 3u};
    int n = 0;
    for (size_t i = 0; i < sizeof th / sizeof th[0]; i++)
        for (int passes = 1; passes <= 3; passes++)
            for (int sat = 0; sat < 2; sat++) {
                bloom_config_t c;
                bloom_config_default(&c, 97, 61);
                bloom_config_preset(&c, BLOOM_PRESET_XNA);
                c.sample_bits = 16;
                c.threshold = th[i];
                c.p.passes = passes;
                c.intensity = BLOOM_MAX_INTENSITY;
                c.flags = BLOOM_FLAG_DEBUG_VIEW | (sat ? BLOOM_FLAG_SATURATE : 0);
                c.out_fmt = BLOOM_FMT_RGBQ16;
                frame_t src = frame_alloc(c.width, c.height, BLOOM_FMT_RGB888, 255);
                preset_conform_t pc = preset_conform(&c, &src, NULL, 0);
                CHECKF(pc.ok && pc.bittrue_diff == 0, "xna white, threshold %u, %d passes%s: %lld off", th[i],
                       passes, sat ? ", saturate" : "", pc.bittrue_diff);
                frame_free(&src);
                n++;
            }
    printf("xna worst case: %d white frames, bit-exact with the model\n", n);
#endif
}

/* The workspace of each width (the rings halve; the source rows, the
 * schedule and the engine's own struct do not). */
static void workspace(void)
{
    const int cases[][4] = {
        {320, 240, BLOOM_FMT_RGB565, 5}, {640, 480, BLOOM_FMT_RGB888, 5}, {1920, 1080, BLOOM_FMT_RGB888, 5}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        bloom_config_t c;
        bloom_config_default(&c, cases[i][0], cases[i][1]);
        c.in_fmt = c.out_fmt = (bloom_format_t)cases[i][2];
        c.levels = cases[i][3];
        const size_t w32 = bloom_workspace_size(&c);
        c.sample_bits = 16;
        const size_t w16 = bloom_workspace_size(&c);
        printf("workspace %dx%d %s: %zu bytes with 32-bit samples, %zu with 16 (%.3fx)\n", cases[i][0],
               cases[i][1], cases[i][2] == BLOOM_FMT_RGB565 ? "RGB565" : "RGB888", w32, w16,
               (double)w16 / (double)w32);
        CHECK(w16 > 0 && w16 < w32);
        const bloom_preset_t others[] = {BLOOM_PRESET_ARM, BLOOM_PRESET_XNA};
        for (size_t p = 0; p < 2; p++) {
            bloom_config_t o = c;
            if (bloom_config_preset(&o, others[p]) != BLOOM_OK)
                continue; /* (compiled out) */
            o.sample_bits = 32;
            const size_t o32 = bloom_workspace_size(&o);
            o.sample_bits = 16;
            const size_t o16 = bloom_workspace_size(&o);
            printf("  %s: %zu bytes with 32-bit samples, %zu with 16 (%.3fx)\n", bloom_preset_name(others[p]),
                   o32, o16, (double)o16 / (double)o32);
            CHECK(o16 > 0 && o16 < o32);
        }
    }
}

/* BLOOM_WORKSPACE_MAX_S with 16: never below the exact size, and below the
 * 32-bit bound. */
static void workspace_macro(void)
{
    const int ws[] = {1, 2, 3, 5, 64, 257, 320, 640, 1280, 1920, 4000, 16384};
    const int hs[] = {1, 2, 7, 131, 240, 480, 1080, 3000};
    const bloom_format_t fmts[] = {BLOOM_FMT_RGB565, BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888};
    int ok = 1, n = 0;
    double worst = 0, gain = 0;
    for (size_t wi = 0; wi < sizeof ws / sizeof ws[0]; wi++)
        for (size_t hi = 0; hi < sizeof hs / sizeof hs[0]; hi++)
            for (int lv = 1; lv <= 16; lv++)
                for (int copy = 0; copy <= 1; copy++) {
                    bloom_config_t c;
                    bloom_config_default(&c, ws[wi], hs[hi]);
                    c.levels = lv;
                    c.sample_bits = 16;
                    c.in_fmt = fmts[(wi + hi + (size_t)lv) % 3];
                    c.flags = copy ? BLOOM_FLAG_COPY_SOURCE : 0;
                    const size_t exact = bloom_workspace_size(&c);
                    if (exact == 0)
                        continue; /* too big for this address space (test_core checks the refusal) */
                    const int bpp = bloom_format_bpp(c.in_fmt);
                    const unsigned long long bound =
                                                 BLOOM_WORKSPACE_MAX_S(c.width, c.height, lv, bpp, copy, 16),
                                             b32 = BLOOM_WORKSPACE_MAX(c.width, c.height, lv, bpp, copy);
                    n++;
                    if (bound < exact || bound > b32) {
                        ok = 0;
                        fprintf(stderr, "%dx%d L%d copy%d: bound %llu, exact %zu, 32-bit bound %llu\n",
                                c.width, c.height, lv, copy, bound, exact, b32);
                    }
                    bloom_info_t info;
                    bloom_query(&c, &info);
                    if (info.levels == lv && lv == 5 && !copy && c.width >= 320) {
                        worst = (double)bound / (double)exact > worst ? (double)bound / (double)exact : worst;
                        gain = (double)bound / (double)b32 > gain ? (double)bound / (double)b32 : gain;
                    }
                }
    CHECK(ok);
    printf(
        "BLOOM_WORKSPACE_MAX_S(..., 16): %d configurations, none below the exact size nor above the 32-bit "
        "bound; at 5 levels built (width >= 320) at most %.2fx the exact size, %.2fx the 32-bit bound\n",
        n, worst, gain);
    CHECK(worst < 1.5);
    BLOOM_WORKSPACE_DEFINE(ws16, BLOOM_WORKSPACE_MAX_S(320, 240, 5, 2, 0, 16));
    bloom_config_t c;
    bloom_config_default(&c, 320, 240);
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGB565;
    c.sample_bits = 16;
    bloom_t *b = NULL;
    CHECK(bloom_init(&b, ws16, sizeof ws16, &c) == BLOOM_OK);
}

int main(void)
{
#if !BLOOM_USE_S16
    SKIP("16-bit samples: compiled out (BLOOM_USE_S16 0)");
    return harness_finish();
#else
    refusals();
    twins();
    bit_exact();
    worst_case();
    worst_case_arm();
    worst_case_xna();
    workspace();
    workspace_macro();
    return harness_finish();
#endif
}
