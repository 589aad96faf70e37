/* fuzz_y4m: the Y4M reader of sim/sim_source.c on a regular file (checked
 * whole at open: every frame header and the exact size) and on a pipe
 * (checked as it goes, the frame buffer growing with the data). A file
 * that opens must then read every frame it counted; the pipe must deliver
 * the same frames, and fail where the file failed to open. */
#include "fuzz.h"
#include "sim.h"

#include <string.h>

#define MAX_FRAMES 64

/* Reads every frame; returns the count read, -1 after an error. The
 * frames' words are summed into *sum (the pipe must give the same). */
static long read_all(sim_source_t *s, uint64_t *sum)
{
    char err[SIM_ERRLEN];
    sim_frame_t f;
    memset(&f, 0, sizeof f);
    long n = 0;
    int r;
    while (n < MAX_FRAMES && (r = sim_source_read(s, &f, err, sizeof err)) == 1) {
        FZ_CHECK(f.w >= 1 && f.w <= BLOOM_MAX_DIM && f.h >= 1 && f.h <= BLOOM_MAX_DIM);
        for (size_t i = 0; i < (size_t)f.w * (size_t)f.h * 3u; i++) {
            FZ_CHECK(f.px[i] <= 255);
            *sum = *sum * 31u + f.px[i];
        }
        n++;
    }
    if (n < MAX_FRAMES && r < 0) {
        FZ_CHECKF(strstr(err, ": frame ") != NULL, "%s", err);
        n = -1;
    }
    sim_frame_free(&f);
    return n;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 9 || memcmp(data, "YUV4MPEG2", 9)) /* other formats: the image targets */
        return 0;
    char err[SIM_ERRLEN];
    sim_input_opts_t o;
    memset(&o, 0, sizeof o);
    sim_source_t *s;
    uint64_t sum_file = 0, sum_pipe = 0;
    long nf = -2, np = -2;
    if (sim_source_open(&s, fz_file(data, size), &o, err, sizeof err) == 0) {
        const long frames = sim_source_frames(s);
        nf = read_all(s, &sum_file);
        /* a Y4M file that opens was checked whole: every frame reads */
        if (frames >= 0 && frames <= MAX_FRAMES)
            FZ_CHECKF(nf == frames, "%ld of %ld frames", nf, frames);
        sim_source_close(s);
    } else {
        FZ_CHECK(strstr(err, ": frame ") != NULL);
    }
    if (sim_source_open(&s, fz_pipe(data, size), &o, err, sizeof err) == 0) {
        np = read_all(s, &sum_pipe);
        sim_source_close(s);
    }
    if (nf >= 0 && nf < MAX_FRAMES) /* the pipe reads what the file had */
        FZ_CHECKF(np == nf && sum_pipe == sum_file, "pipe %ld frames, file %ld", np, nf);
    return 0;
}
