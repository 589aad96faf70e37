// The OpenCV 4 side of the benchmark (bench_cv.h): the engine's bloom written
// with OpenCV's API in float, and the tutorial bloom in 8-bit.
//
// "Same algorithm" (sim/docs/bloom-model.md, CV_32FC3 linear light):
//   decode      cv::LUT, 256-entry float table of the sRGB curve
//   box down    4x4 box at columns 2x-1 .. 2x+2, edges replicated; two ways:
//               BOXFILTER: cv::boxFilter 4x4 with anchor (1,1) (it covers
//                 x-1 .. x+2) at every pixel of the level, BORDER_REPLICATE,
//                 then cv::resize INTER_NEAREST by exactly 1/2 (it keeps
//                 columns 2x); an odd-sized level is first padded by one
//                 replicated row/column (cv::copyMakeBorder), which changes
//                 nothing under the replicate rule and makes the 1/2 exact.
//               AREA: cv::resize INTER_AREA averages columns 2x, 2x+1, not
//                 2x-1 .. 2x+2, so it is not the box by itself: the level is
//                 kept with a replicated border (one column/row on the left
//                 and top, enough on the right and bottom for an exact 2x),
//                 INTER_AREA then gives A(x) = (S(2x-1) + S(2x)) / 2 and a
//                 2x2 cv::boxFilter at the lower level gives
//                 (A(x) + A(x+1)) / 2 = the 4-tap box. Same numbers, a
//                 quarter of the filtering work.
//   knee        cv::split, cv::max, cv::subtract, cv::min, cv::multiply,
//               cv::divide, cv::merge: the model's formula, 1e-5 guards included
//   tent up     cv::resize INTER_NEAREST by exactly 2, then cv::sepFilter2D
//               with [1 2 2 2 1] / 8 on both axes (BORDER_REPLICATE), cropped
//               to the level size. On the nearest-upsampled row N(x) = U(x/2)
//               the five taps at x-2 .. x+2 give 3U(m-1) + 4U(m) + U(m+1) for
//               even x = 2m and U(m-1) + 4U(m) + 3U(m+1) for odd x = 2m+1:
//               the model's [3,4,1]/8 and [1,4,3]/8 phases. (Equivalently
//               [1 3 4 4 3 1] / 8 = [1 3 3 1] * [1 0 1] / 8 on the zero-stuffed
//               row, whose two polyphase components are those two kernels.)
//   accumulate  cv::add (in place into the tent result)
//   composite   cv::scaleAdd (S + I*B)
//   encode      cv::min, cv::pow, convertTo, cv::compare + copyTo for the
//               linear segment, convertTo CV_8U (rounds to nearest)
// Tutorial (8-bit sRGB codes, no linearisation, as tutorials do it):
//   cv::resize to half (INTER_LINEAR), cv::threshold THRESH_TOZERO,
//   cv::GaussianBlur, cv::resize back (INTER_LINEAR), cv::addWeighted.
#include "bench_cv.h"

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include <exception>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>

namespace
{

std::string g_error;
std::string g_version;
std::string g_parallel;

struct Level {
    cv::Mat pad, box; // BOXFILTER: padded input, full box-filtered level
    cv::Mat D;        // BOXFILTER: D_k
    cv::Mat P;        // AREA: D_k with its replicated border; D_k = P(1, 1, w, h)
    cv::Mat area;     // AREA: INTER_AREA result of this level's P (next level + 1)
    cv::Mat N, T;     // tent up onto this level: nearest-upsampled, filtered
};

} // namespace

struct bcv_ctx {
    bcv_params_t p;
    int w, h, L;
    cv::Mat lut, k5;
    cv::Mat S; // BOXFILTER: decoded source
    Level lv[BCV_MAX_LEVELS + 1];
    cv::Mat ch[3], bmax, soft, over, num, den, f, f3; // knee
    cv::Mat O, G, lin, mask;                          // composite, encode
    cv::Mat small, bright, blur, up;                  // tutorial
};

namespace
{

cv::Mat inner(const cv::Mat &P, int w, int h)
{
    return P(cv::Rect(1, 1, w, h));
}

// P holds an image at (1, 1) of w x h: replicate its edges into the rest.
void fill_border(cv::Mat &P, int w, int h)
{
    P(cv::Rect(1, 1, 1, h)).copyTo(P(cv::Rect(0, 1, 1, h)));
    for (int x = 1 + w; x < P.cols; x++)
        P(cv::Rect(w, 1, 1, h)).copyTo(P(cv::Rect(x, 1, 1, h)));
    P.row(1).copyTo(P.row(0));
    for (int y = 1 + h; y < P.rows; y++)
        P.row(h).copyTo(P.row(y));
}

// Padded size of level k for the AREA route: an exact 2x of level k+1 plus one.
cv::Size padded(const bcv_ctx &c, int k)
{
    return cv::Size(2 * ((c.p.level_w[k] + 1) / 2) + 2, 2 * ((c.p.level_h[k] + 1) / 2) + 2);
}

void knee(bcv_ctx &c, cv::Mat D)
{
    const double t = c.p.threshold, k = c.p.knee;
    cv::split(D, c.ch);
    cv::max(c.ch[0], c.ch[1], c.bmax);
    cv::max(c.bmax, c.ch[2], c.bmax);
    cv::subtract(c.bmax, cv::Scalar(t - k), c.soft); // b - t + knee
    cv::max(c.soft, 0.0, c.soft);
    cv::min(c.soft, 2.0 * k, c.soft);
    cv::multiply(c.soft, c.soft, c.soft, 0.25 / (k + 0.00001));
    cv::subtract(c.bmax, cv::Scalar(t), c.over);
    cv::max(c.soft, c.over, c.num);
    cv::max(c.bmax, 0.00001, c.den);
    cv::divide(c.num, c.den, c.f);
    const cv::Mat planes[3] = {c.f, c.f, c.f};
    cv::merge(planes, 3, c.f3);
    cv::multiply(D, c.f3, D);
}

void box_down_filter(const cv::Mat &X, Level &lv, Level &out)
{
    const cv::Mat *in = &X;
    if ((X.cols | X.rows) & 1) {
        cv::copyMakeBorder(X, lv.pad, 0, X.rows & 1, 0, X.cols & 1, cv::BORDER_REPLICATE);
        in = &lv.pad;
    }
    cv::boxFilter(*in, lv.box, -1, cv::Size(4, 4), cv::Point(1, 1), true, cv::BORDER_REPLICATE);
    cv::resize(lv.box, out.D, cv::Size(in->cols / 2, in->rows / 2), 0, 0, cv::INTER_NEAREST);
}

cv::Mat tent_up(const bcv_ctx &c, const cv::Mat &U, Level &lv, int w, int h)
{
    cv::resize(U, lv.N, cv::Size(2 * U.cols, 2 * U.rows), 0, 0, cv::INTER_NEAREST);
    cv::sepFilter2D(lv.N, lv.T, -1, c.k5, c.k5, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
    return lv.T(cv::Rect(0, 0, w, h));
}

void composite_encode(bcv_ctx &c, const cv::Mat &S, const cv::Mat &B, cv::Mat &dst)
{
    cv::scaleAdd(B, c.p.intensity, S, c.O);
    cv::min(c.O, 1.0, c.O);
    cv::pow(c.O, 1.0 / 2.4, c.G);
    c.G.convertTo(c.G, -1, 1.055, -0.055);
    cv::compare(c.O, 0.0031308, c.mask, cv::CMP_LE);
    c.O.convertTo(c.lin, -1, 12.92);
    c.lin.copyTo(c.G, c.mask);
    c.G.convertTo(dst, CV_8U, 255.0);
}

void up_chain(bcv_ctx &c, cv::Mat *D, const cv::Mat &S, cv::Mat &dst)
{
    cv::Mat U = D[c.L];
    for (int k = c.L - 1; k >= 1; k--) {
        cv::Mat T = tent_up(c, U, c.lv[k], c.p.level_w[k], c.p.level_h[k]);
        cv::add(D[k], T, T);
        U = T;
    }
    cv::Mat B = tent_up(c, U, c.lv[0], c.w, c.h);
    composite_encode(c, S, B, dst);
}

void run_boxfilter(bcv_ctx &c, const cv::Mat &src, cv::Mat &dst)
{
    cv::LUT(src, c.lut, c.S);
    cv::Mat D[BCV_MAX_LEVELS + 1];
    for (int k = 1; k <= c.L; k++) {
        box_down_filter(k == 1 ? c.S : c.lv[k - 1].D, c.lv[k - 1], c.lv[k]);
        if (k == 1)
            knee(c, c.lv[1].D);
        D[k] = c.lv[k].D;
    }
    up_chain(c, D, c.S, dst);
}

void run_area(bcv_ctx &c, const cv::Mat &src, cv::Mat &dst)
{
    cv::Mat S = inner(c.lv[0].P, c.w, c.h);
    cv::LUT(src, c.lut, S); // writes into the padded buffer
    fill_border(c.lv[0].P, c.w, c.h);
    cv::Mat D[BCV_MAX_LEVELS + 1];
    for (int k = 1; k <= c.L; k++) {
        const int w = c.p.level_w[k], h = c.p.level_h[k];
        cv::resize(c.lv[k - 1].P, c.lv[k - 1].area, cv::Size(w + 1, h + 1), 0, 0, cv::INTER_AREA);
        cv::Mat box = c.lv[k].P(cv::Rect(1, 1, w + 1, h + 1));
        cv::boxFilter(c.lv[k - 1].area, box, -1, cv::Size(2, 2), cv::Point(0, 0), true, cv::BORDER_REPLICATE);
        D[k] = inner(c.lv[k].P, w, h);
        if (k == 1)
            knee(c, D[1]);
        if (k < c.L)
            fill_border(c.lv[k].P, w, h);
    }
    up_chain(c, D, S, dst);
}

void run_tutorial(bcv_ctx &c, const cv::Mat &src, cv::Mat &dst)
{
    cv::resize(src, c.small, cv::Size((c.w + 1) / 2, (c.h + 1) / 2));
    cv::threshold(c.small, c.bright, c.p.tutorial_code, 255, cv::THRESH_TOZERO);
    cv::GaussianBlur(c.bright, c.blur, cv::Size(0, 0), c.p.tutorial_sigma / 2.0);
    cv::resize(c.blur, c.up, src.size());
    cv::addWeighted(src, 1.0, c.up, c.p.tutorial_weight, 0.0, dst);
}

} // namespace

extern "C" {

const char *bcv_version(void)
{
    g_version = cv::getVersionString();
    return g_version.c_str();
}

const char *bcv_parallel_framework(void)
{
    std::istringstream in(cv::getBuildInformation());
    std::string line;
    g_parallel = "unknown";
    while (std::getline(in, line)) {
        const std::string key = "Parallel framework:";
        const std::string::size_type at = line.find(key);
        if (at != std::string::npos) {
            std::string v = line.substr(at + key.size());
            const std::string::size_type b = v.find_first_not_of(" \t");
            g_parallel = b == std::string::npos ? "" : v.substr(b);
            break;
        }
    }
    return g_parallel.c_str();
}

int bcv_set_threads(int threads)
{
    cv::setNumThreads(threads);
    return cv::getNumThreads();
}

bcv_ctx_t *bcv_create(int w, int h, const bcv_params_t *p)
{
    bcv_ctx *c = new (std::nothrow) bcv_ctx;
    if (!c) {
        g_error = "out of memory";
        return nullptr;
    }
    try {
        c->p = *p;
        c->w = w;
        c->h = h;
        c->L = p->levels;
        if (c->L < 1 || c->L > BCV_MAX_LEVELS || p->level_w[0] != w || p->level_h[0] != h)
            throw std::runtime_error("bad level sizes");
        c->lut = cv::Mat(1, 256, CV_32F);
        for (int i = 0; i < 256; i++)
            c->lut.at<float>(0, i) = p->decode_lut[i];
        c->k5 = (cv::Mat_<float>(1, 5) << 0.125f, 0.25f, 0.25f, 0.25f, 0.125f);
        for (int k = 0; k <= c->L; k++)
            c->lv[k].P = cv::Mat(padded(*c, k), CV_32FC3, cv::Scalar::all(0));
    } catch (const std::exception &e) {
        g_error = e.what();
        delete c;
        return nullptr;
    }
    return c;
}

int bcv_run(bcv_ctx_t *c, int kind, const uint8_t *src, size_t src_stride, uint8_t *dst, size_t dst_stride)
{
    try {
        const cv::Mat s(c->h, c->w, CV_8UC3, const_cast<uint8_t *>(src), src_stride);
        cv::Mat d(c->h, c->w, CV_8UC3, dst, dst_stride);
        switch (kind) {
        case BCV_SAME_BOXFILTER:
            run_boxfilter(*c, s, d);
            break;
        case BCV_SAME_AREA:
            run_area(*c, s, d);
            break;
        case BCV_TUTORIAL:
            run_tutorial(*c, s, d);
            break;
        default:
            g_error = "unknown variant";
            return -1;
        }
        if (d.data != dst) {
            g_error = "OpenCV reallocated the output instead of writing the caller's frame";
            return -1;
        }
    } catch (const std::exception &e) {
        g_error = e.what();
        return -1;
    }
    return 0;
}

void bcv_destroy(bcv_ctx_t *c)
{
    delete c;
}

const char *bcv_error(void)
{
    return g_error.c_str();
}

} // extern "C"
