/* fuzz_jpeg: the JPEG reader (sim/sim_jpeg.c, libjpeg) from a memory
 * stream, from a pipe and through the simulator's input path on a regular
 * file; the three must agree. */
#include "fuzz_img_common.h"

#include <setjmp.h>

#include <jpeglib.h>

typedef struct {
    struct jpeg_error_mgr pub;
    jmp_buf jb;
} probe_err_t;

static void probe_exit(j_common_ptr ci)
{
    longjmp(((probe_err_t *)(void *)ci->err)->jb, 1);
}

static void probe_message(j_common_ptr ci, int level)
{
    (void)ci;
    (void)level;
}

/* The size the header declares, as libjpeg reads it; 0 when it cannot. */
static uint64_t declared_pixels(const uint8_t *data, size_t size, int *too_big)
{
    struct jpeg_decompress_struct ci;
    probe_err_t e;
    volatile uint64_t px = 0;
    ci.err = jpeg_std_error(&e.pub);
    e.pub.error_exit = probe_exit;
    e.pub.emit_message = probe_message;
    jpeg_create_decompress(&ci);
    if (!setjmp(e.jb)) {
        jpeg_mem_src(&ci, data, (unsigned long)size);
        if (jpeg_read_header(&ci, TRUE) == JPEG_HEADER_OK) {
            px = (uint64_t)ci.image_width * ci.image_height;
            *too_big = ci.image_width > BLOOM_MAX_DIM || ci.image_height > BLOOM_MAX_DIM;
        }
    }
    jpeg_destroy_decompress(&ci);
    return px;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    int too_big = 0;
    if (size && declared_pixels(data, size, &too_big) > FZ_MAX_PIXELS && !too_big)
        return 0; /* a large image the engine takes: skipped (fuzz.h) */
    const int ra = fz_read_mem_and_pipe(sim_jpeg_read, data, size);
    if (too_big)
        FZ_CHECK(ra != 0);
    fz_source(data, size, "\xFF\xD8\xFF", ra == 0, 0);
    return 0;
}
