/* Tests of build/bloom_sim (sim/docs/simulator.md): inputs of every format
 * generated in a temp dir, the tool run on them, its outputs decoded and
 * checked (size, frame count, and bit for bit against bloom_process run
 * here, or against the documented conversion rules through --intensity 0,
 * where the engine's output equals its input), the --compare statistics
 * against the float model run here. Malformed inputs: simtest_errors.c.
 *
 *   simtest TOOL [TOOL2]   TOOL gets every test (the sanitized build);
 *                          TOOL2 (build/bloom_sim) the bit-exact ones. */
#include "harness.h"
#include "simtest.h"
#include "simtest_cases.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bloom_model.h"

st_run_t R;
const char *tool;

/* Dark noise with a few bright blobs, so the bloom has work to do. */
void make_scene(uint8_t *rgb, int w, int h, uint32_t seed)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int c = 0; c < 3; c++) {
                seed = seed * 1664525u + 1013904223u;
                int v = (int)(seed >> 27) + 10 * c;
                int dx = x - w / 3, dy = y - h / 2, dx2 = x - (3 * w) / 4, dy2 = y - h / 4;
                if (dx * dx + dy * dy < 9 || dx2 * dx2 + dy2 * dy2 < 4)
                    v = 250 - 5 * c;
                rgb[3 * ((size_t)y * (size_t)w + (size_t)x) + (size_t)c] = (uint8_t)v;
            }
}

int write_ppm8(const char *path, const uint8_t *px, int w, int h, int channels)
{
    img_t im;
    char err[256];
    if (img_alloc(&im, w, h, channels, 255))
        return -1;
    for (size_t i = 0; i < (size_t)w * (size_t)h * (size_t)channels; i++)
        im.u16[i] = px[i];
    int rc = img_write_ppm(path, &im, err, sizeof err);
    img_free(&im);
    return rc;
}

/* Does the tool's output file equal the engine run here with c on src? */
int output_matches_engine(const char *path, const bloom_config_t *c, const void *src)
{
    int w, h;
    const size_t n = (size_t)c->width * (size_t)c->height;
    uint8_t *got = st_read_rgb8(path, &w, &h);
    uint8_t *dst = malloc(n * 12);
    int ok = got && dst && w == c->width && h == c->height && st_engine(c, src, dst) == 0;
    int maxv[3] = {255, 255, 255};
    for (size_t i = 0; ok && i < n; i++) {
        uint32_t v[3];
        switch (c->out_fmt) {
        case BLOOM_FMT_RGB888:
            v[0] = dst[3 * i], v[1] = dst[3 * i + 1], v[2] = dst[3 * i + 2];
            break;
        case BLOOM_FMT_XRGB8888:
            v[0] = dst[4 * i + 2], v[1] = dst[4 * i + 1], v[2] = dst[4 * i];
            break;
        default: { /* RGB565, shown with the documented rule round(c * 255 / max) */
            uint32_t wd = (uint32_t)dst[2 * i] | (uint32_t)dst[2 * i + 1] << 8;
            v[0] = wd >> 11, v[1] = (wd >> 5) & 63, v[2] = wd & 31;
            maxv[0] = maxv[2] = 31, maxv[1] = 63;
            break;
        }
        }
        for (int k = 0; k < 3; k++)
            ok &= got[3 * i + (size_t)k] == (v[k] * 255u + (uint32_t)maxv[k] / 2u) / (uint32_t)maxv[k];
    }
    free(got);
    free(dst);
    return ok;
}

static bloom_config_t cfg(int w, int h)
{
    bloom_config_t c;
    bloom_config_default(&c, w, h);
    return c;
}

/* ---- bit-exact runs: PPM, PNG, raw ------------------------------------------------ */

static void test_bitexact_ppm(void)
{
    const int w = 37, h = 29;
    uint8_t px[37 * 29 * 3];
    make_scene(px, w, h, 1);
    CHECK(write_ppm8(st_path("in.ppm"), px, w, h, 3) == 0);
    bloom_config_t c = cfg(w, h);
    CHECKF(RUN(NULL, st_path("in.ppm"), "-o", st_path("out.ppm")) == 0, "%s", R.err);
    CHECKF(output_matches_engine(st_path("out.ppm"), &c, px), "%s: PPM output differs from bloom_process",
           tool);
    CHECKF(R.err[0] == '\0', "stderr not quiet: %s", R.err); /* not a terminal: no progress */

    c.levels = 3;
    c.threshold = BLOOM_Q16(0.4);
    c.soft_knee = BLOOM_Q16(0.25);
    c.intensity = BLOOM_Q16(2.5);
    CHECK(RUN(NULL, st_path("in.ppm"), "-o", st_path("out.png"), "--levels", "3", "--threshold", "0.4",
              "--knee=0.25", "--intensity", "2.5") == 0);
    CHECKF(output_matches_engine(st_path("out.png"), &c, px), "%s: PNG output differs", tool);

    c = cfg(w, h);
    c.flags = BLOOM_FLAG_LINEAR | BLOOM_FLAG_COPY_SOURCE;
    CHECK(RUN(NULL, st_path("in.ppm"), "-o", st_path("out.ppm"), "--linear", "--copy-source") == 0);
    CHECK(output_matches_engine(st_path("out.ppm"), &c, px));

    c = cfg(w, h);
    c.flags = BLOOM_FLAG_DEBUG_VIEW;
    CHECK(RUN(NULL, st_path("in.ppm"), "-o", st_path("out.ppm"), "--view", "bloom") == 0);
    CHECKF(output_matches_engine(st_path("out.ppm"), &c, px), "--view bloom differs");

    /* board formats: XRGB8888 carries the same codes; RGB565 input is the
     * 8-bit code rounded to 5/6 bits */
    c = cfg(w, h);
    c.in_fmt = c.out_fmt = BLOOM_FMT_XRGB8888;
    uint8_t x[37 * 29 * 4], p565[37 * 29 * 2];
    for (int i = 0; i < w * h; i++) {
        x[4 * i] = px[3 * i + 2], x[4 * i + 1] = px[3 * i + 1], x[4 * i + 2] = px[3 * i], x[4 * i + 3] = 0xFF;
        unsigned r5 = (px[3 * i] * 31u + 127u) / 255u, g6 = (px[3 * i + 1] * 63u + 127u) / 255u,
                 b5 = (px[3 * i + 2] * 31u + 127u) / 255u, wd = r5 << 11 | g6 << 5 | b5;
        p565[2 * i] = (uint8_t)wd, p565[2 * i + 1] = (uint8_t)(wd >> 8);
    }
    CHECK(RUN(NULL, st_path("in.ppm"), "-o", st_path("out.ppm"), "--format", "xrgb8888") == 0);
    CHECK(output_matches_engine(st_path("out.ppm"), &c, x));
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGB565;
    CHECK(RUN(NULL, st_path("in.ppm"), "-o", st_path("out.ppm"), "--format", "rgb565") == 0);
    CHECKF(output_matches_engine(st_path("out.ppm"), &c, p565), "--format rgb565 differs");
    c.out_fmt = BLOOM_FMT_RGB888;
    CHECK(RUN(NULL, st_path("in.ppm"), "-o", st_path("out.ppm"), "--in-format", "rgb565") == 0);
    CHECK(output_matches_engine(st_path("out.ppm"), &c, p565));
    CHECK(strstr(R.out, "rgb565 -> rgb888") != NULL);
}

static void test_bitexact_raw(void)
{
    const int w = 20, h = 12, nf = 3;
    uint8_t px[3][20 * 12 * 3];
    for (int f = 0; f < nf; f++)
        make_scene(px[f], w, h, 10u + (uint32_t)f);
    CHECK(st_write_file(st_path("in.rgb"), px, sizeof px) == 0);
    CHECKF(RUN(NULL, st_path("in.rgb"), "--raw-size", "20x12", "--raw-format", "rgb24", "-o",
               st_path("raw_%02d.ppm")) == 0,
           "%s", R.err);
    bloom_config_t c = cfg(w, h);
    char name[32];
    for (int f = 0; f < nf; f++) {
        snprintf(name, sizeof name, "raw_%02d.ppm", f);
        CHECKF(output_matches_engine(st_path(name), &c, px[f]), "%s: raw frame %d differs", tool, f);
    }
    CHECK(strstr(R.out, "frame 2:") != NULL && strstr(R.out, "frame 3:") == NULL);
    /* the same through standard input (the streaming path) */
    CHECK(RUN(st_path("in.rgb"), "-", "--raw-size=20x12", "--raw-format=RGB3", "-o",
              st_path("pipe_%d.png")) == 0);
    CHECK(output_matches_engine(st_path("pipe_2.png"), &c, px[2]));
    /* --frames */
    remove(st_path("raw_02.ppm"));
    CHECK(RUN(NULL, st_path("in.rgb"), "--raw-size", "20x12", "--raw-format", "rgb24", "--frames", "2", "-o",
              st_path("raw_%02d.ppm")) == 0);
    int w2, h2;
    uint8_t *p = st_read_rgb8(st_path("raw_02.ppm"), &w2, &h2);
    CHECK(p == NULL);
    free(p);
}

static void test_raw_formats(void)
{
    const int w = 16, h = 10;
    /* RGB565 dump: engine input rgb565 by default, output rgb888 */
    uint8_t p565[2][16 * 10 * 2], rgb[16 * 10 * 3];
    for (int f = 0; f < 2; f++) {
        make_scene(rgb, w, h, 20u + (uint32_t)f);
        for (int i = 0; i < w * h; i++) {
            unsigned wd = (rgb[3 * i] >> 3) << 11 | (rgb[3 * i + 1] >> 2) << 5 | rgb[3 * i + 2] >> 3;
            p565[f][2 * i] = (uint8_t)wd, p565[f][2 * i + 1] = (uint8_t)(wd >> 8);
        }
    }
    CHECK(st_write_file(st_path("in.565"), p565, sizeof p565) == 0);
    bloom_config_t c = cfg(w, h);
    c.in_fmt = BLOOM_FMT_RGB565;
    CHECK(RUN(NULL, st_path("in.565"), "--raw-size", "16x10", "--raw-format", "rgb565", "-o",
              st_path("r565_%d.ppm")) == 0);
    CHECK(output_matches_engine(st_path("r565_1.ppm"), &c, p565[1]));
    c.out_fmt = BLOOM_FMT_RGB565;
    CHECK(RUN(NULL, st_path("in.565"), "--raw-size", "16x10", "--raw-format", "RGBP", "--out-format",
              "rgb565", "-o", st_path("r565_%d.png")) == 0);
    CHECK(output_matches_engine(st_path("r565_0.png"), &c, p565[0]));

    /* GREY: Y replicated to R, G, B (full range) */
    uint8_t grey[16 * 10], rep[16 * 10 * 3];
    for (int i = 0; i < w * h; i++)
        grey[i] = (uint8_t)(i * 37 % 256), rep[3 * i] = rep[3 * i + 1] = rep[3 * i + 2] = grey[i];
    CHECK(st_write_file(st_path("in.grey"), grey, sizeof grey) == 0);
    c = cfg(w, h);
    CHECK(RUN(NULL, st_path("in.grey"), "--raw-size", "16x10", "--raw-format", "grey", "-o",
              st_path("grey.ppm")) == 0);
    CHECK(output_matches_engine(st_path("grey.ppm"), &c, rep));

    /* YUYV, with a padded stride: known colours through --intensity 0 */
    static const int yuv[6][3] = {{235, 128, 128}, {16, 128, 128}, {81, 90, 240},
                                  {145, 54, 34},   {41, 240, 110}, {126, 128, 128}};
    const int stride = 2 * w + 8;
    uint8_t yuyv[10 * (2 * 16 + 8)];
    memset(yuyv, 0xEE, sizeof yuyv);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x += 2) {
            const int *k = yuv[(y * w + x) / 2 % 6];
            uint8_t *q = yuyv + (size_t)y * (size_t)stride + 2 * (size_t)x;
            q[0] = q[2] = (uint8_t)k[0], q[1] = (uint8_t)k[1], q[3] = (uint8_t)k[2];
        }
    CHECK(st_write_file(st_path("in.yuyv"), yuyv, sizeof yuyv) == 0);
    CHECK(RUN(NULL, st_path("in.yuyv"), "--raw-size", "16x10", "--raw-format", "yuyv", "--raw-stride", "40",
              "--intensity", "0", "-o", st_path("yuyv.ppm")) == 0);
    int ow, oh, worst = 0;
    uint8_t *o = st_read_rgb8(st_path("yuyv.ppm"), &ow, &oh);
    CHECK(o && ow == w && oh == h);
    for (int i = 0; o && i < w * h; i++) {
        const int *k = yuv[i / 2 % 6];
        double yy = 255.0 / 219 * (k[0] - 16), u = 255.0 / 224 * (k[1] - 128), v = 255.0 / 224 * (k[2] - 128);
        double ref[3] = {yy + 1.402 * v, yy - 0.344136 * u - 0.714136 * v, yy + 1.772 * u};
        for (int ch = 0; ch < 3; ch++) {
            int e = (int)fmin(255, fmax(0, floor(ref[ch] + 0.5)));
            int d = abs(o[3 * i + ch] - e);
            worst = d > worst ? d : worst;
        }
    }
    CHECKF(worst <= 1, "YUYV conversion off by %d", worst);
    CHECK(o && o[0] == 255 && o[1] == 255 && o[2] == 255 && o[6] == 0 && o[7] == 0 && o[8] == 0);
    free(o);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: simtest BLOOM_SIM [BLOOM_SIM2]\n");
        return 2;
    }
    if (st_setup_dir()) {
        fprintf(stderr, "simtest: cannot create a temp dir\n");
        return 1;
    }
    tool = argv[1];
    CHECK(RUN(NULL, "--help") == 0 && strstr(R.out, "--raw-format") && strstr(R.out, "16-bit"));
    test_bitexact_ppm();
    test_bitexact_raw();
    test_raw_formats();
    test_images();
    test_video();
    test_compare();
    test_cli();
    test_errors();
    test_presets();
    if (argc > 2) { /* the optimised build: the bit-exact runs */
        tool = argv[2];
        test_bitexact_ppm();
        test_bitexact_raw();
    }
    CHECKF(st_count_tmp_files() == 0, "temp files left behind");
    int p, f;
    simtest_formats_counts(&p, &f);
    harness_pass += p;
    harness_fail += f;
    simtest_errors_counts(&p, &f);
    harness_pass += p;
    harness_fail += f;
    simtest_presets_counts(&p, &f);
    harness_pass += p;
    harness_fail += f;
    st_remove_dir();
    return harness_finish();
}
