/* The preset machinery: names, configuration checks, the row-graph engine
 * (sizing, row and frame interfaces, aux plane), and the graph running the
 * default pipeline's stages bit for bit like the default engine. Each
 * preset's own maths is checked against its model in test_preset_<name>.c. */
#include <stdlib.h>

#include "harness.h"
#include "preset_conform.h"

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
        CHECKF(bloom_query(&c, &info) == BLOOM_OK, "preset %s defaults valid",
               bloom_preset_name((bloom_preset_t)p));
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

/* bloom_query's status for preset p at its defaults with parameter bit
 * (BLOOM_PARAM_*) out of range, or with the preset flag or an aux plane
 * bit stands for; if_read, if_not: the status a preset that reads it,
 * and one that does not, gives. */
static bloom_status_t query_with(bloom_preset_t p, uint32_t bit, bloom_status_t *if_read,
                                 bloom_status_t *if_not)
{
    bloom_config_t c;
    bloom_info_t info;
    bloom_config_default(&c, 64, 48);
    bloom_config_preset(&c, p);
    *if_not = BLOOM_OK; /* a parameter the preset does not read is ignored */
    switch (bit) {
    case BLOOM_PARAM_STRENGTH:
        c.p.strength = UINT32_MAX;
        *if_read = BLOOM_E_STRENGTH;
        break;
    case BLOOM_PARAM_PASSES:
        c.p.passes = 0;
        *if_read = BLOOM_E_PASSES;
        break;
    case BLOOM_PARAM_ATTENUATION:
        c.p.attenuation = BLOOM_ONE + 1u;
        *if_read = BLOOM_E_ATTENUATION;
        break;
    case BLOOM_PARAM_MAX_REDUCTION:
        c.p.max_reduction = BLOOM_ONE + 1u;
        *if_read = BLOOM_E_ATTENUATION;
        break;
    case BLOOM_PARAM_TINT:
        c.p.tint[1] = BLOOM_ONE + 1u;
        *if_read = BLOOM_E_TINT;
        break;
    case BLOOM_PARAM_WEIGHTS:
        c.p.level_weight[2] = BLOOM_ONE + 1u;
        *if_read = BLOOM_E_WEIGHT;
        break;
    case BLOOM_PARAM_AUX: /* an aux plane: accepted or refused */
        c.aux_fmt = BLOOM_AUX_U8;
        *if_read = BLOOM_OK;
        *if_not = BLOOM_E_AUX;
        break;
    default: /* a preset flag: accepted (with an aux plane if the preset reads one) or refused */
        c.flags |= bit == BLOOM_PARAM_SATURATE      ? (uint32_t)BLOOM_FLAG_SATURATE
                   : bit == BLOOM_PARAM_ADDITIVE    ? (uint32_t)BLOOM_FLAG_ADDITIVE
                   : bit == BLOOM_PARAM_KEEP_LEVELS ? (uint32_t)BLOOM_FLAG_KEEP_LEVELS
                                                    : (uint32_t)BLOOM_FLAG_BAKED;
        if (bloom_preset_params(p) & BLOOM_PARAM_AUX)
            c.aux_fmt = BLOOM_AUX_U8;
        *if_read = BLOOM_OK;
        *if_not = BLOOM_E_FLAGS;
    }
    return bloom_query(&c, &info);
}

/* bloom_preset_params against what the presets accept and refuse: a value
 * out of range of a parameter a preset reads is refused, one it does not
 * read is ignored; a preset flag or an aux plane is accepted by the
 * presets that read it and refused by the others; RADIUS by the presets
 * whose defaults follow the level count. */
static void test_preset_params(void)
{
    static const uint32_t bits[] = {BLOOM_PARAM_STRENGTH,      BLOOM_PARAM_PASSES,   BLOOM_PARAM_ATTENUATION,
                                    BLOOM_PARAM_MAX_REDUCTION, BLOOM_PARAM_AUX,      BLOOM_PARAM_TINT,
                                    BLOOM_PARAM_WEIGHTS,       BLOOM_PARAM_SATURATE, BLOOM_PARAM_ADDITIVE,
                                    BLOOM_PARAM_BAKED,         BLOOM_PARAM_RADIUS,   BLOOM_PARAM_KEEP_LEVELS};
    const size_t nbits = sizeof bits / sizeof bits[0];
    uint32_t all = 0;
    for (size_t i = 0; i < nbits; i++) {
        CHECK((all & bits[i]) == 0);
        all |= bits[i];
    }
    CHECK(bloom_preset_params(BLOOM_PRESET_UNITY) == 0);
    CHECK(bloom_preset_params(BLOOM_PRESET_COUNT) == 0);
    CHECK(bloom_preset_params((bloom_preset_t)-1) == 0);
    uint32_t seen = 0;
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        const bloom_preset_t pr = (bloom_preset_t)p;
        const uint32_t reads = bloom_preset_params(pr);
        const char *pn = bloom_preset_name(pr);
        seen |= reads;
        CHECKF((reads & ~all) == 0, "%s: only known bits (%#x)", pn, (unsigned)reads);
        if (!bloom_preset_available(pr))
            continue;
        for (size_t i = 0; i < nbits; i++) {
            if (bits[i] == BLOOM_PARAM_RADIUS)
                continue;
            bloom_status_t if_read, if_not;
            const bloom_status_t st = query_with(pr, bits[i], &if_read, &if_not);
            const int r = (reads & bits[i]) != 0;
            CHECKF(st == (r ? if_read : if_not), "%s %s parameter %#x: status %d, expected %d", pn,
                   r ? "reads" : "does not read", (unsigned)bits[i], (int)st, (int)(r ? if_read : if_not));
        }
        bloom_config_t c3, c6;
        bloom_config_default(&c3, 64, 48);
        bloom_config_default(&c6, 64, 48);
        c3.levels = 3;
        c6.levels = 6;
        bloom_config_preset(&c3, pr);
        bloom_config_preset(&c6, pr);
        const int follows = memcmp(&c3.p, &c6.p, sizeof c3.p) != 0;
        CHECKF(follows == ((reads & BLOOM_PARAM_RADIUS) != 0),
               "%s: RADIUS %s, defaults follow the level count %d", pn,
               (reads & BLOOM_PARAM_RADIUS) ? "read" : "not read", follows);
    }
    CHECKF(seen == all, "every bit read by some preset (%#x of %#x)", (unsigned)seen, (unsigned)all);
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
    CHECKF(mismatches == 0, "graph engine (attenuation a=0) = default engine: %d of %d runs differ",
           mismatches, runs);
}

/* Row interface with the depth plane (preset_check_rows). */
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
    preset_check_rows(&c, &src, depth, 40);
    frame_free(&src);
    free(depth);
}
#endif

int main(void)
{
    test_names();
    test_config_checks();
    test_preset_params();
#if BLOOM_USE_ATTENUATION
    test_graph_equals_default();
    test_graph_rows();
#endif
    return harness_finish();
}
