/* The engine's set-up: planning a configuration (the preset's graph, built
 * with graph/bloom_graph.c; a tile's window and columns, bloom_tile.c; the
 * dry run, bloom_sched.c), sizing and carving the caller's workspace, and
 * the start of a frame. The row, band and frame calls are bloom_frame.c.
 *
 * Every preset, the default included, is a graph of row stages built by its
 * hooks (bloom_preset_<name>.c); one scheduler runs them all. */
#include <string.h>

#include "bloom_engine.h"
#include "bloom_internal.h"
#include "bloom_stages.h"

#if BLOOM_USE_S16
#define D1_16 bg_fn_d1_16
#else
#define D1_16 bg_fn_d1 /* (never compared) */
#endif

#if BLOOM_USE_SKIP
/* The largest code of each width whose decoded value is at most cut: rows
 * without a larger code contribute nothing to the first stage. */
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

static void set_dark(bloom_t *g, uint32_t cut)
{
    const bool lin = g->row.par.out.linear;
    (void)lin;
#if BLOOM_USE_RGB888 || BLOOM_USE_XRGB8888
    g->row.dark.c8 = dark_code(cut, lin, bloom_srgb_dec8, 255);
#endif
#if BLOOM_USE_RGB565
    g->row.dark.c6 = dark_code(cut, lin, bloom_srgb_dec6, 63);
    g->row.dark.c5 = dark_code(cut, lin, bloom_srgb_dec5, 31);
#endif
    g->row.dark.q16 = cut >> BLOOM_Q16_SHIFT; /* min(w, 2^24 - 1) << shift <= cut */
#if BLOOM_USE_RGBF32
    if (g->cfg.in_fmt == BLOOM_FMT_RGBF32) {
        /* the largest positive float bits decoding to at most cut: the
         * decode is monotone in them (bisection, 31 steps; +Inf when all are) */
        uint32_t lo = 0, hi = 0x7F800000u;
        if (bloom_f32_to_lin(hi) <= cut)
            lo = hi;
        while (hi - lo > 1u) {
            const uint32_t mid = lo + (hi - lo) / 2u;
            if (bloom_f32_to_lin(mid) <= cut)
                lo = mid;
            else
                hi = mid;
        }
        g->row.dark.q16 = lo;
    }
#endif
}
#endif

/* The graph over the window x0, y0, w x h of the frame (no dry run yet):
 * the preset's build hook makes it from the configuration, and the
 * parameters it returns go to the row context. */
static bloom_status_t plan_window(bloom_t *g, const bloom_config_t *cfg, bg_node_t *nodes, int cap, int x0,
                                  int y0, int w, int h)
{
    const bloom_preset_ops_t *ops = bloom_preset_ops(cfg->preset);
    if (!ops)
        return BLOOM_E_PRESET;
    memset(g, 0, sizeof *g); /* the nodes are set as they are made */
    g->cfg = *cfg;
    bg_graph_t *gr = &g->gr;
    bg_ctx_t *row = &g->row;
    gr->cfg = row->cfg = &g->cfg;
    gr->node = nodes;
    row->node = nodes;
    gr->node_cap = cap;
#if !BLOOM_SMALL /* (else the window is the frame, bg_win_x/y are 0) */
    gr->frame_w = cfg->width;
    gr->frame_h = cfg->height;
    row->win_x = x0;
    row->win_y = y0;
#else
    (void)x0;
    (void)y0;
#endif
    gr->w[0] = row->w0 = w;
    gr->h[0] = h;
    bg_levels(gr, cfg->levels);
    bg_params_t *par = &row->par;                    /* what the build hook returns, the engine's first */
    par->knee.t = cfg->threshold << BLOOM_Q16_SHIFT; /* Q16.16 -> internal, exact */
    par->knee.k = (uint32_t)(((uint64_t)par->knee.t * cfg->soft_knee + 32768u) >> 16);
    par->out.in_fmt = cfg->in_fmt;
    par->out.out_fmt = cfg->out_fmt;
    par->out.linear = (cfg->flags & BLOOM_FLAG_LINEAR) != 0;
    par->out.debug = (cfg->flags & BLOOM_FLAG_DEBUG_VIEW) != 0;
    par->out.intensity = bloom_srgb_to_linear_q16(cfg->intensity);
    par->dark_cut = BG_NO_CUT;
    par->scratch_len = (size_t)w * 3u + 16u; /* (scratch_rows, views: 0 from the memset) */
    gr->out_node = -1;
    bloom_status_t st = ops->build(gr, par);
    if (st != BLOOM_OK)
        return st;
    if (gr->failed && gr->nnodes == cap && cap < BG_MAX_NODES)
        return BLOOM_E_WORKSPACE; /* bloom_init's buffer: too small for the nodes */
    if (gr->failed)
        return BLOOM_E_INTERNAL;
#if !BLOOM_SMALL || BLOOM_USE_GRAPH /* a build hook's mistakes (the default's graph alone is
                                        checked by every other build) */
    if (gr->out_node < 0 || gr->out_node != gr->nnodes - 1 || nodes[gr->out_node].h != gr->h[0] ||
        par->scratch_rows < 0 || par->scratch_rows > BG_SCRATCH)
        return BLOOM_E_INTERNAL;
#endif
    g->row.skip = BLOOM_USE_SKIP && !(cfg->flags & BLOOM_FLAG_NO_SKIP);
    bloom_kernels_select(&row->kern, cfg->flags);
    row->src_bpp = (uint8_t)bloom_format_bpp(cfg->in_fmt);
#if BLOOM_USE_GRAPH
    row->aux_bpp = cfg->aux_fmt == BLOOM_AUX_U16 ? 2 : cfg->aux_fmt == BLOOM_AUX_U8 ? 1 : 0;
#endif
    g->src_row_bytes = (size_t)w * (size_t)row->src_bpp;
    g->aux_row_bytes = (size_t)w * (size_t)bg_aux_bpp(row);
#if BLOOM_USE_GRAPH /* (a list worth its code where graphs are big) */
    for (int i = 0; i < gr->nnodes; i++)
        for (int j = 0; j < nodes[i].nin; j++)
            if (nodes[i].in[j].node < 0) {
                g->src_reader[g->nsrc_readers++] = (int8_t)i;
                break;
            }
#endif
#if BLOOM_USE_SKIP
    g->row.dark_src = g->row.skip && par->dark_cut != BG_NO_CUT;
    if (g->row.dark_src)
        set_dark(g, par->dark_cut);
#else
    (void)par->dark_cut;
#endif
    return BLOOM_OK;
}

bloom_status_t bloom_plan(bloom_t *g, const bloom_config_t *cfg, bg_node_t *nodes, int cap)
{
    bloom_status_t st = plan_window(g, cfg, nodes, cap, 0, 0, cfg->width, cfg->height);
#if !BLOOM_SMALL
    if (st == BLOOM_OK && cfg->tile_w > 0) {
        /* the graph over the whole frame says how far its pixels reach; the
         * window is the tile with that halo, out to multiples of the
         * deepest level's pixel so its levels halve as the frame's, and
         * the graph is built again over it */
        int x0, x1, y0, y1;
        bloom_tile_window(g, cfg, &x0, &y0, &x1, &y1);
        st = plan_window(g, cfg, nodes, cap, x0, y0, x1 - x0, y1 - y0);
        g->row.tiled = true;
        g->tile_x0 = cfg->tile_x - x0;
        g->tile_x1 = g->tile_x0 + cfg->tile_w;
        g->tile_y0 = cfg->tile_y - y0;
        g->tile_y1 = g->tile_y0 + cfg->tile_h;
        if (st == BLOOM_OK) {
            bloom_tile_cut(g);
            /* the tile's row written in place when the output row function
             * can start at the tile's column (an even one: the tents pair
             * the output's columns; with the flat kernels, which every set
             * but the size build's has), else made into out_row and copied
             * out */
            const bg_node_t *o = &g->gr.node[g->gr.out_node];
            const int lead = g->tile_x0 - o->xa;
            g->out_direct = bg_out_from_x0(o->fn) && !(lead & 1) && g->row.kern.htent_eo;
            g->row.out_x0 = g->out_direct ? lead : 0;
            g->row.out_src_x = g->out_direct ? g->tile_x0 : 0; /* (input_step) */
        }
    }
#endif
    if (st == BLOOM_OK)
        bloom_dry_frame(g);
    return st;
}

/* `bytes` at offset *off of base (NULL: only counted), *off moved on,
 * 8-byte aligned (BLOOM_TAKE as a function: one copy of the 64-bit sums). */
static void *take(uint8_t *base, uint64_t *off, uint64_t bytes)
{
    void *p = base ? base + (size_t)*off : NULL;
    *off = bloom_align8(*off + bytes);
    return p;
}

#if BLOOM_SCHED_TABLE
/* The byte offset, in the rows of input i of node n, of the first column n
 * reads (a tile's window: bg_in_w; 0 without a tile). */
static uint32_t input_step(const bloom_t *g, const bg_node_t *n, int i)
{
#if !BLOOM_SMALL
    if (g->row.tiled) {
        const int from = n->in[i].node;
        if (g->out_direct && n == &g->gr.node[g->gr.out_node] && from == BG_SRC)
            return 0; /* the row function adds the tile's column (bg_out_src_x) */
        const bg_node_t *src = from >= 0 ? &g->gr.node[from] : NULL;
        const int off = bg_base(n->in[i].map, n->xa) - (src ? src->xa : 0);
        const size_t bytes = src ? (size_t)src->ch * BG_SB(src)
                                 : (size_t)(from == BG_SRC ? g->row.src_bpp : bg_aux_bpp(&g->row));
        return (uint32_t)((size_t)off * bytes);
    }
#endif
    (void)g;
    (void)n;
    (void)i;
    return 0;
}
#endif

#if BLOOM_SCHED_TABLE
/* Each input's gather, for the row calls, from offset off of base (NULL:
 * only counted; returns the offset after them); cap: the source ring's
 * slots. A tile's inputs read from a column on: their own view of the
 * slots' pointers, when the slots stay (node rings, copied source rows);
 * else (the caller's own rows) the offset is added per row read. */
static uint64_t lay_out_gathers(bloom_t *g, uint8_t *base, uint64_t off, int cap)
{
    int nin = 0;
    for (int i = 0; i < g->gr.nnodes; i++)
        nin += g->gr.node[i].nin;
    bg_gather_t *gat = (bg_gather_t *)take(base, &off, (uint64_t)nin * sizeof(bg_gather_t));
    for (int i = 0; i < g->gr.nnodes; i++) {
        bg_node_t *n = &g->gr.node[i];
        if (base)
            n->gat = gat;
        for (int j = 0; j < n->nin; j++) {
            const bg_input_t *in = &n->in[j];
            const bg_node_t *f = in->node >= 0 ? &g->gr.node[in->node] : NULL;
            const int c = f ? imax(f->need, 1) : cap;
            const uint32_t step = input_step(g, n, j);
            const void **view = NULL;
            /* (the flag, not g->src_copy: that is NULL while only counting,
             * and a count without the views made tiles of copied rows
             * overrun their workspace) */
            if (step && (f || (g->cfg.flags & BLOOM_FLAG_COPY_SOURCE)))
                view = (const void **)take(base, &off, 2u * (uint64_t)c * sizeof(const void *));
            if (!base)
                continue;
            bg_gather_t *ga = gat++;
            ga->ring = f ? f->rowp : !BLOOM_USE_GRAPH || in->node == BG_SRC ? g->src_ptr : g->aux_ptr;
            ga->tags = f ? f->tag : g->src_tag;
            ga->cap = (uint16_t)c;
            ga->h = (uint16_t)(f ? f->h : g->gr.h[0]);
            ga->add = view ? 0u : step; /* (the cursor: bloom_begin) */
            ga->zb = !f ? (const void *)g->src_zb : c > BG_ZB_CAP ? NULL : &g->gr.node[in->node].zb;
            ga->zw = !f;
            ga->lo = in->lo;
            ga->n1 = (uint8_t)(in->hi - in->lo);
            ga->sh = (uint8_t)(in->map == BG_DOWN ? 0 : in->map == BG_SAME ? 1 : 2);
            ga->zmask = (2u << (in->hi - in->lo)) - 1u;
            ga->zaux = in->node == BG_AUX;
            ga->fend = (uint16_t)(ga->add || !ga->zb ? 0 : imax(ga->h - (in->hi - in->lo), 0));
            for (int s = 0; view && s < 2 * c; s++)
                view[s] = (const uint8_t *)ga->ring[s] + step;
            if (view)
                ga->ring = view;
        }
    }
    return off;
}
#endif

/* Lay the rings out after the engine struct; with base NULL only count.
 * Counted in 64 bits: on a 32-bit target a huge configuration must be
 * refused (BLOOM_E_TOO_BIG), not wrap around. */
uint64_t bloom_carve(bloom_t *g, uint8_t *base, size_t *per_level)
{
    uint64_t off = bloom_align8(sizeof(bloom_t)) + bloom_align8(sizeof(bg_node_t) * (uint64_t)g->gr.nnodes);
    const int cap = imax(g->need_src, 1);
    const uint64_t ucap = (uint64_t)cap;
    if (g->cfg.flags & BLOOM_FLAG_COPY_SOURCE) {
        const uint64_t before = off;
        g->src_copy = (uint8_t *)take(base, &off, ucap * g->src_row_bytes);
        if (bg_aux_bpp(&g->row))
            g->aux_copy = (uint8_t *)take(base, &off, ucap * g->aux_row_bytes);
        if (per_level)
            per_level[0] += (size_t)(off - before);
    }
    const uint64_t copies = BG_RING_COPIES * ucap; /* (pointers and tags) */
    if (BLOOM_SCHED_TABLE ||
        !(g->cfg.flags & BLOOM_FLAG_COPY_SOURCE)) { /* (the size build finds copies by their slot) */
        g->src_ptr = (const void **)take(base, &off, copies * sizeof(const void *));
        if (bg_aux_bpp(&g->row))
            g->aux_ptr = (const void **)take(base, &off, copies * sizeof(const void *));
    }
#if BLOOM_SCHED_TABLE
    for (int s = 0; base && g->src_copy && s < (int)copies; s++) { /* the copies' slots */
        g->src_ptr[s] = g->src_copy + (size_t)(s % cap) * g->src_row_bytes;
        if (bg_aux_bpp(&g->row))
            g->aux_ptr[s] = g->aux_copy + (size_t)(s % cap) * g->aux_row_bytes;
    }
#endif
    g->src_tag = (int32_t *)take(base, &off, copies * sizeof(int32_t));
#if BLOOM_SCHED_TABLE
    g->src_zb = (uint32_t *)take(base, &off, (copies + 31) / 32 * sizeof(uint32_t));
#endif
    if (bg_tiled(&g->row) && !g->out_direct)
        g->out_row = (uint8_t *)take(
            base, &off, (uint64_t)g->gr.node[g->gr.out_node].w * (uint64_t)bloom_bpp(g->cfg.out_fmt));
#if !BLOOM_SMALL
    /* the default's level-1 node keeps its lower rows' sums for the next
     * row (bloom_d1_keep_t): one entry per column pair of its row, 8 bytes
     * a source column; for RGB888 and XRGB8888 (bloom_row_box_src_kept_c),
     * not RGB565, the microcontrollers' format, whose QVGA frame stays
     * within 48 KB (tests/test_core.c) */
    g->d1_keep_n = 0;
    g->row.d1_keep = NULL;
    const bool keeps = g->cfg.in_fmt == BLOOM_FMT_RGB888 || g->cfg.in_fmt == BLOOM_FMT_XRGB8888;
    for (int i = 0; keeps && i < g->gr.nnodes; i++) {
        const bg_node_t *n = &g->gr.node[i];
        if (n->fn != bg_fn_d1 && !(BLOOM_USE_S16 && n->fn == D1_16))
            continue;
        const uint64_t e = (uint64_t)n->w + 1u;
        g->d1_keep.sum = (uint32_t *)take(base, &off, e * 3u * sizeof(uint32_t));
        g->d1_keep.tag = (int32_t *)take(base, &off, e * sizeof(int32_t));
        g->d1_keep_n = (int)e;
        g->row.d1_keep = base ? &g->d1_keep : NULL;
        break;
    }
#endif
    g->row.scratch = (uint32_t *)take(
        base, &off, (uint64_t)g->row.par.scratch_rows * g->row.par.scratch_len * sizeof(uint32_t));
#if BLOOM_SCHED_TABLE
    g->sched = (uint8_t *)take(base, &off, (uint64_t)g->sched_len);
#endif
    if (base)
        g->src_cap = cap;
    for (int i = 0; i < g->gr.nnodes; i++) {
        bg_node_t *n = &g->gr.node[i];
        if (i == g->gr.out_node)
            continue;
        const uint64_t before = off;
        const int c = imax(n->need, 1);
        const uint64_t bytes = (uint64_t)c * bg_row_bytes(n);
        n->buf = (uint32_t *)take(base, &off, bytes);
#if BLOOM_SCHED_TABLE
        n->rowp = (const void **)take(base, &off, 2u * (uint64_t)c * sizeof(const void *));
        for (int s = 0; base && s < 2 * c; s++)
            n->rowp[s] = (const uint8_t *)n->buf + (size_t)(s % c) * bg_row_bytes(n);
#endif
        n->tag = (int32_t *)take(base, &off, BG_RING_COPIES * (uint64_t)c * sizeof(int32_t));
        if (base) { /* zeros in every slot, said by the tags: a zero row then costs nothing */
            n->cap = (uint16_t)c;
            if (BLOOM_USE_SKIP)
                memset(n->buf, 0, (size_t)bytes);
            /* every tag byte 0x40: the zero bit (bit 30) set in each tag,
             * whatever the byte order; bloom_begin (bloom_init's last
             * step) then makes each "no row", keeping that bit */
            memset(n->tag, BLOOM_USE_SKIP ? 0x40 : 0, BG_RING_COPIES * (size_t)c * sizeof *n->tag);
        }
        if (per_level && n->level >= 0 && n->level <= BLOOM_MAX_LEVELS)
            per_level[n->level] += (size_t)(off - before);
    }
#if BLOOM_SCHED_TABLE
    off = lay_out_gathers(g, base, off, cap);
#endif
    return off;
}

bloom_status_t bloom_query(const bloom_config_t *cfg, bloom_info_t *info)
{
    if (!cfg)
        return BLOOM_E_NULL;
    bloom_status_t st = bloom_validate(cfg);
    if (st != BLOOM_OK)
        return st;
    bloom_t tmp;
    bg_node_t nodes[BG_MAX_NODES];
    st = bloom_plan(&tmp, cfg, nodes, BG_MAX_NODES);
    if (st != BLOOM_OK || !info)
        return st;
    memset(info, 0, sizeof *info);
    info->levels = tmp.gr.L;
    for (int k = 0; k <= tmp.gr.L; k++) {
        info->level_w[k] = tmp.gr.w[k];
        info->level_h[k] = tmp.gr.h[k];
    }
    info->latency_rows = tmp.latency;
    info->source_rows = imax(tmp.need_src, 1);
    info->threshold_q = tmp.row.par.knee.t;
    info->knee_q = tmp.row.par.knee.k;
    info->intensity_q = tmp.row.par.out.intensity;
#if !BLOOM_SMALL /* (else no tiles: the whole frame, from 0, 0) */
    info->src_x = tmp.row.win_x;
    info->src_y = tmp.row.win_y;
#endif
#if BLOOM_USE_S16
    info->sample_bits = tmp.row.par.s16 ? 16 : 32;
    info->sample_frac = BLOOM_LIN_BITS - tmp.row.par.s16;
#else
    info->sample_bits = 32;
    info->sample_frac = BLOOM_LIN_BITS;
#endif
    info->src_w = tmp.gr.w[0];
    info->src_h = tmp.gr.h[0];
#if BLOOM_SCHED_TABLE /* (else 0, from the memset) */
    info->schedule_bytes = (size_t)tmp.sched_len;
#endif
    const uint64_t bytes = bloom_carve(&tmp, NULL, info->ring_bytes);
    if (bytes > SIZE_MAX)
        return BLOOM_E_TOO_BIG;
    info->workspace_bytes = (size_t)bytes;
    return BLOOM_OK;
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
    const size_t head = (size_t)bloom_align8(sizeof(bloom_t));
    if (ws_bytes < head + sizeof(bg_node_t))
        return BLOOM_E_WORKSPACE;
    /* Plan in place (no engine-sized stack frame), the nodes right after
     * the struct; a buffer found too small afterwards is refused, its first
     * bytes used as scratch. */
    bloom_t *g = (bloom_t *)ws;
    const size_t room = (ws_bytes - head) / sizeof(bg_node_t);
    st = bloom_plan(g, cfg, (bg_node_t *)(void *)((uint8_t *)ws + head),
                    room < BG_MAX_NODES ? (int)room : BG_MAX_NODES);
    if (st != BLOOM_OK)
        return st;
    const uint64_t need = bloom_carve(g, NULL, NULL);
    if (need > SIZE_MAX)
        return BLOOM_E_TOO_BIG;
    if (ws_bytes < need)
        return BLOOM_E_WORKSPACE;
    if (bloom_carve(g, (uint8_t *)ws, NULL) != need) /* the carving ends where sizing said */
        return BLOOM_E_INTERNAL;
#if BLOOM_SCHED_TABLE
    /* the dry run again, now that the schedule has its place: it writes
     * the same firings it counted (and finds the same ring sizes) */
    const int len = g->sched_len;
    bloom_dry_frame(g);
    if (g->sched_len != len || g->failed) /* (failed: a repeat of the period that differs) */
        return BLOOM_E_INTERNAL;
#endif
    *out = g;
    return bloom_begin(g);
}

bloom_status_t bloom_begin(bloom_t *b)
{
    if (!b)
        return BLOOM_E_NULL;
    b->src_n = 0;
    b->out_rows = 0;
    b->failed = false;
#if BLOOM_SCHED_TABLE
    b->src_put = 0;
    b->sched_at = 0;
    b->src_free = 0;
    b->src_seen = 0;
    b->fold_rep = 0;
    b->walk_end = b->fold_m > 1 ? b->fold_e : b->sched_len;
#endif
    /* an empty source slot: a negative row (no row matches it), without
     * the zero bit (were it read, it would not pass for a dark row) */
    for (int i = 0; i < BG_RING_COPIES * b->src_cap; i++)
        b->src_tag[i] = -1 - BLOOM_TAG_ZERO;
#if !BLOOM_SMALL
    if (b->row.d1_keep) /* nothing kept from the frame before */
        memset(b->d1_keep.tag, 0xFF, (size_t)b->d1_keep_n * sizeof *b->d1_keep.tag);
#endif
#if BLOOM_SCHED_TABLE
    memset(b->src_zb, 0, (size_t)(BG_RING_COPIES * b->src_cap + 31) / 32 * sizeof *b->src_zb);
#endif
    /* node slots keep their zero bit: a slot that holds zeros still does */
    for (int i = 0; i < b->gr.nnodes; i++) {
        bg_node_t *n = &b->gr.node[i];
        n->next = 0;
#if BLOOM_SCHED_TABLE
        n->put = 0;
        for (int j = 0; j < n->nin; j++)
            n->gat[j].off = 0; /* row 0 is in slot 0 */
#endif
#if BLOOM_SCHED_TABLE
        n->zb = 0;
#endif
        for (int s = 0; s < BG_RING_COPIES * n->cap; s++) {
            n->tag[s] = (n->tag[s] & BLOOM_TAG_ZERO) | 0x3FFFFFFF;
#if BLOOM_SCHED_TABLE
            if (s < 64)
                n->zb |= (uint64_t)((uint32_t)n->tag[s] >> 30 & 1u) << s;
#endif
        }
    }
    return BLOOM_OK;
}
