/* Seeds of fuzz_api (byte strings in the order fuzz_api.c and fuzz_api_config.c read them),
 * fuzz_cam_opts (argument lists, NUL-separated) and fuzz_cam_conv. */
#include "gen_seeds.h"

#include <stdio.h>
#include <string.h>

#include "bloom.h"

typedef struct {
    uint8_t b[2048];
    size_t n;
} seed_t;

static void add(seed_t *s, unsigned v)
{
    s->b[s->n++] = (uint8_t)v;
}

/* check_pure's bytes, the configuration (a preset's defaults), the frame
 * set-up; ops follow. fmt: 0 RGB888, 1 XRGB8888, 2 RGB565, 3 RGBQ16. */
static void head(seed_t *s, int preset, int w, int h, int fin, int fout, int levels, unsigned flags,
                 unsigned gaps)
{
    s->n = 0;
    add(s, 0); /* no name */
    add(s, 3), add(s, 0), add(s, 0), add(s, 0);
    add(s, 0); /* m: sizes, formats and depth in range, fields untouched */
    add(s, (unsigned)w - 1), add(s, (unsigned)h - 1), add(s, (unsigned)fin), add(s, (unsigned)fout);
    add(s, (unsigned)levels - 1), add(s, (unsigned)preset), add(s, flags);
    add(s, gaps), add(s, 0x12), add(s, 0x34), add(s, 0x56), add(s, 0x78);
    add(s, 1); /* pattern: dark with a few lights */
    add(s, (unsigned)preset % 4), add(s, 0xC3);
}

static void put_seed(const seed_t *s, const char *name)
{
    gs_put("api", name, s->b, s->n);
}

void gs_seeds_api(void)
{
    static const char *const pn[6] = {"unity", "gamedev", "xna", "attenuation", "arm", "cod"};
    seed_t s;
    char name[64];
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        const int w = 13 + 7 * p, h = 9 + 5 * p;
        /* row by row: push one, drain, to the end; then a pull past the end */
        head(&s, p, w, h, p % 4, (p + 1) % 4, 3 + p % 3, 0, 0);
        if (p == 3 || p == 4)
            add(&s, 9); /* bloom_set_aux */
        add(&s, 4);     /* pull before any push */
        for (int y = 0; y < h && s.n < sizeof s.b - 4; y++)
            add(&s, 1), add(&s, 7);
        add(&s, 7), add(&s, 4), add(&s, 1);
        snprintf(name, sizeof name, "gen-%s-rows.bin", pn[p]);
        put_seed(&s, name);
        /* bands of 5 rows, COPY_SOURCE and NO_SKIP, rows with gaps */
        head(&s, p, w, h, 0, 0, 5, 1 | 2, 7);
        add(&s, 9);
        for (int y = 0; y < h; y += 5)
            add(&s, 8), add(&s, 6);
        add(&s, 0), add(&s, 11), add(&s, 11 | 0x20), add(&s, 6);
        snprintf(name, sizeof name, "gen-%s-bands.bin", pn[p]);
        put_seed(&s, name);
    }
    /* misuse: NULLs, begin twice, push without pulling until BUSY, re-init */
    head(&s, 0, 64, 64, 3, 3, 2, 4, 0);
    add(&s, 10), add(&s, 0), add(&s, 0);
    for (int i = 0; i < 70; i++)
        add(&s, 1);
    add(&s, 7), add(&s, 11 | 0x10), add(&s, 11);
    put_seed(&s, "gen-misuse.bin");
    head(&s, 5, 64, 1, 1, 2, 16, 32 | 16, 3);
    add(&s, 11), add(&s, 1), add(&s, 4), add(&s, 4);
    put_seed(&s, "gen-cod-one-row-debug-linear.bin");

    /* bloom_cam's command lines: arguments NUL-separated */
#define ARGS(x)                                                                                              \
    {                                                                                                        \
        x, sizeof x - 1                                                                                      \
    }
    static const struct {
        const char *s;
        size_t n;
    } argv[] = {
        ARGS("--size\0"
             "320x240\0"
             "--format\0"
             "grey\0"
             "--threshold=0.8\0"
             "--stats"),
        ARGS("--preset\0"
             "cod\0"
             "--radius\0"
             "40\0"
             "--tint\0"
             "1,0.5,0.25\0"
             "--weights=0.1,0.2,0.3"),
        ARGS("--preset=attenuation\0"
             "--aux\0"
             "d.pgm\0"
             "--attenuation\0"
             "0.7\0"
             "--max-reduction\0"
             "0.2"),
        ARGS("--preset\0"
             "arm\0"
             "--baked\0"
             "--aux\0"
             "m.pgm\0"
             "--strength\0"
             "4"),
        ARGS("--preset\0"
             "xna\0"
             "--passes\0"
             "3\0"
             "--saturate\0"
             "--mode\0"
             "bloom-only"),
        ARGS("--preset\0"
             "gamedev\0"
             "--strength\0"
             "2.5\0"
             "--levels\0"
             "3\0"
             "--knee\0"
             "0"),
        ARGS("--device\0"
             "/dev/video1\0"
             "--fb\0"
             "none\0"
             "--buffers\0"
             "16\0"
             "--timeout\0"
             "5\0"
             "--frames\0"
             "9"),
        ARGS("--gpio-frame\0"
             "gpiochip0:17\0"
             "--gpio-button\0"
             "gpiochip0:27\0"
             "-q"),
        ARGS("--size\0"
             "641x480"),
        ARGS("--preset\0"
             "cod\0"
             "--radius\0"
             "40\0"
             "--levels\0"
             "3"),
        ARGS("--passes\0"
             "2"),
    };
    for (size_t i = 0; i < sizeof argv / sizeof argv[0]; i++) {
        snprintf(name, sizeof name, "gen-args-%zu.bin", i);
        gs_put("cam_opts", name, argv[i].s, argv[i].n);
    }
    uint8_t conv[96];
    for (size_t i = 0; i < sizeof conv; i++)
        conv[i] = (uint8_t)(i * 37 + 11);
    conv[0] = 0, conv[1] = 7; /* rows, 16 pixels */
    gs_put("cam_conv", "gen-rows.bin", conv, sizeof conv);
    conv[0] = 1, conv[1] = 2; /* a layout: 16 bpp */
    gs_put("cam_conv", "gen-layout.bin", conv, 12);
    conv[0] = 2; /* placement */
    gs_put("cam_conv", "gen-place.bin", conv, 9);
}
