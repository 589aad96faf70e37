/* Shared state of the benchmark (bench.c measures, bench_out.c writes the
 * CSV and the Markdown). */
#ifndef BENCH_H
#define BENCH_H

#include <stddef.h>
#include <stdint.h>

/* The compiler and flags of the engine build, for the report (bench.mk). */
#ifndef BENCH_CC
#define BENCH_CC "cc"
#endif
#ifndef BENCH_FLAGS
#define BENCH_FLAGS "(unknown)"
#endif

#define MAX_SIZES 8
#define MAX_ROWS 256
#define SLOW_RUN_S 0.25 /* a warm-up slower than this: SLOW_RUNS runs */
#define SLOW_RUNS 5

typedef struct {
    int w, h;
    const char *group; /* floor, engine, opencv, model */
    char name[96];
    int threads;
    int runs;
    double median_ms, min_ms;
    double cpu_ms;               /* median process CPU time (every thread) per run */
    double x_memcpy, x_engine;   /* wall-time ratios */
    double xc_memcpy, xc_engine; /* CPU-time ratios, single-threaded rows; -1 otherwise */
    int agree_max;               /* -1: not compared */
    double agree_exact;
    /* engine - this row, per byte: mean, and the bytes with engine > this
     * row, engine < this row (a bias hides in the two figures above) */
    double agree_signed;
    long long agree_above, agree_below;
    char note[96];
} row_t;

typedef struct {
    const char *image;
    int runs, warm;
    int model_w[MAX_SIZES], model_h[MAX_SIZES], n_model;
} opts_t;

typedef struct {
    double active_src_pct;  /* source pixels whose max channel passes the knee's lower edge */
    double changed_out_pct; /* output bytes of the engine that differ from the input */
    int levels;
} size_info_t;

extern row_t rows[MAX_ROWS];
extern int nrows;
extern size_info_t size_info[MAX_SIZES];
extern int opencv_threads_default;
extern char cpu_model[160];
extern int ncpu;
extern size_t llc_sysfs, llc_sysconf;
extern int llc_level;
extern char date_utc[64];
extern double load_start, load_end;

/* The measuring machinery (bench_time.c): the cold frame rings, timed runs
 * (median and minimum, CPU time beside), paired rounds against the floor
 * and the engine reference. */
typedef struct {
    uint8_t *src, *dst;
    size_t bytes, slot;
    int nslots, next;
    int filled_fmt;     /* format the input slots hold, 0 = none */
    size_t filled_size; /* w*h it was filled for */
} ring_t;

typedef int (*run_fn)(void *ctx, const uint8_t *src, uint8_t *dst);

typedef struct {
    const char *name;
    run_fn fn;
    void *ctx;
} contender_t;
#define MAX_CONTENDERS 8

void ring_alloc(ring_t *r, size_t bytes);
void ring_prepare(ring_t *r, const uint8_t *frame, size_t frame_bytes, size_t slot_bytes, int fmt, size_t wh);
double median(double *v, int n); /* sorts v */
double cpu_s(void);              /* CPU time of the whole process, every thread */
int measure(ring_t *r, run_fn fn, void *ctx, int warm, int runs, row_t *row);
void paired(ring_t *r, const contender_t *c, int nc, int rounds, int w, int h);
void *xmalloc(size_t n); /* malloc or die (bench.c) */
row_t *new_row(int w, int h, const char *group, const char *name);

void die(const char *fmt, const char *arg);
const char *bench_cv_row_name(int i); /* the OpenCV variants, in table order */
double loadavg1(void);
void bench_read_machine(void); /* fills cpu_model, ncpu, llc_* (bench_machine.c) */
void write_csv(const char *path);
void write_md(const char *path, const int *sw, const int *sh, int nsizes, const opts_t *o, size_t ring_bytes,
              const char *cv_version, const char *cv_parallel);

#endif
