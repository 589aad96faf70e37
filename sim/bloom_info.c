/* bloom_info: the engine's memory and latency for common configurations, as
 * the Markdown table README shows (`make memtable`). Every figure comes from
 * bloom_query(), the sizing function itself. */
#include <stdio.h>

#include "bloom.h"

int main(void)
{
    static const struct {
        int w, h, levels;
        bloom_format_t fmt;
        unsigned flags;
    } rows[] = {
        {160, 120, 5, BLOOM_FMT_RGB565, 0},    {320, 240, 5, BLOOM_FMT_RGB565, 0},
        {320, 240, 5, BLOOM_FMT_RGB565, BLOOM_FLAG_COPY_SOURCE},
        {640, 480, 5, BLOOM_FMT_RGB888, 0},    {1280, 720, 5, BLOOM_FMT_RGB888, 0},
        {1920, 1080, 5, BLOOM_FMT_RGB888, 0},  {1920, 1080, 5, BLOOM_FMT_RGB888, BLOOM_FLAG_COPY_SOURCE},
        {1920, 1080, 3, BLOOM_FMT_RGB888, 0},  {1920, 1080, 8, BLOOM_FMT_RGB888, 0},
        {3840, 2160, 5, BLOOM_FMT_XRGB8888, 0},
    };
    static const char *names[] = {"", "RGB888", "XRGB8888", "RGB565", "RGBQ16"};
    printf("| frame | input | levels | source rows | workspace bytes | of one RGB888 frame | "
           "latency (rows) |\n|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        bloom_config_t c;
        bloom_info_t info;
        bloom_config_default(&c, rows[i].w, rows[i].h);
        c.levels = rows[i].levels;
        c.in_fmt = c.out_fmt = rows[i].fmt;
        c.flags = rows[i].flags;
        if (bloom_query(&c, &info) != BLOOM_OK)
            return 1;
        printf("| %dx%d | %s | %d | %s | %zu | %.2f %% (1/%.0f) | %d |\n", c.width, c.height,
               names[c.in_fmt], info.levels, (c.flags & BLOOM_FLAG_COPY_SOURCE) ? "copied" : "pointers",
               info.workspace_bytes, 100.0 * (double)info.workspace_bytes / (3.0 * c.width * c.height),
               3.0 * c.width * c.height / (double)info.workspace_bytes, info.latency_rows);
    }
    return 0;
}
