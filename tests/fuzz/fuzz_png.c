/* fuzz_png: the PNG reader (sim/sim_png.c, libpng) from a memory stream,
 * from a pipe (spooled to a temporary file) and through the simulator's
 * input path on a regular file; the three must agree. */
#include "fuzz_img_common.h"

static uint32_t be32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* IHDR is the first chunk: a large image the engine takes is skipped */
    if (size >= 24 && !memcmp(data + 12, "IHDR", 4)) {
        const uint32_t w = be32(data + 16), h = be32(data + 20);
        if (w <= BLOOM_MAX_DIM && h <= BLOOM_MAX_DIM && (uint64_t)w * h > FZ_MAX_PIXELS)
            return 0;
    }
    const int ra = fz_read_mem_and_pipe(sim_png_read, data, size);
    fz_source(data, size, "\x89PNG\r\n\x1a\n", ra == 0, (int)(size & 1));
    return 0;
}
