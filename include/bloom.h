/* bloom: an allocation-free, integer-only, row-streaming bloom engine.
 *
 * The caller owns all memory: bloom_workspace_size() tells how many bytes a
 * configuration needs, bloom_init() carves the engine out of the caller's
 * buffer. Frames go through row by row (bloom_push_row / bloom_pull_row) or
 * whole (bloom_process, a thin loop over the row calls). The maths is
 * sim/docs/bloom-model.md; the integer formats are sim/docs/fixed-point.md. */
#ifndef BLOOM_H
#define BLOOM_H

#include <stddef.h>
#include <stdint.h>

#include "bloom_config.h"

#ifdef __cplusplus
extern "C" {
#endif

#define BLOOM_FRAC_BITS 16
#define BLOOM_ONE (1u << BLOOM_FRAC_BITS)         /* linear 1.0 in Q16.16 */
#define BLOOM_MAX_LINEAR ((1u << 24) - 1u)        /* largest linear sample, 255.99998 */
#define BLOOM_Q16(x) ((uint32_t)((x) * 65536.0 + 0.5)) /* for constants */
#define BLOOM_MAX_LEVELS 16
#define BLOOM_MAX_DIM 16384
#define BLOOM_MAX_THRESHOLD (1u << 24)            /* 256.0 */
#define BLOOM_MAX_INTENSITY (10u << BLOOM_FRAC_BITS) /* gamma-space 10.0 */
#define BLOOM_WORKSPACE_ALIGN 8

typedef enum {
    BLOOM_FMT_RGB888 = 1, /* bytes R, G, B (V4L2 RGB24) */
    BLOOM_FMT_XRGB8888,   /* LE word 0xXXRRGGBB: bytes B, G, R, X (fbdev 32 bpp) */
    BLOOM_FMT_RGB565,     /* LE 16-bit RRRRRGGG GGGBBBBB (fbdev 16 bpp) */
    BLOOM_FMT_RGBQ16      /* 3 native uint32_t, linear Q16.16 (HDR in and out) */
} bloom_format_t;

enum {
    BLOOM_FLAG_LINEAR = 1u << 0,      /* no sRGB decode/encode: codes are linear */
    BLOOM_FLAG_DEBUG_VIEW = 1u << 1,  /* output I*B only (bloom-only view) */
    BLOOM_FLAG_COPY_SOURCE = 1u << 2, /* engine copies the source rows it still
                                         needs; without it, it keeps pointers */
    BLOOM_FLAG_NO_SKIP = 1u << 3,     /* compute rows known to be zero anyway
                                         (for tests and benchmarks) */
    BLOOM_FLAG_NO_SIMD = 1u << 4      /* C row kernels only, no SSE2/NEON (same
                                         bits; for tests and benchmarks) */
};

typedef enum {
    BLOOM_OK = 0,
    BLOOM_AGAIN = 1, /* pull: no output row ready yet, push more rows */
    BLOOM_DONE = 2,  /* pull: every row of the frame has been written */
    BLOOM_E_NULL = -1,
    BLOOM_E_SIZE = -2,
    BLOOM_E_LEVELS = -3,
    BLOOM_E_THRESHOLD = -4,
    BLOOM_E_KNEE = -5,
    BLOOM_E_INTENSITY = -6,
    BLOOM_E_FORMAT = -7,
    BLOOM_E_FLAGS = -8,
    BLOOM_E_WORKSPACE = -9,
    BLOOM_E_ALIGN = -10,
    BLOOM_E_BUSY = -11,
    BLOOM_E_STATE = -12,
    BLOOM_E_INTERNAL = -13,
    BLOOM_E_TOO_BIG = -14
} bloom_status_t;

typedef struct {
    int width, height;        /* 1 .. BLOOM_MAX_DIM */
    bloom_format_t in_fmt, out_fmt;
    int levels;               /* requested pyramid depth N, 1 .. 16 */
    uint32_t threshold;       /* linear, Q16.16, 0 .. BLOOM_MAX_THRESHOLD */
    uint32_t soft_knee;       /* Q16.16, 0 .. 1.0 (0 = hard knee) */
    uint32_t intensity;       /* gamma space, Q16.16, 0 .. 10.0 */
    uint32_t flags;           /* BLOOM_FLAG_* */
} bloom_config_t;

typedef struct {
    size_t workspace_bytes;   /* what bloom_init needs */
    int levels;               /* L: levels actually built (level-count rule) */
    int level_w[BLOOM_MAX_LEVELS + 1], level_h[BLOOM_MAX_LEVELS + 1];
    int latency_rows;         /* output row y is ready once source row
                                 min(y + latency_rows, height - 1) is in */
    int source_rows;          /* source rows the engine reads back: the last
                                 source_rows pushed rows must stay readable
                                 (pointer mode) or are copied (COPY_SOURCE) */
    size_t ring_bytes[BLOOM_MAX_LEVELS + 1]; /* row memory per level; [0] = source copy */
    uint32_t threshold_q, knee_q; /* quantized threshold and knee, Q12.20 */
    uint32_t intensity_q;         /* linear intensity I_q, Q16.16 */
} bloom_info_t;

typedef struct bloom bloom_t;

/* Fill cfg with the defaults (threshold 1.0, soft knee 0.5, intensity 1.0,
 * 5 levels, RGB888 in and out, sRGB). */
void bloom_config_default(bloom_config_t *cfg, int width, int height);

/* Validate cfg and describe the engine it gives. Pure. */
bloom_status_t bloom_query(const bloom_config_t *cfg, bloom_info_t *info);

/* Workspace bytes for cfg, or 0 if cfg is invalid. Pure. */
size_t bloom_workspace_size(const bloom_config_t *cfg);

/* Carve an engine out of ws (aligned to BLOOM_WORKSPACE_ALIGN). Refuses a
 * buffer that is too small (BLOOM_E_WORKSPACE); the buffer's contents are
 * unspecified after any failure. */
bloom_status_t bloom_init(bloom_t **out, void *ws, size_t ws_bytes, const bloom_config_t *cfg);

/* Row interface. Per frame: bloom_begin, then push source rows in order;
 * after each push pull output rows until BLOOM_AGAIN. A push that would
 * overwrite a row the engine still needs returns BLOOM_E_BUSY: pull first.
 * After the last push, pull until BLOOM_DONE. pull writes output row
 * bloom_rows_out() (before the call) to dst_row. Output row y never needs
 * source rows above y, so dst may alias src (in place) when the formats
 * and strides match. */
bloom_status_t bloom_begin(bloom_t *b);
bloom_status_t bloom_push_row(bloom_t *b, const void *src_row);
bloom_status_t bloom_pull_row(bloom_t *b, void *dst_row);
int bloom_rows_in(const bloom_t *b);
int bloom_rows_out(const bloom_t *b);

/* Band interface: push source rows rows_in .. rows_in + nrows - 1 (src is
 * the frame's row 0, src_stride bytes apart) and write every output row that
 * becomes ready to dst (frame row 0, dst_stride bytes apart). */
bloom_status_t bloom_run_rows(bloom_t *b, const void *src, ptrdiff_t src_stride, int nrows,
                              void *dst, ptrdiff_t dst_stride);

/* Whole frame: bloom_begin + bloom_run_rows(height) + drain. */
bloom_status_t bloom_process(bloom_t *b, const void *src, ptrdiff_t src_stride, void *dst,
                             ptrdiff_t dst_stride);

/* Bytes per pixel of a format (0 if unknown or compiled out). */
int bloom_format_bpp(bloom_format_t fmt);

/* What a status means, for messages: "threshold above 256.0", ... */
const char *bloom_status_str(bloom_status_t st);

/* Static workspace: an upper bound of bloom_workspace_size() usable in a
 * constant expression (tests check it against the exact size over a grid of
 * sizes and depths). src_bpp is the input bytes per pixel, copy 1 with
 * BLOOM_FLAG_COPY_SOURCE. Rows held per level (sim/docs/streaming.md): 12 at
 * level 1, 8 at level 2, at most 2^(L-k+2) at level k >= 3, of w/2^k + 1 pixels of
 * 12 bytes, plus one zero row of w/2 pixels; that sums to below
 * w*(2^L + 100) + 12*2^L; the source ring holds fewer than 4*2^L + 8 rows
 * (pointers, or copies). Computed in unsigned long long: a configuration
 * too big for the target's address space fails to compile as a static
 * array instead of wrapping around. */
#define BLOOM_WORKSPACE_MAX(w, h, levels, src_bpp, copy)                                   \
    (3072ull + (unsigned long long)(w) * ((1ull << (levels)) + 100u) + (64ull << (levels)) + \
     64ull * (unsigned long long)(levels) +                                                \
     ((copy) ? ((4ull << (levels)) + 8u) * (unsigned long long)(w) * (unsigned long long)(src_bpp) \
             : 0ull))
#define BLOOM_WORKSPACE_DEFINE(name, bytes) \
    static uint64_t name[((bytes) + 7u) / 8u]

#ifdef __cplusplus
}
#endif
#endif
