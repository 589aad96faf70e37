/* Vertical strips of a frame for the tile tables (issue 14, item 2): the
 * strip widths `make memtable`, `make tile-table` and `make report` share,
 * and the configuration of strip s. Header-only so that bloom_info (core
 * flags only) and the measurement programs use the one definition. */
#ifndef TILE_STRIPS_H
#define TILE_STRIPS_H

#include "bloom.h"

/* Output columns per strip; 0 is the untiled frame. 480 is not in the
 * issue's list: it is 4 strips of 1920, the tiling item 4's 10 % target
 * is about. */
static const int tile_strip_widths[] = {64, 128, 256, 480, 512, 960, 0};
#define TILE_NWIDTHS ((int)(sizeof tile_strip_widths / sizeof tile_strip_widths[0]))
static const int tile_levels[] = {3, 5, 7};
#define TILE_NLEVELS 3

/* Strips of sw columns over a frame w wide (the last one narrower); a width
 * of 0 or of the frame or more is the untiled frame, one "strip". */
static inline int tile_strip_count(int w, int sw)
{
    return sw <= 0 || sw >= w ? 1 : (w + sw - 1) / sw;
}

/* cfg (size, levels and the rest already set) for strip s: columns
 * s*sw .. , every row. The untiled frame keeps tile_w = 0, so its engine
 * is the one without a tile. */
static inline void tile_strip_config(bloom_config_t *cfg, int sw, int s)
{
    if (sw <= 0 || sw >= cfg->width) {
        cfg->tile_x = cfg->tile_y = cfg->tile_w = cfg->tile_h = 0;
        return;
    }
    cfg->tile_x = s * sw;
    cfg->tile_w = cfg->width - cfg->tile_x < sw ? cfg->width - cfg->tile_x : sw;
    cfg->tile_y = 0;
    cfg->tile_h = cfg->height;
}

/* Over the strips of one tiling: the largest workspace (one strip engine
 * re-initialised per strip needs that much), the widest source rectangle,
 * and the source pixels read by all strips together. Returns the status of
 * the first refused strip. */
typedef struct {
    int strips;
    size_t ws_max;
    int src_w_max;
    long long src_px; /* sum of src_w * src_h over the strips */
} tile_plan_t;

static inline bloom_status_t tile_plan(const bloom_config_t *base, int sw, tile_plan_t *p)
{
    p->strips = tile_strip_count(base->width, sw);
    p->ws_max = 0;
    p->src_w_max = 0;
    p->src_px = 0;
    for (int s = 0; s < p->strips; s++) {
        bloom_config_t c = *base;
        bloom_info_t info;
        tile_strip_config(&c, sw, s);
        const bloom_status_t st = bloom_query(&c, &info);
        if (st != BLOOM_OK)
            return st;
        if (info.workspace_bytes > p->ws_max)
            p->ws_max = info.workspace_bytes;
        if (info.src_w > p->src_w_max)
            p->src_w_max = info.src_w;
        p->src_px += (long long)info.src_w * info.src_h;
    }
    return BLOOM_OK;
}

#endif
