/* Test helper on the host (make test-linux): the JPEG frames loopfeed sends.
 * "mkjpeg W H GOOD CORRUPT TRUNCATED": a W x H picture with bright lights
 * (libjpeg, quality 90), the same with a marker written into its entropy
 * data, and its first half. Each is decoded here again: the good one must
 * decode without a warning, the other two must not (libjpeg warns about a
 * premature end or a marker in the data), or the cases would test nothing. */
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

typedef struct {
    struct jpeg_error_mgr e;
    jmp_buf jb;
    int warnings;
} err_t;

static void on_error(j_common_ptr ci)
{
    longjmp(((err_t *)ci->err)->jb, 1);
}

static void on_message(j_common_ptr ci, int level)
{
    if (level < 0)
        ((err_t *)ci->err)->warnings++;
}

/* 0: decoded cleanly; 1: a warning or an error */
static int damaged(const unsigned char *j, size_t n)
{
    struct jpeg_decompress_struct ci;
    err_t err;
    ci.err = jpeg_std_error(&err.e);
    err.e.error_exit = on_error;
    err.e.emit_message = on_message;
    err.warnings = 0;
    if (setjmp(err.jb)) {
        jpeg_destroy_decompress(&ci);
        return 1;
    }
    jpeg_create_decompress(&ci);
    jpeg_mem_src(&ci, j, (unsigned long)n);
    jpeg_read_header(&ci, TRUE);
    jpeg_start_decompress(&ci);
    unsigned char *row = malloc((size_t)ci.output_width * (size_t)ci.output_components);
    while (ci.output_scanline < ci.output_height)
        jpeg_read_scanlines(&ci, &row, 1);
    jpeg_finish_decompress(&ci);
    jpeg_destroy_decompress(&ci);
    free(row);
    return err.warnings > 0;
}

static int put(const char *path, const unsigned char *b, size_t n)
{
    FILE *f = fopen(path, "wb");
    int ok = f && fwrite(b, 1, n, f) == n;
    if (f && fclose(f))
        ok = 0;
    if (!ok)
        fprintf(stderr, "mkjpeg: cannot write %s\n", path);
    return ok;
}

int main(int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: mkjpeg W H GOOD CORRUPT TRUNCATED\n");
        return 2;
    }
    const int w = atoi(argv[1]), h = atoi(argv[2]);
    if (w < 16 || h < 16 || w > 4096 || h > 4096)
        return 2;
    unsigned char *rgb = malloc((size_t)w * (size_t)h * 3);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) { /* a dim gradient and three lights */
            unsigned char *p = rgb + ((size_t)y * (size_t)w + (size_t)x) * 3;
            int v[3] = {20 + 60 * x / w, 30 + 50 * y / h, 40};
            const int lx[3] = {w / 4, w / 2, 3 * w / 4}, ly[3] = {h / 3, 2 * h / 3, h / 2}, r = h / 12;
            for (int i = 0; i < 3; i++)
                if ((x - lx[i]) * (x - lx[i]) + (y - ly[i]) * (y - ly[i]) < r * r)
                    v[0] = v[1] = v[2] = 255 - 20 * i, v[i] = 255;
            p[0] = (unsigned char)v[0];
            p[1] = (unsigned char)v[1];
            p[2] = (unsigned char)v[2];
        }
    struct jpeg_compress_struct cc;
    struct jpeg_error_mgr je;
    cc.err = jpeg_std_error(&je);
    jpeg_create_compress(&cc);
    unsigned char *good = NULL;
    unsigned long n = 0;
    jpeg_mem_dest(&cc, &good, &n);
    cc.image_width = (JDIMENSION)w;
    cc.image_height = (JDIMENSION)h;
    cc.input_components = 3;
    cc.in_color_space = JCS_RGB;
    jpeg_set_defaults(&cc);
    jpeg_set_quality(&cc, 90, TRUE);
    jpeg_start_compress(&cc, TRUE);
    for (int y = 0; y < h; y++) {
        JSAMPROW row = rgb + (size_t)y * (size_t)w * 3;
        jpeg_write_scanlines(&cc, &row, 1);
    }
    jpeg_finish_compress(&cc);
    jpeg_destroy_compress(&cc);
    unsigned char *bad = malloc(n);
    memcpy(bad, good, n);
    bad[n * 11 / 20] = 0xFF; /* RST3 where no restart interval is set */
    bad[n * 11 / 20 + 1] = 0xD3;
    if (damaged(good, n) || !damaged(bad, n) || !damaged(good, n / 2)) {
        fprintf(stderr, "mkjpeg: the good frame warns, or a damaged one does not\n");
        return 1;
    }
    if (!put(argv[3], good, n) || !put(argv[4], bad, n) || !put(argv[5], good, n / 2))
        return 1;
    printf("mkjpeg: %dx%d, %lu bytes; corrupt and truncated (%lu bytes) frames made\n", w, h, n, n / 2);
    free(good);
    free(bad);
    free(rgb);
    return 0;
}
