/* Host side of make test-linux: compare a framebuffer dump written by
 * bloom_cam --dump-fb (W x H pixels, rows packed, RGB565 or XRGB8888) with
 * the simulator's PPM of the same frame (bloom_sim -o, 8-bit: RGB565 codes
 * written as round(c * 255 / max), an injective map, so equal PPM bytes mean
 * equal framebuffer bits). Prints "identical" or the first difference.
 * With STRIDE X Y the dump is a whole screen page (rows of STRIDE bytes, as
 * fbgrab writes it) and the frame is the W x H one at X,Y (the GStreamer
 * cases: fbdevsink centres the video). With part X Y H the dump is the
 * W x H the screen showed of a larger frame (bloom_cam cropping a capture
 * larger than the screen), compared with the simulator's frame at X,Y. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned expand(unsigned c, unsigned max)
{
    return (c * 255u + max / 2u) / max;
}

int main(int argc, char **argv)
{
    const int part = argc == 9 && !strcmp(argv[5], "part");
    if (argc != 5 && argc != 8 && !part) {
        fprintf(stderr, "usage: fbcmp FBDUMP rgb565|xrgb8888 W SIM.ppm [STRIDE X Y | part X Y H]\n");
        return 2;
    }
    const int is565 = !strcmp(argv[2], "rgb565"), bpp = is565 ? 2 : 4;
    FILE *a = fopen(argv[1], "rb"), *b = fopen(argv[4], "rb");
    int w, h, maxv;
    const long px = part ? atol(argv[6]) : 0, py = part ? atol(argv[7]) : 0;
    const int fw = atoi(argv[3]), fh = part ? atoi(argv[8]) : 0;
    int good = a && b && fscanf(b, "P6 %d %d %d", &w, &h, &maxv) == 3 && maxv == 255 && fgetc(b) != EOF;
    if (good && part) /* the shown part lies within the simulator's frame */
        good = px >= 0 && py >= 0 && fw >= 1 && fh >= 1 && px + fw <= w && py + fh <= h;
    else if (good)
        good = w == fw;
    if (!good) {
        fprintf(stderr, "fbcmp: cannot read %s or %s (or the sizes do not fit)\n", argv[1], argv[4]);
        return 2;
    }
    const long ppm0 = ftell(b), ppm_w = w; /* the simulator's frame: its first pixel, its width */
    if (part) {
        w = fw;
        h = fh;
    }
    const int crop = argc == 8;
    const long stride = crop ? atol(argv[5]) : 0, x0 = crop ? atol(argv[6]) : 0,
               y0 = crop ? atol(argv[7]) : 0;
    long diffs = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            if (crop && x == 0 && fseek(a, (y0 + y) * stride + x0 * bpp, SEEK_SET)) {
                fprintf(stderr, "fbcmp: %s: cannot seek to row %ld\n", argv[1], y0 + y);
                return 1;
            }
            if (part && x == 0 && fseek(b, ppm0 + ((py + y) * ppm_w + px) * 3, SEEK_SET)) {
                fprintf(stderr, "fbcmp: %s: cannot seek to row %ld\n", argv[4], py + y);
                return 1;
            }
            unsigned char p[4], q[3];
            unsigned r, g, bl;
            if (fread(p, 1, (size_t)bpp, a) != (size_t)bpp || fread(q, 1, 3, b) != 3) {
                fprintf(stderr, "fbcmp: %s is short at pixel %d,%d\n", argv[1], x, y);
                return 1;
            }
            if (is565) {
                unsigned v = p[0] | (unsigned)p[1] << 8;
                r = expand(v >> 11, 31);
                g = expand((v >> 5) & 63, 63);
                bl = expand(v & 31, 31);
            } else {
                r = p[2];
                g = p[1];
                bl = p[0];
            }
            if (r != q[0] || g != q[1] || bl != q[2]) {
                if (!diffs)
                    fprintf(stderr, "fbcmp: first difference at %d,%d: fb %u,%u,%u sim %u,%u,%u\n", x, y, r,
                            g, bl, q[0], q[1], q[2]);
                diffs++;
            }
        }
    if (!crop && fgetc(a) != EOF) {
        fprintf(stderr, "fbcmp: %s is longer than %dx%d\n", argv[1], w, h);
        return 1;
    }
    if (diffs) {
        fprintf(stderr, "fbcmp: %ld pixels differ\n", diffs);
        return 1;
    }
    if (crop)
        printf("identical (%dx%d at %ld,%ld)\n", w, h, x0, y0);
    else if (part)
        printf("identical (%dx%d of the frame at %ld,%ld)\n", w, h, px, py);
    else
        printf("identical (%dx%d)\n", w, h);
    return 0;
}
