/* The bloom_sim test groups and what they share (tests/sim/simtest*.c).
 * harness.h keeps its counters per file: each group file reports its own
 * through *_counts, and main adds them up. */
#ifndef BLOOM_SIMTEST_CASES_H
#define BLOOM_SIMTEST_CASES_H

#include "simtest.h"

extern st_run_t R;       /* the last run */
extern const char *tool; /* the bloom_sim under test */

#define ARGS(...) ((const char *const[]){__VA_ARGS__, NULL})
#define RUN(in, ...) st_run(&R, tool, in, ARGS(__VA_ARGS__))

void make_scene(uint8_t *rgb, int w, int h, uint32_t seed);
int write_ppm8(const char *path, const uint8_t *px, int w, int h, int channels);
int output_matches_engine(const char *path, const bloom_config_t *c, const void *src);

void test_images(void); /* simtest_formats.c */
void test_video(void);
void test_compare(void);
void simtest_formats_counts(int *pass, int *fail);
void test_cli(void); /* simtest_errors.c */
void test_errors(void);
void simtest_errors_counts(int *pass, int *fail);
void test_presets(void); /* simtest_presets.c */
void simtest_presets_counts(int *pass, int *fail);

#endif
