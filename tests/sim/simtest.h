/* Helpers of the bloom_sim tests (tests/sim/simtest.c): running the tool,
 * files in a temp dir, the engine run directly, and writers/readers of every
 * input and output format (PNG and JPEG through libpng/libjpeg, OpenEXR
 * through OpenEXRCore, Y4M and raw by hand). None of these count checks:
 * they return -1 (or NULL) on failure and the caller CHECKs. */
#ifndef BLOOM_SIMTEST_H
#define BLOOM_SIMTEST_H

#include <stddef.h>
#include <stdint.h>

#include "bloom.h"
#include "imgio.h"

/* ---- environment ---------------------------------------------------------- */
int st_setup_dir(void);                /* creates the temp dir */
void st_remove_dir(void);              /* removes it and everything in it */
const char *st_path(const char *name); /* dir/name, from a ring of 8 buffers */
int st_count_tmp_files(void);          /* files named *.tmp-* left in the dir */

typedef struct {
    int status; /* exit code, or 128 + signal */
    char out[1 << 16], err[1 << 14];
} st_run_t;

/* Runs tool with the NULL-terminated arguments; stdin from stdin_path (or
 * /dev/null); stdout and stderr captured. */
int st_run(st_run_t *r, const char *tool, const char *stdin_path, const char *const *args);
/* Runs tool with stderr on a pseudo-terminal; what appeared there goes to
 * tty_out. Returns the exit status, or -1 when no pty is available. */
int st_run_tty(const char *tool, const char *const *args, char *tty_out, size_t cap);

/* ---- files ------------------------------------------------------------------ */
int st_write_file(const char *path, const void *data, size_t len);
unsigned char *st_read_file(const char *path, size_t *len); /* malloc'd, NUL-terminated */
int st_same_file(const char *path, const void *data, size_t len);

/* ---- the engine, run directly ------------------------------------------------ */
/* src and dst packed (stride = width * bpp). Returns 0 or -1. */
int st_engine(const bloom_config_t *c, const void *src, void *dst);

/* ---- writers ------------------------------------------------------------------ */
int st_write_png(const char *path, const void *px, int w, int h, int channels, int depth16);
int st_write_png_rgba(const char *path, const uint8_t *rgba, int w, int h);
int st_write_jpeg(const char *path, const uint8_t *px, int w, int h, int channels, int quality);
int st_write_exr(const char *path, const float *rgb, int w, int h, int half); /* -1 if not built */
int st_exr_built(void);
/* Y4M: chroma "420jpeg", "422", "mono", ...; planes holds frames*frame_bytes. */
int st_write_y4m(const char *path, const char *header_extra, int w, int h, const char *cs,
                 const uint8_t *planes, int frames);
size_t st_y4m_frame_bytes(int w, int h, const char *cs);

/* ---- readers ------------------------------------------------------------------ */
/* 8-bit RGB of a PNG (any layout, converted by libpng) or 8-bit PPM; malloc'd. */
uint8_t *st_read_rgb8(const char *path, int *w, int *h);
/* JPEG decoded by libjpeg to 8-bit, channels 1 or 3 as stored. */
uint8_t *st_decode_jpeg(const char *path, int *w, int *h, int *channels);
/* A Y4M file's header fields and frame count; planes (all frames) malloc'd. */
typedef struct {
    int w, h, frames;
    char cs[32];
    uint8_t *planes;
    size_t frame_bytes;
} st_y4m_t;
int st_read_y4m(const char *path, st_y4m_t *y);

#endif
