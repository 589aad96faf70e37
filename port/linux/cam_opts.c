/* bloom_cam: command line, in the style of v4l2-ctl (--opt VALUE or
 * --opt=VALUE). Pure: no device is touched here. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cam.h"

void cam_usage(void *stream)
{
    fputs("usage: bloom_cam [options]\n"
          "  --device DEV          V4L2 capture device (default /dev/video0)\n"
          "  --fb FB               framebuffer (default /dev/fb0); 'none' draws off-screen\n"
          "  --size WxH            capture size asked of the driver (default 640x480)\n"
          "  --format F            yuyv | rgb24 | grey (default yuyv)\n"
          "  --levels N            pyramid levels, 1..16 (default 5)\n"
          "  --threshold T         0..256 (default 1.0)\n"
          "  --knee S              0..1 (default 0.5)\n"
          "  --intensity I         0..10 (default 1.0)\n"
          "  --mode M              bloom | off | bloom-only: what to show first (default bloom)\n"
          "  --frames N            stop after N frames (default: until SIGINT/SIGTERM)\n"
          "  --buffers N           capture buffers, 2..16 (default 4)\n"
          "  --timeout MS          longest wait for a frame (default 2000)\n"
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
    switch (f) {
    case CAM_FMT_YUYV: return "yuyv";
    case CAM_FMT_RGB24: return "rgb24";
    case CAM_FMT_GREY: return "grey";
    }
    return "?";
}

const char *cam_mode_name(enum cam_mode m)
{
    switch (m) {
    case CAM_MODE_BLOOM: return "bloom";
    case CAM_MODE_OFF: return "off";
    case CAM_MODE_BLOOM_ONLY: return "bloom-only";
    case CAM_MODE_COUNT: break;
    }
    return "?";
}

static int fail(char *err, size_t errlen, const char *fmt, ...)
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
    "--device", "--fb", "--size", "--format", "--levels", "--threshold", "--knee",
    "--intensity", "--mode", "--frames", "--buffers", "--timeout", "--gpio-frame",
    "--gpio-button", "--record", "--dump-fb", NULL};

int cam_parse_opts(cam_opts_t *o, int argc, char **argv, char *err, size_t errlen)
{
    bloom_config_t d;
    bloom_config_default(&d, 2, 2);
    memset(o, 0, sizeof *o);
    o->device = "/dev/video0";
    o->fb = "/dev/fb0";
    o->width = 640;
    o->height = 480;
    o->format = CAM_FMT_YUYV;
    o->levels = d.levels;
    o->threshold = d.threshold;
    o->knee = d.soft_knee;
    o->intensity = d.intensity;
    o->buffers = 4;
    o->timeout_ms = 2000;
    o->mode = CAM_MODE_BLOOM;

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
        size_t n = eq ? (size_t)(eq - a) : strlen(a);
        if (n >= sizeof name)
            return fail(err, errlen, "unknown option '%s'", a);
        memcpy(name, a, n);
        name[n] = '\0';
        int known = 0;
        for (int k = 0; with_value[k]; k++)
            known |= !strcmp(name, with_value[k]);
        if (!known)
            return fail(err, errlen, "unknown option '%s'", a);
        if (eq)
            v = eq + 1;
        else if (i + 1 < argc)
            v = argv[++i];
        else
            return fail(err, errlen, "%s needs a value", name);

        long l;
        if (!strcmp(name, "--device")) {
            o->device = v;
        } else if (!strcmp(name, "--fb")) {
            o->fb = v;
        } else if (!strcmp(name, "--size")) {
            if (parse_size(v, &o->width, &o->height))
                return fail(err, errlen, "--size: '%s' is not WxH (2..16384 x 1..16384)", v);
        } else if (!strcmp(name, "--format")) {
            if (!strcmp(v, "yuyv") || !strcmp(v, "YUYV"))
                o->format = CAM_FMT_YUYV;
            else if (!strcmp(v, "rgb24") || !strcmp(v, "RGB3"))
                o->format = CAM_FMT_RGB24;
            else if (!strcmp(v, "grey") || !strcmp(v, "gray") || !strcmp(v, "GREY"))
                o->format = CAM_FMT_GREY;
            else
                return fail(err, errlen, "--format: '%s' is not yuyv, rgb24 or grey", v);
        } else if (!strcmp(name, "--levels")) {
            if (parse_long(v, 1, BLOOM_MAX_LEVELS, &l))
                return fail(err, errlen, "--levels: '%s' is not 1..16", v);
            o->levels = (int)l;
        } else if (!strcmp(name, "--threshold")) {
            if (parse_q16(v, 0, 256, &o->threshold))
                return fail(err, errlen, "--threshold: '%s' is not 0..256", v);
        } else if (!strcmp(name, "--knee")) {
            if (parse_q16(v, 0, 1, &o->knee))
                return fail(err, errlen, "--knee: '%s' is not 0..1", v);
        } else if (!strcmp(name, "--intensity")) {
            if (parse_q16(v, 0, 10, &o->intensity))
                return fail(err, errlen, "--intensity: '%s' is not 0..10", v);
        } else if (!strcmp(name, "--mode")) {
            if (!strcmp(v, "bloom"))
                o->mode = CAM_MODE_BLOOM;
            else if (!strcmp(v, "off"))
                o->mode = CAM_MODE_OFF;
            else if (!strcmp(v, "bloom-only"))
                o->mode = CAM_MODE_BLOOM_ONLY;
            else
                return fail(err, errlen, "--mode: '%s' is not bloom, off or bloom-only", v);
        } else if (!strcmp(name, "--frames")) {
            if (parse_long(v, 0, 2000000000L, &o->frames))
                return fail(err, errlen, "--frames: '%s' is not a count", v);
        } else if (!strcmp(name, "--buffers")) {
            if (parse_long(v, 2, CAM_MAX_BUFFERS, &l))
                return fail(err, errlen, "--buffers: '%s' is not 2..%d", v, CAM_MAX_BUFFERS);
            o->buffers = (int)l;
        } else if (!strcmp(name, "--timeout")) {
            if (parse_long(v, 1, 3600000L, &l))
                return fail(err, errlen, "--timeout: '%s' is not 1..3600000 ms", v);
            o->timeout_ms = (int)l;
        } else if (!strcmp(name, "--gpio-frame") || !strcmp(name, "--gpio-button")) {
            cam_gpio_spec_t *g = name[7] == 'f' ? &o->gpio_frame : &o->gpio_button;
            if (parse_gpio(v, g))
                return fail(err, errlen, "%s: '%s' is not CHIP:LINE", name, v);
        } else if (!strcmp(name, "--record")) {
            o->record = v;
        } else if (!strcmp(name, "--dump-fb")) {
            o->dump_fb = v;
        }
    }
    if (o->format == CAM_FMT_YUYV && (o->width & 1))
        return fail(err, errlen, "--size: YUYV needs an even width, not %d", o->width);
    if ((o->gpio_frame.set || o->gpio_button.set) && !cam_gpio_available)
        return fail(err, errlen, "--gpio-frame/--gpio-button: built without libgpiod "
                                 "(install libgpiod-dev and rebuild)");
    return 0;
}
