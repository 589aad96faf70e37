/* The preset machinery: names, configuration checks, the row-graph engine
 * (sizing, row and frame interfaces, aux plane), and the graph running the
 * default pipeline's stages bit for bit like the default engine. Each
 * preset's own maths is checked against its model in test_preset_<name>.c. */
#include <stdlib.h>

#include "harness.h"
#include "testutil.h"

static void test_names(void)
{
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        const char *n = bloom_preset_name((bloom_preset_t)p);
        CHECK(n != NULL);
        CHECK(bloom_preset_from_name(n) == p);
    }
    CHECK(bloom_preset_name(BLOOM_PRESET_COUNT) == NULL);
    CHECK(bloom_preset_from_name("bogus") == -1);
    CHECK(bloom_preset_from_name(NULL) == -1);
    CHECK(bloom_preset_available(BLOOM_PRESET_UNITY));
}

static void test_config_checks(void)
{
    bloom_config_t c;
    bloom_info_t info;
    bloom_config_default(&c, 64, 48);
    /* the default preset refuses preset-only flags and an aux plane */
    c.flags = BLOOM_FLAG_SATURATE;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FLAGS);
    c.flags = 0;
    c.aux_fmt = BLOOM_AUX_U8;
    CHECK(bloom_query(&c, &info) == BLOOM_E_AUX);
    c.aux_fmt = BLOOM_AUX_NONE;
    c.preset = (bloom_preset_t)99;
    CHECK(bloom_query(&c, &info) == BLOOM_E_PRESET);
    CHECK(bloom_config_preset(&c, (bloom_preset_t)99) == BLOOM_E_PRESET);
    for (int p = 1; p < BLOOM_PRESET_COUNT; p++) {
        bloom_config_default(&c, 64, 48);
        const bloom_status_t st = bloom_config_preset(&c, (bloom_preset_t)p);
        if (!bloom_preset_available((bloom_preset_t)p)) {
            CHECK(st == BLOOM_E_PRESET);
            c.preset = (bloom_preset_t)p;
            CHECK(bloom_query(&c, &info) == BLOOM_E_PRESET);
            continue;
        }
        CHECK(st == BLOOM_OK && c.preset == (bloom_preset_t)p);
        CHECKF(bloom_query(&c, &info) == BLOOM_OK, "preset %s defaults valid", bloom_preset_name((bloom_preset_t)p));
        CHECK(info.workspace_bytes == bloom_workspace_size(&c) && info.workspace_bytes > 0);
        /* every status has a message */
        CHECK(bloom_status_str((bloom_status_t)-21)[0] != 'u');
    }
#if BLOOM_USE_ATTENUATION
    bloom_config_default(&c, 64, 48);
    bloom_config_preset(&c, BLOOM_PRESET_ATTENUATION);
    c.p.attenuation = BLOOM_ONE + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_ATTENUATION);
    c.p.attenuation = BLOOM_ONE;
    c.p.max_reduction = BLOOM_ONE + 1u;
    CHECK(bloom_query(&c, &info) == BLOOM_E_ATTENUATION);
    c.p.max_reduction = 0;
    c.aux_fmt = BLOOM_AUX_NONE;
    CHECK(bloom_query(&c, &info) == BLOOM_E_AUX);
    c.aux_fmt = (bloom_aux_format_t)7;
    CHECK(bloom_query(&c, &info) == BLOOM_E_AUX);
    c.aux_fmt = BLOOM_AUX_U16;
    c.flags = BLOOM_FLAG_BAKED;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FLAGS);
#endif
}

#if BLOOM_USE_ATTENUATION
/* The attenuation preset with a = 0 multiplies by exactly 1: the graph
 * engine must then give the default engine's bytes, at every size, depth,
 * format pair and interface. */
static void test_graph_equals_default(void)
{
    static const int sizes[][2] = {{1, 1}, {2, 3}, {5, 4}, {17, 9}, {33, 31}, {64, 48}, {101, 67}, {160, 7}};
    static const bloom_format_t fmts[][2] = {{BLOOM_FMT_RGB888, BLOOM_FMT_RGB888},
                                             {BLOOM_FMT_RGB565, BLOOM_FMT_XRGB8888},
                                             {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16}};
    int mismatches = 0, runs = 0;
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (int levels = 1; levels <= 8; levels++)
            for (size_t f = 0; f < sizeof fmts / sizeof fmts[0]; f++) {
                bloom_config_t u, a;
                bloom_config_default(&u, sizes[s][0], sizes[s][1]);
                u.levels = levels;
                u.in_fmt = fmts[f][0];
                u.out_fmt = fmts[f][1];
                u.threshold = BLOOM_Q16(0.4);
                u.flags = (s & 1) ? BLOOM_FLAG_COPY_SOURCE : 0;
                a = u;
                bloom_config_preset(&a, BLOOM_PRESET_ATTENUATION);
                a.threshold = u.threshold;
                a.levels = levels;
                a.p.attenuation = 0;
                frame_t src = frame_random(&u, u.in_fmt, (uint32_t)(s * 131 + (size_t)levels * 7 + f));
                uint8_t *depth = (uint8_t *)xmalloc((size_t)u.width * (size_t)u.height);
                for (size_t i = 0; i < (size_t)u.width * (size_t)u.height; i++)
                    depth[i] = (uint8_t)(i * 37u);
                frame_t o1 = run_engine(&u, &src);
                frame_t o2 = run_engine_aux(&a, &src, depth, u.width);
                mismatches += !frame_equal(&o1, &o2);
                runs++;
                bloom_info_t iu, ia;
                bloom_query(&u, &iu);
                bloom_query(&a, &ia);
                if (iu.levels != ia.levels)
                    mismatches++;
                frame_free(&o1);
                frame_free(&o2);
                frame_free(&src);
                free(depth);
            }
    CHECKF(mismatches == 0, "graph engine (attenuation a=0) = default engine: %d of %d runs differ", mismatches,
           runs);
}

/* Row interface: push several rows before pulling, BUSY when the ring is
 * full, aux required, workspace one byte short refused, in-place output. */
static void test_graph_rows(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 40, 30);
    bloom_config_preset(&c, BLOOM_PRESET_ATTENUATION);
    c.threshold = BLOOM_Q16(0.3);
    frame_t src = frame_random(&c, c.in_fmt, 5);
    uint8_t *depth = (uint8_t *)xmalloc(40 * 30);
    for (int i = 0; i < 40 * 30; i++)
        depth[i] = (uint8_t)(i % 251);
    frame_t ref = run_engine_aux(&c, &src, depth, 40);

    bloom_info_t info;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    guarded_t ws = guarded_alloc(info.workspace_bytes);
    bloom_t *b = NULL;
    CHECK(bloom_init(&b, ws.p, info.workspace_bytes - 1, &c) == BLOOM_E_WORKSPACE);
    CHECK(bloom_init(&b, ws.p, info.workspace_bytes, &c) == BLOOM_OK);
    CHECK(bloom_push_row(b, src.p) == BLOOM_E_AUX); /* the preset needs its depth row */
    CHECK(bloom_rows_in(b) == 0);
    frame_t out = frame_alloc(40, 30, c.out_fmt, 0);
    int busy = 0;
    bloom_status_t st = BLOOM_OK;
    while (bloom_rows_in(b) < 30) {
        const int r = bloom_rows_in(b);
        st = bloom_push_row_aux(b, src.p + (size_t)r * src.stride, depth + 40 * r);
        if (st == BLOOM_E_BUSY) { /* drain and retry */
            busy++;
            while ((st = bloom_pull_row(b, out.p + (size_t)bloom_rows_out(b) * out.stride)) == BLOOM_OK)
                ;
            CHECK(st == BLOOM_AGAIN);
        } else if (st != BLOOM_OK) {
            break;
        }
    }
    CHECK(st != BLOOM_E_INTERNAL);
    while ((st = bloom_pull_row(b, out.p + (size_t)bloom_rows_out(b) * out.stride)) == BLOOM_OK)
        ;
    CHECK(st == BLOOM_DONE);
    CHECK(frame_equal(&out, &ref));
    CHECKF(busy > 0 || info.source_rows >= 30, "ring fills when pushing without pulling (%d)", busy);
    /* in place: dst aliases src */
    frame_t inpl = frame_alloc(40, 30, c.in_fmt, 0);
    memcpy(inpl.p, src.p, src.bytes);
    CHECK(bloom_set_aux(b, depth, 40) == BLOOM_OK);
    CHECK(bloom_process(b, inpl.p, (ptrdiff_t)inpl.stride, inpl.p, (ptrdiff_t)inpl.stride) == BLOOM_OK);
    CHECK(frame_equal(&inpl, &ref));
    CHECK(guarded_intact(&ws));
    guarded_free(&ws);
    frame_free(&inpl);
    frame_free(&out);
    frame_free(&ref);
    frame_free(&src);
    free(depth);
}
#endif

int main(void)
{
    test_names();
    test_config_checks();
#if BLOOM_USE_ATTENUATION
    test_graph_equals_default();
    test_graph_rows();
#endif
    return harness_finish();
}
