/* C interface of the OpenCV 4 side of the benchmark (bench_opencv.cpp).
 * Every variant reads an RGB888 frame and writes an RGB888 frame; the
 * C side times the calls and compares the outputs with the engine. */
#ifndef BENCH_CV_H
#define BENCH_CV_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    /* The engine's algorithm in float, the box down as cv::boxFilter 4x4
     * (anchor 1,1) over every pixel + decimation (cv::resize INTER_NEAREST). */
    BCV_SAME_BOXFILTER = 0,
    /* The same, the box down as cv::resize INTER_AREA (exact 2x) on the
     * image shifted by one pixel + a 2x2 cv::boxFilter at the lower level. */
    BCV_SAME_AREA = 1,
    /* The tutorial bloom in 8-bit sRGB: cv::resize to half, cv::threshold,
     * cv::GaussianBlur, cv::resize back, cv::addWeighted. */
    BCV_TUTORIAL = 2
};

#define BCV_MAX_LEVELS 16

typedef struct {
    int levels;                                                   /* L actually built (bloom_query) */
    int level_w[BCV_MAX_LEVELS + 1], level_h[BCV_MAX_LEVELS + 1]; /* [0] = frame */
    float decode_lut[256];                                        /* sRGB code -> linear light */
    double threshold, knee;                                       /* t and t*s of the knee, linear */
    double intensity;                                             /* linear I of the composite */
    int tutorial_code;                                            /* tutorial threshold, 8-bit sRGB code */
    double tutorial_sigma;  /* tutorial Gaussian sigma, full-resolution pixels */
    double tutorial_weight; /* tutorial addWeighted weight of the glow */
} bcv_params_t;

typedef struct bcv_ctx bcv_ctx_t;

const char *bcv_version(void);
/* The "Parallel framework" line of cv::getBuildInformation(). */
const char *bcv_parallel_framework(void);
/* threads 0: cv::setNumThreads(0) (OpenCV runs every function sequentially);
 * -1: back to OpenCV's default. Returns cv::getNumThreads() afterwards. */
int bcv_set_threads(int threads);

/* Work buffers for one frame size (kept between runs, as an application
 * would keep them). NULL on failure (bcv_error says why). */
bcv_ctx_t *bcv_create(int w, int h, const bcv_params_t *p);
/* One frame. Returns 0, or -1 (bcv_error says why). */
int bcv_run(bcv_ctx_t *c, int kind, const uint8_t *src, size_t src_stride, uint8_t *dst, size_t dst_stride);
void bcv_destroy(bcv_ctx_t *c);
const char *bcv_error(void);

#ifdef __cplusplus
}
#endif
#endif
