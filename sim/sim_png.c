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
    int io_failed;          /* err already says what happened */
    const char *op;         /* "PNG decode failed", "PNG write failed" */
    png_bytep data;
    png_bytepp rows;
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
}

static int read_body(png_ctx_t *c, png_structp png, png_infop info, img_t *img)
{
    if (setjmp(png_jmpbuf(png)))
        return -1;
    png_set_read_fn(png, c, on_read);
    png_read_info(png, info);
    png_set_expand(png);
    png_set_strip_alpha(png);
    (void)png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    const int depth = png_get_bit_depth(png, info), ch = png_get_channels(png, info);
    if (w > 65535 || h > 65535)
        return sim_errf(c->err, c->errlen, "PNG is %lux%lu: larger than 65535", (unsigned long)w,
                        (unsigned long)h);
    if ((depth != 8 && depth != 16) || (ch != 1 && ch != 3))
        return sim_errf(c->err, c->errlen, "PNG layout not supported (%d channels of %d bits)", ch,
                        depth);
    const size_t rowbytes = png_get_rowbytes(png, info);
    if (rowbytes != (size_t)w * (size_t)ch * (size_t)(depth / 8))
        return sim_errf(c->err, c->errlen, "PNG row size %zu unexpected", rowbytes);
    c->data = malloc(rowbytes * h);
    c->rows = malloc(sizeof *c->rows * h);
    if (!c->data || !c->rows || img_alloc(img, (int)w, (int)h, ch, depth == 16 ? 65535 : 255))
        return sim_errf(c->err, c->errlen, "out of memory for a %lux%lu PNG", (unsigned long)w,
                        (unsigned long)h);
    for (png_uint_32 y = 0; y < h; y++)
        c->rows[y] = c->data + (size_t)y * rowbytes;
    png_read_image(png, c->rows);
    png_read_end(png, NULL);
    const size_t n = (size_t)w * (size_t)h * (size_t)ch;
    for (size_t i = 0; i < n; i++)
        img->u16[i] = depth == 16 ? (uint16_t)(c->data[2 * i] << 8 | c->data[2 * i + 1])
                                  : c->data[i];
    return 0;
}

int sim_png_read(FILE *f, img_t *img, char *err, size_t errlen)
{
    memset(img, 0, sizeof *img);
    png_ctx_t c = {f, 0, err, errlen, 0, "PNG decode failed", NULL, NULL};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &c, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    int rc = info ? read_body(&c, png, info, img) : sim_errf(err, errlen, "out of memory");
    png_destroy_read_struct(png ? &png : NULL, info ? &info : NULL, NULL);
    free(c.data);
    free(c.rows);
    if (rc)
        img_free(img);
    return rc;
}

static int write_body(png_ctx_t *c, png_structp png, png_infop info, const uint8_t *rgb, int w,
                      int h)
{
    if (setjmp(png_jmpbuf(png)))
        return -1;
    png_init_io(png, c->f);
    png_set_compression_level(png, 3); /* sequences: speed over the last few percent */
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < h; y++)
        png_write_row(png, rgb + (size_t)y * (size_t)w * 3u);
    png_write_end(png, NULL);
    return 0;
}

int sim_png_write_rgb8(FILE *f, const uint8_t *rgb, int w, int h, char *err, size_t errlen)
{
    png_ctx_t c = {f, 0, err, errlen, 0, "PNG write failed", NULL, NULL};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &c, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    int rc = info ? write_body(&c, png, info, rgb, w, h) : sim_errf(err, errlen, "out of memory");
    png_destroy_write_struct(png ? &png : NULL, info ? &info : NULL);
    return rc;
}
