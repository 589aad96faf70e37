/* Seed writers of tests/fuzz/gen_seeds.c for the compressed formats: PNG
 * (libpng), JPEG (libjpeg), OpenEXR (OpenEXRCore), each into memory or a
 * file, in the layouts the readers handle differently. */
#include "gen_seeds.h"

#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

/* ---- PNG ------------------------------------------------------------------ */

int gs_png(const char *path, const uint8_t *rgb, int w, int h, int color, int depth, int interlace)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    uint8_t *row = malloc((size_t)w * 8);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        free(row);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, depth, color,
                 interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (color == PNG_COLOR_TYPE_PALETTE) {
        png_color pal[16];
        png_byte trns[16];
        for (int i = 0; i < 16; i++) {
            pal[i].red = (png_byte)(i * 17);
            pal[i].green = (png_byte)(255 - i * 17);
            pal[i].blue = (png_byte)(i * 5);
            trns[i] = (png_byte)(i * 16);
        }
        png_set_PLTE(png, info, pal, 16);
        png_set_tRNS(png, info, trns, 16, NULL);
    }
    png_set_gAMA(png, info, 0.45455);
    png_write_info(png, info);
    if (depth < 8)
        png_set_packing(png);
    const int passes = interlace ? png_set_interlace_handling(png) : 1;
    const int ch = color == PNG_COLOR_TYPE_RGB          ? 3
                   : color == PNG_COLOR_TYPE_RGBA       ? 4
                   : color == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                                        : 1;
    const unsigned top = depth == 16 ? 65535u : (1u << depth) - 1u;
    for (int p = 0; p < passes; p++)
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++)
                for (int c = 0; c < ch; c++) {
                    const unsigned v8 = rgb[3 * ((size_t)y * (size_t)w + (size_t)x) + (size_t)(c % 3)];
                    const unsigned v = c == 3 || (c == 1 && ch == 2) ? top : v8 * top / 255u;
                    if (depth == 16) {
                        row[2 * (x * ch + c)] = (uint8_t)(v >> 8);
                        row[2 * (x * ch + c) + 1] = (uint8_t)v;
                    } else {
                        row[x * ch + c] = (uint8_t)v;
                    }
                }
            png_write_row(png, row);
        }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    return fclose(f);
}

/* ---- JPEG ----------------------------------------------------------------- */

int gs_jpeg(const char *path, const uint8_t *rgb, int w, int h, int grey, int progressive, int arith,
            int subsample, int restart)
{
    struct jpeg_compress_struct ci;
    struct jpeg_error_mgr jerr;
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    ci.err = jpeg_std_error(&jerr);
    jpeg_create_compress(&ci);
    jpeg_stdio_dest(&ci, f);
    ci.image_width = (JDIMENSION)w;
    ci.image_height = (JDIMENSION)h;
    ci.input_components = grey ? 1 : 3;
    ci.in_color_space = grey ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&ci);
    jpeg_set_quality(&ci, 85, TRUE);
    if (progressive)
        jpeg_simple_progression(&ci);
    ci.arith_code = arith ? TRUE : FALSE;
    ci.restart_interval = (unsigned)restart;
    if (!grey && !subsample)
        for (int c = 0; c < 3; c++)
            ci.comp_info[c].h_samp_factor = ci.comp_info[c].v_samp_factor = 1;
    jpeg_start_compress(&ci, TRUE);
    uint8_t *row = malloc((size_t)w * 3);
    while (ci.next_scanline < ci.image_height) {
        const uint8_t *src = rgb + (size_t)ci.next_scanline * (size_t)w * 3;
        for (int x = 0; x < w; x++)
            if (grey)
                row[x] = src[3 * x + 1];
            else
                memcpy(row + 3 * x, src + 3 * x, 3);
        JSAMPROW r = row;
        jpeg_write_scanlines(&ci, &r, 1);
    }
    jpeg_finish_compress(&ci);
    jpeg_destroy_compress(&ci);
    free(row);
    return fclose(f);
}

/* ---- OpenEXR ---------------------------------------------------------------- */

#ifdef SIM_NO_EXR
int gs_exr(const char *path, const float *rgb, int w, int h, int nch, int half, int comp, int tile)
{
    (void)path, (void)rgb, (void)w, (void)h, (void)nch, (void)half, (void)comp, (void)tile;
    return -1;
}
#else
#include <openexr.h>

/* Points the encoder's channels at the pixels of the chunk at (px, py). */
static void exr_point(exr_encode_pipeline_t *enc, const float *rgb, int w, int px, int py)
{
    for (int c = 0; c < enc->channel_count; c++) {
        exr_coding_channel_info_t *ch = &enc->channels[c];
        const char *n = ch->channel_name;
        const int slot = !strcmp(n, "R") || !strcmp(n, "Y") ? 0 : !strcmp(n, "G") ? 1 : 2;
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
        ch->user_pixel_stride = 12;
        ch->user_line_stride = 12 * w;
        ch->encode_from_ptr =
            (const uint8_t *)(rgb + ((size_t)py * (size_t)w + (size_t)px) * 3u + (size_t)slot);
    }
}

/* nch: 1 (Y), 3 (R, G, B) or 4 (with A); tile 0 for scanlines, else its side. */
int gs_exr(const char *path, const float *rgb, int w, int h, int nch, int half, int comp, int tile)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    exr_encode_pipeline_t enc;
    memset(&enc, 0, sizeof enc);
    int part, lines, started = 0, rc = -1;
    if (exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init) ||
        exr_add_part(ctx, "main", tile ? EXR_STORAGE_TILED : EXR_STORAGE_SCANLINE, &part) ||
        exr_initialize_required_attr_simple(ctx, part, w, h, (exr_compression_t)comp))
        goto out;
    if (tile && exr_set_tile_descriptor(ctx, part, (uint32_t)tile, (uint32_t)tile, EXR_TILE_ONE_LEVEL,
                                        EXR_TILE_ROUND_DOWN))
        goto out;
    static const char *const names[4] = {"A", "B", "G", "R"};
    for (int c = 0; c < (nch == 1 ? 1 : nch); c++)
        if (exr_add_channel(ctx, part, nch == 1 ? "Y" : names[4 - nch + c],
                            half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR, 1, 1))
            goto out;
    if (exr_write_header(ctx))
        goto out;
    exr_chunk_info_t ci;
    if (!tile) {
        if (exr_get_scanlines_per_chunk(ctx, part, &lines))
            goto out;
        for (int y = 0; y < h; y += lines) {
            if (exr_write_scanline_chunk_info(ctx, part, y, &ci) ||
                (started ? exr_encoding_update(ctx, part, &ci, &enc)
                         : exr_encoding_initialize(ctx, part, &ci, &enc)))
                goto out;
            exr_point(&enc, rgb, w, 0, y);
            if ((!started && exr_encoding_choose_default_routines(ctx, part, &enc)) ||
                exr_encoding_run(ctx, part, &enc))
                goto out;
            started = 1;
        }
    } else {
        for (int ty = 0; ty * tile < h; ty++)
            for (int tx = 0; tx * tile < w; tx++) {
                if (exr_write_tile_chunk_info(ctx, part, tx, ty, 0, 0, &ci) ||
                    (started ? exr_encoding_update(ctx, part, &ci, &enc)
                             : exr_encoding_initialize(ctx, part, &ci, &enc)))
                    goto out;
                exr_point(&enc, rgb, w, tx * tile, ty * tile);
                if ((!started && exr_encoding_choose_default_routines(ctx, part, &enc)) ||
                    exr_encoding_run(ctx, part, &enc))
                    goto out;
                started = 1;
            }
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
