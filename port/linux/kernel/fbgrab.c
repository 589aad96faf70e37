/* Guest helper of make test-linux (the GStreamer cases): print a
 * framebuffer's geometry, "xres yres xoffset yoffset line_length bpp", and
 * with OUT write its visible page (yres rows of line_length bytes from the
 * pan offset yoffset), as fbdevsink left it. fbdevsink takes the screen's
 * layout as it finds it; vivid's 16 bpp screen starts as RGB555 and bloom
 * writes RGB565, so "--rgb565 SAVE" saves the layout and asks the driver for
 * RGB565 (as bloom_cam does, or fbset -rgba 5/11,6/5,5/0,0/0), and
 * "--restore SAVE" puts the saved one back. */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <linux/fb.h>

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 4 || (argc == 4 && strcmp(argv[2], "--rgb565") && strcmp(argv[2], "--restore"))) {
        fprintf(stderr, "usage: fbgrab FBDEV [OUT | --rgb565 SAVE | --restore SAVE]\n");
        return 2;
    }
    struct fb_var_screeninfo v;
    struct fb_fix_screeninfo f;
    int fd = open(argv[1], argc == 4 ? O_RDWR : O_RDONLY);
    if (fd < 0 || ioctl(fd, FBIOGET_VSCREENINFO, &v) || ioctl(fd, FBIOGET_FSCREENINFO, &f)) {
        perror(argv[1]);
        return 1;
    }
    if (argc == 4) {
        const int set = !strcmp(argv[2], "--rgb565");
        FILE *sf = fopen(argv[3], set ? "wb" : "rb");
        if (!sf) {
            perror(argv[3]);
            return 1;
        }
        if (set) {
            if (fwrite(&v, sizeof v, 1, sf) != 1 || fclose(sf)) {
                perror(argv[3]);
                return 1;
            }
            v.bits_per_pixel = 16;
            v.grayscale = v.nonstd = 0;
            v.red = (struct fb_bitfield){11, 5, 0};
            v.green = (struct fb_bitfield){5, 6, 0};
            v.blue = (struct fb_bitfield){0, 5, 0};
            v.transp = (struct fb_bitfield){0, 0, 0};
        } else if (fread(&v, sizeof v, 1, sf) != 1) {
            fprintf(stderr, "fbgrab: %s is short\n", argv[3]);
            return 1;
        }
        v.activate = FB_ACTIVATE_NOW;
        if (ioctl(fd, FBIOPUT_VSCREENINFO, &v) || ioctl(fd, FBIOGET_VSCREENINFO, &v)) {
            perror("FBIOPUT_VSCREENINFO");
            return 1;
        }
        printf("%u bpp, red %u/%u green %u/%u blue %u/%u transp %u/%u\n", v.bits_per_pixel, v.red.length,
               v.red.offset, v.green.length, v.green.offset, v.blue.length, v.blue.offset, v.transp.length,
               v.transp.offset);
        return 0;
    }
    printf("%u %u %u %u %u %u\n", v.xres, v.yres, v.xoffset, v.yoffset, f.line_length, v.bits_per_pixel);
    if (argc == 2)
        return 0;
    const size_t n = (size_t)f.line_length * v.yres;
    unsigned char *buf = malloc(n);
    FILE *o = fopen(argv[2], "wb");
    if (!buf || !o || lseek(fd, (off_t)v.yoffset * f.line_length, SEEK_SET) < 0) {
        perror(argv[2]);
        return 1;
    }
    for (size_t got = 0; got < n;) {
        ssize_t r = read(fd, buf + got, n - got);
        if (r <= 0) {
            perror("read");
            return 1;
        }
        got += (size_t)r;
    }
    if (fwrite(buf, 1, n, o) != n || fclose(o)) {
        perror(argv[2]);
        return 1;
    }
    return 0;
}
