/* Test helper for the guest (make test-linux): a camera that sends MJPEG
 * through v4l2loopback. "loopfeed DEVICE W H GOOD CORRUPT TRUNCATED" sets
 * the loopback's output format to W x H Motion-JPEG and writes frames with
 * write() at about 30 per second until killed: the good JPEG, except every
 * tenth frame from the fourth on is the corrupt one and every tenth from
 * the eighth the truncated one. Says "streaming" on stdout after its first
 * frame (the loopback offers capture from then on: exclusive_caps=1).
 * With "N W2 H2 GOOD2" after them, a camera that comes back in another
 * size: after N frames it closes the device, opens it again until the
 * loopback takes W2 x H2 (refused while a reader holds the old format),
 * and sends GOOD2 from then on. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include <linux/videodev2.h>

static unsigned char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "loopfeed: %s: %s\n", path, strerror(errno));
        exit(1);
    }
    unsigned char *b = malloc(1 << 20);
    *len = b ? fread(b, 1, 1 << 20, f) : 0;
    fclose(f);
    if (!*len) {
        fprintf(stderr, "loopfeed: %s: empty or unreadable\n", path);
        exit(1);
    }
    return b;
}

/* The loopback opened and its output set to w x h MJPEG: the descriptor,
 * or -1 (said once on stderr when quiet is not set by a retry). */
static int out_fmt(const char *dev, int w, int h, struct v4l2_format *f)
{
    static int told;
    int fd = open(dev, O_RDWR);
    if (fd < 0) {
        if (!told++)
            fprintf(stderr, "loopfeed: open %s: %s\n", dev, strerror(errno));
        return -1;
    }
    memset(f, 0, sizeof *f);
    f->type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
    f->fmt.pix.width = (unsigned)w;
    f->fmt.pix.height = (unsigned)h;
    f->fmt.pix.pixelformat = V4L2_PIX_FMT_MJPEG;
    f->fmt.pix.field = V4L2_FIELD_NONE;
    if (ioctl(fd, VIDIOC_S_FMT, f) < 0 || f->fmt.pix.width != (unsigned)w ||
        f->fmt.pix.height != (unsigned)h) {
        if (!told++)
            fprintf(stderr, "loopfeed: VIDIOC_S_FMT %dx%d: %s\n", w, h, strerror(errno));
        close(fd);
        return -1;
    }
    return fd;
}

int main(int argc, char **argv)
{
    if (argc != 7 && argc != 11) {
        fprintf(stderr, "usage: loopfeed DEVICE W H GOOD CORRUPT TRUNCATED [N W2 H2 GOOD2]\n");
        return 2;
    }
    struct v4l2_format f;
    int fd = out_fmt(argv[1], atoi(argv[2]), atoi(argv[3]), &f);
    if (fd < 0)
        return 1;
    size_t len[4];
    unsigned char *frame[4];
    for (int i = 0; i < 3; i++)
        frame[i] = slurp(argv[4 + i], &len[i]);
    const long resize_at = argc == 11 ? atol(argv[7]) : -1;
    if (argc == 11)
        frame[3] = slurp(argv[10], &len[3]);
    const struct timespec gap = {0, 33333333};
    int resized = 0;
    for (long i = 0;; i++) {
        if (i == resize_at) { /* gone, then back in the other size once the reader let go */
            close(fd);
            for (int tries = 0; (fd = out_fmt(argv[1], atoi(argv[8]), atoi(argv[9]), &f)) < 0; tries++) {
                if (tries == 600)
                    return 1;
                const struct timespec t = {0, 100000000};
                nanosleep(&t, NULL);
            }
            printf("resized to %ux%u after %ld frames\n", f.fmt.pix.width, f.fmt.pix.height, i);
            fflush(stdout);
            resized = 1;
        }
        const int k = resized ? 3 : i % 10 == 3 ? 1 : i % 10 == 7 ? 2 : 0;
        if (write(fd, frame[k], len[k]) != (ssize_t)len[k]) {
            fprintf(stderr, "loopfeed: write: %s\n", strerror(errno));
            return 1;
        }
        if (i == 0) {
            printf("streaming %ux%u MJPEG, sizeimage %u\n", f.fmt.pix.width, f.fmt.pix.height,
                   f.fmt.pix.sizeimage);
            fflush(stdout);
        }
        nanosleep(&gap, NULL);
    }
}
