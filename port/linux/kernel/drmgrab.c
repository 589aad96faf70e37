/* Guest helper of make test-linux (the DRM cases, drm_cases.sh), through
 * libdrm (linked statically, as bloom_cam is):
 *   drmgrab CARD crtc        each CRTC: "crtc ID fb FB mode NAME" (or "mode off")
 *   drmgrab CARD grab OUT    the framebuffer on the first lit CRTC, as the
 *                            display reads it: DRM_IOCTL_MODE_GETFB (a handle
 *                            for root, CAP_SYS_ADMIN, though bloom_cam is the
 *                            master) and MAP_DUMB; writes its height rows of
 *                            pitch bytes and prints "W H PITCH BPP FB"
 *   drmgrab CARD hold WxH    a CRTC state of its own to be restored: a
 *                            dumb buffer of that mode's size on the first
 *                            connector's CRTC, then the master dropped so
 *                            bloom_cam can take it; prints "held fb FB mode
 *                            NAME" and keeps the buffer (and its file) until
 *                            SIGTERM, so no last close restores the fbdev's
 *                            mode behind bloom_cam's back. */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include <xf86drm.h>
#include <xf86drmMode.h>

static int die(const char *what)
{
    fprintf(stderr, "drmgrab: %s: %s\n", what, strerror(errno));
    return 1;
}

static int crtcs(int fd, drmModeRes *r)
{
    for (int i = 0; i < r->count_crtcs; i++) {
        drmModeCrtc *c = drmModeGetCrtc(fd, r->crtcs[i]);
        if (!c)
            return die("drmModeGetCrtc");
        if (c->mode_valid)
            printf("crtc %u fb %u mode %s\n", c->crtc_id, c->buffer_id, c->mode.name);
        else
            printf("crtc %u fb %u mode off\n", c->crtc_id, c->buffer_id);
        drmModeFreeCrtc(c);
    }
    return 0;
}

static int grab(int fd, drmModeRes *r, const char *out)
{
    for (int i = 0; i < r->count_crtcs; i++) {
        drmModeCrtc *c = drmModeGetCrtc(fd, r->crtcs[i]);
        if (!c || !c->buffer_id) {
            drmModeFreeCrtc(c);
            continue;
        }
        drmModeFB *f = drmModeGetFB(fd, c->buffer_id);
        if (!f)
            return die("drmModeGetFB");
        if (!f->handle) {
            fprintf(stderr, "drmgrab: GETFB gave no handle (not root?)\n");
            return 1;
        }
        struct drm_mode_map_dumb m = {.handle = f->handle};
        if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &m))
            return die("DRM_IOCTL_MODE_MAP_DUMB");
        const size_t n = (size_t)f->pitch * f->height;
        void *p = mmap(NULL, n, PROT_READ, MAP_SHARED, fd, (off_t)m.offset);
        if (p == MAP_FAILED)
            return die("mmap");
        FILE *o = fopen(out, "wb");
        if (!o || fwrite(p, 1, n, o) != n || fclose(o))
            return die(out);
        printf("%u %u %u %u %u\n", f->width, f->height, f->pitch, f->bpp, c->buffer_id);
        return 0;
    }
    fprintf(stderr, "drmgrab: no CRTC shows a framebuffer\n");
    return 1;
}

static int hold(int fd, drmModeRes *r, const char *size)
{
    int w = 0, h = 0;
    if (sscanf(size, "%dx%d", &w, &h) != 2)
        return 2;
    for (int i = 0; i < r->count_connectors; i++) {
        drmModeConnector *k = drmModeGetConnector(fd, r->connectors[i]);
        if (!k || k->connection == DRM_MODE_DISCONNECTED)
            continue;
        /* the encoder's CRTC, else (none bound yet) the first one */
        drmModeEncoder *e = k->encoder_id ? drmModeGetEncoder(fd, k->encoder_id) : NULL;
        const uint32_t crtc = e && e->crtc_id ? e->crtc_id : r->crtcs[0];
        int mi = -1;
        for (int j = 0; j < k->count_modes && mi < 0; j++)
            if (k->modes[j].hdisplay == w && k->modes[j].vdisplay == h)
                mi = j;
        if (!crtc || mi < 0) {
            fprintf(stderr, "drmgrab: connector %u: no CRTC or no %s mode\n", k->connector_id, size);
            return 1;
        }
        struct drm_mode_create_dumb cr = {.width = (uint32_t)w, .height = (uint32_t)h, .bpp = 32};
        if (drmIoctl(fd, DRM_IOCTL_MODE_CREATE_DUMB, &cr))
            return die("DRM_IOCTL_MODE_CREATE_DUMB");
        uint32_t id;
        if (drmModeAddFB(fd, (uint32_t)w, (uint32_t)h, 24, 32, cr.pitch, cr.handle, &id))
            return die("drmModeAddFB");
        struct drm_mode_map_dumb m = {.handle = cr.handle};
        void *p;
        if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &m) ||
            (p = mmap(NULL, cr.size, PROT_WRITE, MAP_SHARED, fd, (off_t)m.offset)) == MAP_FAILED)
            return die("mapping the dumb buffer");
        memset(p, 0x40, cr.size); /* grey: not the fbdev's black */
        if (drmModeSetCrtc(fd, crtc, id, 0, 0, &k->connector_id, 1, &k->modes[mi]))
            return die("drmModeSetCrtc");
        if (drmDropMaster(fd))
            return die("drmDropMaster");
        printf("held fb %u mode %s\n", id, k->modes[mi].name);
        fflush(stdout);
        sigset_t s;
        sigemptyset(&s);
        sigaddset(&s, SIGTERM);
        sigprocmask(SIG_BLOCK, &s, NULL);
        int sig;
        sigwait(&s, &sig);
        return 0;
    }
    fprintf(stderr, "drmgrab: no connected connector\n");
    return 1;
}

int main(int argc, char **argv)
{
    if (argc < 3 || (strcmp(argv[2], "crtc") && argc != 4)) {
        fprintf(stderr, "usage: drmgrab CARD crtc | grab OUT | hold WxH\n");
        return 2;
    }
    int fd = open(argv[1], O_RDWR | O_CLOEXEC);
    drmModeRes *r = fd >= 0 ? drmModeGetResources(fd) : NULL;
    if (!r)
        return die(argv[1]);
    if (!strcmp(argv[2], "crtc"))
        return crtcs(fd, r);
    if (!strcmp(argv[2], "grab"))
        return grab(fd, r, argv[3]);
    if (!strcmp(argv[2], "hold"))
        return hold(fd, r, argv[3]);
    return 2;
}
