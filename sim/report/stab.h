/* The stability matrix (report_stab): shared between its driver (stab.c)
 * and its case tables (stab_cases.c). */
#ifndef REPORT_STAB_H
#define REPORT_STAB_H

#include <stdio.h>

#include "report.h"

extern const char *stab_data_dir, *stab_out_dir;

typedef struct {
    bloom_status_t st;
    int built;   /* L */
    rstat_t s;   /* against the model on the input as the engine sees it */
    rstat_t raw; /* against the model on unclamped words (has_raw) */
    int has_raw;
    long long changed; /* output samples that differ from the input; -1: not comparable */
} res_t;

/* Engine and float model on in with config c; with_raw: also the model on
 * the words as given (RGBQ16 words above 2^24 - 1 unclamped). */
res_t stab_run(const rin_t *in, const bloom_config_t *c, int with_raw);
/* One row of the CSV and of the current Markdown table. */
void stab_emit(const char *section, const char *cas, const rin_t *in, const bloom_config_t *c,
               const char *levels, const res_t *r, const char *note);
/* A Markdown table header with a title and an introduction. */
void stab_table(const char *title, const char *intro);
void stab_config(bloom_config_t *c, const rin_t *in, int levels, double t, double k, double i,
                 bloom_format_t out);
void stab_input(rin_t *in, const char *name, int w, int h);

/* The sections (stab_cases.c), in report order. */
void stab_params(FILE *md);
void stab_hdr(FILE *md);
void stab_float(FILE *md);
void stab_shapes(FILE *md);
void stab_stress(FILE *md);

#endif
