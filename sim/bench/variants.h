/* The engine rows of the benchmark and of the instruction counts: one table,
 * so that a new preset, pixel format or SIMD on/off switch is one more line
 * in variants.c and shows up in `make bench` and `make icount` alike. */
#ifndef BENCH_VARIANTS_H
#define BENCH_VARIANTS_H

#include <stdint.h>

#include "bloom.h"

/* Scene parameters: bloom_config_default's (soft knee 0.5, intensity 1.0,
 * 5 levels) except the threshold, lowered from 1.0 so that the bloom is
 * active on the scene's lamps and sky, not only on clipped pixels. */
#define BENCH_THRESHOLD 0.6

typedef struct {
    const char *name; /* row label and icount key, no spaces */
    bloom_format_t in_fmt, out_fmt;
    uint32_t flags; /* BLOOM_FLAG_* added to the defaults */
    /* Extension point for presets and SIMD switches: called after the
     * defaults are in cfg and before bloom_init; may change cfg or a
     * process-wide switch. Returns 0, or -1 to skip the row (feature not
     * built or not supported by this CPU). NULL: nothing to do. */
    int (*setup)(bloom_config_t *cfg);
    /* Undoes what setup changed outside cfg. NULL: nothing to do. */
    void (*teardown)(void);
} bench_engine_t;

extern const bench_engine_t bench_engines[];
extern const int bench_engine_count;

/* Fills cfg for row e at w x h. Returns 0, or -1 if the row is skipped. */
int bench_engine_config(const bench_engine_t *e, int w, int h, bloom_config_t *cfg);
/* After bloom_init: gives an engine whose preset reads an aux plane a
 * synthetic one (a horizontal depth ramp: near at the left; no mask
 * effect for arm, which has none by default). Returns 0 or -1. */
int bench_engine_attach(bloom_t *b, const bloom_config_t *cfg);

#endif
