/* fuzz_exr: the OpenEXR reader (sim/sim_exr.c, OpenEXRCore) on a regular
 * file and on a pipe (which it must refuse cleanly: the library seeks),
 * and through the simulator's input path. */
#include "fuzz_img_common.h"

#ifndef SIM_NO_EXR
#include <openexr.h>

static void quiet(exr_const_context_t c, exr_result_t code, const char *msg)
{
    (void)c;
    (void)code;
    (void)msg;
}

/* Samples of every channel the header declares, the library's own reading
 * of it (0 when it cannot); *too_big when a side exceeds the engine's. */
static uint64_t declared_samples(const char *path, int *too_big)
{
    exr_context_t ctx = NULL;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = quiet;
    uint64_t n = 0;
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *cl;
    if (exr_start_read(&ctx, path, &init) == EXR_ERR_SUCCESS &&
        exr_get_data_window(ctx, 0, &dw) == EXR_ERR_SUCCESS &&
        exr_get_channels(ctx, 0, &cl) == EXR_ERR_SUCCESS) {
        const int64_t w = (int64_t)dw.max.x - dw.min.x + 1, h = (int64_t)dw.max.y - dw.min.y + 1;
        *too_big = w > BLOOM_MAX_DIM || h > BLOOM_MAX_DIM;
        if (w > 0 && h > 0)
            n = (uint64_t)w * (uint64_t)h * (uint64_t)(cl->num_channels > 0 ? cl->num_channels : 1);
    }
    if (ctx)
        exr_finish(&ctx);
    return n;
}
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
#ifdef SIM_NO_EXR
    (void)data;
    (void)size;
    return 0;
#else
    const char *path = fz_file(data, size);
    int too_big = 0;
    if (declared_samples(path, &too_big) > 3u * FZ_MAX_PIXELS && !too_big)
        return 0; /* a large image the engine takes: skipped (fuzz.h) */
    char err[SIM_ERRLEN];
    img_t a, b;
    const int ra = sim_exr_read(path, &a, err, sizeof err);
    if (ra == 0) {
        fz_check_img(&a);
        FZ_CHECK(a.f32 && a.maxval == 0);
    } else {
        FZ_CHECK(!a.u16 && !a.f32 && err[0]);
    }
    if (too_big)
        FZ_CHECK(ra != 0);
    const int rb = sim_exr_read(fz_pipe(data, size), &b, err, sizeof err);
    if (rb == 0)
        fz_same_img(&a, &b);
    img_free(&a);
    img_free(&b);
    fz_source(data, size, "\x76\x2f\x31\x01", ra == 0, 0);
    return 0;
#endif
}
