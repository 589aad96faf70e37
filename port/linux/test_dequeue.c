/* bloom_cam host tests of the capture faults (part of test_cam_host; its
 * closing line counts these): cam_v4l2_dequeue and cam_v4l2_latest through
 * the ioctl/poll seam in cam_v4l2_t, driven by a scripted fake (no device).
 * EINTR and EAGAIN are retried; ENODEV, a poll error and a timeout are
 * fatal with their kind (CAM_LOST_*: the reconnection's business); short
 * bytesused and V4L2_BUF_FLAG_ERROR frames are requeued and counted; a
 * V4L2_EVENT_SOURCE_CHANGE event ends the stream for a renegotiation;
 * --latest hands back the newest frame. */
#include <errno.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <linux/videodev2.h>

#include "cam.h"
#include "harness.h"

void test_dequeue(int *pass, int *fail);

/* ---- capture faults through the ioctl/poll seam ---------------------------
 * A script of steps, each one poll(2) or one VIDIOC_DQBUF: what it returns,
 * errno when it fails, revents for a poll, the buffer for a DQBUF. */
enum { STEP_POLL = 1, STEP_DQBUF, STEP_QBUF, STEP_DQEVENT }; /* DQEVENT: flags = type, index = changes */
typedef struct {
    int kind, ret, err;
    short revents;
    uint32_t index, bytesused, flags, sequence;
} fake_step_t;

static const fake_step_t *fake_script;
static int fake_n, fake_at, fake_polls, fake_ioctls, fake_unexpected;

static const sigset_t *fake_mask_seen;
static int fake_poll(struct pollfd *fds, nfds_t nfds, int timeout_ms, const sigset_t *mask)
{
    (void)timeout_ms;
    fake_mask_seen = mask;
    fake_polls++;
    if (fake_at >= fake_n || fake_script[fake_at].kind != STEP_POLL || nfds < 1) {
        fake_unexpected++;
        errno = EIO;
        return -1;
    }
    const fake_step_t *s = &fake_script[fake_at++];
    for (nfds_t i = 0; i < nfds; i++)
        fds[i].revents = 0;
    fds[0].revents = s->revents;
    if (s->ret < 0)
        errno = s->err;
    return s->ret;
}

static int fake_ioctl(int fd, unsigned long req, void *arg)
{
    (void)fd;
    fake_ioctls++;
    const int kind = req == (unsigned long)VIDIOC_DQBUF     ? STEP_DQBUF
                     : req == (unsigned long)VIDIOC_QBUF    ? STEP_QBUF
                     : req == (unsigned long)VIDIOC_DQEVENT ? STEP_DQEVENT
                                                            : 0;
    if (!kind || fake_at >= fake_n || fake_script[fake_at].kind != kind) {
        fake_unexpected++;
        errno = EIO;
        return -1;
    }
    const fake_step_t *s = &fake_script[fake_at++];
    if (s->ret < 0) {
        errno = s->err;
        return -1;
    }
    if (kind == STEP_DQEVENT) {
        struct v4l2_event *ev = arg;
        ev->type = s->flags;
        ev->u.src_change.changes = s->index;
        return 0;
    }
    struct v4l2_buffer *b = arg;
    if (kind == STEP_QBUF) { /* the buffer the step names must be the one queued */
        if (b->index != s->index)
            fake_unexpected++;
        return 0;
    }
    b->index = s->index;
    b->bytesused = s->bytesused;
    b->flags = s->flags;
    b->sequence = s->sequence;
    return 0;
}

/* Run cam_v4l2_dequeue (latest: then cam_v4l2_latest, counting into
 * skipped and bad) over a script with stderr captured into msg. */
static long fake_skipped, fake_bad[3];
static int lost_kind;
static int run_script(const fake_step_t *script, int n, cam_frame_t *f, char *msg, size_t len, int latest)
{
    enum { W = 16, H = 4, BPL = 2 * W };
    static uint8_t mem[3][BPL * H];
    cam_v4l2_t c;
    memset(&c, 0, sizeof c);
    c.fd = -1;
    c.ioctl_fn = fake_ioctl;
    c.poll_fn = fake_poll;
    c.width = W;
    c.height = H;
    c.pixelformat = V4L2_PIX_FMT_YUYV;
    c.bytesperline = BPL;
    c.sizeimage = BPL * H;
    c.nbufs = 3;
    for (int i = 0; i < 3; i++) {
        c.bufs[i].start = mem[i];
        c.bufs[i].length = sizeof mem[i];
    }
    c.streaming = 1;
    c.events = 1;
    fake_script = script;
    fake_n = n;
    fake_at = fake_polls = fake_ioctls = fake_unexpected = 0;

    FILE *tmp = tmpfile();
    int saved = dup(2);
    fflush(stderr);
    if (tmp)
        dup2(fileno(tmp), 2);
    memset(f, 0, sizeof *f);
    static sigset_t mask;
    sigemptyset(&mask);
    c.wait_mask = &mask;
    fake_mask_seen = NULL;
    fake_skipped = fake_bad[0] = fake_bad[1] = fake_bad[2] = 0;
    int r = cam_v4l2_dequeue(&c, 100, -1, NULL, f);
    if (r == 0 && latest)
        r = cam_v4l2_latest(&c, f, &fake_skipped, fake_bad);
    if (fake_polls && fake_mask_seen != &mask)
        fake_unexpected++; /* the wait must be given the mask that lets the stop signals in */
    lost_kind = c.lost;
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    msg[0] = '\0';
    if (tmp) {
        rewind(tmp);
        size_t got = fread(msg, 1, len - 1, tmp);
        msg[got] = '\0';
        fclose(tmp);
    }
    if (f->data) /* as an index into mem, so the test can check which */
        f->data = (const uint8_t *)(f->data - mem[0]);
    return r;
}
static int run_dequeue(const fake_step_t *script, int n, cam_frame_t *f, char *msg, size_t len)
{
    return run_script(script, n, f, msg, len, 0);
}

static void test_dequeue_faults(void)
{
    enum { FULL = 2 * 16 * 4 };
    char msg[512];
    cam_frame_t f;

    /* EINTR from DQBUF is retried without polling again, the frame comes. */
    static const fake_step_t eintr[] = {
        {STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0},
        {STEP_DQBUF, -1, EINTR, 0, 0, 0, 0, 0},
        {STEP_DQBUF, 0, 0, 0, 2, FULL, 0, 7},
    };
    int r = run_dequeue(eintr, 3, &f, msg, sizeof msg);
    CHECKF(r == 0 && f.index == 2 && f.sequence == 7 && f.bytesused == FULL &&
               (size_t)f.data == 2 * (size_t)FULL && !msg[0],
           "EINTR retried: r %d index %d sequence %u msg '%s'", r, f.index, (unsigned)f.sequence, msg);
    CHECKF(fake_polls == 1 && fake_ioctls == 2 && !fake_unexpected && fake_at == 3,
           "EINTR: %d polls, %d ioctls, %d unexpected", fake_polls, fake_ioctls, fake_unexpected);

    /* EAGAIN from DQBUF after a plain POLLIN: poll again, then the frame. */
    static const fake_step_t eagain[] = {
        {STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0},
        {STEP_DQBUF, -1, EAGAIN, 0, 0, 0, 0, 0},
        {STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0},
        {STEP_DQBUF, 0, 0, 0, 1, FULL, 0, 8},
    };
    r = run_dequeue(eagain, 4, &f, msg, sizeof msg);
    CHECKF(r == 0 && f.index == 1 && f.sequence == 8 && !msg[0], "EAGAIN waits again: r %d index %d msg '%s'",
           r, f.index, msg);
    CHECKF(fake_polls == 2 && fake_ioctls == 2 && !fake_unexpected && fake_at == 4,
           "EAGAIN: %d polls, %d ioctls, %d unexpected", fake_polls, fake_ioctls, fake_unexpected);

    /* A signal during poll: 1, nothing dequeued, no message. */
    static const fake_step_t sig[] = {{STEP_POLL, -1, EINTR, 0, 0, 0, 0, 0}};
    r = run_dequeue(sig, 1, &f, msg, sizeof msg);
    CHECKF(r == 1 && fake_ioctls == 0 && !msg[0], "poll EINTR: r %d msg '%s'", r, msg);

    /* The faults: each -1 with one message naming the call. */
    static const struct {
        fake_step_t s[2];
        const char *want;
    } bad[] = {
        {{{STEP_POLL, 1, 0, POLLIN | POLLERR, 0, 0, 0, 0}, {STEP_DQBUF, -1, ENODEV, 0, 0, 0, 0, 0}},
         "bloom_cam: VIDIOC_DQBUF: No such device\n"},
        {{{STEP_POLL, 1, 0, POLLERR, 0, 0, 0, 0}, {STEP_DQBUF, -1, EAGAIN, 0, 0, 0, 0, 0}},
         "bloom_cam: poll: the device reports an error (revents 0x8)\n"},
        {{{STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0}, {STEP_DQBUF, 0, 0, 0, 3, FULL, 0, 6}},
         "bloom_cam: VIDIOC_DQBUF: buffer index 3 out of range\n"},
        {{{STEP_POLL, 0, 0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 0, 0, 0}},
         "bloom_cam: poll: no frame from the device within 100 ms\n"},
        {{{STEP_POLL, -1, EBADF, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 0, 0, 0}},
         "bloom_cam: poll: Bad file descriptor\n"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int steps = bad[i].s[1].kind ? 2 : 1;
        r = run_dequeue(bad[i].s, steps, &f, msg, sizeof msg);
        int lines = 0;
        for (const char *p = msg; *p; p++)
            lines += *p == '\n';
        CHECKF(r == -1 && !strncmp(msg, bad[i].want, strlen(bad[i].want)) && lines == 1 && fake_at == steps &&
                   !fake_unexpected,
               "fault %zu: r %d, %d of %d steps, message '%s', want '%s'", i, r, fake_at, steps, msg,
               bad[i].want);
    }
    CHECKF(lost_kind == CAM_LOST_DEVICE, "a poll failure is a device fault (lost %d)", lost_kind);

    /* Bad frames: requeued at once, 2, which kind in f->bad, no message. */
    static const struct {
        fake_step_t s[3];
        int bad;
        uint32_t seq;
    } skip[] = {
        {{{STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0},
          {STEP_DQBUF, 0, 0, 0, 0, FULL - 1, 0, 3},
          {STEP_QBUF, 0, 0, 0, 0, 0, 0, 0}},
         CAM_BAD_SHORT,
         3},
        {{{STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0},
          {STEP_DQBUF, 0, 0, 0, 2, 0, 0, 4},
          {STEP_QBUF, 0, 0, 0, 2, 0, 0, 0}},
         CAM_BAD_SHORT,
         4},
        {{{STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0},
          {STEP_DQBUF, 0, 0, 0, 1, FULL, V4L2_BUF_FLAG_ERROR, 5},
          {STEP_QBUF, 0, 0, 0, 1, 0, 0, 0}},
         CAM_BAD_FLAGGED,
         5},
    };
    for (size_t i = 0; i < sizeof skip / sizeof skip[0]; i++) {
        r = run_dequeue(skip[i].s, 3, &f, msg, sizeof msg);
        CHECKF(r == 2 && f.bad == skip[i].bad && f.sequence == skip[i].seq && !msg[0] && fake_at == 3 &&
                   !fake_unexpected,
               "bad frame %zu: r %d bad %d sequence %u, %d of 3 steps, %d unexpected, message '%s'", i, r,
               f.bad, (unsigned)f.sequence, fake_at, fake_unexpected, msg);
    }
    /* A timeout says so (a stall: the reconnection's business). */
    static const fake_step_t stall[] = {{STEP_POLL, 0, 0, 0, 0, 0, 0, 0}};
    r = run_dequeue(stall, 1, &f, msg, sizeof msg);
    CHECKF(r == -1 && lost_kind == CAM_LOST_TIMEOUT, "timeout: r %d lost %d", r, lost_kind);
    static const fake_step_t gone[] = {{STEP_POLL, 1, 0, POLLIN | POLLERR, 0, 0, 0, 0},
                                       {STEP_DQBUF, -1, ENODEV, 0, 0, 0, 0, 0}};
    r = run_dequeue(gone, 2, &f, msg, sizeof msg);
    CHECKF(r == -1 && lost_kind == CAM_LOST_DEVICE, "ENODEV: r %d lost %d", r, lost_kind);

    /* --latest: the older of two ready frames goes back, a bad one in
     * between is requeued and counted, EAGAIN ends the look. */
    static const fake_step_t newest[] = {
        {STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0},
        {STEP_DQBUF, 0, 0, 0, 0, FULL, 0, 10},
        {STEP_DQBUF, 0, 0, 0, 1, FULL, V4L2_BUF_FLAG_ERROR, 11},
        {STEP_QBUF, 0, 0, 0, 1, 0, 0, 0},
        {STEP_DQBUF, 0, 0, 0, 2, FULL, 0, 12},
        {STEP_QBUF, 0, 0, 0, 0, 0, 0, 0},
        {STEP_DQBUF, -1, EAGAIN, 0, 0, 0, 0, 0},
    };
    r = run_script(newest, 7, &f, msg, sizeof msg, 1);
    CHECKF(r == 0 && f.index == 2 && f.sequence == 12 && fake_skipped == 1 &&
               fake_bad[CAM_BAD_FLAGGED] == 1 && fake_at == 7 && !fake_unexpected && !msg[0],
           "--latest: r %d index %d sequence %u skipped %ld flagged %ld, %d of 7 steps, %d unexpected '%s'",
           r, f.index, (unsigned)f.sequence, fake_skipped, fake_bad[CAM_BAD_FLAGGED], fake_at,
           fake_unexpected, msg);
    static const fake_step_t only[] = {{STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0},
                                       {STEP_DQBUF, 0, 0, 0, 1, FULL, 0, 20},
                                       {STEP_DQBUF, -1, EAGAIN, 0, 0, 0, 0, 0}};
    r = run_script(only, 3, &f, msg, sizeof msg, 1);
    CHECKF(r == 0 && f.index == 1 && fake_skipped == 0 && fake_at == 3 && !fake_unexpected,
           "--latest, one frame ready: r %d index %d skipped %ld", r, f.index, fake_skipped);
}

/* V4L2_EVENT_SOURCE_CHANGE (POLLPRI, then VIDIOC_DQEVENT) ends the stream
 * with its own kind, one message; another event is read and ignored. */
static void test_source_change(void)
{
    enum { FULL = 2 * 16 * 4 };
    char msg[512];
    cam_frame_t f;
    static const fake_step_t change[] = {
        {STEP_POLL, 1, 0, POLLPRI, 0, 0, 0, 0},
        {STEP_DQEVENT, 0, 0, 0, V4L2_EVENT_SRC_CH_RESOLUTION, 0, V4L2_EVENT_SOURCE_CHANGE, 0},
    };
    int r = run_dequeue(change, 2, &f, msg, sizeof msg);
    CHECKF(r == -1 && lost_kind == CAM_LOST_SOURCE && fake_at == 2 && !fake_unexpected &&
               !strcmp(msg, "bloom_cam: the source changed (changes 0x1): negotiating the format again\n"),
           "source change: r %d lost %d, %d of 2 steps, %d unexpected, message '%s'", r, lost_kind, fake_at,
           fake_unexpected, msg);
    static const fake_step_t other[] = {
        {STEP_POLL, 1, 0, POLLPRI, 0, 0, 0, 0},
        {STEP_DQEVENT, 0, 0, 0, 0, 0, V4L2_EVENT_EOS, 0},
        {STEP_POLL, 1, 0, POLLIN, 0, 0, 0, 0},
        {STEP_DQBUF, 0, 0, 0, 1, FULL, 0, 9},
    };
    r = run_dequeue(other, 4, &f, msg, sizeof msg);
    CHECKF(r == 0 && f.index == 1 && f.sequence == 9 && fake_at == 4 && !fake_unexpected && !msg[0],
           "another event is ignored: r %d index %d, %d of 4 steps, %d unexpected, message '%s'", r, f.index,
           fake_at, fake_unexpected, msg);
    static const fake_step_t both[] = {
        /* an event and a frame in one wakeup: the change wins */
        {STEP_POLL, 1, 0, POLLPRI | POLLIN, 0, 0, 0, 0},
        {STEP_DQEVENT, 0, 0, 0, V4L2_EVENT_SRC_CH_RESOLUTION, 0, V4L2_EVENT_SOURCE_CHANGE, 0},
    };
    r = run_dequeue(both, 2, &f, msg, sizeof msg);
    CHECKF(r == -1 && lost_kind == CAM_LOST_SOURCE && fake_at == 2 && !fake_unexpected,
           "source change with a frame ready: r %d lost %d, %d of 2 steps", r, lost_kind, fake_at);
}

void test_dequeue(int *pass, int *fail)
{
    test_dequeue_faults();
    test_source_change();
    *pass += harness_pass;
    *fail += harness_fail;
}
