/* report_skip: what the skip paths save (issue 3, section 4, the report part).
 *
 *   report_skip --out DIR [--data DIR] [--sizes WxH,...] [--runs N]
 *               [--runs-big N] [--ring-mb N] [--icount TSV]
 *
 * Scenes (report.h): dark, sparse (one small light), dense (the benchmark
 * scene: floodlights and 24 lights), grid (a light in every 64x64 cell).
 * bloom_config_default: threshold 1.0, soft knee 0.5, 5 levels, RGB888.
 * Per size and scene: rounds of {cold memcpy, engine, engine with
 * BLOOM_FLAG_NO_SKIP} (and the dark frame in place), medians, ratios of the
 * same rounds; outputs of skip and no-skip compared byte for byte. TSV:
 * callgrind counts from run.sh (size, scene, skip|noskip, Ir, checksum line).
 * Writes DIR/skip.csv and DIR/skip.md; asserts nothing about time. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bloom_model.h"
#include "report.h"

#define MAX_SIZES 4

static const char *scenes[] = {"dark", "sparse", "scene", "grid"};
static const char *about[] = {"dark (nothing reaches the knee)", "sparse (one small light)",
                              "dense (benchmark scene: floodlights + 24 lights)",
                              "full (a light in every 64x64 cell)"};
#define NSCENES 4

/* callgrind count of (size, scene, mode) from the TSV, or -1. */
static long long icount(const char *tsv, int w, int h, const char *scene, const char *mode)
{
    FILE *f = tsv ? fopen(tsv, "r") : NULL;
    char line[512], sz[32], sc[64], md[16];
    long long n, found = -1;
    char want[32];
    snprintf(want, sizeof want, "%dx%d", w, h);
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "%31s %63s %15s %lld", sz, sc, md, &n) == 4 && !strcmp(sz, want) &&
            !strcmp(sc, scene) && !strcmp(md, mode))
            found = n;
    if (f)
        fclose(f);
    return found;
}

/* % of source rows with a pixel whose largest channel reaches the knee's
 * lower edge T - kT (the rows the engine cannot skip at level 0). */
static double active_rows(const rin_t *in, const bloom_config_t *c)
{
    const double edge = (c->threshold - (double)c->threshold * c->soft_knee / 65536.0) / 65536.0;
    long long rows = 0;
    for (int y = 0; y < in->h; y++) {
        int any = 0;
        for (int i = 0; i < in->w * 3 && !any; i++)
            any = bloom_srgb_to_linear(in->p[(size_t)y * in->stride + (size_t)i] / 255.0) > edge;
        rows += any;
    }
    return 100.0 * (double)rows / in->h;
}

static bloom_t *engine(const bloom_config_t *c, void **ws)
{
    bloom_info_t info;
    bloom_t *b = NULL;
    bloom_status_t st = bloom_query(c, &info);
    if (st != BLOOM_OK || posix_memalign(ws, BLOOM_WORKSPACE_ALIGN, info.workspace_bytes) ||
        (st = bloom_init(&b, *ws, info.workspace_bytes, c)) != BLOOM_OK)
        rdie("engine: %s", bloom_status_str(st));
    return b;
}

int main(int argc, char **argv)
{
    const char *out = NULL, *data = "tests/data", *tsv = NULL;
    int sw[MAX_SIZES] = {1920, 640}, sh[MAX_SIZES] = {1080, 480}, nsizes = 2;
    int runs = 15, runs_big = 9;
    size_t ring_bytes = (size_t)256 << 20;
    for (int i = 1; i + 1 < argc; i += 2) {
        const char *a = argv[i], *v = argv[i + 1];
        if (!strcmp(a, "--out"))
            out = v;
        else if (!strcmp(a, "--data"))
            data = v;
        else if (!strcmp(a, "--icount"))
            tsv = v;
        else if (!strcmp(a, "--sizes")) {
            if ((nsizes = scene_parse_sizes(v, sw, sh, MAX_SIZES)) < 1)
                rdie("bad --sizes '%s'", v);
        } else if (!strcmp(a, "--runs"))
            runs = atoi(v);
        else if (!strcmp(a, "--runs-big"))
            runs_big = atoi(v);
        else if (!strcmp(a, "--ring-mb"))
            ring_bytes = (size_t)atol(v) << 20;
        else
            rdie("unknown option %s", a);
    }
    if (!out || argc % 2 == 0 || runs < 1 || runs_big < 1)
        rdie("usage: report_skip --out DIR [options] (see sim/report/skip.c)");
    rring_t ring;
    if (rring_init(&ring, ring_bytes))
        rdie("cannot allocate the rings");
    char cpath[1024], ctmp[1100], mpath[1024], mtmp[1100];
    snprintf(cpath, sizeof cpath, "%s/skip.csv", out);
    snprintf(mpath, sizeof mpath, "%s/skip.md", out);
    FILE *csv = ropen(cpath, ctmp, sizeof ctmp), *md = ropen(mpath, mtmp, sizeof mtmp);
    fprintf(csv, "width,height,scene,active_rows_pct,runs,memcpy_ms,memcpy_cpu_ms,skip_ms,skip_cpu_ms,"
                 "noskip_ms,noskip_cpu_ms,skip_over_noskip,skip_over_noskip_cpu,skip_x_memcpy,"
                 "skip_x_memcpy_cpu,inplace_ms,inplace_cpu_ms,inplace_x_memcpy,"
                 "inplace_x_memcpy_cpu,icount_skip,icount_noskip,identical,output_is_input\n");
    fprintf(md, "| frame | scene | source rows reaching the knee | skip / full path, CPU (wall) | "
                "skip x cold memcpy, CPU (wall) | instructions: skip / full path | ratio | "
                "skip output = full-path output |\n|---|---|---:|---:|---:|---:|---:|---|\n");
    int all_identical = 1;
    for (int s = 0; s < nsizes; s++) {
        const int w = sw[s], h = sh[s];
        const size_t bytes = (size_t)w * (size_t)h * 3u;
        const int r = (size_t)w * (size_t)h > 1000000u ? runs_big : runs;
        for (int si = 0; si < NSCENES; si++) {
            char err[512];
            rin_t in;
            if (rin_make(&in, scenes[si], data, w, h, err, sizeof err))
                rdie("%s", err);
            bloom_config_t c, cn;
            bloom_config_default(&c, w, h);
            cn = c;
            cn.flags |= BLOOM_FLAG_NO_SKIP;
            void *ws1 = NULL, *ws2 = NULL, *ws3 = NULL;
            rengine_ctx_t e1 = {engine(&c, &ws1), w * 3, w * 3}, e2 = {engine(&cn, &ws2), w * 3, w * 3};
            rengine_ctx_t e3 = {engine(&c, &ws3), w * 3, w * 3};
            const int dark = !strcmp(scenes[si], "dark");
            rtimer_t t[4] = {{rrun_memcpy, (void *)&bytes, 0, 0, 0, NULL},
                             {rrun_engine, &e1, 0, 0, 0, NULL},
                             {rrun_engine, &e2, 0, 0, 0, NULL},
                             {rrun_engine, &e3, 1, 0, 0, NULL}};
            if (rring_fill(&ring, in.p, bytes, bytes) || rtime_rounds(&ring, t, dark ? 4 : 3, 1, r))
                rdie("timing failed at %dx%d", w, h);
            /* The same input through both paths, out of the ring. */
            uint8_t *o1 = rxmalloc(bytes), *o2 = rxmalloc(bytes), *o3 = rxmalloc(bytes);
            memcpy(o3, in.p, bytes);
            if (rrun_engine(&e1, in.p, o1) || rrun_engine(&e2, in.p, o2) || rrun_engine(&e3, o3, o3))
                rdie("engine failed");
            const int same = !memcmp(o1, o2, bytes) && !memcmp(o1, o3, bytes);
            const int is_input = !memcmp(o1, in.p, bytes);
            all_identical &= same;
            const long long ic1 = icount(tsv, w, h, scenes[si], "skip");
            const long long ic2 = icount(tsv, w, h, scenes[si], "noskip");
            const double act = active_rows(&in, &c);
            fprintf(csv, "%d,%d,%s,%.2f,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,", w, h,
                    scenes[si], act, r, t[0].wall_ms, t[0].cpu_ms, t[1].wall_ms, t[1].cpu_ms, t[2].wall_ms,
                    t[2].cpu_ms, t[1].wall_ms / t[2].wall_ms, t[1].cpu_ms / t[2].cpu_ms,
                    t[1].wall_ms / t[0].wall_ms, t[1].cpu_ms / t[0].cpu_ms);
            if (dark)
                fprintf(csv, "%.4f,%.4f,%.4f,%.4f,", t[3].wall_ms, t[3].cpu_ms, t[3].wall_ms / t[0].wall_ms,
                        t[3].cpu_ms / t[0].cpu_ms);
            else
                fprintf(csv, ",,,,");
            fprintf(csv, "%lld,%lld,%s,%s\n", ic1, ic2, same ? "yes" : "NO", is_input ? "yes" : "no");
            fprintf(md, "| %dx%d | %s | %.1f %% | %.3f (%.3f) | %.2f (%.2f) | ", w, h, about[si], act,
                    t[1].cpu_ms / t[2].cpu_ms, t[1].wall_ms / t[2].wall_ms, t[1].cpu_ms / t[0].cpu_ms,
                    t[1].wall_ms / t[0].wall_ms);
            if (ic1 > 0 && ic2 > 0)
                fprintf(md, "%lld / %lld | %.4f | ", ic1, ic2, (double)ic1 / (double)ic2);
            else
                fprintf(md, "- | - | ");
            fprintf(md, "%s%s |\n", same ? "identical" : "**DIFFERENT**", is_input ? " (and = input)" : "");
            if (dark)
                fprintf(md, "| %dx%d | dark, in place (dst = src) | | | %.2f (%.2f) | | | %s |\n", w, h,
                        t[3].cpu_ms / t[0].cpu_ms, t[3].wall_ms / t[0].wall_ms,
                        !memcmp(o3, in.p, bytes) ? "untouched (= input)" : "**changed**");
            printf("skip %dx%d %-7s skip/full %.3f (CPU %.3f), skip x memcpy %.2f (CPU %.2f), %s\n", w, h,
                   scenes[si], t[1].wall_ms / t[2].wall_ms, t[1].cpu_ms / t[2].cpu_ms,
                   t[1].wall_ms / t[0].wall_ms, t[1].cpu_ms / t[0].cpu_ms, same ? "identical" : "DIFFERENT");
            fflush(stdout);
            free(o1);
            free(o2);
            free(o3);
            free(ws1);
            free(ws2);
            free(ws3);
            rin_free(&in);
        }
    }
    fprintf(md,
            "\nSkip and full-path outputs %s in every row (each scene run once more "
            "outside the ring, out of place and in place, and compared byte for byte).\n",
            all_identical ? "are identical" : "**differ**");
    rclose(csv, ctmp, cpath);
    rclose(md, mtmp, mpath);
    rring_free(&ring);
    if (!all_identical) /* reported in skip.md; the report is still written */
        fprintf(stderr, "report_skip: skip and full-path outputs DIFFER\n");
    return 0;
}
