/* Image file I/O for the host tools: binary PGM/PPM (P5/P6, 8- and 16-bit)
 * and PFM (PF/Pf, either byte order on read, little-endian on write).
 * Host-only code: allocates on the heap, uses POSIX mkstemp/rename. */
#ifndef BLOOM_IMGIO_H
#define BLOOM_IMGIO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef struct {
    int width, height, channels; /* channels 1 or 3 */
    int maxval;                  /* PPM/PGM: 1..65535; 0 for float images (PFM) */
    uint16_t *u16;               /* integer samples (PPM/PGM), row-major, top row first,
                                      channels interleaved; NULL for float */
    float *f32;                  /* float samples (PFM), top row first (PFM stores
                                      bottom-to-top: flipped on read/write); NULL for integer */
} img_t;

/* Each returns 0 on success. On failure returns -1, leaves *img empty (all
 * zero, nothing allocated) and writes into err (size errlen; may be NULL/0)
 * a message naming the file and what is wrong, e.g.
 * "data/x.ppm: truncated: expected 921600 bytes of pixel data, got 1000". */

/* Reads P5, P6 (8-bit, or 16-bit big-endian when maxval > 255), PF, Pf
 * (negative scale = little-endian); the format is detected by magic.
 * Integer samples above maxval are an error; float samples (NaN, Inf,
 * negative) are returned as stored. Trailing bytes after the pixels are
 * ignored. */
int img_read(const char *path, img_t *img, char *err, size_t errlen);

/* The same with width and height at most maxdim (1..65535; the simulator
 * passes the engine's BLOOM_MAX_DIM), refused as the header is read:
 * "bad header: width 20000 exceeds the limit of 16384 per side". Neither
 * allocates more than the file backs: a regular file's size is checked
 * against the header before any allocation, and from a pipe the samples
 * grow with the rows that arrive. */
int img_read_max(const char *path, img_t *img, int maxdim, char *err, size_t errlen);
/* The same from an open stream, from its current position; name is what
 * messages call it. The stream is left open. */
int img_fread(FILE *f, const char *name, img_t *img, int maxdim, char *err, size_t errlen);

/* Writes P5 (channels 1) or P6 (channels 3), 16-bit when maxval > 255.
 * Writers go through "path.tmp-XXXXXX" and rename() over path only when
 * everything was written, so a failed write never clobbers an old file. */
int img_write_ppm(const char *path, const img_t *img, char *err, size_t errlen);

/* Writes little-endian PF (channels 3) or Pf (channels 1), scale -1.0. */
int img_write_pfm(const char *path, const img_t *img, char *err, size_t errlen);

/* Frees the samples and zeroes *img; safe on an empty image or NULL. */
void img_free(img_t *img);

/* Allocates zeroed samples: u16 when maxval is 1..65535, f32 when maxval is
 * 0. Returns -1 (and leaves *img empty) on bad arguments (w, h outside
 * 1..65535, channels not 1 or 3) or out of memory. */
int img_alloc(img_t *img, int w, int h, int channels, int maxval);

/* The rule for float (PFM) samples entering the engine's linear Q16.16
 * format: NaN and negative -> 0 (lossy-codec ringing and garbage carry no
 * light), at or above 256.0 and +Inf -> 2^24 - 1 (the engine's largest
 * value), otherwise round half up of v * 65536. */
uint32_t img_float_to_q16(float v);

#endif
