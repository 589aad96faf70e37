/* Test vectors for the Icarus bench (tb_icarus.v): for one case, writes
 * <prefix>.cfg (register values), <prefix>.in (the frames' pixels) and
 * <prefix>.out (bloom_process of the C library on each frame), one
 * hexadecimal word per line for $readmemh.
 *
 *   gen_vectors PREFIX FMT888 W H LEVELS THRESHOLD KNEE INTENSITY DEBUG FRAMES SEED GAP BP
 *   gen_vectors --workspace W H LEVELS FMT888   the C engine's workspace, bytes
 *                                               (the memory column of make fpga) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bloom.h"

static unsigned long long st;
static unsigned rnd(void)
{
    st = st * 6364136223846793005ull + 1442695040888963407ull;
    return (unsigned)(st >> 33);
}

static FILE *open_w(const char *prefix, const char *ext)
{
    char path[512];
    snprintf(path, sizeof path, "%s.%s", prefix, ext);
    FILE *f = fopen(path, "w");
    if (!f) {
        perror(path);
        exit(2);
    }
    return f;
}

int main(int argc, char **argv)
{
    if (argc == 6 && !strcmp(argv[1], "--workspace")) {
        bloom_config_t c;
        bloom_config_default(&c, atoi(argv[2]), atoi(argv[3]));
        c.levels = atoi(argv[4]);
        c.in_fmt = c.out_fmt = atoi(argv[5]) ? BLOOM_FMT_RGB888 : BLOOM_FMT_RGB565;
        printf("%zu\n", bloom_workspace_size(&c));
        return 0;
    }
    if (argc != 14) {
        fprintf(stderr, "usage: gen_vectors PREFIX FMT888 W H LEVELS THRESHOLD KNEE INTENSITY DEBUG FRAMES "
                        "SEED GAP BP\n");
        return 2;
    }
    const int fmt888 = atoi(argv[2]), w = atoi(argv[3]), h = atoi(argv[4]), levels = atoi(argv[5]);
    const int debug = atoi(argv[9]), frames = atoi(argv[10]);
    const int bpp = fmt888 ? 3 : 2;
    bloom_config_t cfg;
    bloom_config_default(&cfg, w, h);
    cfg.in_fmt = cfg.out_fmt = fmt888 ? BLOOM_FMT_RGB888 : BLOOM_FMT_RGB565;
    cfg.levels = levels;
    cfg.threshold = (uint32_t)(atof(argv[6]) * 65536.0 + 0.5);
    cfg.soft_knee = (uint32_t)(atof(argv[7]) * 65536.0 + 0.5);
    cfg.intensity = (uint32_t)(atof(argv[8]) * 65536.0 + 0.5);
    if (debug)
        cfg.flags |= BLOOM_FLAG_DEBUG_VIEW;
    bloom_info_t info;
    bloom_status_t s = bloom_query(&cfg, &info);
    if (s != BLOOM_OK) {
        fprintf(stderr, "gen_vectors: %s\n", bloom_status_str(s));
        return 2;
    }
    void *ws = malloc(info.workspace_bytes);
    uint8_t *in = malloc((size_t)w * h * bpp), *out = malloc((size_t)w * h * bpp);
    bloom_t *b;
    if (!ws || !in || !out || bloom_init(&b, ws, info.workspace_bytes, &cfg) != BLOOM_OK) {
        fprintf(stderr, "gen_vectors: set-up failed\n");
        return 2;
    }
    FILE *fc = open_w(argv[1], "cfg"), *fi = open_w(argv[1], "in"), *fo = open_w(argv[1], "out");
    /* w, h, levels requested, T_q, K_q, I_q, debug, frames, seed, gap %, back-pressure %, L built */
    fprintf(fc, "%x\n%x\n%x\n%x\n%x\n%x\n%x\n%x\n%x\n%x\n%x\n%x\n", w, h, levels, (unsigned)info.threshold_q,
            (unsigned)info.knee_q, (unsigned)info.intensity_q, debug, frames, atoi(argv[11]), atoi(argv[12]),
            atoi(argv[13]), info.levels);
    st = (unsigned long long)atoi(argv[11]) * 0x9E3779B97F4A7C15ull + 1;
    for (int f = 0; f < frames; f++) {
        for (int i = 0; i < w * h; i++) {
            unsigned v = rnd(), r, g, bl;
            if ((v & 15) == 0) /* a light */
                r = 190 + (v >> 8) % 66, g = 170 + (v >> 16) % 86, bl = 150 + (v >> 24) % 106;
            else
                r = (v >> 8) & 127, g = (v >> 15) & 127, bl = (v >> 22) & 127;
            if (fmt888)
                in[3 * i] = (uint8_t)r, in[3 * i + 1] = (uint8_t)g, in[3 * i + 2] = (uint8_t)bl;
            else {
                const unsigned p = ((r >> 3) << 11) | ((g >> 2) << 5) | (bl >> 3);
                in[2 * i] = (uint8_t)p, in[2 * i + 1] = (uint8_t)(p >> 8);
            }
        }
        bloom_process(b, in, (size_t)w * bpp, out, (size_t)w * bpp);
        for (int i = 0; i < w * h; i++) {
            const uint8_t *p = in + (size_t)i * bpp, *q = out + (size_t)i * bpp;
            fprintf(fi, "%x\n", fmt888 ? p[0] | p[1] << 8 | p[2] << 16 : p[0] | p[1] << 8);
            fprintf(fo, "%x\n", fmt888 ? q[0] | q[1] << 8 | q[2] << 16 : q[0] | q[1] << 8);
        }
    }
    fclose(fc);
    fclose(fi);
    fclose(fo);
    free(ws);
    free(in);
    free(out);
    return 0;
}
