/* Test helper for the guest (no v4l2-ctl there): set a V4L2 control by its
 * name, "vctl /dev/video0 'Disconnect' 1". Button controls take any value.
 * Prints the controls when the name is not found. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <linux/videodev2.h>

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: vctl DEVICE NAME VALUE\n");
        return 2;
    }
    int fd = open(argv[1], O_RDWR);
    if (fd < 0) {
        fprintf(stderr, "vctl: open %s: %s\n", argv[1], strerror(errno));
        return 1;
    }
    struct v4l2_queryctrl q;
    memset(&q, 0, sizeof q);
    q.id = V4L2_CTRL_FLAG_NEXT_CTRL;
    while (ioctl(fd, VIDIOC_QUERYCTRL, &q) == 0) {
        if (!strcmp((const char *)q.name, argv[2])) {
            struct v4l2_control c = {q.id, atoi(argv[3])};
            if (ioctl(fd, VIDIOC_S_CTRL, &c)) {
                fprintf(stderr, "vctl: VIDIOC_S_CTRL %s: %s\n", argv[2], strerror(errno));
                return 1;
            }
            return 0;
        }
        q.id |= V4L2_CTRL_FLAG_NEXT_CTRL;
    }
    fprintf(stderr, "vctl: %s has no control '%s'; it has:\n", argv[1], argv[2]);
    memset(&q, 0, sizeof q);
    q.id = V4L2_CTRL_FLAG_NEXT_CTRL;
    while (ioctl(fd, VIDIOC_QUERYCTRL, &q) == 0) {
        fprintf(stderr, "  %s\n", (const char *)q.name);
        q.id |= V4L2_CTRL_FLAG_NEXT_CTRL;
    }
    return 1;
}
