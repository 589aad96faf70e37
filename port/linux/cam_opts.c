/* bloom_cam: command line, in the style of v4l2-ctl (--opt VALUE or
 * --opt=VALUE). Pure: no device is touched here. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "bloom_mt.h"
#include "cam.h"

void cam_usage(void *stream)
{
    fputs("usage: bloom_cam [options]\n"
          "  --device DEV          V4L2 capture device (default /dev/video0)\n"
          "  --display D           drm | fbdev | auto (default auto: the fbdev when --fb is\n"
          "                        given, else DRM when a /dev/dri/card* has a connected\n"
          "                        connector, else the fbdev)\n"
          "  --drm-card CARD       the DRM device (default: the first with a connected connector)\n"
          "  --drm-mode WxH        the mode to set (default: the connector's preferred mode)\n"
          "  --drm-format F        auto | xrgb8888 | rgb565 (auto: XRGB8888 if the plane takes it)\n"
          "  --fb FB               framebuffer (default /dev/fb0); 'none' draws off-screen\n"
          "  --vt TTY|off          the console's VT, kept in graphics mode while drawing so\n"
          "                        that its text does not draw over the video (default\n"
          "                        /dev/tty0, the VT in front; off: left alone)\n"
          "  --size WxH            capture size asked of the driver (default 640x480)\n"
          "  --format F            auto (default): the best the device offers for --size and\n"
          "                        --fps (README, formats); or one of rgb24 yuyv uyvy yvyu\n"
          "                        nv16 nv61 nv12 nv21 rgb565 grey, nv12m nv21m nv16m nv61m,\n"
          "                        mjpeg jpeg (decoded by libjpeg)\n"
          "  --fps N               frame rate asked of the driver (VIDIOC_S_PARM), 1..1000\n"
          "  --levels N            pyramid levels, 1..16 (default 5)\n"
          "  --sample-bits B       pyramid samples, 32 (default) or 16: unity, attenuation,\n"
          "                        xna and arm, 0.7-0.85x the engine's memory\n"
          "  --threshold T         0..256 (default 1.0)\n"
          "  --knee S              0..1 (default 0.5)\n"
          "  --intensity I         0..10 (default 1.0)\n"
          "  --preset NAME         unity (default), gamedev, xna, attenuation, arm, cod; the\n"
          "                        preset's defaults (those above are unity's), then the\n"
          "                        options given, in any order\n"
          "  --strength S          gamedev, arm --baked: 0..16\n"
          "  --passes P            xna: Kawase passes, 1..8     --saturate  xna: clamp at 1.0\n"
          "  --attenuation A       attenuation: a, 0..1         --max-reduction R  r, 0..1\n"
          "  --aux FILE            the preset's one-channel plane, read once: attenuation's\n"
          "                        depth, arm's mask or --baked map; an 8- or 16-bit binary\n"
          "                        PGM of the capture size\n"
          "  --tint R,G,B          cod, arm: glow colour, each 0..1\n"
          "  --weights c0,c1,...   cod: level weights, each 0..1   --additive  cod: additive\n"
          "  --baked               arm: the baked bloom map (--aux) instead of the pyramid\n"
          "  --radius PX           cod: levels for a glow of about PX pixels (not --levels)\n"
          "  --mode M              bloom | off | bloom-only: what to show first (default bloom)\n"
          "  --frames N            stop after N frames (default: until a stop signal:\n"
          "                        INT, TERM, HUP, QUIT, or PIPE from --record\n"
          "  --buffers N           capture buffers, 2..16 (default 4)\n"
          "  --timeout MS          longest wait for a frame (default 2000): then the device\n"
          "                        counts as lost\n"
          "  --reconnect S|off     a lost device (stalled, unplugged, failing) is closed and\n"
          "                        opened again, backing off, for up to S seconds\n"
          "                        (default 30); off: a lost device ends the run\n"
          "  --latest on|off       show the newest frame ready, skipping older ones\n"
          "                        (default on: latency stays one frame)\n"
          "  --debounce MS         presses of --gpio-button closer than MS count once\n"
          "                        (default 30; 0: every falling edge)\n"
          "  --threads N           N strips of each frame on N threads, 0..64 (0, default: the\n"
          "                        online CPUs); 1: row by row as the camera delivers them\n"
          "                        (lowest latency and memory); more: whole frames, the same\n"
          "                        bytes on the screen, an RGB888 frame more for YUYV and GREY\n"
          "  --gpio-frame CHIP:LINE   output held high while a frame is processed\n"
          "  --gpio-button CHIP:LINE  input (pull-up, active low): each press cycles the mode\n"
          "  --stats               fps, dropped frames, processing time per frame\n"
          "  --record FILE         write the captured frames as v4l2-ctl --stream-to does\n"
          "  --dump-fb FILE        write the last frame as drawn in the framebuffer\n"
          "  -q                    no progress messages\n"
          "  -h, --help            this text\n"
          "CHIP is a gpiochip name, number, path or label; LINE an offset or line name.\n",
          (FILE *)stream);
}

const char *cam_format_name(enum cam_pixfmt f)
{
    const cam_fmt_t *t = cam_fmt_of_opt(f);
    return f == CAM_FMT_AUTO ? "auto" : t ? t->name : "?";
}

const char *cam_mode_name(enum cam_mode m)
{
    switch (m) {
    case CAM_MODE_BLOOM:
        return "bloom";
    case CAM_MODE_OFF:
        return "off";
    case CAM_MODE_BLOOM_ONLY:
        return "bloom-only";
    case CAM_MODE_COUNT:
        break;
    }
    return "?";
}

int cam_errf(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
    return -1;
}

static int parse_long(const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

static int parse_q16(const char *s, double lo, double hi, uint32_t *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || !(v >= lo && v <= hi))
        return -1;
    *out = BLOOM_Q16(v);
    return 0;
}

static int parse_size(const char *s, int *w, int *h)
{
    char *end;
    errno = 0;
    long a = strtol(s, &end, 10);
    if (errno || end == s || (*end != 'x' && *end != 'X'))
        return -1;
    const char *t = end + 1;
    long b = strtol(t, &end, 10);
    if (errno || end == t || *end || a < 2 || b < 1 || a > BLOOM_MAX_DIM || b > BLOOM_MAX_DIM)
        return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

static int parse_gpio(const char *s, cam_gpio_spec_t *g)
{
    const char *colon = strrchr(s, ':');
    if (!colon || colon == s || !colon[1])
        return -1;
    size_t n = (size_t)(colon - s);
    if (n >= sizeof g->chip || strlen(colon + 1) >= sizeof g->line)
        return -1;
    memcpy(g->chip, s, n);
    g->chip[n] = '\0';
    strcpy(g->line, colon + 1);
    g->set = 1;
    return 0;
}

static const char *const with_value[] = {
    "--device",    "--fb",      "--size",    "--format",      "--levels",  "--threshold",   "--knee",
    "--intensity", "--mode",    "--frames",  "--buffers",     "--timeout", "--gpio-frame",  "--gpio-button",
    "--record",    "--dump-fb", "--preset",  "--strength",    "--passes",  "--attenuation", "--max-reduction",
    "--aux",       "--tint",    "--weights", "--radius",      "--threads", "--reconnect",   "--latest",
    "--debounce",  "--fps",     "--vt",      "--sample-bits", NULL};

/* The display's options (drm_pick.c), apart from the table above. */
static const char *const display_value[] = {"--display", "--drm-card", "--drm-mode", "--drm-format", NULL};

/* "a,b,c": up to max values in 0..1 to Q16.16; the count, or -1. */
static int parse_list01(const char *s, uint32_t *out, int max)
{
    int n = 0;
    for (;;) {
        char *end;
        errno = 0;
        double v = strtod(s, &end);
        if (errno || end == s || n == max || !(v >= 0 && v <= 1) || (*end && *end != ','))
            return -1;
        out[n++] = BLOOM_Q16(v);
        if (!*end)
            return n;
        s = end + 1;
    }
}

/* The options given, applied over the preset's defaults at the end; a
 * preset parameter's bit is its BLOOM_PARAM_* bit. */
enum {
    G_STRENGTH = BLOOM_PARAM_STRENGTH,
    G_PASSES = BLOOM_PARAM_PASSES,
    G_SATURATE = BLOOM_PARAM_SATURATE,
    G_ATTENUATION = BLOOM_PARAM_ATTENUATION,
    G_MAX_REDUCTION = BLOOM_PARAM_MAX_REDUCTION,
    G_AUX = BLOOM_PARAM_AUX,
    G_TINT = BLOOM_PARAM_TINT,
    G_WEIGHTS = BLOOM_PARAM_WEIGHTS,
    G_ADDITIVE = BLOOM_PARAM_ADDITIVE,
    G_BAKED = BLOOM_PARAM_BAKED,
    G_RADIUS = BLOOM_PARAM_RADIUS,
    G_LEVELS = 1u << 16,
    G_THRESHOLD = 1u << 17,
    G_KNEE = 1u << 18,
    G_INTENSITY = 1u << 19
};
/* The option of each preset parameter; the presets that do not read it
 * (bloom_preset_params) refuse it by name. */
static const struct {
    unsigned bit;
    const char *opt;
} param_opt[] = {
    {G_STRENGTH, "--strength"},
    {G_PASSES, "--passes"},
    {G_SATURATE, "--saturate"},
    {G_ATTENUATION, "--attenuation"},
    {G_MAX_REDUCTION, "--max-reduction"},
    {G_AUX, "--aux"},
    {G_TINT, "--tint"},
    {G_WEIGHTS, "--weights"},
    {G_ADDITIVE, "--additive"},
    {G_BAKED, "--baked"},
    {G_RADIUS, "--radius"},
};

/* "unity, attenuation": the presets this build carries. */
static void available(char *buf, size_t len)
{
    size_t n = 0;
    buf[0] = '\0';
    for (int p = 0; p < BLOOM_PRESET_COUNT && n < len; p++)
        if (bloom_preset_available((bloom_preset_t)p))
            n += (size_t)snprintf(buf + n, len - n, "%s%s", n ? ", " : "",
                                  bloom_preset_name((bloom_preset_t)p));
}

/* The preset parameters given over p (the preset's defaults). */
static void given_params(const cam_opts_t *o, bloom_preset_params_t *p)
{
    const bloom_preset_params_t *g = &o->given_params;
    if (o->given_mask & CAM_P_STRENGTH)
        p->strength = g->strength;
    if (o->given_mask & CAM_P_PASSES)
        p->passes = g->passes;
    if (o->given_mask & CAM_P_ATTENUATION)
        p->attenuation = g->attenuation;
    if (o->given_mask & CAM_P_MAX_REDUCTION)
        p->max_reduction = g->max_reduction;
    if (o->given_mask & CAM_P_TINT)
        memcpy(p->tint, g->tint, sizeof p->tint);
    for (int k = 0; k < o->given_weights; k++)
        p->level_weight[k] = g->level_weight[k];
}

void cam_opts_config(const cam_opts_t *o, int w, int h, bloom_config_t *cfg)
{
    bloom_config_default(cfg, w, h);
    cfg->levels = o->levels; /* before the preset: cod's default weights follow the depth */
    bloom_config_preset(cfg, o->preset);
    cfg->threshold = o->threshold;
    cfg->soft_knee = o->knee;
    cfg->intensity = o->intensity;
    given_params(o, &cfg->p);
    cfg->flags |= o->preset_flags;
    cfg->aux_fmt = o->aux_fmt;
    cfg->sample_bits = o->sample_bits;
}

int cam_parse_opts(cam_opts_t *o, int argc, char **argv, char *err, size_t errlen)
{
    bloom_config_t d;
    bloom_config_default(&d, 2, 2);
    memset(o, 0, sizeof *o);
    o->device = "/dev/video0";
    o->fb = "/dev/fb0";
    o->vt = "/dev/tty0";
    o->width = 640;
    o->height = 480;
    o->format = CAM_FMT_AUTO;
    o->levels = d.levels;
    o->sample_bits = 32;
    o->threshold = d.threshold;
    o->knee = d.soft_knee;
    o->intensity = d.intensity;
    o->buffers = 4;
    o->timeout_ms = 2000;
    o->reconnect_s = 30;
    o->latest = 1;
    o->debounce_ms = 30;
    o->mode = CAM_MODE_BLOOM;
    o->preset = BLOOM_PRESET_UNITY;
    unsigned given = 0;
    int nweights = 0;
    long radius = 0;
    bloom_config_t gv; /* values given */
    memset(&gv, 0, sizeof gv);
    int drm_given = 0;

    for (int i = 1; i < argc; i++) {
        char name[32];
        const char *a = argv[i], *v = NULL;
        const char *eq = strchr(a, '=');
        if (!strcmp(a, "-h") || !strcmp(a, "--help"))
            return 1;
        if (!strcmp(a, "-q")) {
            o->quiet = 1;
            continue;
        }
        if (!strcmp(a, "--stats")) {
            o->stats = 1;
            continue;
        }
        if (!strcmp(a, "--saturate") || !strcmp(a, "--additive") || !strcmp(a, "--baked")) {
            given |= a[2] == 's' ? G_SATURATE : a[2] == 'a' ? G_ADDITIVE : G_BAKED;
            continue;
        }
        size_t n = eq ? (size_t)(eq - a) : strlen(a);
        if (n >= sizeof name)
            return cam_errf(err, errlen, "unknown option '%s'", a);
        memcpy(name, a, n);
        name[n] = '\0';
        int known = 0;
        for (int k = 0; with_value[k]; k++)
            known |= !strcmp(name, with_value[k]);
        for (int k = 0; display_value[k]; k++)
            known |= !strcmp(name, display_value[k]);
        if (!known)
            return cam_errf(err, errlen, "unknown option '%s'", a);
        if (eq)
            v = eq + 1;
        else if (i + 1 < argc)
            v = argv[++i];
        else
            return cam_errf(err, errlen, "%s needs a value", name);

        long l;
        const int dr = cam_display_opt(o, name, v, err, errlen, &drm_given);
        if (dr < 0)
            return -1;
        if (dr)
            continue;
        if (!strcmp(name, "--device")) {
            o->device = v;
        } else if (!strcmp(name, "--fb")) {
            o->fb = v;
            o->fb_given = 1;
        } else if (!strcmp(name, "--size")) {
            if (parse_size(v, &o->width, &o->height))
                return cam_errf(err, errlen, "--size: '%s' is not WxH (2..16384 x 1..16384)", v);
        } else if (!strcmp(name, "--format")) {
            int f = !strcasecmp(v, "auto") ? CAM_FMT_AUTO : !strcasecmp(v, "gray") ? CAM_FMT_GREY : -1;
            for (int k = 1; f < 0 && k < CAM_FMT_COUNT; k++) { /* a name, or its fourcc ("RGB3") */
                const uint32_t cc = cam_fmt_of_opt((enum cam_pixfmt)k)->fourcc;
                const char s4[5] = {(char)cc, (char)(cc >> 8), (char)(cc >> 16), (char)(cc >> 24), 0};
                if (!strcasecmp(v, cam_format_name((enum cam_pixfmt)k)) || !strcmp(v, s4))
                    f = k;
            }
            if (f < 0)
                return cam_errf(
                    err, errlen,
                    "--format: '%s' is not auto, rgb24, yuyv, uyvy, yvyu, nv16, nv61, nv12, nv21, "
                    "rgb565, grey, nv12m, nv21m, nv16m, nv61m, mjpeg or jpeg",
                    v);
            o->format = (enum cam_pixfmt)f;
        } else if (!strcmp(name, "--fps")) {
            if (parse_long(v, 1, 1000, &l))
                return cam_errf(err, errlen, "--fps: '%s' is not 1..1000", v);
            o->fps = (int)l;
        } else if (!strcmp(name, "--sample-bits")) {
            if (parse_long(v, 16, 32, &l) || (l != 16 && l != 32))
                return cam_errf(err, errlen, "--sample-bits: '%s' is not 16 or 32", v);
            o->sample_bits = (int)l;
        } else if (!strcmp(name, "--levels")) {
            if (parse_long(v, 1, BLOOM_MAX_LEVELS, &l))
                return cam_errf(err, errlen, "--levels: '%s' is not 1..16", v);
            gv.levels = (int)l;
            given |= G_LEVELS;
        } else if (!strcmp(name, "--threshold")) {
            if (parse_q16(v, 0, 256, &gv.threshold))
                return cam_errf(err, errlen, "--threshold: '%s' is not 0..256", v);
            given |= G_THRESHOLD;
        } else if (!strcmp(name, "--knee")) {
            if (parse_q16(v, 0, 1, &gv.soft_knee))
                return cam_errf(err, errlen, "--knee: '%s' is not 0..1", v);
            given |= G_KNEE;
        } else if (!strcmp(name, "--intensity")) {
            if (parse_q16(v, 0, 10, &gv.intensity))
                return cam_errf(err, errlen, "--intensity: '%s' is not 0..10", v);
            given |= G_INTENSITY;
        } else if (!strcmp(name, "--preset")) {
            const int p = bloom_preset_from_name(v);
            char list[128];
            available(list, sizeof list);
            if (p < 0)
                return cam_errf(err, errlen, "--preset: unknown preset '%s' (this build has: %s)", v, list);
            if (!bloom_preset_available((bloom_preset_t)p))
                return cam_errf(err, errlen,
                                "--preset: '%s' is compiled out of this build (BLOOM_USE_*); this "
                                "build has: %s",
                                v, list);
            o->preset = (bloom_preset_t)p;
        } else if (!strcmp(name, "--strength")) {
            if (parse_q16(v, 0, 16, &gv.p.strength))
                return cam_errf(err, errlen, "--strength: '%s' is not 0..16", v);
            given |= G_STRENGTH;
        } else if (!strcmp(name, "--passes")) {
            if (parse_long(v, 1, 8, &l))
                return cam_errf(err, errlen, "--passes: '%s' is not 1..8", v);
            gv.p.passes = (int)l;
            given |= G_PASSES;
        } else if (!strcmp(name, "--attenuation") || !strcmp(name, "--max-reduction")) {
            const int att = name[2] == 'a';
            if (parse_q16(v, 0, 1, att ? &gv.p.attenuation : &gv.p.max_reduction))
                return cam_errf(err, errlen, "%s: '%s' is not 0..1", name, v);
            given |= att ? G_ATTENUATION : G_MAX_REDUCTION;
        } else if (!strcmp(name, "--aux")) {
            o->aux = v;
            given |= G_AUX;
        } else if (!strcmp(name, "--tint")) {
            if (parse_list01(v, gv.p.tint, 3) != 3)
                return cam_errf(err, errlen, "--tint: '%s' is not R,G,B (each 0..1)", v);
            given |= G_TINT;
        } else if (!strcmp(name, "--weights")) {
            nweights = parse_list01(v, gv.p.level_weight, BLOOM_MAX_LEVELS);
            if (nweights < 1)
                return cam_errf(err, errlen, "--weights: '%s' is not c0,c1,... (1..16 values, each 0..1)", v);
            given |= G_WEIGHTS;
        } else if (!strcmp(name, "--radius")) {
            if (parse_long(v, 1, 1L << 20, &radius))
                return cam_errf(err, errlen, "--radius: '%s' is not 1..1048576 pixels", v);
            given |= G_RADIUS;
        } else if (!strcmp(name, "--mode")) {
            if (!strcmp(v, "bloom"))
                o->mode = CAM_MODE_BLOOM;
            else if (!strcmp(v, "off"))
                o->mode = CAM_MODE_OFF;
            else if (!strcmp(v, "bloom-only"))
                o->mode = CAM_MODE_BLOOM_ONLY;
            else
                return cam_errf(err, errlen, "--mode: '%s' is not bloom, off or bloom-only", v);
        } else if (!strcmp(name, "--frames")) {
            if (parse_long(v, 0, 2000000000L, &o->frames))
                return cam_errf(err, errlen, "--frames: '%s' is not a count", v);
        } else if (!strcmp(name, "--buffers")) {
            if (parse_long(v, 2, CAM_MAX_BUFFERS, &l))
                return cam_errf(err, errlen, "--buffers: '%s' is not 2..%d", v, CAM_MAX_BUFFERS);
            o->buffers = (int)l;
        } else if (!strcmp(name, "--timeout")) {
            if (parse_long(v, 1, 3600000L, &l))
                return cam_errf(err, errlen, "--timeout: '%s' is not 1..3600000 ms", v);
            o->timeout_ms = (int)l;
        } else if (!strcmp(name, "--vt")) {
            o->vt = v;
        } else if (!strcmp(name, "--reconnect")) {
            if (!strcmp(v, "off"))
                o->reconnect_s = 0;
            else if (!strcmp(v, "on"))
                o->reconnect_s = 30;
            else if (parse_long(v, 1, 86400L * 365, &l))
                return cam_errf(err, errlen, "--reconnect: '%s' is not off, on or 1..31536000 seconds", v);
            else
                o->reconnect_s = l;
        } else if (!strcmp(name, "--latest")) {
            if (strcmp(v, "on") && strcmp(v, "off"))
                return cam_errf(err, errlen, "--latest: '%s' is not on or off", v);
            o->latest = !strcmp(v, "on");
        } else if (!strcmp(name, "--debounce")) {
            if (parse_long(v, 0, 10000L, &l))
                return cam_errf(err, errlen, "--debounce: '%s' is not 0..10000 ms", v);
            o->debounce_ms = (int)l;
        } else if (!strcmp(name, "--threads")) {
            if (parse_long(v, 0, BLOOM_MT_MAX_THREADS, &l))
                return cam_errf(err, errlen, "--threads: '%s' is not 0..%d (0: the online CPUs)", v,
                                BLOOM_MT_MAX_THREADS);
            o->threads = (int)l;
        } else if (!strcmp(name, "--gpio-frame") || !strcmp(name, "--gpio-button")) {
            cam_gpio_spec_t *g = name[7] == 'f' ? &o->gpio_frame : &o->gpio_button;
            if (parse_gpio(v, g))
                return cam_errf(err, errlen, "%s: '%s' is not CHIP:LINE", name, v);
        } else if (!strcmp(name, "--record")) {
            o->record = v;
        } else if (!strcmp(name, "--dump-fb")) {
            o->dump_fb = v;
        }
    }
    if (cam_display_check(o, drm_given, err, errlen))
        return -1;
    /* the preset's defaults, then what was given */
    const char *pn = bloom_preset_name(o->preset);
    for (size_t k = 0; k < sizeof param_opt / sizeof param_opt[0]; k++)
        if ((given & param_opt[k].bit) && !(bloom_preset_params(o->preset) & param_opt[k].bit)) {
            char who[64] = "";
            size_t n = 0;
            for (int q = 0; q < BLOOM_PRESET_COUNT; q++)
                if (bloom_preset_params((bloom_preset_t)q) & param_opt[k].bit)
                    n += (size_t)snprintf(who + n, sizeof who - n, "%s%s", n ? " or " : "",
                                          bloom_preset_name((bloom_preset_t)q));
            return cam_errf(err, errlen, "%s applies to the %s preset, not %s (give --preset)",
                            param_opt[k].opt, who, pn);
        }
    if ((given & G_RADIUS) && (given & G_LEVELS))
        return cam_errf(err, errlen, "--radius chooses the level count: give --radius or --levels");
    bloom_config_default(&d, o->width, o->height); /* the size asked for; the
                                                       driver's is used at run time */
    bloom_config_preset(&d, o->preset);
    o->levels = (given & G_LEVELS) ? gv.levels : d.levels;
    o->threshold = (given & G_THRESHOLD) ? gv.threshold : d.threshold;
    o->knee = (given & G_KNEE) ? gv.soft_knee : d.soft_knee;
    o->intensity = (given & G_INTENSITY) ? gv.intensity : d.intensity;
    o->given_params = gv.p;
    o->given_mask = ((given & G_STRENGTH) ? CAM_P_STRENGTH : 0u) | ((given & G_PASSES) ? CAM_P_PASSES : 0u) |
                    ((given & G_ATTENUATION) ? CAM_P_ATTENUATION : 0u) |
                    ((given & G_MAX_REDUCTION) ? CAM_P_MAX_REDUCTION : 0u) |
                    ((given & G_TINT) ? CAM_P_TINT : 0u);
    o->given_weights = nweights;
    o->params = d.p;
    given_params(o, &o->params);
    o->preset_flags = d.flags & (uint32_t)(BLOOM_FLAG_SATURATE | BLOOM_FLAG_BAKED | BLOOM_FLAG_ADDITIVE);
    o->preset_flags |= ((given & G_SATURATE) ? (uint32_t)BLOOM_FLAG_SATURATE : 0u) |
                       ((given & G_BAKED) ? (uint32_t)BLOOM_FLAG_BAKED : 0u) |
                       ((given & G_ADDITIVE) ? (uint32_t)BLOOM_FLAG_ADDITIVE : 0u);
#if BLOOM_USE_COD
    if (given & G_RADIUS) {
        const int lv = bloom_levels_for_radius((int)radius);
        if (lv < 1 || lv > BLOOM_MAX_LEVELS)
            return cam_errf(err, errlen, "--radius %ld: no level count reaches it", radius);
        o->levels = lv;
    }
#else
    (void)radius;
#endif
    /* the aux plane: the file's depth decides U8/U16 once it is read (after
     * VIDIOC_S_FMT); a preset that cannot run without one needs --aux */
    o->aux_fmt = d.aux_fmt;
    if (!o->aux) {
        bloom_config_t t;
        bloom_info_t info;
        cam_opts_config(o, o->width, o->height, &t);
        t.aux_fmt = BLOOM_AUX_NONE;
        const bloom_status_t st = bloom_query(&t, &info);
        if (st == BLOOM_E_AUX)
            return cam_errf(err, errlen,
                            "--preset %s: %s: give its %s with --aux FILE (an 8- or 16-bit PGM of "
                            "the capture size)",
                            pn, bloom_status_str(st),
                            o->preset == BLOOM_PRESET_ATTENUATION  ? "depth plane"
                            : (o->preset_flags & BLOOM_FLAG_BAKED) ? "baked bloom map"
                                                                   : "plane");
        o->aux_fmt = BLOOM_AUX_NONE; /* optional: run without */
    } else if (o->aux && o->aux_fmt == BLOOM_AUX_NONE) {
        o->aux_fmt = BLOOM_AUX_U8; /* the preset reads an optional plane: this one */
    }
    {
        bloom_config_t t;
        bloom_info_t info;
        cam_opts_config(o, o->width, o->height, &t);
        const bloom_status_t st = bloom_query(&t, &info);
        if (st != BLOOM_OK)
            return cam_errf(err, errlen, "--preset %s with these options: %s", pn, bloom_status_str(st));
    }
    if ((o->format == CAM_FMT_YUYV || o->format == CAM_FMT_UYVY || o->format == CAM_FMT_YVYU) &&
        (o->width & 1))
        return cam_errf(err, errlen, "--size: %s needs an even width, not %d", cam_format_name(o->format),
                        o->width);
    if ((o->gpio_frame.set || o->gpio_button.set) && !cam_gpio_available)
        return cam_errf(err, errlen,
                        "--gpio-frame/--gpio-button: built without libgpiod "
                        "(install libgpiod-dev and rebuild)");
    return 0;
}
