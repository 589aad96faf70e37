/* bloom_sim command line: --help text and option parsing. */
#include "bloom_mt.h"
#include "sim.h"

#include <stdlib.h>
#include <string.h>
#include <strings.h>

static int bad(const char *opt, const char *val)
{
    fprintf(stderr, "bloom_sim: %s: bad value '%s' (see bloom_sim --help)\n", opt, val);
    return -1;
}

static int parse_real_q16(const char *s, double lo, double hi, uint32_t *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !(v >= lo && v <= hi))
        return -1;
    *out = (uint32_t)(v * 65536.0 + 0.5);
    return 0;
}

static int parse_long(const char *s, long lo, long hi, long *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (end == s || *end || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

static int parse_size(const char *s, int *w, int *h)
{
    char *end;
    long a = strtol(s, &end, 10), b;
    if (end == s || (*end != 'x' && *end != 'X'))
        return -1;
    const char *t = end + 1;
    b = strtol(t, &end, 10);
    if (end == t || *end || a < 1 || b < 1 || a > BLOOM_MAX_DIM || b > BLOOM_MAX_DIM)
        return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

static int parse_raw_fmt(const char *s, sim_raw_fmt_t *f)
{
    static const struct {
        const char *name;
        sim_raw_fmt_t fmt;
    } names[] = {{"yuyv", SIM_RAW_YUYV},   {"rgb24", SIM_RAW_RGB24}, {"rgb3", SIM_RAW_RGB24},
                 {"grey", SIM_RAW_GREY},   {"gray", SIM_RAW_GREY},   {"rgb565", SIM_RAW_RGB565},
                 {"rgbp", SIM_RAW_RGB565}, {"uyvy", SIM_RAW_UYVY},   {"yvyu", SIM_RAW_YVYU},
                 {"nv12", SIM_RAW_NV12},   {"nv21", SIM_RAW_NV21},   {"nv16", SIM_RAW_NV16},
                 {"nv61", SIM_RAW_NV61}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcasecmp(s, names[i].name)) {
            *f = names[i].fmt;
            return 0;
        }
    return -1;
}

/* Options that take a value. */
static const char *const with_value[] = {"-o",
                                         "--output",
                                         "--side-by-side",
                                         "--view",
                                         "--diff-gain",
                                         "--fps",
                                         "--levels",
                                         "--threshold",
                                         "--knee",
                                         "--intensity",
                                         "--format",
                                         "--in-format",
                                         "--out-format",
                                         "--frames",
                                         "--repeat",
                                         "--threads",
                                         "--progress-after",
                                         "--raw-size",
                                         "--raw-format",
                                         "--raw-stride",
                                         "--decode16",
                                         "--preset",
                                         "--strength",
                                         "--passes",
                                         "--attenuation",
                                         "--max-reduction",
                                         "--aux",
                                         "--tint",
                                         "--weights",
                                         "--radius",
                                         "--raw-ycbcr",
                                         "--sample-bits"};

static int takes_value(const char *name)
{
    for (size_t i = 0; i < sizeof with_value / sizeof with_value[0]; i++)
        if (!strcmp(name, with_value[i]))
            return 1;
    return 0;
}

/* The options given, applied over the preset's defaults at the end; a
 * preset parameter's bit is its BLOOM_PARAM_* bit. */
enum {
    SET_STRENGTH = BLOOM_PARAM_STRENGTH,
    SET_PASSES = BLOOM_PARAM_PASSES,
    SET_ATTENUATION = BLOOM_PARAM_ATTENUATION,
    SET_MAX_REDUCTION = BLOOM_PARAM_MAX_REDUCTION,
    SET_TINT = BLOOM_PARAM_TINT,
    SET_WEIGHTS = BLOOM_PARAM_WEIGHTS,
    SET_RADIUS = BLOOM_PARAM_RADIUS,
    SET_SATURATE = BLOOM_PARAM_SATURATE,
    SET_ADDITIVE = BLOOM_PARAM_ADDITIVE,
    SET_BAKED = BLOOM_PARAM_BAKED,
    SET_KEEP_LEVELS = BLOOM_PARAM_KEEP_LEVELS,
    SET_AUX = BLOOM_PARAM_AUX,
    SET_LEVELS = 1u << 16,
    SET_THRESHOLD = 1u << 17,
    SET_KNEE = 1u << 18,
    SET_INTENSITY = 1u << 19,
    SET_SAMPLE_BITS = 1u << 20
};

typedef sim_given_t given_t;

/* The option of each preset parameter; the presets that do not read it
 * (bloom_preset_params: the fields of bloom_preset_params_t, the preset
 * flags, the aux plane) refuse it by name. */
static const struct {
    unsigned bit;
    const char *opt;
} param_opt[] = {
    {SET_STRENGTH, "--strength"},
    {SET_PASSES, "--passes"},
    {SET_SATURATE, "--saturate"},
    {SET_ATTENUATION, "--attenuation"},
    {SET_MAX_REDUCTION, "--max-reduction"},
    {SET_AUX, "--aux"},
    {SET_TINT, "--tint"},
    {SET_WEIGHTS, "--weights"},
    {SET_ADDITIVE, "--additive"},
    {SET_BAKED, "--baked"},
    {SET_RADIUS, "--radius"},
    {SET_KEEP_LEVELS, "--keep-levels"},
};

const char *sim_presets_available(void)
{
    static char list[128];
    size_t len = 0;
    list[0] = '\0';
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++)
        if (bloom_preset_available((bloom_preset_t)p))
            len += (size_t)snprintf(list + len, sizeof list - len, "%s%s", len ? ", " : "",
                                    bloom_preset_name((bloom_preset_t)p));
    return list;
}

const char *sim_preset_aux_name(const bloom_config_t *c)
{
    switch (c->preset) {
    case BLOOM_PRESET_ATTENUATION:
        return "depth plane";
    case BLOOM_PRESET_ARM:
        return (c->flags & BLOOM_FLAG_BAKED) ? "baked bloom map" : "mask";
    default:
        return c->aux_fmt != BLOOM_AUX_NONE ? "aux plane" : NULL;
    }
}

/* "a,b,c": n values in lo..hi to Q16.16; returns the count, or -1. */
static int parse_list_q16(const char *s, double lo, double hi, uint32_t *out, int max)
{
    int n = 0;
    for (;;) {
        char *end;
        double v = strtod(s, &end);
        if (end == s || n == max || !(v >= lo && v <= hi) || (*end && *end != ','))
            return -1;
        out[n++] = (uint32_t)(v * 65536.0 + 0.5);
        if (!*end)
            return n;
        s = end + 1;
    }
}

static int apply(sim_opts_t *o, given_t *g, const char *a, const char *v)
{
    long n;
    if (!strcmp(a, "-o") || !strcmp(a, "--output"))
        o->out_pattern = v;
    else if (!strcmp(a, "--side-by-side"))
        o->sbs_pattern = v;
    else if (!strcmp(a, "--view")) {
        if (strcmp(v, "final") && strcmp(v, "bloom"))
            return bad(a, v);
        o->view_bloom = !strcmp(v, "bloom");
    } else if (!strcmp(a, "--diff-gain")) {
        if (parse_long(v, 1, 65535, &n))
            return bad(a, v);
        o->diff_gain = (int)n;
    } else if (!strcmp(a, "--fps")) {
        char *end;
        long num = strtol(v, &end, 10), den = 1;
        if (*end == ':')
            den = strtol(end + 1, &end, 10);
        if (end == v || *end || num < 1 || den < 1 || num > 1000000000L || den > 1000000000L)
            return bad(a, v);
        o->fps_num = (int)num;
        o->fps_den = (int)den;
    } else if (!strcmp(a, "--levels")) {
        if (parse_long(v, 1, BLOOM_MAX_LEVELS, &n))
            return bad(a, v);
        g->v.levels = (int)n;
        g->set |= SET_LEVELS;
    } else if (!strcmp(a, "--sample-bits")) {
        if (parse_long(v, 16, 32, &n) || (n != 16 && n != 32))
            return bad(a, v);
        g->v.sample_bits = (int)n;
        g->set |= SET_SAMPLE_BITS;
    } else if (!strcmp(a, "--threshold")) {
        if (parse_real_q16(v, 0, 256, &g->v.threshold))
            return bad(a, v);
        g->set |= SET_THRESHOLD;
    } else if (!strcmp(a, "--knee")) {
        if (parse_real_q16(v, 0, 1, &g->v.soft_knee))
            return bad(a, v);
        g->set |= SET_KNEE;
    } else if (!strcmp(a, "--intensity")) {
        if (parse_real_q16(v, 0, 10, &g->v.intensity))
            return bad(a, v);
        g->set |= SET_INTENSITY;
    } else if (!strcmp(a, "--preset")) {
        g->preset = bloom_preset_from_name(v);
        if (g->preset < 0) {
            fprintf(stderr, "bloom_sim: --preset: unknown preset '%s' (this build has: %s)\n", v,
                    sim_presets_available());
            return -1;
        }
        if (!bloom_preset_available((bloom_preset_t)g->preset)) {
            char up[32];
            size_t k = 0;
            for (const char *q = bloom_preset_name((bloom_preset_t)g->preset); *q && k + 1 < sizeof up; q++)
                up[k++] = (char)(*q >= 'a' && *q <= 'z' ? *q - 'a' + 'A' : *q);
            up[k] = '\0';
            fprintf(stderr,
                    "bloom_sim: --preset: '%s' is compiled out of this build (BLOOM_USE_%s=0 in "
                    "include/bloom_config.h); this build has: %s\n",
                    v, up, sim_presets_available());
            return -1;
        }
    } else if (!strcmp(a, "--strength")) {
        if (parse_real_q16(v, 0, 16, &g->v.p.strength))
            return bad(a, v);
        g->set |= SET_STRENGTH;
    } else if (!strcmp(a, "--passes")) {
        if (parse_long(v, 1, 8, &n))
            return bad(a, v);
        g->v.p.passes = (int)n;
        g->set |= SET_PASSES;
    } else if (!strcmp(a, "--attenuation")) {
        if (parse_real_q16(v, 0, 1, &g->v.p.attenuation))
            return bad(a, v);
        g->set |= SET_ATTENUATION;
    } else if (!strcmp(a, "--max-reduction")) {
        if (parse_real_q16(v, 0, 1, &g->v.p.max_reduction))
            return bad(a, v);
        g->set |= SET_MAX_REDUCTION;
    } else if (!strcmp(a, "--aux")) {
        o->aux_path = v;
        g->set |= SET_AUX;
    } else if (!strcmp(a, "--tint")) {
        if (parse_list_q16(v, 0, 1, g->v.p.tint, 3) != 3)
            return bad(a, v);
        g->set |= SET_TINT;
    } else if (!strcmp(a, "--weights")) {
        g->nweights = parse_list_q16(v, 0, 1, g->v.p.level_weight, BLOOM_MAX_LEVELS);
        if (g->nweights < 1)
            return bad(a, v);
        g->set |= SET_WEIGHTS;
    } else if (!strcmp(a, "--radius")) {
        if (parse_long(v, 1, 1L << 20, &g->radius))
            return bad(a, v);
        g->set |= SET_RADIUS;
    } else if (!strcmp(a, "--format") || !strcmp(a, "--in-format") || !strcmp(a, "--out-format")) {
        bloom_format_t f;
        if (sim_fmt_parse(v, &f))
            return bad(a, v);
        if (strcmp(a, "--out-format")) {
            o->in_fmt = f;
            o->in_fmt_set = 1;
        }
        if (strcmp(a, "--in-format")) {
            o->out_fmt = f;
            o->out_fmt_set = 1;
        }
    } else if (!strcmp(a, "--frames")) {
        if (parse_long(v, 1, 1000000000L, &o->max_frames))
            return bad(a, v);
    } else if (!strcmp(a, "--repeat") || !strcmp(a, "--threads")) {
        const int thr = a[2] == 't'; /* --threads 0: the online CPUs (port/threads) */
        if (parse_long(v, thr ? 0 : 1, thr ? BLOOM_MT_MAX_THREADS : 1000, &n))
            return bad(a, v);
        *(thr ? &o->threads : &o->repeat) = thr && n == 0 ? bloom_mt_cpus() : (int)n;
    } else if (!strcmp(a, "--progress-after")) {
        char *end;
        o->progress_after = strtod(v, &end);
        if (end == v || *end || !(o->progress_after >= 0 && o->progress_after < 1e6))
            return bad(a, v);
    } else if (!strcmp(a, "--raw-size")) {
        if (parse_size(v, &o->in.raw_w, &o->in.raw_h))
            return bad(a, v);
    } else if (!strcmp(a, "--raw-format")) {
        if (parse_raw_fmt(v, &o->in.raw_fmt))
            return bad(a, v);
    } else if (!strcmp(a, "--raw-stride")) {
        if (parse_long(v, 1, 1L << 20, &o->in.raw_stride))
            return bad(a, v);
    } else if (!strcmp(a, "--raw-ycbcr")) { /* bt601|bt709, -limited (the default) or -full */
        const int m = !strncmp(v, "bt601", 5) ? 0 : !strncmp(v, "bt709", 5) ? SIM_YCC_709 : -1;
        if (m < 0 || (v[5] && strcmp(v + 5, "-limited") && strcmp(v + 5, "-full")))
            return bad(a, v);
        o->in.raw_ycc = m | (!strcmp(v + 5, "-full") ? SIM_YCC_FULL : 0);
    } else if (!strcmp(a, "--decode16")) {
        if (strcmp(v, "linear") && strcmp(v, "srgb"))
            return bad(a, v);
        o->in.decode16_srgb = !strcmp(v, "srgb");
    } else {
        return bad(a, v);
    }
    return 0;
}

/* The configuration: the preset's defaults (bloom_config_preset), then
 * every option given. */
/* The preset's defaults for a w x h frame, then every option given. */
static int config_for(const given_t *g, int w, int h, bloom_config_t *c, char *err, size_t errlen)
{
    const bloom_preset_t p = g->preset < 0 ? BLOOM_PRESET_UNITY : (bloom_preset_t)g->preset;
    bloom_config_default(c, w, h);
    c->flags = g->flags;
    if (g->set & SET_LEVELS) /* before the preset: cod's default weights follow the depth */
        c->levels = g->v.levels;
#if BLOOM_USE_COD
    if (g->set & SET_RADIUS) {
        const int l = bloom_levels_for_radius((int)g->radius);
        if (l < 1 || l > BLOOM_MAX_LEVELS)
            return sim_errf(err, errlen, "--radius %ld: no level count reaches it", g->radius);
        c->levels = l;
    }
#endif
    bloom_status_t st = bloom_config_preset(c, p);
    if (st != BLOOM_OK)
        return sim_errf(err, errlen, "--preset %s: %s (this build has: %s)", bloom_preset_name(p),
                        bloom_status_str(st), sim_presets_available());
    if (g->set & SET_SAMPLE_BITS)
        c->sample_bits = g->v.sample_bits;
    if (g->set & SET_THRESHOLD)
        c->threshold = g->v.threshold;
    if (g->set & SET_KNEE)
        c->soft_knee = g->v.soft_knee;
    if (g->set & SET_INTENSITY)
        c->intensity = g->v.intensity;
    if (g->set & SET_STRENGTH)
        c->p.strength = g->v.p.strength;
    if (g->set & SET_PASSES)
        c->p.passes = g->v.p.passes;
    if (g->set & SET_ATTENUATION)
        c->p.attenuation = g->v.p.attenuation;
    if (g->set & SET_MAX_REDUCTION)
        c->p.max_reduction = g->v.p.max_reduction;
    if (g->set & SET_TINT)
        memcpy(c->p.tint, g->v.p.tint, sizeof c->p.tint);
    for (int k = 0; k < g->nweights; k++)
        c->p.level_weight[k] = g->v.p.level_weight[k];
    if (g->set & SET_SATURATE)
        c->flags |= BLOOM_FLAG_SATURATE;
    if (g->set & SET_ADDITIVE)
        c->flags |= BLOOM_FLAG_ADDITIVE;
    if (g->set & SET_BAKED)
        c->flags |= BLOOM_FLAG_BAKED;
    if (g->set & SET_KEEP_LEVELS)
        c->flags |= BLOOM_FLAG_KEEP_LEVELS;
    return 0;
}

int sim_opts_config(const sim_opts_t *o, int w, int h, bloom_config_t *c, char *err, size_t errlen)
{
    if (config_for(&o->given, w, h, c, err, errlen))
        return -1;
    c->aux_fmt = o->cfg.aux_fmt; /* the preset's, or the --aux file's (main decides) */
    return 0;
}

/* Checks what can be checked without a frame, and builds o->cfg for a
 * 1x1 frame (the preset, its flags and aux plane; per-frame sizes come
 * from sim_opts_config). */
static int build_config(sim_opts_t *o)
{
    const given_t *g = &o->given;
    const bloom_preset_t p = g->preset < 0 ? BLOOM_PRESET_UNITY : (bloom_preset_t)g->preset;
    const char *pn = bloom_preset_name(p);
    for (size_t i = 0; i < sizeof param_opt / sizeof param_opt[0]; i++)
        if ((g->set & param_opt[i].bit) && !(bloom_preset_params(p) & param_opt[i].bit)) {
            char who[64] = "";
            size_t len = 0;
            for (int q = 0; q < BLOOM_PRESET_COUNT; q++)
                if (bloom_preset_params((bloom_preset_t)q) & param_opt[i].bit)
                    len += (size_t)snprintf(who + len, sizeof who - len, "%s%s", len ? " or " : "",
                                            bloom_preset_name((bloom_preset_t)q));
            fprintf(stderr, "bloom_sim: %s applies to the %s preset, not %s (give --preset)\n",
                    param_opt[i].opt, who, pn);
            return -1;
        }
    if ((g->set & SET_RADIUS) && (g->set & SET_LEVELS)) {
        fputs("bloom_sim: --radius chooses the level count: give --radius or --levels, not both\n", stderr);
        return -1;
    }
    char err[SIM_ERRLEN];
    if (config_for(g, 1, 1, &o->cfg, err, sizeof err)) {
        fprintf(stderr, "bloom_sim: %s\n", err);
        return -1;
    }
    return 0;
}

int sim_opts_parse(int argc, char **argv, sim_opts_t *o)
{
    memset(o, 0, sizeof *o);
    bloom_config_default(&o->cfg, 1, 1);
    o->diff_gain = 64;
    o->fps_num = 25;
    o->fps_den = 1;
    o->repeat = 1;
    o->threads = bloom_mt_cpus();
    o->progress_after = 1.0;
    o->inputs = calloc((size_t)argc, sizeof *o->inputs);
    if (!o->inputs) {
        fprintf(stderr, "bloom_sim: out of memory\n");
        return -1;
    }
    given_t *g = &o->given;
    g->preset = -1;
    int only_inputs = 0;
    for (int i = 1; i < argc; i++) {
        char *a = argv[i];
        if (only_inputs || a[0] != '-' || !strcmp(a, "-")) {
            o->inputs[o->ninputs++] = a;
            continue;
        }
        if (!strcmp(a, "--")) {
            only_inputs = 1;
        } else if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            sim_usage(stdout);
            return 1;
        } else if (!strcmp(a, "--linear")) {
            g->flags |= BLOOM_FLAG_LINEAR;
        } else if (!strcmp(a, "--copy-source")) {
            g->flags |= BLOOM_FLAG_COPY_SOURCE;
        } else if (!strcmp(a, "--saturate")) {
            g->set |= SET_SATURATE;
        } else if (!strcmp(a, "--additive")) {
            g->set |= SET_ADDITIVE;
        } else if (!strcmp(a, "--baked")) {
            g->set |= SET_BAKED;
        } else if (!strcmp(a, "--keep-levels")) {
            g->set |= SET_KEEP_LEVELS;
        } else if (!strcmp(a, "--compare")) {
            o->compare = 1;
        } else if (!strcmp(a, "--bittrue")) {
            o->bittrue = 1;
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            o->quiet = 1;
        } else {
            char name[64];
            const char *eq = strchr(a, '='), *v;
            size_t nl = eq ? (size_t)(eq - a) : strlen(a);
            snprintf(name, sizeof name, "%.*s", (int)(nl < sizeof name ? nl : sizeof name - 1), a);
            if (!takes_value(name)) {
                fprintf(stderr, "bloom_sim: unknown option %s (see bloom_sim --help)\n", a);
                return -1;
            }
            if (eq) {
                v = eq + 1;
            } else if (i + 1 < argc) {
                v = argv[++i];
            } else {
                fprintf(stderr, "bloom_sim: %s needs a value (see bloom_sim --help)\n", a);
                return -1;
            }
            if (apply(o, g, name, v))
                return -1;
        }
    }
    if (o->ninputs == 0) {
        fputs("bloom_sim: no input (see bloom_sim --help)\n", stderr);
        return -1;
    }
    if ((o->in.raw_fmt != SIM_RAW_NONE) != (o->in.raw_w > 0)) {
        fputs("bloom_sim: a raw dump needs both --raw-size WxH and --raw-format FMT\n", stderr);
        return -1;
    }
    if (o->in.raw_stride && o->in.raw_fmt == SIM_RAW_NONE) {
        fputs("bloom_sim: --raw-stride applies to raw dumps only\n", stderr);
        return -1;
    }
    if (o->sbs_pattern)
        o->compare = 1;
    if (o->view_bloom)
        g->flags |= BLOOM_FLAG_DEBUG_VIEW;
    return build_config(o);
}
