/* GEGL's gegl:bloom (GIMP's Filters > Light and Shadow > Bloom) on the
 * frame of `make bench-peers`, timed in-process as peers_drv.c times the
 * engine: the gegl CLI would add PNG decoding and encoding to every frame.
 *   peers_gegl FRAME.rgb W H FRAMES THRESHOLD_PERCENT RADIUS
 * Per frame: wrap a cold input slot as a GeglBuffer ("R'G'B' u8", no copy),
 * render gegl:bloom into a cold output slot in the same format (gegl_node_blit,
 * no cache), one thread, no OpenCL; prints the median ms over FRAMES after
 * one warm-up frame. Built by bench.mk only when libgegl-dev is installed. */
#include <gegl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static int cmp_d(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double one(GeglNode *src, GeglNode *bloom, const Babl *fmt, int w, int h, guchar *in, guchar *out)
{
    const GeglRectangle r = {0, 0, w, h};
    const double t0 = now_ms();
    GeglBuffer *buf = gegl_buffer_linear_new_from_data(in, fmt, &r, w * 3, NULL, NULL);
    gegl_node_set(src, "buffer", buf, NULL);
    gegl_node_blit(bloom, 1.0, &r, fmt, out, w * 3, GEGL_BLIT_DEFAULT);
    g_object_unref(buf);
    return now_ms() - t0;
}

int main(int argc, char **argv)
{
    if (argc != 7) {
        fprintf(stderr, "usage: peers_gegl FRAME.rgb W H FRAMES THRESHOLD_PERCENT RADIUS\n");
        return 2;
    }
    const int w = atoi(argv[2]), h = atoi(argv[3]), n = atoi(argv[4]);
    const size_t fb = (size_t)w * h * 3;
    guchar *in = malloc(fb * (n + 1)), *out = malloc(fb * (n + 1));
    double *t = malloc(sizeof(double) * n);
    FILE *f = fopen(argv[1], "rb");
    if (!in || !out || !t || !f || fread(in, 1, fb, f) != fb) {
        fprintf(stderr, "peers_gegl: cannot read %s or out of memory\n", argv[1]);
        return 1;
    }
    fclose(f);
    for (int i = 1; i <= n; i++)
        memcpy(in + fb * i, in, fb);
    memset(out, 0, fb * (n + 1));
    gegl_init(NULL, NULL);
    g_object_set(gegl_config(), "threads", 1, "use-opencl", FALSE, NULL);
    GeglNode *g = gegl_node_new();
    GeglNode *src = gegl_node_new_child(g, "operation", "gegl:buffer-source", NULL);
    GeglNode *bloom = gegl_node_new_child(g, "operation", "gegl:bloom", "threshold", atof(argv[5]), "radius",
                                          atof(argv[6]), NULL);
    gegl_node_link(src, bloom);
    const Babl *fmt = babl_format("R'G'B' u8");
    one(src, bloom, fmt, w, h, in, out); /* warm-up: plugin code, babl fish */
    for (int i = 0; i < n; i++)
        t[i] = one(src, bloom, fmt, w, h, in + fb * (i + 1), out + fb * (i + 1));
    qsort(t, (size_t)n, sizeof *t, cmp_d);
    printf("%.4f\n", n % 2 ? t[n / 2] : (t[n / 2 - 1] + t[n / 2]) / 2);
    g_object_unref(g);
    gegl_exit();
    return 0;
}
