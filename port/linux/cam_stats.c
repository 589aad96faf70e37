/* bloom_cam: what a run went through (frames, drops, bad frames by kind,
 * reconnects), for --stats every second and the closing "total:" line. */
#include <stdio.h>

#include "cam.h"

void cam_stats_line(const char *what, const cam_counts_t *n, double t0, double t1, double proc_sum,
                    double proc_min, double proc_max)
{
    double el = t1 - t0;
    const long frames = n->frames;
    fprintf(stderr,
            "%s: %s: %ld frames, %.2f fps, %ld dropped, processing %.2f ms/frame "
            "(min %.2f, max %.2f); %ld skipped for newer (--latest), %ld bad (%ld flagged, %ld short, "
            "%ld undecodable JPEG), %ld reconnects\n",
            CAM_PROG, what, frames, el > 0 ? (double)frames / el : 0.0, n->dropped,
            frames ? proc_sum * 1e3 / (double)frames : 0.0, frames ? proc_min * 1e3 : 0.0, proc_max * 1e3,
            n->skipped, n->bad[CAM_BAD_FLAGGED] + n->bad[CAM_BAD_SHORT] + n->bad[CAM_BAD_JPEG],
            n->bad[CAM_BAD_FLAGGED], n->bad[CAM_BAD_SHORT], n->bad[CAM_BAD_JPEG], n->reconnects);
}

void cam_count_bad(cam_counts_t *n, cam_counts_t *win, int kind, uint32_t sequence, const char *why,
                   int quiet)
{
    n->bad[kind]++;
    win->bad[kind]++;
    if (!quiet && n->bad[kind] == 1) /* the first of each kind is told, the rest counted */
        fprintf(stderr, "%s: frame %u %s%s: skipped (counted from here on, not told again)\n", CAM_PROG,
                (unsigned)sequence,
                kind == CAM_BAD_FLAGGED ? "flagged V4L2_BUF_FLAG_ERROR"
                : kind == CAM_BAD_SHORT ? "short (bytesused)"
                                        : "undecodable JPEG: ",
                kind == CAM_BAD_JPEG && why ? why : "");
}
