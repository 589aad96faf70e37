/* The cost bench of the Cortex-M example (issue 21, section 4): one frame
 * of a preset at a level count and a frame size, whole or in vertical
 * strips, for port/mcu/mcu_count.py to count the instructions the engine
 * calls execute under emulation. Linked into the firmware with
 * FW_MAIN_APP=fw_cost_app (fw_main.c), so the image also runs under
 * qemu-system-arm like the others; built for the host too, whose "frame"
 * line is the checksum the emulated run must print.
 *
 * The job is a structure in .data that the harness overwrites in the
 * loaded image before the run (the host reads it from FW_COST_JOB, "preset
 * levels width height strip"); the defaults are the firmware's own frame. */
#include "fw_app.h"

#ifndef FW_TARGET
#include <stdio.h>
#include <stdlib.h>
#endif

#define CW 640 /* the largest frame the bench renders */
#define CH 480
#ifndef FW_COST_WS
/* Room for every preset at up to 7 levels at 320x240 and for any strip
 * engine: the bench measures instructions, not the smallest footprint
 * (FIGURES.md has that). */
#define FW_COST_WS (512u * 1024u)
#endif

typedef struct {
    /* levels 0 = the preset's own; strip = columns per strip, 0 = whole frame */
    int32_t preset, levels, width, height, strip;
} fw_cost_job_t;

/* volatile: the values are read at run time, not folded from the
 * initialiser (the harness changes them in the image). */
volatile fw_cost_job_t fw_cost_job = {0, FW_LEVELS, FW_W, FW_H, 0};

#ifdef FW_TARGET
#define FW_FB_ATTR __attribute__((section(".framebuffer")))
#else
#define FW_FB_ATTR
#endif
BLOOM_WORKSPACE_DEFINE(cost_ws, FW_COST_WS);
FW_FB_ATTR static uint8_t cost_src[CW * CH * 2] __attribute__((aligned(8)));
FW_FB_ATTR static uint8_t cost_dst[CW * CH * 2] __attribute__((aligned(8)));
FW_FB_ATTR static uint8_t cost_aux[CW * CH] __attribute__((aligned(8)));

static void say(const fw_platform_t *pf, const char *what, const char *why)
{
    fw_line_t l = {.n = 0};
    fw_str(&l, "error: ");
    fw_str(&l, what);
    fw_str(&l, ": ");
    fw_str(&l, why);
    pf->puts(l.s);
}

/* The job's engine for strip s (or the whole frame). */
static bloom_status_t config(bloom_config_t *c, const fw_cost_job_t *j, int s)
{
    bloom_config_default(c, j->width, j->height);
    c->in_fmt = c->out_fmt = BLOOM_FMT_RGB565;
    if (j->preset != BLOOM_PRESET_UNITY) {
        const bloom_status_t st = bloom_config_preset(c, (bloom_preset_t)j->preset);
        if (st != BLOOM_OK)
            return st;
    }
    if (j->levels > 0) /* 0: the preset's own level count */
        c->levels = j->levels;
#ifdef BLOOM_COST_SAMPLE_BITS /* make target-cost's width (COST_CFLAGS_16) */
    c->sample_bits = BLOOM_COST_SAMPLE_BITS;
#endif
    if (j->strip > 0 && j->strip < j->width) {
        c->tile_x = s * j->strip;
        c->tile_w = j->width - c->tile_x < j->strip ? j->width - c->tile_x : j->strip;
        c->tile_y = 0;
        c->tile_h = j->height;
    }
    return BLOOM_OK;
}

int fw_cost_app(const fw_platform_t *pf)
{
    fw_cost_job_t j = {fw_cost_job.preset, fw_cost_job.levels, fw_cost_job.width, fw_cost_job.height,
                       fw_cost_job.strip};
#ifndef FW_TARGET
    const char *env = getenv("FW_COST_JOB");
    if (env && sscanf(env, "%d %d %d %d %d", &j.preset, &j.levels, &j.width, &j.height, &j.strip) != 5) {
        say(pf, "FW_COST_JOB", "wants \"preset levels width height strip\"");
        return 1;
    }
#endif
    if (j.width < 1 || j.width > CW || j.height < 1 || j.height > CH || j.strip < 0) {
        say(pf, "job", "frame larger than the bench's buffers");
        return 1;
    }
    const ptrdiff_t stride = (ptrdiff_t)j.width * 2;
    /* The firmware's scene; a larger frame repeats it shifted (fw_tiles.c). */
    const int dx = j.width > FW_W ? 37 : 0, dy = j.height > FW_H ? 11 : 0;
    for (int y = 0; y < j.height; y++)
        for (int x = 0; x < j.width; x++) {
            const uint16_t v = fw_pattern_pixel((x + dx) % FW_W, (y + dy) % FW_H);
            uint8_t *p = cost_src + (size_t)y * (size_t)stride + (size_t)x * 2u;
            p[0] = (uint8_t)v;
            p[1] = (uint8_t)(v >> 8);
            /* the depth plane or mask of the presets that read one */
            cost_aux[(size_t)y * (size_t)j.width + (size_t)x] =
                (uint8_t)((uint32_t)x * 255u / (uint32_t)(j.width > 1 ? j.width - 1 : 1));
        }

    const int strips = j.strip > 0 && j.strip < j.width ? (j.width + j.strip - 1) / j.strip : 1;
    int levels = 0;
    for (int s = 0; s < strips; s++) {
        bloom_config_t c;
        bloom_t *b;
        uint32_t stack = 0;
        bloom_status_t st = config(&c, &j, s);
        levels = c.levels;
        if (st == BLOOM_OK)
            st = pf->init(&b, cost_ws, sizeof cost_ws, &c, &stack);
        if (st == BLOOM_OK && c.aux_fmt != BLOOM_AUX_NONE)
            st = bloom_set_aux(b, cost_aux, (ptrdiff_t)j.width);
        if (st == BLOOM_OK)
            st = pf->run(b, cost_src, cost_dst, stride, &stack);
        if (st != BLOOM_OK) {
            say(pf, "engine", bloom_status_str(st));
            return 1;
        }
    }
    /* Strips write only their own columns; a whole-frame engine all of
     * them: the checksum covers the frame either way. */
    fw_line_t l = {.n = 0};
    fw_str(&l, "frame cost preset ");
    fw_dec(&l, (uint32_t)j.preset);
    fw_str(&l, " levels ");
    fw_dec(&l, (uint32_t)levels);
    fw_str(&l, " ");
    fw_dec(&l, (uint32_t)j.width);
    fw_str(&l, "x");
    fw_dec(&l, (uint32_t)j.height);
    fw_str(&l, " strips ");
    fw_dec(&l, (uint32_t)strips);
    fw_str(&l, ": output fnv1a ");
    fw_hex(&l, fw_fnv1a(cost_dst, (size_t)stride * (size_t)j.height));
    pf->puts(l.s);
    return 0;
}
