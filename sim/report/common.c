/* Engine and model wrappers, error statistics, the cold ring and its timer
 * (report.h). */
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bloom_model.h"
#include "report.h"
#include "timing.h"

void rdie(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "report: ");
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\n");
    va_end(ap);
    exit(1);
}

void *rxmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p)
        rdie("out of memory (%zu bytes)", n);
    return p;
}

bloom_status_t rengine_run(const bloom_config_t *c, const void *src, size_t src_stride, void *dst,
                           size_t dst_stride)
{
    bloom_info_t info;
    bloom_status_t st = bloom_query(c, &info);
    if (st != BLOOM_OK)
        return st;
    void *ws = NULL;
    if (posix_memalign(&ws, BLOOM_WORKSPACE_ALIGN, info.workspace_bytes))
        rdie("out of memory (workspace)");
    bloom_t *b;
    st = bloom_init(&b, ws, info.workspace_bytes, c);
    if (st == BLOOM_OK)
        st = bloom_process(b, src, (ptrdiff_t)src_stride, dst, (ptrdiff_t)dst_stride);
    free(ws);
    return st;
}

int rmodel_run(const bloom_config_t *c, const uint32_t *codes, int src_max, uint32_t *out, int dst_max)
{
    bloom_model_params_t p;
    memset(&p, 0, sizeof p);
    p.width = c->width;
    p.height = c->height;
    p.levels = c->levels;
    p.linear = (c->flags & BLOOM_FLAG_LINEAR) != 0;
    p.debug_view = (c->flags & BLOOM_FLAG_DEBUG_VIEW) != 0;
    /* the real values of the Q16.16 parameters the engine was given */
    p.threshold = c->threshold / 65536.0;
    p.soft_knee = c->soft_knee / 65536.0;
    p.intensity = c->intensity / 65536.0;
    const int sm[3] = {src_max, src_max, src_max}, dm[3] = {dst_max, dst_max, dst_max};
    return bloom_model_run(&p, codes, sm, out, dm, NULL);
}

/* ---- statistics ------------------------------------------------------------ */

void rstat_add(rstat_t *s, long long eng, long long ref, long long top)
{
    const long long d = eng > ref ? eng - ref : ref - eng;
    s->n++;
    s->exact += d == 0;
    if (d > s->peak)
        s->peak = d;
    s->sum_abs += (double)d;
    s->sum_sq += (double)d * (double)d;
    s->sum_signed += (double)(eng - ref);
    s->above += eng > ref;
    s->below += eng < ref;
    s->sat_eng += eng >= top;
    s->sat_ref += ref >= top;
    if (d > 0 && ref > 0 && ref >= s->rel_floor && (double)d / (double)ref > s->peak_rel)
        s->peak_rel = (double)d / (double)ref;
}

void rstat_merge(rstat_t *into, const rstat_t *s)
{
    into->n += s->n;
    into->exact += s->exact;
    if (s->peak > into->peak)
        into->peak = s->peak;
    into->sat_eng += s->sat_eng;
    into->sat_ref += s->sat_ref;
    into->sum_abs += s->sum_abs;
    into->sum_sq += s->sum_sq;
    into->sum_signed += s->sum_signed;
    into->above += s->above;
    into->below += s->below;
    if (s->peak_rel > into->peak_rel)
        into->peak_rel = s->peak_rel;
}

double rstat_mean(const rstat_t *s)
{
    return s->n ? s->sum_abs / (double)s->n : 0.0;
}

double rstat_signed_mean(const rstat_t *s)
{
    return s->n ? s->sum_signed / (double)s->n : 0.0;
}

double rstat_mse(const rstat_t *s)
{
    return s->n ? s->sum_sq / (double)s->n : 0.0;
}

double rstat_exact(const rstat_t *s)
{
    return s->n ? 100.0 * (double)s->exact / (double)s->n : 100.0;
}

double rstat_psnr(const rstat_t *s)
{
    const double m = rstat_mse(s);
    return m > 0.0 ? 10.0 * log10(255.0 * 255.0 / m) : INFINITY;
}

const char *rpsnr_str(double psnr, char *buf, size_t n)
{
    if (isinf(psnr))
        snprintf(buf, n, "inf");
    else
        snprintf(buf, n, "%.2f", psnr);
    return buf;
}

/* ---- timing ------------------------------------------------------------------ */

double rnow_wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

double rnow_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

double rmedian(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, bench_cmp_double);
    return n & 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int rring_init(rring_t *r, size_t bytes)
{
    memset(r, 0, sizeof *r);
    void *a = NULL, *b = NULL;
    if (posix_memalign(&a, 4096, bytes))
        return -1;
    if (posix_memalign(&b, 4096, bytes)) {
        free(a);
        return -1;
    }
    memset(a, 0, bytes); /* fault the pages in now, not in a timed run */
    memset(b, 0, bytes);
    r->src = a;
    r->dst = b;
    r->bytes = bytes;
    return 0;
}

int rring_fill(rring_t *r, const void *frame, size_t frame_bytes, size_t slot_bytes)
{
    r->slot = (slot_bytes + 4095u) & ~(size_t)4095u;
    r->nslots = (int)(r->bytes / r->slot);
    r->next = 0;
    if (r->nslots < 3)
        return -1;
    for (int i = 0; i < r->nslots; i++)
        memcpy(r->src + (size_t)i * r->slot, frame, frame_bytes);
    return 0;
}

void rring_free(rring_t *r)
{
    free(r->src);
    free(r->dst);
    memset(r, 0, sizeof *r);
}

int rtime_rounds(rring_t *r, rtimer_t *t, int k, int warm, int runs)
{
    double *wall = rxmalloc(sizeof *wall * (size_t)(runs * k));
    double *cpu = rxmalloc(sizeof *cpu * (size_t)(runs * k));
    int e = 0;
    for (int round = 0; round < warm + runs && !e; round++)
        for (int i = 0; i < k && !e; i++) {
            const size_t s = (size_t)(r->next++ % r->nslots) * r->slot;
            uint8_t *src = r->src + s, *dst = t[i].inplace ? src : r->dst + s;
            const double c0 = rnow_cpu(), w0 = rnow_wall();
            e = t[i].fn(t[i].ctx, src, dst);
            const double w1 = rnow_wall(), c1 = rnow_cpu();
            t[i].last_dst = dst;
            if (round >= warm) {
                wall[i * runs + round - warm] = w1 - w0;
                cpu[i * runs + round - warm] = c1 - c0;
            }
        }
    for (int i = 0; i < k && !e; i++) {
        t[i].wall_ms = 1e3 * rmedian(wall + i * runs, runs);
        t[i].cpu_ms = 1e3 * rmedian(cpu + i * runs, runs);
    }
    free(wall);
    free(cpu);
    return e;
}

int rrun_memcpy(void *ctx, const uint8_t *src, uint8_t *dst)
{
    memcpy(dst, src, *(const size_t *)ctx);
    return 0;
}

int rrun_engine(void *ctx, const uint8_t *src, uint8_t *dst)
{
    const rengine_ctx_t *e = ctx;
    const bloom_status_t st = bloom_process(e->b, src, e->in_stride, dst, e->out_stride);
    if (st != BLOOM_OK) {
        fprintf(stderr, "report: bloom_process: %s\n", bloom_status_str(st));
        return 1;
    }
    return 0;
}

/* ---- misc ---------------------------------------------------------------------- */

FILE *ropen(const char *path, char *tmp, size_t tmplen)
{
    snprintf(tmp, tmplen, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    if (!f)
        rdie("cannot write %s", tmp);
    return f;
}

void rclose(FILE *f, const char *tmp, const char *path)
{
    if (fclose(f) || rename(tmp, path))
        rdie("cannot write %s", path);
}
