/* bloom_cam's engines: one per mode (bloom, bloom-only, off), row by row
 * (bloom_init on a workspace of its own) or, with --threads, a pool of
 * strip engines each (cam_mt.c); made again when the camera comes back in
 * another size (cam_resize). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <linux/videodev2.h>

#include "bloom_mt.h"
#include "cam.h"

int cam_make_engines(cam_t *c)
{
    if (c->o.aux) { /* the preset's plane, the capture's size (known after S_FMT) */
        char err[512];
        bloom_aux_format_t f;
        if (cam_aux_load(c->o.aux, c->cap.width, c->cap.height, &f, &c->aux, err, sizeof err)) {
            fprintf(stderr, "%s: %s\n", CAM_PROG, err);
            return -1;
        }
        c->o.aux_fmt = f;
        c->aux_stride = (size_t)c->cap.width * (f == BLOOM_AUX_U16 ? 2u : 1u);
    }
    { /* --threads: 0 the online CPUs; a frame too small for them gets fewer */
        bloom_config_t cfg;
        cam_opts_config(&c->o, c->cap.width, c->cap.height, &cfg);
        c->threads = bloom_mt_tiles_for(&cfg, c->o.threads ? c->o.threads : bloom_mt_cpus());
        if (c->threads > 1 && cam_mt_frames(&c->mt, &c->cap, &c->fb, &c->place))
            return -1;
    }
    for (int m = 0; m < CAM_MODE_COUNT; m++) {
        bloom_config_t cfg;
        cam_opts_config(&c->o, c->cap.width, c->cap.height, &cfg);
        cfg.in_fmt = BLOOM_FMT_RGB888;
        cfg.out_fmt = c->fb.format;
        if (c->cap.pixelformat != V4L2_PIX_FMT_RGB24)
            cfg.flags |= BLOOM_FLAG_COPY_SOURCE;
        if (m == CAM_MODE_BLOOM_ONLY)
            cfg.flags |= BLOOM_FLAG_DEBUG_VIEW;
        if (m == CAM_MODE_OFF) { /* the default pipeline with B = 0 on every row: the
                                    source, re-encoded, whatever the preset */
            bloom_config_default(&cfg, c->cap.width, c->cap.height);
            cfg.in_fmt = BLOOM_FMT_RGB888;
            cfg.out_fmt = c->fb.format;
            if (c->cap.pixelformat != V4L2_PIX_FMT_RGB24)
                cfg.flags |= BLOOM_FLAG_COPY_SOURCE;
            cfg.levels = c->o.levels;
            cfg.threshold = BLOOM_MAX_THRESHOLD;
            cfg.soft_knee = 0;
            cfg.intensity = 0;
        }
        bloom_info_t info;
        bloom_status_t st = bloom_query(&cfg, &info);
        if (st != BLOOM_OK && m == CAM_MODE_BLOOM_ONLY && c->o.mode != CAM_MODE_BLOOM_ONLY) {
            if (!c->o.quiet)
                fprintf(stderr, "%s: preset %s: no bloom-only view (%s); the button skips it\n", CAM_PROG,
                        bloom_preset_name(cfg.preset), bloom_status_str(st));
            continue;
        }
        if (st != BLOOM_OK) {
            fprintf(stderr, "%s: bloom_query (preset %s%s): %s\n", CAM_PROG, bloom_preset_name(cfg.preset),
                    m == CAM_MODE_BLOOM_ONLY ? ", bloom-only" : "", bloom_status_str(st));
            return -1;
        }
        c->eng_aux[m] = cfg.aux_fmt != BLOOM_AUX_NONE;
        if (c->threads > 1) { /* whole frames: nothing to copy */
            size_t bytes;
            cfg.flags &= ~(uint32_t)BLOOM_FLAG_COPY_SOURCE;
            if (cam_mt_mode(&c->mt, (enum cam_mode)m, &cfg, c->threads, c->eng_aux[m] ? c->aux : NULL,
                            c->aux_stride, &bytes))
                return -1;
            if (m == CAM_MODE_BLOOM && !c->o.quiet)
                fprintf(stderr,
                        "%s: engine: preset %s%s%s, %d levels, %d threads (%d %s), workspace %zu bytes, "
                        "frame buffers %zu bytes (in: %s, out: %s)\n",
                        CAM_PROG, bloom_preset_name(cfg.preset), c->o.aux ? ", aux plane " : "",
                        c->o.aux ? c->o.aux : "", info.levels, c->threads, c->mt.tiles,
                        c->cap.width / c->mt.tiles >= BLOOM_MT_MIN_STRIP ? "strips" : "tiles", bytes,
                        c->mt.frame_bytes, c->mt.rgb ? "an RGB888 frame" : "the capture read in place",
                        c->mt.out ? "a frame, the shown part copied" : "straight to the page");
            continue;
        }
        size_t n = (info.workspace_bytes + 63) / 64 * 64;
        c->ws[m] = aligned_alloc(64, n);
        if (!c->ws[m]) {
            fprintf(stderr, "%s: workspace of %zu bytes: out of memory\n", CAM_PROG, n);
            return -1;
        }
        st = bloom_init(&c->eng[m], c->ws[m], n, &cfg);
        if (st != BLOOM_OK) {
            fprintf(stderr, "%s: bloom_init: %s\n", CAM_PROG, bloom_status_str(st));
            return -1;
        }
        if (m == CAM_MODE_BLOOM && !c->o.quiet)
            fprintf(stderr,
                    "%s: engine: preset %s%s%s, %d levels, 1 thread (row by row), workspace %zu bytes, "
                    "latency %d rows%s\n",
                    CAM_PROG, bloom_preset_name(cfg.preset), c->o.aux ? ", aux plane " : "",
                    c->o.aux ? c->o.aux : "", info.levels, info.workspace_bytes, info.latency_rows,
                    (cfg.flags & BLOOM_FLAG_COPY_SOURCE) ? ", source rows copied" : "");
    }
    return 0;
}

int cam_resize(cam_t *c)
{
    if (c->o.aux) { /* (reconnect refuses this: the plane has the old size) */
        fprintf(stderr, "%s: --aux: the plane is not of the new size\n", CAM_PROG);
        return -1;
    }
    cam_mt_close(&c->mt);
    for (int m = 0; m < CAM_MODE_COUNT; m++) {
        free(c->ws[m]);
        c->ws[m] = NULL;
        c->eng[m] = NULL;
    }
    free(c->line);
    free(c->scratch);
    cam_place(c->cap.width, c->cap.height, c->fb.xres, c->fb.yres, &c->place);
    c->line = malloc((size_t)c->cap.width * 3);
    c->scratch = malloc((size_t)c->cap.width * 4);
    if (!c->line || !c->scratch) {
        fprintf(stderr, "%s: out of memory\n", CAM_PROG);
        return -1;
    }
    c->clear_pages = c->fb.pages > 1 ? c->fb.pages : 1;
    if (cam_make_engines(c))
        return -1;
    if (!c->o.quiet)
        fprintf(stderr, "%s: reconnect: renegotiated %dx%d; frame at %d,%d, %dx%d shown from %d,%d\n",
                CAM_PROG, c->cap.width, c->cap.height, c->place.dst_x, c->place.dst_y, c->place.w, c->place.h,
                c->place.src_x, c->place.src_y);
    return 0;
}
