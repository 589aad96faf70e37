/* bloom_sim: recorded frames through the fixed-point bloom engine and, on
 * request, the float reference model side by side. See bloom_sim --help and
 * sim/docs/simulator.md. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* clock_gettime, isatty */
#endif

#include "bloom_mt.h"
#include "sim.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bloom_model.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* ---- the engine and its buffers for one frame geometry ------------------- */
typedef struct {
    int w, h;
    bloom_config_t cfg;
    bloom_info_t info;
    void *ws;
    bloom_t *b;     /* the engine of one thread, or tile 0 of mt */
    bloom_mt_t *mt; /* --threads N > 1: the strips (port/threads), in ws */
    int in_max[3], out_max[3];
    uint8_t *src, *dst;
    uint32_t *in_codes, *out_codes, *fl_codes, *bt_codes;
    uint8_t *rgb, *sbs;
    float *lin;
    const sim_aux_t *aux; /* the --aux plane when the preset reads one, else NULL */
} engine_t;

static void engine_free(engine_t *e)
{
    bloom_mt_free(e->mt);
    free(e->ws);
    free(e->src);
    free(e->dst);
    free(e->in_codes);
    free(e->out_codes);
    free(e->fl_codes);
    free(e->bt_codes);
    free(e->rgb);
    free(e->sbs);
    free(e->lin);
    memset(e, 0, sizeof *e);
}

/* (Re)builds the engine when the frame size or the formats change. */
/* "preset attenuation (a 0.75, r 0.25, depth plane d.pgm)": the preset and
 * the parameters it reads. */
static void preset_desc(const bloom_config_t *c, const sim_opts_t *o, char *buf, size_t len)
{
    const bloom_preset_params_t *p = &c->p;
    int n = snprintf(buf, len, "preset %s", bloom_preset_name(c->preset));
    char more[512] = "";
    size_t m = 0;
#define ADD(...) (m += (size_t)snprintf(more + m, sizeof more - m, __VA_ARGS__))
    switch (c->preset) {
    case BLOOM_PRESET_GAMEDEV:
        ADD(", strength %.5g", p->strength / 65536.0);
        break;
    case BLOOM_PRESET_XNA:
        ADD(", %d passes%s", p->passes, (c->flags & BLOOM_FLAG_SATURATE) ? ", saturate" : "");
        break;
    case BLOOM_PRESET_ATTENUATION:
        ADD(", attenuation %.5g, max reduction %.5g", p->attenuation / 65536.0, p->max_reduction / 65536.0);
        break;
    case BLOOM_PRESET_ARM:
        if (c->flags & BLOOM_FLAG_BAKED)
            ADD(", baked, strength %.5g", p->strength / 65536.0);
        ADD(", tint %.5g,%.5g,%.5g", p->tint[0] / 65536.0, p->tint[1] / 65536.0, p->tint[2] / 65536.0);
        break;
    case BLOOM_PRESET_COD:
        ADD(", weights");
        for (int k = 0; k < c->levels && k < BLOOM_MAX_LEVELS; k++)
            ADD("%s%.5g", k ? "," : " ", p->level_weight[k] / 65536.0);
        ADD(", tint %.5g,%.5g,%.5g%s%s", p->tint[0] / 65536.0, p->tint[1] / 65536.0, p->tint[2] / 65536.0,
            (c->flags & BLOOM_FLAG_ADDITIVE) ? ", additive" : "",
            (c->flags & BLOOM_FLAG_KEEP_LEVELS) ? ", levels kept" : "");
        break;
    default:
        break;
    }
    if (c->aux_fmt != BLOOM_AUX_NONE && o->aux_path)
        ADD(", %s %s, %s", sim_preset_aux_name(c), o->aux_path,
            c->aux_fmt == BLOOM_AUX_U16 ? "16-bit" : "8-bit");
#undef ADD
    if (m && n >= 0 && (size_t)n < len)
        snprintf(buf + n, len - (size_t)n, " (%s)", more + 2);
}

static int engine_setup(engine_t *e, const sim_opts_t *o, const sim_aux_t *aux, const sim_frame_t *f,
                        char *err, size_t errlen)
{
    bloom_config_t c;
    if (sim_opts_config(o, f->w, f->h, &c, err, errlen))
        return -1;
    if (o->in_fmt_set)
        c.in_fmt = o->in_fmt;
    else if (f->max[0] == (int)SIM_F32) /* float images as they are */
        c.in_fmt = BLOOM_FMT_RGBF32;
    else if (f->max[0] == 0)
        c.in_fmt = BLOOM_FMT_RGBQ16;
    else if (f->max[0] == 31 && f->max[1] == 63)
        c.in_fmt = BLOOM_FMT_RGB565;
    else
        c.in_fmt = BLOOM_FMT_RGB888;
    c.out_fmt = o->out_fmt_set ? o->out_fmt : BLOOM_FMT_RGB888;
    if (e->b && !memcmp(&c, &e->cfg, sizeof c))
        return 0;
    engine_free(e);
    if (c.aux_fmt != BLOOM_AUX_NONE && (aux->w != f->w || aux->h != f->h))
        return sim_errf(err, errlen,
                        "%s: --aux: the %s is %dx%d but the frame is %dx%d (it must be the "
                        "frame's size)",
                        o->aux_path, sim_preset_aux_name(&c), aux->w, aux->h, f->w, f->h);
    bloom_status_t st = bloom_query(&c, &e->info);
    if (st != BLOOM_OK)
        return sim_errf(err, errlen, "engine configuration for %dx%d: %s", f->w, f->h, bloom_status_str(st));
    const size_t n = (size_t)f->w * (size_t)f->h;
    e->w = f->w;
    e->h = f->h;
    e->cfg = c;
    /* more than one thread: the strip engines of bloom_mt in one buffer (the
     * output is the same bytes; the frames are never in place here) */
    const size_t ws_bytes = o->threads > 1 ? bloom_mt_size(&c, o->threads) : e->info.workspace_bytes;
    e->ws = malloc(ws_bytes);
    e->src = malloc(n * (size_t)bloom_format_bpp(c.in_fmt));
    e->dst = malloc(n * (size_t)bloom_format_bpp(c.out_fmt));
    e->in_codes = malloc(n * 3 * sizeof(uint32_t));
    e->out_codes = malloc(n * 3 * sizeof(uint32_t));
    e->fl_codes = malloc(n * 3 * sizeof(uint32_t));
    e->bt_codes = malloc(n * 3 * sizeof(uint32_t));
    e->rgb = malloc(n * 3);
    e->sbs = malloc(n * 12);
    e->lin = malloc(n * 3 * sizeof(float));
    if (!e->ws || !e->src || !e->dst || !e->in_codes || !e->out_codes || !e->fl_codes || !e->bt_codes ||
        !e->rgb || !e->sbs || !e->lin)
        return sim_errf(err, errlen, "out of memory for %dx%d frames", f->w, f->h);
    if (o->threads > 1) {
        if ((st = bloom_mt_init(&e->mt, e->ws, ws_bytes, &c, o->threads)) != BLOOM_OK)
            return sim_errf(err, errlen, "engine init (%d threads): %s", o->threads, bloom_mt_status_str(st));
        e->b = bloom_mt_engine(e->mt, 0);
    } else if ((st = bloom_init(&e->b, e->ws, e->info.workspace_bytes, &c)) != BLOOM_OK)
        return sim_errf(err, errlen, "engine init: %s", bloom_status_str(st));
    if (c.aux_fmt != BLOOM_AUX_NONE) {
        e->aux = aux;
        const ptrdiff_t as = (ptrdiff_t)aux->w * (aux->fmt == BLOOM_AUX_U16 ? 2 : 1);
        if ((st = e->mt ? bloom_mt_set_aux(e->mt, aux->data, as) : bloom_set_aux(e->b, aux->data, as)) !=
            BLOOM_OK)
            return sim_errf(err, errlen, "engine aux plane: %s", bloom_status_str(st));
    }
    sim_fmt_max(c.in_fmt, e->in_max);
    sim_fmt_max(c.out_fmt, e->out_max);
    char pd[640], tdesc[96] = "";
    preset_desc(&c, o, pd, sizeof pd);
    if (e->mt)
        snprintf(tdesc, sizeof tdesc, ", %d threads (%d strips in %zu bytes)", o->threads,
                 bloom_mt_tiles(e->mt), ws_bytes);
    printf("engine: %dx%d %s -> %s, %s%s%s, %d levels (%d built), threshold %.5g, knee %.5g, "
           "intensity %.5g, workspace %zu bytes, latency %d rows%s\n",
           f->w, f->h, sim_fmt_name(c.in_fmt), sim_fmt_name(c.out_fmt), pd,
           (c.flags & BLOOM_FLAG_LINEAR) ? ", linear" : ", sRGB",
           (c.flags & BLOOM_FLAG_DEBUG_VIEW) ? ", bloom-only view" : "", c.levels, e->info.levels,
           c.threshold / 65536.0, c.soft_knee / 65536.0, c.intensity / 65536.0, e->info.workspace_bytes,
           e->info.latency_rows, tdesc);
    return 0;
}

/* Runs the preset's reference model (float or bit-true) on the engine's
 * input (bloom_model_preset_run: the same configuration and aux plane). */
static int run_model(const engine_t *e, int bittrue, uint32_t *dst)
{
    bloom_model_preset_args_t a;
    memset(&a, 0, sizeof a);
    a.cfg = &e->cfg;
    a.bittrue = bittrue;
    a.src = e->in_codes;
    memcpy(a.src_max, e->in_max, sizeof a.src_max);
    if (e->aux) {
        a.aux = e->aux->codes;
        a.aux_max = e->aux->max;
    }
    a.dst_codes = dst;
    memcpy(a.dst_max, e->out_max, sizeof a.dst_max);
    return bloom_model_preset_run(&a) < 0 ? -1 : 0;
}

/* ---- statistics and progress -------------------------------------------- */
typedef struct {
    long frames;
    double *times;
    size_t cap;
    double pixels;
    unsigned long long samples, exact, above, below, bt_samples, bt_diff;
    uint32_t peak;
    double err_sum, err_signed; /* |error| and signed error: a bias hides in the first */
} stats_t;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

typedef struct {
    int enabled, shown, share; /* share: stdout is the same kind of terminal */
    double start, after, last;
    long total;
} progress_t;

static void progress_clear(progress_t *p)
{
    if (p->shown) {
        fputs("\r\033[K", stderr);
        fflush(stderr);
        p->shown = 0;
    }
}

static void progress_update(progress_t *p, long done)
{
    double t = now_s();
    if (!p->enabled || t - p->start < p->after || (p->shown && t - p->last < 0.2))
        return;
    p->last = t;
    if (p->total > 0)
        fprintf(stderr, "\r\033[Kbloom_sim: frame %ld of %ld (%.0f%%), %.1f s", done, p->total,
                100.0 * (double)done / (double)p->total, t - p->start);
    else
        fprintf(stderr, "\r\033[Kbloom_sim: frame %ld, %.1f s", done, t - p->start);
    fflush(stderr);
    p->shown = 1;
}

/* ---- one frame -------------------------------------------------------------- */
typedef struct {
    const sim_opts_t *o;
    engine_t eng;
    stats_t st;
    sim_out_t *out, *sbs;
    progress_t prog;
    sim_aux_t aux;
} run_t;

static int do_frame(run_t *r, const sim_frame_t *f, long gi, const char *name, char *err, size_t errlen)
{
    const sim_opts_t *o = r->o;
    engine_t *e = &r->eng;
    if (engine_setup(e, o, &r->aux, f, err, errlen)) {
        if (o->ninputs > 1) {
            size_t l = strlen(err);
            snprintf(err + l, errlen - l, " (frame %ld of the sequence, %s)", gi, name);
        }
        return -1;
    }
    const size_t n = (size_t)f->w * (size_t)f->h;
    sim_to_engine(f, e->cfg.in_fmt, (e->cfg.flags & BLOOM_FLAG_LINEAR) != 0, e->src);
    const ptrdiff_t ss = (ptrdiff_t)f->w * bloom_format_bpp(e->cfg.in_fmt);
    const ptrdiff_t ds = (ptrdiff_t)f->w * bloom_format_bpp(e->cfg.out_fmt);
    double best = 1e30;
    for (int k = 0; k < o->repeat; k++) {
        double t0 = now_s();
        bloom_status_t bs = e->mt ? bloom_mt_process(e->mt, e->src, ss, e->dst, ds)
                                  : bloom_process(e->b, e->src, ss, e->dst, ds);
        double t = now_s() - t0;
        if (bs != BLOOM_OK)
            return sim_errf(err, errlen, "frame %ld: engine: %s", gi, bloom_status_str(bs));
        best = t < best ? t : best;
    }
    sim_from_engine(e->dst, e->cfg.out_fmt, n, e->out_codes);
    sim_from_engine(e->src, e->cfg.in_fmt, n, e->in_codes);
    stats_t *st = &r->st;
    if (st->frames == (long)st->cap) {
        size_t cap = st->cap ? 2 * st->cap : 64;
        double *t = realloc(st->times, cap * sizeof *t);
        if (!t)
            return sim_errf(err, errlen, "out of memory");
        st->times = t;
        st->cap = cap;
    }
    st->times[st->frames++] = best;
    st->pixels += (double)n;

    char line[512];
    int len = snprintf(line, sizeof line, "frame %ld", gi);
    if (o->ninputs > 1)
        len += snprintf(line + len, sizeof line - (size_t)len, " (%s)", name);
    len += snprintf(line + len, sizeof line - (size_t)len, ": %dx%d, preset %s, engine %.3f ms", f->w, f->h,
                    bloom_preset_name(e->cfg.preset), best * 1e3);
    if (o->compare) {
        if (run_model(e, 0, e->fl_codes))
            return sim_errf(err, errlen, "frame %ld: the float model failed", gi);
        uint32_t peak = 0;
        unsigned long long exact = 0, above = 0, below = 0;
        double sum = 0, sgn = 0;
        for (size_t i = 0; i < 3 * n; i++) {
            uint32_t a = e->out_codes[i], b = e->fl_codes[i], d = a > b ? a - b : b - a;
            peak = d > peak ? d : peak;
            exact += d == 0;
            above += a > b;
            below += a < b;
            sum += d;
            sgn += (double)a - (double)b;
        }
        st->peak = peak > st->peak ? peak : st->peak;
        st->exact += exact;
        st->above += above;
        st->below += below;
        st->err_sum += sum;
        st->err_signed += sgn;
        st->samples += 3 * n;
        len +=
            snprintf(line + len, sizeof line - (size_t)len,
                     ", vs float: peak %u LSB, exact %.3f%%, signed mean %+.5f LSB (%llu above, %llu below)",
                     peak, 100.0 * (double)exact / (double)(3 * n), sgn / (double)(3 * n), above, below);
    }
    if (o->bittrue) {
        if (run_model(e, 1, e->bt_codes))
            return sim_errf(err, errlen, "frame %ld: the bit-true model failed", gi);
        unsigned long long diff = 0;
        for (size_t i = 0; i < 3 * n; i++)
            diff += e->out_codes[i] != e->bt_codes[i];
        st->bt_diff += diff;
        st->bt_samples += 3 * n;
        snprintf(line + len, sizeof line - (size_t)len, ", bit-true: %llu differ", diff);
    }
    if (!o->quiet) {
        if (r->prog.share)
            progress_clear(&r->prog);
        puts(line);
        fflush(stdout);
    }

    const int linear = (e->cfg.flags & BLOOM_FLAG_LINEAR) != 0;
    if (r->out) {
        if (sim_out_kind(r->out) == SIM_OUT_PFM)
            sim_codes_to_float(e->out_codes, e->out_max, n, linear, e->lin);
        else
            sim_codes_to_rgb8(e->out_codes, e->out_max, n, linear, e->rgb);
        if (sim_out_write(r->out, gi, f->w, f->h, e->rgb, e->lin, err, errlen))
            return -1;
    }
    if (r->sbs) {
        /* panels: input | fixed-point | float | |fixed - float| * gain */
        const size_t w = (size_t)f->w, row = 12 * w;
        uint8_t *panel = e->rgb; /* n*3 scratch */
        const uint32_t *codes[3] = {e->in_codes, e->out_codes, e->fl_codes};
        const int *maxes[3] = {e->in_max, e->out_max, e->out_max};
        for (int k = 0; k < 3; k++) {
            sim_codes_to_rgb8(codes[k], maxes[k], n, linear, panel);
            for (size_t y = 0; y < (size_t)f->h; y++)
                memcpy(e->sbs + y * row + (size_t)k * 3 * w, panel + y * 3 * w, 3 * w);
        }
        for (size_t y = 0; y < (size_t)f->h; y++)
            for (size_t i = 0; i < 3 * w; i++) {
                uint32_t a = e->out_codes[y * 3 * w + i], b = e->fl_codes[y * 3 * w + i];
                uint64_t d = (uint64_t)(a > b ? a - b : b - a) * (uint64_t)o->diff_gain;
                e->sbs[y * row + 9 * w + i] = (uint8_t)(d > 255 ? 255 : d);
            }
        if (sim_out_write(r->sbs, gi, 4 * f->w, f->h, e->sbs, NULL, err, errlen))
            return -1;
    }
    return 0;
}

static void print_summary(const run_t *r)
{
    const stats_t *st = &r->st;
    if (!st->frames)
        return;
    double *t = malloc((size_t)st->frames * sizeof *t), sum = 0, med;
    if (!t)
        return;
    memcpy(t, st->times, (size_t)st->frames * sizeof *t);
    qsort(t, (size_t)st->frames, sizeof *t, cmp_double);
    for (long i = 0; i < st->frames; i++)
        sum += t[i];
    med = st->frames % 2 ? t[st->frames / 2] : (t[st->frames / 2 - 1] + t[st->frames / 2]) / 2;
    printf("summary: %ld frame%s, preset %s, engine per frame: mean %.3f ms, median %.3f ms, min %.3f ms, "
           "max %.3f ms (%.1f Mpixel/s)\n",
           st->frames, st->frames == 1 ? "" : "s", bloom_preset_name(r->o->cfg.preset),
           1e3 * sum / (double)st->frames, 1e3 * med, 1e3 * t[0], 1e3 * t[st->frames - 1],
           sum > 0 ? st->pixels / sum / 1e6 : 0.0);
    free(t);
    if (r->o->compare && st->samples)
        printf("summary vs float model: peak %u LSB, exact %.3f%%, signed mean %+.5f LSB (%llu above, %llu "
               "below), "
               "mean |e| %.5f LSB, %llu samples\n",
               st->peak, 100.0 * (double)st->exact / (double)st->samples,
               st->err_signed / (double)st->samples, st->above, st->below, st->err_sum / (double)st->samples,
               st->samples);
    if (r->o->bittrue)
        printf("summary vs bit-true model: %llu of %llu samples differ\n", st->bt_diff, st->bt_samples);
}

/* The aux plane: --aux loaded (its depth decides BLOOM_AUX_U8/U16) and
 * checked against the preset, or, without --aux, the preset asked whether
 * it runs without one. *status is 1 for a file that cannot be used, 2 for
 * a command line that lacks the plane or gives one the preset does not read. */
static int aux_check(sim_opts_t *o, sim_aux_t *aux, char *err, size_t errlen, int *status)
{
    bloom_config_t t = o->cfg;
    bloom_info_t info;
    t.width = t.height = 16;
    if (!o->aux_path) {
        const char *what = sim_preset_aux_name(&t);
        t.aux_fmt = BLOOM_AUX_NONE;
        if (!what) /* the presets that read no plane refuse nothing here */
            what = "aux plane";
        bloom_status_t st = bloom_query(&t, &info);
        if (st == BLOOM_E_AUX) {
            *status = 2;
            return sim_errf(err, errlen,
                            "preset %s: %s (its %s: give it with --aux FILE, a grey PGM or "
                            "PNG of the frames' size)",
                            bloom_preset_name(t.preset), bloom_status_str(st), what);
        }
        o->cfg.aux_fmt = BLOOM_AUX_NONE; /* the plane is optional: run without it */
        return 0;
    }
    if (sim_aux_load(aux, o->aux_path, err, errlen)) {
        *status = 1;
        return -1;
    }
    t.aux_fmt = o->cfg.aux_fmt = aux->fmt;
    bloom_status_t st = bloom_query(&t, &info);
    if (st == BLOOM_E_AUX) {
        *status = 2;
        return sim_errf(err, errlen, "--aux: preset %s: %s", bloom_preset_name(t.preset),
                        bloom_status_str(st));
    }
    if (!o->quiet)
        printf("aux: %s: %s, %s\n", o->aux_path, aux->desc, sim_preset_aux_name(&o->cfg));
    return 0;
}

int main(int argc, char **argv)
{
    sim_opts_t o;
    int pr = sim_opts_parse(argc, argv, &o);
    if (pr) {
        free(o.inputs);
        return pr > 0 ? 0 : 2;
    }
    char err[SIM_ERRLEN];
    int rc = 1;
    run_t r;
    memset(&r, 0, sizeof r);
    r.o = &o;
    sim_frame_t frame;
    memset(&frame, 0, sizeof frame);
    sim_source_t **src = calloc((size_t)o.ninputs, sizeof *src);
    long total = 0;
    if (!src) {
        fputs("bloom_sim: out of memory\n", stderr);
        goto done;
    }
    if (aux_check(&o, &r.aux, err, sizeof err, &rc))
        goto fail;
    /* every input is opened (and Y4M/raw checked whole) before any output */
    for (int i = 0; i < o.ninputs; i++) {
        if (sim_source_open(&src[i], o.inputs[i], &o.in, err, sizeof err))
            goto fail;
        long nf = sim_source_frames(src[i]);
        total = total < 0 || nf < 0 ? -1 : total + nf;
    }
    if (o.max_frames && (total < 0 || total > o.max_frames))
        total = o.max_frames;
    int fn = o.fps_num, fd = o.fps_den;
    for (int i = 0; i < o.ninputs; i++)
        if (sim_source_fps(src[i], &fn, &fd) == 0)
            break;
    if (o.out_pattern && sim_out_open(&r.out, o.out_pattern, fn, fd, err, sizeof err))
        goto usage;
    if (o.sbs_pattern && sim_out_open(&r.sbs, o.sbs_pattern, fn, fd, err, sizeof err))
        goto usage;
    if (r.sbs && sim_out_kind(r.sbs) == SIM_OUT_PFM) {
        sim_errf(err, sizeof err, "--side-by-side writes .ppm, .png or .y4m (display images)");
        goto usage;
    }
    for (int k = 0; k < 2; k++) {
        sim_out_t *out = k ? r.sbs : r.out;
        if (out && !sim_out_has_number(out) && total > 1) {
            sim_errf(err, sizeof err,
                     "output '%s' names one file but the input has %ld frames: add a frame "
                     "number, e.g. out_%%04d.png",
                     sim_out_pattern(out), total);
            goto usage;
        }
    }
    r.prog.enabled = isatty(STDERR_FILENO);
    r.prog.share = isatty(STDOUT_FILENO);
    r.prog.start = now_s();
    r.prog.after = o.progress_after;
    r.prog.total = total;
    long gi = 0;
    for (int i = 0; i < o.ninputs && (!o.max_frames || gi < o.max_frames); i++) {
        for (int announced = 0;;) {
            if (o.max_frames && gi >= o.max_frames)
                break;
            int got = sim_source_read(src[i], &frame, err, sizeof err);
            if (got < 0) {
                if (o.ninputs > 1) {
                    size_t l = strlen(err);
                    snprintf(err + l, sizeof err - l, " (frame %ld of the sequence)", gi);
                }
                goto fail;
            }
            if (got == 0)
                break;
            /* one line per input; with -q none for each image of a list */
            if (!announced && !(o.quiet && o.ninputs > 1)) {
                if (r.prog.share)
                    progress_clear(&r.prog);
                printf("input: %s: %s\n", strcmp(o.inputs[i], "-") ? o.inputs[i] : "(stdin)",
                       sim_source_desc(src[i]));
            }
            announced = 1;
            if (do_frame(&r, &frame, gi, o.inputs[i], err, sizeof err))
                goto fail;
            gi++;
            progress_update(&r.prog, gi);
        }
    }
    progress_clear(&r.prog);
    for (int k = 0; k < 2; k++) {
        sim_out_t **out = k ? &r.sbs : &r.out;
        if (!*out)
            continue;
        char pat[1024];
        long cnt = sim_out_count(*out);
        snprintf(pat, sizeof pat, "%s", sim_out_pattern(*out));
        int fr = sim_out_finish(*out, err, sizeof err);
        *out = NULL;
        if (fr)
            goto fail;
        printf("wrote %s: %ld frame%s\n", pat, cnt, cnt == 1 ? "" : "s");
    }
    print_summary(&r);
    rc = 0;
    if (o.bittrue && r.st.bt_diff) {
        fprintf(stderr, "bloom_sim: the engine differs from the bit-true model in %llu samples\n",
                r.st.bt_diff);
        rc = 1;
    }
    goto done;
usage:
    rc = 2;
    /* fall through */
fail:
    progress_clear(&r.prog);
    if (rc != 2)
        rc = 1;
    fflush(stdout);
    fprintf(stderr, "bloom_sim: %s\n", err);
done:
    sim_out_abort(r.out);
    sim_out_abort(r.sbs);
    for (int i = 0; src && i < o.ninputs; i++)
        sim_source_close(src[i]);
    free(src);
    free(o.inputs);
    sim_frame_free(&frame);
    engine_free(&r.eng);
    sim_aux_free(&r.aux);
    free(r.st.times);
    return rc;
}
