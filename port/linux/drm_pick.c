/* bloom_cam: the pure rules of the DRM output (drm.c), apart so that the
 * host tests (test_drm.c) run them without libdrm or a device. */
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
