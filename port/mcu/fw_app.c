/* Shared by the firmware and the host build: see fw_app.h. */
#include "fw_app.h"

/* The firmware puts the framebuffer in a linker section of its own (on a
 * real part: external RAM) so the figures count it apart from the engine. */
#ifdef FW_TARGET
#define FW_FB_ATTR __attribute__((section(".framebuffer")))
#else
#define FW_FB_ATTR
#endif
/* FW_WS_BYTES: the workspace declared; by default the header's constant
 * bound. A build may pass the exact bloom_workspace_size() instead. */
#ifndef FW_WS_BYTES
#define FW_WS_BYTES BLOOM_WORKSPACE_MAX(FW_W, FW_H, FW_LEVELS, 2, 0)
#endif

BLOOM_WORKSPACE_DEFINE(fw_ws, FW_WS_BYTES);
FW_FB_ATTR static uint8_t fw_fb[FW_H * FW_STRIDE] __attribute__((aligned(8)));

void fw_str(fw_line_t *l, const char *s)
{
    while (*s && l->n + 1 < sizeof l->s)
        l->s[l->n++] = *s++;
    l->s[l->n] = '\0';
}

void fw_dec(fw_line_t *l, uint32_t v)
{
    char t[11];
    int i = 10;
    t[i] = '\0';
    do {
        t[--i] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    fw_str(l, t + i);
}

void fw_hex(fw_line_t *l, uint32_t v)
{
    char t[11] = "0x";
    for (int i = 0; i < 8; i++)
        t[2 + i] = "0123456789abcdef"[(v >> (28 - 4 * i)) & 15u];
    t[10] = '\0';
    fw_str(l, t);
}

uint32_t fw_fnv1a(const uint8_t *p, size_t n)
{
    uint32_t h = 2166136261u;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 16777619u;
    }
    return h;
}

/* Lamps: centre, radius, RGB565 channels. White and saturated colours at
 * full code (linear 1.0, above the knee), one at the corner and one on the
 * right edge to exercise edge replication, and a one-pixel star. */
static const struct {
    int16_t x, y, r;
    uint8_t cr, cg, cb;
} lamps[] = {
    {60, 50, 9, 31, 63, 31},  {250, 40, 4, 31, 40, 6},   {160, 120, 14, 31, 63, 31}, {0, 0, 3, 31, 63, 31},
    {319, 180, 6, 8, 63, 31}, {100, 200, 2, 31, 20, 31}, {210, 150, 0, 31, 63, 31},  {280, 220, 5, 31, 63, 0},
};

static uint32_t mix(uint32_t h)
{
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

uint16_t fw_pattern_pixel(int x, int y)
{
    const uint32_t n = mix((uint32_t)x * 0x9e3779b1u ^ (uint32_t)y * 0x85ebca77u);
    uint32_t r = (uint32_t)x * 12u / FW_W + (n & 3u);
    uint32_t g = (uint32_t)y * 20u / FW_H + ((n >> 2) & 3u);
    uint32_t b = 4u + (uint32_t)(x + y) * 10u / (FW_W + FW_H) + ((n >> 4) & 3u);
    for (size_t i = 0; i < sizeof lamps / sizeof lamps[0]; i++) {
        const int dx = x - lamps[i].x, dy = y - lamps[i].y;
        if (dx * dx + dy * dy <= lamps[i].r * lamps[i].r) {
            r = lamps[i].cr;
            g = lamps[i].cg;
            b = lamps[i].cb;
        }
    }
    /* a neon bar: a bright line two pixels high */
    if (y >= 90 && y <= 91 && x >= 20 && x < 120) {
        r = 31;
        g = 10;
        b = 28;
    }
    return (uint16_t)((r << 11) | (g << 5) | b);
}

void fw_pattern(uint8_t *fb)
{
    for (int y = 0; y < FW_H; y++)
        for (int x = 0; x < FW_W; x++) {
            const uint16_t v = fw_pattern_pixel(x, y);
            uint8_t *p = fb + (size_t)y * FW_STRIDE + (size_t)x * 2u;
            p[0] = (uint8_t)v; /* RGB565 is little-endian by definition */
            p[1] = (uint8_t)(v >> 8);
        }
}

static void frame_head(fw_line_t *l)
{
    l->n = 0;
    fw_str(l, "frame 320x240 RGB565 levels ");
    fw_dec(l, FW_LEVELS);
    fw_str(l, ": ");
}

static void status_line(const fw_platform_t *pf, const char *what, bloom_status_t st)
{
    fw_line_t l = {.n = 0};
    fw_str(&l, "error: ");
    fw_str(&l, what);
    fw_str(&l, ": ");
    fw_str(&l, bloom_status_str(st));
    pf->puts(l.s);
}

static void stack_line(const fw_platform_t *pf, const char *call, uint32_t bytes)
{
    if (!bytes)
        return;
    fw_line_t l = {.n = 0};
    fw_str(&l, "stack ");
    fw_str(&l, call);
    fw_str(&l, " levels ");
    fw_dec(&l, FW_LEVELS);
    fw_str(&l, ": ");
    fw_dec(&l, bytes);
    fw_str(&l, " bytes");
    pf->puts(l.s);
}

/* Workspace of the default preset in RGB565 at a few frame sizes, from the
 * sizing function as compiled for this target (pointers are 4 bytes on
 * Cortex-M, 8 on x86-64, so the two differ). */
static void workspace_lines(const fw_platform_t *pf)
{
    static const int16_t sizes[][2] = {{160, 120}, {320, 240}, {640, 480}};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        bloom_config_t c;
        bloom_config_default(&c, sizes[i][0], sizes[i][1]);
        c.in_fmt = c.out_fmt = BLOOM_FMT_RGB565;
        fw_line_t l = {.n = 0};
        fw_str(&l, "workspace ");
        fw_dec(&l, (uint32_t)c.width);
        fw_str(&l, "x");
        fw_dec(&l, (uint32_t)c.height);
        fw_str(&l, " RGB565 levels 5: ");
        fw_dec(&l, (uint32_t)bloom_workspace_size(&c));
        fw_str(&l, " bytes exact, ");
        fw_dec(&l, (uint32_t)BLOOM_WORKSPACE_MAX(c.width, c.height, 5, 2, 0));
        fw_str(&l, " bytes BLOOM_WORKSPACE_MAX");
        pf->puts(l.s);
    }
    fw_line_t l = {.n = 0};
    fw_str(&l, "workspace declared: ");
    fw_dec(&l, (uint32_t)sizeof fw_ws);
    fw_str(&l, " bytes");
    pf->puts(l.s);
}

int fw_app(const fw_platform_t *pf)
{
    bloom_config_t cfg;
    bloom_info_t info;
    fw_line_t l;
    uint32_t stack_init = 0, stack_process = 0;

    /* the deepest pyramid this frame allows, for the report */
    bloom_config_default(&cfg, FW_W, FW_H);
    cfg.in_fmt = cfg.out_fmt = BLOOM_FMT_RGB565;
    cfg.levels = BLOOM_MAX_LEVELS;
    bloom_status_t st = bloom_query(&cfg, &info);
    if (st != BLOOM_OK) {
        status_line(pf, "bloom_query", st);
        return 1;
    }
    const int deepest = info.levels;

    cfg.levels = FW_LEVELS;
    bloom_t *b;
    st = pf->init(&b, fw_ws, sizeof fw_ws, &cfg, &stack_init);
    if (st != BLOOM_OK) {
        status_line(pf, "bloom_init", st);
        return 1;
    }
    if (bloom_query(&cfg, &info) != BLOOM_OK || info.levels != FW_LEVELS) {
        pf->puts("error: the pyramid built is not FW_LEVELS deep");
        return 1;
    }

    fw_pattern(fw_fb);
    frame_head(&l);
    fw_str(&l, "input fnv1a ");
    fw_hex(&l, fw_fnv1a(fw_fb, sizeof fw_fb));
    fw_str(&l, ", deepest pyramid ");
    fw_dec(&l, (uint32_t)deepest);
    fw_str(&l, " levels, latency ");
    fw_dec(&l, (uint32_t)info.latency_rows);
    fw_str(&l, " rows");
    pf->puts(l.s);

    st = pf->process(b, fw_fb, &stack_process); /* in place: the framebuffer is src and dst */
    if (st != BLOOM_OK) {
        status_line(pf, "bloom_process", st);
        return 1;
    }
    uint32_t changed = 0;
    for (int y = 0; y < FW_H; y++)
        for (int x = 0; x < FW_W; x++) {
            const uint8_t *p = fw_fb + (size_t)y * FW_STRIDE + (size_t)x * 2u;
            changed += ((uint32_t)p[0] | ((uint32_t)p[1] << 8)) != fw_pattern_pixel(x, y);
        }
    frame_head(&l);
    fw_str(&l, "output fnv1a ");
    fw_hex(&l, fw_fnv1a(fw_fb, sizeof fw_fb));
    fw_str(&l, ", ");
    fw_dec(&l, changed);
    fw_str(&l, " pixels changed");
    pf->puts(l.s);
    if (changed == 0) {
        pf->puts("error: the bloom changed nothing");
        return 1;
    }

    stack_line(pf, "bloom_init", stack_init);
    stack_line(pf, "bloom_process", stack_process);
    workspace_lines(pf);
    return 0;
}
