/* bloom_info: the engine's memory and latency for common configurations, as
 * the Markdown table README shows (`make memtable`). Every figure comes from
 * bloom_query(), the sizing function itself. */
#include <stdio.h>
#include <string.h>

#include "bench/tile_strips.h"
#include "bloom.h"

/* Issue 14, item 2: a strip engine's workspace against the strip width and
 * the level count, 1920x1080 RGB888, default preset, source rows by
 * pointer. The workspace follows the strip's source rectangle (the strip
 * and its halo), so the halo sets a floor that the width cannot go under;
 * the columns read say how much of that is halo. The instruction overhead
 * beside these is `make tile-table` (callgrind, sim/docs/tiles.md). */
static int strip_table(void)
{
    enum { W = 1920, H = 1080 };
    printf("| levels | strip (output columns) | strips | workspace of one strip engine (bytes) | "
           "of the untiled | source columns per strip (widest) | source pixels read / frame |\n"
           "|---|---|---|---|---|---|---|\n");
    for (int li = 0; li < TILE_NLEVELS; li++) {
        bloom_config_t c;
        tile_plan_t whole;
        bloom_config_default(&c, W, H);
        c.levels = tile_levels[li];
        if (tile_plan(&c, 0, &whole) != BLOOM_OK)
            return 1;
        for (int i = 0; i < TILE_NWIDTHS; i++) {
            const int sw = tile_strip_widths[i];
            tile_plan_t p;
            if (tile_plan(&c, sw, &p) != BLOOM_OK)
                return 1;
            char what[32];
            snprintf(what, sizeof what, sw ? "%d" : "untiled (%d)", sw ? sw : W);
            printf("| %d | %s | %d | %zu | %.2f | %d | %.2f |\n", c.levels, what, p.strips, p.ws_max,
                   (double)p.ws_max / (double)whole.ws_max, p.src_w_max, (double)p.src_px / (double)(W * H));
        }
    }
    /* the target, stated with what this build measures */
    bloom_config_t c;
    tile_plan_t p;
    bloom_config_default(&c, W, H);
    if (tile_plan(&c, 256, &p) != BLOOM_OK)
        return 1;
    printf("\nIssue 14 target: 1920x1080 RGB888, 5 levels, strips of 256 output columns, workspace <= "
           "65536 bytes: measured %zu bytes, %s.\n",
           p.ws_max, p.ws_max <= 65536 ? "met" : "not met");
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && !strcmp(argv[1], "--strips"))
        return strip_table();
    if (argc != 1) {
        fprintf(stderr, "usage: bloom_info [--strips]\n");
        return 2;
    }
    static const struct {
        int w, h, levels;
        bloom_format_t fmt;
        unsigned flags;
    } rows[] = {
        {160, 120, 5, BLOOM_FMT_RGB565, 0},
        {320, 240, 5, BLOOM_FMT_RGB565, 0},
        {320, 240, 5, BLOOM_FMT_RGB565, BLOOM_FLAG_COPY_SOURCE},
        {640, 480, 5, BLOOM_FMT_RGB888, 0},
        {1280, 720, 5, BLOOM_FMT_RGB888, 0},
        {1920, 1080, 5, BLOOM_FMT_RGB888, 0},
        {1920, 1080, 5, BLOOM_FMT_RGB888, BLOOM_FLAG_COPY_SOURCE},
        {1920, 1080, 3, BLOOM_FMT_RGB888, 0},
        {1920, 1080, 8, BLOOM_FMT_RGB888, 0},
        {3840, 2160, 5, BLOOM_FMT_XRGB8888, 0},
    };
    static const char *names[] = {"", "RGB888", "XRGB8888", "RGB565", "RGBQ16", "RGBF32"};
    printf("| frame | input | levels | source rows | workspace bytes | of one RGB888 frame | "
           "of it, the static schedule | latency (rows) | with 16-bit samples (G) |\n"
           "|---|---|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        bloom_config_t c;
        bloom_info_t info;
        bloom_config_default(&c, rows[i].w, rows[i].h);
        c.levels = rows[i].levels;
        c.in_fmt = c.out_fmt = rows[i].fmt;
        c.flags = rows[i].flags;
        if (bloom_query(&c, &info) != BLOOM_OK)
            return 1;
        bloom_info_t s16; /* cfg.sample_bits = 16 (sim/docs/fixed-point.md, "16-bit samples") */
        c.sample_bits = 16;
        const int have16 = bloom_query(&c, &s16) == BLOOM_OK;
        char w16[48] = "not built in";
        if (have16)
            snprintf(w16, sizeof w16, "%zu (%.2fx, G %d)", s16.workspace_bytes,
                     (double)s16.workspace_bytes / (double)info.workspace_bytes, s16.sample_frac);
        printf("| %dx%d | %s | %d | %s | %zu | %.2f %% (1/%.0f) | %zu | %d | %s |\n", c.width, c.height,
               names[c.in_fmt], info.levels, (c.flags & BLOOM_FLAG_COPY_SOURCE) ? "copied" : "pointers",
               info.workspace_bytes, 100.0 * (double)info.workspace_bytes / (3.0 * c.width * c.height),
               3.0 * c.width * c.height / (double)info.workspace_bytes, info.schedule_bytes,
               info.latency_rows, w16);
    }
    /* Every preset at its own defaults (levels, aux plane), RGB888 in and
     * out, source rows kept by pointer; the row memory by level. */
    printf(
        "\n| preset | levels | 1920x1080 workspace | of one frame | latency | 320x240 workspace | latency |\n"
        "|---|---|---|---|---|---|---|\n");
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p))
            continue;
        bloom_info_t big, small;
        bloom_config_t c;
        bloom_config_default(&c, 1920, 1080);
        bloom_config_preset(&c, (bloom_preset_t)p);
        if (bloom_query(&c, &big) != BLOOM_OK)
            return 1;
        bloom_config_default(&c, 320, 240);
        bloom_config_preset(&c, (bloom_preset_t)p);
        if (bloom_query(&c, &small) != BLOOM_OK)
            return 1;
        printf("| %s | %d | %zu | 1/%.0f | %d | %zu | %d |\n", bloom_preset_name((bloom_preset_t)p),
               big.levels, big.workspace_bytes, 3.0 * 1920 * 1080 / (double)big.workspace_bytes,
               big.latency_rows, small.workspace_bytes, small.latency_rows);
    }
    printf("\nWorkspace against strip width (tiles; instructions: make tile-table, sim/docs/tiles.md):\n\n");
    return strip_table();
}
