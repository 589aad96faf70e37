/* bloom_mt: one frame of the bloom engine spread over a pool of POSIX
 * threads, for host and Linux callers (the core stays free of threads).
 *
 * The frame is cut into N tiles (vertical strips; a grid when the strips
 * would be narrower than BLOOM_MT_MIN_STRIP columns), each rendered by its
 * own engine (cfg.tile_*), all carved from ONE caller buffer of
 * bloom_mt_size(cfg, n) bytes: the helper allocates nothing but what
 * pthread_create takes for its threads. The threads are created once by
 * bloom_mt_init and reused for every frame; bloom_mt_process blocks until
 * every tile is written. The calling thread renders one tile itself, so N
 * tiles take N - 1 pool threads (N = 1: no thread, the untiled engine).
 *
 * Tiles are bit for bit what the whole frame has there (the engine's tile
 * contract), so the output does not depend on N. A tile is never written in
 * place (its halo reads its neighbours' source): src and dst must not
 * overlap, whatever N, and an overlap is refused with the engine's own
 * BLOOM_E_ALIAS. */
#ifndef BLOOM_MT_H
#define BLOOM_MT_H

#include <stddef.h>

#include "bloom.h"

#ifdef __cplusplus
extern "C" {
#endif

#define BLOOM_MT_MAX_THREADS 64
/* Narrowest strip before the frame is cut into a grid instead: a strip
 * much narrower than the pyramid's reach is mostly halo. */
#define BLOOM_MT_MIN_STRIP 64
/* Not an engine status: a pool thread could not be created. */
#define BLOOM_MT_E_THREAD ((bloom_status_t)-100)

typedef struct bloom_mt bloom_mt_t;

/* The online CPUs (sysconf(_SC_NPROCESSORS_ONLN)), 1 .. BLOOM_MT_MAX_THREADS. */
int bloom_mt_cpus(void);

/* n <= 0 means bloom_mt_cpus(); larger than BLOOM_MT_MAX_THREADS or than
 * the frame can be cut into is clamped. The tile count bloom_mt_init will
 * use for cfg. */
int bloom_mt_tiles_for(const bloom_config_t *cfg, int n);

/* Bytes of the one buffer bloom_mt_init carves for cfg and n threads (the
 * helper's state and every tile engine's workspace), 0 if cfg is invalid
 * or already has a tile. Pure. */
size_t bloom_mt_size(const bloom_config_t *cfg, int n);

/* Carves the tile engines out of buf (any alignment) and starts the pool.
 * Returns the first engine status that refuses cfg, BLOOM_E_WORKSPACE for a
 * short buffer, BLOOM_MT_E_THREAD if a thread cannot be created (nothing
 * left running). */
bloom_status_t bloom_mt_init(bloom_mt_t **out, void *buf, size_t bytes, const bloom_config_t *cfg, int n);

/* The tiles (= threads, the caller's included) actually used. */
int bloom_mt_tiles(const bloom_mt_t *mt);
/* Tile i's engine (to query or inspect; do not run it while a frame runs). */
bloom_t *bloom_mt_engine(const bloom_mt_t *mt, int i);

/* The aux plane for every tile engine: its row 0 and stride (the frame's). */
bloom_status_t bloom_mt_set_aux(bloom_mt_t *mt, const void *aux, ptrdiff_t aux_stride);

/* One whole frame: every tile engine's bloom_process on src/dst (the
 * frames' row 0), in parallel; returns when all are done, with the first
 * failing tile's status (in tile order) or BLOOM_OK. src and dst must not
 * overlap (BLOOM_E_ALIAS). Not reentrant: one frame at a time per mt. */
bloom_status_t bloom_mt_process(bloom_mt_t *mt, const void *src, ptrdiff_t src_stride, void *dst,
                                ptrdiff_t dst_stride);

/* Stops and joins the pool. The buffer is the caller's again. NULL: no-op. */
void bloom_mt_free(bloom_mt_t *mt);

/* bloom_status_str, and BLOOM_MT_E_THREAD. */
const char *bloom_mt_status_str(bloom_status_t st);

#ifdef __cplusplus
}
#endif
#endif
