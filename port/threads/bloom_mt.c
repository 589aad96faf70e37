/* bloom_mt: tiles of one frame on a pool of POSIX threads (bloom_mt.h).
 *
 * Layout of the caller's buffer, every part on a 64-byte boundary so that
 * no two threads' hot state shares a cache line: the helper's state
 * (struct bloom_mt, with the mutex, the condition variables and the
 * thread handles), then each tile engine's workspace. A frame is a
 * generation: the caller publishes the job and bumps gen under the mutex,
 * wakes the pool, renders tile 0 itself, and waits for pending to reach 0;
 * each pool thread renders its own tile once per generation. */
#include "bloom_mt.h"

#include <pthread.h>
#include <stdint.h>
#include <string.h>
#include <unistd.h>

#define MT_LINE 64u

typedef struct {
    struct bloom_mt *mt;
    bloom_t *b;
    int x, y, w, h; /* the tile (w == 0: the untiled engine of N = 1) */
    bloom_status_t status;
} mt_tile_t;

struct bloom_mt {
    int n, cols, rows, threads_started;
    bloom_config_t cfg;
    mt_tile_t tile[BLOOM_MT_MAX_THREADS];
    pthread_t thread[BLOOM_MT_MAX_THREADS];
    pthread_mutex_t lock;
    pthread_cond_t go, done;
    unsigned gen; /* frames published */
    int pending;  /* pool tiles of this generation still running */
    int quit;
    /* the frame of the current generation */
    const void *src;
    void *dst;
    ptrdiff_t src_stride, dst_stride;
};

static size_t round_line(size_t n)
{
    return (n + MT_LINE - 1u) / MT_LINE * MT_LINE;
}

int bloom_mt_cpus(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        return 1;
    return n > BLOOM_MT_MAX_THREADS ? BLOOM_MT_MAX_THREADS : (int)n;
}

/* The grid for n tiles: cols x rows == n with every tile at least one pixel;
 * vertical strips while they stay BLOOM_MT_MIN_STRIP wide (every strip
 * engine reads every source row, but a strip's halo is only at its two
 * sides), else the grid with the fewest columns. Returns the tiles used
 * (fewer than n when the frame is too small for n). */
static int mt_grid(const bloom_config_t *cfg, int n, int *cols)
{
    const int W = cfg->width, H = cfg->height;
    if (n <= 0)
        n = bloom_mt_cpus();
    if (n > BLOOM_MT_MAX_THREADS)
        n = BLOOM_MT_MAX_THREADS;
    for (; n > 1; n--) {
        for (int c = n; c >= 1; c--)
            if (n % c == 0 && c <= W && n / c <= H && W / c >= BLOOM_MT_MIN_STRIP) {
                *cols = c;
                return n;
            }
        for (int c = 1; c <= n; c++)
            if (n % c == 0 && c <= W && n / c <= H) {
                *cols = c;
                return n;
            }
    }
    *cols = 1;
    return 1;
}

int bloom_mt_tiles_for(const bloom_config_t *cfg, int n)
{
    int cols;
    return cfg ? mt_grid(cfg, n, &cols) : 0;
}

/* Tile i of the grid: its config (cfg with the rectangle set). */
static void mt_tile_cfg(const bloom_config_t *cfg, int n, int cols, int i, bloom_config_t *c)
{
    *c = *cfg;
    if (n == 1)
        return; /* the untiled engine: the old path, bit for bit and cost */
    const int rows = n / cols, cx = i % cols, ry = i / cols;
    const long W = cfg->width, H = cfg->height;
    c->tile_x = (int)(W * cx / cols);
    c->tile_w = (int)(W * (cx + 1) / cols) - c->tile_x;
    c->tile_y = (int)(H * ry / rows);
    c->tile_h = (int)(H * (ry + 1) / rows) - c->tile_y;
}

/* Total bytes for cfg cut into n tiles, 0 if refused (*st says why). */
static size_t mt_size(const bloom_config_t *cfg, int n, int cols, bloom_status_t *st)
{
    if (cfg->tile_w != 0 || cfg->tile_h != 0 || cfg->tile_x != 0 || cfg->tile_y != 0) {
        *st = BLOOM_E_TILE; /* the helper owns the tiling */
        return 0;
    }
    size_t total = MT_LINE + round_line(sizeof(struct bloom_mt));
    for (int i = 0; i < n; i++) {
        bloom_config_t c;
        bloom_info_t info;
        mt_tile_cfg(cfg, n, cols, i, &c);
        if ((*st = bloom_query(&c, &info)) != BLOOM_OK)
            return 0;
        total += round_line(info.workspace_bytes);
    }
    *st = BLOOM_OK;
    return total;
}

size_t bloom_mt_size(const bloom_config_t *cfg, int n)
{
    if (!cfg)
        return 0;
    int cols;
    n = mt_grid(cfg, n, &cols);
    bloom_status_t st;
    return mt_size(cfg, n, cols, &st);
}

static bloom_status_t mt_run_tile(struct bloom_mt *mt, mt_tile_t *t)
{
    return bloom_process(t->b, mt->src, mt->src_stride, mt->dst, mt->dst_stride);
}

static void *mt_worker(void *arg)
{
    mt_tile_t *t = (mt_tile_t *)arg;
    struct bloom_mt *mt = t->mt;
    pthread_mutex_lock(&mt->lock);
    unsigned seen = 0; /* gen at bloom_mt_init: a thread that starts late still sees frame 1 */
    for (;;) {
        while (mt->gen == seen && !mt->quit)
            pthread_cond_wait(&mt->go, &mt->lock);
        if (mt->quit)
            break;
        seen = mt->gen;
        /* the job fields are only written while pending == 0, that is
         * never while this tile runs: reading them unlocked is safe */
        pthread_mutex_unlock(&mt->lock);
        const bloom_status_t st = mt_run_tile(mt, t);
        pthread_mutex_lock(&mt->lock);
        t->status = st;
        if (--mt->pending == 0)
            pthread_cond_signal(&mt->done);
    }
    pthread_mutex_unlock(&mt->lock);
    return NULL;
}

static void mt_stop(struct bloom_mt *mt)
{
    pthread_mutex_lock(&mt->lock);
    mt->quit = 1;
    pthread_cond_broadcast(&mt->go);
    pthread_mutex_unlock(&mt->lock);
    for (int i = 1; i < mt->threads_started; i++)
        pthread_join(mt->thread[i], NULL);
    pthread_cond_destroy(&mt->done);
    pthread_cond_destroy(&mt->go);
    pthread_mutex_destroy(&mt->lock);
}

bloom_status_t bloom_mt_init(bloom_mt_t **out, void *buf, size_t bytes, const bloom_config_t *cfg, int n)
{
    if (!out || !buf || !cfg)
        return BLOOM_E_NULL;
    *out = NULL;
    int cols;
    n = mt_grid(cfg, n, &cols);
    bloom_status_t st;
    const size_t need = mt_size(cfg, n, cols, &st);
    if (!need)
        return st;
    if (bytes < need)
        return BLOOM_E_WORKSPACE;
    uint8_t *p = (uint8_t *)buf;
    p += (MT_LINE - (uintptr_t)p % MT_LINE) % MT_LINE;
    struct bloom_mt *mt = (struct bloom_mt *)(void *)p;
    memset(mt, 0, sizeof *mt);
    p += round_line(sizeof *mt);
    mt->n = n;
    mt->cols = cols;
    mt->rows = n / cols;
    mt->cfg = *cfg;
    for (int i = 0; i < n; i++) {
        bloom_config_t c;
        bloom_info_t info;
        mt_tile_cfg(cfg, n, cols, i, &c);
        if ((st = bloom_query(&c, &info)) != BLOOM_OK)
            return st;
        const size_t ws = round_line(info.workspace_bytes);
        if ((st = bloom_init(&mt->tile[i].b, p, ws, &c)) != BLOOM_OK)
            return st;
        p += ws;
        mt->tile[i].mt = mt;
        mt->tile[i].x = c.tile_x;
        mt->tile[i].y = c.tile_y;
        mt->tile[i].w = c.tile_w;
        mt->tile[i].h = c.tile_h;
    }
    if (pthread_mutex_init(&mt->lock, NULL))
        return BLOOM_MT_E_THREAD;
    if (pthread_cond_init(&mt->go, NULL)) {
        pthread_mutex_destroy(&mt->lock);
        return BLOOM_MT_E_THREAD;
    }
    if (pthread_cond_init(&mt->done, NULL)) {
        pthread_cond_destroy(&mt->go);
        pthread_mutex_destroy(&mt->lock);
        return BLOOM_MT_E_THREAD;
    }
    /* tile 0 is the caller's: threads 1 .. n-1 */
    mt->threads_started = 1;
    for (int i = 1; i < n; i++) {
        if (pthread_create(&mt->thread[i], NULL, mt_worker, &mt->tile[i])) {
            mt_stop(mt);
            return BLOOM_MT_E_THREAD;
        }
        mt->threads_started = i + 1;
    }
    *out = mt;
    return BLOOM_OK;
}

int bloom_mt_tiles(const bloom_mt_t *mt)
{
    return mt ? mt->n : 0;
}

bloom_t *bloom_mt_engine(const bloom_mt_t *mt, int i)
{
    return mt && i >= 0 && i < mt->n ? mt->tile[i].b : NULL;
}

bloom_status_t bloom_mt_set_aux(bloom_mt_t *mt, const void *aux, ptrdiff_t aux_stride)
{
    if (!mt)
        return BLOOM_E_NULL;
    for (int i = 0; i < mt->n; i++) {
        const bloom_status_t st = bloom_set_aux(mt->tile[i].b, aux, aux_stride);
        if (st != BLOOM_OK)
            return st;
    }
    return BLOOM_OK;
}

/* The bytes a frame of h rows of row_bytes spans, as [lo, hi). */
static void mt_span(const void *p, ptrdiff_t stride, int h, size_t row_bytes, uintptr_t *lo, uintptr_t *hi)
{
    const uintptr_t a = (uintptr_t)p, b = a + (uintptr_t)(stride * (ptrdiff_t)(h - 1));
    *lo = a < b ? a : b;
    *hi = (a < b ? b : a) + row_bytes;
}

bloom_status_t bloom_mt_process(bloom_mt_t *mt, const void *src, ptrdiff_t src_stride, void *dst,
                                ptrdiff_t dst_stride)
{
    if (!mt || !src || !dst)
        return BLOOM_E_NULL;
    /* Refused whatever N, so that a caller's result does not depend on the
     * machine's CPU count: the N = 1 engine alone could run in place. */
    uintptr_t slo, shi, dlo, dhi;
    const int W = mt->cfg.width, H = mt->cfg.height;
    mt_span(src, src_stride, H, (size_t)W * (size_t)bloom_format_bpp(mt->cfg.in_fmt), &slo, &shi);
    mt_span(dst, dst_stride, H, (size_t)W * (size_t)bloom_format_bpp(mt->cfg.out_fmt), &dlo, &dhi);
    if (slo < dhi && dlo < shi)
        return BLOOM_E_ALIAS;
    if (mt->n == 1)
        return bloom_process(mt->tile[0].b, src, src_stride, dst, dst_stride);
    pthread_mutex_lock(&mt->lock);
    mt->src = src;
    mt->dst = dst;
    mt->src_stride = src_stride;
    mt->dst_stride = dst_stride;
    mt->pending = mt->n - 1;
    mt->gen++;
    pthread_cond_broadcast(&mt->go);
    pthread_mutex_unlock(&mt->lock);
    const bloom_status_t st0 = mt_run_tile(mt, &mt->tile[0]);
    pthread_mutex_lock(&mt->lock);
    while (mt->pending > 0)
        pthread_cond_wait(&mt->done, &mt->lock);
    bloom_status_t st = st0;
    for (int i = 1; i < mt->n && st == BLOOM_OK; i++)
        st = mt->tile[i].status;
    pthread_mutex_unlock(&mt->lock);
    return st;
}

void bloom_mt_free(bloom_mt_t *mt)
{
    if (mt)
        mt_stop(mt);
}

const char *bloom_mt_status_str(bloom_status_t st)
{
    return st == BLOOM_MT_E_THREAD ? "a pool thread could not be created (pthread_create)"
                                   : bloom_status_str(st);
}
