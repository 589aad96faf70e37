/* Shared by the `make report` tools (sim/report/): test inputs at any size,
 * error statistics against the float model, the cold-frame ring and its
 * interleaved timer. Host-only code (heap, stdio, POSIX clocks). */
#ifndef REPORT_H
#define REPORT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "bloom.h"
#include "scene.h" /* scene_parse_sizes */

/* ---- inputs (inputs.c) --------------------------------------------------- */

typedef struct {
    char name[32];
    int w, h;
    bloom_format_t fmt;   /* RGB888 or RGBQ16 */
    size_t stride, bytes; /* packed rows */
    uint8_t *p;           /* the frame in fmt */
    uint32_t *codes;      /* w*h*3 model input: 8-bit codes or Q16.16 words */
    int src_max;          /* 255, or 0 for Q16.16 words (bloom_model_run) */
} rin_t;

/* Builds input `name` at w x h:
 *   rocket, hubble          tests/data PPM, nearest-neighbour to w x h, RGB888
 *   studio, hall            tests/data PFM, nearest-neighbour, img_float_to_q16, RGBQ16
 *   scene                   sim/bench/scene.c on rocket (bilinear + 24 lights)
 *   scene-hubble            the same 24 lights on the Hubble deep field
 *   dark                    rocket at 0.7x its codes: nothing reaches the knee
 *   sparse                  dark plus one white disc of radius 0.5 % of the width
 *   grid                    dark plus a white disc in every 64x64 cell
 *                           (no row band is free of light)
 *   point, hdr-point        black with a 3x3 block in the centre at 1.0
 *                           (RGB888 255) or 255.99998 (RGBQ16 2^24 - 1)
 * Returns 0, or -1 with a message in err. */
int rin_make(rin_t *f, const char *name, const char *data_dir, int w, int h, char *err, size_t errlen);
/* An RGBQ16 frame from words (w*h*3), taken over. */
int rin_from_words(rin_t *f, const char *name, int w, int h, uint32_t *words);
void rin_free(rin_t *f);
/* Nearest-neighbour source index of destination x in 0..n-1 from s samples. */
int rin_nn(int x, int n, int s);

/* ---- engine and model ----------------------------------------------------- */

/* Whole frame through a fresh engine (heap workspace). Returns the status. */
bloom_status_t rengine_run(const bloom_config_t *c, const void *src, size_t src_stride, void *dst,
                           size_t dst_stride);
/* Float model of config c on codes (src_max as bloom_model_run), output codes
 * of dst_max (255, or 0 = Q16.16 words) into out (w*h*3). Returns L or -1. */
int rmodel_run(const bloom_config_t *c, const uint32_t *codes, int src_max, uint32_t *out, int dst_max);

/* ---- error statistics ----------------------------------------------------- */

/* eng - ref per sample. The signed sum and the counts above (eng > ref)
 * and below (eng < ref) are kept beside the absolute one: a bias hides in
 * a mean of absolute errors. */
typedef struct {
    long long n, exact, peak;
    long long above, below;     /* samples with eng > ref, eng < ref */
    long long sat_eng, sat_ref; /* samples at the top code */
    double sum_abs, sum_sq, sum_signed;
    double peak_rel;     /* largest |eng - ref| / ref over ref >= rel_floor */
    long long rel_floor; /* set before adding; 0 counts as 1 */
} rstat_t;

void rstat_add(rstat_t *s, long long eng, long long ref, long long top);
void rstat_merge(rstat_t *into, const rstat_t *s);
double rstat_mean(const rstat_t *s);        /* mean |eng - ref| */
double rstat_signed_mean(const rstat_t *s); /* mean (eng - ref) */
double rstat_mse(const rstat_t *s);
double rstat_exact(const rstat_t *s); /* percent */
double rstat_psnr(const rstat_t *s);  /* dB for 8-bit codes; INFINITY when exact */
/* "inf" or "%.2f" of a PSNR. */
const char *rpsnr_str(double psnr, char *buf, size_t n);

/* ---- timing ----------------------------------------------------------------- */

double rnow_wall(void);
double rnow_cpu(void); /* this thread's CPU time */
double rmedian(double *v, int n);

/* Input and output rings of `bytes` each, page-aligned slots: every run
 * takes the next slot, so its frames were last touched a ring ago. */
typedef struct {
    uint8_t *src, *dst;
    size_t bytes, slot;
    int nslots, next;
} rring_t;

int rring_init(rring_t *r, size_t bytes);
/* Slots of slot_bytes (page-rounded); every input slot gets frame. */
int rring_fill(rring_t *r, const void *frame, size_t frame_bytes, size_t slot_bytes);
void rring_free(rring_t *r);

typedef int (*rrun_fn)(void *ctx, const uint8_t *src, uint8_t *dst);

typedef struct {
    rrun_fn fn;
    void *ctx;
    int inplace;             /* dst = src slot */
    double wall_ms, cpu_ms;  /* medians */
    const uint8_t *last_dst; /* output of the last run */
} rtimer_t;

/* `warm` + `runs` rounds; a round runs every timer once, each on its own
 * next slot, so the timers see the same machine state (load, clocks)
 * and their ratios are measured in the same run. Returns 0 or the first
 * non-zero result of a run. */
int rtime_rounds(rring_t *r, rtimer_t *t, int k, int warm, int runs);

/* memcpy of ctx's size_t bytes: the floor. */
int rrun_memcpy(void *ctx, const uint8_t *src, uint8_t *dst);

typedef struct {
    bloom_t *b;
    ptrdiff_t in_stride, out_stride;
} rengine_ctx_t;
int rrun_engine(void *ctx, const uint8_t *src, uint8_t *dst);

/* ---- misc -------------------------------------------------------------------- */

void rdie(const char *fmt, ...);
void *rxmalloc(size_t n);
/* "WxH,WxH,..." into w/h (at most max). Returns the count or -1. */
/* Writes through path.tmp and renames on close. */
FILE *ropen(const char *path, char *tmp, size_t tmplen);
void rclose(FILE *f, const char *tmp, const char *path);

#endif
