/* Test helper for the guest: print the console mode of a VT, "text" or
 * "graphics" (KDGETMODE), so a case can check that bloom_cam put it in
 * graphics mode while drawing and back to text on every way out.
 * "vtmode /dev/tty0". */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <linux/kd.h>

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: vtmode TTY\n");
        return 2;
    }
    int fd = open(argv[1], O_RDWR | O_NOCTTY);
    int mode = 0;
    if (fd < 0 || ioctl(fd, KDGETMODE, &mode)) {
        fprintf(stderr, "vtmode: %s: %s\n", argv[1], strerror(errno));
        return 1;
    }
    close(fd);
    puts(mode == KD_TEXT ? "text" : mode == KD_GRAPHICS ? "graphics" : "other");
    return 0;
}
