/* fuzz_y4m: the Y4M reader of sim/sim_source.c on a regular file (checked
 * whole at open: every frame header and the exact size) and on a pipe
 * (checked as it goes, the frame buffer growing with the data). A file
 * that opens must then read every frame it counted; the pipe must deliver
 * the same frames, and fail where the file failed to open. */
#include "fuzz.h"
#include "fuzz_img_common.h"

#include <string.h>

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
        nf = fz_read_frames(s, &sum_file);
        /* a Y4M file that opens was checked whole: every frame reads */
        if (frames >= 0 && frames <= FZ_MAX_FRAMES)
            FZ_CHECKF(nf == frames, "%ld of %ld frames", nf, frames);
        sim_source_close(s);
    } else {
        FZ_CHECK(strstr(err, ": frame ") != NULL);
    }
    if (sim_source_open(&s, fz_pipe(data, size), &o, err, sizeof err) == 0) {
        np = fz_read_frames(s, &sum_pipe);
        sim_source_close(s);
    }
    if (nf >= 0 && nf < FZ_MAX_FRAMES) /* the pipe reads what the file had */
        FZ_CHECKF(np == nf && sum_pipe == sum_file, "pipe %ld frames, file %ld", np, nf);
    return 0;
}
