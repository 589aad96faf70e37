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
#define BLOOM_ONE (1u << BLOOM_FRAC_BITS)            /* linear 1.0 in Q16.16 */
#define BLOOM_MAX_LINEAR ((1u << 24) - 1u)           /* largest linear sample, 255.99998 */
#define BLOOM_Q16(x) ((uint32_t)((x)*65536.0 + 0.5)) /* for constants */
#define BLOOM_MAX_LEVELS 16
#define BLOOM_MAX_DIM 16384
#define BLOOM_MAX_THRESHOLD (1u << 24)               /* 256.0 */
#define BLOOM_MAX_INTENSITY (10u << BLOOM_FRAC_BITS) /* gamma-space 10.0 */
#define BLOOM_WORKSPACE_ALIGN 8

/* The pipelines (sim/docs/presets.md): the default and the seed recipes,
 * each a preset of the same streaming engine. */
typedef enum {
    BLOOM_PRESET_UNITY = 0,   /* box down / tent up, soft knee, additive (default) */
    BLOOM_PRESET_GAMEDEV,     /* luminance threshold, 9-tap Gaussian at 1/2..1/8, Reinhard, gamma 2.2 */
    BLOOM_PRESET_XNA,         /* threshold subtraction at 1/4, Kawase passes, screen combine */
    BLOOM_PRESET_ATTENUATION, /* the default with the first pass scaled by a depth plane */
    BLOOM_PRESET_ARM,         /* dual filtering on a one-channel luminance plane, mask, baked map */
    BLOOM_PRESET_COD,         /* 13-tap down with Karis average, 3x3 tent up, energy-conserving */
    BLOOM_PRESET_COUNT
} bloom_preset_t;

/* A one-channel plane beside the frame, same size: the depth plane of the
 * attenuation preset (0 = near ... max = far), the mask or the baked map of
 * the arm preset. Rows are (pointer, stride) like the frame's. */
typedef enum {
    BLOOM_AUX_NONE = 0,
    BLOOM_AUX_U8, /* one byte per pixel (R8 / GREY) */
    BLOOM_AUX_U16 /* one native uint16_t per pixel (V4L2 Z16) */
} bloom_aux_format_t;

typedef enum {
    BLOOM_FMT_RGB888 = 1, /* bytes R, G, B (V4L2 RGB24) */
    BLOOM_FMT_XRGB8888,   /* LE word 0xXXRRGGBB: bytes B, G, R, X (fbdev 32 bpp) */
    BLOOM_FMT_RGB565,     /* LE 16-bit RRRRRGGG GGGBBBBB (fbdev 16 bpp) */
    BLOOM_FMT_RGBQ16,     /* 3 native uint32_t, linear Q16.16 (HDR in and out) */
    BLOOM_FMT_RGBF32      /* 3 native IEEE-754 binary32 floats, linear (HDR input only),
                             decoded with integers only */
} bloom_format_t;

enum {
    BLOOM_FLAG_LINEAR = 1u << 0,      /* no sRGB decode/encode: codes are linear */
    BLOOM_FLAG_DEBUG_VIEW = 1u << 1,  /* output I*B only (bloom-only view) */
    BLOOM_FLAG_COPY_SOURCE = 1u << 2, /* engine copies the source rows it still
                                         needs; without it, it keeps pointers */
    BLOOM_FLAG_NO_SKIP = 1u << 3,     /* compute rows known to be zero anyway
                                         (for tests and benchmarks) */
    BLOOM_FLAG_NO_SIMD = 1u << 4,     /* C row kernels only, no SSE2/NEON (same
                                         bits; for tests and benchmarks) */
    BLOOM_FLAG_SATURATE = 1u << 5,    /* xna: clamp to 1.0 between passes (8-bit targets) */
    BLOOM_FLAG_BAKED = 1u << 6,       /* arm: no pyramid; out = S + S*map*strength
                                         with the aux plane as the map */
    BLOOM_FLAG_ADDITIVE = 1u << 7,    /* cod: additive levels instead of energy-conserving */
    BLOOM_FLAG_NO_AVX2 = 1u << 8,     /* x86-64: SSE2 row kernels even where the CPU has
                                         AVX2 (same bits; for tests and benchmarks) */
    BLOOM_FLAG_KEEP_LEVELS = 1u << 9  /* cod: keep the levels the up pass reads in
                                         delay lines instead of computing them again
                                         (same bits; faster, more workspace:
                                         sim/docs/presets/cod.md) */
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
    BLOOM_E_TOO_BIG = -14,
    BLOOM_E_PRESET = -15, /* unknown preset, or compiled out */
    BLOOM_E_STRENGTH = -16,
    BLOOM_E_PASSES = -17,
    BLOOM_E_ATTENUATION = -18,
    BLOOM_E_WEIGHT = -19,
    BLOOM_E_TINT = -20,
    BLOOM_E_AUX = -21,        /* aux plane missing, unexpected or of an unknown format */
    BLOOM_E_ALIAS = -22,      /* destination overlaps source rows still needed: in place
                                needs the same format and stride */
    BLOOM_E_TILE = -23,       /* the output rectangle is not inside the frame */
    BLOOM_E_SAMPLE_BITS = -24 /* sample_bits not 16 or 32, or 16 where they cannot carry
                                 the configuration (sim/docs/fixed-point.md) */
} bloom_status_t;

/* Parameters of the presets other than the default; a preset ignores the
 * ones it does not name. All Q16.16. */
typedef struct {
    uint32_t strength;                       /* gamedev: scene + strength*bloom, 0 .. 16.0;
                                arm with BLOOM_FLAG_BAKED: map strength 0 .. 16.0 */
    int passes;                              /* xna: Kawase passes P, 1 .. 8 */
    uint32_t attenuation;                    /* attenuation: a, 0 .. 1.0 */
    uint32_t max_reduction;                  /* attenuation: r, 0 .. 1.0 */
    uint32_t level_weight[BLOOM_MAX_LEVELS]; /* cod: blend factor c_k, 0 .. 1.0, of the
                                upsample into level k (k = 0: the final composite) */
    uint32_t tint[3];                        /* cod and arm: glow colour R, G, B, 0 .. 1.0 */
} bloom_preset_params_t;

typedef struct {
    int width, height; /* 1 .. BLOOM_MAX_DIM */
    bloom_format_t in_fmt, out_fmt;
    int levels;                 /* requested pyramid depth N, 1 .. 16 */
    uint32_t threshold;         /* linear, Q16.16, 0 .. BLOOM_MAX_THRESHOLD */
    uint32_t soft_knee;         /* Q16.16, 0 .. 1.0 (0 = hard knee) */
    uint32_t intensity;         /* gamma space, Q16.16, 0 .. 10.0 */
    uint32_t flags;             /* BLOOM_FLAG_* */
    bloom_preset_t preset;      /* BLOOM_PRESET_UNITY (0) unless set */
    bloom_aux_format_t aux_fmt; /* BLOOM_AUX_NONE unless the preset reads a plane */
    bloom_preset_params_t p;    /* the preset's own parameters */
    /* The output rectangle (a tile): the engine writes exactly these pixels
     * of the frame, bit for bit what the whole frame would have there, and
     * reads the source rectangle bloom_query reports (the tile and its
     * halo). tile_w == 0 (bloom_config_default) is the whole frame. */
    int tile_x, tile_y, tile_w, tile_h;
    /* Bits per pyramid sample: 32 (bloom_config_default; 0 means 32 too)
     * or 16, uint16_t rows holding a format chosen by the level count
     * (sim/docs/fixed-point.md, "16-bit samples"): about half the
     * workspace, for the default preset on 8/6/5-bit input; refused
     * elsewhere with BLOOM_E_SAMPLE_BITS. */
    int sample_bits;
} bloom_config_t;

typedef struct {
    size_t workspace_bytes; /* what bloom_init needs */
    int levels;             /* L: levels actually built (level-count rule) */
    int level_w[BLOOM_MAX_LEVELS + 1], level_h[BLOOM_MAX_LEVELS + 1];
    int latency_rows;                        /* output row y is ready once source row
                                 min(y + latency_rows, height - 1) is in */
    int source_rows;                         /* source rows the engine reads back: the last
                                 source_rows pushed rows must stay readable
                                 (pointer mode) or are copied (COPY_SOURCE) */
    size_t ring_bytes[BLOOM_MAX_LEVELS + 1]; /* row memory per level; [0] = source copy */
    uint32_t threshold_q, knee_q;            /* quantized threshold and knee, Q12.20 */
    uint32_t intensity_q;                    /* linear intensity I_q, Q16.16 */
    /* The source rectangle the engine reads for its output rectangle (the
     * whole frame without a tile); level_w/h are the sizes over it. */
    int src_x, src_y, src_w, src_h;
    int sample_bits;       /* 32 or 16 (the configuration's) */
    int sample_frac;       /* fraction bits of the pyramid samples: 20 (Q12.20), or 16 - bitlen(L) */
    size_t schedule_bytes; /* of workspace_bytes, the static schedule's table (0 in the size build) */
} bloom_info_t;

typedef struct bloom bloom_t;

/* Fill cfg with the defaults (threshold 1.0, soft knee 0.5, intensity 1.0,
 * 5 levels, RGB888 in and out, sRGB). */
void bloom_config_default(bloom_config_t *cfg, int width, int height);

/* Switch cfg to preset p with that preset's default parameters (size,
 * formats, the level count and the flags other than the preset's own are
 * kept; set the level count first: cod's default level weights follow it).
 * Returns BLOOM_E_PRESET for an unknown or compiled-out preset. */
bloom_status_t bloom_config_preset(bloom_config_t *cfg, bloom_preset_t p);

/* "unity", "gamedev", "xna", "attenuation", "arm", "cod"; NULL if unknown. */
const char *bloom_preset_name(bloom_preset_t p);
/* The preset of that name, or -1. Compiled-out presets are still named. */
int bloom_preset_from_name(const char *name);
/* Whether this build carries preset p (BLOOM_USE_<PRESET>). */
int bloom_preset_available(bloom_preset_t p);

/* What a preset reads beyond the common parameters (threshold, knee,
 * intensity, levels, formats, the common flags): bits of
 * bloom_preset_params(). A preset ignores the bloom_preset_params_t fields
 * it does not read; it refuses the preset flags and the aux plane it does
 * not read (bloom_query). */
typedef enum {
    BLOOM_PARAM_STRENGTH = 1u << 0,      /* p.strength */
    BLOOM_PARAM_PASSES = 1u << 1,        /* p.passes */
    BLOOM_PARAM_ATTENUATION = 1u << 2,   /* p.attenuation */
    BLOOM_PARAM_MAX_REDUCTION = 1u << 3, /* p.max_reduction */
    BLOOM_PARAM_AUX = 1u << 4,           /* an aux plane (aux_fmt, bloom_set_aux, bloom_push_row_aux) */
    BLOOM_PARAM_TINT = 1u << 5,          /* p.tint */
    BLOOM_PARAM_WEIGHTS = 1u << 6,       /* p.level_weight */
    BLOOM_PARAM_SATURATE = 1u << 7,      /* BLOOM_FLAG_SATURATE */
    BLOOM_PARAM_ADDITIVE = 1u << 8,      /* BLOOM_FLAG_ADDITIVE */
    BLOOM_PARAM_BAKED = 1u << 9,         /* BLOOM_FLAG_BAKED */
    BLOOM_PARAM_RADIUS = 1u << 10,       /* the level count from bloom_levels_for_radius */
    BLOOM_PARAM_KEEP_LEVELS = 1u << 11   /* BLOOM_FLAG_KEEP_LEVELS */
} bloom_param_t;

/* The BLOOM_PARAM_* bits preset p reads; 0 for the default and for an
 * unknown preset. Pure; compiled-out presets are still described. */
uint32_t bloom_preset_params(bloom_preset_t p);

/* cod: the level count whose glow reaches about radius_px output pixels,
 * whatever the frame size (sim/docs/presets.md: reach of L levels). */
int bloom_levels_for_radius(int radius_px);

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
 * and strides match; a destination row that overlaps a source row still
 * needed, or source row y in another format, is refused (BLOOM_E_ALIAS).
 * BLOOM_SMALL builds (the size build) refuse only the same rows in another
 * format or stride; the other overlaps are then the caller's to avoid.
 * With a tile (cfg.tile_w > 0): the rows pushed are those of the source
 * rectangle (info.src_y .. src_y + src_h - 1), each given as its frame row
 * (column 0: the engine reads columns src_x .. src_x + src_w - 1, so every
 * strip engine of a frame is pushed the same rows); pull writes the tile's
 * columns of the frame row dst_row for output rows tile_y ..
 * tile_y + tile_h - 1 (output row tile_y + bloom_rows_out()); bloom_rows_in
 * and bloom_rows_out count those rows, and latency_rows counts source
 * rectangle rows. A tiling is not written in place: a tile's halo reads its
 * neighbours' source; the frame and band calls, and the row calls without
 * BLOOM_FLAG_COPY_SOURCE, refuse a destination over the source (BLOOM_E_ALIAS). */
bloom_status_t bloom_begin(bloom_t *b);
bloom_status_t bloom_push_row(bloom_t *b, const void *src_row);
/* The same with the aux plane's row (presets that read one). */
bloom_status_t bloom_push_row_aux(bloom_t *b, const void *src_row, const void *aux_row);
/* The aux plane for bloom_run_rows/bloom_process: its row 0 and stride. */
bloom_status_t bloom_set_aux(bloom_t *b, const void *aux, ptrdiff_t aux_stride);
bloom_status_t bloom_pull_row(bloom_t *b, void *dst_row);
/* Source rows pushed and output rows pulled in this frame (BLOOM_E_NULL
 * for a NULL handle). */
int bloom_rows_in(const bloom_t *b);
int bloom_rows_out(const bloom_t *b);

/* Band interface: push source rows rows_in .. rows_in + nrows - 1 (src is
 * the frame's row 0, src_stride bytes apart) and write every output row that
 * becomes ready to dst (frame row 0, dst_stride bytes apart). With a tile,
 * rows are counted from the source rectangle's first row (info.src_y), and
 * src and dst are still the frames' row 0. */
bloom_status_t bloom_run_rows(bloom_t *b, const void *src, ptrdiff_t src_stride, int nrows, void *dst,
                              ptrdiff_t dst_stride);

/* Whole frame (with a tile: the tile of the frame): bloom_begin +
 * bloom_run_rows(all source rows) + drain. The destination is defined when
 * it returns: out of place, a dark source row may be copied to its
 * destination row when it is read and written again at its turn if it gets
 * bloom (bloom_run_rows writes no row before its turn). */
bloom_status_t bloom_process(bloom_t *b, const void *src, ptrdiff_t src_stride, void *dst,
                             ptrdiff_t dst_stride);

/* Bytes per pixel of a format (0 if unknown or compiled out). */
int bloom_format_bpp(bloom_format_t fmt);

/* What a status means, for messages: "threshold above 256.0", ... */
const char *bloom_status_str(bloom_status_t st);

/* Static workspace: an upper bound of bloom_workspace_size() usable in a
 * constant expression (tests check it against the exact size over a grid of
 * sizes and depths) for the default preset without a tile (a tile may add an
 * output row; the other presets need their own bytes: ask
 * bloom_workspace_size). src_bpp is the input bytes per pixel, copy 1 with
 * BLOOM_FLAG_COPY_SOURCE. Rows held per level (sim/docs/streaming.md): 12 at
 * level 1, 8 at level 2, at most 2^(L-k+2) at level k >= 3, of w/2^k + 1 pixels of
 * 12 bytes, plus one zero row of w/2 pixels; that sums to below
 * w*(2^L + 100) + 12*2^L; the source ring holds fewer than 4*2^L + 8 rows
 * (pointers, or copies). With the static schedule (BLOOM_SCHED_TABLE, all
 * but the size build) each ring slot's row pointer and tag are kept twice
 * over (under 64*2^L more bytes), each node input has its gather (under
 * 96 more bytes a level) and its table takes a byte per row made and two
 * per source row (under 6*h), folded to the start-up, one period of 2^L
 * source rows and the end where L <= 6 (under 6*8*2^L: at most 28.5*2^L
 * bytes over widths 1 .. 4000, heights 1 .. 16384 and L = 1 .. 6); with
 * src_bpp 3 or 4 (RGB888, XRGB8888) the level-1 box keeps a row's sums
 * for the next, 16 bytes per column pair (under 8*w + 40: at most
 * (w + 3)/2 pairs, two arrays rounded up to 8 bytes). Computed in unsigned
 * long long: a configuration too big for the target's address space fails
 * to compile as a static
 * array instead of wrapping around. */
#define BLOOM_WORKSPACE_MAX(w, h, levels, src_bpp, copy)                                                     \
    BLOOM_WORKSPACE_MAX_S(w, h, levels, src_bpp, copy, 32)
/* The same for a sample width (cfg.sample_bits, 32 or 16). With 16 the
 * rows of levels 1 and 2 are half as wide in bytes (48 w fewer) and one
 * 32-bit scratch row of level 1 is added (6 w + 76 more): 100 w becomes
 * 70 w, which holds for BLOOM_S16_LEVELS 1 as well (30 w fewer). */
#define BLOOM_WORKSPACE_MAX_S(w, h, levels, src_bpp, copy, sample_bits)                                      \
    (3072ull + (unsigned long long)(w) * ((1ull << (levels)) + ((sample_bits) == 16 ? 70u : 100u)) +         \
     ((BLOOM_SCHED_TABLE ? 128ull : 64ull) << (levels)) +                                                    \
     (BLOOM_SCHED_TABLE ? 160ull : 64ull) * (unsigned long long)(levels) +                                   \
     (BLOOM_SCHED_TABLE                                                                                      \
          ? 6ull * ((levels) <= 6 && (8ull << (levels)) < (unsigned long long)(h) ? (8ull << (levels))       \
                                                                                  : (unsigned long long)(h)) \
          : 0ull) +                                                                                          \
     (BLOOM_SCHED_TABLE && ((src_bpp) == 3 || (src_bpp) == 4) ? 8ull * (unsigned long long)(w) + 40ull       \
                                                              : 0ull) +                                      \
     ((copy) ? ((4ull << (levels)) + 8u) * (unsigned long long)(w) * (unsigned long long)(src_bpp) : 0ull))
#define BLOOM_WORKSPACE_DEFINE(name, bytes) static uint64_t name[((bytes) + 7u) / 8u]

#ifdef __cplusplus
}
#endif
#endif
