/* bloom_cam: GPIO lines through libgpiod v1 (Debian bookworm: 1.6).
 * --gpio-frame: an output held high while a frame is processed.
 * --gpio-button: an input with pull-up whose falling edges (a press of a
 * button wired to ground) cycle the mode. Lines are requested once, held for
 * the life of the process and released by cam_gpio_close.
 * Built without libgpiod (CAM_NO_GPIOD) the options are refused. */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cam.h"

int cam_debounce(int64_t *last_ns, int64_t t_ns, int ms)
{
    if (*last_ns != INT64_MIN && t_ns - *last_ns < (int64_t)ms * 1000000)
        return 0; /* a bounce of the last press (or of its release) */
    *last_ns = t_ns;
    return 1;
}

#ifdef CAM_NO_GPIOD

const int cam_gpio_available = 0;

int cam_gpio_open(cam_gpio_t **g, const cam_gpio_spec_t *frame, const cam_gpio_spec_t *button,
                  int debounce_ms)
{
    (void)debounce_ms;
    *g = NULL;
    if (frame->set || button->set) {
        fprintf(stderr, "%s: GPIO: built without libgpiod\n", CAM_PROG);
        return -1;
    }
    return 0;
}
void cam_gpio_frame(cam_gpio_t *g, int high)
{
    (void)g;
    (void)high;
}
int cam_gpio_button_fd(cam_gpio_t *g)
{
    (void)g;
    return -1;
}
int cam_gpio_button_presses(cam_gpio_t *g)
{
    (void)g;
    return 0;
}
void cam_gpio_close(cam_gpio_t *g)
{
    (void)g;
}

#else

#include <gpiod.h>

const int cam_gpio_available = 1;

struct cam_gpio {
    struct gpiod_chip *frame_chip, *button_chip;
    struct gpiod_line *frame, *button;
    int frame_high;
    int debounce_ms;
    int64_t last_press_ns;
};

static struct gpiod_line *find_line(struct gpiod_chip **chip, const cam_gpio_spec_t *s, const char *opt)
{
    *chip = gpiod_chip_open_lookup(s->chip);
    if (!*chip) {
        fprintf(stderr, "%s: %s: gpiod_chip_open_lookup %s: %s\n", CAM_PROG, opt, s->chip,
                strerror(errno ? errno : ENODEV));
        return NULL;
    }
    char *end;
    errno = 0;
    unsigned long off = strtoul(s->line, &end, 10);
    struct gpiod_line *l;
    if (!errno && end != s->line && !*end) {
        if (off >= gpiod_chip_num_lines(*chip)) {
            fprintf(stderr, "%s: %s: %s has %u lines, no line %lu\n", CAM_PROG, opt, s->chip,
                    gpiod_chip_num_lines(*chip), off);
            return NULL;
        }
        l = gpiod_chip_get_line(*chip, (unsigned)off);
    } else {
        l = gpiod_chip_find_line(*chip, s->line);
    }
    if (!l)
        fprintf(stderr, "%s: %s: %s has no line %s\n", CAM_PROG, opt, s->chip, s->line);
    return l;
}

int cam_gpio_open(cam_gpio_t **out, const cam_gpio_spec_t *frame, const cam_gpio_spec_t *button,
                  int debounce_ms)
{
    *out = NULL;
    if (!frame->set && !button->set)
        return 0;
    cam_gpio_t *g = calloc(1, sizeof *g);
    if (!g) {
        fprintf(stderr, "%s: GPIO: out of memory\n", CAM_PROG);
        return -1;
    }
    *out = g;
    /* libgpiod 1.x (Debian bookworm) asks the kernel for no debounce (its
     * v1 line requests have no such attribute): presses are debounced here,
     * on the kernel's event timestamps */
    g->debounce_ms = debounce_ms;
    g->last_press_ns = INT64_MIN;
    if (frame->set) {
        g->frame = find_line(&g->frame_chip, frame, "--gpio-frame");
        if (!g->frame)
            return -1;
        if (gpiod_line_request_output(g->frame, CAM_PROG " frame", 0)) {
            fprintf(stderr, "%s: --gpio-frame: gpiod_line_request_output %s:%s: %s\n", CAM_PROG, frame->chip,
                    frame->line, strerror(errno));
            g->frame = NULL;
            return -1;
        }
    }
    if (button->set) {
        g->button = find_line(&g->button_chip, button, "--gpio-button");
        if (!g->button)
            return -1;
        int r = gpiod_line_request_falling_edge_events_flags(g->button, CAM_PROG " button",
                                                             GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP);
        if (r && errno == EINVAL) /* kernels before 5.5 know no bias flags */
            r = gpiod_line_request_falling_edge_events(g->button, CAM_PROG " button");
        if (r) {
            fprintf(stderr, "%s: --gpio-button: gpiod_line_request_falling_edge_events %s:%s: %s\n", CAM_PROG,
                    button->chip, button->line, strerror(errno));
            g->button = NULL;
            return -1;
        }
    }
    return 0;
}

void cam_gpio_frame(cam_gpio_t *g, int high)
{
    if (!g || !g->frame || g->frame_high == high)
        return;
    if (gpiod_line_set_value(g->frame, high) == 0)
        g->frame_high = high;
}

int cam_gpio_button_fd(cam_gpio_t *g)
{
    return g && g->button ? gpiod_line_event_get_fd(g->button) : -1;
}

int cam_gpio_button_presses(cam_gpio_t *g)
{
    if (!g || !g->button)
        return 0;
    int presses = 0;
    struct timespec zero = {0, 0};
    struct gpiod_line_event ev[16];
    while (gpiod_line_event_wait(g->button, &zero) == 1) {
        int n = gpiod_line_event_read_multiple(g->button, ev, 16);
        if (n <= 0)
            break;
        for (int i = 0; i < n; i++)
            if (ev[i].event_type == GPIOD_LINE_EVENT_FALLING_EDGE)
                presses +=
                    cam_debounce(&g->last_press_ns, (int64_t)ev[i].ts.tv_sec * 1000000000 + ev[i].ts.tv_nsec,
                                 g->debounce_ms);
    }
    return presses;
}

void cam_gpio_close(cam_gpio_t *g)
{
    if (!g)
        return;
    if (g->frame) {
        gpiod_line_set_value(g->frame, 0);
        gpiod_line_release(g->frame);
    }
    if (g->button)
        gpiod_line_release(g->button);
    if (g->frame_chip)
        gpiod_chip_close(g->frame_chip);
    if (g->button_chip)
        gpiod_chip_close(g->button_chip);
    free(g);
}

#endif
