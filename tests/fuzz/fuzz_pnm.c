/* fuzz_ppm and fuzz_pfm (one source, two corpora): the PPM/PGM (P5/P6, 8-
 * and 16-bit) and PFM (PF/Pf, either byte order) reader of sim/imgio.c,
 * through the simulator's input path (sim_source_open/read on a regular
 * file: detection, the engine's side limit, the pixel rules) and through a
 * pipe (no size to check: the samples grow with the rows that come). */
#include "fuzz.h"
#include "sim.h"

#include <string.h>

/* What a successful read must hold. */
static void check_img(const img_t *im)
{
    FZ_CHECK(im->width >= 1 && im->width <= BLOOM_MAX_DIM && im->height >= 1 && im->height <= BLOOM_MAX_DIM);
    FZ_CHECK(im->channels == 1 || im->channels == 3);
    FZ_CHECK(!im->u16 != !im->f32);
    const size_t n = (size_t)im->width * (size_t)im->height * (size_t)im->channels;
    if (im->u16) {
        FZ_CHECK(im->maxval >= 1 && im->maxval <= 65535);
        for (size_t i = 0; i < n; i++)
            FZ_CHECK(im->u16[i] <= im->maxval);
    } else {
        FZ_CHECK(im->maxval == 0);
    }
}

/* The pixel rules over a decoded image: every word in range. */
static void check_frame(const img_t *im, int srgb)
{
    sim_frame_t f;
    memset(&f, 0, sizeof f);
    FZ_CHECK(sim_frame_from_img(im, srgb, &f) == 0);
    const size_t n = (size_t)f.w * (size_t)f.h * 3u;
    for (size_t i = 0; i < n; i++)
        FZ_CHECK(f.max[i % 3] ? f.px[i] <= (uint32_t)f.max[i % 3] : f.px[i] <= BLOOM_MAX_LINEAR);
    sim_frame_free(&f);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[SIM_ERRLEN];
    img_t a, b;
    /* the reader's own path, on a regular file */
    const char *path = fz_file(data, size);
    const int ra = img_read_max(path, &a, BLOOM_MAX_DIM, err, sizeof err);
    if (ra == 0) {
        check_img(&a);
        check_frame(&a, 0);
        check_frame(&a, 1);
    } else {
        FZ_CHECK(!a.u16 && !a.f32 && err[0]);
    }
    /* the same bytes through a pipe: the same verdict and the same samples */
    const int rb = img_read_max(fz_pipe(data, size), &b, BLOOM_MAX_DIM, err, sizeof err);
    FZ_CHECKF(ra == rb, "file %d, pipe %d: %s", ra, rb, err);
    if (ra == 0 && rb == 0) {
        const size_t n = (size_t)a.width * (size_t)a.height * (size_t)a.channels;
        FZ_CHECK(a.width == b.width && a.height == b.height && a.channels == b.channels &&
                 a.maxval == b.maxval);
        FZ_CHECK(a.u16 ? !memcmp(a.u16, b.u16, n * 2) : !memcmp(a.f32, b.f32, n * 4));
    }
    img_free(&a);
    img_free(&b);

    /* the simulator's input path: detection, then the frame */
    sim_input_opts_t o;
    memset(&o, 0, sizeof o);
    o.decode16_srgb = size & 1;
    sim_source_t *s;
    if (sim_source_open(&s, path, &o, err, sizeof err) == 0) {
        sim_frame_t f;
        memset(&f, 0, sizeof f);
        int r = sim_source_read(s, &f, err, sizeof err);
        FZ_CHECK(r == 1 || r == -1);
        if (r == 1)
            FZ_CHECK(f.w >= 1 && f.w <= BLOOM_MAX_DIM && f.h >= 1 && f.h <= BLOOM_MAX_DIM);
        if (r == 1)
            FZ_CHECK(sim_source_read(s, &f, err, sizeof err) == 0);
        else
            FZ_CHECK(strstr(err, ": frame 0: ") != NULL);
        sim_frame_free(&f);
        sim_source_close(s);
    }
    return 0;
}
