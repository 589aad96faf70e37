/* The row-graph engine (bloom_graph.h): scheduler, sizing, carving, rows in
 * and out. The same pull-driven scheme as the default engine (bloom.c):
 * an output row asks its inputs for the rows it reads, each node row asks
 * its inputs, down to the source rows pushed so far; a request that cannot
 * be met yet returns false and is resumed later, so the order of row
 * computations depends on the frame geometry alone. */
#include "bloom_graph.h"

#include <string.h>

#if BLOOM_USE_GRAPH

#define FAR (1 << 30)

const bloom_preset_ops_t *bloom_preset_ops(bloom_preset_t p)
{
    switch (p) {
#if BLOOM_USE_GAMEDEV
    case BLOOM_PRESET_GAMEDEV:
        return &bloom_preset_gamedev;
#endif
#if BLOOM_USE_XNA
    case BLOOM_PRESET_XNA:
        return &bloom_preset_xna;
#endif
#if BLOOM_USE_ATTENUATION
    case BLOOM_PRESET_ATTENUATION:
        return &bloom_preset_attenuation;
#endif
#if BLOOM_USE_ARM
    case BLOOM_PRESET_ARM:
        return &bloom_preset_arm;
#endif
#if BLOOM_USE_COD
    case BLOOM_PRESET_COD:
        return &bloom_preset_cod;
#endif
    default:
        return NULL;
    }
}

/* ---- construction ------------------------------------------------------ */

void bg_levels(bloom_graph_t *g, int n)
{
    g->L = 1;
    for (int k = 1; k <= BLOOM_MAX_LEVELS; k++) {
        const int w = (g->w[k - 1] + 1) / 2, h = (g->h[k - 1] + 1) / 2;
        if (k > 1 && (k > n || imin(w, h) < 2))
            break;
        g->w[k] = w;
        g->h[k] = h;
        g->L = k;
    }
}

int bg_node(bloom_graph_t *g, bg_row_fn fn, int w, int h, int ch, int level)
{
    if (g->nnodes >= BG_MAX_NODES) {
        g->failed = true;
        return -1;
    }
    bg_node_t *n = &g->node[g->nnodes];
    memset(n, 0, sizeof *n);
    n->fn = fn;
    n->w = w;
    n->h = h;
    n->ch = ch;
    n->level = level;
    return g->nnodes++;
}

void bg_input(bloom_graph_t *g, int n, int from, bg_map_t map, int lo, int hi)
{
    if (n < 0 || n >= g->nnodes || g->node[n].nin >= BG_MAX_IN || from >= n || from < BG_AUX) {
        g->failed = true; /* inputs must be built before their readers */
        return;
    }
    bg_node_t *nd = &g->node[n];
    nd->in[nd->nin++] = (bg_input_t){from, map, lo, hi};
}

/* ---- rows -------------------------------------------------------------- */

static int base_row(bg_map_t map, int r)
{
    return map == BG_DOWN ? 2 * r : map == BG_SAME ? r : r >> 1;
}

static int in_height(const bloom_graph_t *g, int from)
{
    return from < 0 ? g->h[0] : g->node[from].h;
}

/* The oldest row of `from` that a node still reads; FAR if none. */
static int oldest_of(const bloom_graph_t *g, int from)
{
    int o = FAR;
    const int hin = in_height(g, from);
    for (int c = (from < 0 ? 0 : from + 1); c < g->nnodes; c++) {
        const bg_node_t *n = &g->node[c];
        if (n->next >= n->h)
            continue;
        for (int i = 0; i < n->nin; i++)
            if (n->in[i].node == from || (from == BG_SRC && n->in[i].node == BG_AUX))
                o = imin(o, clampi(base_row(n->in[i].map, n->next) + n->in[i].lo, 0, hin - 1));
    }
    return o;
}

static const void *row_of(const bloom_graph_t *g, int from, int r)
{
    if (from < 0) {
        const int slot = r % g->src_cap;
        if (from == BG_SRC)
            return g->src_copy ? g->src_copy + (size_t)slot * g->src_row_bytes : g->src_ptr[slot];
        return g->aux_copy ? g->aux_copy + (size_t)slot * g->aux_row_bytes : g->aux_ptr[slot];
    }
    const bg_node_t *n = &g->node[from];
    return n->buf + (size_t)(r % n->cap) * (size_t)n->w * (size_t)n->ch;
}

#if BLOOM_CHECK_RINGS
static bool row_ok(const bloom_graph_t *g, int from, int r)
{
    if (from < 0)
        return g->src_tag[r % g->src_cap] == r;
    const bg_node_t *n = &g->node[from];
    return n->tag[r % n->cap] == r;
}
#endif

static bool ensure(bloom_graph_t *g, int ni, int j);

/* Make sure every input row of node row r exists. */
static bool ensure_inputs(bloom_graph_t *g, const bg_node_t *n, int r)
{
    for (int i = 0; i < n->nin; i++) {
        const bg_input_t *in = &n->in[i];
        const int top = clampi(base_row(in->map, r) + in->hi, 0, in_height(g, in->node) - 1);
        if (!ensure(g, in->node, top))
            return false;
    }
    return true;
}

/* Run node row r into dst: gather the input rows, call the row function. */
static void run_row(bloom_graph_t *g, const bg_node_t *n, int r, void *dst)
{
    const void *rows[BG_MAX_ROWS];
    const void *const *in[BG_MAX_IN] = {NULL, NULL, NULL};
    int used = 0;
    for (int i = 0; i < n->nin; i++) {
        const bg_input_t *ip = &n->in[i];
        const int hin = in_height(g, ip->node), b = base_row(ip->map, r);
        in[i] = rows + used;
        for (int j = ip->lo; j <= ip->hi; j++) {
            const int rr = clampi(b + j, 0, hin - 1);
#if BLOOM_CHECK_RINGS
            if (!row_ok(g, ip->node, rr))
                g->failed = true;
#endif
            rows[used++] = row_of(g, ip->node, rr);
        }
    }
    n->fn(g, n, r, in, dst);
}

static bool ensure(bloom_graph_t *g, int ni, int j)
{
    if (ni < 0)
        return j < g->src_n;
    bg_node_t *n = &g->node[ni];
    while (n->next <= j) {
        const int r = n->next;
        if (!ensure_inputs(g, n, r))
            return false;
        const int oldest = oldest_of(g, ni);
        if (g->dry) {
            n->need = imax(n->need, r - imin(oldest, r) + 1);
        } else {
#if BLOOM_CHECK_RINGS
            if (r - n->cap >= oldest)
                g->failed = true;
#endif
            n->tag[r % n->cap] = r;
            run_row(g, n, r, n->buf + (size_t)(r % n->cap) * (size_t)n->w * (size_t)n->ch);
        }
        n->next++;
    }
    return true;
}

/* ---- helpers for row functions ---------------------------------------- */

void bg_decode_row(const bloom_graph_t *g, const uint8_t *src, uint32_t *dst)
{
    const int bpp = g->src_bpp;
    for (int x = 0; x < g->w[0]; x++)
        bloom_pixel_decode(g->out.in_fmt, g->out.linear, src + (size_t)x * (size_t)bpp, dst + 3 * x);
}

uint32_t bg_aux_q16(const bloom_graph_t *g, const void *row, int x)
{
    if (g->cfg.aux_fmt == BLOOM_AUX_U16) {
        uint16_t c16; /* rows need not be 2-byte aligned */
        memcpy(&c16, (const uint8_t *)row + 2 * x, 2);
        const uint32_t c = c16;
        return c + ((c + 32768u) >> 16); /* c * 65536 / 65535, rounded: exact at 0 and 65535 */
    }
    const uint32_t c = ((const uint8_t *)row)[x];
    return c * 257u + (c >= 128u); /* (c * 65536 + 127) / 255: c * 65536 = 255 * 257c + c */
}

/* The same code as a Q24 fraction of the plane's top code, rounded (the
 * attenuation factor: at Q16 a constant depth gave every pixel the same
 * rounding, up to 1.2e-5 of a bright sample). */
uint32_t bg_aux_q24(const bloom_graph_t *g, const void *row, int x)
{
    if (g->cfg.aux_fmt == BLOOM_AUX_U16) {
        uint16_t c16;
        memcpy(&c16, (const uint8_t *)row + 2 * x, 2);
        const uint32_t c = c16; /* c 2^24 / 65535 = 256 c + 256 c / 65535 */
        return 256u * c + (256u * c + 32767u) / 65535u;
    }
    const uint32_t c = ((const uint8_t *)row)[x];
    return 65793u * c + (c >= 128u); /* c 2^24 / 255 = 65793 c + c / 255 */
}

/* ---- planning ---------------------------------------------------------- */

bloom_status_t bloom_graph_validate(const bloom_config_t *cfg)
{
    const bloom_preset_ops_t *ops = bloom_preset_ops(cfg->preset);
    if (!ops)
        return BLOOM_E_PRESET;
    if (cfg->aux_fmt != BLOOM_AUX_NONE && cfg->aux_fmt != BLOOM_AUX_U8 && cfg->aux_fmt != BLOOM_AUX_U16)
        return BLOOM_E_AUX;
    return ops->validate(cfg);
}

static void dry_frame(bloom_graph_t *g)
{
    bg_node_t *o = &g->node[g->out_node];
    g->dry = true;
    for (int y = 0; y < g->h[0]; y++) {
        g->need_src = imax(g->need_src, y - imin(oldest_of(g, BG_SRC), y) + 1);
        g->src_n = y + 1;
        while (o->next < g->h[0]) {
            if (!ensure_inputs(g, o, o->next))
                break;
            g->latency = imax(g->latency, y - o->next);
            o->next++;
        }
    }
    g->dry = false;
}

bloom_status_t bloom_graph_plan(bloom_graph_t *g, const bloom_config_t *cfg, bloom_info_t *info)
{
    bloom_status_t st = bloom_graph_validate(cfg);
    if (st != BLOOM_OK)
        return st;
    memset(g, 0, sizeof *g);
    g->cfg = *cfg;
    g->w[0] = cfg->width;
    g->h[0] = cfg->height;
    bg_levels(g, cfg->levels);
    g->knee.t = cfg->threshold << BLOOM_Q16_SHIFT;
    g->knee.k = (uint32_t)(((uint64_t)g->knee.t * cfg->soft_knee + 32768u) >> 16);
    g->out.in_fmt = cfg->in_fmt;
    g->out.out_fmt = cfg->out_fmt;
    g->out.linear = (cfg->flags & BLOOM_FLAG_LINEAR) != 0;
    g->out.debug = (cfg->flags & BLOOM_FLAG_DEBUG_VIEW) != 0;
    g->out.intensity = bloom_srgb_to_linear_q16(cfg->intensity);
    bloom_kernels_select(&g->kern, cfg->flags);
    g->src_bpp = bloom_format_bpp(cfg->in_fmt);
    g->aux_bpp = cfg->aux_fmt == BLOOM_AUX_U16 ? 2 : cfg->aux_fmt == BLOOM_AUX_U8 ? 1 : 0;
    g->src_row_bytes = (size_t)cfg->width * (size_t)g->src_bpp;
    g->aux_row_bytes = (size_t)cfg->width * (size_t)g->aux_bpp;
    g->scratch_len = (size_t)cfg->width * 3u + 16u;
    g->out_node = -1;
    g->scratch_rows = -1;
    st = bloom_preset_ops(cfg->preset)->build(g);
    if (g->scratch_rows < 0 || g->scratch_rows > BG_SCRATCH)
        g->scratch_rows = BG_SCRATCH;
    if (st != BLOOM_OK)
        return st;
    if (g->failed || g->out_node != g->nnodes - 1 || g->node[g->out_node].h != g->h[0])
        return BLOOM_E_INTERNAL;
    dry_frame(g);
    if (info) {
        bloom_info_fill(info, g->L, g->w, g->h, g->latency, g->need_src, &g->knee, &g->out);
        const uint64_t bytes =
            bloom_graph_carve(g, NULL, info->ring_bytes); /* adds to the zeroed ring_bytes */
        if (bytes > SIZE_MAX)
            return BLOOM_E_TOO_BIG;
        info->workspace_bytes = (size_t)bytes;
    }
    return BLOOM_OK;
}

/* Bytes after the graph struct (which the caller places); with base NULL
 * only count. per_level[k] gets the ring bytes of nodes at level k, [0] the
 * source copies. */
uint64_t bloom_graph_carve(bloom_graph_t *g, uint8_t *base, size_t *per_level)
{
    uint64_t off = 0;
    const int cap = imax(g->need_src, 1);
#define TAKE(ptr, type, count) BLOOM_TAKE(base, off, ptr, type, count)
    if (g->cfg.flags & BLOOM_FLAG_COPY_SOURCE) {
        TAKE(g->src_copy, uint8_t, (uint64_t)cap * g->src_row_bytes);
        if (g->aux_bpp)
            TAKE(g->aux_copy, uint8_t, (uint64_t)cap * g->aux_row_bytes);
        if (per_level)
            per_level[0] = (size_t)off;
    } else {
        TAKE(g->src_ptr, const uint8_t *, cap);
        if (g->aux_bpp)
            TAKE(g->aux_ptr, const uint8_t *, cap);
    }
    TAKE(g->src_tag, int32_t, cap);
    TAKE(g->scratch, uint32_t, (uint64_t)g->scratch_rows * g->scratch_len);
    if (base)
        g->src_cap = cap;
    for (int i = 0; i < g->nnodes; i++) {
        bg_node_t *n = &g->node[i];
        if (i == g->out_node)
            continue;
        const uint64_t before = off;
        const int c = imax(n->need, 1);
        TAKE(n->buf, uint32_t, (uint64_t)c * (uint64_t)n->w * (uint64_t)n->ch);
        TAKE(n->tag, int32_t, c);
        if (base)
            n->cap = c;
        if (per_level && n->level >= 0 && n->level <= BLOOM_MAX_LEVELS)
            per_level[n->level] += (size_t)(off - before);
    }
#undef TAKE
    return off;
}

/* ---- frames ------------------------------------------------------------ */

bloom_status_t bloom_graph_begin(bloom_graph_t *g)
{
    g->src_n = 0;
    g->failed = false;
    for (int i = 0; i < g->src_cap; i++)
        g->src_tag[i] = -1;
    for (int i = 0; i < g->nnodes; i++) {
        bg_node_t *n = &g->node[i];
        n->next = 0;
        for (int s = 0; s < n->cap; s++)
            n->tag[s] = -1;
    }
    return BLOOM_OK;
}

bloom_status_t bloom_graph_push(bloom_graph_t *g, const void *src_row, const void *aux_row)
{
    if (!src_row || (g->aux_bpp && !aux_row))
        return g->aux_bpp && !aux_row ? BLOOM_E_AUX : BLOOM_E_NULL;
    if (!g->aux_bpp && aux_row) /* as the default pipeline: a plane the preset does not read */
        return BLOOM_E_AUX;
    if (g->src_n >= g->h[0])
        return BLOOM_E_STATE;
    const int r = g->src_n, slot = r % g->src_cap;
    if (r - g->src_cap >= oldest_of(g, BG_SRC))
        return BLOOM_E_BUSY;
    if (g->src_copy) {
        memcpy(g->src_copy + (size_t)slot * g->src_row_bytes, src_row, g->src_row_bytes);
        if (g->aux_bpp)
            memcpy(g->aux_copy + (size_t)slot * g->aux_row_bytes, aux_row, g->aux_row_bytes);
    } else {
        g->src_ptr[slot] = (const uint8_t *)src_row;
        if (g->aux_bpp)
            g->aux_ptr[slot] = (const uint8_t *)aux_row;
    }
    g->src_tag[slot] = r;
    g->src_n++;
    return BLOOM_OK;
}

bloom_status_t bloom_graph_pull(bloom_graph_t *g, void *dst_row)
{
    bg_node_t *o = &g->node[g->out_node];
    const int y = o->next;
    if (y >= g->h[0])
        return BLOOM_DONE;
    if (y >= g->src_n || !ensure_inputs(g, o, y))
        return g->failed ? BLOOM_E_INTERNAL : BLOOM_AGAIN;
    run_row(g, o, y, dst_row);
    if (g->failed)
        return BLOOM_E_INTERNAL;
    o->next++;
    return BLOOM_OK;
}

#else
typedef int bloom_graph_unused_t; /* ISO C: a translation unit is not empty */
#endif
