/* bloom_cam host tests of MJPEG capture (build/linux/test_cam_mjpeg, in
 * make test-linux-host): frames encoded here with libjpeg (quality 100,
 * 4:4:4, and 4:2:0 as cameras send), decoded through bloom_cam's row
 * reader (cam_cap_begin / cam_cap_next / cam_cap_end, cam_mjpeg.c), equal
 * byte for byte to what bloom_sim's JPEG reader (sim/sim_jpeg.c) makes of
 * the same bytes; a frame without its DHT segments (as UVC cameras send)
 * decoded the same; corrupt frames (bytes of the entropy data flipped, a
 * bad marker), truncated ones (cut at several points, the EOI missing) and
 * one of another size each found bad, with the next good frame decoded
 * right after; the format table and --format auto's rule for MJPEG. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>
#include <linux/videodev2.h>

#include "cam.h"
#include "harness.h"
#include "sim.h"
#include "test_jpeg.h"

/* A test frame: smooth ramps, a bright square and hashed noise, so the
 * entropy data is neither trivial nor all noise. */
static void pattern(uint8_t *rgb, int w, int h, int seed)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t *p = rgb + ((size_t)y * (size_t)w + (size_t)x) * 3;
            const unsigned hash = ((unsigned)(x + seed) * 2654435761u) ^ ((unsigned)y * 40503u);
            const int sq = x % 29 < 9 && y % 23 < 9;
            p[0] = (uint8_t)(sq ? 250 : (x * 255) / (w > 1 ? w - 1 : 1));
            p[1] = (uint8_t)(sq ? 245 : (y * 255) / (h > 1 ? h - 1 : 1));
            p[2] = (uint8_t)(sq ? 240 : 60 + (hash >> 24) % 64);
        }
}

static size_t encode(const uint8_t *rgb, int w, int h, int quality, int sub, int grey, unsigned char **out)
{
    return test_jpeg_encode(rgb, w, h, (size_t)w * 3, quality, sub, grey, out);
}

/* bloom_cam's path: the frame's rows through the row reader of an MJPEG
 * capture of w x h. 0 and the rows in rgb, or -1 (the frame bad). */
static int cam_decode(cam_v4l2_t *c, const uint8_t *jpg, size_t len, uint8_t *rgb)
{
    cam_frame_t f;
    memset(&f, 0, sizeof f);
    f.data = jpg;
    f.len = len;
    if (cam_cap_begin(c, &f))
        return -1;
    uint8_t *line = malloc((size_t)c->width * 3);
    int bad = !line;
    for (int y = 0; !bad && y < c->height; y++) {
        const uint8_t *row = cam_cap_next(c, &f, y, line);
        if (!row)
            bad = 1;
        else
            memcpy(rgb + (size_t)y * (size_t)c->width * 3, row, (size_t)c->width * 3);
    }
    free(line);
    if (bad)
        return -1;
    return cam_cap_end(c);
}

/* bloom_sim's JPEG reader on the same bytes: RGB888 (a grey JPEG's one
 * channel spread to three), 0, or -1. */
static int sim_decode(const uint8_t *jpg, size_t len, int w, int h, uint8_t *rgb)
{
    FILE *f = fmemopen((void *)jpg, len, "rb");
    if (!f)
        return -1;
    img_t im;
    char err[256];
    int rc = sim_jpeg_read(f, &im, err, sizeof err);
    fclose(f);
    if (rc)
        return -1;
    rc = im.width == w && im.height == h && (im.channels == 3 || im.channels == 1) ? 0 : -1;
    for (size_t i = 0; !rc && i < (size_t)w * (size_t)h * 3; i++)
        rgb[i] = (uint8_t)im.u16[im.channels == 3 ? i : i / 3];
    img_free(&im);
    return rc;
}

static void open_cap(cam_v4l2_t *c, int w, int h)
{
    memset(c, 0, sizeof *c);
    c->width = w;
    c->height = h;
    c->pixelformat = V4L2_PIX_FMT_MJPEG;
    CHECK(cam_mjpeg_open(&c->jpeg, w, h) == 0);
}

/* The JPEG without its DHT segments (what many UVC cameras send): a new
 * buffer of *len bytes. */
static unsigned char *strip_dht(const unsigned char *j, size_t n, size_t *len, int *found)
{
    unsigned char *o = malloc(n);
    size_t i = 2, k = 2;
    *found = 0;
    memcpy(o, j, 2); /* SOI */
    while (i + 4 <= n && j[i] == 0xFF && j[i + 1] != 0xDA) {
        const size_t seg = 2 + ((size_t)j[i + 2] << 8 | j[i + 3]);
        if (j[i + 1] == 0xC4)
            (*found)++;
        else {
            memcpy(o + k, j + i, seg);
            k += seg;
        }
        i += seg;
    }
    memcpy(o + k, j + i, n - i); /* SOS, the entropy data, EOI */
    *len = k + n - i;
    return o;
}

/* The offset of the first byte of entropy data (after the SOS header). */
static size_t entropy_start(const unsigned char *j, size_t n)
{
    size_t i = 2;
    while (i + 4 <= n && j[i] == 0xFF && j[i + 1] != 0xDA)
        i += 2 + ((size_t)j[i + 2] << 8 | j[i + 3]);
    return i + 4 <= n ? i + 2 + ((size_t)j[i + 2] << 8 | j[i + 3]) : n;
}

static void same_as_sim(void)
{
    static const struct {
        int w, h, q, sub, grey;
    } t[] = {{64, 48, 100, 1, 0},  {320, 180, 100, 1, 0}, {37, 21, 100, 1, 0},
             {320, 180, 85, 2, 0}, {38, 22, 90, 2, 0},    {64, 48, 100, 1, 1}};
    for (size_t k = 0; k < sizeof t / sizeof t[0]; k++) {
        const int w = t[k].w, h = t[k].h;
        const size_t n = (size_t)w * (size_t)h * 3;
        uint8_t *src = malloc(n), *a = malloc(n), *b = malloc(n);
        pattern(src, w, h, (int)k);
        unsigned char *jpg;
        const size_t len = encode(src, w, h, t[k].q, t[k].sub, t[k].grey, &jpg);
        cam_v4l2_t c;
        open_cap(&c, w, h);
        memset(a, 1, n);
        memset(b, 2, n);
        const int ra = cam_decode(&c, jpg, len, a), rb = sim_decode(jpg, len, w, h, b);
        long maxd = 0;
        double sum = 0;
        for (size_t i = 0; i < n; i++) {
            const int want =
                t[k].grey
                    ? (src[i - i % 3] * 299 + src[i - i % 3 + 1] * 587 + src[i - i % 3 + 2] * 114 + 500) /
                          1000
                    : src[i];
            const long d = labs((long)a[i] - want);
            maxd = d > maxd ? d : maxd;
            sum += (double)d;
        }
        const double mean = sum / (double)n;
        CHECKF(ra == 0 && rb == 0 && !memcmp(a, b, n),
               "%dx%d q%d %s: bloom_cam's decode (%d) differs from bloom_sim's (%d)", w, h, t[k].q,
               t[k].grey       ? "grey"
               : t[k].sub == 1 ? "4:4:4"
                               : "4:2:0",
               ra, rb);
        /* and it is the picture (not two equal wrong decodes): within the
         * JPEG's own loss of the source */
        CHECKF(mean < (t[k].sub == 1 ? 1.5 : 12.0), "%dx%d q%d: mean error %.2f against the source", w, h,
               t[k].q, mean);
        printf("ok: %dx%d q%d %s: %zu bytes, decoded = bloom_sim's; against the source max %ld, mean %.3f\n",
               w, h, t[k].q,
               t[k].grey       ? "grey"
               : t[k].sub == 1 ? "4:4:4"
                               : "4:2:0",
               len, maxd, mean);

        /* the same frame without its Huffman tables: libjpeg-turbo puts the
         * standard ones in (the encoder used them) */
        size_t slen;
        int found;
        unsigned char *nodht = strip_dht(jpg, len, &slen, &found);
        memset(b, 3, n);
        const int rd = cam_decode(&c, nodht, slen, b);
        CHECKF(found >= 2 && slen < len && rd == 0 && !memcmp(a, b, n),
               "%dx%d without DHT (%d segments taken out, %zu of %zu bytes): decode %d, %s", w, h, found,
               slen, len, rd,
               rd                ? cam_mjpeg_why(c.jpeg)
               : memcmp(a, b, n) ? "rows differ"
                                 : "");
        free(nodht);
        free(jpg);
        cam_mjpeg_close(c.jpeg);
        free(src);
        free(a);
        free(b);
    }
}

/* A bad frame is bad, and the decoder takes the next good one at once. */
static void bad_then_good(cam_v4l2_t *c, const unsigned char *bad, size_t blen, const unsigned char *good,
                          size_t glen, const uint8_t *want, uint8_t *rgb, const char *what, const char *why)
{
    const size_t n = (size_t)c->width * (size_t)c->height * 3;
    const int r = cam_decode(c, bad, blen, rgb);
    const char *got = cam_mjpeg_why(c->jpeg);
    CHECKF(r == -1 && (!why || strstr(got, why)), "%s: decode %d (%s), wanted bad%s%s", what, r, got,
           why ? ": " : "", why ? why : "");
    if (r == -1)
        printf("ok: %s: bad (%s)\n", what, got);
    memset(rgb, 0, n);
    CHECKF(cam_decode(c, good, glen, rgb) == 0 && !memcmp(rgb, want, n), "%s: the good frame after it", what);
}

static void bad_frames(void)
{
    const int w = 160, h = 120;
    const size_t n = (size_t)w * (size_t)h * 3;
    uint8_t *src = malloc(n), *want = malloc(n), *rgb = malloc(n);
    pattern(src, w, h, 7);
    unsigned char *jpg, *small;
    const size_t len = encode(src, w, h, 90, 2, 0, &jpg);
    cam_v4l2_t c;
    open_cap(&c, w, h);
    CHECK(cam_decode(&c, jpg, len, want) == 0);
    unsigned char *b = malloc(len + 16);
    const size_t e0 = entropy_start(jpg, len);

    /* 8 bytes of the entropy data flipped, at a quarter, half and three
     * quarters of it. Mostly the decode loses step, and that is found (a
     * bad code, the data running out before the last block, or bytes left
     * over before the EOI); but JPEG carries no checksum, and a damage
     * after which the Huffman codes fall back in step, ending at the EOI
     * with the right number of blocks, decodes without complaint: the
     * three-quarter case here is one (the frame is shown, wrong). */
    for (int q = 1; q <= 3; q++) {
        char what[80];
        memcpy(b, jpg, len);
        const size_t at = e0 + (len - 2 - e0) * (size_t)q / 4;
        for (size_t i = at; i < at + 8; i++)
            b[i] = (uint8_t)(b[i] == 0xFF ? 0x00 : ~b[i] & 0x7F); /* no 0xFF: not a marker by chance */
        snprintf(what, sizeof what, "8 entropy bytes flipped at %zu of %zu", at, len);
        if (q < 3) {
            bad_then_good(&c, b, len, jpg, len, want, rgb, what, NULL);
            continue;
        }
        const int r = cam_decode(&c, b, len, rgb);
        long differ = 0;
        for (size_t i = 0; i < n; i += 3)
            differ += memcmp(rgb + i, want + i, 3) != 0;
        CHECKF(r == 0 && differ > 0, "%s: decode %d, %ld pixels differ", what, r, differ);
        printf("ok: %s: not seen by libjpeg (no checksum in JPEG): decoded, %ld of %d pixels differ\n", what,
               differ, w * h);
    }
    /* a marker that is not one where the entropy data should be */
    memcpy(b, jpg, len);
    b[e0 + 40] = 0xFF;
    b[e0 + 41] = 0xD9; /* an EOI in the middle: the data ends early */
    bad_then_good(&c, b, len, jpg, len, want, rgb, "an EOI in the entropy data", NULL);
    memcpy(b, jpg, len);
    b[2] = 0xFF;
    b[3] = 0x01; /* the first segment's marker broken */
    bad_then_good(&c, b, len, jpg, len, want, rgb, "a bad marker after SOI", NULL);
    memcpy(b, jpg, len);
    b[0] = 0x00; /* no SOI at all */
    bad_then_good(&c, b, len, jpg, len, want, rgb, "no SOI", "no SOI");
    bad_then_good(&c, b, 0, jpg, len, want, rgb, "an empty buffer (bytesused 0)", "no SOI");

    /* truncated: in the header, at a quarter, half and three quarters of
     * the data, just the EOI missing, and one byte of it */
    const size_t cuts[] = {20,     e0 + (len - e0) / 4, e0 + (len - e0) / 2, e0 + (len - e0) * 3 / 4, len - 2,
                           len - 1};
    for (size_t k = 0; k < sizeof cuts / sizeof cuts[0]; k++) {
        char what[80];
        snprintf(what, sizeof what, "cut at %zu of %zu bytes", cuts[k], len);
        bad_then_good(&c, jpg, cuts[k], jpg, len, want, rgb, what, NULL);
    }
    /* trailing bytes after the EOI (a driver's padding) are not a fault */
    memcpy(b, jpg, len);
    memset(b + len, 0, 16);
    memset(rgb, 0, n);
    CHECKF(cam_decode(&c, b, len + 16, rgb) == 0 && !memcmp(rgb, want, n), "16 zero bytes after the EOI");

    /* another size than the capture's */
    const size_t slen = encode(src, w / 2, h / 2, 90, 2, 0, &small);
    bad_then_good(&c, small, slen, jpg, len, want, rgb, "an 80x60 JPEG in a 160x120 capture", "80x60");
    free(small);
    free(b);
    free(jpg);
    cam_mjpeg_close(c.jpeg);
    free(src);
    free(want);
    free(rgb);
}

static void table(void)
{
    const cam_fmt_t *m = cam_fmt_of_fourcc(V4L2_PIX_FMT_MJPEG), *j = cam_fmt_of_fourcc(V4L2_PIX_FMT_JPEG),
                    *g = cam_fmt_of_fourcc(V4L2_PIX_FMT_GREY);
    CHECK(m && j && g && m->bpp == 0 && j->bpp == 0 && m->rank > g->rank && j->rank > m->rank);
    CHECK(m && m->opt == CAM_FMT_MJPEG && !strcmp(cam_format_name(CAM_FMT_MJPEG), "mjpeg"));
    /* auto: last when others offer the size, chosen when it alone does
     * (a USB webcam's large sizes), or alone the rate */
    cam_fmt_cand_t c[3] = {{m, 1, 1}, {g, 1, 1}, {cam_fmt_of_fourcc(V4L2_PIX_FMT_YUYV), 1, 1}};
    CHECK(cam_fmt_best(c, 3) == 2);
    c[1].size_ok = c[2].size_ok = 0;
    CHECK(cam_fmt_best(c, 3) == 0);
    c[1].size_ok = c[2].size_ok = 1;
    c[1].fps_ok = c[2].fps_ok = 0;
    CHECK(cam_fmt_best(c, 3) == 0);
    cam_opts_t o;
    char err[256];
    char *a1[] = {"bloom_cam", "--format", "mjpeg", NULL}, *a2[] = {"bloom_cam", "--format", "MJPG", NULL},
         *a3[] = {"bloom_cam", "--format", "jpeg", NULL};
    CHECK(cam_parse_opts(&o, 3, a1, err, sizeof err) == 0 && o.format == CAM_FMT_MJPEG);
    CHECK(cam_parse_opts(&o, 3, a2, err, sizeof err) == 0 && o.format == CAM_FMT_MJPEG);
    CHECK(cam_parse_opts(&o, 3, a3, err, sizeof err) == 0 && o.format == CAM_FMT_JPEG);
}

int main(void)
{
    same_as_sim();
    bad_frames();
    table();
    return harness_finish();
}
