/* The static schedule from inside (white box: the engine's own struct,
 * src/engine/bloom_engine.h): a table spoiled after bloom_init ends the
 * frame call with BLOOM_E_INTERNAL at the push that would overwrite a
 * source row still to be read, and pushes nothing after it. bloom_init
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

/* For each level count: the first push in the walk with one free row to
 * spare, the last free before it moved to just after it (the bytes
 * between move up one); the frame call must fail at that push, with the
 * pushes before it done. */
static void test_spoiled_table(void)
{
    int tried = 0;
    for (int lv = 1; lv <= 5; lv++) {
        bloom_config_t c;
        bloom_config_default(&c, 48, 96);
        c.levels = lv;
        engine_t e = engine_new(&c);
        bloom_t *g = e.b;
        static int idx[1 << 16];
        const int n = walk_order(g, idx, (int)(sizeof idx / sizeof idx[0]));
        int pushes = 0, frees = 0, last_free = -1, at = -1, from = -1, pushed = 0;
        for (int k = 0; k < n && at < 0; k++) {
            const uint8_t byte = g->sched[idx[k]];
            if (byte == BG_S_FREE)
                frees++, last_free = k;
            if (byte != BG_S_PUSH)
                continue;
            /* push number `pushes` needs pushes - src_cap < frees */
            if (pushes - g->src_cap == frees - 1 && last_free >= 0 &&
                idx[k] - idx[last_free] == k - last_free) /* (one stretch of the table) */
                at = idx[k], from = idx[last_free], pushed = pushes;
            pushes++;
        }
        if (at < 0) { /* (no push waits on a free at this size: nothing to spoil) */
            engine_free(&e);
            continue;
        }
        tried++;
        memmove(g->sched + from, g->sched + from + 1, (size_t)(at - from));
        g->sched[at] = BG_S_FREE;
        frame_t src = frame_random(&c, c.in_fmt, (uint32_t)lv), dst = frame_alloc(48, 96, c.out_fmt, 0);
        const bloom_status_t st =
            bloom_process(g, src.p, (ptrdiff_t)src.stride, dst.p, (ptrdiff_t)dst.stride);
        CHECKF(st == BLOOM_E_INTERNAL, "L%d: a spoiled table gave %s", lv, bloom_status_str(st));
        CHECKF(g->src_n == pushed, "L%d: %d rows pushed, the table's push %d should have failed", lv,
               g->src_n, pushed);
        frame_free(&src);
        frame_free(&dst);
        engine_free(&e);
    }
    printf("spoiled table: %d engines failed at the push\n", tried);
    CHECKF(tried >= 3, "only %d level counts had a push to spoil", tried);
}

int main(void)
{
    test_spoiled_table();
    return harness_finish();
}
