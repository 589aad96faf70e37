/* bloom_sim tests: the command line (usage errors, several inputs, the
 * progress line on a terminal) and malformed inputs: each must exit 1 with
 * a message naming the file and the frame, and leave an existing output
 * file untouched and no temp file behind. Headers that claim more than the
 * engine takes, or than the file holds, must be refused before the frame
 * is allocated (test_limits). */
#include "harness.h"
#include "simtest_cases.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void simtest_errors_counts(int *pass, int *fail)
{
    *pass = harness_pass;
    *fail = harness_fail;
}

static const char precious[] = "P6\n1 1\n255\nabc";

/* Puts the precious content into each output name. */
static void plant(const char *a, const char *b)
{
    CHECK(st_write_file(st_path(a), precious, sizeof precious - 1) == 0);
    if (b)
        CHECK(st_write_file(st_path(b), precious, sizeof precious - 1) == 0);
}

/* The last run failed with status 1, named file and "frame N" and what,
 * and left the planted outputs alone. */
static void expect_failure(const char *label, const char *file, long frame, const char *what,
                           const char *out1, const char *out2)
{
    char fr[64];
    snprintf(fr, sizeof fr, "%s: frame %ld: ", file, frame);
    CHECKF(R.status == 1, "%s: status %d", label, R.status);
    CHECKF(strstr(R.err, fr) != NULL, "%s: message lacks \"%s\": %s", label, fr, R.err);
    CHECKF(strstr(R.err, what) != NULL, "%s: message lacks \"%s\": %s", label, what, R.err);
    CHECKF(st_same_file(st_path(out1), precious, sizeof precious - 1), "%s: %s was touched", label, out1);
    if (out2)
        CHECKF(st_same_file(st_path(out2), precious, sizeof precious - 1), "%s: %s was touched", label, out2);
    CHECKF(st_count_tmp_files() == 0, "%s: temp file left", label);
}

static unsigned char *find(unsigned char *b, size_t len, const char *needle, size_t n)
{
    for (size_t i = 0; i + n <= len; i++)
        if (!memcmp(b + i, needle, n))
            return b + i;
    return NULL;
}

static unsigned char *slurp(const char *name, size_t *len)
{
    unsigned char *b = st_read_file(st_path(name), len);
    CHECK(b != NULL);
    return b;
}

/* ---- what a header may cost ------------------------------------------------ */

static void be32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24), p[1] = (unsigned char)(v >> 16), p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static uint32_t crc32_of(const unsigned char *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return ~c;
}

/* Runs the (sanitized) tool on path with every allocation above 64 MiB
 * fatal (ASan exits 86 then): a header that claims a huge frame must be
 * refused with status 1 and "frame 0: " and what, having allocated no
 * more than the data backs. */
static void expect_refused(const char *label, const char *in, const char *path, const char *what,
                           const char *const *extra)
{
    const char *old = getenv("ASAN_OPTIONS");
    char *keep = old ? strdup(old) : NULL, opts[512];
    snprintf(opts, sizeof opts, "%s%smax_allocation_size_mb=64:allocator_may_return_null=0:exitcode=86",
             old ? old : "", old && *old ? ":" : "");
    setenv("ASAN_OPTIONS", opts, 1);
    const char *args[12] = {in ? "-" : path, "-o", st_path("keep.ppm")};
    for (int i = 0; extra && extra[i] && i < 8; i++)
        args[3 + i] = extra[i];
    st_run(&R, tool, in, args);
    if (keep)
        setenv("ASAN_OPTIONS", keep, 1);
    else
        unsetenv("ASAN_OPTIONS");
    free(keep);
    expect_failure(label, in ? "(stdin)" : path, 0, what, "keep.ppm", NULL);
}

static void test_limits(const uint8_t *px, int w, int h)
{
    size_t len;
    unsigned char *b;
    plant("keep.ppm", NULL);
    /* the known finding: a 368-byte JPEG that claims 13362 x 64831 made
     * bloom_sim allocate about 5 GB before anything else */
    CHECK(st_write_jpeg(st_path("l.jpg"), px, w, h, 3, 90) == 0);
    b = st_read_file(st_path("l.jpg"), &len);
    unsigned char *sof = b ? find(b, len, "\xFF\xC0", 2) : NULL;
    CHECK(sof != NULL);
    if (sof) {
        sof[5] = 64831 >> 8, sof[6] = 64831 & 255, sof[7] = 13362 >> 8, sof[8] = 13362 & 255;
        CHECK(st_write_file(st_path("huge.jpg"), b, len) == 0);
        expect_refused("JPEG 13362x64831", NULL, st_path("huge.jpg"),
                       "JPEG is 13362x64831: larger than the engine's limit of 16384 per side", NULL);
        sof[5] = sof[7] = 16384 >> 8, sof[6] = sof[8] = 0; /* what the engine takes, the data short */
        CHECK(st_write_file(st_path("short.jpg"), b, len) == 0);
        expect_refused("JPEG 16384x16384, data short", NULL, st_path("short.jpg"), "JPEG", NULL);
    }
    free(b);
    /* PNG: above the limit, and a 16384 x 16384 header over a few hundred bytes */
    CHECK(st_write_png(st_path("l.png"), px, w, h, 3, 0) == 0);
    b = st_read_file(st_path("l.png"), &len);
    CHECK(b && len > 33 && !memcmp(b + 12, "IHDR", 4));
    if (b && len > 33) {
        be32(b + 16, 20000), be32(b + 20, 8), be32(b + 29, crc32_of(b + 12, 17));
        CHECK(st_write_file(st_path("huge.png"), b, len) == 0);
        expect_refused("PNG 20000x8", NULL, st_path("huge.png"),
                       "PNG is 20000x8: larger than the engine's limit of 16384 per side", NULL);
        be32(b + 16, 16384), be32(b + 20, 16384), be32(b + 29, crc32_of(b + 12, 17));
        CHECK(st_write_file(st_path("short.png"), b, len) == 0);
        expect_refused("PNG 16384x16384, data short", NULL, st_path("short.png"), "truncated", NULL);
    }
    free(b);
    /* PPM/PGM/PFM: above the limit, and a short body */
    static const struct {
        const char *name, *data, *what;
    } pnm[] = {{"huge.ppm", "P6\n16385 2\n255\n......", "width 16385 exceeds the limit of 16384"},
               {"huge.pgm", "P5\n2 20000\n255\n....", "height 20000 exceeds the limit of 16384"},
               {"short.ppm", "P6\n16384 16384\n255\n........", "truncated"},
               {"short.pfm", "PF\n16384 16384\n-1.0\n............", "truncated"}};
    for (size_t i = 0; i < sizeof pnm / sizeof pnm[0]; i++) {
        CHECK(st_write_file(st_path(pnm[i].name), pnm[i].data, strlen(pnm[i].data)) == 0);
        expect_refused(pnm[i].name, NULL, st_path(pnm[i].name), pnm[i].what, NULL);
    }
    /* OpenEXR: the data window above the limit, and 16384 x 16384 over a small file */
    if (st_exr_built()) {
        float f[8 * 8 * 3] = {0};
        CHECK(st_write_exr(st_path("l.exr"), f, 8, 8, 1) == 0);
        b = st_read_file(st_path("l.exr"), &len);
        unsigned char *dw = b ? find(b, len, "dataWindow\0box2i\0", 17) : NULL;
        CHECK(dw != NULL);
        if (dw) {
            unsigned char *v = dw + 17 + 4 + 8;        /* xMax, yMax: little-endian */
            v[0] = 0x1F, v[1] = 0x4E, v[2] = v[3] = 0; /* 19999: 20000 wide */
            CHECK(st_write_file(st_path("huge.exr"), b, len) == 0);
            expect_refused("EXR 20000x8", NULL, st_path("huge.exr"),
                           "OpenEXR data window 20000x8 is larger than the engine's limit", NULL);
            v[0] = v[4] = 0xFF, v[1] = v[5] = 0x3F; /* 16383, 16383 */
            CHECK(st_write_file(st_path("short.exr"), b, len) == 0);
            expect_refused("EXR 16384x16384, data short", NULL, st_path("short.exr"), "OpenEXR", NULL);
        }
        free(b);
    }
    /* streams: a Y4M header claiming 16384 x 16384 4:4:4 (805 MB frames),
     * and raw frames of 16384 rows of 1 MiB, with a few hundred bytes */
    static const char y4m[] = "YUV4MPEG2 W16384 H16384 C444\nFRAME\n................................";
    CHECK(st_write_file(st_path("huge.y4m"), y4m, sizeof y4m - 1) == 0);
    expect_refused("Y4M 16384x16384 on stdin", st_path("huge.y4m"), NULL, "truncated", NULL);
    expect_refused("Y4M 16384x16384", NULL, st_path("huge.y4m"), "truncated", NULL);
    expect_refused("raw stride 1 MiB x 16384 on stdin", st_path("huge.y4m"), NULL, "partial frame",
                   ARGS("--raw-size", "16384x16384", "--raw-format", "grey", "--raw-stride", "1048576"));
    /* the aux plane */
    CHECK(write_ppm8(st_path("in.ppm"), px, w, h, 3) == 0);
    CHECK(st_write_file(st_path("huge_aux.pgm"), "P5\n16384 16384\n255\n....", 24) == 0);
    RUN(NULL, st_path("in.ppm"), "--preset", "attenuation", "--aux", st_path("huge_aux.pgm"), "-o",
        st_path("keep.ppm"));
    CHECKF(R.status == 1 && strstr(R.err, "--aux: truncated"), "huge aux: %d %s", R.status, R.err);
    CHECK(st_write_file(st_path("wide_aux.pgm"), "P5\n20000 1\n255\n....", 19) == 0);
    RUN(NULL, st_path("in.ppm"), "--preset", "attenuation", "--aux", st_path("wide_aux.pgm"), "-o",
        st_path("keep.ppm"));
    CHECKF(R.status == 1 && strstr(R.err, "--aux: bad header: width 20000 exceeds the limit of 16384"),
           "wide aux: %d %s", R.status, R.err);
}

void test_errors(void)
{
    const int w = 16, h = 8;
    uint8_t px[16 * 8 * 3];
    make_scene(px, w, h, 3);
    size_t len;
    unsigned char *b;

    /* missing file */
    plant("keep.ppm", NULL);
    RUN(NULL, st_path("missing.ppm"), "-o", st_path("keep.ppm"));
    expect_failure("missing", st_path("missing.ppm"), 0, "cannot open", "keep.ppm", NULL);
    /* a directory */
    RUN(NULL, st_path(""), "-o", st_path("keep.ppm"));
    CHECK(R.status == 1 && strstr(R.err, "frame 0: ") != NULL);

    /* truncated PPM */
    CHECK(write_ppm8(st_path("t.ppm"), px, w, h, 3) == 0);
    b = slurp("t.ppm", &len);
    CHECK(b && st_write_file(st_path("t.ppm"), b, len - 100) == 0);
    free(b);
    RUN(NULL, st_path("t.ppm"), "-o", st_path("keep.ppm"));
    expect_failure("truncated PPM", st_path("t.ppm"), 0, "truncated", "keep.ppm", NULL);

    /* unrecognised content */
    CHECK(st_write_file(st_path("junk.bin"), "GIF89a....", 10) == 0);
    RUN(NULL, st_path("junk.bin"), "-o", st_path("keep.ppm"));
    expect_failure("unknown", st_path("junk.bin"), 0, "unrecognised format", "keep.ppm", NULL);

    /* Y4M: 3 frames, the last cut short; checked whole before any output */
    const int W = 10, H = 6;
    size_t fb = st_y4m_frame_bytes(W, H, "420jpeg");
    uint8_t planes[3 * 90];
    memset(planes, 128, sizeof planes);
    CHECK(fb == 90 && st_write_y4m(st_path("t.y4m"), NULL, W, H, "420jpeg", planes, 3) == 0);
    b = slurp("t.y4m", &len);
    CHECK(b && st_write_file(st_path("t.y4m"), b, len - 40) == 0);
    plant("k_0.ppm", "keep.y4m");
    RUN(NULL, st_path("t.y4m"), "-o", st_path("k_%d.ppm"), "--side-by-side", st_path("keep.y4m"));
    expect_failure("truncated Y4M", st_path("t.y4m"), 2, "truncated", "k_0.ppm", "keep.y4m");
    /* the same from a pipe: frames 0 and 1 run, the stream is only renamed at the end */
    RUN(st_path("t.y4m"), "-", "-o", st_path("keep.y4m"));
    expect_failure("truncated Y4M on stdin", "(stdin)", 2, "truncated", "keep.y4m", NULL);
    CHECK(strstr(R.out, "frame 1:") != NULL);
    /* a bad frame header at frame 1 */
    memcpy(b + (len - 3 * (fb + 6)) + fb + 6, "FRAMX\n", 6);
    CHECK(st_write_file(st_path("f.y4m"), b, len) == 0);
    RUN(NULL, st_path("f.y4m"), "-o", st_path("keep.y4m"));
    expect_failure("bad frame header", st_path("f.y4m"), 1, "bad frame header", "keep.y4m", NULL);
    free(b);
    /* bad stream headers */
    static const char *const bad_headers[][2] = {
        {"YUV4MPEG2 W0 H6 C420jpeg\nFRAME\n", "width"},
        {"YUV4MPEG2 W10 C420jpeg\nFRAME\n", "no H"},
        {"YUV4MPEG2 W10 H6 C420p10\nFRAME\n", "C420p10 not supported"},
        {"YUV4MPEG2 W10 H6 F0:0\nFRAME\n", "frame rate"},
        {"YUV4MPEG2 W10 H6", "ends inside the header"},
        {"YUV4MPEG2 W10 H6 C420jpeg\n", "no frames"}};
    for (size_t i = 0; i < sizeof bad_headers / sizeof bad_headers[0]; i++) {
        CHECK(st_write_file(st_path("h.y4m"), bad_headers[i][0], strlen(bad_headers[i][0])) == 0);
        RUN(NULL, st_path("h.y4m"), "-o", st_path("keep.y4m"));
        expect_failure(bad_headers[i][1], st_path("h.y4m"), 0, bad_headers[i][1], "keep.y4m", NULL);
    }

    /* raw dump with a partial frame: 2 frames and 100 bytes */
    uint8_t raw[2 * 16 * 8 * 3 + 100];
    memset(raw, 90, sizeof raw);
    CHECK(st_write_file(st_path("p.rgb"), raw, sizeof raw) == 0);
    plant("r_0.ppm", NULL);
    RUN(NULL, st_path("p.rgb"), "--raw-size", "16x8", "--raw-format", "rgb24", "-o", st_path("r_%d.ppm"));
    expect_failure("partial raw", st_path("p.rgb"), 2, "byte offset 768", "r_0.ppm", NULL);
    RUN(st_path("p.rgb"), "-", "--raw-size", "16x8", "--raw-format", "rgb24", "-o", st_path("keep.y4m"));
    expect_failure("partial raw on stdin", "(stdin)", 2, "byte offset 768", "keep.y4m", NULL);
    CHECK(st_write_file(st_path("e.rgb"), raw, 0) == 0);
    RUN(NULL, st_path("e.rgb"), "--raw-size", "16x8", "--raw-format", "rgb24", "-o", st_path("keep.ppm"));
    expect_failure("empty raw", st_path("e.rgb"), 0, "empty", "keep.ppm", NULL);
    /* NV12: a frame is the luma rows then half as many chroma rows (16x8:
     * 192 bytes), so 288 bytes are a frame and half; NV16's 256-byte frames
     * make 288 partial too; --raw-ycbcr names a matrix and a range */
    CHECK(st_write_file(st_path("p.nv"), raw, 288) == 0);
    RUN(NULL, st_path("p.nv"), "--raw-size", "16x8", "--raw-format", "nv12", "-o", st_path("keep.ppm"));
    expect_failure("partial NV12", st_path("p.nv"), 1, "byte offset 192: 96 of 192 bytes", "keep.ppm", NULL);
    RUN(NULL, st_path("p.nv"), "--raw-size", "16x8", "--raw-format", "nv16", "--raw-ycbcr", "bt709-full",
        "-o", st_path("keep.ppm"));
    expect_failure("partial NV16", st_path("p.nv"), 1, "byte offset 256: 32 of 256 bytes", "keep.ppm", NULL);
    RUN(NULL, st_path("p.nv"), "--raw-size", "16x8", "--raw-format", "nv12", "--raw-ycbcr", "bt2020");
    CHECKF(R.status == 2 && strstr(R.err, "--raw-ycbcr: bad value 'bt2020'"), "--raw-ycbcr bt2020: %d %s",
           R.status, R.err);
    RUN(NULL, st_path("p.nv"), "--raw-size", "15x8", "--raw-format", "uyvy");
    CHECKF(R.status == 1 && strstr(R.err, "UYVY needs an even width (got 15)"), "odd UYVY: %d %s", R.status,
           R.err);

    /* PNG: a damaged byte (CRC error), and cut short */
    CHECK(st_write_png(st_path("c.png"), px, w, h, 3, 0) == 0);
    b = slurp("c.png", &len);
    if (b) {
        unsigned char *idat = find(b, len, "IDAT", 4);
        CHECK(idat != NULL);
        if (idat)
            idat[6] ^= 0x5A;
        CHECK(st_write_file(st_path("bad.png"), b, len) == 0);
        CHECK(st_write_file(st_path("cut.png"), b, len / 2) == 0);
        free(b);
    }
    RUN(NULL, st_path("bad.png"), "-o", st_path("keep.ppm"));
    expect_failure("corrupt PNG", st_path("bad.png"), 0, "PNG", "keep.ppm", NULL);
    RUN(NULL, st_path("cut.png"), "-o", st_path("keep.ppm"));
    expect_failure("truncated PNG", st_path("cut.png"), 0, "truncated", "keep.ppm", NULL);

    /* JPEG: cut short, and a broken frame header (height 0) */
    CHECK(st_write_jpeg(st_path("c.jpg"), px, w, h, 3, 90) == 0);
    b = slurp("c.jpg", &len);
    if (b) {
        CHECK(st_write_file(st_path("cut.jpg"), b, len * 2 / 3) == 0);
        unsigned char *sof = find(b, len, "\xFF\xC0", 2);
        CHECK(sof != NULL);
        if (sof)
            sof[5] = sof[6] = 0; /* number of lines */
        CHECK(st_write_file(st_path("bad.jpg"), b, len) == 0);
        free(b);
    }
    RUN(NULL, st_path("cut.jpg"), "-o", st_path("keep.ppm"));
    expect_failure("truncated JPEG", st_path("cut.jpg"), 0, "truncated", "keep.ppm", NULL);
    RUN(NULL, st_path("bad.jpg"), "-o", st_path("keep.ppm"));
    expect_failure("corrupt JPEG", st_path("bad.jpg"), 0, "JPEG", "keep.ppm", NULL);

    /* OpenEXR cut short */
    if (st_exr_built()) {
        float f[8 * 8 * 3];
        for (int i = 0; i < 8 * 8 * 3; i++)
            f[i] = (float)i / 50.0f;
        CHECK(st_write_exr(st_path("c.exr"), f, 8, 8, 1) == 0);
        b = slurp("c.exr", &len);
        CHECK(b && st_write_file(st_path("cut.exr"), b, len - 30) == 0);
        free(b);
        RUN(NULL, st_path("cut.exr"), "-o", st_path("keep.ppm"));
        expect_failure("truncated EXR", st_path("cut.exr"), 0, "OpenEXR", "keep.ppm", NULL);
    }

    test_limits(px, w, h);

    /* in a sequence, the frame of the sequence is named too */
    CHECK(write_ppm8(st_path("ok.ppm"), px, w, h, 3) == 0);
    plant("s_1.ppm", NULL);
    RUN(NULL, st_path("ok.ppm"), st_path("t.ppm"), "-o", st_path("s_%d.ppm"));
    expect_failure("sequence", st_path("t.ppm"), 0, "(frame 1 of the sequence)", "s_1.ppm", NULL);
}

void test_cli(void)
{
    const int w = 12, h = 10;
    uint8_t px[12 * 10 * 3], raw[3 * 12 * 10 * 3];
    make_scene(px, w, h, 8);
    CHECK(write_ppm8(st_path("a.ppm"), px, w, h, 3) == 0);
    memset(raw, 200, sizeof raw);
    CHECK(st_write_file(st_path("three.rgb"), raw, sizeof raw) == 0);
    static const char *const bad[][4] = {
        {"--bogus", NULL, NULL, NULL},       {"--threshold", "300", NULL, NULL},
        {"--levels", "0", NULL, NULL},       {"--format", "yuv", NULL, NULL},
        {"-o", "x%s.ppm", NULL, NULL},       {"-o", "x%d%d.ppm", NULL, NULL},
        {"-o", "x.bmp", NULL, NULL},         {"--side-by-side", "x.pfm", NULL, NULL},
        {"--raw-size", "12x10", NULL, NULL}, {"--view", "glow", NULL, NULL},
        {"--threshold", NULL, NULL, NULL},   {"-o", "/nonexistent-dir/x_%d.png", NULL, NULL}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *args[6] = {st_path("a.ppm"), bad[i][0], bad[i][1], NULL};
        st_run(&R, tool, NULL, args);
        CHECKF(R.status == 2 && strstr(R.err, "bloom_sim: ") != NULL, "usage error %s %s: status %d",
               bad[i][0], bad[i][1] ? bad[i][1] : "", R.status);
    }
    CHECK(RUN(NULL, "--compare") == 2 && strstr(R.err, "no input") != NULL);
    /* one output name, several frames */
    RUN(NULL, st_path("three.rgb"), "--raw-size", "12x10", "--raw-format", "rgb24", "-o", st_path("one.ppm"));
    CHECK(R.status == 2 && strstr(R.err, "names one file") != NULL);
    int ow, oh;
    uint8_t *o = st_read_rgb8(st_path("one.ppm"), &ow, &oh);
    CHECK(o == NULL);
    free(o);
    /* the same from a pipe (count unknown): caught at the second frame */
    RUN(st_path("three.rgb"), "-", "--raw-size", "12x10", "--raw-format", "rgb24", "-o", st_path("one.ppm"));
    CHECK(R.status == 1 && strstr(R.err, "names one file") != NULL);

    /* several inputs of different sizes; %% in a pattern */
    CHECK(st_write_png(st_path("b.png"), raw, 9, 30, 3, 0) == 0);
    CHECKF(RUN(NULL, st_path("a.ppm"), st_path("b.png"), "-o", st_path("m%%_%d.ppm"), "-q") == 0, "%s",
           R.err);
    uint8_t *m0 = st_read_rgb8(st_path("m%_0.ppm"), &ow, &oh);
    CHECK(m0 && ow == 12 && oh == 10);
    free(m0);
    m0 = st_read_rgb8(st_path("m%_1.ppm"), &ow, &oh);
    CHECK(m0 && ow == 9 && oh == 30);
    free(m0);
    CHECK(strstr(R.out, "frame 0") == NULL && strstr(R.out, "summary: 2 frames") != NULL);
    /* Y4M output needs one size */
    RUN(NULL, st_path("a.ppm"), st_path("b.png"), "-o", st_path("mixed.y4m"));
    CHECK(R.status == 1 && strstr(R.err, "Y4M stream is 12x10") != NULL && st_count_tmp_files() == 0);

    /* progress on a terminal (shown at once with --progress-after 0), none
     * when stderr is a file (every other run here) */
    char tty[4096];
    int st = st_run_tty(
        tool,
        ARGS(st_path("three.rgb"), "--raw-size", "12x10", "--raw-format", "rgb24", "--progress-after", "0"),
        tty, sizeof tty);
    if (st < 0) {
        printf("no pseudo-terminal here: progress line not tested\n");
    } else {
        /* the first update is drawn at once; the line is erased at the end */
        size_t tl = strlen(tty);
        CHECKF(st == 0 && strstr(tty, "bloom_sim: frame 1 of 3 (33%)") != NULL && tl >= 4 &&
                   !strcmp(tty + tl - 4, "\r\033[K"),
               "tty: %s", tty);
    }
    CHECK(RUN(NULL, st_path("three.rgb"), "--raw-size", "12x10", "--raw-format", "rgb24") == 0 &&
          R.err[0] == '\0');
}
