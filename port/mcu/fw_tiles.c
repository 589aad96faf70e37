/* The tiles case of the Cortex-M example (issue 14, item 2): a frame whose
 * untiled workspace would not fit the chip's on-chip SRAM, rendered in
 * vertical strips with a small static workspace, matching the host's
 * checksum of the same frame rendered untiled.
 *
 * The frame is 640x480 RGB565 (600 KB in, 600 KB out) in the boards' large
 * RAM (.framebuffer); the rest of the image, stack and workspace included,
 * must fit FW_SRAM_BYTES (mcu.mk links with FW_SRAM_LIMIT, which mps2.ld
 * asserts). On the target every strip engine is carved in turn out of one
 * FW_TILE_WS-byte workspace: the widest strip of a short list whose every
 * strip fits it. On the host the same frame runs untiled (the reference),
 * then tiled, and the two must agree there too. */
#include "fw_app.h"

#define TW 640
#define TH 480
#define TSTRIDE (TW * 2)
#ifndef FW_TILE_LEVELS
/* the default 5 (the untiled engine needs more than the SRAM; strip
 * engines make only the columns their readers use, so a strip of 64
 * columns fits 32 KB: port/mcu/FIGURES.md, sim/docs/tiles.md) */
#define FW_TILE_LEVELS 5
#endif
#ifndef FW_TILE_WS
#define FW_TILE_WS 32768 /* the bound for the strip workspace */
#endif
#define FW_SRAM_BYTES 65536 /* the on-chip SRAM this case stands for */

#ifdef FW_TARGET
#define FW_FB_ATTR __attribute__((section(".framebuffer")))
BLOOM_WORKSPACE_DEFINE(tile_ws, FW_TILE_WS);
#else
#define FW_FB_ATTR
/* the host's untiled reference needs the whole-frame workspace */
BLOOM_WORKSPACE_DEFINE(tile_ws, BLOOM_WORKSPACE_MAX(TW, TH, FW_TILE_LEVELS, 2, 0));
static uint8_t host_ref[TH * TSTRIDE];
#endif
_Static_assert(FW_TILE_WS <= 32768, "the issue asks for a strip workspace of at most 32 KB");

FW_FB_ATTR static uint8_t tile_src[TH * TSTRIDE] __attribute__((aligned(8)));
FW_FB_ATTR static uint8_t tile_dst[TH * TSTRIDE] __attribute__((aligned(8)));

/* The 320x240 test scene repeated 2x2 and shifted, so that lamps sit on
 * strip boundaries and at the frame's edges. */
static uint16_t pixel(int x, int y)
{
    return fw_pattern_pixel((x + 37) % FW_W, (y + 11) % FW_H);
}

static void line(const fw_platform_t *pf, const char *a, uint32_t v, const char *b)
{
    fw_line_t l = {.n = 0};
    fw_str(&l, a);
    fw_dec(&l, v);
    fw_str(&l, b);
    pf->puts(l.s);
}

static void frame_line(const fw_platform_t *pf, const char *what, uint32_t sum, const char *tail, uint32_t n)
{
    fw_line_t l = {.n = 0};
    fw_str(&l, "frame 640x480 RGB565 levels ");
    fw_dec(&l, FW_TILE_LEVELS);
    fw_str(&l, ": ");
    fw_str(&l, what);
    fw_str(&l, " fnv1a ");
    fw_hex(&l, sum);
    if (tail) {
        fw_str(&l, ", ");
        fw_dec(&l, n);
        fw_str(&l, tail);
    }
    pf->puts(l.s);
}

static void config_l(bloom_config_t *c, int levels, int sw, int s)
{
    bloom_config_default(c, TW, TH);
    c->in_fmt = c->out_fmt = BLOOM_FMT_RGB565;
    c->levels = levels;
    if (sw < TW) {
        c->tile_x = s * sw;
        c->tile_w = TW - c->tile_x < sw ? TW - c->tile_x : sw;
        c->tile_y = 0;
        c->tile_h = TH;
    }
}

static void config(bloom_config_t *c, int sw, int s)
{
    config_l(c, FW_TILE_LEVELS, sw, s);
}

/* The largest workspace over the strips of width sw, 0 if refused. */
static size_t strip_ws_l(int levels, int sw)
{
    size_t most = 0;
    for (int s = 0; s * sw < TW; s++) {
        bloom_config_t c;
        config_l(&c, levels, sw, s);
        const size_t n = bloom_workspace_size(&c);
        if (!n)
            return 0;
        most = n > most ? n : most;
    }
    return most;
}

static size_t strip_ws(int sw)
{
    return strip_ws_l(FW_TILE_LEVELS, sw);
}

/* Every strip of width sw from tile_src into dst. */
static int run_strips(const fw_platform_t *pf, int sw, uint8_t *dst, uint32_t *stack)
{
    for (int s = 0; s * sw < TW; s++) {
        bloom_config_t c;
        bloom_t *b;
        uint32_t st_init = 0, st_run = 0;
        config(&c, sw, s);
        bloom_status_t st = pf->init(&b, tile_ws, sizeof tile_ws, &c, &st_init);
        if (st == BLOOM_OK)
            st = pf->run(b, tile_src, dst, TSTRIDE, &st_run);
        if (st != BLOOM_OK) {
            fw_line_t l = {.n = 0};
            fw_str(&l, "error: strip engine: ");
            fw_str(&l, bloom_status_str(st));
            pf->puts(l.s);
            return 1;
        }
        if (st_run > *stack)
            *stack = st_run;
    }
    return 0;
}

int fw_tiles_app(const fw_platform_t *pf)
{
    static const int16_t widths[] = {320, 256, 160, 128, 64, 32, 16};
    bloom_config_t c;
    for (int y = 0; y < TH; y++)
        for (int x = 0; x < TW; x++) {
            const uint16_t v = pixel(x, y);
            tile_src[(size_t)y * TSTRIDE + (size_t)x * 2u] = (uint8_t)v;
            tile_src[(size_t)y * TSTRIDE + (size_t)x * 2u + 1u] = (uint8_t)(v >> 8);
        }
    frame_line(pf, "input", fw_fnv1a(tile_src, sizeof tile_src), 0, 0);
    config(&c, TW, 0);
    const size_t untiled = bloom_workspace_size(&c);
    line(pf, "tiles: untiled workspace ", (uint32_t)untiled, " bytes");
    int sw = 0;
    for (size_t i = 0; i < sizeof widths / sizeof widths[0] && !sw; i++) {
        const size_t n = strip_ws(widths[i]);
        if (n && n <= FW_TILE_WS)
            sw = widths[i];
    }
    uint32_t stack = 0;
#ifdef FW_TARGET
    if (untiled <= FW_SRAM_BYTES) {
        pf->puts("error: the untiled engine would fit the SRAM: the case shows nothing");
        return 1;
    }
    if (!sw) {
        pf->puts("error: no strip width fits the workspace");
        return 1;
    }
    line(pf, "tiles: strip width ", (uint32_t)sw, " output columns");
    line(pf, "tiles: strips ", (uint32_t)((TW + sw - 1) / sw), "");
    line(pf, "tiles: strip workspace ", (uint32_t)strip_ws(sw), " bytes (largest strip)");
    line(pf, "tiles: workspace declared ", (uint32_t)sizeof tile_ws, " bytes");
    line(pf, "tiles: on-chip SRAM ", FW_SRAM_BYTES, " bytes (stack, data, bss; linker-checked)");
    /* the choice of width and depth, as this target sizes it (figures.sh) */
    for (int lv = 3; lv <= 5; lv++)
        for (size_t i = 0; i < sizeof widths / sizeof widths[0]; i++) {
            fw_line_t l = {.n = 0};
            fw_str(&l, "tiles: levels ");
            fw_dec(&l, (uint32_t)lv);
            fw_str(&l, " strip ");
            fw_dec(&l, (uint32_t)widths[i]);
            fw_str(&l, ": ");
            fw_dec(&l, (uint32_t)strip_ws_l(lv, widths[i]));
            fw_str(&l, " bytes");
            pf->puts(l.s);
        }
    for (int lv = 3; lv <= 5; lv++) {
        fw_line_t l = {.n = 0};
        config_l(&c, lv, TW, 0);
        fw_str(&l, "tiles: levels ");
        fw_dec(&l, (uint32_t)lv);
        fw_str(&l, " untiled: ");
        fw_dec(&l, (uint32_t)bloom_workspace_size(&c));
        fw_str(&l, " bytes");
        pf->puts(l.s);
    }
    if (run_strips(pf, sw, tile_dst, &stack))
        return 1;
    line(pf, "stack bloom_process tiles: ", stack, " bytes");
#else
    bloom_t *b;
    uint32_t unused;
    bloom_status_t st = pf->init(&b, tile_ws, sizeof tile_ws, &c, &unused);
    if (st == BLOOM_OK)
        st = pf->run(b, tile_src, tile_dst, TSTRIDE, &unused);
    if (st != BLOOM_OK) {
        pf->puts("error: untiled engine failed");
        return 1;
    }
    /* the host also renders the target's strips: the same bytes here too */
    if (!sw)
        sw = 64; /* host pointers are wider: its strips may not fit 32 KB */
    if (run_strips(pf, sw, host_ref, &stack)) {
        pf->puts("error: strips failed on the host");
        return 1;
    }
    for (size_t i = 0; i < sizeof host_ref; i++)
        if (host_ref[i] != tile_dst[i]) {
            pf->puts("error: host strips differ from the untiled frame");
            return 1;
        }
    line(pf, "tiles: host strips of ", (uint32_t)sw, " columns = untiled frame");
#endif
    uint32_t changed = 0;
    for (int y = 0; y < TH; y++)
        for (int x = 0; x < TW; x++) {
            const uint8_t *p = tile_dst + (size_t)y * TSTRIDE + (size_t)x * 2u;
            changed += ((uint32_t)p[0] | ((uint32_t)p[1] << 8)) != pixel(x, y);
        }
    frame_line(pf, "output", fw_fnv1a(tile_dst, sizeof tile_dst), " pixels changed", changed);
    if (!changed) {
        pf->puts("error: the bloom changed nothing");
        return 1;
    }
    return 0;
}
