/* bloom_sim inputs: format detection by content, single images (PPM/PGM/
 * PFM through imgio, PNG, JPEG, OpenEXR), Y4M streams and raw V4L2 dumps.
 * Every message has the form "PATH: frame N: what is wrong". */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* fseeko, ftello, fileno */
#endif

#include "sim.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

typedef enum { K_PNM, K_PNG, K_JPEG, K_EXR, K_Y4M, K_RAW } kind_t;

struct sim_source {
    char *path;
    FILE *f; /* Y4M and raw: the open stream */
    kind_t kind;
    long frames;            /* -1: unknown until the end (a pipe) */
    long next;              /* number of the next frame */
    unsigned long long pos; /* bytes of the stream consumed */
    sim_input_opts_t o;
    int w, h;
    int sx, sy, mono, full; /* Y4M chroma subsampling (log2), luma only, full range */
    int fps_num, fps_den;
    size_t frame_bytes; /* Y4M payload or raw frame, bytes */
    size_t stride;      /* raw row bytes */
    unsigned char *buf;
    size_t cap;    /* bytes allocated at buf */
    size_t errlen; /* of the caller's err buffer */
    char desc[160];
};

static int SIM_PRINTF(4, 5) src_err(const sim_source_t *s, long frame, char *err, const char *fmt, ...);

/* "PATH: frame N: " and the message; returns -1. */
static int src_err(const sim_source_t *s, long frame, char *err, const char *fmt, ...)
{
    if (!err || !s->errlen)
        return -1;
    int n = snprintf(err, s->errlen, "%s: frame %ld: ", s->path, frame);
    if (n >= 0 && (size_t)n < s->errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err + n, s->errlen - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

long sim_source_frames(const sim_source_t *s)
{
    return s->frames;
}
const char *sim_source_desc(const sim_source_t *s)
{
    return s->desc;
}

int sim_source_fps(const sim_source_t *s, int *num, int *den)
{
    if (s->kind != K_Y4M || s->fps_num < 1)
        return -1;
    *num = s->fps_num;
    *den = s->fps_den;
    return 0;
}

void sim_source_close(sim_source_t *s)
{
    if (!s)
        return;
    if (s->f && s->f != stdin)
        fclose(s->f);
    free(s->buf);
    free(s->path);
    free(s);
}

/* ---- Y4M --------------------------------------------------------------- */

/* Reads one header line (without the '\n') into line, after the n bytes
 * already there. Returns its length, -1 on a clean end of file before any
 * byte, -2 on end of file inside the line, -3 when the line is longer than
 * cap - 1. */
static long read_line(sim_source_t *s, char *line, size_t cap, size_t n)
{
    for (;;) {
        int c = getc(s->f);
        if (c == EOF)
            return n ? -2 : -1;
        s->pos++;
        if (c == '\n')
            break;
        if (n + 1 >= cap)
            return -3;
        line[n++] = (char)(c >= 0x20 && c < 0x7f ? c : '?');
    }
    line[n] = '\0';
    return (long)n;
}

/* The stream header; its first n0 bytes (the magic) were read into m. */
static int parse_y4m_header(sim_source_t *s, const unsigned char *m, size_t n0, char *err)
{
    char line[4096];
    memcpy(line, m, n0);
    long n = read_line(s, line, sizeof line, n0);
    if (n < 0)
        return src_err(s, 0, err, "bad Y4M stream header: %s",
                       n == -3 ? "no end of line in the first 4096 bytes"
                               : "the file ends inside the header");
    char *save = NULL, *tok = strtok_r(line, " ", &save);
    if (!tok || strcmp(tok, "YUV4MPEG2"))
        return src_err(s, 0, err, "bad Y4M stream header: does not start with \"YUV4MPEG2 \"");
    const char *cs = "420jpeg";
    s->sx = s->sy = 1;
    while ((tok = strtok_r(NULL, " ", &save))) {
        char *end;
        long a, b;
        switch (tok[0]) {
        case 'W':
        case 'H':
            a = strtol(tok + 1, &end, 10);
            if (*end || end == tok + 1 || a < 1 || a > BLOOM_MAX_DIM)
                return src_err(s, 0, err, "bad Y4M stream header: %s '%s' (must be 1..%d)",
                               tok[0] == 'W' ? "width" : "height", tok + 1, BLOOM_MAX_DIM);
            *(tok[0] == 'W' ? &s->w : &s->h) = (int)a;
            break;
        case 'F':
            a = strtol(tok + 1, &end, 10);
            b = *end == ':' ? strtol(end + 1, &end, 10) : 0;
            if (*end || a < 1 || b < 1 || a > 1000000000L || b > 1000000000L)
                return src_err(s, 0, err, "bad Y4M stream header: frame rate '%s' is not N:D", tok + 1);
            s->fps_num = (int)a;
            s->fps_den = (int)b;
            break;
        case 'C':
            cs = tok + 1;
            if (!strcmp(cs, "420jpeg") || !strcmp(cs, "420paldv") || !strcmp(cs, "420mpeg2") ||
                !strcmp(cs, "420"))
                s->sx = s->sy = 1;
            else if (!strcmp(cs, "422"))
                s->sx = 1, s->sy = 0;
            else if (!strcmp(cs, "444"))
                s->sx = s->sy = 0;
            else if (!strcmp(cs, "mono"))
                s->mono = 1;
            else
                return src_err(s, 0, err,
                               "Y4M colour space C%s not supported (8-bit C420jpeg, C420paldv, "
                               "C420mpeg2, C420, C422, C444 and Cmono are)",
                               cs);
            break;
        case 'X':
            if (!strcmp(tok, "XCOLORRANGE=FULL"))
                s->full = 1;
            else if (!strcmp(tok, "XCOLORRANGE=LIMITED"))
                s->full = 0;
            break;
        default: /* I (interlacing), A (aspect) and others: not needed */
            break;
        }
    }
    if (!s->w || !s->h)
        return src_err(s, 0, err, "bad Y4M stream header: no %s", s->w ? "H (height)" : "W (width)");
    const size_t cw = (size_t)(s->w + s->sx) >> s->sx, ch = (size_t)(s->h + s->sy) >> s->sy;
    s->frame_bytes = (size_t)s->w * (size_t)s->h + (s->mono ? 0 : 2 * cw * ch);
    snprintf(s->desc, sizeof s->desc, "Y4M %dx%d C%s, %s-range BT.601", s->w, s->h, cs,
             s->full ? "full" : "limited");
    return 0;
}

/* The header of frame s->next: 1 ok, 0 clean end of stream, -1 error. */
static int y4m_frame_header(sim_source_t *s, char *err)
{
    char line[256];
    unsigned long long at = s->pos;
    long n = read_line(s, line, sizeof line, 0);
    if (n == -1)
        return 0;
    if (n == -2)
        return src_err(s, s->next, err, "truncated: the file ends inside the frame header (byte offset %llu)",
                       at);
    if (n == -3 || strncmp(line, "FRAME", 5) || (line[5] != '\0' && line[5] != ' ')) {
        line[n == -3 || n > 40 ? 40 : n] = '\0';
        return src_err(s, s->next, err,
                       "bad frame header at byte offset %llu: expected \"FRAME\", got \"%s\"", at, line);
    }
    return 1;
}

/* Regular files: walk every frame header and check the size before any
 * frame is processed, so a truncated or damaged stream writes nothing. */
static int y4m_prescan(sim_source_t *s, off_t size, char *err)
{
    const off_t data = ftello(s->f);
    const unsigned long long pos0 = s->pos;
    for (;;) {
        int r = y4m_frame_header(s, err);
        if (r < 0)
            return -1;
        if (r == 0)
            break;
        off_t here = ftello(s->f);
        if (size - here < (off_t)s->frame_bytes)
            return src_err(s, s->next, err,
                           "truncated: expected %zu bytes of frame data at byte offset %llu, got %lld",
                           s->frame_bytes, (unsigned long long)here, (long long)(size - here));
        if (fseeko(s->f, here + (off_t)s->frame_bytes, SEEK_SET))
            return src_err(s, s->next, err, "seek failed: %s", strerror(errno));
        s->pos += s->frame_bytes;
        s->next++;
    }
    s->frames = s->next;
    s->next = 0;
    s->pos = pos0;
    if (s->frames == 0)
        return src_err(s, 0, err, "no frames: the Y4M stream ends after its header");
    if (fseeko(s->f, data, SEEK_SET))
        return src_err(s, 0, err, "seek failed: %s", strerror(errno));
    return 0;
}

static void y4m_convert(const sim_source_t *s, sim_frame_t *f)
{
    const unsigned char *yp = s->buf;
    const size_t cw = (size_t)(s->w + s->sx) >> s->sx, ch = (size_t)(s->h + s->sy) >> s->sy;
    const unsigned char *up = yp + (size_t)s->w * (size_t)s->h, *vp = up + cw * ch;
    for (int y = 0; y < s->h; y++)
        for (int x = 0; x < s->w; x++) {
            size_t i = (size_t)y * (size_t)s->w + (size_t)x;
            size_t c = ((size_t)y >> s->sy) * cw + ((size_t)x >> s->sx); /* nearest chroma */
            sim_ycbcr_to_rgb(yp[i], s->mono ? 128 : up[c], s->mono ? 128 : vp[c], s->full, f->px + 3 * i);
        }
}

/* ---- raw V4L2 dumps ------------------------------------------------------ */

static const char *raw_name(sim_raw_fmt_t fmt)
{
    static const char *const names[] = {"?",    "YUYV", "RGB24", "GREY", "RGB565", "UYVY",
                                        "YVYU", "NV12", "NV21",  "NV16", "NV61"};
    return names[fmt < sizeof names / sizeof names[0] ? fmt : 0];
}

/* NV..: the chroma rows' vertical shift (4:2:0 1, 4:2:2 0); -1 otherwise */
static int nv_shift(sim_raw_fmt_t fmt)
{
    return fmt == SIM_RAW_NV12 || fmt == SIM_RAW_NV21   ? 1
           : fmt == SIM_RAW_NV16 || fmt == SIM_RAW_NV61 ? 0
                                                        : -1;
}

static int raw_setup(sim_source_t *s, off_t size, int regular, char *err)
{
    const sim_raw_fmt_t rf = s->o.raw_fmt;
    const int nv = nv_shift(rf);
    const int bpp = rf == SIM_RAW_RGB24 ? 3 : rf == SIM_RAW_GREY || nv >= 0 ? 1 : 2;
    s->w = s->o.raw_w;
    s->h = s->o.raw_h;
    if (s->w < 1 || s->h < 1 || s->w > BLOOM_MAX_DIM || s->h > BLOOM_MAX_DIM)
        return src_err(s, 0, err, "raw frames of %dx%d: each side must be 1..%d (the engine's limit)", s->w,
                       s->h, BLOOM_MAX_DIM);
    if ((rf == SIM_RAW_YUYV || rf == SIM_RAW_UYVY || rf == SIM_RAW_YVYU) && s->w % 2)
        return src_err(s, 0, err, "%s needs an even width (got %d)", raw_name(rf), s->w);
    /* NV..: each row's chroma pairs cover an odd width's last pixel too */
    const size_t row = nv >= 0 ? (size_t)(s->w + (s->w & 1)) : (size_t)s->w * (size_t)bpp;
    s->stride = s->o.raw_stride ? (size_t)s->o.raw_stride : row;
    if (s->stride < row)
        return src_err(s, 0, err, "--raw-stride %zu is less than the %zu bytes of a row", s->stride, row);
    if (s->stride > SIZE_MAX / 4 / (size_t)s->h)
        return src_err(s, 0, err, "frames of %zu x %d bytes are too large", s->stride, s->h);
    s->frame_bytes = s->stride * ((size_t)s->h + (nv < 0 ? 0 : ((size_t)s->h + (size_t)nv) >> nv));
    snprintf(s->desc, sizeof s->desc, "raw %s %dx%d, %zu bytes per frame", raw_name(s->o.raw_fmt), s->w, s->h,
             s->frame_bytes);
    if (!regular)
        return 0;
    if (size == 0)
        return src_err(s, 0, err, "empty file: no frames");
    s->frames = (long)(size / (off_t)s->frame_bytes);
    off_t rest = size % (off_t)s->frame_bytes;
    if (rest)
        return src_err(s, s->frames, err,
                       "partial frame at byte offset %lld: %lld of %zu bytes (the file is not a "
                       "whole number of %dx%d %s frames)",
                       (long long)(size - rest), (long long)rest, s->frame_bytes, s->w, s->h,
                       raw_name(s->o.raw_fmt));
    return 0;
}

static void raw_convert(const sim_source_t *s, sim_frame_t *f)
{
    const int is565 = s->o.raw_fmt == SIM_RAW_RGB565, nv = nv_shift(s->o.raw_fmt), how = s->o.raw_ycc;
    f->max[0] = f->max[2] = is565 ? 31 : 255;
    f->max[1] = is565 ? 63 : 255;
    const unsigned char *chroma = s->buf + s->stride * (size_t)s->h; /* NV..: after the luma rows */
    for (int y = 0; y < s->h; y++) {
        const unsigned char *r = s->buf + (size_t)y * s->stride;
        const unsigned char *cr = nv >= 0 ? chroma + (size_t)(y >> nv) * s->stride : r;
        uint32_t *o = f->px + (size_t)y * (size_t)s->w * 3u;
        for (int x = 0; x < s->w; x++, o += 3) {
            const size_t pair = (size_t)(x / 2); /* the pixel pair sharing a chroma sample */
            switch (s->o.raw_fmt) {
            case SIM_RAW_YUYV: /* Y0 U Y1 V: a pair shares its chroma */
                sim_ycbcr_to_rgb(r[4 * pair + 2 * (size_t)(x % 2)], r[4 * pair + 1], r[4 * pair + 3], how, o);
                break;
            case SIM_RAW_UYVY: /* U Y0 V Y1 */
                sim_ycbcr_to_rgb(r[4 * pair + 1 + 2 * (size_t)(x % 2)], r[4 * pair], r[4 * pair + 2], how, o);
                break;
            case SIM_RAW_YVYU: /* Y0 V Y1 U */
                sim_ycbcr_to_rgb(r[4 * pair + 2 * (size_t)(x % 2)], r[4 * pair + 3], r[4 * pair + 1], how, o);
                break;
            case SIM_RAW_NV12: /* the chroma rows: Cb Cr pairs, nearest (each of 2 x 2^nv pixels) */
            case SIM_RAW_NV16:
                sim_ycbcr_to_rgb(r[x], cr[2 * pair], cr[2 * pair + 1], how, o);
                break;
            case SIM_RAW_NV21: /* Cr Cb pairs */
            case SIM_RAW_NV61:
                sim_ycbcr_to_rgb(r[x], cr[2 * pair + 1], cr[2 * pair], how, o);
                break;
            case SIM_RAW_RGB24:
                o[0] = r[3 * x];
                o[1] = r[3 * x + 1];
                o[2] = r[3 * x + 2];
                break;
            case SIM_RAW_GREY:
                o[0] = o[1] = o[2] = r[x];
                break;
            default: { /* RGB565: little-endian rrrrrggg gggbbbbb */
                unsigned wd = (unsigned)r[2 * x] | (unsigned)r[2 * x + 1] << 8;
                o[0] = wd >> 11;
                o[1] = (wd >> 5) & 63u;
                o[2] = wd & 31u;
                break;
            }
            }
        }
    }
}

/* ---- opening ----------------------------------------------------------------- */

static int detect(sim_source_t *s, const unsigned char *m, size_t n, char *err)
{
    if (n == 0)
        return src_err(s, 0, err, "empty file");
    if (n >= 2 && m[0] == 'P' && ((m[1] >= '1' && m[1] <= '7') || m[1] == 'F' || m[1] == 'f'))
        s->kind = K_PNM;
    else if (n >= 8 && !memcmp(m, "\x89PNG\r\n\x1a\n", 8))
        s->kind = K_PNG;
    else if (n >= 3 && m[0] == 0xFF && m[1] == 0xD8 && m[2] == 0xFF)
        s->kind = K_JPEG;
    else if (n >= 4 && !memcmp(m, "\x76\x2f\x31\x01", 4))
        s->kind = K_EXR;
    else if (n >= 9 && !memcmp(m, "YUV4MPEG2", 9))
        s->kind = K_Y4M;
    else {
        char hex[40] = "";
        for (size_t i = 0; i < n && i < 8; i++)
            snprintf(hex + 3 * i, sizeof hex - 3 * i, " %02x", m[i]);
        return src_err(s, 0, err,
                       "unrecognised format (first bytes%s): not PPM/PGM/PFM, PNG, JPEG, OpenEXR "
                       "or Y4M; a raw dump needs --raw-size and --raw-format",
                       hex);
    }
    if (s->kind == K_EXR && !sim_exr_available())
        return src_err(s, 0, err, "OpenEXR support not built in (needs libopenexr-dev)");
    return 0;
}

int sim_source_open(sim_source_t **out, const char *path, const sim_input_opts_t *o, char *err, size_t errlen)
{
    *out = NULL;
    sim_source_t *s = calloc(1, sizeof *s);
    if (!s || !(s->path = strdup(!strcmp(path, "-") ? "(stdin)" : path))) {
        free(s);
        return sim_errf(err, errlen, "%s: out of memory", path);
    }
    s->o = *o;
    s->errlen = errlen;
    s->frames = 1;
    int is_stdin = !strcmp(path, "-");
    s->f = is_stdin ? stdin : fopen(path, "rb");
    if (!s->f) {
        src_err(s, 0, err, "cannot open: %s", strerror(errno));
        sim_source_close(s);
        return -1;
    }
    struct stat st;
    int regular = !is_stdin && fstat(fileno(s->f), &st) == 0 && S_ISREG(st.st_mode);
    if (!is_stdin && !regular && fstat(fileno(s->f), &st) == 0 && S_ISDIR(st.st_mode)) {
        src_err(s, 0, err, "cannot read: is a directory");
        sim_source_close(s);
        return -1;
    }
    int rc = 0;
    if (o->raw_fmt != SIM_RAW_NONE) {
        s->kind = K_RAW;
        s->frames = -1;
        rc = raw_setup(s, regular ? st.st_size : 0, regular, err);
    } else {
        unsigned char m[9]; /* enough for every magic ("YUV4MPEG2" is the longest) */
        size_t n = fread(m, 1, sizeof m, s->f);
        rc = detect(s, m, n, err);
        if (rc == 0 && s->kind != K_Y4M && (is_stdin || !regular))
            rc = src_err(s, 0, err, "images are read from regular files only (pipes carry Y4M or raw dumps)");
        if (rc == 0 && s->kind == K_Y4M) {
            s->pos = n;
            s->frames = -1;
            rc = parse_y4m_header(s, m, n, err);
            if (rc == 0 && regular)
                rc = y4m_prescan(s, st.st_size, err);
        }
        if (s->kind != K_Y4M && s->f != stdin) { /* single images: decoded when read */
            fclose(s->f);
            s->f = NULL;
        }
    }
    /* A regular file's frames are checked against its size above: the
     * frame buffer is allocated now. From a pipe it grows as the data comes
     * (read_frame), so a header that claims a huge frame costs nothing the
     * stream does not deliver. */
    if (rc == 0 && regular && (s->kind == K_Y4M || s->kind == K_RAW)) {
        s->cap = s->frame_bytes ? s->frame_bytes : 1;
        if (!(s->buf = malloc(s->cap)))
            rc = src_err(s, 0, err, "out of memory");
    }
    if (rc) {
        sim_source_close(s);
        return -1;
    }
    *out = s;
    return 0;
}

/* ---- reading ------------------------------------------------------------------ */

static const char *kind_name(kind_t k)
{
    return k == K_PNG ? "PNG" : k == K_JPEG ? "JPEG" : k == K_EXR ? "OpenEXR" : "PNM";
}

static int read_image(sim_source_t *s, sim_frame_t *f, char *err)
{
    img_t im;
    char why[SIM_ERRLEN];
    int rc;
    if (s->kind == K_PNM) {
        rc = img_read_max(s->path, &im, BLOOM_MAX_DIM, why, sizeof why);
        /* imgio's message starts with the path: keep only what is wrong */
        size_t pl = strlen(s->path);
        if (rc && !strncmp(why, s->path, pl) && !strncmp(why + pl, ": ", 2))
            memmove(why, why + pl + 2, strlen(why + pl + 2) + 1);
    } else if (s->kind == K_EXR) {
        rc = sim_exr_read(s->path, &im, why, sizeof why);
    } else {
        FILE *fp = fopen(s->path, "rb");
        if (!fp)
            return src_err(s, 0, err, "cannot open: %s", strerror(errno));
        rc = s->kind == K_PNG ? sim_png_read(fp, &im, why, sizeof why)
                              : sim_jpeg_read(fp, &im, why, sizeof why);
        fclose(fp);
    }
    if (rc) /* each decoder refuses a side above BLOOM_MAX_DIM as it reads the header */
        return src_err(s, 0, err, "%s", why);
    const char *what = s->kind == K_PNM ? (im.f32             ? "PFM"
                                           : im.channels == 1 ? "PGM"
                                                              : "PPM")
                                        : kind_name(s->kind);
    if (im.f32)
        snprintf(s->desc, sizeof s->desc, "%s %dx%d float %s -> linear", what, im.width, im.height,
                 im.channels == 1 ? "grey" : "RGB");
    else
        snprintf(s->desc, sizeof s->desc, "%s %dx%d %d-bit %s%s", what, im.width, im.height,
                 im.maxval > 255 ? 16 : 8, im.channels == 1 ? "grey" : "RGB",
                 im.maxval <= 255     ? " (sRGB codes)"
                 : s->o.decode16_srgb ? " -> linear (sRGB-encoded)"
                                      : " -> linear (linear light)");
    rc = sim_frame_from_img(&im, s->o.decode16_srgb, f);
    img_free(&im);
    if (rc)
        return src_err(s, 0, err, "out of memory");
    return 0;
}

/* Reads up to one frame's bytes into s->buf, growing it (doubling, from
 * 64 KiB) while the stream delivers; returns the bytes read, or -1 out of
 * memory. */
static long long read_frame(sim_source_t *s)
{
    size_t got = 0;
    while (got < s->frame_bytes) {
        if (got == s->cap) {
            size_t n = s->cap < 65536 ? 65536 : s->cap * 2;
            if (n > s->frame_bytes || n < s->cap)
                n = s->frame_bytes;
            unsigned char *b = realloc(s->buf, n);
            if (!b)
                return -1;
            s->buf = b;
            s->cap = n;
        }
        size_t want = (s->cap < s->frame_bytes ? s->cap : s->frame_bytes) - got;
        size_t n = fread(s->buf + got, 1, want, s->f);
        got += n;
        if (n < want)
            break; /* end of the stream or an error: the caller tells which */
    }
    return (long long)got;
}

int sim_source_read(sim_source_t *s, sim_frame_t *f, char *err, size_t errlen)
{
    s->errlen = errlen;
    if (s->frames >= 0 && s->next >= s->frames)
        return 0;
    if (s->kind != K_Y4M && s->kind != K_RAW) {
        if (read_image(s, f, err))
            return -1;
        s->next++;
        return 1;
    }
    if (s->kind == K_Y4M) {
        int r = y4m_frame_header(s, err);
        if (r <= 0) {
            if (r == 0 && s->next == 0)
                return src_err(s, 0, err, "no frames: the Y4M stream ends after its header");
            return r;
        }
    }
    const long long rd = read_frame(s);
    if (rd < 0)
        return src_err(s, s->next, err, "out of memory for a frame of %zu bytes", s->frame_bytes);
    const size_t got = (size_t)rd;
    if (got != s->frame_bytes) {
        if (ferror(s->f))
            return src_err(s, s->next, err, "read error: %s", strerror(errno));
        if (s->kind == K_RAW && got == 0) {
            if (s->next == 0)
                return src_err(s, 0, err, "empty input: no frames");
            return 0;
        }
        if (s->kind == K_RAW)
            return src_err(s, s->next, err,
                           "partial frame at byte offset %llu: %zu of %zu bytes (the input is not "
                           "a whole number of %dx%d %s frames)",
                           s->pos, got, s->frame_bytes, s->w, s->h, raw_name(s->o.raw_fmt));
        return src_err(s, s->next, err,
                       "truncated: expected %zu bytes of frame data at byte offset %llu, got %zu",
                       s->frame_bytes, s->pos, got);
    }
    s->pos += got;
    if (sim_frame_alloc(f, s->w, s->h))
        return src_err(s, s->next, err, "out of memory");
    f->max[0] = f->max[1] = f->max[2] = 255;
    if (s->kind == K_Y4M)
        y4m_convert(s, f);
    else
        raw_convert(s, f);
    s->next++;
    return 1;
}
