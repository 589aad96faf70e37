/* bloom_sim: shared declarations of the simulator's modules.
 *
 *   sim_source.c   input files: format detection, PPM/PGM/PFM (imgio), Y4M, raw dumps
 *   sim_png.c      PNG read/write (libpng)       sim_jpeg.c  JPEG read (libjpeg)
 *   sim_exr.c      OpenEXR read (OpenEXRCore)    sim_convert.c  pixel rules
 *   sim_aux.c      --aux: the one-channel plane of the presets (depth, mask, map)
 *   sim_out.c      output files: patterns, temp files, PPM/PNG/PFM/Y4M writers
 *   bloom_sim.c    options, the frame loop, statistics, progress
 *
 * The rules (how each input becomes engine input, how outputs are shown)
 * are in sim/docs/simulator.md. Every function that can fail returns -1 and
 * writes a message into err (size errlen). */
#ifndef BLOOM_SIM_H
#define BLOOM_SIM_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "bloom.h"
#include "imgio.h"

#if defined(__GNUC__)
#define SIM_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define SIM_PRINTF(a, b)
#endif

#define SIM_ERRLEN 1024

/* Writes a formatted message into err; returns -1. */
int sim_errf(char *err, size_t errlen, const char *fmt, ...) SIM_PRINTF(3, 4);

/* ---- frames ------------------------------------------------------------
 * A decoded frame in the reference model's input representation: 3 words
 * per pixel (R, G, B), row-major; each word is a code of max[c] (255 for
 * 8-bit sources, 31/63/31 for RGB565 dumps), with max[c] == 0 a linear
 * Q16.16 value (16-bit sources), or with max[c] == SIM_F32 the bits of a
 * linear float (PFM, OpenEXR: given to the engine as RGBF32 unless another
 * input format is asked for). */
#define SIM_F32 0xFFFFFFFFu
typedef struct {
    int w, h;
    int max[3];
    uint32_t *px;
} sim_frame_t;

int sim_frame_alloc(sim_frame_t *f, int w, int h); /* px zeroed; -1 out of memory */
void sim_frame_free(sim_frame_t *f);

/* ---- what a header may cost ---------------------------------------------
 * A header is refused as soon as it declares more than BLOOM_MAX_DIM per
 * side, and no reader allocates the frame a header declares before the
 * data is there to back it: sizes are checked against the file where that
 * can be known, else the samples grow with the data that arrives. */
/* Bytes from f's position to its end (a regular file or a seekable
 * stream), -1 when that cannot be known (a pipe). */
long long sim_stream_left(FILE *f);
/* The rest of f copied into an unnamed temporary file, rewound (the
 * caller closes it): how a reader that must look ahead or know the size
 * reads a pipe. NULL with a message in err on failure. */
FILE *sim_spool(FILE *f, char *err, size_t errlen);
/* Room for rows 0 .. rows-1 of img's samples (width, height, channels and
 * maxval set; u16, or f32 when maxval is 0), grown by doubling up to
 * height; *cap holds the rows allocated (0 at first). -1 out of memory. */
int sim_img_rows(img_t *img, int rows, int *cap);

/* ---- inputs ------------------------------------------------------------ */
typedef enum {
    SIM_RAW_NONE = 0,
    SIM_RAW_YUYV,
    SIM_RAW_RGB24,
    SIM_RAW_GREY,
    SIM_RAW_RGB565,
    SIM_RAW_UYVY,
    SIM_RAW_YVYU,
    SIM_RAW_NV12,
    SIM_RAW_NV21,
    SIM_RAW_NV16,
    SIM_RAW_NV61
} sim_raw_fmt_t;
/* sim_ycbcr_to_rgb's rule: these bits or'ed (0: BT.601 limited range) */
enum { SIM_YCC_FULL = 1, SIM_YCC_709 = 2 };

typedef struct {
    sim_raw_fmt_t raw_fmt; /* SIM_RAW_NONE: detect the format from the content */
    int raw_w, raw_h;
    long raw_stride;   /* bytes per row of a raw dump; 0 = packed */
    int raw_ycc;       /* --raw-ycbcr: SIM_YCC_* of a Y'CbCr dump */
    int decode16_srgb; /* 16-bit PPM/PGM/PNG: 0 linear light, 1 sRGB-encoded */
} sim_input_opts_t;

typedef struct sim_source sim_source_t;

/* Opens path ("-" = standard input: Y4M or raw only) and checks what can
 * be checked before any frame is processed: the header, and for regular
 * Y4M and raw files every frame header and the exact file size. */
int sim_source_open(sim_source_t **out, const char *path, const sim_input_opts_t *o, char *err,
                    size_t errlen);
long sim_source_frames(const sim_source_t *s);                 /* -1 when unknown (a pipe) */
int sim_source_fps(const sim_source_t *s, int *num, int *den); /* 0 if the input has a rate */
const char *sim_source_desc(const sim_source_t *s);            /* "Y4M 4:2:0 (C420jpeg), limited range" */
/* Reads the next frame into f (allocated or reused here). Returns 1 with a
 * frame, 0 at the end, -1 on error ("path: frame N: what is wrong"). */
int sim_source_read(sim_source_t *s, sim_frame_t *f, char *err, size_t errlen);
void sim_source_close(sim_source_t *s);

/* Single-image decoders into imgio's img_t (u16 with maxval 255 or 65535,
 * or f32 with maxval 0; channels 1 or 3). err gets only "what is wrong";
 * the caller names the file and frame. */
int sim_png_read(FILE *f, img_t *img, char *err, size_t errlen);
int sim_jpeg_read(FILE *f, img_t *img, char *err, size_t errlen);
int sim_exr_read(const char *path, img_t *img, char *err, size_t errlen);
int sim_exr_available(void); /* 0 when built without OpenEXR */

/* ---- pixel rules (sim_convert.c) ------------------------------------- */
/* img_t -> frame: 8-bit codes (maxval < 255 rescaled to 255), 16-bit codes
 * (linear light, or sRGB with decode16_srgb) and floats (img_float_to_q16)
 * to linear Q16.16; one channel is replicated to R, G, B. */
int sim_frame_from_img(const img_t *im, int decode16_srgb, sim_frame_t *f);

/* Y'CbCr to R'G'B' codes: how is SIM_YCC_* or'ed, 0 limited-range BT.601,
 * SIM_YCC_FULL full range, SIM_YCC_709 the BT.709 matrix. */
void sim_ycbcr_to_rgb(int y, int cb, int cr, int how, uint32_t rgb[3]);
/* 8-bit RGB (w*h*3) to planar 4:2:0 limited-range BT.601 Y'CbCr: a w*h Y
 * plane then Cb and Cr planes of ceil(w/2)*ceil(h/2), each chroma sample the
 * average over its (up to) 2x2 block. */
void sim_rgb8_to_yuv420(const uint8_t *rgb, int w, int h, uint8_t *out);

int sim_fmt_parse(const char *s, bloom_format_t *fmt);
const char *sim_fmt_name(bloom_format_t fmt);
void sim_fmt_max(bloom_format_t fmt, int max[3]); /* code range of a format; 0 = Q16.16 */

/* Frame -> engine input buffer in fmt (packed rows, bloom_format_bpp(fmt)). */
void sim_to_engine(const sim_frame_t *f, bloom_format_t fmt, int linear, uint8_t *buf);
/* Engine buffer -> codes in the frame representation (max from sim_fmt_max). */
void sim_from_engine(const uint8_t *buf, bloom_format_t fmt, size_t npix, uint32_t *codes);
/* Codes of range max -> 8-bit display RGB (Q16.16 is sRGB-encoded, or
 * linear with linear != 0, clipped at 1.0). */
void sim_codes_to_rgb8(const uint32_t *codes, const int max[3], size_t npix, int linear, uint8_t *rgb);
/* Codes -> linear light floats (for PFM output). */
void sim_codes_to_float(const uint32_t *codes, const int max[3], size_t npix, int linear, float *out);

/* ---- the aux plane (sim_aux.c) ------------------------------------------
 * A grey PGM/PNG read once for every frame: 8-bit (BLOOM_AUX_U8) or 16-bit
 * (BLOOM_AUX_U16); other maxvals are rescaled to 255 or 65535. */
typedef struct {
    int w, h;
    bloom_aux_format_t fmt;
    int max;         /* 255 or 65535 */
    uint8_t *data;   /* the engine's plane: w bytes (U8) or w native uint16 (U16) per row */
    uint32_t *codes; /* the same codes for the model, w*h */
    char desc[64];   /* "PGM 64x48 8-bit grey" */
} sim_aux_t;

/* Errors name the file: "depth.png: --aux: an RGB image; ...". */
int sim_aux_load(sim_aux_t *a, const char *path, char *err, size_t errlen);
void sim_aux_free(sim_aux_t *a);

/* ---- options (sim_opts.c) ---------------------------------------------- */
/* The engine and preset options given on the command line (set: SIM_SET_*
 * bits), applied over the preset's defaults for each frame size. */
typedef struct {
    unsigned set;
    int preset;       /* -1: not given (unity) */
    bloom_config_t v; /* the values given */
    int nweights;     /* --weights: level_weight[0 .. nweights-1] */
    long radius;      /* --radius */
    uint32_t flags;   /* --linear, --copy-source, --view bloom */
} sim_given_t;

typedef struct {
    const char **inputs;
    int ninputs;
    sim_input_opts_t in;
    const char *out_pattern, *sbs_pattern; /* NULL: not written */
    int view_bloom;                        /* --view bloom */
    int diff_gain;                         /* side-by-side difference amplification */
    int fps_num, fps_den;                  /* Y4M output rate when the input has none */
    bloom_config_t cfg;                    /* preset with its defaults, then the options
                                              given: levels, threshold, knee, intensity,
                                              flags, preset parameters (aux_fmt: the
                                              preset's until --aux is loaded) */
    const char *aux_path;                  /* --aux FILE, or NULL */
    sim_given_t given;                     /* what cfg was built from */
    int in_fmt_set, out_fmt_set;
    bloom_format_t in_fmt, out_fmt;
    int compare, bittrue;
    long max_frames;       /* 0: all */
    int repeat;            /* engine runs per frame (best time) */
    int threads;           /* --threads N: strips on a pool (port/threads); 1 = one engine */
    int quiet;             /* no per-frame lines */
    double progress_after; /* seconds before a progress line appears */
} sim_opts_t;

/* The --help text, with the presets this build has (sim_usage.c). */
void sim_usage(FILE *f);
/* Parses argv into o. Returns 0 to run, 1 when --help was printed (exit
 * 0), -1 after printing a usage error to stderr (exit 2). */
int sim_opts_parse(int argc, char **argv, sim_opts_t *o);
/* The engine configuration for a w x h frame: the preset's defaults for
 * that size (bloom_config_preset: some depend on it, e.g. cod's level
 * weights), then the options given; aux_fmt and formats as in o->cfg.
 * Returns 0, or -1 with a message in err. */
int sim_opts_config(const sim_opts_t *o, int w, int h, bloom_config_t *c, char *err, size_t errlen);
/* "unity, attenuation": the presets this build carries. */
const char *sim_presets_available(void);
/* What the preset's aux plane is ("depth plane", "mask", ...); NULL when it reads none. */
const char *sim_preset_aux_name(const bloom_config_t *c);

/* ---- outputs (sim_out.c) ---------------------------------------------- */
typedef enum { SIM_OUT_PPM, SIM_OUT_PNG, SIM_OUT_PFM, SIM_OUT_Y4M } sim_out_kind_t;
typedef struct sim_out sim_out_t;

/* pattern: "name%04d.png" (one %d conversion, optional 0 flag and width;
 * %% for a literal %), a plain file name (one frame only), or "x.y4m" (one
 * stream). The kind follows the extension: .ppm .png .pfm .y4m. */
int sim_out_open(sim_out_t **out, const char *pattern, int fps_num, int fps_den, char *err, size_t errlen);
sim_out_kind_t sim_out_kind(const sim_out_t *o);
int sim_out_has_number(const sim_out_t *o); /* pattern has a %d (or is a stream) */
/* Writes frame n: rgb (w*h*3 bytes) for PPM/PNG/Y4M, lin (w*h*3 floats) for PFM. */
int sim_out_write(sim_out_t *o, long n, int w, int h, const uint8_t *rgb, const float *lin, char *err,
                  size_t errlen);
/* Commits a Y4M stream (rename over the target); per-frame files are
 * already in place. Frees o. */
int sim_out_finish(sim_out_t *o, char *err, size_t errlen);
void sim_out_abort(sim_out_t *o); /* removes an uncommitted temp file; frees o */
const char *sim_out_pattern(const sim_out_t *o);
long sim_out_count(const sim_out_t *o); /* frames written */

/* Temp file beside path ("path.tmp-XXXXXX"); commit renames it over path
 * when ok, else removes it. The temp file is also removed if the process
 * is stopped by SIGINT, SIGTERM, SIGHUP or SIGPIPE. */
FILE *sim_tmp_open(const char *path, char **tmp, char *err, size_t errlen);
int sim_tmp_commit(FILE *f, char *tmp, const char *path, int ok, char *err, size_t errlen);

/* PNG writer: 8-bit RGB rows to f. */
int sim_png_write_rgb8(FILE *f, const uint8_t *rgb, int w, int h, char *err, size_t errlen);

#endif
