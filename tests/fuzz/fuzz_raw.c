/* fuzz_raw: raw V4L2 dumps (sim/sim_source.c) of every --raw-format
 * (yuyv, rgb24, grey, rgb565) with a size and --raw-stride taken from the
 * input's first 7 bytes, the rest being the dump, on a regular file and on
 * a pipe: the same frames either way, an error naming the frame. */
#include "fuzz.h"
#include "fuzz_img_common.h"

#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in_t in = {data, size};
    sim_input_opts_t o;
    memset(&o, 0, sizeof o);
    const unsigned sel = fz_u8(&in);
    o.raw_fmt = (sim_raw_fmt_t)(SIM_RAW_YUYV + (sel & 3));
    /* sides 1..64 mostly; with bit 2 anything up to 2^16 (the command line
     * allows 1..16384: the reader must refuse the rest by itself) */
    const unsigned w = fz_u16(&in), h = fz_u16(&in);
    o.raw_w = sel & 4 ? (int)w : 1 + (int)(w % 64);
    o.raw_h = sel & 4 ? (int)h : 1 + (int)(h % 64);
    /* --raw-stride: 0 (packed) or 1..2^20 as the command line allows,
     * mostly a little above the packed row */
    const unsigned st = fz_u16(&in);
    const int bpp = o.raw_fmt == SIM_RAW_RGB24 ? 3 : o.raw_fmt == SIM_RAW_GREY ? 1 : 2;
    o.raw_stride = sel & 8 ? 0 : sel & 16 ? 1 + (long)st * 16 : (long)o.raw_w * bpp + (long)(st % 8) - 2;
    if (o.raw_stride < 0)
        o.raw_stride = 0;
    char err[SIM_ERRLEN];
    sim_source_t *s;
    uint64_t sum_file = 0, sum_pipe = 0;
    long nf = -2, np = -2;
    if (sim_source_open(&s, fz_file(in.p, in.n), &o, err, sizeof err) == 0) {
        const long frames = sim_source_frames(s);
        nf = fz_read_frames(s, &sum_file);
        if (frames <= FZ_MAX_FRAMES)
            FZ_CHECKF(nf == frames, "%ld of %ld frames", nf, frames);
        sim_source_close(s);
    } else {
        FZ_CHECK(strstr(err, ": frame ") != NULL);
    }
    if (sim_source_open(&s, fz_pipe(in.p, in.n), &o, err, sizeof err) == 0) {
        np = fz_read_frames(s, &sum_pipe);
        sim_source_close(s);
    }
    if (nf >= 0 && nf < FZ_MAX_FRAMES)
        FZ_CHECKF(np == nf && sum_pipe == sum_file, "pipe %ld frames, file %ld", np, nf);
    return 0;
}
