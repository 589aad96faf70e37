/* report_icount: exactly one bloom_process call, for
 * `valgrind --tool=callgrind --toggle-collect=bloom_process` (run.sh).
 *
 *   report_icount DATA_DIR INPUT W H LEVELS THRESHOLD [noskip] [s16]
 *
 * INPUT as rin_make (report.h); THRESHOLD linear (e.g. 0.6); output RGB888;
 * s16: 16-bit row samples (cfg.sample_bits 16).
 * Prints the output's FNV-1a so that skip and no-skip runs can be seen to
 * agree next to their counts. Deterministic: no clocks. */
#include <stdlib.h>
#include <string.h>

#include "report.h"

int main(int argc, char **argv)
{
    int noskip = 0, s16 = 0;
    for (int i = 7; i < argc; i++) {
        if (!strcmp(argv[i], "noskip"))
            noskip = 1;
        else if (!strcmp(argv[i], "s16"))
            s16 = 1;
        else
            argc = 0; /* the usage below */
    }
    if (argc < 7) {
        fprintf(stderr, "usage: report_icount DATA_DIR INPUT W H LEVELS THRESHOLD [noskip] [s16]\n");
        return 2;
    }
    const int w = atoi(argv[3]), h = atoi(argv[4]), lv = atoi(argv[5]);
    const double t = atof(argv[6]);
    char err[512];
    rin_t in;
    if (w < 1 || h < 1 || w > BLOOM_MAX_DIM || h > BLOOM_MAX_DIM || t < 0.0 || t > 256.0)
        rdie("bad size or threshold");
    if (rin_make(&in, argv[2], argv[1], w, h, err, sizeof err))
        rdie("%s", err);
    bloom_config_t c;
    bloom_config_default(&c, w, h);
    c.levels = lv;
    c.threshold = BLOOM_Q16(t);
    c.in_fmt = in.fmt;
    if (noskip)
        c.flags |= BLOOM_FLAG_NO_SKIP;
    if (s16)
        c.sample_bits = 16;
    bloom_info_t info;
    bloom_status_t st = bloom_query(&c, &info);
    if (st != BLOOM_OK)
        rdie("bloom_query: %s", bloom_status_str(st));
    void *ws = NULL;
    bloom_t *b;
    uint8_t *dst = rxmalloc((size_t)w * (size_t)h * 3u);
    if (posix_memalign(&ws, BLOOM_WORKSPACE_ALIGN, info.workspace_bytes))
        rdie("out of memory");
    if ((st = bloom_init(&b, ws, info.workspace_bytes, &c)) != BLOOM_OK)
        rdie("bloom_init: %s", bloom_status_str(st));
    if ((st = bloom_process(b, in.p, (ptrdiff_t)in.stride, dst, (ptrdiff_t)w * 3)) != BLOOM_OK)
        rdie("bloom_process: %s", bloom_status_str(st));
    uint32_t sum = 2166136261u;
    for (size_t i = 0; i < (size_t)w * (size_t)h * 3u; i++)
        sum = (sum ^ dst[i]) * 16777619u;
    printf("F%d %s %dx%d L%d%s%s fnv1a %08x\n", BLOOM_LIN_BITS, in.name, w, h, info.levels,
           noskip ? " noskip" : "", s16 ? " s16" : "", (unsigned)sum);
    free(ws);
    free(dst);
    rin_free(&in);
    return 0;
}
