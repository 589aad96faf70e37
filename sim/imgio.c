/* Image file I/O for the host tools: P5/P6 (8/16-bit) and PF/Pf. See imgio.h.
 * Headers are read byte by byte with getc so that the "exactly one whitespace
 * byte after maxval/scale" rule can be honoured; pixels are read row by row. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* mkstemp, fchmod, fsync, ftello */
#endif

#include "imgio.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#define IMG_MAXDIM 65535
#define IMG_MAXVAL 65535

#if defined(__GNUC__)
#define PRINTF_LIKE(a, b) __attribute__((format(printf, a, b)))
#else
#define PRINTF_LIKE(a, b)
#endif

_Static_assert(sizeof(float) == 4, "PFM samples are 32-bit IEEE floats");

/* Writes "path: message" into err; returns -1 so callers can "return set_err(...)". */
static int PRINTF_LIKE(4, 5) set_err(char *err, size_t errlen, const char *path, const char *fmt, ...)
{
    if (!err || errlen == 0)
        return -1;
    int n = snprintf(err, errlen, "%s: ", path);
    if (n >= 0 && (size_t)n < errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err + n, errlen - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

void img_free(img_t *img)
{
    if (!img)
        return;
    free(img->u16);
    free(img->f32);
    memset(img, 0, sizeof *img);
}

int img_alloc(img_t *img, int w, int h, int channels, int maxval)
{
    if (!img)
        return -1;
    memset(img, 0, sizeof *img);
    if (w < 1 || w > IMG_MAXDIM || h < 1 || h > IMG_MAXDIM || (channels != 1 && channels != 3) ||
        maxval < 0 || maxval > IMG_MAXVAL)
        return -1;
    size_t elem = maxval ? sizeof(uint16_t) : sizeof(float);
    size_t n = (size_t)w * (size_t)h; /* <= 65535^2: fits even a 32-bit size_t */
    if (n > SIZE_MAX / (size_t)channels / elem)
        return -1;
    n *= (size_t)channels;
    if (maxval)
        img->u16 = calloc(n, elem);
    else
        img->f32 = calloc(n, elem);
    if (!img->u16 && !img->f32)
        return -1;
    img->width = w;
    img->height = h;
    img->channels = channels;
    img->maxval = maxval;
    return 0;
}

/* ---- reading ---- */

typedef struct {
    FILE *f;
    const char *path;
    char *err;
    size_t errlen;
    int maxdim; /* largest width or height taken */
} rd_t;

#define rfail(r, ...) set_err((r)->err, (r)->errlen, (r)->path, __VA_ARGS__)

static bool is_ws(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

/* Describes one byte for a message; buf must hold 16 chars. */
static const char *show_byte(int c, char *buf)
{
    snprintf(buf, 16, c >= 0x20 && c < 0x7f ? "'%c'" : "byte 0x%02x", (unsigned)c);
    return buf;
}

/* End of file (or a read error) inside the header. */
static int header_eof(rd_t *r, const char *where, const char *what)
{
    int e = errno;
    if (ferror(r->f))
        return rfail(r, "read error: %s", strerror(e));
    return rfail(r, "bad header: unexpected end of file %s %s", where, what);
}

/* Skips whitespace and (PNM only) '#' comments, which run to CR or LF. */
static int skip_space(FILE *f, bool comments)
{
    for (;;) {
        int c = getc(f);
        if (c == '#' && comments) {
            do
                c = getc(f);
            while (c != EOF && c != '\n' && c != '\r');
            if (c == EOF)
                return EOF;
        } else if (!is_ws(c)) {
            return c;
        }
    }
}

/* Checks the byte after a header token: whitespace (consumed), or for PNM
 * a '#' starting a comment, except after maxval, where exactly one
 * whitespace byte separates the header from the pixels. */
static int token_end(rd_t *r, int c, bool comment_ok, const char *what, const char *tok)
{
    char b[16];
    if (c == EOF)
        return header_eof(r, "after", what);
    if (c == '#' && comment_ok)
        ungetc(c, r->f);
    else if (!is_ws(c))
        return rfail(r, "bad header: %s %s is followed by %s, not whitespace", what, tok, show_byte(c, b));
    return 0;
}

/* Reads a decimal header field in 1..limit. */
static int read_field(rd_t *r, bool comments, const char *what, bool last, long limit, int *out)
{
    char b[16], digits[20];
    int c = skip_space(r->f, comments);
    if (c == EOF)
        return header_eof(r, "before", what);
    if (c < '0' || c > '9')
        return rfail(r, "bad header: expected %s as a decimal number, got %s", what, show_byte(c, b));
    size_t nd = 0;
    long v = 0;
    for (; c >= '0' && c <= '9'; c = getc(r->f)) {
        if (nd < sizeof digits - 4)
            digits[nd++] = (char)c;
        else if (nd == sizeof digits - 4) {
            memcpy(digits + nd, "...", 3);
            nd += 3;
        }
        v = v * 10 + (c - '0');
        if (v > limit)
            v = limit + 1; /* saturate: keeps the arithmetic from overflowing */
    }
    digits[nd] = '\0';
    if (token_end(r, c, comments && !last, what, digits) != 0)
        return -1;
    if (v == 0)
        return rfail(r, "bad header: %s is 0 (must be 1..%ld)", what, limit);
    if (v > limit && limit < IMG_MAXDIM) /* a caller's own side limit (maxval's is 65535) */
        return rfail(r, "bad header: %s %s exceeds the limit of %ld per side", what, digits, limit);
    if (v > limit)
        return rfail(r, "bad header: %s %s exceeds %ld", what, digits, limit);
    *out = (int)v;
    return 0;
}

/* PFM scale: a float token followed by one whitespace byte; its sign gives
 * the byte order, its magnitude is ignored (samples are returned as stored). */
static int read_scale(rd_t *r, bool *little)
{
    char tok[64];
    size_t n = 0;
    int c = skip_space(r->f, false);
    if (c == EOF)
        return header_eof(r, "before", "scale");
    for (; c != EOF && !is_ws(c); c = getc(r->f))
        if (n < sizeof tok - 1)
            tok[n++] = (char)(c >= 0x20 && c < 0x7f ? c : '?');
    tok[n] = '\0';
    if (token_end(r, c, false, "scale", tok) != 0)
        return -1;
    char *end;
    double s = strtod(tok, &end);
    if (end == tok || *end != '\0' || n == sizeof tok - 1)
        return rfail(r, "bad header: scale '%s' is not a number", tok);
    if (!isfinite(s) || s == 0.0)
        return rfail(r, "bad header: scale '%s' must be nonzero and finite (its sign gives the byte order)",
                     tok);
    *little = s < 0.0;
    return 0;
}

static int truncated(rd_t *r, uint64_t expected, uint64_t got)
{
    return rfail(r, "truncated: expected %llu bytes of pixel data, got %llu", (unsigned long long)expected,
                 (unsigned long long)got);
}

/* Bytes from the current position to the end of a regular file; -1 when
 * that cannot be known (a pipe). */
static long long bytes_left(FILE *f)
{
    struct stat st;
    off_t pos = ftello(f);
    if (pos < 0 || fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode))
        return -1;
    return st.st_size > pos ? (long long)(st.st_size - pos) : 0;
}

/* maxval 0 means float samples (4 bytes, rows stored bottom to top). */
static int read_pixels(rd_t *r, img_t *img, int w, int h, int ch, int maxval, bool little)
{
    size_t bps = maxval == 0 ? 4 : maxval > 255 ? 2 : 1;
    size_t per_row = (size_t)w * (size_t)ch, rowbytes = per_row * bps;
    size_t elem = maxval ? sizeof(uint16_t) : sizeof(float), row_elems = per_row * elem;
    uint64_t expected = (uint64_t)rowbytes * (uint64_t)h;

    /* Check the size first when we can, so a lying header cannot make us
     * allocate gigabytes just to find out the file is short. From a pipe
     * the samples grow with the rows that arrive (doubling), so there too
     * memory follows the data, not the header's claim. */
    long long avail = bytes_left(r->f);
    if (avail >= 0 && (uint64_t)avail < expected)
        return truncated(r, expected, (uint64_t)avail);
    if (expected > SIZE_MAX || (uint64_t)row_elems * (uint64_t)h > SIZE_MAX)
        return rfail(r, "out of memory for a %dx%dx%d image", w, h, ch);
    int cap = avail >= 0 || h < 64 ? h : 64; /* rows allocated */
    unsigned char *buf = malloc(row_elems * (size_t)cap);
    unsigned char *row = malloc(rowbytes);
    if (!buf || !row) {
        free(buf);
        free(row);
        return rfail(r, "out of memory for a %dx%dx%d image", w, h, ch);
    }
    int rc = 0;
    for (int y = 0; y < h && rc == 0; y++) {
        if (y == cap) {
            int ncap = cap > h / 2 ? h : 2 * cap;
            unsigned char *nb = realloc(buf, row_elems * (size_t)ncap);
            if (!nb) {
                rc = rfail(r, "out of memory for a %dx%dx%d image", w, h, ch);
                break;
            }
            buf = nb;
            cap = ncap;
        }
        size_t got = fread(row, 1, rowbytes, r->f);
        if (got != rowbytes) {
            int e = errno;
            rc = ferror(r->f) ? rfail(r, "read error: %s", strerror(e))
                              : truncated(r, expected, (uint64_t)rowbytes * (uint64_t)y + got);
        } else if (maxval == 0) {
            float *out = (float *)(void *)(buf + (size_t)y * row_elems); /* file order: flipped below */
            for (size_t i = 0; i < per_row; i++) {
                uint32_t u = 0;
                for (unsigned k = 0; k < 4; k++)
                    u |= (uint32_t)row[4 * i + (little ? k : 3 - k)] << (8 * k);
                /* assumes float and uint32_t share byte order, as on every host we build on */
                memcpy(&out[i], &u, sizeof u);
            }
        } else {
            uint16_t *out = (uint16_t *)(void *)(buf + (size_t)y * row_elems);
            for (size_t i = 0; i < per_row && rc == 0; i++) {
                unsigned v = bps == 2 ? (unsigned)row[2 * i] << 8 | row[2 * i + 1] : row[i];
                if (v > (unsigned)maxval)
                    rc = rfail(r, "sample value %u exceeds maxval %d (row %d, column %zu)", v, maxval, y,
                               i / (size_t)ch);
                out[i] = (uint16_t)v;
            }
        }
    }
    if (rc == 0 && maxval == 0) /* PFM stores the bottom row first */
        for (int y = 0; y < h / 2; y++) {
            unsigned char *a = buf + (size_t)y * row_elems, *b = buf + (size_t)(h - 1 - y) * row_elems;
            for (size_t i = 0; i < row_elems; i++) {
                unsigned char t = a[i];
                a[i] = b[i];
                b[i] = t;
            }
        }
    free(row);
    if (rc != 0) {
        free(buf);
        return rc;
    }
    img->width = w;
    img->height = h;
    img->channels = ch;
    img->maxval = maxval;
    if (maxval)
        img->u16 = (uint16_t *)(void *)buf;
    else
        img->f32 = (float *)(void *)buf;
    return 0;
}

static int read_file(rd_t *r, img_t *img)
{
    int m0 = getc(r->f);
    if (m0 == EOF)
        return ferror(r->f) ? rfail(r, "read error: %s", strerror(errno))
                            : rfail(r, "bad header: empty file");
    int m1 = getc(r->f);
    bool pnm = m0 == 'P' && (m1 == '5' || m1 == '6');
    bool pfm = m0 == 'P' && (m1 == 'F' || m1 == 'f');
    if (!pnm && !pfm) {
        char magic[12] = "";
        for (int i = 0, c = m0, n = 0; i < 2 && c != EOF; c = m1, i++)
            n += snprintf(magic + n, sizeof magic - (size_t)n,
                          c >= 0x20 && c < 0x7f && c != '\\' ? "%c" : "\\x%02x", (unsigned)c);
        return rfail(r, "bad header: '%s' is not P5, P6, PF or Pf", magic);
    }
    char tok[3] = {'P', (char)m1, '\0'};
    if (token_end(r, getc(r->f), pnm, "magic", tok) != 0)
        return -1;
    int w, h, maxval = 0, ch = (m1 == '6' || m1 == 'F') ? 3 : 1;
    bool little = false;
    if (read_field(r, pnm, "width", false, r->maxdim, &w) != 0 ||
        read_field(r, pnm, "height", false, r->maxdim, &h) != 0 ||
        (pnm ? read_field(r, true, "maxval", true, IMG_MAXVAL, &maxval) : read_scale(r, &little)) != 0)
        return -1;
    return read_pixels(r, img, w, h, ch, maxval, little);
}

int img_fread(FILE *f, const char *name, img_t *img, int maxdim, char *err, size_t errlen)
{
    if (!name)
        name = "(stream)";
    if (!img || !f)
        return set_err(err, errlen, name, "no image to read into");
    memset(img, 0, sizeof *img);
    if (err && errlen)
        err[0] = '\0';
    if (maxdim < 1 || maxdim > IMG_MAXDIM)
        maxdim = IMG_MAXDIM;
    rd_t r = {f, name, err, errlen, maxdim};
    int rc = read_file(&r, img);
    if (rc != 0)
        img_free(img);
    return rc;
}

int img_read_max(const char *path, img_t *img, int maxdim, char *err, size_t errlen)
{
    if (!path)
        path = "(null path)";
    if (!img)
        return set_err(err, errlen, path, "no image to read into");
    memset(img, 0, sizeof *img);
    FILE *f = fopen(path, "rb");
    if (!f)
        return set_err(err, errlen, path, "cannot open: %s", strerror(errno));
    int rc = img_fread(f, path, img, maxdim, err, errlen);
    fclose(f); /* read-only: nothing to lose if close fails */
    return rc;
}

int img_read(const char *path, img_t *img, char *err, size_t errlen)
{
    return img_read_max(path, img, IMG_MAXDIM, err, errlen);
}

/* ---- writing ---- */

/* Opens "path.tmp-XXXXXX" beside path (same filesystem, so rename is atomic);
 * tmp_finish renames or removes it. */
static FILE *tmp_open(const char *path, char **tmp, char *err, size_t errlen)
{
    static const char suffix[] = ".tmp-XXXXXX";
    size_t n = strlen(path);
    if (!(*tmp = malloc(n + sizeof suffix))) {
        set_err(err, errlen, path, "out of memory");
        return NULL;
    }
    memcpy(*tmp, path, n);
    memcpy(*tmp + n, suffix, sizeof suffix);
    int fd = mkstemp(*tmp);
    if (fd < 0) {
        set_err(err, errlen, path, "cannot create temporary file %s: %s", *tmp, strerror(errno));
        free(*tmp);
        return NULL;
    }
    /* mkstemp creates 0600; give the result the mode a plain fopen would
     * (reading the umask briefly changes it: fine for single-threaded tools) */
    mode_t mask = umask(0);
    umask(mask);
    FILE *f = NULL;
    if (fchmod(fd, 0666 & ~mask) != 0 || !(f = fdopen(fd, "wb"))) {
        set_err(err, errlen, path, "cannot set up temporary file %s: %s", *tmp, strerror(errno));
        close(fd);
        remove(*tmp);
        free(*tmp);
    }
    return f;
}

/* Commits (flush, fsync, close, rename) when ok, else discards the temp.
 * Errors already reported by the caller are not overwritten. */
static int tmp_finish(FILE *f, char *tmp, const char *path, bool ok, char *err, size_t errlen)
{
    if (ok && (fflush(f) != 0 || fsync(fileno(f)) != 0)) {
        set_err(err, errlen, path, "write failed: %s", strerror(errno));
        ok = false;
    }
    if (fclose(f) != 0 && ok) {
        set_err(err, errlen, path, "write failed on close: %s", strerror(errno));
        ok = false;
    }
    if (ok && rename(tmp, path) != 0) {
        set_err(err, errlen, path, "cannot rename %s over it: %s", tmp, strerror(errno));
        ok = false;
    }
    if (!ok)
        remove(tmp);
    free(tmp);
    return ok ? 0 : -1;
}

/* Converts file row y into bytes: big-endian integers, or little-endian
 * floats taken bottom row first. False (after reporting) on a bad sample. */
static bool fill_row(const img_t *img, bool pfm, int y, unsigned char *row, const char *path, char *err,
                     size_t errlen)
{
    size_t n = (size_t)img->width * (size_t)img->channels;
    for (size_t i = 0; i < n; i++) {
        if (pfm) {
            uint32_t u;
            memcpy(&u, &img->f32[(size_t)(img->height - 1 - y) * n + i], sizeof u);
            for (unsigned k = 0; k < 4; k++)
                row[4 * i + k] = (unsigned char)(u >> (8 * k));
            continue;
        }
        unsigned v = img->u16[(size_t)y * n + i];
        if (v > (unsigned)img->maxval) {
            set_err(err, errlen, path, "cannot write: sample value %u exceeds maxval %d (row %d, column %zu)",
                    v, img->maxval, y, i / (size_t)img->channels);
            return false;
        }
        if (img->maxval > 255) {
            row[2 * i] = (unsigned char)(v >> 8);
            row[2 * i + 1] = (unsigned char)(v & 0xff);
        } else {
            row[i] = (unsigned char)v;
        }
    }
    return true;
}

static int write_image(const char *path, const img_t *img, bool pfm, char *err, size_t errlen)
{
    const char *why = NULL;
    if (!path)
        path = "(null path)";
    if (!img)
        why = "no image";
    else if (img->width < 1 || img->width > IMG_MAXDIM || img->height < 1 || img->height > IMG_MAXDIM)
        why = "width and height must be 1..65535";
    else if (img->channels != 1 && img->channels != 3)
        why = "channels must be 1 or 3";
    else if (pfm && !img->f32)
        why = "PFM needs float samples (f32 is NULL)";
    else if (!pfm && !img->u16)
        why = "PPM needs integer samples (u16 is NULL)";
    else if (!pfm && (img->maxval < 1 || img->maxval > IMG_MAXVAL))
        why = "maxval must be 1..65535";
    if (why)
        return set_err(err, errlen, path, "cannot write: %s", why);

    char header[48];
    if (pfm)
        snprintf(header, sizeof header, "P%c\n%d %d\n-1.0\n", img->channels == 3 ? 'F' : 'f', img->width,
                 img->height);
    else
        snprintf(header, sizeof header, "P%c\n%d %d\n%d\n", img->channels == 3 ? '6' : '5', img->width,
                 img->height, img->maxval);
    size_t rowbytes = (size_t)img->width * (size_t)img->channels * (pfm ? 4u : img->maxval > 255 ? 2u : 1u);
    unsigned char *row = malloc(rowbytes);
    char *tmp;
    FILE *f = row ? tmp_open(path, &tmp, err, errlen) : NULL;
    if (!f) {
        if (!row)
            set_err(err, errlen, path, "out of memory");
        free(row);
        return -1;
    }
    bool ok = true;
    int e = -1; /* errno of a failed write, captured right away */
    if (fputs(header, f) < 0)
        e = errno;
    for (int y = 0; ok && e < 0 && y < img->height; y++) {
        ok = fill_row(img, pfm, y, row, path, err, errlen);
        if (ok && fwrite(row, 1, rowbytes, f) != rowbytes)
            e = errno;
    }
    if (e >= 0) {
        set_err(err, errlen, path, "write failed: %s", e ? strerror(e) : "I/O error");
        ok = false;
    }
    free(row);
    return tmp_finish(f, tmp, path, ok, err, errlen);
}

int img_write_ppm(const char *path, const img_t *img, char *err, size_t errlen)
{
    return write_image(path, img, false, err, errlen);
}

int img_write_pfm(const char *path, const img_t *img, char *err, size_t errlen)
{
    return write_image(path, img, true, err, errlen);
}

uint32_t img_float_to_q16(float v)
{
    if (!(v > 0.0f)) /* NaN, negative, zero */
        return 0;
    if (v >= 256.0f)
        return (1u << 24) - 1u;
    uint32_t q = (uint32_t)((double)v * 65536.0 + 0.5);
    return q > (1u << 24) - 1u ? (1u << 24) - 1u : q;
}
