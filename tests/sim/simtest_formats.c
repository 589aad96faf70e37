/* bloom_sim tests: image inputs (PGM, 16-bit PPM/PGM/PNG, PFM, PNG, JPEG,
 * OpenEXR), Y4M input and output, and the --compare statistics and the
 * side-by-side image against the float model run here. */
#include "harness.h"
#include "simtest_cases.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bloom_model.h"

void simtest_formats_counts(int *pass, int *fail)
{
    *pass = harness_pass;
    *fail = harness_fail;
}

static bloom_config_t cfg(int w, int h)
{
    bloom_config_t c;
    bloom_config_default(&c, w, h);
    return c;
}

/* Is the PFM at path exactly q[i] / 65536 (n samples, RGB)? */
static int pfm_is_q16(const char *path, const uint32_t *q, size_t n)
{
    img_t im;
    char err[256];
    if (img_read(path, &im, err, sizeof err) || !im.f32 || im.channels != 3 ||
        (size_t)im.width * (size_t)im.height * 3u != n) {
        img_free(&im);
        return 0;
    }
    int ok = 1;
    for (size_t i = 0; i < n; i++)
        if (im.f32[i] != (float)(q[i] / 65536.0)) {
            fprintf(stderr, "  %s sample %zu: %.9g, expected %.9g (q %u)\n", path, i, (double)im.f32[i],
                    q[i] / 65536.0, q[i]);
            ok = 0;
            break;
        }
    img_free(&im);
    return ok;
}

/* 16-bit rule: linear light q = round(c * 65536 / m), or sRGB-encoded. */
static uint32_t rule16(unsigned c, unsigned m, int srgb)
{
    return srgb ? (uint32_t)floor(bloom_srgb_to_linear((double)c / m) * 65536.0 + 0.5)
                : (uint32_t)(((uint64_t)c * 65536u + m / 2u) / m);
}

#define PASS_Q16 "--intensity", "0", "--out-format", "rgbq16"

static void test_16bit(void)
{
    static const unsigned codes[] = {0, 1, 32768, 65535, 12345, 40000, 255, 256, 60000};
    const int w = 3, h = 3; /* 9 RGB pixels from the codes, rotated per channel */
    img_t im;
    char err[256];
    uint32_t q[27], qs[27];
    CHECK(img_alloc(&im, w, h, 3, 65535) == 0);
    uint16_t px16[27];
    for (int i = 0; i < 27; i++) {
        im.u16[i] = px16[i] = (uint16_t)codes[(i + i / 3) % 9];
        q[i] = rule16(codes[(i + i / 3) % 9], 65535, 0);
        qs[i] = rule16(codes[(i + i / 3) % 9], 65535, 1);
    }
    CHECK(img_write_ppm(st_path("in16.ppm"), &im, err, sizeof err) == 0);
    img_free(&im);
    CHECKF(RUN(NULL, st_path("in16.ppm"), PASS_Q16, "-o", st_path("o16.pfm")) == 0, "%s", R.err);
    CHECKF(pfm_is_q16(st_path("o16.pfm"), q, 27), "16-bit PPM: linear rule");
    CHECK(strstr(R.out, "rgbq16 -> rgbq16") != NULL);
    CHECK(RUN(NULL, st_path("in16.ppm"), PASS_Q16, "--decode16", "srgb", "-o", st_path("o16s.pfm")) == 0);
    CHECKF(pfm_is_q16(st_path("o16s.pfm"), qs, 27), "16-bit PPM: --decode16 srgb");

    /* 16-bit PNG: the same rule */
    CHECK(st_write_png(st_path("in16.png"), px16, w, h, 3, 1) == 0);
    CHECK(RUN(NULL, st_path("in16.png"), PASS_Q16, "-o", st_path("o16p.pfm")) == 0);
    CHECKF(pfm_is_q16(st_path("o16p.pfm"), q, 27), "16-bit PNG: linear rule");

    /* 16-bit PGM with maxval 1000: grey replicated */
    static const unsigned g[6] = {0, 1, 333, 500, 999, 1000};
    uint32_t qg[18];
    CHECK(img_alloc(&im, 3, 2, 1, 1000) == 0);
    for (int i = 0; i < 6; i++) {
        im.u16[i] = (uint16_t)g[i];
        qg[3 * i] = qg[3 * i + 1] = qg[3 * i + 2] = rule16(g[i], 1000, 0);
    }
    CHECK(img_write_ppm(st_path("in16.pgm"), &im, err, sizeof err) == 0);
    img_free(&im);
    CHECK(RUN(NULL, st_path("in16.pgm"), PASS_Q16, "-o", st_path("o16g.pfm")) == 0);
    CHECKF(pfm_is_q16(st_path("o16g.pfm"), qg, 18), "16-bit PGM maxval 1000");
}

static void test_pfm_rule(void)
{
    const float v[12] = {NAN,   -1.0f, INFINITY, 300.0f, 0.5f,     255.99f,
                         1e-6f, -0.0f, 1.0f,     256.0f, 3.14159f, -INFINITY};
    img_t im;
    char err[256];
    uint32_t q[12];
    CHECK(img_alloc(&im, 2, 2, 3, 0) == 0);
    for (int i = 0; i < 12; i++)
        im.f32[i] = v[i], q[i] = img_float_to_q16(v[i]);
    CHECK(img_write_pfm(st_path("in.pfm"), &im, err, sizeof err) == 0);
    img_free(&im);
    CHECK(RUN(NULL, st_path("in.pfm"), PASS_Q16, "-o", st_path("opfm.pfm")) == 0);
    CHECKF(pfm_is_q16(st_path("opfm.pfm"), q, 12), "PFM NaN/Inf/negative rule");
    CHECK(q[0] == 0 && q[1] == 0 && q[2] == BLOOM_MAX_LINEAR && q[3] == BLOOM_MAX_LINEAR);

    if (!st_exr_built())
        return;
    /* OpenEXR, half and float: the PFM rule on the stored values */
    const float e[12] = {0.5f,   2.0f, 1.25f,    0.0f, 1000.0f, -2.0f,
                         0.125f, NAN,  INFINITY, 3.0f, 0.0625f, 255.0f};
    for (int i = 0; i < 12; i++)
        q[i] = img_float_to_q16(e[i]);
    for (int half = 0; half < 2; half++) {
        CHECK(st_write_exr(st_path("in.exr"), e, 4, 1, half) == 0);
        CHECKF(RUN(NULL, st_path("in.exr"), PASS_Q16, "-o", st_path("oexr.pfm")) == 0, "%s", R.err);
        CHECKF(pfm_is_q16(st_path("oexr.pfm"), q, 12), "OpenEXR %s", half ? "half" : "float");
    }
    /* an HDR source runs as rgbf32 by default (the floats as they are),
     * as rgbq16 when asked (the PFM rule); each bit-exact with the engine.
     * The values are not on the Q16.16 grid, so the two differ. */
    float big[24 * 16 * 3];
    uint32_t words[24 * 16 * 3], bits[24 * 16 * 3];
    for (int i = 0; i < 24 * 16 * 3; i++) {
        big[i] = (i % 97 == 0) ? 40.0f : (float)(i % 13) / 3000.0f;
        words[i] = img_float_to_q16(big[i]);
        memcpy(&bits[i], &big[i], 4);
    }
    CHECK(st_write_exr(st_path("big.exr"), big, 24, 16, 0) == 0);
    bloom_config_t c = cfg(24, 16);
    c.in_fmt = BLOOM_FMT_RGBF32;
    CHECK(RUN(NULL, st_path("big.exr"), "-o", st_path("oexr.png")) == 0);
    CHECK(strstr(R.out, "rgbf32 -> rgb888") != NULL);
    CHECK(output_matches_engine(st_path("oexr.png"), &c, bits));
    c.in_fmt = BLOOM_FMT_RGBQ16;
    CHECK(RUN(NULL, st_path("big.exr"), "--in-format", "rgbq16", "-o", st_path("oexq.png")) == 0);
    CHECK(output_matches_engine(st_path("oexq.png"), &c, words));
    CHECK(!output_matches_engine(st_path("oexr.png"), &c, words)); /* the two differ */
}

/* Forcing formats: an 8-bit source as rgbq16 is decoded to Q16.16 by the
 * documented rule; an HDR source as rgb888 is encoded, clipped at 1.0. */
static void test_forced_formats(const uint8_t *px, int w, int h)
{
    CHECK(write_ppm8(st_path("ff.ppm"), px, w, h, 3) == 0);
    const size_t n = (size_t)w * (size_t)h * 3u;
    uint32_t *q = malloc(n * sizeof *q);
    for (int lin = 0; q && lin < 2; lin++) {
        for (size_t i = 0; i < n; i++)
            q[i] = lin ? (px[i] * 65536u + 127u) / 255u
                       : (uint32_t)floor(bloom_srgb_to_linear(px[i] / 255.0) * 65536.0 + 0.5);
        CHECK(RUN(NULL, st_path("ff.ppm"), "--format", "rgbq16", "--intensity", "0", "-o", st_path("ff.pfm"),
                  lin ? "--linear" : "-q") == 0);
        CHECKF(pfm_is_q16(st_path("ff.pfm"), q, n), "8-bit into rgbq16 (%s)", lin ? "linear" : "sRGB");
    }
    free(q);
    const float v[6] = {0.0f, 0.001f, 0.2f, 0.5f, 1.0f, 7.0f};
    img_t im;
    char err[256];
    CHECK(img_alloc(&im, 2, 1, 3, 0) == 0);
    memcpy(im.f32, v, sizeof v);
    CHECK(img_write_pfm(st_path("ff.pfm"), &im, err, sizeof err) == 0);
    img_free(&im);
    for (int lin = 0; lin < 2; lin++) {
        CHECK(RUN(NULL, st_path("ff.pfm"), "--in-format", "rgb888", "--intensity", "0", "-o",
                  st_path("ff_c.ppm"), lin ? "--linear" : "-q") == 0);
        int ow, oh, ok;
        uint8_t *o = st_read_rgb8(st_path("ff_c.ppm"), &ow, &oh);
        ok = o && ow == 2 && oh == 1;
        for (int i = 0; ok && i < 6; i++) {
            double lv = img_float_to_q16(v[i]) / 65536.0, x = lv > 1 ? 1 : lv;
            double e = floor((lin ? x : bloom_linear_to_srgb(x)) * 255 + 0.5);
            ok = o[i] == e;
        }
        CHECKF(ok, "HDR into rgb888 (%s)", lin ? "linear" : "sRGB");
        free(o);
    }
}

void test_images(void)
{
    const int w = 23, h = 19;
    uint8_t px[23 * 19 * 3], grey[23 * 19], rep[23 * 19 * 3], rgba[23 * 19 * 4];
    make_scene(px, w, h, 5);
    for (int i = 0; i < w * h; i++) {
        grey[i] = px[3 * i + 1];
        rep[3 * i] = rep[3 * i + 1] = rep[3 * i + 2] = grey[i];
        memcpy(rgba + 4 * i, px + 3 * i, 3);
        rgba[4 * i + 3] = (uint8_t)(i * 7);
    }
    bloom_config_t c = cfg(w, h);
    /* PGM 8-bit: grey replicated */
    CHECK(write_ppm8(st_path("in.pgm"), grey, w, h, 1) == 0);
    CHECK(RUN(NULL, st_path("in.pgm"), "-o", st_path("opgm.ppm")) == 0);
    CHECKF(output_matches_engine(st_path("opgm.ppm"), &c, rep), "PGM");
    /* PNG 8-bit RGB, grey and RGBA (alpha dropped) */
    CHECK(st_write_png(st_path("in8.png"), px, w, h, 3, 0) == 0);
    CHECK(RUN(NULL, st_path("in8.png"), "-o", st_path("opng.png")) == 0);
    CHECKF(output_matches_engine(st_path("opng.png"), &c, px), "PNG RGB");
    CHECK(st_write_png(st_path("ing.png"), grey, w, h, 1, 0) == 0);
    CHECK(RUN(NULL, st_path("ing.png"), "-o", st_path("opngg.ppm")) == 0);
    CHECKF(output_matches_engine(st_path("opngg.ppm"), &c, rep), "PNG grey");
    CHECK(st_write_png_rgba(st_path("inrgba.png"), rgba, w, h) == 0);
    CHECK(RUN(NULL, st_path("inrgba.png"), "-o", st_path("orgba.ppm")) == 0);
    CHECKF(output_matches_engine(st_path("orgba.ppm"), &c, px), "PNG RGBA");
    /* JPEG colour and grey: the pixels libjpeg decodes */
    const char *jp[2] = {"in.jpg", "ing.jpg"};
    for (int k = 0; k < 2; k++) {
        CHECK(st_write_jpeg(st_path(jp[k]), k ? grey : px, w, h, k ? 1 : 3, 90) == 0);
        int jw, jh, jc;
        uint8_t *dec = st_decode_jpeg(st_path(jp[k]), &jw, &jh, &jc);
        CHECK(dec && jw == w && jh == h && jc == (k ? 1 : 3));
        uint8_t in[23 * 19 * 3];
        for (int i = 0; dec && i < w * h; i++)
            for (int ch = 0; ch < 3; ch++)
                in[3 * i + ch] = dec[jc == 3 ? 3 * i + ch : i];
        CHECKF(RUN(NULL, st_path(jp[k]), "-o", st_path("ojpg.png")) == 0, "%s", R.err);
        CHECKF(dec && output_matches_engine(st_path("ojpg.png"), &c, in), "JPEG %s", k ? "grey" : "RGB");
        free(dec);
    }
    test_16bit();
    test_pfm_rule();
    test_forced_formats(px, w, h);
}

/* ---- Y4M ------------------------------------------------------------------- */

/* Checks a --intensity 0 output against BT.601 in double, within 1 code. */
static int yuv_close(const uint8_t *o, int y, int u, int v, int full)
{
    double ys = full ? 1.0 : 255.0 / 219, cs = full ? 1.0 : 255.0 / 224, y0 = full ? 0 : 16;
    double yy = ys * (y - y0), uu = cs * (u - 128), vv = cs * (v - 128);
    double ref[3] = {yy + 1.402 * vv, yy - 0.344136 * uu - 0.714136 * vv, yy + 1.772 * uu};
    for (int c = 0; c < 3; c++) {
        double e = fmin(255, fmax(0, floor(ref[c] + 0.5)));
        if (fabs(o[c] - e) > 1)
            return 0;
    }
    return 1;
}

static void test_y4m_tag(const char *cs, const char *extra, int full)
{
    const int w = 9, h = 7, nf = 2;
    size_t fb = st_y4m_frame_bytes(w, h, cs);
    uint8_t *pl = malloc(fb * (size_t)nf);
    /* frame f: Y ramps along x, chroma constant per frame */
    static const int uv[2][2] = {{100, 150}, {170, 60}};
    for (int f = 0; pl && f < nf; f++) {
        uint8_t *p = pl + (size_t)f * fb;
        memset(p, 0, fb);
        for (int i = 0; i < w * h; i++)
            p[i] = (uint8_t)(40 + 20 * (i % w));
        size_t csz = (fb - (size_t)(w * h)) / 2;
        memset(p + w * h, uv[f][0], csz);
        memset(p + (size_t)(w * h) + csz, uv[f][1], csz);
    }
    CHECK(pl && st_write_y4m(st_path("tag.y4m"), extra, w, h, cs, pl, nf) == 0);
    CHECKF(RUN(NULL, st_path("tag.y4m"), "--intensity", "0", "-o", st_path("tag_%d.ppm")) == 0, "C%s: %s",
           cs ? cs : "(none)", R.err);
    int mono = cs && !strcmp(cs, "mono");
    for (int f = 0; f < nf; f++) {
        char name[32];
        snprintf(name, sizeof name, "tag_%d.ppm", f);
        int ow, oh, ok = 1;
        uint8_t *o = st_read_rgb8(st_path(name), &ow, &oh);
        ok = o && ow == w && oh == h;
        for (int i = 0; ok && i < w * h; i++)
            ok = yuv_close(o + 3 * i, 40 + 20 * (i % w), mono ? 128 : uv[f][0], mono ? 128 : uv[f][1], full);
        CHECKF(ok, "Y4M C%s%s frame %d", cs ? cs : "(none)", extra ? extra : "", f);
        free(o);
    }
    free(pl);
}

void test_video(void)
{
    test_y4m_tag("420jpeg", NULL, 0);
    test_y4m_tag("420paldv", NULL, 0);
    test_y4m_tag("420mpeg2", " XYSCSS=420MPEG2", 0);
    test_y4m_tag("422", NULL, 0);
    test_y4m_tag("444", NULL, 0);
    test_y4m_tag("mono", NULL, 0);
    test_y4m_tag(NULL, NULL, 0); /* no C tag: 4:2:0 */
    test_y4m_tag("420jpeg", " XCOLORRANGE=FULL", 1);

    /* 4:2:2 chroma placement: column pair x/2 of row y */
    const int w = 8, h = 4;
    uint8_t p[8 * 4 * 2];
    for (int i = 0; i < w * h; i++)
        p[i] = 120;
    for (int i = 0; i < w * h / 2; i++) {
        p[w * h + i] = (uint8_t)(60 + 13 * i);
        p[w * h + w * h / 2 + i] = (uint8_t)(200 - 9 * i);
    }
    CHECK(st_write_y4m(st_path("c422.y4m"), NULL, w, h, "422", p, 1) == 0);
    CHECK(RUN(NULL, st_path("c422.y4m"), "--intensity", "0", "-o", st_path("c422.ppm")) == 0);
    int ow, oh, ok;
    uint8_t *o = st_read_rgb8(st_path("c422.ppm"), &ow, &oh);
    ok = o && ow == w && oh == h;
    for (int y = 0; ok && y < h; y++)
        for (int x = 0; ok && x < w; x++) {
            int ci = y * (w / 2) + x / 2;
            ok = yuv_close(o + 3 * (y * w + x), 120, 60 + 13 * ci, 200 - 9 * ci, 0);
        }
    CHECKF(ok, "4:2:2 chroma placement");
    free(o);

    /* 3 frames of 33x17 (odd) to per-frame files and to a Y4M stream, also from a pipe */
    const int W = 33, H = 17, N = 3;
    size_t fb = st_y4m_frame_bytes(W, H, "420jpeg");
    uint8_t *pl = malloc(fb * N);
    for (size_t i = 0; pl && i < fb * N; i++)
        pl[i] = (uint8_t)(i % fb < (size_t)(W * H) ? 30 + (i * 7) % 200 : 100 + (i % 50));
    CHECK(pl && st_write_y4m(st_path("in.y4m"), NULL, W, H, "420jpeg", pl, N) == 0);
    CHECK(RUN(NULL, st_path("in.y4m"), "-o", st_path("v_%03d.png"), "--side-by-side", st_path("vs.y4m")) ==
          0);
    for (int f = 0; f < N; f++) {
        char name[32];
        snprintf(name, sizeof name, "v_%03d.png", f);
        uint8_t *q = st_read_rgb8(st_path(name), &ow, &oh);
        CHECKF(q && ow == W && oh == H, "Y4M frame %d output", f);
        free(q);
    }
    st_y4m_t y;
    CHECK(st_read_y4m(st_path("vs.y4m"), &y) == 0 && y.frames == N && y.w == 4 * W && y.h == H &&
          !strcmp(y.cs, "420jpeg"));
    free(y.planes);
    CHECK(RUN(st_path("in.y4m"), "-", "-o", st_path("vp.y4m")) == 0);
    CHECK(st_read_y4m(st_path("vp.y4m"), &y) == 0 && y.frames == N && y.w == W && y.h == H);
    size_t len;
    unsigned char *raw = st_read_file(st_path("vp.y4m"), &len);
    CHECK(raw && strstr((char *)raw, "F30000:1001") != NULL); /* input rate kept */
    free(raw);
    free(y.planes);
    free(pl);

    /* Y4M output levels: white 235, black 16, grey chroma 128 */
    uint8_t bw[8 * 4 * 3];
    for (int i = 0; i < 32; i++)
        memset(bw + 3 * i, i % 8 < 4 ? 255 : 0, 3);
    CHECK(write_ppm8(st_path("bw.ppm"), bw, 8, 4, 3) == 0);
    CHECK(RUN(NULL, st_path("bw.ppm"), "--intensity", "0", "-o", st_path("bw.y4m"), "--fps", "50") == 0);
    CHECK(st_read_y4m(st_path("bw.y4m"), &y) == 0 && y.frames == 1 && y.w == 8 && y.h == 4);
    CHECK(y.planes && y.planes[0] == 235 && y.planes[7] == 16 && y.planes[32] == 128 &&
          y.planes[32 + 8 + 3] == 128);
    free(y.planes);
    raw = st_read_file(st_path("bw.y4m"), &len);
    CHECK(raw && strstr((char *)raw, " F50:1 ") != NULL);
    free(raw);
}

/* ---- --compare, --bittrue, --side-by-side ------------------------------------------- */

void test_compare(void)
{
    const int w = 41, h = 23;
    uint8_t px[41 * 23 * 3];
    make_scene(px, w, h, 77);
    CHECK(write_ppm8(st_path("cmp.ppm"), px, w, h, 3) == 0);
    CHECKF(RUN(NULL, st_path("cmp.ppm"), "--compare", "--bittrue", "--threshold", "0.5", "--intensity", "3",
               "-o", st_path("cmp_out.ppm"), "--side-by-side", st_path("cmp_sbs.png"), "--diff-gain",
               "100") == 0,
           "%s", R.err);
    /* the float model here */
    bloom_config_t c = cfg(w, h);
    c.threshold = BLOOM_Q16(0.5);
    c.intensity = BLOOM_Q16(3);
    bloom_model_params_t p;
    memset(&p, 0, sizeof p);
    p.width = w, p.height = h, p.levels = c.levels;
    p.threshold = c.threshold / 65536.0, p.soft_knee = c.soft_knee / 65536.0, p.intensity = 3.0;
    uint32_t codes[41 * 23 * 3], fl[41 * 23 * 3];
    const int mx[3] = {255, 255, 255};
    for (int i = 0; i < w * h * 3; i++)
        codes[i] = px[i];
    CHECK(bloom_model_run(&p, codes, mx, fl, mx, NULL) > 0);
    int ow, oh;
    uint8_t *out = st_read_rgb8(st_path("cmp_out.ppm"), &ow, &oh);
    unsigned peak = 0, exact = 0, above = 0, below = 0;
    double sgn = 0;
    for (int i = 0; out && i < w * h * 3; i++) {
        const int e = (int)out[i] - (int)fl[i];
        const unsigned d = (unsigned)abs(e);
        peak = d > peak ? d : peak, exact += d == 0, sgn += e, above += e > 0, below += e < 0;
    }
    unsigned gp = 9999, ga = 0, gb = 0;
    double gm = -1, ge = -1;
    const char *l = strstr(R.out, "frame 0:");
    CHECKF(l && sscanf(strstr(l, "vs float:"),
                       "vs float: peak %u LSB, exact %lf%%, signed mean %lf LSB (%u above, %u below)", &gp,
                       &ge, &gm, &ga, &gb) == 5,
           "stats line: %s", R.out);
    CHECKF(gp == peak && fabs(gm - sgn / (w * h * 3)) < 1e-5 &&
               fabs(ge - 100.0 * exact / (w * h * 3)) < 1e-3 && ga == above && gb == below,
           "printed peak %u signed mean %g exact %g (%u / %u), expected %u %g %g (%u / %u)", gp, gm, ge, ga,
           gb, peak, sgn / (w * h * 3), 100.0 * exact / (w * h * 3), above, below);
    CHECK(peak <= 1);
    CHECK(strstr(R.out, "bit-true: 0 differ") != NULL);
    CHECK(strstr(R.out, "summary vs float model: peak") != NULL);
    CHECK(strstr(R.out, "summary vs bit-true model: 0 of 2829 samples differ") != NULL);
    CHECK(strstr(R.out, "summary: 1 frame, preset unity, engine per frame: mean") != NULL);
    /* side-by-side: input | fixed-point | float | |diff| * 100 */
    int sw, sh;
    uint8_t *s = st_read_rgb8(st_path("cmp_sbs.png"), &sw, &sh);
    int ok = s && out && sw == 4 * w && sh == h;
    for (int y = 0; ok && y < h; y++)
        for (int i = 0; ok && i < 3 * w; i++) {
            const uint8_t *r = s + (size_t)y * 12 * (size_t)w;
            int k = y * 3 * w + i, d = abs((int)out[k] - (int)fl[k]) * 100;
            ok = r[i] == px[k] && r[3 * w + i] == out[k] && r[6 * w + i] == fl[k] &&
                 r[9 * w + i] == (d > 255 ? 255 : d);
        }
    CHECKF(ok, "side-by-side panels");
    free(s);
    free(out);
    /* without --compare: no model figures */
    CHECK(RUN(NULL, st_path("cmp.ppm")) == 0 && strstr(R.out, "vs float") == NULL &&
          strstr(R.out, "engine") != NULL);
}
