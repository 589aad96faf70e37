/* The engine through its API: configuration errors, workspace sizing and
 * canaries, streaming invariance, and answers worked out by hand. */
#include <stdlib.h>
#include <string.h>

#include "bloom.h"
#include "harness.h"
#include "testutil.h"

static void test_validation(void)
{
    bloom_config_t c;
    bloom_info_t info;
    bloom_config_default(&c, 64, 48);
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    CHECK(bloom_query(NULL, &info) == BLOOM_E_NULL);
    bloom_config_t bad;
#define EXPECT(field_assign, st)                                                                             \
    do {                                                                                                     \
        bad = c;                                                                                             \
        field_assign;                                                                                        \
        bloom_status_t got = bloom_query(&bad, &info);                                                       \
        CHECKF(got == (st), "%s: got %d (%s)", #field_assign, got, bloom_status_str(got));                   \
        CHECK(bloom_workspace_size(&bad) == 0);                                                              \
    } while (0)
    EXPECT(bad.width = 0, BLOOM_E_SIZE);
    EXPECT(bad.height = -3, BLOOM_E_SIZE);
    EXPECT(bad.width = BLOOM_MAX_DIM + 1, BLOOM_E_SIZE);
    EXPECT(bad.levels = 0, BLOOM_E_LEVELS);
    EXPECT(bad.levels = 17, BLOOM_E_LEVELS);
    EXPECT(bad.levels = 1000, BLOOM_E_LEVELS);
    EXPECT(bad.threshold = BLOOM_MAX_THRESHOLD + 1, BLOOM_E_THRESHOLD);
    EXPECT(bad.soft_knee = BLOOM_ONE + 1, BLOOM_E_KNEE);
    EXPECT(bad.intensity = BLOOM_MAX_INTENSITY + 1, BLOOM_E_INTENSITY);
    EXPECT(bad.in_fmt = (bloom_format_t)0, BLOOM_E_FORMAT);
    EXPECT(bad.out_fmt = (bloom_format_t)99, BLOOM_E_FORMAT);
    EXPECT(bad.flags = 1u << 7, BLOOM_E_FLAGS);
#undef EXPECT
    /* Every status has a message naming the problem. */
    for (int st = -14; st <= 2; st++)
        CHECK(strcmp(bloom_status_str((bloom_status_t)st), "unknown status") != 0);
    /* The limits themselves are accepted. */
    bad = c;
    bad.levels = 16;
    bad.threshold = BLOOM_MAX_THRESHOLD;
    bad.soft_knee = BLOOM_ONE;
    bad.intensity = BLOOM_MAX_INTENSITY;
    CHECK(bloom_query(&bad, &info) == BLOOM_OK);
}

static void test_workspace(void)
{
    const int sizes[][2] = {{1, 1}, {2, 2}, {3, 1}, {1, 7}, {64, 48}, {257, 131}, {640, 480}};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        for (int lv = 1; lv <= 16; lv += 3) {
            for (int copy = 0; copy <= 1; copy++) {
                bloom_config_t c;
                bloom_config_default(&c, sizes[si][0], sizes[si][1]);
                c.levels = lv;
                c.flags = copy ? BLOOM_FLAG_COPY_SOURCE : 0;
                const size_t need = bloom_workspace_size(&c);
                CHECK(need > 0);
                CHECK(bloom_workspace_size(&c) == need); /* pure */
                CHECKF(BLOOM_WORKSPACE_MAX(c.width, c.height, lv, 3, copy) >= need,
                       "%dx%d L%d copy%d: macro %llu < %zu", c.width, c.height, lv, copy,
                       BLOOM_WORKSPACE_MAX(c.width, c.height, lv, 3, copy), need);
                guarded_t ws = guarded_alloc(need);
                bloom_t *b = NULL;
                CHECK(bloom_init(&b, ws.p, need - 1, &c) == BLOOM_E_WORKSPACE);
                CHECK(b == NULL);
                CHECK(bloom_init(&b, ws.p + 1, need, &c) == BLOOM_E_ALIGN);
                CHECK(bloom_init(&b, ws.p, need, &c) == BLOOM_OK);
                frame_t src = frame_random(&c, c.in_fmt, 1234u + (unsigned)si);
                frame_t dst = frame_alloc(c.width, c.height, c.out_fmt, 0);
                CHECK(bloom_process(b, src.p, src.stride, dst.p, dst.stride) == BLOOM_OK);
                CHECK(guarded_intact(&ws));
                CHECK(frame_intact(&dst));
                frame_free(&src);
                frame_free(&dst);
                guarded_free(&ws);
            }
        }
    }
    /* The memory targets of the issue, from the sizing function. */
    bloom_config_t c;
    bloom_config_default(&c, 1920, 1080);
    size_t n = bloom_workspace_size(&c);
    printf("workspace 1920x1080 RGB888, 5 levels: %zu bytes = 1/%.1f of one frame (target <= 1/16)\n", n,
           1920.0 * 1080.0 * 3.0 / (double)n);
    CHECK(n <= 1920u * 1080u * 3u / 16u);
#if BLOOM_SCHED_TABLE
    /* The static schedule is folded (start-up, one period, the end): its
     * table does not grow with the frame's height once the pyramid has
     * filled. Unfolded it took 6 110 bytes at 1080 rows. */
    {
        bloom_info_t i1, i2;
        CHECK(bloom_query(&c, &i1) == BLOOM_OK);
        bloom_config_default(&c, 1920, 4320);
        CHECK(bloom_query(&c, &i2) == BLOOM_OK);
        printf("static schedule, 1920 wide, 5 levels: %zu bytes at 1080 rows, %zu at 4320\n",
               i1.schedule_bytes, i2.schedule_bytes);
        CHECK(i1.schedule_bytes > 0 && i1.schedule_bytes < 2048 && i2.schedule_bytes < 2048);
    }
#endif
    bloom_config_default(&c, 320, 240);
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGB565;
    n = bloom_workspace_size(&c);
    printf("workspace 320x240 RGB565, 5 levels: %zu bytes (target <= 49152)\n", n);
    CHECK(n <= 48u * 1024u);
}

/* The compile-time bound is never below the exact size, and not loose. */
static void test_workspace_macro(void)
{
    const int ws[] = {1, 2, 3, 5, 64, 257, 320, 640, 1280, 1920, 4000, 16384};
    const int hs[] = {1, 2, 7, 131, 240, 480, 1080, 3000, 16384};
    const bloom_format_t fmts[] = {BLOOM_FMT_RGB565, BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGBQ16};
    int ok = 1, n = 0;
    double worst = 0;
    for (size_t wi = 0; wi < sizeof ws / sizeof ws[0]; wi++)
        for (size_t hi = 0; hi < sizeof hs / sizeof hs[0]; hi++)
            for (int lv = 1; lv <= 16; lv++)
                for (int copy = 0; copy <= 1; copy++) {
                    bloom_config_t c;
                    bloom_config_default(&c, ws[wi], hs[hi]);
                    c.levels = lv;
                    c.in_fmt = fmts[(wi + hi + (size_t)lv) % 4];
                    c.flags = copy ? BLOOM_FLAG_COPY_SOURCE : 0;
                    const size_t exact = bloom_workspace_size(&c);
                    if (exact == 0) { /* too big for this address space: refused */
                        bloom_info_t too;
                        CHECK(sizeof(size_t) < 8 && bloom_query(&c, &too) == BLOOM_E_TOO_BIG);
                        continue;
                    }
                    const unsigned long long bound =
                        BLOOM_WORKSPACE_MAX(c.width, c.height, lv, bloom_format_bpp(c.in_fmt), copy);
                    n++;
                    if (bound < exact) {
                        ok = 0;
                        fprintf(stderr, "%dx%d L%d copy%d: bound %llu < exact %zu\n", c.width, c.height, lv,
                                copy, bound, exact);
                    }
                    bloom_info_t info;
                    bloom_query(&c, &info);
                    if (info.levels == lv && lv == 5 && !copy && c.width >= 320 &&
                        (double)bound / exact > worst)
                        worst = (double)bound / exact;
                }
    CHECK(ok);
    printf("BLOOM_WORKSPACE_MAX: %d configurations, none below the exact size; at 5 levels "
           "built (width >= 320) at most %.2fx the exact size\n",
           n, worst);
    CHECK(worst < 1.5);

    /* A static workspace sized by the macro, as firmware declares it. */
    BLOOM_WORKSPACE_DEFINE(static_ws, BLOOM_WORKSPACE_MAX(320, 240, 5, 2, 0));
    bloom_config_t c;
    bloom_config_default(&c, 320, 240);
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGB565;
    bloom_t *b = NULL;
    CHECK(bloom_init(&b, static_ws, sizeof static_ws, &c) == BLOOM_OK);
    CHECK(sizeof static_ws >= bloom_workspace_size(&c));
    CHECK(sizeof static_ws <= bloom_workspace_size(&c) * 6u / 5u);
}

/* The same frame fed one row at a time, in bands of every height, whole,
 * with copied source rows, and in place: identical output. */
static void test_streaming(void)
{
    const int sizes[][2] = {{257, 131}, {33, 70}, {5, 200}, {1, 9}, {64, 1}};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        for (int lv = 1; lv <= 8; lv++) {
            bloom_config_t c;
            bloom_config_default(&c, sizes[si][0], sizes[si][1]);
            c.levels = lv;
            c.threshold = BLOOM_Q16(0.4);
            frame_t src = frame_random(&c, c.in_fmt, 99u + (unsigned)lv);
            frame_t ref = frame_alloc(c.width, c.height, c.out_fmt, 0);
            frame_t out = frame_alloc(c.width, c.height, c.out_fmt, 0);
            engine_t e = engine_new(&c);
            CHECK(bloom_process(e.b, src.p, src.stride, ref.p, ref.stride) == BLOOM_OK);

            /* row by row with the push/pull calls */
            bloom_begin(e.b);
            memset(out.p, 0, out.bytes);
            int ok = 1;
            for (int y = 0; y < c.height; y++) {
                ok &= bloom_push_row(e.b, src.p + (size_t)y * src.stride) == BLOOM_OK;
                while (bloom_pull_row(e.b, out.p + (size_t)bloom_rows_out(e.b) * out.stride) == BLOOM_OK)
                    ;
            }
            ok &= bloom_pull_row(e.b, out.p) == BLOOM_DONE;
            CHECK(ok);
            CHECK(frame_equal(&ref, &out));
            CHECK(bloom_push_row(e.b, src.p) == BLOOM_E_STATE);

            /* bands of 1, 2, 3, 7 and 64 rows */
            const int bands[] = {1, 2, 3, 7, 64};
            for (size_t bi = 0; bi < sizeof bands / sizeof bands[0]; bi++) {
                memset(out.p, 0, out.bytes);
                bloom_begin(e.b);
                bloom_status_t st = BLOOM_OK;
                for (int y = 0; y < c.height && st == BLOOM_OK; y += bands[bi]) {
                    int n = c.height - y < bands[bi] ? c.height - y : bands[bi];
                    st = bloom_run_rows(e.b, src.p, src.stride, n, out.p, out.stride);
                }
                CHECK(st == BLOOM_OK && bloom_rows_out(e.b) == c.height);
                CHECK(frame_equal(&ref, &out));
            }
            engine_free(&e);

            /* the engine keeps its own copies of the source rows */
            c.flags = BLOOM_FLAG_COPY_SOURCE;
            e = engine_new(&c);
            memset(out.p, 0, out.bytes);
            bloom_begin(e.b);
            frame_t row = frame_alloc(c.width, 1, c.in_fmt, 0);
            for (int y = 0; y < c.height; y++) {
                memcpy(row.p, src.p + (size_t)y * src.stride, row.bytes);
                CHECK(bloom_push_row(e.b, row.p) == BLOOM_OK);
                memset(row.p, 0xA5, row.bytes); /* the caller reuses its line buffer */
                while (bloom_pull_row(e.b, out.p + (size_t)bloom_rows_out(e.b) * out.stride) == BLOOM_OK)
                    ;
            }
            CHECK(bloom_rows_out(e.b) == c.height);
            CHECK(frame_equal(&ref, &out));
            frame_free(&row);
            engine_free(&e);

            /* in place */
            c.flags = 0;
            e = engine_new(&c);
            memcpy(out.p, src.p, src.bytes);
            CHECK(bloom_process(e.b, out.p, out.stride, out.p, out.stride) == BLOOM_OK);
            CHECK(frame_equal(&ref, &out));
            engine_free(&e);
            frame_free(&src);
            frame_free(&ref);
            frame_free(&out);
        }
    }
}

/* A push beyond what the source ring holds is refused, not lost. */
static void test_busy(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 40, 300);
    c.flags = BLOOM_FLAG_COPY_SOURCE;
    bloom_info_t info;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    engine_t e = engine_new(&c);
    frame_t src = frame_random(&c, c.in_fmt, 5);
    int y = 0;
    while (y < c.height && bloom_push_row(e.b, src.p + (size_t)y * src.stride) == BLOOM_OK)
        y++;
    CHECKF(y == info.source_rows, "accepted %d rows, source_rows %d", y, info.source_rows);
    CHECK(bloom_push_row(e.b, src.p + (size_t)y * src.stride) == BLOOM_E_BUSY);
    CHECK(bloom_rows_in(e.b) == y);
    frame_free(&src);
    engine_free(&e);
}

/* The zero-row shortcuts (dark source rows, zero levels, B = 0 output rows)
 * change no output bit: every scene, format and view against NO_SKIP. */
static void test_skip_identical(void)
{
    const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565, BLOOM_FMT_RGBQ16};
    int same = 1, runs = 0;
    for (int scene = 0; scene < 4; scene++) /* dark, one light, many, random */
        for (size_t fi = 0; fi < 4; fi++)
            for (int view = 0; view < 3; view++) { /* apply, bloom-only, linear */
                bloom_config_t c;
                bloom_config_default(&c, 203, 157);
                c.in_fmt = fmts[fi];
                c.out_fmt = fmts[(fi + (size_t)scene) % 4];
                c.threshold = BLOOM_Q16(0.7);
                c.flags = view == 1 ? BLOOM_FLAG_DEBUG_VIEW : view == 2 ? BLOOM_FLAG_LINEAR : 0;
                frame_t src = frame_random(&c, c.in_fmt, 11u + (unsigned)scene);
                if (scene < 3) { /* dark background, then lights */
                    frame_t dark = frame_alloc(c.width, c.height, c.in_fmt, 40);
                    frame_free(&src);
                    src = dark;
                    frame_t lit = frame_random(&c, c.in_fmt, 3);
                    const int lights = scene == 0 ? 0 : scene == 1 ? 1 : 40;
                    for (int k = 0; k < lights; k++) {
                        const int x = (k * 71 + 50) % c.width, y = (k * 37 + 20) % c.height;
                        memset(src.p + (size_t)y * src.stride + (size_t)x * (size_t)src.bpp, 0xFF,
                               (size_t)src.bpp);
                    }
                    frame_free(&lit);
                }
                frame_t fast = run_engine(&c, &src);
                c.flags |= BLOOM_FLAG_NO_SKIP;
                frame_t full = run_engine(&c, &src);
                same &= frame_equal(&fast, &full);
                runs++;
                frame_free(&fast);
                frame_free(&full);
                /* in place, same format */
                c.out_fmt = c.in_fmt;
                full = run_engine(&c, &src);
                c.flags &= ~(uint32_t)BLOOM_FLAG_NO_SKIP;
                engine_t e = engine_new(&c);
                CHECK(bloom_process(e.b, src.p, (ptrdiff_t)src.stride, src.p, (ptrdiff_t)src.stride) ==
                      BLOOM_OK);
                same &= frame_equal(&src, &full);
                engine_free(&e);
                frame_free(&full);
                frame_free(&src);
            }
    CHECKF(same, "skip paths differ from the full path");
    printf("zero-row shortcuts: %d scene/format/view runs identical to BLOOM_FLAG_NO_SKIP\n", runs);
}

/* Hand-worked answers. */
static void test_known(void)
{
    /* A constant frame stays constant. Linear, threshold 0: D_k = S on every
     * level, B = L*S, out = S*(1 + L*I) with I = 1 and L = 4: code 10 -> 50. */
    bloom_config_t c;
    bloom_config_default(&c, 37, 23);
    c.flags = BLOOM_FLAG_LINEAR;
    c.threshold = 0;
    c.soft_knee = 0;
    bloom_info_t info;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    CHECK(info.levels == 4); /* 37x23 -> 19x12, 10x6, 5x3, 3x2, (2x1 stops) */
    CHECK(info.intensity_q == 65536);
    frame_t src = frame_alloc(c.width, c.height, c.in_fmt, 10);
    frame_t dst = run_engine(&c, &src);
    int allsame = 1;
    for (size_t i = 0; i < (size_t)c.width * c.height * 3; i++)
        allsame &= frame_byte(&dst, i) == 50; /* S = 2570 (10/255), 5*S encodes to 50 */
    CHECK(allsame);
    frame_free(&src);
    frame_free(&dst);

    /* One bright pixel, one level, Q16 in and out, bloom-only view: B is
     * the tent of the box. V = 16.0 at (x0, y0) = (10, 6) of a 24x16 frame:
     * D1 = 1.0 at x in {4, 5}, y in {2, 3} (4x4 box weights 1/16), and
     * B(X, Y) = sum over those cells of tent weights wx * wy / 64. */
    bloom_config_default(&c, 24, 16);
    c.levels = 1;
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
    c.threshold = 0;
    c.soft_knee = 0;
    c.flags = BLOOM_FLAG_DEBUG_VIEW;
    src = frame_alloc(c.width, c.height, c.in_fmt, 0);
    frame_set_q16(&src, 10, 6, 16u << 16);
    dst = run_engine(&c, &src);
    int exact = 1;
    for (int y = 0; y < c.height; y++)
        for (int x = 0; x < c.width; x++) {
            uint32_t want = 1024u * tent_weight_sum(x, 4, 5) * tent_weight_sum(y, 2, 3);
            exact &= frame_get_q16(&dst, x, y) == want;
        }
    CHECK(exact);
    CHECK(frame_get_q16(&dst, 10, 6) == 1024u * 7u * 7u); /* peak: 4 + 3 eighths per axis */
    frame_free(&src);
    frame_free(&dst);

    /* 1x1, 1xN and Nx1 frames keep one level and a constant result. */
    const int tiny[][2] = {{1, 1}, {1, 17}, {17, 1}, {2, 1}, {1, 2}};
    for (size_t i = 0; i < sizeof tiny / sizeof tiny[0]; i++) {
        bloom_config_default(&c, tiny[i][0], tiny[i][1]);
        c.levels = 16;
        c.flags = BLOOM_FLAG_LINEAR;
        c.threshold = 0;
        c.soft_knee = 0;
        CHECK(bloom_query(&c, &info) == BLOOM_OK && info.levels == 1);
        src = frame_alloc(c.width, c.height, c.in_fmt, 20);
        dst = run_engine(&c, &src);
        int same = 1;
        for (size_t k = 0; k < (size_t)c.width * c.height * 3; k++)
            same &= frame_byte(&dst, k) == 40; /* S + 1*S */
        CHECK(same);
        frame_free(&src);
        frame_free(&dst);
    }
}

/* The folded static schedule (a period walked again and again, with or
 * without an end part after it: the period can end the table) makes every
 * row, twice in a row, whatever the height: every height 1 .. 70 at 1 .. 6
 * levels, the default and arm's baked map (no pyramid, one source row
 * held), each frame processed twice by one engine. */
static void test_folded_schedule(void)
{
    int runs = 0, bad = 0;
    uint8_t aux[12 * 70];
    for (int i = 0; i < (int)sizeof aux; i++)
        aux[i] = (uint8_t)(i * 37);
    for (int baked = 0; baked <= 1; baked++)
        for (int lv = 1; lv <= 6; lv++)
            for (int h = 1; h <= 70; h++) {
                bloom_config_t c;
                bloom_config_default(&c, 12, h);
                if (baked && (bloom_config_preset(&c, BLOOM_PRESET_ARM) != BLOOM_OK))
                    continue;
                c.levels = lv;
                if (baked) {
                    c.flags |= BLOOM_FLAG_BAKED;
                    c.aux_fmt = BLOOM_AUX_U8;
                }
                if (bloom_workspace_size(&c) == 0)
                    continue;
                engine_t e = engine_new(&c);
                frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(h * 7 + lv)),
                        d1 = frame_alloc(12, h, c.out_fmt, 0), d2 = frame_alloc(12, h, c.out_fmt, 0);
                bloom_status_t st = baked ? bloom_set_aux(e.b, aux, 12) : BLOOM_OK;
                if (st == BLOOM_OK)
                    st = bloom_process(e.b, src.p, (ptrdiff_t)src.stride, d1.p, (ptrdiff_t)d1.stride);
                if (st == BLOOM_OK)
                    st = bloom_process(e.b, src.p, (ptrdiff_t)src.stride, d2.p, (ptrdiff_t)d2.stride);
                runs++;
                if (st != BLOOM_OK || !frame_equal(&d1, &d2)) {
                    if (bad++ < 5)
                        fprintf(stderr, "%s 12x%d L%d: %s\n", baked ? "arm baked" : "default", h, lv,
                                st != BLOOM_OK ? bloom_status_str(st) : "second frame differs");
                }
                frame_free(&src);
                frame_free(&d1);
                frame_free(&d2);
                engine_free(&e);
            }
    printf("folded schedule: %d engines, every frame made twice\n", runs);
    CHECKF(bad == 0, "%d of %d engines failed a frame", bad, runs);
}

int main(void)
{
    test_validation();
    test_workspace();
    test_workspace_macro();
    test_streaming();
    test_busy();
    test_folded_schedule();
    test_skip_identical();
    test_known();
    return harness_finish();
}
