/* report_sweep: error against run time for one BLOOM_LIN_BITS build (the
 * make report rule builds one binary per F, each with that F's tables).
 *
 *   report_sweep --ref DIR [--csv PATH] [--data DIR] [--sizes WxH,...]
 *                [--levels A-B] [--inputs a,b,...] [--runs N] [--runs-big N]
 *                [--warmup N] [--ring-mb N] [--widths 32,16] [--model-only]
 *
 * Per size, input and level count: the float model's RGB888 output (cached
 * in DIR: it does not depend on F, so one run of the model serves every F;
 * --model-only only fills the cache), then rounds of {cold memcpy of the
 * RGB888 frame, engine}, medians of both, and the engine's output of the
 * last round against the model (peak, mean |e|, signed mean with the samples
 * above and below it, MSE, % exact); one CSV row each (run.sh pools the
 * inputs). --widths lists the row sample widths (cfg.sample_bits) run at
 * every level count; the model does not depend on them either. A width the
 * engine refuses for a configuration is reported and left out.
 * Measures and prints; asserts nothing. */
#include <stdlib.h>
#include <string.h>

#include "report.h"
#include "variants.h" /* BENCH_THRESHOLD: the parameters of make bench */

#define MAX_SIZES 8
#define MAX_INPUTS 16
#define BIG_PIXELS 1000000

typedef struct {
    const char *data, *ref, *csv;
    int sw[MAX_SIZES], sh[MAX_SIZES], nsizes;
    int lmin, lmax;
    const char *inputs[MAX_INPUTS];
    int ninputs;
    int runs, runs_big, warm, model_only;
    int widths[2], nwidths;
    size_t ring_bytes;
} opts_t;

/* One configuration's figures (one input). */
typedef struct {
    rstat_t st;
    double eng_ms, eng_cpu, mc_ms, mc_cpu, x_wall, x_cpu;
    int built, runs;
    size_t ws;
} row_t;

static void config_for(bloom_config_t *c, const rin_t *in, int levels)
{
    bloom_config_default(c, in->w, in->h);
    c->levels = levels;
    c->threshold = BLOOM_Q16(BENCH_THRESHOLD);
    c->in_fmt = in->fmt;
    c->out_fmt = BLOOM_FMT_RGB888;
}

/* The model's output codes for (input, size, levels), from the cache or
 * computed and cached (written whole, then renamed: two jobs may race). */
static uint8_t *reference(const opts_t *o, const rin_t *in, const bloom_config_t *c)
{
    char path[1024], tmp[1100];
    const size_t n = (size_t)in->w * (size_t)in->h * 3u;
    snprintf(path, sizeof path, "%s/%s-%dx%d-L%d-t%u.u8", o->ref, in->name, in->w, in->h, c->levels,
             (unsigned)c->threshold);
    uint8_t *ref = rxmalloc(n);
    FILE *f = fopen(path, "rb");
    if (f) {
        const size_t got = fread(ref, 1, n, f);
        fclose(f);
        if (got == n)
            return ref;
    }
    uint32_t *out = rxmalloc(n * sizeof *out);
    if (rmodel_run(c, in->codes, in->src_max, out, 255) < 0)
        rdie("bloom_model_run failed on %s %dx%d L%d", in->name, in->w, in->h, c->levels);
    for (size_t i = 0; i < n; i++)
        ref[i] = (uint8_t)out[i];
    free(out);
    snprintf(tmp, sizeof tmp, "%s.tmp%ld", path, (long)rnow_wall());
    if (!(f = fopen(tmp, "wb")) || fwrite(ref, 1, n, f) != n || fclose(f) || rename(tmp, path))
        rdie("cannot write %s", path);
    return ref;
}

static void csv_row(FILE *f, int w, int h, int lv, int bits, const char *input, const char *fmt,
                    const row_t *a)
{
    char ps[32];
    /* the bias fields last: sweep.awk reads the columns by index */
    fprintf(f,
            "%d,%d,%d,%d,%d,%s,%s,%d,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%lld,%.6f,%.6f,%s,%.4f,%zu,"
            "%.6f,%lld,%lld,%d\n",
            BLOOM_LIN_BITS, w, h, lv, a->built, input, fmt, a->runs, a->eng_ms, a->eng_cpu, a->mc_ms,
            a->mc_cpu, a->x_wall, a->x_cpu, a->st.peak, rstat_mean(&a->st), rstat_mse(&a->st),
            rpsnr_str(rstat_psnr(&a->st), ps, sizeof ps), rstat_exact(&a->st), a->ws,
            rstat_signed_mean(&a->st), a->st.above, a->st.below, bits);
}

static void sweep_size(const opts_t *o, int w, int h, rring_t *ring, FILE *csv)
{
    const size_t rgb_bytes = (size_t)w * (size_t)h * 3u;
    const int runs = (size_t)w * (size_t)h > BIG_PIXELS ? o->runs_big : o->runs;
    for (int ii = 0; ii < o->ninputs; ii++) {
        char err[512];
        rin_t in;
        if (rin_make(&in, o->inputs[ii], o->data, w, h, err, sizeof err))
            rdie("%s", err);
        if (!o->model_only && rring_fill(ring, in.p, in.bytes, in.bytes > rgb_bytes ? in.bytes : rgb_bytes))
            rdie("ring too small for %dx%d (--ring-mb)", w, h);
        for (int lv = o->lmin; lv <= o->lmax; lv++) {
            bloom_config_t c;
            config_for(&c, &in, lv);
            uint8_t *ref = reference(o, &in, &c);
            if (o->model_only) {
                free(ref);
                continue;
            }
            for (int wi = 0; wi < o->nwidths; wi++) {
                c.sample_bits = o->widths[wi];
                bloom_info_t info;
                bloom_status_t st = bloom_query(&c, &info);
                if (st == BLOOM_E_SAMPLE_BITS) { /* RGBQ16 input, or a format it cannot carry */
                    printf("F%d %dx%d L%d %-12s %d-bit samples refused: %s\n", BLOOM_LIN_BITS, w, h, lv,
                           in.name, c.sample_bits, bloom_status_str(st));
                    continue;
                }
                void *ws = NULL;
                bloom_t *b = NULL;
                if (st != BLOOM_OK || posix_memalign(&ws, BLOOM_WORKSPACE_ALIGN, info.workspace_bytes) ||
                    (st = bloom_init(&b, ws, info.workspace_bytes, &c)) != BLOOM_OK)
                    rdie("engine %s %dx%d L%d: %s", in.name, w, h, lv, bloom_status_str(st));
                size_t mc_bytes = rgb_bytes;
                rengine_ctx_t ec = {b, (ptrdiff_t)in.stride, (ptrdiff_t)(w * 3)};
                rtimer_t t[2] = {{rrun_memcpy, &mc_bytes, 0, 0, 0, NULL}, {rrun_engine, &ec, 0, 0, 0, NULL}};
                if (rtime_rounds(ring, t, 2, o->warm, runs))
                    rdie("engine run failed");
                row_t one;
                memset(&one, 0, sizeof one);
                for (size_t i = 0; i < rgb_bytes; i++)
                    rstat_add(&one.st, t[1].last_dst[i], ref[i], 255);
                one.eng_ms = t[1].wall_ms;
                one.eng_cpu = t[1].cpu_ms;
                one.mc_ms = t[0].wall_ms;
                one.mc_cpu = t[0].cpu_ms;
                one.x_wall = t[1].wall_ms / t[0].wall_ms;
                one.x_cpu = t[1].cpu_ms / t[0].cpu_ms;
                one.built = info.levels;
                one.runs = runs;
                bloom_config_t c8 = c; /* the RGB888-input figure, as README's memory table */
                c8.in_fmt = BLOOM_FMT_RGB888;
                one.ws = bloom_workspace_size(&c8);
                csv_row(csv, w, h, lv, c.sample_bits, in.name,
                        in.fmt == BLOOM_FMT_RGBQ16 ? "RGBQ16" : "RGB888", &one);
                printf("F%d %dx%d L%d w%d %-12s x memcpy %7.2f (CPU %7.2f)  peak %lld exact %.3f%% "
                       "signed mean %+.5f (%lld above, %lld below) mean |e| %.5f\n",
                       BLOOM_LIN_BITS, w, h, lv, c.sample_bits, in.name, one.x_wall, one.x_cpu, one.st.peak,
                       rstat_exact(&one.st), rstat_signed_mean(&one.st), one.st.above, one.st.below,
                       rstat_mean(&one.st));
                fflush(stdout);
                free(ws);
            }
            free(ref);
        }
        rin_free(&in);
    }
}

int main(int argc, char **argv)
{
    static const char *def_inputs[] = {"rocket", "hubble", "studio", "hall", "scene", "scene-hubble"};
    opts_t o;
    memset(&o, 0, sizeof o);
    o.data = "tests/data";
    o.sw[0] = 640, o.sh[0] = 480, o.sw[1] = 1280, o.sh[1] = 720, o.sw[2] = 1920, o.sh[2] = 1080;
    o.nsizes = 3;
    o.lmin = 1, o.lmax = 8;
    for (int i = 0; i < 6; i++)
        o.inputs[i] = def_inputs[i];
    o.ninputs = 6;
    o.runs = 7, o.runs_big = 5, o.warm = 1;
    o.ring_bytes = 0;
    o.widths[0] = 32, o.widths[1] = 16, o.nwidths = 2;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--model-only")) {
            o.model_only = 1;
            continue;
        }
        if (!v)
            rdie("%s needs a value (see the top of sim/report/sweep.c)", a);
        i++;
        if (!strcmp(a, "--ref"))
            o.ref = v;
        else if (!strcmp(a, "--csv"))
            o.csv = v;
        else if (!strcmp(a, "--data"))
            o.data = v;
        else if (!strcmp(a, "--sizes")) {
            if ((o.nsizes = scene_parse_sizes(v, o.sw, o.sh, MAX_SIZES)) < 1)
                rdie("bad --sizes '%s'", v);
        } else if (!strcmp(a, "--levels")) {
            if (sscanf(v, "%d-%d", &o.lmin, &o.lmax) != 2 || o.lmin < 1 || o.lmax > BLOOM_MAX_LEVELS ||
                o.lmin > o.lmax)
                rdie("bad --levels '%s' (A-B)", v);
        } else if (!strcmp(a, "--inputs")) {
            char *s = strdup(v);
            o.ninputs = 0;
            for (char *t = strtok(s, ","); t && o.ninputs < MAX_INPUTS; t = strtok(NULL, ","))
                o.inputs[o.ninputs++] = t; /* s lives until exit */
        } else if (!strcmp(a, "--runs"))
            o.runs = atoi(v);
        else if (!strcmp(a, "--runs-big"))
            o.runs_big = atoi(v);
        else if (!strcmp(a, "--warmup"))
            o.warm = atoi(v);
        else if (!strcmp(a, "--widths")) {
            o.nwidths = sscanf(v, "%d,%d", &o.widths[0], &o.widths[1]);
            for (int k = 0; k < o.nwidths; k++)
                if (o.widths[k] != 32 && o.widths[k] != 16)
                    o.nwidths = 0;
            if (o.nwidths < 1)
                rdie("bad --widths '%s' (32, 16 or 32,16)", v);
        } else if (!strcmp(a, "--ring-mb"))
            o.ring_bytes = (size_t)atol(v) << 20;
        else
            rdie("unknown option %s", a);
    }
    if (!o.ref || (!o.model_only && !o.csv) || o.runs < 1 || o.runs_big < 1 || o.warm < 0)
        rdie("usage: report_sweep --ref DIR (--csv PATH | --model-only) [options]");
    rring_t ring;
    memset(&ring, 0, sizeof ring);
    FILE *csv = NULL;
    char tmp[1100];
    if (!o.ring_bytes) { /* 8 slots of the widest frame (RGBQ16), at least 128 MiB */
        o.ring_bytes = (size_t)128 << 20;
        for (int s = 0; s < o.nsizes; s++)
            if ((size_t)o.sw[s] * (size_t)o.sh[s] * 12u * 8u > o.ring_bytes)
                o.ring_bytes = (size_t)o.sw[s] * (size_t)o.sh[s] * 12u * 8u;
    }
    if (!o.model_only) {
        if (rring_init(&ring, o.ring_bytes))
            rdie("cannot allocate two rings of %zu MiB", o.ring_bytes >> 20);
        csv = ropen(o.csv, tmp, sizeof tmp);
        fprintf(csv, "F,width,height,levels,levels_built,input,format,runs,engine_ms,engine_cpu_ms,"
                     "memcpy_ms,memcpy_cpu_ms,x_memcpy,x_memcpy_cpu,peak_lsb,mean_lsb,mse,psnr_db,"
                     "exact_pct,workspace,signed_mean_lsb,n_above,n_below,sample_bits\n");
    }
    for (int s = 0; s < o.nsizes; s++)
        sweep_size(&o, o.sw[s], o.sh[s], &ring, csv);
    if (csv)
        rclose(csv, tmp, o.csv);
    rring_free(&ring);
    return 0;
}
