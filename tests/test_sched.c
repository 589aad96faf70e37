/* The static schedule from inside (white box: the engine's own struct,
 * src/engine/bloom_engine.h): a walk whose count of freed source rows
 * falls short (a table spoiled after bloom_init, or built wrong) ends the
 * call with BLOOM_E_INTERNAL at the push that would overwrite a source row
 * still to be read, and pushes nothing after it. bloom_init
 * checks the table byte for byte against the dry run; the push's own
 * check is what is left once the table is in the caller's memory, and
 * the only one without the rings' checks (BLOOM_CHECK_RINGS 0). */
#include <stdlib.h>
#include <string.h>

#include "bloom.h"
#include "bloom_engine.h"
#include "harness.h"
#include "testutil.h"

/* The walk's order of table bytes: the start-up and the period up to
 * fold_e, the period fold_m - 1 more times, then the end. */
static int walk_order(const bloom_t *g, int *idx, int cap)
{
    int n = 0;
    for (int i = 0; i < g->fold_e && n < cap; i++)
        idx[n++] = i;
    for (int rep = 1; rep < g->fold_m; rep++)
        for (int i = g->fold_b; i < g->fold_e && n < cap; i++)
            idx[n++] = i;
    for (int i = g->fold_e; i < g->sched_len && n < cap; i++)
        idx[n++] = i;
    return n;
}

/* For each level count and three heights: the frame's rows through a band
 * call (bloom_run_rows) with the count of freed source rows one short, as
 * if the table had lost a free. The first push in the walk with exactly one
 * free row to spare must then fail, with the pushes before it done. */
static void test_spoiled_count(void)
{
    int tried = 0, sizes = 0;
    for (int e = 0; e < 15; e++) {
        const int lv = 1 + e % 5, hh = 96 + 37 * (e / 5); /* heights 96, 133, 170 */
        sizes++;
        bloom_config_t c;
        bloom_config_default(&c, 48, hh);
        c.levels = lv;
        engine_t en = engine_new(&c);
        bloom_t *g = en.b;
        static int idx[1 << 16];
        const int n = walk_order(g, idx, (int)(sizeof idx / sizeof idx[0]));
        int pushes = 0, frees = 0, pushed = -1;
        for (int k = 0; k < n && pushed < 0; k++) {
            const uint8_t byte = g->sched[idx[k]];
            frees += byte == BG_S_FREE;
            if (byte != BG_S_PUSH)
                continue;
            if (pushes - g->src_cap == frees - 1) /* push `pushes` needs pushes - src_cap < frees */
                pushed = pushes;
            pushes++;
        }
        if (pushed < 0) { /* (no push waits on a free at this size) */
            engine_free(&en);
            continue;
        }
        tried++;
        frame_t src = frame_random(&c, c.in_fmt, (uint32_t)e), dst = frame_alloc(48, hh, c.out_fmt, 0);
        bloom_status_t st = bloom_begin(g);
        g->src_free = -1;
        if (st == BLOOM_OK)
            st = bloom_run_rows(g, src.p, (ptrdiff_t)src.stride, hh, dst.p, (ptrdiff_t)dst.stride);
        CHECKF(st == BLOOM_E_INTERNAL, "L%d h %d: a free short gave %s", lv, hh, bloom_status_str(st));
        CHECKF(g->src_n == pushed, "L%d h %d: %d rows pushed, the table's push %d should have failed", lv, hh,
               g->src_n, pushed);
        frame_free(&src);
        frame_free(&dst);
        engine_free(&en);
    }
    printf("a free short: %d of %d engines had a push to fail, and failed there\n", tried, sizes);
    CHECKF(tried >= sizes / 2, "only %d of %d engines had a push to fail", tried, sizes);
}

int main(void)
{
    test_spoiled_count();
    return harness_finish();
}
