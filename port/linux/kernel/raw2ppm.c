/* Host side of make test-linux (the GStreamer cases): the BGRx frames
 * v4l2src recorded (W x H, rows of STRIDE bytes, back to back) as 8-bit
 * PPMs for bloom_sim (bytes R, G, B: the same codes, X dropped; bloom_sim
 * --in-format xrgb8888 gives them to the engine as XRGB8888 again).
 * Prints the number of frames written. */
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: raw2ppm RAW W H STRIDE OUT%%04d.ppm\n");
        return 2;
    }
    const int w = atoi(argv[2]), h = atoi(argv[3]), stride = atoi(argv[4]);
    FILE *in = fopen(argv[1], "rb");
    unsigned char *row = malloc((size_t)(stride > 0 ? stride : 1));
    if (!in || !row || w <= 0 || h <= 0 || stride < w * 4) {
        fprintf(stderr, "raw2ppm: cannot read %s (or a bad size)\n", argv[1]);
        return 2;
    }
    int n = 0;
    for (;; n++) {
        int c = fgetc(in);
        if (c == EOF)
            break;
        ungetc(c, in);
        char name[4096];
        snprintf(name, sizeof name, argv[5], n);
        FILE *o = fopen(name, "wb");
        if (!o) {
            perror(name);
            return 1;
        }
        fprintf(o, "P6\n%d %d\n255\n", w, h);
        for (int y = 0; y < h; y++) {
            if (fread(row, 1, (size_t)stride, in) != (size_t)stride) {
                fprintf(stderr, "raw2ppm: %s: frame %d is short\n", argv[1], n);
                return 1;
            }
            for (int x = 0; x < w; x++) {
                const unsigned char px[3] = {row[4 * x + 2], row[4 * x + 1], row[4 * x]};
                fwrite(px, 1, 3, o);
            }
        }
        if (fclose(o)) {
            perror(name);
            return 1;
        }
    }
    printf("%d\n", n);
    return n > 0 ? 0 : 1;
}
