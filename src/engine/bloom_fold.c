/* The period search of the static schedule (bloom_fold.h): the first dry
 * run hashes the table's bytes push by push and keeps the longest run of
 * repeats; bloom_sched.c writes the folded table in the second. Only
 * bloom_init runs it (no frame does). */
#include "bloom_fold.h"

#if BLOOM_SCHED_TABLE
/* The run that ends before chunk y (exclusive): the fold it gives, kept if
 * it saves the most. */
static void fold_run_end(struct bloom_fold_scan *f, int y)
{
    if (f->run < 0)
        return;
    const int m = (y - (f->run - f->P)) / f->P; /* whole blocks from the block's start */
    if (m > 1 && (m - 1) * f->run_len > f->best) {
        f->best = (m - 1) * f->run_len;
        f->fb = f->run_b;
        f->fe = f->run_b + f->run_len;
        f->fm = m;
    }
    f->run = -1;
}

/* Chunk f->y is complete (the next push, or the end): compare it with the
 * chunk P before it, whose slot it then takes. */
static void fold_chunk_end(bloom_t *g, struct bloom_fold_scan *f)
{
    const int y = f->y, k = y % f->P, len = g->dry_n - f->off;
    if (y >= 0) {
        if (len > 0xFFFF) { /* (never, at L <= 6: the search stops, no fold) */
            f->P = 0;
            return;
        }
        const bool same = y >= f->P && f->hash[k] == f->h && f->len[k] == len;
        if (same && f->run < 0) { /* the last P chunks are the block */
            f->run = y;
            f->run_b = f->off - f->wsum;
            f->run_len = f->wsum;
        } else if (!same) {
            fold_run_end(f, y);
        }
        f->wsum += len - (y >= f->P ? f->len[k] : 0);
        f->hash[k] = f->h;
        f->len[k] = (uint16_t)len;
    }
    f->y = y + 1;
    f->off = g->dry_n;
    f->h = 0xcbf29ce484222325ull;
}
void bloom_fold_start(bloom_t *g, struct bloom_fold_scan *f)
{
    f->P = g->gr.L >= 0 && (1 << g->gr.L) <= FOLD_MAX_P ? 1 << g->gr.L : 0;
    f->wsum = 0;
    f->y = -1;
    f->off = 0;
    f->h = 0;
    f->run = -1;
    f->best = 0;
    f->fb = f->fe = 0;
    f->fm = 1;
    g->fold_b = g->fold_e = 0;
    g->fold_m = 1;
    g->scan = f->P ? f : NULL;
}

void bloom_fold_byte(bloom_t *g, int byte)
{
    struct bloom_fold_scan *f = g->scan;
    if (!f->P)
        return;
    if (byte == BG_S_PUSH)
        fold_chunk_end(g, f);
    f->h = (f->h ^ (uint8_t)byte) * 0x100000001b3ull;
}

void bloom_fold_finish(bloom_t *g)
{
    struct bloom_fold_scan *f = g->scan;
    if (f->P)
        fold_chunk_end(g, f);
    if (f->P) /* (the last chunk may have stopped the search) */
        fold_run_end(f, f->y);
    g->fold_b = f->fb;
    g->fold_e = f->fe;
    g->fold_m = f->fm;
    /* the bytes counted were the unfolded table's */
    g->sched_len -= (g->fold_m - 1) * (g->fold_e - g->fold_b);
    g->scan = NULL;
}
#else
typedef int bloom_fold_unused; /* (ISO C: no empty translation unit) */
#endif
