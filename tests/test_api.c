/* The API's edges: every public function given NULL where it expects a
 * handle or a pointer; in-place use with another format or stride refused
 * (BLOOM_E_ALIAS) and the real in-place case still allowed; the latency
 * that bloom_query reports, held against when rows really come out, for
 * every preset and level count: a row is never later than it says, and
 * some row is exactly that late. */
#include <stdlib.h>
#include <string.h>

#include "bloom.h"
#include "harness.h"
#include "testutil.h"

static uint64_t ws_buf[1 << 17]; /* 1 MB, enough for every case here */

static bloom_t *make(const bloom_config_t *c)
{
    bloom_t *b = NULL;
    bloom_status_t st = bloom_init(&b, ws_buf, sizeof ws_buf, c);
    CHECKF(st == BLOOM_OK, "bloom_init: %s", bloom_status_str(st));
    return st == BLOOM_OK ? b : NULL;
}

static void test_null(void)
{
    bloom_config_t c;
    bloom_info_t info;
    bloom_config_default(NULL, 8, 8); /* no crash, nothing to report */
    bloom_config_default(&c, 8, 8);
    uint8_t px[8 * 8 * 3] = {0}, out[8 * 8 * 3];
    CHECK(bloom_config_preset(NULL, BLOOM_PRESET_UNITY) == BLOOM_E_NULL);
    CHECK(bloom_preset_from_name(NULL) == -1);
    CHECK(bloom_query(NULL, &info) == BLOOM_E_NULL);
    CHECK(bloom_workspace_size(NULL) == 0);
    bloom_t *b = (bloom_t *)1;
    CHECK(bloom_init(NULL, ws_buf, sizeof ws_buf, &c) == BLOOM_E_NULL);
    CHECK(bloom_init(&b, NULL, sizeof ws_buf, &c) == BLOOM_E_NULL && b == (bloom_t *)1);
    CHECK(bloom_init(&b, ws_buf, sizeof ws_buf, NULL) == BLOOM_E_NULL);
    CHECK(bloom_begin(NULL) == BLOOM_E_NULL);
    CHECK(bloom_push_row(NULL, px) == BLOOM_E_NULL);
    CHECK(bloom_push_row_aux(NULL, px, px) == BLOOM_E_NULL);
    CHECK(bloom_set_aux(NULL, px, 8) == BLOOM_E_NULL);
    CHECK(bloom_pull_row(NULL, out) == BLOOM_E_NULL);
    CHECK(bloom_rows_in(NULL) == BLOOM_E_NULL);
    CHECK(bloom_rows_out(NULL) == BLOOM_E_NULL);
    CHECK(bloom_run_rows(NULL, px, 24, 1, out, 24) == BLOOM_E_NULL);
    CHECK(bloom_process(NULL, px, 24, out, 24) == BLOOM_E_NULL);
    CHECK(strcmp(bloom_status_str(BLOOM_E_NULL), "null pointer argument") == 0);
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p))
            continue;
        bloom_config_default(&c, 8, 8);
        CHECK(bloom_config_preset(&c, (bloom_preset_t)p) == BLOOM_OK);
        const int aux = (bloom_preset_params((bloom_preset_t)p) & BLOOM_PARAM_AUX) != 0;
        if (aux)
            c.aux_fmt = BLOOM_AUX_U8;
        b = make(&c);
        if (!b)
            continue;
        CHECK(bloom_push_row(b, NULL) == BLOOM_E_NULL);
        CHECK(bloom_push_row_aux(b, NULL, px) == BLOOM_E_NULL);
        CHECK(bloom_set_aux(b, NULL, 8) == BLOOM_E_NULL);
        CHECK(bloom_pull_row(b, NULL) == BLOOM_E_NULL);
        CHECK(bloom_run_rows(b, NULL, 24, 1, out, 24) == BLOOM_E_NULL);
        CHECK(bloom_run_rows(b, px, 24, 1, NULL, 24) == BLOOM_E_NULL);
        CHECK(bloom_process(b, NULL, 24, out, 24) == BLOOM_E_NULL);
        CHECK(bloom_process(b, px, 24, NULL, 24) == BLOOM_E_NULL);
        CHECK(bloom_rows_in(b) >= 0 && bloom_rows_out(b) >= 0);
    }
}

/* A frame whose pixels vary, so that a corrupted source row shows. */
static void fill(uint8_t *p, size_t n, unsigned seed)
{
    for (size_t i = 0; i < n; i++)
        p[i] = (uint8_t)((i * 37u + seed * 11u) ^ (i >> 5));
}

static void test_alias(void)
{
    enum { W = 40, H = 30 };
    static uint8_t buf[W * H * 4 * 2], ref[W * H * 4], src[W * H * 4];
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p) ||
            (bloom_preset_params((bloom_preset_t)p) & BLOOM_PARAM_AUX))
            continue; /* the aux presets take the same path; their plane is not the point */
        for (int copy = 0; copy < 2; copy++) {
            bloom_config_t c;
            bloom_config_default(&c, W, H);
            bloom_config_preset(&c, (bloom_preset_t)p);
            c.threshold = BLOOM_Q16(0.3);
            c.flags |= copy ? BLOOM_FLAG_COPY_SOURCE : 0;
            bloom_t *b = make(&c);
            if (!b)
                continue;
            /* in place, same format and stride: allowed, same bytes as out of place */
            fill(src, W * H * 3, (unsigned)p);
            CHECK(bloom_process(b, src, W * 3, ref, W * 3) == BLOOM_OK);
            memcpy(buf, src, W * H * 3);
            CHECK(bloom_process(b, buf, W * 3, buf, W * 3) == BLOOM_OK);
            CHECK(memcmp(buf, ref, W * H * 3) == 0);
            /* the same buffer with another stride, or shifted by a row: refused */
            memcpy(buf, src, W * H * 3);
            CHECK(bloom_process(b, buf, W * 3, buf, W * 3 + 3) == BLOOM_E_ALIAS);
            CHECK(bloom_process(b, buf + W * 3, W * 3, buf, W * 3) == BLOOM_E_ALIAS);
            CHECK(memcmp(buf, src, W * H * 3) == 0); /* refused before anything was written */
            /* band calls of one row each with the destination a row below the
             * source: the rows written trail the source rows (the latency) and
             * the ring holds earlier bands' rows: refused, not written wrong */
            if (!copy) {
                CHECK(bloom_begin(b) == BLOOM_OK);
                int st = BLOOM_OK;
                for (int y = 0; y < H && st == BLOOM_OK; y++)
                    st = bloom_run_rows(b, buf, W * 3, 1, buf + W * 3, W * 3);
                CHECK(st == BLOOM_E_ALIAS);
                CHECK(memcmp(buf, src, W * H * 3) == 0);
            }
            /* row mode: a destination over a source row still held */
            if (!copy) {
                CHECK(bloom_begin(b) == BLOOM_OK);
                int st = BLOOM_OK;
                for (int y = 0; y < H && st == BLOOM_OK; y++)
                    st = bloom_push_row(b, buf + y * W * 3);
                CHECK(bloom_pull_row(b, buf + 5 * W * 3) == BLOOM_E_ALIAS);
                CHECK(bloom_pull_row(b, buf + 2) == BLOOM_E_ALIAS);
                CHECK(bloom_pull_row(b, buf) == BLOOM_OK); /* row 0 over row 0: in place */
            }
            /* another format, same buffer: refused */
            c.out_fmt = BLOOM_FMT_XRGB8888;
            b = make(&c);
            if (!b)
                continue;
            memcpy(buf, src, W * H * 3);
            CHECK(bloom_process(b, buf, W * 3, buf, W * 3) == BLOOM_E_ALIAS);
            CHECK(bloom_process(b, buf, W * 3, buf, W * 4) == BLOOM_E_ALIAS);
            CHECK(memcmp(buf, src, W * H * 3) == 0);
            if (!copy) {
                CHECK(bloom_begin(b) == BLOOM_OK);
                CHECK(bloom_push_row(b, buf) == BLOOM_OK);
                int st = BLOOM_OK;
                for (int y = 1; y < H && st == BLOOM_OK; y++)
                    st = bloom_push_row(b, buf + y * W * 3);
                CHECK(bloom_pull_row(b, buf) == BLOOM_E_ALIAS); /* row 0 in another format */
            }
            /* disjoint buffers, any strides: fine */
            CHECK(bloom_process(b, src, W * 3, buf, W * 4) == BLOOM_OK);
            CHECK(bloom_process(b, src + (H - 1) * W * 3, -(ptrdiff_t)W * 3, buf, W * 4) == BLOOM_OK);
        }
    }
}

/* Output row y must be out once source row min(y + latency, h - 1) has been
 * pushed (pulled until AGAIN after every push), and the latency is the
 * least such number: some row waits exactly that long. */
static void test_latency(void)
{
    static uint8_t src[300 * 3 * 8], dst[300 * 3];
    const int hs[] = {1, 7, 40, 200, 300};
    int checked = 0, bad = 0, tight = 0;
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p) ||
            (bloom_preset_params((bloom_preset_t)p) & BLOOM_PARAM_AUX))
            continue;
        for (int L = 1; L <= 6; L++)
            for (size_t hi = 0; hi < sizeof hs / sizeof hs[0]; hi++) {
                bloom_config_t c;
                bloom_config_default(&c, 8, hs[hi]);
                c.levels = L;
                bloom_config_preset(&c, (bloom_preset_t)p);
                c.flags |= BLOOM_FLAG_COPY_SOURCE; /* rows from one small buffer */
                bloom_info_t info;
                if (bloom_query(&c, &info) != BLOOM_OK)
                    continue;
                bloom_t *b = make(&c);
                if (!b)
                    continue;
                /* the formula of README and sim/docs/streaming.md (default engine) */
                if (p == BLOOM_PRESET_UNITY && c.height > 4 * (1 << info.levels))
                    CHECKF(info.latency_rows == 4 * (1 << info.levels) - 4, "unity L=%d h=%d latency %d",
                           info.levels, c.height, info.latency_rows);
                int worst = 0;
                fill(src, sizeof src, (unsigned)L);
                for (int r = 0; r < c.height; r++) {
                    CHECK(bloom_push_row(b, src + (r % 8) * 24) == BLOOM_OK);
                    int st;
                    while ((st = bloom_pull_row(b, dst)) == BLOOM_OK) {
                        const int y = bloom_rows_out(b) - 1;
                        const int want =
                            y + info.latency_rows < c.height - 1 ? y + info.latency_rows : c.height - 1;
                        checked++;
                        worst = r - y > worst ? r - y : worst;
                        if (r > want) {
                            bad++;
                            if (bad < 5)
                                fprintf(stderr,
                                        "preset %d L=%d h=%d: row %d out after source row %d, "
                                        "latency %d says %d\n",
                                        p, L, c.height, y, r, info.latency_rows, want);
                        }
                    }
                    CHECK(st == BLOOM_AGAIN || (st == BLOOM_DONE && r == c.height - 1));
                }
                CHECK(bloom_rows_out(b) == c.height);
                /* and the bound is tight: some row waits that long */
                if (c.height > info.latency_rows + 1)
                    CHECKF(worst == info.latency_rows, "preset %d L=%d h=%d: latency %d, longest wait %d", p,
                           L, c.height, info.latency_rows, worst);
                tight += c.height > info.latency_rows + 1;
            }
    }
    CHECKF(bad == 0, "%d of %d output rows not at their stated latency", bad, checked);
    printf("latency: %d output rows, each out once source row min(y + latency, h - 1) was in; "
           "the bound met by some row in each of %d frames taller than it\n",
           checked, tight);
}

/* bloom_config_preset keeps the flags other than the preset's own (the
 * fuzzing found BLOOM_FLAG_NO_AVX2 dropped), and a preset that reads no
 * plane refuses an aux row, as the default pipeline does. */
static void test_preset_flags(void)
{
    const uint32_t keep = BLOOM_FLAG_NO_AVX2 | BLOOM_FLAG_NO_SIMD | BLOOM_FLAG_LINEAR | BLOOM_FLAG_NO_SKIP |
                          BLOOM_FLAG_COPY_SOURCE | BLOOM_FLAG_DEBUG_VIEW;
    uint8_t row[16 * 3] = {0};
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        bloom_config_t c;
        bloom_config_default(&c, 16, 8);
        c.flags = keep;
        if (bloom_config_preset(&c, (bloom_preset_t)p) != BLOOM_OK)
            continue;
        CHECKF((c.flags & keep) == keep, "%s: flags %#x", bloom_preset_name((bloom_preset_t)p),
               (unsigned)c.flags);
        if (bloom_preset_params((bloom_preset_t)p) & BLOOM_PARAM_AUX)
            continue;
        c.flags &= ~(uint32_t)BLOOM_FLAG_COPY_SOURCE;
        bloom_t *b = make(&c);
        if (b)
            CHECKF(bloom_push_row_aux(b, row, row) == BLOOM_E_AUX, "%s: aux row taken",
                   bloom_preset_name((bloom_preset_t)p));
    }
}

int main(void)
{
    test_null();
    test_preset_flags();
    test_alias();
    test_latency();
    return harness_finish();
}
