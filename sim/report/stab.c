/* report_stab: the stability matrix of make report (issue 3, section 3).
 *
 *   report_stab --out DIR [--data DIR] [--curves-only]
 *
 * Writes DIR/stability.csv (every case), DIR/stability.md (the report's
 * section), DIR/levels_fF.csv and DIR/intensity_fF.csv (the two curves;
 * F = BLOOM_LIN_BITS of this build). --curves-only: the curves alone (for
 * the comparison build at another F). Errors are against the float model
 * (bloom_model_run), deterministic; nothing here is timed. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "imgio.h"
#include "report.h"
#include "stab.h"

static FILE *csv, *md;
const char *stab_data_dir = "tests/data", *stab_out_dir = ".";

/* Over every case run (RGB888 output; RGBQ16 output by relative error). */
static struct {
    long long ok, refused, worst8, sat_rows, sat_diff;
    double worst_rel, worst_bias; /* worst_bias: signed mean of largest magnitude */
    char worst8_case[240], worst_rel_case[240], worst_bias_case[240], over1[4096];
} tr;

static void track(const char *cas, const rin_t *in, const bloom_config_t *c, const res_t *r)
{
    if (r->st != BLOOM_OK) {
        tr.refused++;
        return;
    }
    tr.ok++;
    char what[240];
    snprintf(what, sizeof what, "%s (%s %dx%d, N %d, intensity %.1f)", cas, in->name, in->w, in->h, c->levels,
             c->intensity / 65536.0);
    if (c->out_fmt == BLOOM_FMT_RGBQ16) {
        if (r->s.peak_rel > tr.worst_rel) {
            tr.worst_rel = r->s.peak_rel;
            snprintf(tr.worst_rel_case, sizeof tr.worst_rel_case, "%s", what);
        }
        return;
    }
    if (fabs(rstat_signed_mean(&r->s)) > fabs(tr.worst_bias)) {
        tr.worst_bias = rstat_signed_mean(&r->s);
        snprintf(tr.worst_bias_case, sizeof tr.worst_bias_case, "%s", what);
    }
    if (r->s.peak > tr.worst8) {
        tr.worst8 = r->s.peak;
        snprintf(tr.worst8_case, sizeof tr.worst8_case, "%s", what);
    }
    if (r->s.peak > 1 && strlen(tr.over1) + strlen(what) + 32 < sizeof tr.over1)
        snprintf(tr.over1 + strlen(tr.over1), sizeof tr.over1 - strlen(tr.over1), "%s%s: %lld LSB",
                 tr.over1[0] ? "; " : "", what, r->s.peak);
    if (r->s.sat_eng != r->s.sat_ref) {
        const long long d = r->s.sat_eng - r->s.sat_ref;
        tr.sat_rows++;
        if ((d < 0 ? -d : d) > tr.sat_diff)
            tr.sat_diff = d < 0 ? -d : d;
    }
}

static void summary(FILE *f)
{
    fprintf(f,
            "Cases run: %lld, refused as out of range (as they should be): %lld. Largest error "
            "with RGB888 output: **%lld LSB** (first reached by %s). ",
            tr.ok, tr.refused, tr.worst8, tr.worst8_case);
    if (tr.over1[0])
        fprintf(f, "Cases above 1 LSB: %s. ", tr.over1);
    else
        fprintf(f, "No case exceeds 1 LSB. ");
    if (tr.worst_bias_case[0])
        fprintf(f,
                "Largest bias (signed mean of the largest magnitude) with RGB888 output: "
                "%+.5f LSB (%s). ",
                tr.worst_bias, tr.worst_bias_case);
    else
        fprintf(f, "No RGB888 case has a bias (every signed mean is 0). ");
    fprintf(f, "Largest relative error with RGBQ16 output: %.2g (%s). ", tr.worst_rel, tr.worst_rel_case);
    if (tr.sat_rows)
        fprintf(f,
                "Saturation: in %lld cases the engine and the model put a different number "
                "of samples at the top code, by at most %lld samples.\n",
                tr.sat_rows, tr.sat_diff);
    else
        fprintf(f, "Saturation: engine and model put the same number of samples at the top "
                   "code in every case.\n");
}

static const char *fmt_name(bloom_format_t f)
{
    return f == BLOOM_FMT_RGBQ16 ? "RGBQ16" : "RGB888";
}

res_t stab_run(const rin_t *in, const bloom_config_t *c, int with_raw)
{
    res_t r;
    memset(&r, 0, sizeof r);
    r.changed = -1;
    bloom_info_t info;
    if ((r.st = bloom_query(c, &info)) != BLOOM_OK)
        return r;
    r.built = info.levels;
    const size_t n = (size_t)in->w * (size_t)in->h * 3u;
    const int q16 = c->out_fmt == BLOOM_FMT_RGBQ16;
    const size_t ostride = (size_t)in->w * (size_t)bloom_format_bpp(c->out_fmt);
    uint8_t *out = rxmalloc(ostride * (size_t)in->h);
    if ((r.st = rengine_run(c, in->p, in->stride, out, ostride)) != BLOOM_OK) {
        free(out);
        return r;
    }
    uint32_t *eng = rxmalloc(n * 4u), *ref = rxmalloc(n * 4u), *clamped = NULL;
    for (size_t i = 0; i < n; i++) {
        if (q16)
            memcpy(&eng[i], out + 4u * i, 4);
        else
            eng[i] = out[i];
    }
    if (in->src_max == 0) { /* the engine's input rule: words clamp to 2^24 - 1 */
        clamped = rxmalloc(n * 4u);
        for (size_t i = 0; i < n; i++)
            clamped[i] = in->codes[i] > BLOOM_MAX_LINEAR ? BLOOM_MAX_LINEAR : in->codes[i];
    }
    const long long top = q16 ? BLOOM_MAX_LINEAR : 255;
    r.s.rel_floor = r.raw.rel_floor = q16 ? 65536 : 1; /* relative error where v >= 1.0 */
    if (rmodel_run(c, clamped ? clamped : in->codes, in->src_max, ref, q16 ? 0 : 255) != r.built)
        rdie("model and engine disagree on the level count (%s %dx%d)", in->name, in->w, in->h);
    for (size_t i = 0; i < n; i++)
        rstat_add(&r.s, eng[i], ref[i], top);
    if (with_raw && clamped) { /* the model on the words as given, unclamped */
        if (rmodel_run(c, in->codes, 0, ref, q16 ? 0 : 255) < 0)
            rdie("model failed on raw words");
        for (size_t i = 0; i < n; i++)
            rstat_add(&r.raw, eng[i], ref[i], top);
        r.has_raw = 1;
    }
    if (!q16 && in->fmt == BLOOM_FMT_RGB888 && !(c->flags & BLOOM_FLAG_DEBUG_VIEW)) {
        r.changed = 0;
        for (size_t i = 0; i < n; i++)
            r.changed += eng[i] != in->codes[i];
    }
    free(clamped);
    free(ref);
    free(eng);
    free(out);
    return r;
}

void stab_emit(const char *section, const char *cas, const rin_t *in, const bloom_config_t *c,
               const char *levels, const res_t *r, const char *note)
{
    const double t = c->threshold / 65536.0, k = c->soft_knee / 65536.0, I = c->intensity / 65536.0;
    track(cas, in, c, r);
    fprintf(csv, "%s,\"%s\",%s,%d,%d,%s,%s,%s,%d,%.6f,%.6f,%.6f,\"%s\"", section, cas, in->name, in->w, in->h,
            fmt_name(in->fmt), fmt_name(c->out_fmt), levels, r->built, t, k, I,
            r->st == BLOOM_OK ? "ok" : bloom_status_str(r->st));
    if (r->st == BLOOM_OK)
        fprintf(csv, ",%lld,%.6f,%.6f,%.4f,%lld,%lld,%.3g", r->s.peak, rstat_mean(&r->s), rstat_mse(&r->s),
                rstat_exact(&r->s), r->s.sat_eng, r->s.sat_ref, r->s.peak_rel);
    else
        fprintf(csv, ",,,,,,,");
    if (r->has_raw)
        fprintf(csv, ",%lld,%.6f,%lld", r->raw.peak, rstat_mean(&r->raw), r->raw.sat_ref);
    else
        fprintf(csv, ",,,");
    fprintf(csv, ",%lld,\"%s\"", r->changed, note ? note : "");
    /* the bias fields after the note: columns before it keep their index */
    if (r->st == BLOOM_OK)
        fprintf(csv, ",%.6f,%lld,%lld", rstat_signed_mean(&r->s), r->s.above, r->s.below);
    else
        fprintf(csv, ",,,");
    if (r->has_raw)
        fprintf(csv, ",%.6f,%lld,%lld\n", rstat_signed_mean(&r->raw), r->raw.above, r->raw.below);
    else
        fprintf(csv, ",,,\n");

    fprintf(md, "| %s | %s | %dx%d %s | %s (%d) | %s | ", cas, in->name, in->w, in->h, fmt_name(in->fmt),
            levels, r->built, fmt_name(c->out_fmt));
    if (r->st != BLOOM_OK) {
        fprintf(md, "refused: %s | | | | | | %s |\n", bloom_status_str(r->st), note ? note : "");
        return;
    }
    fprintf(md, "%lld | %.5f | %.3f | %+.5f | %lld / %lld | %lld / %lld | ", r->s.peak, rstat_mean(&r->s),
            rstat_exact(&r->s), rstat_signed_mean(&r->s), r->s.above, r->s.below, r->s.sat_eng, r->s.sat_ref);
    char notes[512] = "";
    size_t nk = 0;
    if (c->out_fmt == BLOOM_FMT_RGBQ16)
        nk += (size_t)snprintf(notes + nk, sizeof notes - nk, "; relative error where v >= 1.0: %.2g",
                               r->s.peak_rel);
    if (r->has_raw && nk < sizeof notes)
        nk += (size_t)snprintf(notes + nk, sizeof notes - nk,
                               "; vs unclamped words: peak %lld, mean \\|e\\| %.3f, signed mean %+.3f "
                               "(%lld above, %lld below), model top %lld",
                               r->raw.peak, rstat_mean(&r->raw), rstat_signed_mean(&r->raw), r->raw.above,
                               r->raw.below, r->raw.sat_ref);
    if (r->changed >= 0 && nk < sizeof notes)
        nk += r->changed ? (size_t)snprintf(notes + nk, sizeof notes - nk,
                                            "; %lld samples differ from the input", r->changed)
                         : (size_t)snprintf(notes + nk, sizeof notes - nk, "; output = input");
    if (note && nk < sizeof notes)
        snprintf(notes + nk, sizeof notes - nk, "; %s", note);
    fprintf(md, "%s |\n", notes[0] ? notes + 2 : "");
}

void stab_table(const char *title, const char *intro)
{
    fprintf(md, "\n### %s\n\n%s\n\n", title, intro);
    fprintf(md, "| case | input | frame | N (L built) | out | peak LSB | mean \\|e\\| LSB | exact %% | "
                "signed mean LSB | above / below | top code: engine / model | notes |\n"
                "|---|---|---|---|---|---:|---:|---:|---:|---:|---|---|\n");
}

void stab_config(bloom_config_t *c, const rin_t *in, int levels, double t, double k, double i,
                 bloom_format_t out)
{
    bloom_config_default(c, in->w, in->h);
    c->levels = levels;
    c->threshold = BLOOM_Q16(t);
    c->soft_knee = BLOOM_Q16(k);
    c->intensity = BLOOM_Q16(i);
    c->in_fmt = in->fmt;
    c->out_fmt = out;
}

void stab_input(rin_t *in, const char *name, int w, int h)
{
    char err[512];
    if (rin_make(in, name, stab_data_dir, w, h, err, sizeof err))
        rdie("%s", err);
}

/* ---- the two curves ----------------------------------------------------- */

static const char *curve_inputs[] = {"rocket", "hubble", "scene-hubble", "studio",
                                     "hall",   "point",  "hdr-point"};
#define N_CURVE ((int)(sizeof curve_inputs / sizeof curve_inputs[0]))

/* all: every point of the curve pooled (equal sample counts), for its bias. */
static void summary_line(const char *what, const char *input, const rstat_t *lo, const rstat_t *hi,
                         long long peak_all, double mean_max, const rstat_t *all)
{
    fprintf(md,
            "| %s | %s | %lld / %.5f / %+.5f | %lld / %.5f / %+.5f | %lld | %.5f | %+.5f | "
            "%lld / %lld |\n",
            what, input, lo->peak, rstat_mean(lo), rstat_signed_mean(lo), hi->peak, rstat_mean(hi),
            rstat_signed_mean(hi), peak_all, mean_max, rstat_signed_mean(all), all->above, all->below);
}

static void curves(const char *dir, int with_md)
{
    char path[1024], tmp[1100];
    snprintf(path, sizeof path, "%s/levels_f%d.csv", dir, BLOOM_LIN_BITS);
    FILE *f = ropen(path, tmp, sizeof tmp);
    /* new fields go last in both curves: plots.gp reads columns 1, 2, 5, 7, 8 */
    fprintf(f, "F,input,width,height,levels,levels_built,peak,mean,mse,exact_pct,signed_mean,n_above,"
               "n_below\n");
    if (with_md) {
        fprintf(md, "\n### Error against level count and intensity (the curves)\n\n"
                    "Level curve: every level count N = 1..16 at 1024x768 (L built stops at 9: "
                    "a level needs both sides >= 2), threshold 0.6, soft knee 0.5, intensity 1; "
                    "intensity curve: 0 to 10.0 (the largest allowed) in steps of 0.5 at "
                    "320x240, 5 levels, threshold 0.6. Both RGB888 output. "
                    "`report_levels.png`, `report_intensity.png`; data in "
                    "`report_levels.csv`, `report_intensity.csv`.\n\n"
                    "Peak and mean \\|e\\| in LSB; the signed mean (engine - model) and the samples "
                    "above / below (engine > / < model) show a bias the mean \\|e\\| hides.\n\n"
                    "| curve | input | at the low end: peak / mean \\|e\\| / signed mean | at the high "
                    "end: peak / mean \\|e\\| / signed mean | largest peak | largest mean \\|e\\| | "
                    "signed mean, whole curve | above / below, whole curve |\n"
                    "|---|---|---|---|---:|---:|---:|---:|\n");
    }
    for (int ii = 0; ii < N_CURVE; ii++) {
        rin_t in;
        stab_input(&in, curve_inputs[ii], 1024, 768);
        rstat_t first, last, all;
        memset(&all, 0, sizeof all);
        long long pk = 0;
        double mx = 0.0;
        for (int n = 1; n <= BLOOM_MAX_LEVELS; n++) {
            bloom_config_t c;
            stab_config(&c, &in, n, 0.6, 0.5, 1.0, BLOOM_FMT_RGB888);
            const res_t r = stab_run(&in, &c, 0);
            if (r.st != BLOOM_OK)
                rdie("level curve: %s", bloom_status_str(r.st));
            track("level curve", &in, &c, &r);
            fprintf(f, "%d,%s,%d,%d,%d,%d,%lld,%.6f,%.6f,%.4f,%.6f,%lld,%lld\n", BLOOM_LIN_BITS, in.name,
                    in.w, in.h, n, r.built, r.s.peak, rstat_mean(&r.s), rstat_mse(&r.s), rstat_exact(&r.s),
                    rstat_signed_mean(&r.s), r.s.above, r.s.below);
            if (n == 1)
                first = r.s;
            last = r.s;
            rstat_merge(&all, &r.s);
            pk = r.s.peak > pk ? r.s.peak : pk;
            mx = rstat_mean(&r.s) > mx ? rstat_mean(&r.s) : mx;
        }
        if (with_md)
            summary_line("levels N = 1 .. 16", in.name, &first, &last, pk, mx, &all);
        rin_free(&in);
    }
    rclose(f, tmp, path);

    snprintf(path, sizeof path, "%s/intensity_f%d.csv", dir, BLOOM_LIN_BITS);
    f = ropen(path, tmp, sizeof tmp);
    fprintf(f, "F,input,width,height,intensity,levels_built,peak,mean,mse,exact_pct,top_engine,"
               "top_model,signed_mean,n_above,n_below\n");
    for (int ii = 0; ii < N_CURVE; ii++) {
        rin_t in;
        stab_input(&in, curve_inputs[ii], 320, 240);
        rstat_t first, last, all;
        memset(&all, 0, sizeof all);
        long long pk = 0;
        double mx = 0.0;
        for (int s = 0; s <= 20; s++) {
            bloom_config_t c;
            stab_config(&c, &in, 5, 0.6, 0.5, s * 0.5, BLOOM_FMT_RGB888);
            const res_t r = stab_run(&in, &c, 0);
            if (r.st != BLOOM_OK)
                rdie("intensity curve: %s", bloom_status_str(r.st));
            track("intensity curve", &in, &c, &r);
            fprintf(f, "%d,%s,%d,%d,%.2f,%d,%lld,%.6f,%.6f,%.4f,%lld,%lld,%.6f,%lld,%lld\n", BLOOM_LIN_BITS,
                    in.name, in.w, in.h, s * 0.5, r.built, r.s.peak, rstat_mean(&r.s), rstat_mse(&r.s),
                    rstat_exact(&r.s), r.s.sat_eng, r.s.sat_ref, rstat_signed_mean(&r.s), r.s.above,
                    r.s.below);
            if (s == 0)
                first = r.s;
            last = r.s;
            rstat_merge(&all, &r.s);
            pk = r.s.peak > pk ? r.s.peak : pk;
            mx = rstat_mean(&r.s) > mx ? rstat_mean(&r.s) : mx;
        }
        if (with_md)
            summary_line("intensity 0 .. 10", in.name, &first, &last, pk, mx, &all);
        rin_free(&in);
    }
    rclose(f, tmp, path);
}

int main(int argc, char **argv)
{
    const char *out = NULL;
    int curves_only = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--curves-only"))
            curves_only = 1;
        else if (!strcmp(argv[i], "--out") && i + 1 < argc)
            out = argv[++i];
        else if (!strcmp(argv[i], "--data") && i + 1 < argc)
            stab_data_dir = argv[++i];
        else
            rdie("usage: report_stab --out DIR [--data DIR] [--curves-only]");
    }
    if (!out)
        rdie("usage: report_stab --out DIR [--data DIR] [--curves-only]");
    stab_out_dir = out;
    char mpath[1024], mtmp[1100], cpath[1024], ctmp[1100];
    snprintf(mpath, sizeof mpath, "%s/stability_f%d.md", out, BLOOM_LIN_BITS);
    md = ropen(mpath, mtmp, sizeof mtmp);
    if (curves_only) {
        curves(out, 0);
        rclose(md, mtmp, mpath);
        return 0;
    }
    snprintf(cpath, sizeof cpath, "%s/stability.csv", out);
    csv = ropen(cpath, ctmp, sizeof ctmp);
    fprintf(csv, "section,case,input,width,height,in_fmt,out_fmt,levels,levels_built,threshold,knee,"
                 "intensity,status,peak,mean,mse,exact_pct,top_engine,top_model,peak_rel,raw_peak,"
                 "raw_mean,raw_top_model,changed_vs_input,note,signed_mean,n_above,n_below,"
                 "raw_signed_mean,raw_n_above,raw_n_below\n");
    stab_params(md);
    stab_hdr(md);
    stab_float(md);
    stab_shapes(md);
    stab_stress(md);
    curves(out, 1);
    char spath[1024], stmp[1100];
    snprintf(spath, sizeof spath, "%s/stability_summary.md", out);
    FILE *sf = ropen(spath, stmp, sizeof stmp);
    summary(sf);
    rclose(sf, stmp, spath);
    rclose(csv, ctmp, cpath);
    rclose(md, mtmp, mpath);
    return 0;
}
