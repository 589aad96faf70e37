/* fuzz_aux: the aux plane readers, the simulator's (sim/sim_aux.c: grey
 * PGM or PNG, 8 or 16 bit) on a regular file and on a pipe, and the
 * camera tool's --aux (port/linux/cam_aux.c: P5 only, of the capture's
 * size). Where both take a P5 file they must give the same plane. */
#include "fuzz.h"
#include "sim.h"

#include "cam.h"

#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* IHDR is the first chunk: a large plane the engine takes is skipped */
    if (size >= 24 && !memcmp(data + 12, "IHDR", 4)) {
        const uint32_t w =
            (uint32_t)data[16] << 24 | (uint32_t)data[17] << 16 | (uint32_t)data[18] << 8 | data[19];
        const uint32_t h =
            (uint32_t)data[20] << 24 | (uint32_t)data[21] << 16 | (uint32_t)data[22] << 8 | data[23];
        if (w <= BLOOM_MAX_DIM && h <= BLOOM_MAX_DIM && (uint64_t)w * h > FZ_MAX_PIXELS)
            return 0;
    }
    char err[SIM_ERRLEN];
    sim_aux_t a, b;
    const char *path = fz_file(data, size);
    const int ra = sim_aux_load(&a, path, err, sizeof err);
    if (ra == 0) {
        FZ_CHECK(a.w >= 1 && a.w <= BLOOM_MAX_DIM && a.h >= 1 && a.h <= BLOOM_MAX_DIM);
        FZ_CHECK((a.fmt == BLOOM_AUX_U8 && a.max == 255) || (a.fmt == BLOOM_AUX_U16 && a.max == 65535));
        for (size_t i = 0; i < (size_t)a.w * (size_t)a.h; i++)
            FZ_CHECK(a.codes[i] <= (uint32_t)a.max);
    } else {
        FZ_CHECKF(strstr(err, "--aux: ") != NULL, "%s", err);
    }
    const int rb = sim_aux_load(&b, fz_pipe(data, size), err, sizeof err);
    FZ_CHECKF(ra == rb, "file %d, pipe %d: %s", ra, rb, err);
    if (ra == 0 && rb == 0)
        FZ_CHECK(a.w == b.w && a.h == b.h && a.fmt == b.fmt &&
                 !memcmp(a.codes, b.codes, (size_t)a.w * (size_t)a.h * sizeof *a.codes));
    sim_aux_free(&b);

    /* the camera's reader, at the plane's own size when the simulator read
     * one, else at a size from the input's last bytes */
    int w = ra == 0 ? a.w : 1 + (size ? data[size - 1] % 16 : 0);
    int h = ra == 0 ? a.h : 1 + (size > 1 ? data[size - 2] % 16 : 0);
    bloom_aux_format_t fmt = BLOOM_AUX_NONE;
    uint8_t *plane = NULL;
    const int rc = cam_aux_load(path, w, h, &fmt, &plane, err, sizeof err);
    if (rc == 0) {
        FZ_CHECK(plane && (fmt == BLOOM_AUX_U8 || fmt == BLOOM_AUX_U16));
    } else {
        FZ_CHECK(!plane && strstr(err, "--aux ") != NULL);
    }
    /* a binary PGM the simulator takes, the camera takes too, the same codes */
    if (ra == 0 && size >= 2 && data[0] == 'P' && data[1] == '5') {
        FZ_CHECKF(rc == 0, "the simulator reads it, bloom_cam does not: %s", err);
        FZ_CHECK(fmt == a.fmt &&
                 !memcmp(plane, a.data, (size_t)w * (size_t)h * (fmt == BLOOM_AUX_U16 ? 2u : 1u)));
    }
    free(plane);
    plane = NULL;
    const int rp = cam_aux_load(fz_pipe(data, size), w, h, &fmt, &plane, err, sizeof err);
    FZ_CHECKF(rp == rc, "file %d, pipe %d: %s", rc, rp, err);
    free(plane);
    sim_aux_free(&a);
    return 0;
}
