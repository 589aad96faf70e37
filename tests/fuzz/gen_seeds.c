/* The seed corpora of the fuzz targets (tests/fuzz/README.md): small valid
 * files of every format and layout the readers tell apart, cut from
 * tests/data where a real picture helps, a truncated one of each, and the
 * regression seeds of the header-size checks (a header that claims more
 * than the engine takes, or more than the file holds). Writes
 * CORPUS/<target>/gen-* and regress-*; other files there (the reproducers
 * of fuzzer findings) are left alone.
 *   gen_seeds CORPUS_DIR DATA_DIR */
#include "gen_seeds.h"

#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bloom.h"
#include "imgio.h"

static const char *corpus;

static void put(const char *target, const char *name, const void *data, size_t len)
{
    char p[512];
    snprintf(p, sizeof p, "%s/%s/%s", corpus, target, name);
    FILE *f = fopen(p, "wb");
    if (!f || fwrite(data, 1, len, f) != len || fclose(f) != 0) {
        fprintf(stderr, "gen_seeds: cannot write %s\n", p);
        exit(1);
    }
}

static uint8_t *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    *len = (size_t)ftell(f);
    rewind(f);
    uint8_t *b = malloc(*len + 1);
    if (fread(b, 1, *len, f) != *len) {
        free(b);
        b = NULL;
    }
    fclose(f);
    return b;
}

/* A file written by a library, renamed into the corpus (and cut short as
 * a second seed when cut is given); returns its bytes (malloc'd). */
static uint8_t *adopt(const char *tmp, const char *target, const char *name, const char *cut, size_t *len)
{
    uint8_t *b = slurp(tmp, len);
    remove(tmp);
    if (!b) {
        fprintf(stderr, "gen_seeds: %s/%s not written\n", target, name);
        exit(1);
    }
    put(target, name, b, *len);
    if (cut)
        put(target, cut, b, *len * 2 / 3);
    return b;
}

static uint8_t *find(uint8_t *b, size_t len, const void *needle, size_t n)
{
    for (size_t i = 0; i + n <= len; i++)
        if (!memcmp(b + i, needle, n))
            return b + i;
    return NULL;
}

static void be32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24), p[1] = (uint8_t)(v >> 16), p[2] = (uint8_t)(v >> 8), p[3] = (uint8_t)v;
}

static uint32_t crc32_of(const uint8_t *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return ~c;
}

/* A copy of a PNG with its IHDR size (and interlace flag) replaced, CRC mended. */
static void png_resized(const uint8_t *png, size_t len, uint32_t w, uint32_t h, int interlace,
                        const char *name)
{
    uint8_t *b = malloc(len);
    memcpy(b, png, len);
    be32(b + 16, w);
    be32(b + 20, h);
    if (interlace >= 0)
        b[28] = (uint8_t)interlace;
    be32(b + 29, crc32_of(b + 12, 17));
    put("png", name, b, len);
    free(b);
}

/* ---- pictures --------------------------------------------------------------- */

#define W 16
#define H 12
static uint8_t pic[W * H * 3]; /* 8-bit codes around the brightest spot of rocket_floodlights */
static float hdr[W * H * 3];   /* linear floats around the brightest spot of studio_lamps */

static void cut_pictures(const char *data)
{
    char p[512];
    img_t im;
    char err[256];
    snprintf(p, sizeof p, "%s/rocket_floodlights.ppm", data);
    if (img_read(p, &im, err, sizeof err) || !im.u16) {
        fprintf(stderr, "gen_seeds: %s\n", err);
        exit(1);
    }
    size_t best = 0;
    for (size_t i = 0; i < (size_t)im.width * (size_t)im.height; i++)
        if (im.u16[3 * i] + im.u16[3 * i + 1] > im.u16[3 * best] + im.u16[3 * best + 1])
            best = i;
    int x0 = (int)(best % (size_t)im.width) - W / 2, y0 = (int)(best / (size_t)im.width) - H / 2;
    x0 = x0 < 0 ? 0 : x0 > im.width - W ? im.width - W : x0;
    y0 = y0 < 0 ? 0 : y0 > im.height - H ? im.height - H : y0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W * 3; x++)
            pic[y * W * 3 + x] =
                (uint8_t)im.u16[((size_t)(y0 + y) * (size_t)im.width + (size_t)x0) * 3 + (size_t)x];
    img_free(&im);
    snprintf(p, sizeof p, "%s/studio_lamps.pfm", data);
    if (img_read(p, &im, err, sizeof err) || !im.f32) {
        fprintf(stderr, "gen_seeds: %s\n", err);
        exit(1);
    }
    best = 0;
    for (size_t i = 0; i < (size_t)im.width * (size_t)im.height; i++)
        if (im.f32[3 * i] > im.f32[3 * best])
            best = i;
    x0 = (int)(best % (size_t)im.width) - W / 2, y0 = (int)(best / (size_t)im.width) - H / 2;
    x0 = x0 < 0 ? 0 : x0 > im.width - W ? im.width - W : x0;
    y0 = y0 < 0 ? 0 : y0 > im.height - H ? im.height - H : y0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W * 3; x++)
            hdr[y * W * 3 + x] = im.f32[((size_t)(y0 + y) * (size_t)im.width + (size_t)x0) * 3 + (size_t)x];
    img_free(&im);
}

/* ---- PNM and PFM -------------------------------------------------------------- */

/* A header, then the samples of pic as 8-bit, 16-bit (maxval mv) or
 * grey; n_px pixels (fewer than w*h: a truncated body). */
static void pnm(const char *target, const char *name, const char *header, int grey, int mv, size_t n_px)
{
    uint8_t *b = malloc(strlen(header) + n_px * 6);
    size_t n = strlen(header);
    memcpy(b, header, n);
    for (size_t i = 0; i < n_px; i++)
        for (int c = 0; c < (grey ? 1 : 3); c++) {
            const unsigned v = pic[(3 * i + (grey ? 1 : (unsigned)c)) % sizeof pic] * (unsigned)mv / 255u;
            if (mv > 255)
                b[n++] = (uint8_t)(v >> 8);
            b[n++] = (uint8_t)v;
        }
    put(target, name, b, n);
    free(b);
}

static void pfm(const char *name, const char *header, int grey, int big, size_t n_px, int special)
{
    uint8_t *b = malloc(strlen(header) + n_px * 12);
    size_t n = strlen(header);
    memcpy(b, header, n);
    static const float odd[] = {0.0f / 0.0f, 1.0f / 0.0f, -1.0f / 0.0f, -2.5f, 300.0f, 255.99f, 1e-9f};
    for (size_t i = 0; i < n_px; i++)
        for (int c = 0; c < (grey ? 1 : 3); c++) {
            float v = hdr[(3 * i + (unsigned)c) % (sizeof hdr / sizeof hdr[0])];
            if (special)
                v = odd[(i * 3 + (unsigned)c) % 7];
            uint32_t u;
            memcpy(&u, &v, 4);
            for (int k = 0; k < 4; k++)
                b[n++] = (uint8_t)(u >> (8 * (big ? 3 - k : k)));
        }
    put("pfm", name, b, n);
    free(b);
}

static void seeds_pnm(void)
{
    char h[64];
    snprintf(h, sizeof h, "P6\n%d %d\n255\n", W, H);
    pnm("ppm", "gen-rocket.ppm", h, 0, 255, W * H);
    pnm("ppm", "gen-cut.ppm", h, 0, 255, W * H / 2);
    snprintf(h, sizeof h, "P5\n# a comment\n%d %d\n255\n", W, H);
    pnm("ppm", "gen-grey.pgm", h, 1, 255, W * H);
    snprintf(h, sizeof h, "P6 %d\t%d\r65535\n", W, H);
    pnm("ppm", "gen-16bit.ppm", h, 0, 65535, W * H);
    snprintf(h, sizeof h, "P5\n%d %d\n1000\n", W, H);
    pnm("ppm", "gen-maxval1000.pgm", h, 1, 1000, W * H);
    snprintf(h, sizeof h, "P6\n%d %d\n15\n", W / 2, H / 2);
    pnm("ppm", "gen-maxval15.ppm", h, 0, 15, W * H / 4);
    pnm("ppm", "regress-claims-16384x16384-body-short.ppm", "P6\n16384 16384\n255\n", 0, 255, 20);
    pnm("ppm", "regress-width-above-limit.ppm", "P6\n16385 2\n255\n", 0, 255, 40);
    pnm("ppm", "regress-height-above-limit.pgm", "P5\n2 20000\n255\n", 1, 255, 40);

    snprintf(h, sizeof h, "PF\n%d %d\n-1.0\n", W, H);
    pfm("gen-studio-le.pfm", h, 0, 0, W * H, 0);
    pfm("gen-cut.pfm", h, 0, 0, W * H / 2, 0);
    snprintf(h, sizeof h, "PF\n%d %d\n1.0\n", W / 2, H / 2);
    pfm("gen-big-endian.pfm", h, 0, 1, W * H / 4, 0);
    snprintf(h, sizeof h, "Pf\n%d %d\n-1\n", W, H);
    pfm("gen-grey.pfm", h, 1, 0, W * H, 0);
    pfm("gen-nan-inf-negative.pfm", "PF\n7 1\n-1.0\n", 0, 0, 7, 1);
    pfm("regress-claims-16384x16384-body-short.pfm", "PF\n16384 16384\n-1.0\n", 0, 0, 8, 0);
    pfm("regress-width-above-limit.pfm", "Pf\n30000 1\n-1.0\n", 1, 0, 8, 0);
}

/* ---- PNG, JPEG, OpenEXR ----------------------------------------------------------- */

static void seeds_png(void)
{
    const char *t = "png.tmp";
    size_t len;
    uint8_t *b;
    if (gs_png(t, pic, W, H, PNG_COLOR_TYPE_RGB, 8, 0) == 0) {
        b = adopt(t, "png", "gen-rgb8.png", "gen-cut.png", &len);
        png_resized(b, len, 16384, 16384, -1, "regress-claims-16384x16384-body-short.png");
        png_resized(b, len, 20000, 8, -1, "regress-width-above-limit.png");
        png_resized(b, len, 16384, 16384, 1, "regress-interlaced-claims-16384x16384.png");
        free(b);
    }
    static const struct {
        int color, depth, interlace;
        const char *name;
    } v[] = {{PNG_COLOR_TYPE_GRAY, 1, 0, "gen-grey1.png"},
             {PNG_COLOR_TYPE_GRAY, 16, 0, "gen-grey16.png"},
             {PNG_COLOR_TYPE_PALETTE, 4, 0, "gen-palette4-trns.png"},
             {PNG_COLOR_TYPE_RGBA, 16, 0, "gen-rgba16.png"},
             {PNG_COLOR_TYPE_GRAY_ALPHA, 8, 0, "gen-greyalpha8.png"},
             {PNG_COLOR_TYPE_RGB, 8, 1, "gen-interlaced.png"}};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (gs_png(t, pic, W, H, v[i].color, v[i].depth, v[i].interlace) == 0)
            free(adopt(t, "png", v[i].name, NULL, &len));
}

/* A copy of a JPEG with its frame header's size replaced. */
static void jpeg_resized(uint8_t *b, size_t len, unsigned sof, unsigned w, unsigned h, const char *name)
{
    uint8_t *c = malloc(len);
    memcpy(c, b, len);
    const uint8_t m[2] = {0xFF, (uint8_t)sof};
    uint8_t *s = find(c, len, m, 2);
    if (s) {
        s[5] = (uint8_t)(h >> 8), s[6] = (uint8_t)h, s[7] = (uint8_t)(w >> 8), s[8] = (uint8_t)w;
        put("jpeg", name, c, len);
    }
    free(c);
}

static void seeds_jpeg(void)
{
    const char *t = "jpeg.tmp";
    size_t len;
    uint8_t *b;
    if (gs_jpeg(t, pic, W, H, 0, 0, 0, 1, 0) == 0) {
        b = adopt(t, "jpeg", "gen-420.jpg", "gen-cut.jpg", &len);
        /* the known finding: a header of 13362 x 64831 made bloom_sim allocate ~5 GB */
        jpeg_resized(b, len, 0xC0, 13362, 64831, "regress-13362x64831.jpg");
        jpeg_resized(b, len, 0xC0, 16384, 16384, "regress-baseline-claims-16384x16384.jpg");
        free(b);
    }
    if (gs_jpeg(t, pic, W, H, 0, 1, 0, 1, 0) == 0) {
        b = adopt(t, "jpeg", "gen-progressive.jpg", NULL, &len);
        jpeg_resized(b, len, 0xC2, 16384, 16384, "regress-progressive-claims-16384x16384.jpg");
        jpeg_resized(b, len, 0xC2, 40000, 3, "regress-progressive-width-above-limit.jpg");
        free(b);
    }
    static const struct {
        int grey, prog, arith, sub, restart;
        const char *name;
    } v[] = {{0, 0, 0, 0, 0, "gen-444.jpg"},
             {1, 0, 0, 0, 0, "gen-grey.jpg"},
             {0, 0, 1, 1, 0, "gen-arith.jpg"},
             {0, 1, 1, 0, 0, "gen-progressive-arith.jpg"},
             {0, 0, 0, 1, 1, "gen-restart.jpg"}};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (gs_jpeg(t, pic, W, H, v[i].grey, v[i].prog, v[i].arith, v[i].sub, v[i].restart) == 0)
            free(adopt(t, "jpeg", v[i].name, NULL, &len));
}

/* A copy of an EXR with its dataWindow's max corner replaced. */
static void exr_resized(const uint8_t *b, size_t len, int32_t xmax, int32_t ymax, const char *name)
{
    uint8_t *c = malloc(len);
    memcpy(c, b, len);
    uint8_t *dw = find(c, len, "dataWindow\0box2i\0", 17);
    if (dw) {
        uint8_t *v = dw + 17 + 4 + 8; /* name, type, size, then xMin yMin xMax yMax (LE) */
        for (int k = 0; k < 4; k++)
            v[k] = (uint8_t)((uint32_t)xmax >> (8 * k)), v[4 + k] = (uint8_t)((uint32_t)ymax >> (8 * k));
        put("exr", name, c, len);
    }
    free(c);
}

static void seeds_exr(void)
{
    const char *t = "exr.tmp";
    size_t len;
    /* compression: 0 none, 1 RLE, 2 ZIPS, 3 ZIP, 4 PIZ, 5 PXR24, 6 B44 (OpenEXRCore 3.1 writes no DWA) */
    static const struct {
        int nch, half, comp, tile;
        const char *name;
    } v[] = {{3, 0, 0, 0, "gen-float-none.exr"}, {3, 1, 3, 0, "gen-half-zip.exr"},
             {3, 1, 1, 0, "gen-half-rle.exr"},   {3, 1, 4, 0, "gen-half-piz.exr"},
             {1, 1, 2, 0, "gen-y-zips.exr"},     {4, 1, 5, 0, "gen-rgba-pxr24.exr"},
             {3, 1, 6, 0, "gen-half-b44.exr"},   {3, 0, 0, 4, "gen-tiled.exr"}};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (gs_exr(t, hdr, W, H, v[i].nch, v[i].half, v[i].comp, v[i].tile) == 0) {
            uint8_t *b = adopt(t, "exr", v[i].name, i == 0 ? "gen-cut.exr" : NULL, &len);
            if (i == 0) {
                exr_resized(b, len, 19999, H - 1, "regress-width-above-limit.exr");
                exr_resized(b, len, 16383, 16383, "regress-claims-16384x16384.exr");
            }
            free(b);
        }
}

/* ---- Y4M and raw dumps ---------------------------------------------------------------- */

static void y4m(const char *name, const char *header, size_t frame, int frames, size_t cut,
                const char *frame_hdr)
{
    size_t hl = strlen(header), fl = strlen(frame_hdr);
    uint8_t *b = malloc(hl + (size_t)frames * (fl + frame));
    size_t n = hl;
    memcpy(b, header, hl);
    for (int f = 0; f < frames; f++) {
        memcpy(b + n, frame_hdr, fl);
        n += fl;
        for (size_t i = 0; i < frame; i++)
            b[n++] = pic[(i * 3 + (size_t)f) % sizeof pic];
    }
    put("y4m", name, b, n - cut);
    free(b);
}

static void seeds_video(void)
{
    y4m("gen-420jpeg-2frames.y4m", "YUV4MPEG2 W16 H12 F30000:1001 Ip A1:1 C420jpeg\n", 16 * 12 + 2 * 8 * 6, 2,
        0, "FRAME\n");
    y4m("gen-cut.y4m", "YUV4MPEG2 W16 H12 F25:1 C420jpeg\n", 16 * 12 + 2 * 8 * 6, 2, 50, "FRAME\n");
    y4m("gen-420paldv-odd.y4m", "YUV4MPEG2 W7 H5 C420paldv XCOLORRANGE=FULL\n", 35 + 2 * 4 * 3, 1, 0,
        "FRAME Ixyz\n");
    y4m("gen-422.y4m", "YUV4MPEG2 W8 H4 C422 XCOLORRANGE=LIMITED\n", 32 + 2 * 4 * 4, 1, 0, "FRAME\n");
    y4m("gen-444.y4m", "YUV4MPEG2 W6 H4 C444\n", 3 * 24, 1, 0, "FRAME\n");
    y4m("gen-mono.y4m", "YUV4MPEG2 W9 H3 Cmono\n", 27, 3, 0, "FRAME\n");
    y4m("gen-no-colour-tag.y4m", "YUV4MPEG2 H2 W2\n", 4 + 2, 1, 0, "FRAME\n");
    y4m("gen-bad-frame-header.y4m", "YUV4MPEG2 W2 H2 C444\n", 12, 2, 0, "FRAMX\n");
    y4m("regress-claims-16384x16384-stream.y4m", "YUV4MPEG2 W16384 H16384 C444\n", 300, 1, 0, "FRAME\n");
    y4m("regress-width-above-limit.y4m", "YUV4MPEG2 W16385 H2 C444\n", 30, 1, 0, "FRAME\n");

    /* raw: 7 bytes choose format, size and stride (fuzz_raw.c), then the dump */
    static const char *const fmt[4] = {"yuyv", "rgb24", "grey", "rgb565"};
    static const int bpp[4] = {2, 3, 1, 2};
    for (int f = 0; f < 4; f++) {
        for (int pad = 0; pad < 2; pad++) {
            const int w = 16, h = 8, stride = w * bpp[f] + (pad ? 4 : 0);
            const size_t frame = (size_t)stride * (size_t)h, n = 7 + 2 * frame + (pad ? 10 : 0);
            uint8_t *b = malloc(n);
            /* packed (bit 3) or a stride of w*bpp + st%8 - 2 */
            b[0] = (uint8_t)(f | (pad ? 0 : 8));
            b[1] = (uint8_t)(w - 1), b[2] = 0, b[3] = (uint8_t)(h - 1), b[4] = 0, b[5] = 6, b[6] = 0;
            for (size_t i = 7; i < n; i++)
                b[i] = pic[i % sizeof pic];
            char name[64];
            snprintf(name, sizeof name, pad ? "gen-%s-stride-partial.raw" : "gen-%s-2frames.raw", fmt[f]);
            put("raw", name, b, n);
            free(b);
        }
    }
    /* a stride of 1 + 65535 * 16 bytes and 64 rows: 64 MiB frames, 100 bytes given */
    uint8_t big[7 + 100] = {1 | 16, 15, 0, 63, 0, 0xFF, 0xFF};
    put("raw", "regress-huge-stride-short.raw", big, sizeof big);
    uint8_t wide[7 + 100] = {2 | 4 | 8, 0x20, 0x4E, 1, 0, 0, 0}; /* 20000 x 1 GREY, any size allowed */
    put("raw", "regress-width-above-limit.raw", wide, sizeof wide);
}

/* ---- aux planes -------------------------------------------------------------------------- */

static void seeds_aux(void)
{
    char h[64];
    snprintf(h, sizeof h, "P5\n%d %d\n255\n", W, H);
    pnm("aux", "gen-8bit.pgm", h, 1, 255, W * H);
    pnm("aux", "gen-cut.pgm", h, 1, 255, W * H / 2);
    snprintf(h, sizeof h, "P5 #depth\n%d %d\n65535\n", W, H);
    pnm("aux", "gen-16bit.pgm", h, 1, 65535, W * H);
    snprintf(h, sizeof h, "P5\n%d\n%d\n1000\n", W / 2, H / 2);
    pnm("aux", "gen-maxval1000.pgm", h, 1, 1000, W * H / 4);
    snprintf(h, sizeof h, "P6\n%d %d\n255\n", 2, 2);
    pnm("aux", "gen-rgb-refused.ppm", h, 0, 255, 4);
    pnm("aux", "regress-claims-16384x16384-body-short.pgm", "P5\n16384 16384\n255\n", 1, 255, 30);
    pnm("aux", "regress-width-above-limit.pgm", "P5\n20000 1\n65535\n", 1, 65535, 30);
    const char *t = "aux.tmp";
    size_t len;
    if (gs_png(t, pic, W, H, PNG_COLOR_TYPE_GRAY, 8, 0) == 0)
        free(adopt(t, "aux", "gen-grey8.png", NULL, &len));
    if (gs_png(t, pic, W, H, PNG_COLOR_TYPE_GRAY, 16, 1) == 0)
        free(adopt(t, "aux", "gen-grey16-interlaced.png", NULL, &len));
    if (gs_png(t, pic, 4, 4, PNG_COLOR_TYPE_RGB, 8, 0) == 0)
        free(adopt(t, "aux", "gen-rgb-refused.png", NULL, &len));
}

void gs_put(const char *target, const char *name, const void *data, size_t len)
{
    put(target, name, data, len);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: gen_seeds CORPUS_DIR DATA_DIR\n");
        return 2;
    }
    corpus = argv[1];
    cut_pictures(argv[2]);
    seeds_pnm();
    seeds_png();
    seeds_jpeg();
    seeds_exr();
    seeds_video();
    seeds_aux();
    gs_seeds_api();
    return 0;
}
