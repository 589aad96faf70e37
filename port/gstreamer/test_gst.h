/* make test-gst: helpers of port/gstreamer/test_gst.c (test_gst_util.c):
 * frames, the engine run directly, buffers with a chosen stride, the
 * appsrc ! bloom ! appsink pipeline, PNM files. */
#ifndef TEST_GST_H
#define TEST_GST_H

#include <gst/app/app.h>
#include <gst/check/gstcheck.h>
#include <gst/check/gstharness.h>
#include <gst/video/video.h>

#include "bloom.h"

typedef struct {
    GstVideoFormat vf;
    bloom_format_t bf;
    int bpp;
    const char *name;
} tg_fmt_t;

#define TG_NFMTS 3
extern const tg_fmt_t tg_fmts[TG_NFMTS]; /* RGB, BGRx, RGB16 */

/* A test frame: a dark top third with a few white spots, random codes
 * below; rows stride bytes apart (the padding filled with 0xA5). */
guint8 *tg_frame(const tg_fmt_t *f, int w, int h, int stride, guint32 seed);
/* The unity defaults for w x h frames of f, then preset p's. */
void tg_config(bloom_config_t *c, bloom_preset_t p, int w, int h, bloom_format_t f);
/* The engine itself on src (bloom_process, stride bytes per row in and
 * out), with the aux plane when aux is not NULL; NULL if it refuses cfg. */
guint8 *tg_engine(const bloom_config_t *cfg, const guint8 *src, int stride, const guint8 *aux,
                  int aux_stride);
/* A buffer of the frame with rows `stride` bytes apart (a GstVideoMeta
 * saying so when that is not the default stride). */
GstBuffer *tg_buffer(const tg_fmt_t *f, int w, int h, int stride, const guint8 *px, int px_stride);
/* Whether buf (mapped as a video frame of f, w x h: its own stride) holds
 * exp; on a difference *why (g_free) names the first byte. */
gboolean tg_same(GstBuffer *buf, const tg_fmt_t *f, int w, int h, const guint8 *exp, int exp_stride,
                 char **why);
int tg_default_stride(const tg_fmt_t *f, int w, int h);
char *tg_caps(const tg_fmt_t *f, int w, int h); /* "video/x-raw,format=...", g_free */

/* appsrc name=src ! bloom name=bloom ! appsink name=sink, not started. */
typedef struct {
    GstElement *pipe, *src, *bloom, *sink;
    GstBus *bus;
    int frames;
} tg_pipe_t;
void tg_pipe_new(tg_pipe_t *p, const tg_fmt_t *f, int w, int h);
gboolean tg_pipe_play(tg_pipe_t *p);
/* Push one frame and pull its output (NULL on error or timeout). */
GstBuffer *tg_pipe_run(tg_pipe_t *p, const tg_fmt_t *f, int w, int h, const guint8 *px, int stride);
/* An ERROR or WARNING message's text on the bus within timeout (g_free),
 * or NULL. */
char *tg_bus_text(GstBus *bus, GstMessageType type, GstClockTime timeout);
void tg_pipe_free(tg_pipe_t *p);

/* Binary PNM (P5/P6, maxval <= 255) read whole: the samples, g_free. */
guint8 *tg_read_pnm(const char *path, int *w, int *h, int *channels);
/* A binary PGM, 8-bit (maxval 255) or 16-bit (65535; samples native). */
gboolean tg_write_pgm(const char *path, int w, int h, int wide, const guint8 *data);
/* A test case with the suite's timeout, added to s. */
TCase *tg_tcase(Suite *s, const char *name);
/* The frame and tool tests (test_gst_frames.c), the streaming ones
 * (test_gst_stream.c). */
void tg_add_frame_tests(Suite *s);
void tg_add_stream_tests(Suite *s);
void tg_add_yuy2_tests(Suite *s);   /* test_gst_yuy2.c */
void tg_add_thread_tests(Suite *s); /* test_gst_threads.c: n-threads */

/* The scratch directory (BLOOM_GST_TMP, made if missing). */
const char *tg_tmp(void);

/* A thread (g_thread_new("racer", tg_race, &r)) that sets the integer
 * property `prop` of the element to vals[0], vals[1], ... in turn, every
 * pause_us, until stop is set; flips counts the changes. */
typedef struct {
    GstElement *bloom;
    const char *prop;
    const int *vals;
    int nvals, pause_us;
    gint stop;
    int flips;
} tg_racer_t;
gpointer tg_race(gpointer data);

#endif
