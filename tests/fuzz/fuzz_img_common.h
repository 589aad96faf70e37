/* What the image targets (fuzz_png, fuzz_jpeg, fuzz_exr) check of a
 * decoded image and of the simulator's input path over it, and the stream
 * targets (fuzz_y4m, fuzz_raw) of the frames they read. */
#ifndef BLOOM_FUZZ_IMG_COMMON_H
#define BLOOM_FUZZ_IMG_COMMON_H

#include "fuzz.h"
#include "sim.h"

#include <string.h>

/* A successful decode: a size the engine takes, samples in range. */
static inline void fz_check_img(const img_t *im)
{
    FZ_CHECK(im->width >= 1 && im->width <= BLOOM_MAX_DIM && im->height >= 1 && im->height <= BLOOM_MAX_DIM);
    FZ_CHECK(im->channels == 1 || im->channels == 3);
    FZ_CHECK(!im->u16 != !im->f32);
    const size_t n = (size_t)im->width * (size_t)im->height * (size_t)im->channels;
    if (im->u16)
        for (size_t i = 0; i < n; i++)
            FZ_CHECK(im->u16[i] <= im->maxval);
}

/* Two decodes of the same bytes agree. */
static inline void fz_same_img(const img_t *a, const img_t *b)
{
    FZ_CHECK(a->width == b->width && a->height == b->height && a->channels == b->channels &&
             a->maxval == b->maxval && !a->u16 == !b->u16);
    const size_t n = (size_t)a->width * (size_t)a->height * (size_t)a->channels;
    FZ_CHECK(a->u16 ? !memcmp(a->u16, b->u16, n * 2) : !memcmp(a->f32, b->f32, n * 4));
}

/* The simulator's input path on a regular file: one frame or an error
 * naming frame 0; ok says whether the direct decode succeeded, which the
 * simulator's must match when it detects the same format (the input
 * starts with magic). */
static inline void fz_source(const uint8_t *data, size_t size, const char *magic, int ok, int decode16_srgb)
{
    const size_t ml = strlen(magic);
    const int same = size >= ml && !memcmp(data, magic, ml);
    const char *path = fz_file(data, size);
    char err[SIM_ERRLEN];
    sim_input_opts_t o;
    memset(&o, 0, sizeof o);
    o.decode16_srgb = decode16_srgb;
    sim_source_t *s;
    if (sim_source_open(&s, path, &o, err, sizeof err) != 0)
        return;
    sim_frame_t f;
    memset(&f, 0, sizeof f);
    const int r = sim_source_read(s, &f, err, sizeof err);
    FZ_CHECKF(!same || r == (ok ? 1 : -1), "read %d, direct decode %d: %s", r, ok, r < 0 ? err : "");
    FZ_CHECK(r == 1 || r == -1);
    if (r == 1) {
        const size_t n = (size_t)f.w * (size_t)f.h * 3u;
        for (size_t i = 0; i < n; i++)
            FZ_CHECK(f.max[i % 3] ? f.px[i] <= (uint32_t)f.max[i % 3] : f.px[i] <= BLOOM_MAX_LINEAR);
        FZ_CHECK(sim_source_read(s, &f, err, sizeof err) == 0);
    } else {
        FZ_CHECK(strstr(err, ": frame 0: ") != NULL);
    }
    sim_frame_free(&f);
    sim_source_close(s);
}

/* A stream reader (sim_png_read, sim_jpeg_read) on the input from a
 * memory stream and from a pipe: a good decode passes fz_check_img, a
 * refusal leaves nothing allocated and says why, both give the same
 * verdict and, when they read, the same image. Returns the first's status. */
typedef int (*fz_stream_reader_fn)(FILE *f, img_t *img, char *err, size_t errlen);
static inline int fz_read_mem_and_pipe(fz_stream_reader_fn rd, const uint8_t *data, size_t size)
{
    char err[SIM_ERRLEN];
    img_t a, b;
    FILE *f = fz_mem_stream(data, size);
    const int ra = rd(f, &a, err, sizeof err);
    fclose(f);
    if (ra == 0)
        fz_check_img(&a);
    else
        FZ_CHECK(!a.u16 && !a.f32 && err[0]);
    f = fz_pipe_stream(data, size);
    const int rb = rd(f, &b, err, sizeof err);
    fclose(f);
    FZ_CHECKF(ra == rb, "memory %d, pipe %d: %s", ra, rb, err);
    if (ra == 0)
        fz_same_img(&a, &b);
    img_free(&a);
    img_free(&b);
    return ra;
}

/* Every frame of s up to FZ_MAX_FRAMES: a size the engine takes, codes
 * within their channel's largest, a hash of every word into *sum. Returns
 * the frames read, or -1 when a read failed (its message names the frame). */
#define FZ_MAX_FRAMES 64
static inline long fz_read_frames(sim_source_t *s, uint64_t *sum)
{
    char err[SIM_ERRLEN];
    sim_frame_t f;
    memset(&f, 0, sizeof f);
    long n = 0;
    int r = 0;
    while (n < FZ_MAX_FRAMES && (r = sim_source_read(s, &f, err, sizeof err)) == 1) {
        FZ_CHECK(f.w >= 1 && f.w <= BLOOM_MAX_DIM && f.h >= 1 && f.h <= BLOOM_MAX_DIM);
        for (size_t i = 0; i < (size_t)f.w * (size_t)f.h * 3u; i++) {
            FZ_CHECK(f.px[i] <= (uint32_t)f.max[i % 3]);
            *sum = *sum * 31u + f.px[i];
        }
        n++;
    }
    if (n < FZ_MAX_FRAMES && r < 0) {
        FZ_CHECKF(strstr(err, ": frame ") != NULL, "%s", err);
        n = -1;
    }
    sim_frame_free(&f);
    return n;
}

#endif
