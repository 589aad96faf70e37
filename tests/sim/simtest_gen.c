/* bloom_sim tests: writers of the input formats and readers of the outputs,
 * through the libraries (libpng, libjpeg, OpenEXRCore) or by hand (Y4M). */
#include "simtest.h"

#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

/* ---- PNG ------------------------------------------------------------------ */

int st_write_png(const char *path, const void *px, int w, int h, int channels, int depth16)
{
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    im.width = (png_uint_32)w;
    im.height = (png_uint_32)h;
    im.format = channels == 1 ? (depth16 ? PNG_FORMAT_LINEAR_Y : PNG_FORMAT_GRAY)
                              : (depth16 ? PNG_FORMAT_LINEAR_RGB : PNG_FORMAT_RGB);
    int ok = png_image_write_to_file(&im, path, 0, px, 0, NULL);
    png_image_free(&im);
    return ok ? 0 : -1;
}

int st_write_png_rgba(const char *path, const uint8_t *rgba, int w, int h)
{
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    im.width = (png_uint_32)w;
    im.height = (png_uint_32)h;
    im.format = PNG_FORMAT_RGBA;
    int ok = png_image_write_to_file(&im, path, 0, rgba, 0, NULL);
    png_image_free(&im);
    return ok ? 0 : -1;
}

uint8_t *st_read_rgb8(const char *path, int *w, int *h)
{
    FILE *f = fopen(path, "rb");
    unsigned char sig[8] = {0};
    size_t n = f ? fread(sig, 1, 8, f) : 0;
    if (f)
        fclose(f);
    if (n == 8 && !png_sig_cmp(sig, 0, 8)) {
        png_image im;
        memset(&im, 0, sizeof im);
        im.version = PNG_IMAGE_VERSION;
        if (!png_image_begin_read_from_file(&im, path))
            return NULL;
        im.format = PNG_FORMAT_RGB;
        uint8_t *px = malloc(PNG_IMAGE_SIZE(im));
        if (!px || !png_image_finish_read(&im, NULL, px, 0, NULL)) {
            free(px);
            png_image_free(&im);
            return NULL;
        }
        *w = (int)im.width;
        *h = (int)im.height;
        return px;
    }
    img_t im;
    char err[256];
    if (img_read(path, &im, err, sizeof err) || !im.u16 || im.channels != 3 || im.maxval != 255) {
        img_free(&im);
        return NULL;
    }
    size_t cnt = (size_t)im.width * (size_t)im.height * 3u;
    uint8_t *px = malloc(cnt);
    for (size_t i = 0; px && i < cnt; i++)
        px[i] = (uint8_t)im.u16[i];
    *w = im.width;
    *h = im.height;
    img_free(&im);
    return px;
}

/* ---- JPEG ------------------------------------------------------------------ */

int st_write_jpeg(const char *path, const uint8_t *px, int w, int h, int channels, int quality)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    struct jpeg_compress_struct c;
    struct jpeg_error_mgr e;
    c.err = jpeg_std_error(&e); /* errors exit the test: fine for writing our own files */
    jpeg_create_compress(&c);
    jpeg_stdio_dest(&c, f);
    c.image_width = (JDIMENSION)w;
    c.image_height = (JDIMENSION)h;
    c.input_components = channels;
    c.in_color_space = channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, quality, TRUE);
    jpeg_start_compress(&c, TRUE);
    while (c.next_scanline < c.image_height) {
        JSAMPROW row = (JSAMPROW)(uintptr_t)(px + (size_t)c.next_scanline * (size_t)w * (size_t)channels);
        jpeg_write_scanlines(&c, &row, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    return fclose(f) == 0 ? 0 : -1;
}

uint8_t *st_decode_jpeg(const char *path, int *w, int *h, int *channels)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    struct jpeg_decompress_struct c;
    struct jpeg_error_mgr e;
    c.err = jpeg_std_error(&e);
    jpeg_create_decompress(&c);
    jpeg_stdio_src(&c, f);
    jpeg_read_header(&c, TRUE);
    c.out_color_space = c.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_start_decompress(&c);
    *w = (int)c.output_width;
    *h = (int)c.output_height;
    *channels = c.output_components;
    size_t rb = (size_t)*w * (size_t)*channels;
    uint8_t *px = malloc(rb * (size_t)*h);
    while (px && c.output_scanline < c.output_height) {
        JSAMPROW row = px + (size_t)c.output_scanline * rb;
        jpeg_read_scanlines(&c, &row, 1);
    }
    jpeg_finish_decompress(&c);
    jpeg_destroy_decompress(&c);
    fclose(f);
    return px;
}

/* ---- OpenEXR ------------------------------------------------------------------ */
#ifdef SIM_NO_EXR
int st_exr_built(void)
{
    return 0;
}
int st_write_exr(const char *path, const float *rgb, int w, int h, int half)
{
    (void)path, (void)rgb, (void)w, (void)h, (void)half;
    return -1;
}
#else
#include <openexr.h>

int st_exr_built(void)
{
    return 1;
}

int st_write_exr(const char *path, const float *rgb, int w, int h, int half)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    exr_encode_pipeline_t enc;
    memset(&enc, 0, sizeof enc);
    int part, lines, started = 0, rc = -1;
    if (exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init) ||
        exr_add_part(ctx, "main", EXR_STORAGE_SCANLINE, &part) ||
        exr_initialize_required_attr_simple(ctx, part, w, h, EXR_COMPRESSION_ZIP))
        goto out;
    const char *names[3] = {"B", "G", "R"}; /* any order: the file sorts them */
    for (int c = 0; c < 3; c++)
        if (exr_add_channel(ctx, part, names[c], half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT,
                            EXR_PERCEPTUALLY_LINEAR, 1, 1))
            goto out;
    if (exr_write_header(ctx) || exr_get_scanlines_per_chunk(ctx, part, &lines))
        goto out;
    for (int y = 0; y < h; y += lines) {
        exr_chunk_info_t ci;
        if (exr_write_scanline_chunk_info(ctx, part, y, &ci) ||
            (started ? exr_encoding_update(ctx, part, &ci, &enc)
                     : exr_encoding_initialize(ctx, part, &ci, &enc)))
            goto out;
        for (int c = 0; c < enc.channel_count; c++) {
            exr_coding_channel_info_t *ch = &enc.channels[c];
            int slot = !strcmp(ch->channel_name, "R") ? 0 : !strcmp(ch->channel_name, "G") ? 1 : 2;
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = 12;
            ch->user_line_stride = 12 * w;
            ch->encode_from_ptr = (const uint8_t *)(rgb + (size_t)y * (size_t)w * 3u + (size_t)slot);
        }
        if ((!started && exr_encoding_choose_default_routines(ctx, part, &enc)) ||
            exr_encoding_run(ctx, part, &enc))
            goto out;
        started = 1;
    }
    rc = 0;
out:
    if (started)
        exr_encoding_destroy(ctx, &enc);
    if (ctx && exr_finish(&ctx))
        rc = -1;
    return rc;
}
#endif

/* ---- Y4M ---------------------------------------------------------------------- */

size_t st_y4m_frame_bytes(int w, int h, const char *cs)
{
    size_t luma = (size_t)w * (size_t)h, cw = (size_t)(w + 1) / 2, chh = (size_t)(h + 1) / 2;
    if (cs && !strcmp(cs, "mono"))
        return luma;
    if (cs && !strcmp(cs, "444"))
        return 3 * luma;
    if (cs && !strcmp(cs, "422"))
        return luma + 2 * cw * (size_t)h;
    return luma + 2 * cw * chh;
}

int st_write_y4m(const char *path, const char *header_extra, int w, int h, const char *cs,
                 const uint8_t *planes, int frames)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    fprintf(f, "YUV4MPEG2 W%d H%d F30000:1001 Ip A1:1", w, h);
    if (cs)
        fprintf(f, " C%s", cs);
    fprintf(f, "%s\n", header_extra ? header_extra : "");
    size_t fb = st_y4m_frame_bytes(w, h, cs);
    for (int i = 0; i < frames; i++) {
        fputs("FRAME\n", f);
        fwrite(planes + (size_t)i * fb, 1, fb, f);
    }
    return fclose(f) == 0 ? 0 : -1;
}

int st_read_y4m(const char *path, st_y4m_t *y)
{
    memset(y, 0, sizeof y[0]);
    size_t len;
    unsigned char *b = st_read_file(path, &len);
    if (!b)
        return -1;
    unsigned char *nl = memchr(b, '\n', len);
    if (!nl || memcmp(b, "YUV4MPEG2 ", 10)) {
        free(b);
        return -1;
    }
    *nl = '\0';
    for (char *t = strtok((char *)b + 10, " "); t; t = strtok(NULL, " ")) {
        if (t[0] == 'W')
            y->w = atoi(t + 1);
        else if (t[0] == 'H')
            y->h = atoi(t + 1);
        else if (t[0] == 'C')
            snprintf(y->cs, sizeof y->cs, "%s", t + 1);
    }
    const char *cs = !strncmp(y->cs, "420", 3) || !y->cs[0] ? "420" : y->cs;
    y->frame_bytes = st_y4m_frame_bytes(y->w, y->h, cs);
    size_t pos = (size_t)(nl - b) + 1;
    y->planes = malloc(len);
    while (y->planes && pos + 6 + y->frame_bytes <= len && !memcmp(b + pos, "FRAME\n", 6)) {
        memcpy(y->planes + (size_t)y->frames * y->frame_bytes, b + pos + 6, y->frame_bytes);
        pos += 6 + y->frame_bytes;
        y->frames++;
    }
    int rc = pos == len && y->planes ? 0 : -1; /* nothing left over */
    free(b);
    return rc;
}
