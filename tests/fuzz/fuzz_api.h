/* fuzz_api's configurations (fuzz_api_config.c): made from the input,
 * checked against what bloom_query takes, and the calls that take no
 * engine. */
#ifndef FUZZ_API_H
#define FUZZ_API_H

#include "fuzz.h"

#include "bloom.h"

#define MAXW 64 /* largest side of a frame */

/* Fills c; returns 1 when it is a preset's defaults at a valid size,
 * formats and depth, untouched since (bloom_query must take it). */
int fz_api_make_config(fz_in_t *in, bloom_config_t *c);
/* A configuration bloom_query took: every documented range holds, for the
 * common fields and for the parameters its preset reads. */
void fz_api_check_taken(const bloom_config_t *c, const bloom_info_t *info);
/* The calls that take no engine: names, presets, statuses, formats. */
void fz_api_check_pure(fz_in_t *in);

#endif
