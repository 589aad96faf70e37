/* bloom_sim OpenEXR input through the OpenEXRCore C API (Debian
 * libopenexr-dev). Reads part 0, scanline or tiled (level 0 of a
 * mip/rip-mapped file), any compression the library decodes, half, float or
 * uint samples as float. Channels R, G, B (or Y alone, as grey) of the
 * default layer; other channels (A, Z, layers) are ignored; subsampled
 * channels and deep data are refused. The data window is the image; the
 * display window is ignored. Built with -DSIM_NO_EXR there is no EXR. */
#include "sim.h"

#include <stdlib.h>
#include <string.h>

#ifdef SIM_NO_EXR

int sim_exr_available(void)
{
    return 0;
}

int sim_exr_read(const char *path, img_t *img, char *err, size_t errlen)
{
    (void)path;
    memset(img, 0, sizeof *img);
    return sim_errf(err, errlen, "OpenEXR support not built in (needs libopenexr-dev)");
}

#else

#include <openexr.h>

int sim_exr_available(void)
{
    return 1;
}

/* The library reports details through a callback; the tool is single
 * threaded, so the last message is simply kept here. */
static char exr_msg[512];

static void on_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    snprintf(exr_msg, sizeof exr_msg, "%s", msg ? msg : exr_get_default_error_message(code));
}

static int fail(exr_result_t rv, const char *what, char *err, size_t errlen)
{
    return sim_errf(err, errlen, "OpenEXR %s failed: %s", what,
                    exr_msg[0] ? exr_msg : exr_get_default_error_message(rv));
}

typedef struct {
    exr_context_t ctx;
    exr_decode_pipeline_t dec;
    int started; /* dec initialized */
    int nch, w, h;
    int cap; /* image rows allocated so far */
    img_t *img;
    float *scratch; /* where the channels the tool does not use are decoded */
    size_t scratch_n;
} exr_rd_t;

static int slot_of(const exr_rd_t *r, const char *name)
{
    if (r->nch == 1)
        return !strcmp(name, "Y") ? 0 : -1;
    return !strcmp(name, "R") ? 0 : !strcmp(name, "G") ? 1 : !strcmp(name, "B") ? 2 : -1;
}

/* Decodes one chunk whose top-left pixel is (px, py) of the image. */
static int decode_chunk(exr_rd_t *r, const exr_chunk_info_t *ci, int px, int py, char *err, size_t errlen)
{
    if (px < 0 || py < 0 || ci->width < 1 || ci->height < 1 || (int64_t)px + ci->width > r->w ||
        (int64_t)py + ci->height > r->h)
        return sim_errf(err, errlen, "OpenEXR chunk %d lies outside the data window", ci->idx);
    /* chunks come top to bottom: the image grows with the rows they cover */
    if (sim_img_rows(r->img, py + ci->height, &r->cap))
        return sim_errf(err, errlen, "out of memory for a %dx%d image", r->w, r->h);
    exr_result_t rv = r->started ? exr_decoding_update(r->ctx, 0, ci, &r->dec)
                                 : exr_decoding_initialize(r->ctx, 0, ci, &r->dec);
    if (rv != EXR_ERR_SUCCESS)
        return fail(rv, "chunk setup", err, errlen);
    r->started = 1;
    for (int c = 0; c < r->dec.channel_count; c++) {
        exr_coding_channel_info_t *ch = &r->dec.channels[c];
        int s = slot_of(r, ch->channel_name);
        if (s < 0) {
            /* not wanted: decoded into scratch rather than skipped with a NULL
             * pointer (some of the library's unpack paths write through it
             * regardless: a fuzzer finding, tests/fuzz/README.md) */
            const size_t n = (size_t)ci->width * (size_t)ci->height;
            if (n > r->scratch_n) {
                float *p = realloc(r->scratch, n * sizeof *p);
                if (!p)
                    return sim_errf(err, errlen, "out of memory for a %dx%d chunk", ci->width, ci->height);
                r->scratch = p;
                r->scratch_n = n;
            }
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = 4;
            ch->user_line_stride = ci->width * 4;
            ch->decode_to_ptr = (uint8_t *)r->scratch;
            continue;
        }
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
        ch->user_pixel_stride = r->nch * 4;
        ch->user_line_stride = r->w * r->nch * 4;
        ch->decode_to_ptr =
            (uint8_t *)(r->img->f32 + ((size_t)py * (size_t)r->w + (size_t)px) * (size_t)r->nch + (size_t)s);
    }
    if ((rv = exr_decoding_choose_default_routines(r->ctx, 0, &r->dec)) != EXR_ERR_SUCCESS)
        return fail(rv, "decoder setup", err, errlen);
    if ((rv = exr_decoding_run(r->ctx, 0, &r->dec)) != EXR_ERR_SUCCESS)
        return fail(rv, "decode", err, errlen);
    return 0;
}

static int read_part(exr_rd_t *r, char *err, size_t errlen)
{
    exr_storage_t st;
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *cl;
    exr_result_t rv;
    if ((rv = exr_get_storage(r->ctx, 0, &st)) || (rv = exr_get_data_window(r->ctx, 0, &dw)) ||
        (rv = exr_get_channels(r->ctx, 0, &cl)))
        return fail(rv, "header", err, errlen);
    if (st != EXR_STORAGE_SCANLINE && st != EXR_STORAGE_TILED)
        return sim_errf(err, errlen, "deep OpenEXR data not supported");
    const int64_t w = (int64_t)dw.max.x - dw.min.x + 1, h = (int64_t)dw.max.y - dw.min.y + 1;
    if (w < 1 || h < 1)
        return sim_errf(err, errlen, "OpenEXR data window %lldx%lld is empty", (long long)w, (long long)h);
    if (w > BLOOM_MAX_DIM || h > BLOOM_MAX_DIM)
        return sim_errf(err, errlen,
                        "OpenEXR data window %lldx%lld is larger than the engine's limit of %d per side",
                        (long long)w, (long long)h, BLOOM_MAX_DIM);
    int has[4] = {0, 0, 0, 0}; /* R G B Y */
    char names[256] = "";
    for (int i = 0; i < cl->num_channels; i++) {
        const exr_attr_chlist_entry_t *e = &cl->entries[i];
        const char *nm = e->name.str;
        int k = !strcmp(nm, "R")   ? 0
                : !strcmp(nm, "G") ? 1
                : !strcmp(nm, "B") ? 2
                : !strcmp(nm, "Y") ? 3
                                   : -1;
        size_t used = strlen(names);
        snprintf(names + used, sizeof names - used, "%s%s", used ? ", " : "", nm);
        if (k < 0)
            continue;
        if (e->x_sampling != 1 || e->y_sampling != 1)
            return sim_errf(err, errlen, "OpenEXR channel %s is subsampled: not supported", nm);
        has[k] = 1;
    }
    r->nch = has[0] && has[1] && has[2] ? 3 : has[3] ? 1 : 0;
    if (!r->nch)
        return sim_errf(err, errlen, "OpenEXR file has no R, G, B (or Y) channels (it has: %s)",
                        names[0] ? names : "none");
    r->w = (int)w;
    r->h = (int)h;
    r->img->width = r->w;
    r->img->height = r->h;
    r->img->channels = r->nch;
    r->img->maxval = 0; /* floats; the samples come with the chunks (decode_chunk) */
    exr_chunk_info_t ci;
    if (st == EXR_STORAGE_SCANLINE) {
        int32_t lines;
        if ((rv = exr_get_scanlines_per_chunk(r->ctx, 0, &lines)) || lines < 1)
            return fail(rv, "header", err, errlen);
        for (int64_t y = dw.min.y; y <= dw.max.y; y += lines) {
            if ((rv = exr_read_scanline_chunk_info(r->ctx, 0, (int)y, &ci)))
                return fail(rv, "chunk read", err, errlen);
            /* the chunk's corner in the image, refused (-1) when outside */
            const int64_t dx = (int64_t)ci.start_x - dw.min.x, dy = (int64_t)ci.start_y - dw.min.y;
            if (decode_chunk(r, &ci, dx < 0 || dx > r->w ? -1 : (int)dx, dy < 0 || dy > r->h ? -1 : (int)dy,
                             err, errlen))
                return -1;
        }
        return 0;
    }
    int32_t tw, th;
    if ((rv = exr_get_tile_sizes(r->ctx, 0, 0, 0, &tw, &th)) || tw < 1 || th < 1)
        return fail(rv, "tile header", err, errlen);
    /* in 64 bits: the library bounds tile sizes, this loop need not trust it */
    const int64_t ntx = ((int64_t)r->w + tw - 1) / tw, nty = ((int64_t)r->h + th - 1) / th;
    for (int ty = 0; ty < nty; ty++)
        for (int tx = 0; tx < ntx; tx++) {
            if ((rv = exr_read_tile_chunk_info(r->ctx, 0, tx, ty, 0, 0, &ci)))
                return fail(rv, "tile read", err, errlen);
            if (decode_chunk(r, &ci, (int)((int64_t)tx * tw), (int)((int64_t)ty * th), err, errlen))
                return -1;
        }
    return 0;
}

int sim_exr_read(const char *path, img_t *img, char *err, size_t errlen)
{
    memset(img, 0, sizeof *img);
    exr_rd_t r;
    memset(&r, 0, sizeof r);
    r.img = img;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
    exr_msg[0] = '\0';
    exr_result_t rv = exr_start_read(&r.ctx, path, &init);
    int rc = rv != EXR_ERR_SUCCESS ? fail(rv, "header read", err, errlen) : read_part(&r, err, errlen);
    if (r.started)
        exr_decoding_destroy(r.ctx, &r.dec);
    if (r.ctx)
        exr_finish(&r.ctx);
    free(r.scratch);
    if (rc)
        img_free(img);
    return rc;
}

#endif
