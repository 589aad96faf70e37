/* bloom_sim command line: --help text and option parsing. */
#include "sim.h"

#include <stdlib.h>
#include <string.h>
#include <strings.h>

static const char usage_text[] =
    "usage: bloom_sim [options] INPUT...\n"
    "\n"
    "Runs recorded frames through the fixed-point bloom engine (bloom_process) and,\n"
    "with --compare, the float reference model side by side; prints the engine time\n"
    "per frame and the error against the model; writes the results.\n"
    "\n"
    "Inputs (format found from the content; several INPUTs form one sequence;\n"
    "frames are numbered from 0):\n"
    "  PPM/PGM 8-bit (P6/P5)    sRGB codes (maxval < 255: round(code * 255 / maxval))\n"
    "  PPM/PGM/PNG 16-bit       linear light: code/maxval, to RGBQ16 as\n"
    "                           round(code * 65536 / maxval); with --decode16 srgb the\n"
    "                           codes are sRGB-encoded: round(srgb_to_linear(code/maxval)*65536)\n"
    "  PFM (PF/Pf)              linear floats to RGBQ16: NaN and negative -> 0,\n"
    "                           >= 256 and +Inf -> 2^24-1 (255.99998), else round(v * 65536)\n"
    "  PNG 8-bit, JPEG          sRGB codes; palette expanded, alpha and colour chunks ignored\n"
    "  OpenEXR                  R, G, B (or Y) of part 0, half/float, as PFM floats\n"
    "  Y4M (YUV4MPEG2)          8-bit C420jpeg, C420paldv, C420mpeg2, C420, C422, C444, Cmono;\n"
    "                           BT.601 limited range (full with XCOLORRANGE=FULL) to RGB\n"
    "                           codes in integer arithmetic, chroma repeated (nearest);\n"
    "                           \"-\" reads a stream from standard input\n"
    "  raw V4L2 dump            needs --raw-size WxH and --raw-format yuyv|rgb24|grey|rgb565\n"
    "                           [--raw-stride BYTES]: frames back to back as v4l2-ctl\n"
    "                           --stream-to writes them; frames = file size / frame size.\n"
    "                           YUYV is BT.601 limited range, GREY full range (Y = R = G = B)\n"
    "  Grey images are replicated to R, G, B.\n"
    "\n"
    "Outputs:\n"
    "  -o, --output PATTERN     engine output per frame: name%04d.ppm, .png or .pfm (%d is the\n"
    "                           frame number), or name.y4m: one 4:2:0 stream (BT.601 limited)\n"
    "  --side-by-side PATTERN   input | fixed-point | float | |fixed - float| * gain, per\n"
    "                           frame (.ppm, .png or .y4m); implies --compare\n"
    "  --view final|bloom       the composite S + I*B (default) or the bloom-only view I*B\n"
    "  --diff-gain N            difference amplification of the side-by-side (default 64)\n"
    "  --fps N[:D]              Y4M output rate when the input has none (default 25)\n"
    "  PPM, PNG and Y4M show rgb565 output as round(code * 255 / max) and rgbq16 output\n"
    "  sRGB-encoded (linear with --linear), clipped at 1.0; PFM holds linear floats.\n"
    "\n"
    "Engine (as bloom_demo):\n"
    "  --levels N               pyramid levels, 1..16 (default 5)\n"
    "  --threshold T            0..256 (default 1.0)      --knee S    0..1 (default 0.5)\n"
    "  --intensity I            0..10 (default 1.0)       --linear    codes are linear light\n"
    "  --copy-source            BLOOM_FLAG_COPY_SOURCE (the engine copies its source rows)\n"
    "  --format F               engine input and output format: rgb888, xrgb8888, rgb565,\n"
    "                           rgbq16 (as your board's framebuffer or camera delivers them)\n"
    "  --in-format F, --out-format F   one side only. Defaults: input rgbq16 for HDR inputs\n"
    "                           (16-bit, PFM, OpenEXR), rgb565 for RGB565 dumps, rgb888\n"
    "                           otherwise; output rgb888. A forced conversion follows the\n"
    "                           engine's own rules: codes to rgbq16 decode to Q16.16, HDR\n"
    "                           to 8/5/6-bit codes encodes clipped at 1.0\n"
    "\n"
    "Checks:\n"
    "  --compare                also run the float model: per frame the peak and mean error\n"
    "                           in output LSB and the share of exact samples, and a summary\n"
    "  --bittrue                also run the bit-true model; any differing sample fails the run\n"
    "\n"
    "Run:\n"
    "  --frames N               at most N frames\n"
    "  --repeat N               run the engine N times per frame, report the fastest\n"
    "  -q, --quiet              no per-frame lines (the summary is still printed)\n"
    "  --progress-after S       on a terminal, show a progress line on stderr once the run\n"
    "                           has taken S seconds (default 1); quiet when not a terminal\n"
    "  -h, --help\n"
    "\n"
    "Exit status: 0 done; 1 a malformed or truncated input (the message names the file\n"
    "and the frame), an output that could not be written, an engine error or a bit-true\n"
    "mismatch; 2 a bad command line. Every output goes to a temp file renamed into\n"
    "place when complete (a Y4M stream at the end of the run), so a failed run never\n"
    "leaves a partial file in place of a good one; Y4M and raw files are checked whole\n"
    "before the first frame is processed. Details: sim/docs/simulator.md\n";

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
                 {"rgbp", SIM_RAW_RGB565}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcasecmp(s, names[i].name)) {
            *f = names[i].fmt;
            return 0;
        }
    return -1;
}

/* Options that take a value. */
static const char *const with_value[] = {
    "-o", "--output", "--side-by-side", "--view", "--diff-gain", "--fps", "--levels",
    "--threshold", "--knee", "--intensity", "--format", "--in-format", "--out-format",
    "--frames", "--repeat", "--progress-after", "--raw-size", "--raw-format", "--raw-stride",
    "--decode16"};

static int takes_value(const char *name)
{
    for (size_t i = 0; i < sizeof with_value / sizeof with_value[0]; i++)
        if (!strcmp(name, with_value[i]))
            return 1;
    return 0;
}

static int apply(sim_opts_t *o, const char *a, const char *v)
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
        o->cfg.levels = (int)n;
    } else if (!strcmp(a, "--threshold")) {
        if (parse_real_q16(v, 0, 256, &o->cfg.threshold))
            return bad(a, v);
    } else if (!strcmp(a, "--knee")) {
        if (parse_real_q16(v, 0, 1, &o->cfg.soft_knee))
            return bad(a, v);
    } else if (!strcmp(a, "--intensity")) {
        if (parse_real_q16(v, 0, 10, &o->cfg.intensity))
            return bad(a, v);
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
    } else if (!strcmp(a, "--repeat")) {
        if (parse_long(v, 1, 1000, &n))
            return bad(a, v);
        o->repeat = (int)n;
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
    } else if (!strcmp(a, "--decode16")) {
        if (strcmp(v, "linear") && strcmp(v, "srgb"))
            return bad(a, v);
        o->in.decode16_srgb = !strcmp(v, "srgb");
    } else {
        return bad(a, v);
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
    o->progress_after = 1.0;
    o->inputs = calloc((size_t)argc, sizeof *o->inputs);
    if (!o->inputs) {
        fprintf(stderr, "bloom_sim: out of memory\n");
        return -1;
    }
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
            fputs(usage_text, stdout);
            return 1;
        } else if (!strcmp(a, "--linear")) {
            o->cfg.flags |= BLOOM_FLAG_LINEAR;
        } else if (!strcmp(a, "--copy-source")) {
            o->cfg.flags |= BLOOM_FLAG_COPY_SOURCE;
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
            if (apply(o, name, v))
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
        o->cfg.flags |= BLOOM_FLAG_DEBUG_VIEW;
    return 0;
}
