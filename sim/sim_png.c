/* bloom_sim PNG input and output through libpng (Debian libpng-dev).
 *
 * Reading: palette and grey below 8 bits are expanded to 8 bits, alpha
 * (and tRNS) is dropped, interlacing is undone; 16-bit samples stay 16-bit
 * (the caller applies the 16-bit rule). Colour chunks (gAMA, cHRM, iCCP,
 * sRGB) are ignored: 8-bit samples are taken as sRGB codes. Warnings are
 * ignored; errors (bad CRC in a critical chunk, bad zlib data, truncation)
 * fail the read. */
#include "sim.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    FILE *f;
    unsigned long long pos; /* bytes read so far */
    char *err;
    size_t errlen;
    int io_failed;  /* err already says what happened */
    const char *op; /* "PNG decode failed", "PNG write failed" */
    png_bytep data;
    png_bytepp rows;
    long long left; /* bytes of the file after what was read so far, -1 unknown */
} png_ctx_t;

static void on_error(png_structp png, png_const_charp msg)
{
    png_ctx_t *c = png_get_error_ptr(png);
    if (!c->io_failed)
        sim_errf(c->err, c->errlen, "%s: %s", c->op, msg);
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg)
{
    (void)png; /* benign (an odd iCCP profile, a bad ancillary chunk): ignored */
    (void)msg;
}

static void on_read(png_structp png, png_bytep data, size_t len)
{
    png_ctx_t *c = png_get_io_ptr(png);
    size_t got = fread(data, 1, len, c->f);
    if (got != len) {
        c->io_failed = 1;
        if (ferror(c->f))
            sim_errf(c->err, c->errlen, "read error: %s", strerror(errno));
        else
            sim_errf(c->err, c->errlen, "truncated: the PNG data stops after %llu bytes",
                     c->pos + (unsigned long long)got);
        png_error(png, "read failed");
    }
    c->pos += len;
    if (c->left >= 0)
        c->left -= (long long)len;
}

/* Deflate expands at most 1032:1 (a 258-byte match in two 1-bit codes). */
#define PNG_MAX_INFLATE 1032u

static int read_body(png_ctx_t *c, png_structp png, png_infop info, img_t *img)
{
    if (setjmp(png_jmpbuf(png)))
        return -1;
    png_set_read_fn(png, c, on_read);
    /* libpng's own limit (a million) would speak first, without the engine's */
    png_set_user_limits(png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    png_read_info(png, info);
    const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    if (w > BLOOM_MAX_DIM || h > BLOOM_MAX_DIM)
        return sim_errf(c->err, c->errlen, "PNG is %lux%lu: larger than the engine's limit of %d per side",
                        (unsigned long)w, (unsigned long)h, BLOOM_MAX_DIM);
    /* Before anything the size of the image is allocated: the compressed
     * data left in the file must be able to inflate to the stored samples
     * (filter bytes not counted: a bound for interlaced files too). */
    const unsigned long long stored =
        (unsigned long long)h *
        (((unsigned long long)w * png_get_bit_depth(png, info) * png_get_channels(png, info) + 7) / 8);
    if (c->left >= 0 && stored > (unsigned long long)c->left * PNG_MAX_INFLATE + PNG_MAX_INFLATE)
        return sim_errf(c->err, c->errlen,
                        "truncated: a %lux%lu PNG needs %llu bytes of image data, more than the "
                        "%lld bytes left in the file can hold",
                        (unsigned long)w, (unsigned long)h, stored, c->left);
    png_set_expand(png);
    png_set_strip_alpha(png);
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const int depth = png_get_bit_depth(png, info), ch = png_get_channels(png, info);
    if ((depth != 8 && depth != 16) || (ch != 1 && ch != 3))
        return sim_errf(c->err, c->errlen, "PNG layout not supported (%d channels of %d bits)", ch, depth);
    const size_t rowbytes = png_get_rowbytes(png, info);
    if (rowbytes != (size_t)w * (size_t)ch * (size_t)(depth / 8))
        return sim_errf(c->err, c->errlen, "PNG row size %zu unexpected", rowbytes);
    img->width = (int)w;
    img->height = (int)h;
    img->channels = ch;
    img->maxval = depth == 16 ? 65535 : 255;
    /* Interlaced rows are revisited by every pass: the whole image at once.
     * Otherwise one row at a time, the samples growing with the rows read. */
    const png_uint_32 nbuf = passes > 1 ? h : 1;
    int cap = 0;
    c->data = malloc(rowbytes * nbuf);
    c->rows = malloc(sizeof *c->rows * nbuf);
    if (!c->data || !c->rows || (passes > 1 && sim_img_rows(img, (int)h, &cap)))
        return sim_errf(c->err, c->errlen, "out of memory for a %lux%lu PNG", (unsigned long)w,
                        (unsigned long)h);
    for (png_uint_32 y = 0; y < nbuf; y++)
        c->rows[y] = c->data + (size_t)y * rowbytes;
    if (passes > 1)
        png_read_image(png, c->rows);
    const size_t n = (size_t)w * (size_t)ch;
    for (png_uint_32 y = 0; y < h; y++) {
        const png_bytep r = c->rows[passes > 1 ? y : 0];
        if (passes == 1) {
            if (sim_img_rows(img, (int)y + 1, &cap))
                return sim_errf(c->err, c->errlen, "out of memory for a %lux%lu PNG", (unsigned long)w,
                                (unsigned long)h);
            png_read_row(png, r, NULL);
        }
        uint16_t *o = img->u16 + (size_t)y * n;
        for (size_t i = 0; i < n; i++)
            o[i] = depth == 16 ? (uint16_t)(r[2 * i] << 8 | r[2 * i + 1]) : r[i];
    }
    png_read_end(png, NULL);
    return 0;
}

int sim_png_read(FILE *f, img_t *img, char *err, size_t errlen)
{
    memset(img, 0, sizeof *img);
    /* a pipe is spooled to a temporary file first, so that its size is known */
    long long left = sim_stream_left(f);
    FILE *spool = left < 0 ? sim_spool(f, err, errlen) : NULL;
    if (left < 0 && !spool)
        return -1;
    if (spool)
        left = sim_stream_left(spool);
    png_ctx_t c = {spool ? spool : f, 0, err, errlen, 0, "PNG decode failed", NULL, NULL, left};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &c, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    int rc = info ? read_body(&c, png, info, img) : sim_errf(err, errlen, "out of memory");
    png_destroy_read_struct(png ? &png : NULL, info ? &info : NULL, NULL);
    free(c.data);
    free(c.rows);
    if (spool)
        fclose(spool);
    if (rc)
        img_free(img);
    return rc;
}

static int write_body(png_ctx_t *c, png_structp png, png_infop info, const uint8_t *rgb, int w, int h)
{
    if (setjmp(png_jmpbuf(png)))
        return -1;
    png_init_io(png, c->f);
    png_set_compression_level(png, 3); /* sequences: speed over the last few percent */
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < h; y++)
        png_write_row(png, rgb + (size_t)y * (size_t)w * 3u);
    png_write_end(png, NULL);
    return 0;
}

int sim_png_write_rgb8(FILE *f, const uint8_t *rgb, int w, int h, char *err, size_t errlen)
{
    png_ctx_t c = {f, 0, err, errlen, 0, "PNG write failed", NULL, NULL, -1};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &c, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    int rc = info ? write_body(&c, png, info, rgb, w, h) : sim_errf(err, errlen, "out of memory");
    png_destroy_write_struct(png ? &png : NULL, info ? &info : NULL);
    return rc;
}
