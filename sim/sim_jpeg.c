/* bloom_sim JPEG input through libjpeg (Debian libjpeg62-turbo-dev).
 *
 * Grey JPEGs come out as one channel, colour ones (YCbCr or RGB) as 8-bit
 * RGB; CMYK/YCCK JPEGs are refused. libjpeg treats damaged data as a
 * warning and fills the gap with grey: here every warning (premature end,
 * corrupt entropy data, ...) fails the read, so a broken file is never
 * simulated as if it were good. */
#include "sim.h"

#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include <jerror.h>
#include <jpeglib.h>

typedef struct {
    struct jpeg_error_mgr pub;
    jmp_buf jb;
    char *err;
    size_t errlen;
} jerr_t;

static void on_error(j_common_ptr ci)
{
    jerr_t *e = ci->client_data;
    char msg[JMSG_LENGTH_MAX];
    if (ci->err->msg_code == JWRN_JPEG_EOF) {
        sim_errf(e->err, e->errlen, "truncated: the JPEG data ends before the image is complete");
    } else {
        (*ci->err->format_message)(ci, msg);
        sim_errf(e->err, e->errlen, "JPEG decode failed: %s", msg);
    }
    longjmp(e->jb, 1);
}

static void on_message(j_common_ptr ci, int level)
{
    if (level < 0) /* a warning: the data is damaged */
        on_error(ci);
    /* level >= 0: trace messages, ignored */
}

static int read_body(struct jpeg_decompress_struct *ci, jerr_t *e, FILE *f, img_t *img, JSAMPLE **row)
{
    if (setjmp(e->jb))
        return -1;
    jpeg_create_decompress(ci);
    ci->client_data = e;
    jpeg_stdio_src(ci, f);
    (void)jpeg_read_header(ci, TRUE);
    /* Refused before jpeg_start_decompress, which sizes libjpeg's buffers
     * (for a progressive file the whole image's coefficients) by the header. */
    if (ci->image_width > BLOOM_MAX_DIM || ci->image_height > BLOOM_MAX_DIM)
        return sim_errf(e->err, e->errlen, "JPEG is %ux%u: larger than the engine's limit of %d per side",
                        (unsigned)ci->image_width, (unsigned)ci->image_height, BLOOM_MAX_DIM);
    if (ci->jpeg_color_space == JCS_CMYK || ci->jpeg_color_space == JCS_YCCK)
        return sim_errf(e->err, e->errlen, "CMYK JPEG not supported");
    if (ci->num_components != 1 && ci->num_components != 3)
        return sim_errf(e->err, e->errlen, "JPEG with %d components not supported (1 or 3 are)",
                        ci->num_components);
    ci->out_color_space = ci->num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    (void)jpeg_start_decompress(ci);
    const JDIMENSION w = ci->output_width, h = ci->output_height;
    const int ch = ci->output_components;
    if (w < 1 || h < 1 || w > BLOOM_MAX_DIM || h > BLOOM_MAX_DIM || (ch != 1 && ch != 3))
        return sim_errf(e->err, e->errlen, "JPEG layout not supported (%ux%u, %d components)", (unsigned)w,
                        (unsigned)h, ch);
    img->width = (int)w;
    img->height = (int)h;
    img->channels = ch;
    img->maxval = 255;
    if (!(*row = malloc((size_t)w * (size_t)ch)))
        return sim_errf(e->err, e->errlen, "out of memory for a %ux%u JPEG", (unsigned)w, (unsigned)h);
    /* the samples grow with the rows decoded: a short file that claims a
     * large image fails at its end having allocated what it delivered */
    int cap = 0;
    while (ci->output_scanline < h) {
        JSAMPROW r = *row;
        const size_t y = ci->output_scanline;
        if (sim_img_rows(img, (int)y + 1, &cap))
            return sim_errf(e->err, e->errlen, "out of memory for a %ux%u JPEG", (unsigned)w, (unsigned)h);
        if (jpeg_read_scanlines(ci, &r, 1) != 1)
            return sim_errf(e->err, e->errlen, "JPEG decode failed at row %zu", y);
        for (size_t i = 0; i < (size_t)w * (size_t)ch; i++)
            img->u16[y * (size_t)w * (size_t)ch + i] = r[i];
    }
    (void)jpeg_finish_decompress(ci);
    return 0;
}

int sim_jpeg_read(FILE *f, img_t *img, char *err, size_t errlen)
{
    memset(img, 0, sizeof *img);
    struct jpeg_decompress_struct ci;
    jerr_t e;
    memset(&ci, 0, sizeof ci);
    memset(&e, 0, sizeof e);
    e.err = err;
    e.errlen = errlen;
    ci.err = jpeg_std_error(&e.pub);
    ci.client_data = &e;
    e.pub.error_exit = on_error;
    e.pub.emit_message = on_message;
    JSAMPLE *row = NULL;
    int rc = read_body(&ci, &e, f, img, &row);
    jpeg_destroy_decompress(&ci);
    free(row);
    if (rc)
        img_free(img);
    return rc;
}
