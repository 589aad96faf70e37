/* The bloom core's shared base: the internal sample format, the bytes per
 * pixel of a format and two integer helpers, which the modules share. It
 * includes nothing of theirs; what one module owns lives in that module's
 * header (make check-layout checks both). Pixels, sRGB tables and the
 * fixed-point helpers: pixel/bloom_pixel.h; rounding, knee and output
 * parameters: kernels/bloom_kernels.h; the graph: graph/bloom_graph.h; the
 * engine: engine/bloom_engine.h. Nothing here is API. */
#ifndef BLOOM_INTERNAL_H
#define BLOOM_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "bloom.h"

/* Internal linear samples are Q12.20 (sim/docs/fixed-point.md): 16x finer
 * than the Q16.16 of the API, same 256.0 ceiling. BLOOM_LIN_BITS may be set
 * to 16..20 to measure precision against accuracy (make report); the tables
 * (src/pixel/bloom_tables.c) are generated for 20, `gen_tables F` for the others. */
#if BLOOM_LIN_BITS < 16 || BLOOM_LIN_BITS > 20
#error "BLOOM_LIN_BITS must be 16..20 (the overflow proof covers Q12.20)"
#endif
#define BLOOM_Q16_SHIFT (BLOOM_LIN_BITS - 16) /* Q16.16 -> internal */
#define BLOOM_LIN_ONE (1u << BLOOM_LIN_BITS)

/* Bytes per pixel of a format built in, 0 otherwise (bloom_format_bpp,
 * inline for the row kernels). */
static inline int bloom_bpp(bloom_format_t fmt)
{
    switch (fmt) {
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        return 3;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        return 4;
#endif
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        return 2;
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16:
        return 12;
#endif
#if BLOOM_USE_RGBF32
    case BLOOM_FMT_RGBF32:
        return 12;
#endif
    default:
        return 0;
    }
}

/* Small integer helpers shared by the core's files. */
static inline int imin(int a, int b)
{
    return a < b ? a : b;
}
static inline int imax(int a, int b)
{
    return a > b ? a : b;
}

#endif
