/* make test-linux: a depth plane for bloom_cam --preset attenuation --aux,
 * a binary PGM ramp from near (0) at the left to far (maxval) at the right.
 *   mkdepth W H MAXVAL OUT.pgm      (16-bit big-endian samples when MAXVAL > 255) */
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    long w = argc == 5 ? atol(argv[1]) : 0, h = argc == 5 ? atol(argv[2]) : 0;
    long mv = argc == 5 ? atol(argv[3]) : 0;
    FILE *f = argc == 5 ? fopen(argv[4], "wb") : NULL;
    if (!f || w < 2 || h < 1 || mv < 1 || mv > 65535) {
        fprintf(stderr, "usage: mkdepth W H MAXVAL OUT.pgm\n");
        return 2;
    }
    fprintf(f, "P5\n%ld %ld\n%ld\n", w, h, mv);
    for (long y = 0; y < h; y++)
        for (long x = 0; x < w; x++) {
            const long v = (mv * x + (w - 1) / 2) / (w - 1);
            if (mv > 255)
                fputc((int)(v >> 8), f);
            fputc((int)(v & 255), f);
        }
    return fclose(f) ? 1 : 0;
}
