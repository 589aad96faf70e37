/* Tests for sim/imgio: round trips through files in a temp dir, hand-made
 * headers (comments, big-endian PFM), malformed and truncated files, atomic
 * writes, and the real images in $BLOOM_DATA_DIR (default "data"). */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* mkdtemp, dirent */
#endif

#include "harness.h"
#include "imgio.h"

#include <dirent.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static char dir[64];
static char err[512];

static const char *tpath(const char *name)
{
    static char buf[4][256];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

static void put_file(const char *path, const void *data, size_t len)
{
    FILE *f = fopen(path, "wb");
    CHECKF(f != NULL, "cannot create %s", path);
    if (!f)
        return;
    CHECK(fwrite(data, 1, len, f) == len);
    CHECK(fclose(f) == 0);
}

/* Header text followed by n raw bytes of value fill. */
static void put_pnm(const char *path, const char *header, size_t n, unsigned char fill)
{
    size_t hl = strlen(header);
    unsigned char *buf = malloc(hl + n + 1);
    memcpy(buf, header, hl);
    memset(buf + hl, fill, n);
    put_file(path, buf, hl + n);
    free(buf);
}

static bool img_is_empty(const img_t *im)
{
    return im->width == 0 && im->height == 0 && im->channels == 0 && im->maxval == 0 && im->u16 == NULL &&
           im->f32 == NULL;
}

static bool same_bits(float a, float b)
{
    uint32_t x, y;
    memcpy(&x, &a, 4);
    memcpy(&y, &b, 4);
    return x == y;
}

/* Expects img_read to fail with a message naming the file and containing why. */
static void expect_fail(const char *path, const char *why)
{
    img_t im;
    memset(&im, 0x5a, sizeof im); /* garbage: the reader must clear it */
    err[0] = '\0';
    int rc = img_read(path, &im, err, sizeof err);
    CHECKF(rc == -1, "%s: expected failure (%s), got rc %d", path, why, rc);
    CHECKF(strncmp(err, path, strlen(path)) == 0, "message does not start with the file name: %s", err);
    CHECKF(strstr(err, why) != NULL, "message lacks '%s': %s", why, err);
    CHECKF(img_is_empty(&im), "image not left empty after failure: %s", err);
    if (rc == 0)
        img_free(&im);
}

static void fill_u16(img_t *im, unsigned seed)
{
    size_t n = (size_t)im->width * im->height * im->channels;
    for (size_t i = 0; i < n; i++)
        im->u16[i] = (uint16_t)((i * 2654435761u + seed) % ((unsigned)im->maxval + 1));
    im->u16[0] = (uint16_t)im->maxval; /* include both extremes */
    im->u16[n - 1] = 0;
}

static void roundtrip_pnm(int w, int h, int ch, int maxval, const char *name)
{
    img_t a, b;
    CHECK(img_alloc(&a, w, h, ch, maxval) == 0);
    fill_u16(&a, (unsigned)maxval);
    const char *p = tpath(name);
    CHECKF(img_write_ppm(p, &a, err, sizeof err) == 0, "%s", err);
    CHECKF(img_read(p, &b, err, sizeof err) == 0, "%s", err);
    CHECK(b.width == w && b.height == h && b.channels == ch && b.maxval == maxval);
    CHECK(b.f32 == NULL && b.u16 != NULL);
    if (b.u16)
        CHECKF(memcmp(a.u16, b.u16, (size_t)w * h * ch * 2) == 0, "%s: samples differ", name);

    /* File layout: magic by channels, 16-bit big-endian when maxval > 255. */
    struct stat st;
    char hdr[64];
    int hl = snprintf(hdr, sizeof hdr, "P%d\n%d %d\n%d\n", ch == 3 ? 6 : 5, w, h, maxval);
    size_t bps = maxval > 255 ? 2 : 1;
    CHECK(stat(p, &st) == 0 && (size_t)st.st_size == (size_t)hl + (size_t)w * h * ch * bps);
    FILE *f = fopen(p, "rb");
    unsigned char got[64] = {0};
    CHECK(f && fread(got, 1, (size_t)hl + 2, f) == (size_t)hl + 2);
    if (f)
        fclose(f);
    CHECK(memcmp(got, hdr, (size_t)hl) == 0);
    if (bps == 2)
        CHECK(got[hl] == (maxval >> 8) && got[hl + 1] == (maxval & 0xff));
    else
        CHECK(got[hl] == maxval);
    img_free(&a);
    img_free(&b);
    CHECK(img_is_empty(&b));
}

static void roundtrip_pfm(int w, int h, int ch, const char *name)
{
    img_t a, b;
    CHECK(img_alloc(&a, w, h, ch, 0) == 0);
    CHECK(a.f32 != NULL && a.u16 == NULL && a.maxval == 0);
    size_t n = (size_t)w * h * ch;
    for (size_t i = 0; i < n; i++)
        a.f32[i] = (float)i * 0.37f - 3.0f;
    a.f32[1] = NAN;
    a.f32[2] = -INFINITY;
    a.f32[3] = -0.0f;
    a.f32[4] = 1e-40f; /* subnormal */
    const char *p = tpath(name);
    CHECKF(img_write_pfm(p, &a, err, sizeof err) == 0, "%s", err);
    CHECKF(img_read(p, &b, err, sizeof err) == 0, "%s", err);
    CHECK(b.width == w && b.height == h && b.channels == ch && b.maxval == 0);
    CHECK(b.u16 == NULL && b.f32 != NULL);
    bool same = b.f32 != NULL;
    for (size_t i = 0; same && i < n; i++)
        same = same_bits(a.f32[i], b.f32[i]);
    CHECKF(same, "%s: float samples differ", name);

    /* Layout: little-endian, negative scale, bottom row first. */
    char hdr[64];
    int hl = snprintf(hdr, sizeof hdr, "P%c\n%d %d\n-1.0\n", ch == 3 ? 'F' : 'f', w, h);
    FILE *f = fopen(p, "rb");
    unsigned char got[64] = {0};
    CHECK(f && fread(got, 1, (size_t)hl + 4, f) == (size_t)hl + 4);
    if (f)
        fclose(f);
    CHECK(memcmp(got, hdr, (size_t)hl) == 0);
    uint32_t u;
    memcpy(&u, &a.f32[(size_t)(h - 1) * w * ch], 4); /* first sample of the bottom row */
    CHECK(got[hl] == (u & 0xff) && got[hl + 3] == (u >> 24));
    img_free(&a);
    img_free(&b);
}

static void put_be32(unsigned char *p, float v)
{
    uint32_t u;
    memcpy(&u, &v, 4);
    p[0] = (unsigned char)(u >> 24);
    p[1] = (unsigned char)(u >> 16);
    p[2] = (unsigned char)(u >> 8);
    p[3] = (unsigned char)u;
}

static void test_big_endian_pfm(void)
{
    /* 2x2 Pf, positive scale: big-endian; rows bottom to top in the file. */
    const char hdr[] = "Pf\n2 2\n1.0\n";
    unsigned char buf[sizeof hdr - 1 + 16 + 3];
    memcpy(buf, hdr, sizeof hdr - 1);
    const float file_order[4] = {1.5f, -2.25f, 3.0e38f, 0.125f}; /* bottom row, then top */
    for (int i = 0; i < 4; i++)
        put_be32(buf + sizeof hdr - 1 + 4 * i, file_order[i]);
    memcpy(buf + sizeof hdr - 1 + 16, "xyz", 3); /* trailing junk is ignored */
    const char *p = tpath("be.pfm");
    put_file(p, buf, sizeof buf);
    img_t im;
    CHECKF(img_read(p, &im, err, sizeof err) == 0, "%s", err);
    CHECK(im.width == 2 && im.height == 2 && im.channels == 1 && im.maxval == 0);
    if (im.f32) {
        CHECK(im.f32[0] == 3.0e38f && im.f32[1] == 0.125f); /* top row */
        CHECK(im.f32[2] == 1.5f && im.f32[3] == -2.25f);
    }
    img_free(&im);

    /* Same data as PF (3 channels, 1x1... use 1 pixel) with scale 4.5: magnitude ignored. */
    unsigned char rgb[32];
    const char h3[] = "PF\n1 1\n4.5\n";
    memcpy(rgb, h3, sizeof h3 - 1);
    put_be32(rgb + sizeof h3 - 1, -1.0f);
    put_be32(rgb + sizeof h3 - 1 + 4, NAN);
    put_be32(rgb + sizeof h3 - 1 + 8, INFINITY);
    p = tpath("be3.pfm");
    put_file(p, rgb, sizeof h3 - 1 + 12);
    CHECKF(img_read(p, &im, err, sizeof err) == 0, "%s", err);
    CHECK(im.channels == 3 && im.width == 1 && im.height == 1);
    if (im.f32)
        CHECK(im.f32[0] == -1.0f && isnan(im.f32[1]) && isinf(im.f32[2]) && im.f32[2] > 0);
    img_free(&im);
}

static void test_comments(void)
{
    const char hdr[] = "P5\n# made by hand\n 3#w\n  2 # height\r#cr-ended\n\t#x\n255\n";
    const unsigned char px[6] = {0, 10, 20, 30, 40, 255};
    unsigned char buf[sizeof hdr - 1 + 6];
    memcpy(buf, hdr, sizeof hdr - 1);
    memcpy(buf + sizeof hdr - 1, px, 6);
    const char *p = tpath("comments.pgm");
    put_file(p, buf, sizeof buf);
    img_t im;
    CHECKF(img_read(p, &im, err, sizeof err) == 0, "%s", err);
    CHECK(im.width == 3 && im.height == 2 && im.channels == 1 && im.maxval == 255);
    if (im.u16)
        CHECK(im.u16[0] == 0 && im.u16[2] == 20 && im.u16[5] == 255);
    img_free(&im);

    /* Comment right after the magic; the byte after maxval is data even if it is whitespace. */
    p = tpath("comments2.ppm");
    put_pnm(p, "P6# c\n1 1 200\n", 3, ' ');
    CHECKF(img_read(p, &im, err, sizeof err) == 0, "%s", err);
    CHECK(im.maxval == 200 && im.channels == 3);
    if (im.u16)
        CHECK(im.u16[0] == ' ' && im.u16[2] == ' ');
    img_free(&im);
    p = tpath("ws_data.pgm");
    put_pnm(p, "P5 1 1 255\n", 1, '\n');
    CHECKF(img_read(p, &im, err, sizeof err) == 0, "%s", err);
    if (im.u16)
        CHECK(im.u16[0] == '\n');
    img_free(&im);
}

static void test_malformed(void)
{
    const char *p;
    char want[160];

    p = tpath("magic.pfm");
    put_pnm(p, "PX\n1 1\n-1.0\n", 4, 0);
    expect_fail(p, "bad header: 'PX' is not P5, P6, PF or Pf");
    p = tpath("p3.ppm");
    put_pnm(p, "P3\n1 1\n255\n0 0 0\n", 0, 0);
    expect_fail(p, "'P3' is not P5, P6, PF or Pf");
    p = tpath("binary_magic.ppm");
    put_pnm(p, "\x89PNG", 8, 0);
    expect_fail(p, "'\\x89P' is not");
    p = tpath("empty.ppm");
    put_pnm(p, "", 0, 0);
    expect_fail(p, "bad header: empty file");
    p = tpath("nosep.ppm");
    put_pnm(p, "P61 1 255\n", 3, 0);
    expect_fail(p, "not whitespace");

    p = tpath("zero_width.ppm");
    put_pnm(p, "P6\n0 4\n255\n", 12, 0);
    expect_fail(p, "bad header: width is 0");
    p = tpath("zero_height.pfm");
    put_pnm(p, "PF\n4 0\n-1\n", 48, 0);
    expect_fail(p, "height is 0");
    p = tpath("huge_width.ppm");
    put_pnm(p, "P6\n65536 1\n255\n", 3, 0);
    expect_fail(p, "width 65536 exceeds 65535");
    p = tpath("overflow_width.pgm");
    put_pnm(p, "P5\n99999999999999999999999999999 1\n255\n", 3, 0);
    expect_fail(p, "width 9999999999999999... exceeds 65535");
    p = tpath("huge_height.pfm");
    put_pnm(p, "Pf\n1 70000\n-1.0\n", 4, 0);
    expect_fail(p, "height 70000 exceeds 65535");
    p = tpath("neg_width.ppm");
    put_pnm(p, "P6\n-3 1\n255\n", 3, 0);
    expect_fail(p, "expected width as a decimal number, got '-'");
    p = tpath("alpha_height.ppm");
    put_pnm(p, "P6\n3 2x\n255\n", 18, 0);
    expect_fail(p, "height 2 is followed by 'x'");
    p = tpath("maxval0.pgm");
    put_pnm(p, "P5\n2 2\n0\n", 4, 0);
    expect_fail(p, "maxval is 0");
    p = tpath("maxval_big.pgm");
    put_pnm(p, "P5\n2 2\n65536\n", 8, 0);
    expect_fail(p, "maxval 65536 exceeds 65535");
    p = tpath("maxval_comment.pgm");
    put_pnm(p, "P5\n1 1\n255#c\n", 1, 0);
    expect_fail(p, "maxval 255 is followed by '#'");
    p = tpath("header_cut.ppm");
    put_pnm(p, "P6\n640 # comment never ends", 0, 0);
    expect_fail(p, "unexpected end of file before height");
    p = tpath("no_maxval_ws.pgm");
    put_pnm(p, "P5\n1 1\n255", 0, 0);
    expect_fail(p, "unexpected end of file after maxval");

    p = tpath("missing_data.ppm");
    put_pnm(p, "P6\n4 3\n255\n", 0, 0);
    expect_fail(p, "truncated: expected 36 bytes of pixel data, got 0");
    p = tpath("short8.ppm");
    put_pnm(p, "P6\n4 3\n255\n", 35, 0);
    snprintf(want, sizeof want, "%s: truncated: expected 36 bytes of pixel data, got 35", p);
    expect_fail(p, want); /* the whole message, exactly */
    CHECKF(strcmp(err, want) == 0, "got '%s'", err);
    p = tpath("short16.pgm");
    put_pnm(p, "P5\n3 2\n1000\n", 11, 0);
    expect_fail(p, "truncated: expected 12 bytes of pixel data, got 11");
    p = tpath("short.pfm");
    put_pnm(p, "PF\n2 2\n-1.0\n", 47, 0);
    expect_fail(p, "truncated: expected 48 bytes of pixel data, got 47");
    p = tpath("lying.ppm"); /* must not try to allocate 12 GB */
    put_pnm(p, "P6\n65535 65535\n65535\n", 10, 0);
    expect_fail(p, "truncated: expected 25769017350 bytes of pixel data, got 10");

    p = tpath("over_maxval.pgm");
    put_pnm(p, "P5\n2 1\n100\n", 2, 101);
    expect_fail(p, "sample value 101 exceeds maxval 100");
    p = tpath("over_maxval16.pgm");
    put_pnm(p, "P5\n1 1\n1000\n", 2, 0xff);
    expect_fail(p, "sample value 65535 exceeds maxval 1000");

    p = tpath("scale0.pfm");
    put_pnm(p, "PF\n1 1\n0.0\n", 12, 0);
    expect_fail(p, "bad header: scale '0.0' must be nonzero and finite");
    p = tpath("scale_nan.pfm");
    put_pnm(p, "Pf\n1 1\nnan\n", 4, 0);
    expect_fail(p, "scale 'nan' must be nonzero and finite");
    p = tpath("scale_inf.pfm");
    put_pnm(p, "Pf\n1 1\n-1e999\n", 4, 0);
    expect_fail(p, "must be nonzero and finite");
    p = tpath("scale_text.pfm");
    put_pnm(p, "Pf\n1 1\n-1.0x\n", 4, 0);
    expect_fail(p, "scale '-1.0x' is not a number");
    p = tpath("scale_missing.pfm");
    put_pnm(p, "Pf\n1 1\n", 0, 0);
    expect_fail(p, "unexpected end of file before scale");
    p = tpath("pfm_comment.pfm");
    put_pnm(p, "PF\n# no comments in PFM\n1 1\n-1.0\n", 12, 0);
    expect_fail(p, "expected width as a decimal number, got '#'");

    p = tpath("does_not_exist.ppm");
    expect_fail(p, "cannot open: No such file or directory");
    expect_fail(dir, "read error"); /* a directory opens, then read fails */
}

/* A pipe cannot be sized up front: truncation is found while reading rows. */
static void test_fifo(void)
{
    const char *p = tpath("fifo.ppm");
    const char *data[2] = {"P6\n2 2\n255\nABCDEFGHIJKL", "P6\n2 2\n255\nABCDEFGHIJK"};
    CHECK(mkfifo(p, 0600) == 0);
    for (int k = 0; k < 2; k++) {
        fflush(NULL);
        pid_t pid = fork();
        if (pid == 0) {
            FILE *f = fopen(p, "wb");
            if (f) {
                fputs(data[k], f);
                fclose(f);
            }
            _exit(0);
        }
        CHECK(pid > 0);
        img_t im;
        int rc = img_read(p, &im, err, sizeof err);
        if (k == 0) {
            CHECKF(rc == 0 && im.width == 2 && im.u16 && im.u16[11] == 'L', "%s", err);
        } else {
            CHECK(rc == -1 && img_is_empty(&im));
            CHECKF(strstr(err, p) == err && strstr(err, "truncated: expected 12 bytes of pixel data, got 11"),
                   "%s", err);
        }
        img_free(&im);
        int status;
        CHECK(waitpid(pid, &status, 0) == pid);
    }
    remove(p);
}

static int count_entries(const char *d, const char *prefix)
{
    DIR *dp = opendir(d);
    int n = 0;
    if (!dp)
        return -1;
    for (struct dirent *e; (e = readdir(dp)) != NULL;)
        if (strncmp(e->d_name, prefix, strlen(prefix)) == 0)
            n++;
    closedir(dp);
    return n;
}

static void test_write_errors(void)
{
    img_t a, b;
    const char *p = tpath("keep.ppm");
    CHECK(img_alloc(&a, 4, 2, 3, 255) == 0);
    fill_u16(&a, 1);
    CHECKF(img_write_ppm(p, &a, err, sizeof err) == 0, "%s", err);

    /* File mode follows the umask like fopen, not mkstemp's 0600. */
    struct stat st;
    mode_t mask = umask(022);
    umask(mask);
    CHECK(stat(p, &st) == 0 && (st.st_mode & 0777) == (0666 & ~mask));

    /* A failed write (sample above maxval) leaves the old file and no temp. */
    img_t bad;
    CHECK(img_alloc(&bad, 4, 2, 3, 100) == 0);
    bad.u16[7] = 101;
    CHECK(img_write_ppm(p, &bad, err, sizeof err) == -1);
    CHECKF(strstr(err, p) == err && strstr(err, "sample value 101 exceeds maxval 100"), "%s", err);
    CHECK(count_entries(dir, "keep.ppm.tmp-") == 0);
    CHECKF(img_read(p, &b, err, sizeof err) == 0, "%s", err);
    CHECK(b.maxval == 255 && b.u16 && memcmp(a.u16, b.u16, 4 * 2 * 3 * 2) == 0);
    img_free(&b);
    img_free(&bad);

    /* Wrong kind of image for the writer. */
    CHECK(img_write_pfm(p, &a, err, sizeof err) == -1);
    CHECKF(strstr(err, p) == err && strstr(err, "f32 is NULL"), "%s", err);
    img_t f;
    CHECK(img_alloc(&f, 2, 2, 1, 0) == 0);
    CHECK(img_write_ppm(p, &f, err, sizeof err) == -1 && strstr(err, "u16 is NULL"));
    f.channels = 2;
    CHECK(img_write_pfm(p, &f, err, sizeof err) == -1 && strstr(err, "channels must be 1 or 3"));
    f.channels = 1;

    /* Unwritable places: missing directory, target is a directory. */
    const char *nodir = tpath("no/such/dir/x.pfm");
    CHECK(img_write_pfm(nodir, &f, err, sizeof err) == -1);
    CHECKF(strstr(err, nodir) == err && strstr(err, "No such file or directory"), "%s", err);
    const char *sub = tpath("subdir");
    CHECK(mkdir(sub, 0700) == 0);
    char inner[300];
    snprintf(inner, sizeof inner, "%s/x", sub);
    put_file(inner, "x", 1);
    CHECK(img_write_pfm(sub, &f, err, sizeof err) == -1);
    CHECKF(strstr(err, sub) == err && strstr(err, "cannot rename"), "%s", err);
    CHECK(count_entries(dir, "subdir.tmp-") == 0);
    remove(inner);
    rmdir(sub);

    /* Writes replace an existing file. */
    CHECK(img_write_pfm(p, &f, err, sizeof err) == 0);
    CHECK(img_read(p, &b, err, sizeof err) == 0 && b.maxval == 0 && b.width == 2);
    img_free(&b);
    img_free(&f);
    img_free(&a);

    /* img_alloc argument checks leave the image empty. */
    img_t z;
    CHECK(img_alloc(&z, 0, 1, 1, 255) == -1 && img_is_empty(&z));
    CHECK(img_alloc(&z, 65536, 1, 1, 255) == -1 && img_is_empty(&z));
    CHECK(img_alloc(&z, 1, 1, 2, 255) == -1 && img_is_empty(&z));
    CHECK(img_alloc(&z, 1, 1, 1, 65536) == -1 && img_is_empty(&z));
    CHECK(img_alloc(&z, 1, 1, 1, -1) == -1 && img_is_empty(&z));
    img_free(&z);
    img_free(NULL);
}

static void test_real_files(void)
{
    const char *d = getenv("BLOOM_DATA_DIR");
    if (!d || !*d)
        d = "data";
    char p[512];
    img_t im;

    snprintf(p, sizeof p, "%s/rocket_floodlights.ppm", d);
    if (access(p, R_OK) == 0) {
        CHECKF(img_read(p, &im, err, sizeof err) == 0, "%s", err);
        CHECK(im.width == 640 && im.height == 427 && im.channels == 3 && im.maxval == 255);
        CHECK(im.u16 != NULL && im.f32 == NULL);
        img_free(&im);
    } else {
        printf("skipping %s (not found)\n", p);
    }

    snprintf(p, sizeof p, "%s/hall_lamps.pfm", d);
    if (access(p, R_OK) == 0) {
        CHECKF(img_read(p, &im, err, sizeof err) == 0, "%s", err);
        CHECK(im.width == 512 && im.height == 256 && im.channels == 3 && im.maxval == 0);
        CHECK(im.f32 != NULL && im.u16 == NULL);
        size_t n = (size_t)im.width * im.height * im.channels, neg = 0, big = 0, bad = 0;
        for (size_t i = 0; im.f32 && i < n; i++) {
            neg += im.f32[i] < 0.0f;
            big += im.f32[i] > 1.0f;
            bad += !isfinite(im.f32[i]);
        }
        CHECKF(neg > 0, "expected negative samples in %s", p);
        CHECKF(big > 0 && bad == 0, "%zu above 1.0, %zu non-finite", big, bad);
        img_free(&im);
    } else {
        printf("skipping %s (not found)\n", p);
    }
}

static void cleanup_dir(void)
{
    DIR *dp = opendir(dir);
    if (!dp)
        return;
    for (struct dirent *e; (e = readdir(dp)) != NULL;)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
            remove(tpath(e->d_name));
    closedir(dp);
    rmdir(dir);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/test_imgio-XXXXXX");
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    roundtrip_pnm(5, 3, 1, 255, "p5_8.pgm");
    roundtrip_pnm(7, 4, 3, 255, "p6_8.ppm");
    roundtrip_pnm(3, 2, 3, 100, "p6_8_maxval100.ppm");
    roundtrip_pnm(5, 3, 1, 65535, "p5_16.pgm");
    roundtrip_pnm(6, 5, 3, 1000, "p6_16.ppm");
    roundtrip_pnm(1, 1, 3, 256, "p6_256.ppm");
    roundtrip_pfm(4, 3, 3, "pf.pfm");
    roundtrip_pfm(5, 2, 1, "pf_gray.pfm");
    test_big_endian_pfm();
    test_comments();
    test_malformed();
    test_fifo();
    test_write_errors();
    test_real_files();
    cleanup_dir();
    return harness_finish();
}
