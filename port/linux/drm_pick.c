/* bloom_cam: the pure rules of the DRM output (drm.c), apart so that the
 * host tests (test_drm.c) run them without libdrm or a device. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cam.h"

#ifdef CAM_NO_DRM
const int cam_drm_available = 0;
#else
const int cam_drm_available = 1;
#endif

int cam_drm_pick_mode(const cam_drm_mode_t *m, int n, int want_w, int want_h)
{
    int best = -1;
    for (int i = 0; i < n; i++) {
        if (want_w > 0) {
            if (m[i].w != want_w || m[i].h != want_h)
                continue;
            /* the preferred mode wins when it is the size asked: its timings
             * are the panel's own; else the fastest refresh of that size */
            if (best < 0 || (m[i].preferred && !m[best].preferred) ||
                (m[i].preferred == m[best].preferred && m[i].refresh > m[best].refresh))
                best = i;
        } else if (m[i].preferred) {
            return i;
        }
    }
    if (want_w > 0)
        return best;
    return n > 0 ? 0 : -1; /* none flagged: the driver lists its best first */
}

int cam_drm_pick_formats(const uint32_t *fmts, int n, bloom_format_t want, bloom_format_t out[2])
{
    static const struct {
        bloom_format_t f;
        uint32_t fourcc;
    } order[] = {{BLOOM_FMT_XRGB8888, CAM_DRM_XRGB8888}, {BLOOM_FMT_RGB565, CAM_DRM_RGB565}};
    int k = 0;
    for (unsigned j = 0; j < sizeof order / sizeof order[0]; j++) {
        if (want && want != order[j].f)
            continue;
        for (int i = 0; i < n; i++)
            if (fmts[i] == order[j].fourcc) {
                out[k++] = order[j].f;
                break;
            }
    }
    return k;
}

int cam_display_use_drm(const cam_opts_t *o, int drm_connected)
{
    if (o->display != CAM_DISPLAY_AUTO)
        return o->display == CAM_DISPLAY_DRM;
    return !o->fb_given && drm_connected;
}

static int parse_wxh(const char *s, int *w, int *h)
{
    char *end;
    errno = 0;
    long a = strtol(s, &end, 10);
    if (errno || end == s || *end != 'x')
        return -1;
    const char *t = end + 1;
    long b = strtol(t, &end, 10);
    if (errno || end == t || *end || a < 1 || b < 1 || a > 16384 || b > 16384)
        return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

int cam_display_opt(cam_opts_t *o, const char *name, const char *v, char *err, size_t errlen, int *drm_given)
{
    if (!strcmp(name, "--display")) {
        if (!strcmp(v, "drm"))
            o->display = CAM_DISPLAY_DRM;
        else if (!strcmp(v, "fbdev"))
            o->display = CAM_DISPLAY_FBDEV;
        else if (!strcmp(v, "auto"))
            o->display = CAM_DISPLAY_AUTO;
        else
            return cam_errf(err, errlen, "--display: '%s' is not drm, fbdev or auto", v);
    } else if (!strcmp(name, "--drm-card")) {
        o->drm_card = v;
    } else if (!strcmp(name, "--drm-mode")) {
        if (parse_wxh(v, &o->drm_w, &o->drm_h))
            return cam_errf(err, errlen, "--drm-mode: '%s' is not WxH", v);
    } else if (!strcmp(name, "--drm-format")) {
        if (!strcmp(v, "auto"))
            o->drm_format = (bloom_format_t)0;
        else if (!strcmp(v, "xrgb8888") || !strcmp(v, "XR24"))
            o->drm_format = BLOOM_FMT_XRGB8888;
        else if (!strcmp(v, "rgb565") || !strcmp(v, "RG16"))
            o->drm_format = BLOOM_FMT_RGB565;
        else
            return cam_errf(err, errlen, "--drm-format: '%s' is not auto, xrgb8888 or rgb565", v);
    } else {
        return 0;
    }
    if (name[2] == 'd' && name[3] == 'r')
        *drm_given = 1;
    return 1;
}

int cam_display_check(cam_opts_t *o, int drm_given, char *err, size_t errlen)
{
    if (drm_given && o->display == CAM_DISPLAY_FBDEV)
        return cam_errf(err, errlen, "--drm-card/--drm-mode/--drm-format are for --display drm, not fbdev");
    if (drm_given && o->fb_given)
        return cam_errf(err, errlen, "--fb is the fbdev output, --drm-* the DRM one: give one of them");
    if (o->display == CAM_DISPLAY_DRM && o->fb_given)
        return cam_errf(err, errlen, "--fb is the fbdev output: not with --display drm");
    if (drm_given)
        o->display = CAM_DISPLAY_DRM;
    if (o->display == CAM_DISPLAY_DRM && !cam_drm_available)
        return cam_errf(err, errlen, "--display drm: built without libdrm (install libdrm-dev and rebuild)");
    return 0;
}
