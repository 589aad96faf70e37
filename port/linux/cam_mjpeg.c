/* bloom_cam: MJPEG capture decoded by libjpeg(-turbo) (Debian
 * libjpeg62-turbo-dev), one scanline at a time into the caller's RGB888
 * row, so the engine gets each row as it is decoded (no decoded frame is
 * kept); and the per-frame row reader every capture format goes through
 * (cam_cap_begin / cam_cap_next / cam_cap_end).
 *
 * A camera's JPEG can be damaged (a USB packet lost, a frame cut short):
 * libjpeg calls a few of those errors (the exit is a longjmp back here) and
 * only warns about the rest, padding the gap with grey (a premature end,
 * corrupt entropy data, bytes before a marker). Every warning is taken as
 * an error here, and the stream is read up to its EOI after the last row,
 * so a truncated or damaged frame is reported bad (requeued and counted by
 * the caller) instead of being shown half grey. JPEG carries no checksum:
 * a flipped bit that still decodes to whole blocks cannot be seen. */
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jerror.h>
#include <jpeglib.h>
#include <linux/videodev2.h>

#include "cam.h"

struct cam_mjpeg {
    struct jpeg_decompress_struct ci; /* kept from frame to frame: set up once */
    struct jpeg_error_mgr err;
    jmp_buf jb;
    int w, h;
    int active; /* between a good cam_mjpeg_begin and cam_mjpeg_end (or a failure) */
    char why[JMSG_LENGTH_MAX + 64];
};

static void on_error(j_common_ptr ci)
{
    cam_mjpeg_t *j = ci->client_data;
    char msg[JMSG_LENGTH_MAX];
    (*ci->err->format_message)(ci, msg);
    snprintf(j->why, sizeof j->why, "%s", ci->err->msg_code == JWRN_JPEG_EOF ? "truncated (no EOI)" : msg);
    longjmp(j->jb, 1);
}

static void on_message(j_common_ptr ci, int level)
{
    if (level < 0) /* a warning: the data is damaged, and libjpeg would go on with grey */
        on_error(ci);
}

int cam_mjpeg_open(cam_mjpeg_t **out, int w, int h)
{
    cam_mjpeg_t *j = calloc(1, sizeof *j);
    *out = j;
    if (!j)
        return -1;
    j->w = w;
    j->h = h;
    j->ci.err = jpeg_std_error(&j->err);
    j->err.error_exit = on_error;
    j->err.emit_message = on_message;
    j->ci.client_data = j;
    if (setjmp(j->jb)) { /* out of memory in libjpeg's own set-up */
        jpeg_destroy_decompress(&j->ci);
        free(j);
        *out = NULL;
        return -1;
    }
    jpeg_create_decompress(&j->ci);
    return 0;
}

void cam_mjpeg_close(cam_mjpeg_t *j)
{
    if (!j)
        return;
    jpeg_destroy_decompress(&j->ci);
    free(j);
}

const char *cam_mjpeg_why(const cam_mjpeg_t *j)
{
    return j->why;
}

/* A failure: libjpeg's state for this image dropped (its image pool freed),
 * ready for the next frame. */
static int failed(cam_mjpeg_t *j)
{
    jpeg_abort_decompress(&j->ci);
    j->active = 0;
    return -1;
}

int cam_mjpeg_begin(cam_mjpeg_t *j, const uint8_t *data, size_t len)
{
    if (j->active) /* the last frame was left unfinished (the engine failed) */
        jpeg_abort_decompress(&j->ci);
    j->active = 0;
    j->why[0] = '\0';
    if (setjmp(j->jb))
        return failed(j);
    if (len < 4 || data[0] != 0xFF || data[1] != 0xD8) { /* nothing, or not a JPEG (no SOI) */
        snprintf(j->why, sizeof j->why, "not a JPEG (%zu bytes, no SOI marker)", len);
        return failed(j);
    }
    /* jpeg_mem_src sets its source manager up once (the first call) and
     * points it at the new bytes after: no allocation per frame. At the
     * end of the bytes it warns (JWRN_JPEG_EOF), which is an error here. */
    jpeg_mem_src(&j->ci, data, (unsigned long)len);
    (void)jpeg_read_header(&j->ci, TRUE);
    if (j->ci.image_width != (JDIMENSION)j->w || j->ci.image_height != (JDIMENSION)j->h) {
        snprintf(j->why, sizeof j->why, "a %ux%u JPEG in a %dx%d capture", (unsigned)j->ci.image_width,
                 (unsigned)j->ci.image_height, j->w, j->h);
        return failed(j);
    }
    /* RGB out of Y'CbCr (JFIF's full-range BT.601, libjpeg's integers) or of
     * a grey JPEG; libjpeg's defaults otherwise (the islow IDCT, fancy
     * upsampling), as bloom_sim reads a JPEG file. A frame without Huffman
     * tables (UVC cameras leave out the DHT segment) gets the standard ones
     * from libjpeg-turbo itself (jinit_huff_decoder's std_huff_tables). */
    j->ci.out_color_space = JCS_RGB;
    (void)jpeg_start_decompress(&j->ci);
    if (j->ci.output_components != 3) {
        snprintf(j->why, sizeof j->why, "a JPEG of %d components", j->ci.output_components);
        return failed(j);
    }
    j->active = 1;
    return 0;
}

int cam_mjpeg_row(cam_mjpeg_t *j, uint8_t *dst)
{
    if (!j->active)
        return -1;
    if (setjmp(j->jb))
        return failed(j);
    JSAMPROW r = dst;
    if (jpeg_read_scanlines(&j->ci, &r, 1) != 1) { /* (the memory source never suspends) */
        snprintf(j->why, sizeof j->why, "no row %u", (unsigned)j->ci.output_scanline);
        return failed(j);
    }
    return 0;
}

int cam_mjpeg_end(cam_mjpeg_t *j)
{
    if (!j->active)
        return -1;
    if (setjmp(j->jb))
        return failed(j);
    /* reads on to the EOI: a frame cut after its last row, or with bytes
     * left over in the entropy data, fails here */
    (void)jpeg_finish_decompress(&j->ci);
    j->active = 0;
    return 0;
}

/* ---- the row reader of every format ------------------------------------- */

int cam_cap_begin(const cam_v4l2_t *c, const cam_frame_t *f)
{
    return c->jpeg ? cam_mjpeg_begin(c->jpeg, f->data, f->len) : 0;
}

const uint8_t *cam_cap_next(const cam_v4l2_t *c, const cam_frame_t *f, int y, uint8_t *line)
{
    if (c->jpeg)
        return cam_mjpeg_row(c->jpeg, line) ? NULL : line;
    if (c->pixelformat == V4L2_PIX_FMT_RGB24) /* read in place */
        return f->data + (size_t)y * c->bytesperline;
    cam_cap_row(c, f->data, f->data2, y, line);
    return line;
}

int cam_cap_end(const cam_v4l2_t *c)
{
    return c->jpeg ? cam_mjpeg_end(c->jpeg) : 0;
}
