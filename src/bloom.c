/* The engine: configuration, the row scheduler, workspace carving (the
 * row, band and frame calls are bloom_frame.c).
 *
 * Scheduling is pull-driven: an output row asks for the U_1 rows it needs,
 * each U_k row for the U_{k+1} rows and the D_k row it needs, each D_k row
 * for the D_{k-1} rows below it, down to the source rows pushed so far. A
 * request that cannot be met yet returns false and is resumed later, so the
 * order of row computations is fixed by the frame geometry alone, whatever
 * way the caller feeds rows. bloom_query() runs the same scheduler "dry"
 * (counters only) to find how many rows each ring must hold.
 *
 * Levels 1 and 2 are never delayed: the up pass recomputes D_1 from source
 * rows into a short ring (E1) and, when L >= 3, D_2 from E1, so only levels
 * >= 3 keep delay lines (sim/docs/streaming.md). */
#include <string.h>

#include "bloom_graph.h"
#include "bloom_internal.h"

#if BLOOM_USE_SKIP
/* The largest code of each width whose decoded value the knee zeroes
 * (bmax <= t - k): rows without a larger code contribute nothing. */
static uint32_t dark_code(uint32_t cut, bool linear, const uint32_t *table, uint32_t n)
{
    uint32_t c = 0;
    while (c < n) {
        const uint32_t next = linear ? ((c + 1u) * BLOOM_LIN_ONE + (n - 1u) / 2u) / n : table[c + 1];
        if (next > cut)
            break;
        c++;
    }
    return c;
}

static void set_dark(bloom_t *b)
{
    const uint32_t cut = b->knee.t > b->knee.k ? b->knee.t - b->knee.k : 0u;
    const bool lin = b->out.linear;
    (void)lin;
#if BLOOM_USE_RGB888 || BLOOM_USE_XRGB8888
    b->dark.c8 = dark_code(cut, lin, bloom_srgb_dec8, 255);
#endif
#if BLOOM_USE_RGB565
    b->dark.c6 = dark_code(cut, lin, bloom_srgb_dec6, 63);
    b->dark.c5 = dark_code(cut, lin, bloom_srgb_dec5, 31);
#endif
    b->dark.q16 = cut >> BLOOM_Q16_SHIFT; /* min(w, 2^24 - 1) << shift <= cut */
}
#endif

/* Geometry and quantized parameters; no buffers. */
static void setup(bloom_t *b, const bloom_config_t *cfg)
{
    memset(b, 0, sizeof *b);
    b->cfg = *cfg;
    b->w[0] = cfg->width;
    b->h[0] = cfg->height;
    b->L = 1;
    for (int k = 1; k <= BLOOM_MAX_LEVELS; k++) {
        int w = (b->w[k - 1] + 1) / 2, h = (b->h[k - 1] + 1) / 2;
        if (k > 1 && (k > cfg->levels || imin(w, h) < 2))
            break;
        b->w[k] = w;
        b->h[k] = h;
        b->L = k;
    }
    b->knee.t = cfg->threshold << BLOOM_Q16_SHIFT; /* Q16.16 -> internal, exact */
    b->knee.k = (uint32_t)(((uint64_t)b->knee.t * cfg->soft_knee + 32768u) >> 16);
    b->out.in_fmt = cfg->in_fmt;
    b->out.out_fmt = cfg->out_fmt;
    b->out.linear = (cfg->flags & BLOOM_FLAG_LINEAR) != 0;
    b->out.debug = (cfg->flags & BLOOM_FLAG_DEBUG_VIEW) != 0;
    b->out.intensity = bloom_srgb_to_linear_q16(cfg->intensity);
    b->src_bpp = bloom_format_bpp(cfg->in_fmt);
    b->skip = !(cfg->flags & BLOOM_FLAG_NO_SKIP);
    bloom_kernels_select(&b->kern, cfg->flags);
#if BLOOM_USE_SKIP
    set_dark(b);
#endif
    b->src_row_bytes = (size_t)cfg->width * (size_t)b->src_bpp;
}

/* ---- consumers of each ring: the oldest row anyone still reads ---------- */

#define FAR (1 << 30)

static int oldest_src(const bloom_t *b)
{
    int o = b->out_n < b->h[0] ? b->out_n : FAR;
    if (b->d_next[1] < b->h[1])
        o = imin(o, 2 * b->d_next[1] - 1);
    if (b->L >= 2 && b->e_next < b->h[1])
        o = imin(o, 2 * b->e_next - 1);
    return imax(o, 0);
}

/* Whether the up pass recomputes D_2 (from E1) instead of delaying it. */
static bool recompute_d2(const bloom_t *b)
{
    return b->L >= 3;
}

static int oldest_E1(const bloom_t *b)
{
    int o = b->u_next[1];
    if (recompute_d2(b) && b->u_next[2] < b->h[2])
        o = imin(o, 2 * b->u_next[2] - 1);
    return imax(o, 0);
}

static int oldest_D(const bloom_t *b, int k)
{
    int o = FAR;
    if (k < b->L && b->d_next[k + 1] < b->h[k + 1])
        o = 2 * b->d_next[k + 1] - 1;
    if (k == b->L) { /* U_L is D_L */
        if (k == 1)
            o = imin(o, (b->out_n >> 1) - 1);
        else
            o = imin(o, (b->u_next[k - 1] >> 1) - 1);
    } else if (k >= 3 || (k == 2 && !recompute_d2(b))) {
        o = imin(o, b->u_next[k]);
    }
    return imax(o, 0);
}

static int oldest_U(const bloom_t *b, int k)
{
    return imax(((k == 1 ? b->out_n : b->u_next[k - 1]) >> 1) - 1, 0);
}

/* Ring tags hold the row number; ZBIT marks a row known to be all zero
 * (never written: readers get the shared zero row) or, in the source ring,
 * a dark row (nothing in it passes the knee). Rows are < 2^30. */
#define ZBIT BLOOM_TAG_ZERO
/* The zero-row shortcuts, unless compiled out or switched off. */
#define SKIP(b) (BLOOM_USE_SKIP && (b)->skip)

/* Claim the slot for row r of a ring whose oldest live row is `oldest`. */
static uint32_t *ring_put(bloom_t *b, bloom_ring_t *rg, int *need, int r, int oldest)
{
    if (b->dry) {
        *need = imax(*need, r - oldest + 1);
        return NULL;
    }
#if BLOOM_CHECK_RINGS
    if (r - rg->cap >= oldest)
        b->failed = true;
#endif
    (void)need;
    (void)oldest;
    rg->tag[r % rg->cap] = r;
    return rg->buf + (size_t)(r % rg->cap) * (size_t)rg->width * 3u;
}

static void ring_mark_zero(bloom_ring_t *rg, int r)
{
    rg->tag[r % rg->cap] = r | ZBIT;
}

static bool ring_zero(const bloom_ring_t *rg, int r)
{
    return (rg->tag[r % rg->cap] & ZBIT) != 0;
}

static const uint32_t *ring_get(bloom_t *b, const bloom_ring_t *rg, int r)
{
    const int32_t tag = rg->tag[r % rg->cap];
#if BLOOM_CHECK_RINGS
    if ((tag & ~ZBIT) != r)
        b->failed = true;
#endif
    if (tag & ZBIT)
        return b->zero_row;
    return rg->buf + (size_t)(r % rg->cap) * (size_t)rg->width * 3u;
}

static const uint8_t *src_get(bloom_t *b, int r)
{
    const int slot = r % b->src_cap;
#if BLOOM_CHECK_RINGS
    if ((b->src_tag[slot] & ~ZBIT) != r)
        b->failed = true;
#endif
    if (b->src_copy)
        return b->src_copy + (size_t)slot * b->src_row_bytes;
    return b->src_ptr[slot];
}

/* Whether the `n` rows of a ring from `first` (clamped to the level) are
 * all zero; always false when skipping is off. */
static bool rows_zero(const bloom_t *b, const bloom_ring_t *rg, int first, int n, int h)
{
    if (!SKIP(b))
        return false;
    for (int i = 0; i < n; i++)
        if (!ring_zero(rg, clampi(first + i, 0, h - 1)))
            return false;
    return true;
}

/* D_1 row r from source rows 2r-1 .. 2r+2, box then knee; false when the
 * row is all zero (then dst is not written). */
static bool compute_d1(bloom_t *b, int r, uint32_t *dst)
{
    const uint8_t *s[4];
    bool dark = SKIP(b);
    for (int i = 0; i < 4; i++) {
        const int row = clampi(2 * r - 1 + i, 0, b->h[0] - 1);
        s[i] = src_get(b, row);
        dark = dark && (b->src_tag[row % b->src_cap] & ZBIT);
    }
    if (dark)
        return false;
#if BLOOM_SMALL
    bloom_row_box_src_c(s, b->cfg.in_fmt, b->out.linear, dst, b->w[1], b->w[0]);
    return bloom_row_knee_c(dst, b->w[1], &b->knee) || !SKIP(b);
#else
    /* the same (the SIMD kernels skip the box where the knee zeroes anyway) */
    return b->kern.d1(s, b->cfg.in_fmt, b->out.linear, dst, b->w[1], b->w[0], &b->knee, &b->dark) || !SKIP(b);
#endif
}

/* The ring tent row r of level k reads from: U_{k+1}, or D_L at the bottom. */
static const bloom_ring_t *below(const bloom_t *b, int k)
{
    return (k + 1 == b->L) ? &b->D[k + 1] : &b->U[k + 1];
}

/* The three rows of the level below (k+1) that tent row r of level k reads. */
static void tent_rows(bloom_t *b, int k, int r, const uint32_t *u[3])
{
    const bloom_ring_t *rg = below(b, k);
    const int m = r >> 1, hb = b->h[k + 1];
    for (int i = 0; i < 3; i++)
        u[i] = ring_get(b, rg, clampi(m - 1 + i, 0, hb - 1));
}

/* The row computations live outside the recursive scheduler functions so
 * that each recursion level costs a small frame (the stack figure of the
 * frame call, port/mcu/FIGURES.md). */
#if defined(__GNUC__)
#define BLOOM_NOINLINE __attribute__((noinline))
#else
#define BLOOM_NOINLINE
#endif

/* D_k row r into its slot (k >= 1), or marked zero. */
static BLOOM_NOINLINE void compute_D(bloom_t *b, int k, int r, uint32_t *dst)
{
    bloom_ring_t *rg = &b->D[k];
    if (k == 1) {
        if (!compute_d1(b, r, dst))
            ring_mark_zero(rg, r);
    } else if (rows_zero(b, &b->D[k - 1], 2 * r - 1, 4, b->h[k - 1])) {
        ring_mark_zero(rg, r);
    } else {
        const uint32_t *s[4];
        for (int i = 0; i < 4; i++)
            s[i] = ring_get(b, &b->D[k - 1], clampi(2 * r - 1 + i, 0, b->h[k - 1] - 1));
        b->kern.box(s, dst, b->w[k], b->w[k - 1]);
    }
}

static BLOOM_NOINLINE void compute_E1(bloom_t *b, int r, uint32_t *dst)
{
    if (!compute_d1(b, r, dst))
        ring_mark_zero(&b->E1, r);
}

/* U_k row r = D_k row r + tent(rows of level k+1), or marked zero. */
static BLOOM_NOINLINE void compute_U(bloom_t *b, int k, int r, uint32_t *dst)
{
    const bool d2 = k == 2 && recompute_d2(b);
    bloom_ring_t *rg = &b->U[k];
    const bloom_ring_t *dring = (k == 1 || d2) ? &b->E1 : &b->D[k];
    const bool dzero = d2 ? rows_zero(b, dring, 2 * r - 1, 4, b->h[1]) : rows_zero(b, dring, r, 1, b->h[k]);
    const bool uzero = rows_zero(b, below(b, k), (r >> 1) - 1, 3, b->h[k + 1]);
    if (dzero && uzero) {
        ring_mark_zero(rg, r);
        return;
    }
    const uint32_t *add = NULL; /* the D_k row the tent adds to, if any */
    if (dzero) {
        /* the tent alone */
    } else if (d2) {
        const uint32_t *s[4];
        for (int i = 0; i < 4; i++)
            s[i] = ring_get(b, dring, clampi(2 * r - 1 + i, 0, b->h[1] - 1));
        b->kern.box(s, dst, b->w[2], b->w[1]);
        add = dst;
    } else if (uzero) {
        memcpy(dst, ring_get(b, dring, r), (size_t)b->w[k] * 3u * sizeof *dst);
    } else {
        add = ring_get(b, dring, r); /* read where it is: no copy */
    }
    if (!uzero) {
        const uint32_t *u[3];
        tent_rows(b, k, r, u);
        b->kern.tent(u, r & 1, add, dst, 0, b->w[k], b->w[k + 1]);
    }
}

/* The last row of level k-1 (or of the source) that row r of level k reads. */
static int top_below(const bloom_t *b, int k, int r)
{
    return imin(2 * r + 2, b->h[k - 1] - 1);
}

/* D_k rows up to j. A loop rather than a recursion down the levels (the
 * frame call's stack): find the shallowest level whose next row has all its
 * inputs, compute that row, start again. This is the order the recursion
 * "compute what row r needs, then row r" gives. */
static bool ensure_D(bloom_t *b, int k, int j)
{
    while (b->d_next[k] <= j) {
        int m = k;
        while (m > 1 && b->d_next[m - 1] <= top_below(b, m, b->d_next[m]))
            m--;
        const int r = b->d_next[m];
        if (m == 1 && top_below(b, 1, r) >= b->src_n)
            return false;
        uint32_t *dst = ring_put(b, &b->D[m], &b->need_D[m], r, oldest_D(b, m));
        if (dst)
            compute_D(b, m, r, dst);
        b->d_next[m]++;
    }
    return true;
}

/* E1: D_1 recomputed from the source for the up pass. */
static bool ensure_E1(bloom_t *b, int j)
{
    while (b->e_next <= j) {
        const int r = b->e_next;
        if (imin(2 * r + 2, b->h[0] - 1) >= b->src_n)
            return false;
        uint32_t *dst = ring_put(b, &b->E1, &b->need_E1, r, oldest_E1(b));
        if (dst)
            compute_E1(b, r, dst);
        b->e_next++;
    }
    return true;
}

static bool ensure_up(bloom_t *b, int k, int j);

static bool ensure_U(bloom_t *b, int k, int j)
{
    while (b->u_next[k] <= j) {
        const int r = b->u_next[k];
        if (!ensure_up(b, k + 1, imin((r >> 1) + 1, b->h[k + 1] - 1)))
            return false;
        bool ok;
        if (k == 1)
            ok = ensure_E1(b, r);
        else if (k == 2 && recompute_d2(b))
            ok = ensure_E1(b, imin(2 * r + 2, b->h[1] - 1));
        else
            ok = ensure_D(b, k, r);
        if (!ok)
            return false;
        uint32_t *dst = ring_put(b, &b->U[k], &b->need_U[k], r, oldest_U(b, k));
        if (dst)
            compute_U(b, k, r, dst);
        b->u_next[k]++;
    }
    return true;
}

static bool ensure_up(bloom_t *b, int k, int j)
{
    return k == b->L ? ensure_D(b, k, j) : ensure_U(b, k, j);
}

/* ---- sizing and carving ---------------------------------------------- */

static void dry_frame(bloom_t *b)
{
    b->dry = true;
    for (int y = 0; y < b->h[0]; y++) {
        b->need_src = imax(b->need_src, y - oldest_src(b) + 1);
        b->src_n = y + 1;
        while (b->out_n < b->h[0]) {
            const int y_out = b->out_n;
            if (!ensure_up(b, 1, imin((y_out >> 1) + 1, b->h[1] - 1)))
                break;
            b->latency = imax(b->latency, y - y_out);
            b->out_n++;
        }
    }
}

/* Lay the rings out after the engine struct; with base NULL only count.
 * Counted in 64 bits: on a 32-bit target a huge configuration must be
 * refused (BLOOM_E_TOO_BIG), not wrap around. */
static uint64_t carve(bloom_t *b, uint8_t *base, size_t *per_level)
{
    uint64_t off = bloom_align8(sizeof(bloom_t));
    const int cap_src = imax(b->need_src, 1);
#define TAKE(ptr, type, count) BLOOM_TAKE(base, off, ptr, type, count)
    if (b->cfg.flags & BLOOM_FLAG_COPY_SOURCE) {
        uint64_t before = off;
        TAKE(b->src_copy, uint8_t, (uint64_t)cap_src * b->src_row_bytes);
        if (per_level)
            per_level[0] = (size_t)(off - before);
    } else {
        TAKE(b->src_ptr, const uint8_t *, cap_src);
    }
    TAKE(b->src_tag, int32_t, cap_src);
    TAKE(b->zero_row, uint32_t, (size_t)b->w[1] * 3u);
    if (base)
        b->src_cap = cap_src;
    for (int k = 1; k <= b->L; k++) {
        uint64_t before = off;
        bloom_ring_t *rings[2] = {&b->D[k], k < b->L ? &b->U[k] : NULL};
        const int caps[2] = {imax(b->need_D[k], 1), imax(b->need_U[k], 1)};
        for (int i = 0; i < 2; i++) {
            if (!rings[i])
                continue;
            TAKE(rings[i]->buf, uint32_t, (uint64_t)caps[i] * (uint64_t)b->w[k] * 3u);
            TAKE(rings[i]->tag, int32_t, caps[i]);
            if (base) {
                rings[i]->cap = caps[i];
                rings[i]->width = b->w[k];
            }
        }
        if (k == 1 && b->L >= 2) {
            const int cap = imax(b->need_E1, 1);
            TAKE(b->E1.buf, uint32_t, (uint64_t)cap * (uint64_t)b->w[1] * 3u);
            TAKE(b->E1.tag, int32_t, cap);
            if (base) {
                b->E1.cap = cap;
                b->E1.width = b->w[1];
            }
        }
        if (per_level)
            per_level[k] = (size_t)(off - before);
    }
#undef TAKE
    return off;
}

/* Configure b from cfg, including the dry run; no buffers yet. */
static bloom_status_t plan(bloom_t *b, const bloom_config_t *cfg, bloom_info_t *info)
{
    if (!cfg)
        return BLOOM_E_NULL;
    bloom_status_t st = bloom_validate(cfg);
    if (st != BLOOM_OK)
        return st;
    setup(b, cfg);
    dry_frame(b);
    if (info) {
        bloom_info_fill(info, b->L, b->w, b->h, b->latency, b->need_src, &b->knee, &b->out);
        const uint64_t bytes = carve(b, NULL, info->ring_bytes);
        if (bytes > SIZE_MAX)
            return BLOOM_E_TOO_BIG;
        info->workspace_bytes = (size_t)bytes;
    }
    return BLOOM_OK;
}

#if BLOOM_USE_GRAPH
/* A preset's engine: bloom_t (graph set), the graph, its rings. */
#define GRAPH_OFF bloom_align8(sizeof(bloom_t))
#define GRAPH_RINGS bloom_align8(GRAPH_OFF + sizeof(struct bloom_graph))

/* Not inlined: the graph (about 6 KB) must not enlarge bloom_query's frame on
 * the default path (the Cortex-M stack figure). */
static BLOOM_NOINLINE bloom_status_t graph_query(const bloom_config_t *cfg, bloom_info_t *info)
{
    struct bloom_graph tmp;
    bloom_status_t st = bloom_graph_plan(&tmp, cfg, info);
    if (st == BLOOM_OK && info) {
        if (info->workspace_bytes > SIZE_MAX - GRAPH_RINGS)
            return BLOOM_E_TOO_BIG;
        info->workspace_bytes += GRAPH_RINGS;
    }
    return st;
}

static bloom_status_t graph_init(bloom_t **out, uint8_t *ws, size_t ws_bytes, const bloom_config_t *cfg)
{
    if (ws_bytes < GRAPH_RINGS)
        return BLOOM_E_WORKSPACE;
    bloom_t *b = (bloom_t *)(void *)ws;
    memset(b, 0, sizeof *b);
    b->cfg = *cfg;
    struct bloom_graph *g = (struct bloom_graph *)(void *)(ws + GRAPH_OFF);
    bloom_status_t st = bloom_graph_plan(g, cfg, NULL);
    if (st != BLOOM_OK)
        return st;
    const uint64_t need = bloom_graph_carve(g, NULL, NULL) + GRAPH_RINGS;
    if (need > SIZE_MAX)
        return BLOOM_E_TOO_BIG;
    if (ws_bytes < need)
        return BLOOM_E_WORKSPACE;
    if (bloom_graph_carve(g, ws + GRAPH_RINGS, NULL) + GRAPH_RINGS != need)
        return BLOOM_E_INTERNAL;
    b->graph = g;
    *out = b;
    return bloom_begin(b);
}
#endif

bloom_status_t bloom_query(const bloom_config_t *cfg, bloom_info_t *info)
{
#if BLOOM_USE_GRAPH
    if (cfg && cfg->preset != BLOOM_PRESET_UNITY) {
        bloom_status_t st = bloom_validate(cfg);
        return st != BLOOM_OK ? st : graph_query(cfg, info);
    }
#endif
    bloom_t tmp;
    return plan(&tmp, cfg, info);
}

size_t bloom_workspace_size(const bloom_config_t *cfg)
{
    bloom_info_t info;
    return bloom_query(cfg, &info) == BLOOM_OK ? info.workspace_bytes : 0u;
}

bloom_status_t bloom_init(bloom_t **out, void *ws, size_t ws_bytes, const bloom_config_t *cfg)
{
    if (!out || !ws || !cfg)
        return BLOOM_E_NULL;
    *out = NULL;
    if ((uintptr_t)ws % BLOOM_WORKSPACE_ALIGN)
        return BLOOM_E_ALIGN;
    bloom_status_t st = bloom_validate(cfg);
    if (st != BLOOM_OK)
        return st;
#if BLOOM_USE_GRAPH
    if (cfg->preset != BLOOM_PRESET_UNITY)
        return graph_init(out, (uint8_t *)ws, ws_bytes, cfg);
#endif
    if (ws_bytes < sizeof(bloom_t))
        return BLOOM_E_WORKSPACE;
    /* Plan in place (no engine-sized stack frame); a buffer found too small
     * afterwards is refused, its first bytes used as scratch. */
    bloom_t *b = (bloom_t *)ws;
    plan(b, cfg, NULL);
    const uint64_t need = carve(b, NULL, NULL);
    if (need > SIZE_MAX)
        return BLOOM_E_TOO_BIG;
    if (ws_bytes < need)
        return BLOOM_E_WORKSPACE;
    b->dry = false;
    if (carve(b, (uint8_t *)ws, NULL) != need) /* the carving ends where sizing said */
        return BLOOM_E_INTERNAL;
    memset(b->zero_row, 0, (size_t)b->w[1] * 3u * sizeof *b->zero_row);
    *out = b;
    return bloom_begin(b);
}

/* ---- frames ------------------------------------------------------------ */

bloom_status_t bloom_begin(bloom_t *b)
{
    if (!b)
        return BLOOM_E_NULL;
#if BLOOM_USE_GRAPH
    if (b->graph)
        return bloom_graph_begin(b->graph);
#endif
    b->src_n = b->out_n = b->e_next = 0;
    memset(b->d_next, 0, sizeof b->d_next);
    memset(b->u_next, 0, sizeof b->u_next);
    b->failed = false;
    for (int i = 0; i < b->src_cap; i++)
        b->src_tag[i] = -1;
    for (int k = 1; k <= b->L; k++) {
        bloom_ring_t *rings[2] = {&b->D[k], k < b->L ? &b->U[k] : NULL};
        for (int i = 0; i < 2; i++)
            if (rings[i])
                for (int s = 0; s < rings[i]->cap; s++)
                    rings[i]->tag[s] = -1;
    }
    for (int s = 0; s < b->E1.cap; s++)
        b->E1.tag[s] = -1;
    return BLOOM_OK;
}

/* The default scheduler's push and pull (bloom_frame.c checks the
 * arguments, dispatches, and checks aliasing first). */
bloom_status_t bloom_sched_push(bloom_t *b, const void *src_row)
{
    if (b->src_n >= b->h[0])
        return BLOOM_E_STATE;
    const int r = b->src_n, slot = r % b->src_cap;
    if (r - b->src_cap >= oldest_src(b))
        return BLOOM_E_BUSY;
    if (b->src_copy)
        memcpy(b->src_copy + (size_t)slot * b->src_row_bytes, src_row, b->src_row_bytes);
    else
        b->src_ptr[slot] = (const uint8_t *)src_row;
    const bool dark = SKIP(b) && bloom_row_dark(b->cfg.in_fmt, (const uint8_t *)src_row, b->w[0], &b->dark);
    b->src_tag[slot] = r | (dark ? ZBIT : 0);
    b->src_n++;
    return BLOOM_OK;
}

bloom_status_t bloom_sched_pull(bloom_t *b, void *dst_row)
{
    const int y = b->out_n;
    if (y >= b->h[0])
        return BLOOM_DONE;
    if (y >= b->src_n || !ensure_up(b, 1, imin((y >> 1) + 1, b->h[1] - 1)))
        return b->failed ? BLOOM_E_INTERNAL : BLOOM_AGAIN;
    if (rows_zero(b, below(b, 0), (y >> 1) - 1, 3, b->h[1])) { /* B = 0 here */
        bloom_row_copy_c(src_get(b, y), (uint8_t *)dst_row, b->w[0], &b->out);
    } else {
        const uint32_t *u[3];
        tent_rows(b, 0, y, u);
        if (bloom_kernels_simd(&b->kern))
            bloom_row_out_k(&b->kern, u, y & 1, src_get(b, y), (uint8_t *)dst_row, b->w[0], b->w[1], &b->out);
        else
            bloom_row_out_c(u, y & 1, src_get(b, y), (uint8_t *)dst_row, b->w[0], b->w[1], &b->out);
    }
    if (b->failed)
        return BLOOM_E_INTERNAL;
    b->out_n++;
    return BLOOM_OK;
}
