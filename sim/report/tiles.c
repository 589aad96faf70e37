/* report_tiles: memory and run time against tile width (issue 14, item 4,
 * the report part; `make report`, section 4).
 *
 *   report_tiles --out DIR [--data DIR] [--runs N] [--ring-mb N] [--icount TSV]
 *   report_tiles --once LEVELS STRIP [--data DIR]
 *
 * 1920x1080 RGB888, the benchmark scene (report.h "scene"), default preset
 * at threshold 0.6, levels 3, 5, 7; vertical strips of the widths in
 * sim/bench/tile_strips.h. Per level: rounds of {untiled frame, every
 * tiling}, each a full frame on the next ring slot, medians, ratios to the
 * untiled frame of the same rounds. Every timed frame, untiled too, carves
 * its engines out of one workspace of the largest strip's size (bloom_init
 * per strip, then bloom_process): the memory a strip renderer needs, the
 * set-up included on both sides. Outputs compared byte for byte with the
 * untiled frame. --once: one tiling, nothing timed, for callgrind (run.sh;
 * TSV lines: levels, strip, instructions, checksum). Writes DIR/tiles.csv
 * and DIR/tiles.md; asserts nothing about time. */
#include <stdlib.h>
#include <string.h>

#include "report.h"
#include "tile_strips.h"

enum { W = 1920, H = 1080 };

typedef struct {
    bloom_config_t base;
    int sw;
    void *ws;
    size_t ws_bytes;
} tiling_t;

static void tiling_make(tiling_t *t, int levels, int sw)
{
    tile_plan_t p;
    bloom_config_default(&t->base, W, H);
    t->base.levels = levels;
    t->base.threshold = BLOOM_Q16(0.6);
    t->sw = sw;
    if (tile_plan(&t->base, sw, &p) != BLOOM_OK)
        rdie("tiles: strips of %d refused", sw);
    t->ws_bytes = p.ws_max;
    if (posix_memalign(&t->ws, BLOOM_WORKSPACE_ALIGN, t->ws_bytes))
        rdie("out of memory");
}

static int run_tiling(void *ctx, const uint8_t *src, uint8_t *dst)
{
    const tiling_t *t = ctx;
    const int n = tile_strip_count(W, t->sw);
    for (int s = 0; s < n; s++) {
        bloom_config_t c = t->base;
        bloom_t *b;
        tile_strip_config(&c, t->sw, s);
        bloom_status_t st = bloom_init(&b, t->ws, t->ws_bytes, &c);
        if (st == BLOOM_OK) /* never in place: a strip's halo reads its neighbours' source */
            st = bloom_process(b, src, W * 3, dst, W * 3);
        if (st != BLOOM_OK) {
            fprintf(stderr, "report_tiles: strip %d of %d: %s\n", s, t->sw, bloom_status_str(st));
            return 1;
        }
    }
    return 0;
}

static uint32_t fnv1a(const uint8_t *p, size_t n)
{
    uint32_t h = 2166136261u;
    for (size_t i = 0; i < n; i++)
        h = (h ^ p[i]) * 16777619u;
    return h;
}

/* callgrind count of (levels, strip) from the TSV, or -1. */
static long long icount(const char *tsv, int levels, int sw)
{
    FILE *f = tsv ? fopen(tsv, "r") : NULL;
    char line[512];
    int l, s;
    long long n, found = -1;
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "%d %d %lld", &l, &s, &n) == 3 && l == levels && s == sw)
            found = n;
    if (f)
        fclose(f);
    return found;
}

int main(int argc, char **argv)
{
    const char *out = NULL, *data = "tests/data", *tsv = NULL;
    int runs = 5, once_l = 0, once_s = -1;
    size_t ring_bytes = (size_t)128 << 20;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!v)
            rdie("option %s needs a value", a);
        if (!strcmp(a, "--once") && i + 2 < argc) {
            once_l = atoi(v);
            once_s = atoi(argv[i + 2]);
            i += 2;
            continue;
        }
        if (!strcmp(a, "--out"))
            out = v;
        else if (!strcmp(a, "--data"))
            data = v;
        else if (!strcmp(a, "--icount"))
            tsv = v;
        else if (!strcmp(a, "--runs"))
            runs = atoi(v);
        else if (!strcmp(a, "--ring-mb"))
            ring_bytes = (size_t)atol(v) << 20;
        else
            rdie("unknown option %s", a);
        i++;
    }
    const size_t bytes = (size_t)W * H * 3u;
    char err[512];
    rin_t in;
    if ((!out && once_s < 0) || runs < 1)
        rdie("usage: report_tiles --out DIR [options] | --once LEVELS STRIP (see sim/report/tiles.c)");
    if (rin_make(&in, "scene", data, W, H, err, sizeof err))
        rdie("%s", err);
    uint8_t *ref = rxmalloc(bytes), *o = rxmalloc(bytes);
    if (once_s >= 0) {
        tiling_t t;
        tiling_make(&t, once_l, once_s);
        if (run_tiling(&t, in.p, o))
            return 1;
        printf("levels %d strip %d fnv1a %08x\n", once_l, once_s, (unsigned)fnv1a(o, bytes));
        return 0;
    }

    rring_t ring;
    if (rring_init(&ring, ring_bytes) || rring_fill(&ring, in.p, bytes, bytes))
        rdie("cannot allocate the rings");
    char cpath[1024], ctmp[1100], mpath[1024], mtmp[1100];
    snprintf(cpath, sizeof cpath, "%s/tiles.csv", out);
    snprintf(mpath, sizeof mpath, "%s/tiles.md", out);
    FILE *csv = ropen(cpath, ctmp, sizeof ctmp), *md = ropen(mpath, mtmp, sizeof mtmp);
    fprintf(csv, "levels,strip,strips,workspace,workspace_over_untiled,runs,ms,cpu_ms,over_untiled,"
                 "over_untiled_cpu,instructions,instructions_over_untiled,identical\n");
    fprintf(md,
            "| levels | strip (output columns) | strips | workspace of one strip engine | of the untiled | "
            "time over the untiled, CPU (wall) | instructions over the untiled | CPU ms per frame | "
            "output = untiled |\n|---|---|---:|---:|---:|---:|---:|---:|---|\n");
    int all_same = 1;
    for (int li = 0; li < TILE_NLEVELS; li++) {
        const int lv = tile_levels[li];
        tiling_t t[TILE_NWIDTHS + 1];
        rtimer_t tm[TILE_NWIDTHS + 1];
        /* timer 0 is the untiled frame, then the widths in table order */
        tiling_make(&t[0], lv, 0);
        for (int i = 0; i < TILE_NWIDTHS; i++)
            tiling_make(&t[i + 1], lv, tile_strip_widths[i]);
        for (int i = 0; i <= TILE_NWIDTHS; i++)
            tm[i] = (rtimer_t){run_tiling, &t[i], 0, 0, 0, NULL};
        if (rtime_rounds(&ring, tm, TILE_NWIDTHS + 1, 1, runs))
            rdie("timing failed at %d levels", lv);
        if (run_tiling(&t[0], in.p, ref))
            rdie("engine failed");
        const long long ic0 = icount(tsv, lv, 0);
        for (int i = 1; i <= TILE_NWIDTHS; i++) {
            const int sw = t[i].sw;
            if (!sw)
                continue; /* the untiled row is timer 0 */
            memset(o, 0, bytes);
            if (run_tiling(&t[i], in.p, o))
                rdie("engine failed");
            const int same = !memcmp(o, ref, bytes);
            all_same &= same;
            const long long ic = icount(tsv, lv, sw);
            const double wr = tm[i].wall_ms / tm[0].wall_ms, cr = tm[i].cpu_ms / tm[0].cpu_ms;
            const double ir = ic > 0 && ic0 > 0 ? (double)ic / (double)ic0 : 0.0;
            fprintf(csv, "%d,%d,%d,%zu,%.4f,%d,%.4f,%.4f,%.4f,%.4f,%lld,%.4f,%s\n", lv, sw,
                    tile_strip_count(W, sw), t[i].ws_bytes, (double)t[i].ws_bytes / (double)t[0].ws_bytes,
                    runs, tm[i].wall_ms, tm[i].cpu_ms, wr, cr, ic, ir, same ? "yes" : "NO");
            fprintf(md, "| %d | %d | %d | %zu | %.2f | %.2f (%.2f) | ", lv, sw, tile_strip_count(W, sw),
                    t[i].ws_bytes, (double)t[i].ws_bytes / (double)t[0].ws_bytes, cr, wr);
            if (ir > 0)
                fprintf(md, "%.3f | ", ir);
            else
                fprintf(md, "- | ");
            fprintf(md, "%.1f | %s |\n", tm[i].cpu_ms, same ? "identical" : "**DIFFERENT**");
            printf("tiles L%d strip %4d: workspace %zu, time x untiled %.2f (CPU %.2f), %s\n", lv, sw,
                   t[i].ws_bytes, wr, cr, same ? "identical" : "DIFFERENT");
        }
        fprintf(csv, "%d,0,1,%zu,1,%d,%.4f,%.4f,1,1,%lld,1,yes\n", lv, t[0].ws_bytes, runs, tm[0].wall_ms,
                tm[0].cpu_ms, ic0);
        fprintf(md, "| %d | untiled (1920) | 1 | %zu | 1.00 | 1.00 (1.00) | %s | %.1f | (the reference) |\n",
                lv, t[0].ws_bytes, ic0 > 0 ? "1.000" : "-", tm[0].cpu_ms);
        fflush(stdout);
        for (int i = 0; i <= TILE_NWIDTHS; i++)
            free(t[i].ws);
    }
    fprintf(md, "\nEvery tiling's output %s the untiled frame's, byte for byte.\n",
            all_same ? "is identical to" : "**differs from**");
    rclose(csv, ctmp, cpath);
    rclose(md, mtmp, mpath);
    rring_free(&ring);
    free(ref);
    free(o);
    rin_free(&in);
    if (!all_same)
        fprintf(stderr, "report_tiles: a tiling DIFFERS from the untiled frame\n");
    return 0;
}
