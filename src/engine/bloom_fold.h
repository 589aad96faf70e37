/* The period search of the static schedule's first dry run (engine/,
 * bloom_fold.c; bloom_sched.c's bloom_dry_frame drives it). The bytes
 * from one BG_S_PUSH to the next are a chunk; once the pyramid has filled,
 * chunk y equals chunk y - P (P = 2^L pushes, a row of the deepest level).
 * Each chunk's length and 64-bit FNV-1a hash are kept for P chunks; the
 * longest run of chunks equal to the chunk P before them is the fold: the
 * block of P chunks before the run is written once and walked as many
 * times as it fits in the run. The hash only proposes it: the second dry
 * run compares every byte of the repeats with the block (a mismatch fails
 * bloom_init, never a frame). It lives on bloom_init's stack: 640 bytes at
 * most, below what a frame call takes (port/mcu/FIGURES.md), hence
 * P <= 64. */
#ifndef BLOOM_FOLD_H
#define BLOOM_FOLD_H

#include "bloom_engine.h"

#if BLOOM_SCHED_TABLE
#define FOLD_MAX_P 64 /* L <= 6 (deeper pyramids are not folded) */
struct bloom_fold_scan {
    int P, y;       /* the period in chunks (0: no search); the chunk being hashed */
    int off;        /* its first byte */
    uint64_t h;     /* its hash so far */
    int wsum;       /* the bytes of the last P chunks */
    int run, run_b; /* the run of repeated chunks: its first chunk (-1: none), the block's first byte */
    int run_len;    /* the block's bytes */
    int best;       /* bytes the best fold saves */
    int fb, fe, fm; /* that fold (bloom_t's fold_b, fold_e, fold_m at the end) */
    uint64_t hash[FOLD_MAX_P];
    uint16_t len[FOLD_MAX_P];
};

/* Start the search (P from the graph's depth: 0, no search, past
 * FOLD_MAX_P pushes); g->scan then points at f, and no fold is set. */
void bloom_fold_start(bloom_t *g, struct bloom_fold_scan *f);
/* One byte of the unfolded table, in the order written. */
void bloom_fold_byte(bloom_t *g, int byte);
/* The end of the table: the best fold into g->fold_b, fold_e, fold_m, the
 * table's length counted folded; g->scan back to NULL. */
void bloom_fold_finish(bloom_t *g);
#endif

#endif
