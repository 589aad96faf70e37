/* bloom_sim tests: the presets. Every preset this build carries, chosen by
 * name, with and without its parameters: the tool's output equals the
 * engine run here with the same configuration (the preset's defaults, then
 * the options) and the same aux plane, and --bittrue (the preset's bit-true
 * model) reports 0 differing samples. The refusals: an unknown or
 * compiled-out name (the message lists what this build has), a preset's
 * option given to another preset, a preset that needs an aux plane run
 * without --aux (the engine's message and the option), an aux plane of the
 * wrong size, missing, or not one channel. */
#include "harness.h"
#include "simtest_cases.h"

#include <stdlib.h>
#include <string.h>

void simtest_presets_counts(int *pass, int *fail)
{
    *pass = harness_pass;
    *fail = harness_fail;
}

enum { W = 37, H = 29 };

static uint8_t scene[W * H * 3];
static uint8_t ramp8[W * H]; /* the aux plane: a vertical ramp, 0 at the top */
static uint16_t ramp16[W * H];

/* The engine run here: c on the packed RGB888 scene, aux (W*H, u8 or
 * native u16) when c reads one. Output RGB888 codes into dst. */
static int engine_aux(const bloom_config_t *c, const void *aux, uint8_t *dst)
{
    size_t n = bloom_workspace_size(c);
    void *ws = n ? malloc(n) : NULL;
    bloom_t *b;
    int rc = -1;
    if (ws && bloom_init(&b, ws, n, c) == BLOOM_OK &&
        (!aux || bloom_set_aux(b, aux, (ptrdiff_t)W * (c->aux_fmt == BLOOM_AUX_U16 ? 2 : 1)) == BLOOM_OK) &&
        bloom_process(b, scene, W * 3, dst, W * 3) == BLOOM_OK)
        rc = 0;
    free(ws);
    return rc;
}

/* The last run succeeded, named the preset, reported a clean bit-true
 * check, and its output file equals the engine run here. */
static void expect_run(const char *label, const bloom_config_t *c, const void *aux, const char *out)
{
    char want[64];
    snprintf(want, sizeof want, "preset %s", bloom_preset_name(c->preset));
    CHECKF(R.status == 0, "%s: status %d: %s", label, R.status, R.err);
    CHECKF(strstr(R.out, "bit-true: 0 differ") && strstr(R.out, "summary vs bit-true model: 0 of"),
           "%s: bit-true check: %s", label, R.out);
    CHECKF(strstr(R.out, want) != NULL, "%s: output does not name the preset: %s", label, R.out);
    char sum[96];
    snprintf(sum, sizeof sum, "summary: 1 frame, %s, engine", want);
    CHECKF(strstr(R.out, sum) != NULL, "%s: summary line: %s", label, R.out);
    int ow, oh;
    uint8_t *got = st_read_rgb8(st_path(out), &ow, &oh);
    static uint8_t ref[W * H * 3];
    CHECKF(got && ow == W && oh == H && engine_aux(c, aux, ref) == 0 && !memcmp(got, ref, sizeof ref),
           "%s: output differs from bloom_process with the same configuration", label);
    free(got);
}

/* Does preset c (with its defaults) refuse to run without an aux plane? */
static int needs_aux(const bloom_config_t *c)
{
    bloom_config_t t = *c;
    bloom_info_t info;
    if (t.aux_fmt == BLOOM_AUX_NONE)
        return 0;
    t.aux_fmt = BLOOM_AUX_NONE;
    return bloom_query(&t, &info) == BLOOM_E_AUX;
}

/* One preset by name with extra options (and their effect on the config). */
typedef struct {
    bloom_preset_t preset;
    const char *label;
    const char *args[8]; /* extra options, NULL-terminated */
    int aux;             /* 0 none, 8 the 8-bit PGM, 16 the 16-bit PNG */
} pcase_t;

static void apply_case(const pcase_t *k, bloom_config_t *c)
{
    for (int i = 0; k->args[i]; i++) {
        const char *a = k->args[i], *v = k->args[i + 1];
        if (!strcmp(a, "--strength"))
            c->p.strength = BLOOM_Q16(atof(v));
        else if (!strcmp(a, "--passes"))
            c->p.passes = atoi(v);
        else if (!strcmp(a, "--saturate"))
            c->flags |= BLOOM_FLAG_SATURATE;
        else if (!strcmp(a, "--attenuation"))
            c->p.attenuation = BLOOM_Q16(atof(v));
        else if (!strcmp(a, "--max-reduction"))
            c->p.max_reduction = BLOOM_Q16(atof(v));
        else if (!strcmp(a, "--tint"))
            c->p.tint[0] = BLOOM_Q16(1.0), c->p.tint[1] = BLOOM_Q16(0.5), c->p.tint[2] = BLOOM_Q16(0.25);
        else if (!strcmp(a, "--weights"))
            c->p.level_weight[0] = BLOOM_Q16(0.5), c->p.level_weight[1] = BLOOM_Q16(0.25),
            c->p.level_weight[2] = BLOOM_Q16(0.75);
        else if (!strcmp(a, "--additive"))
            c->flags |= BLOOM_FLAG_ADDITIVE;
        else if (!strcmp(a, "--baked"))
            c->flags |= BLOOM_FLAG_BAKED;
        else if (!strcmp(a, "--levels"))
            c->levels = atoi(v);
#if BLOOM_USE_COD
        else if (!strcmp(a, "--radius"))
            c->levels = bloom_levels_for_radius(atoi(v));
#endif
    }
}

static void run_case(const pcase_t *k)
{
    bloom_config_t c;
    bloom_config_default(&c, W, H);
    if (bloom_config_preset(&c, k->preset) != BLOOM_OK) {
        CHECKF(0, "%s: bloom_config_preset refused an available preset", k->label);
        return;
    }
    c.threshold = BLOOM_Q16(0.5);
    apply_case(k, &c);
    int aux = k->aux;
    if (!aux && needs_aux(&c))
        aux = 8;
    const void *plane = NULL;
    if (aux == 8)
        c.aux_fmt = BLOOM_AUX_U8, plane = ramp8;
    else if (aux == 16)
        c.aux_fmt = BLOOM_AUX_U16, plane = ramp16;
    else
        c.aux_fmt = BLOOM_AUX_NONE;
    const char *args[24];
    int n = 0;
    args[n++] = st_path("p_in.ppm");
    args[n++] = "--preset";
    args[n++] = bloom_preset_name(k->preset);
    args[n++] = "--threshold";
    args[n++] = "0.5";
    args[n++] = "--bittrue";
    args[n++] = "--compare";
    args[n++] = "-o";
    args[n++] = st_path("p_out.ppm");
    if (aux) {
        args[n++] = "--aux";
        args[n++] = st_path(aux == 8 ? "p_ramp.pgm" : "p_ramp16.png");
    }
    for (int i = 0; k->args[i]; i++)
        args[n++] = k->args[i];
    args[n] = NULL;
    remove(st_path("p_out.ppm"));
    st_run(&R, tool, NULL, args);
    expect_run(k->label, &c, plane, "p_out.ppm");
}

static void test_by_name(void)
{
    static const pcase_t cases[] = {
        {BLOOM_PRESET_UNITY, "unity", {NULL}, 0},
        {BLOOM_PRESET_UNITY, "unity, 3 levels", {"--levels", "3", NULL}, 0},
        {BLOOM_PRESET_GAMEDEV, "gamedev", {NULL}, 0},
        {BLOOM_PRESET_GAMEDEV, "gamedev --strength", {"--strength", "2.5", NULL}, 0},
        {BLOOM_PRESET_XNA, "xna", {NULL}, 0},
        {BLOOM_PRESET_XNA, "xna --passes --saturate", {"--passes", "2", "--saturate", NULL}, 0},
        {BLOOM_PRESET_ATTENUATION, "attenuation", {NULL}, 8},
        {BLOOM_PRESET_ATTENUATION,
         "attenuation 16-bit, a and r",
         {"--attenuation", "0.5", "--max-reduction", "0.125", NULL},
         16},
        {BLOOM_PRESET_ARM, "arm", {NULL}, 0},
        {BLOOM_PRESET_ARM, "arm mask, tint", {"--tint", "1,0.5,0.25", NULL}, 8},
        {BLOOM_PRESET_ARM, "arm --baked", {"--baked", "--strength", "2", NULL}, 8},
        {BLOOM_PRESET_COD, "cod", {NULL}, 0},
        {BLOOM_PRESET_COD,
         "cod weights, tint, additive",
         {"--weights", "0.5,0.25,0.75", "--tint", "1,0.5,0.25", "--additive", NULL},
         0},
        {BLOOM_PRESET_COD, "cod --radius", {"--radius", "12", NULL}, 0},
    };
    int ran = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if (!bloom_preset_available(cases[i].preset))
            continue;
        run_case(&cases[i]);
        ran++;
    }
    printf("bloom_sim presets: %d runs by name (this build has", ran);
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++)
        if (bloom_preset_available((bloom_preset_t)p))
            printf(" %s", bloom_preset_name((bloom_preset_t)p));
    printf(")\n");

    /* unity by name is the default run, byte for byte */
    CHECK(RUN(NULL, st_path("p_in.ppm"), "--threshold", "0.5", "-o", st_path("p_def.ppm")) == 0);
    CHECK(RUN(NULL, st_path("p_in.ppm"), "--threshold", "0.5", "--preset=unity", "-o",
              st_path("p_uni.ppm")) == 0);
    size_t l1, l2;
    unsigned char *a = st_read_file(st_path("p_def.ppm"), &l1), *b = st_read_file(st_path("p_uni.ppm"), &l2);
    CHECKF(a && b && l1 == l2 && !memcmp(a, b, l1), "--preset unity differs from the default run");
    free(a);
    free(b);
    /* the options apply over the preset's defaults whatever their order */
    CHECK(RUN(NULL, st_path("p_in.ppm"), "--levels", "2", "--preset", "unity", "-q") == 0 &&
          strstr(R.out, "2 levels") != NULL);
}

static const char precious[] = "P6\n1 1\n255\nabc";

static void test_refusals(void)
{
    /* unknown name: usage error listing what this build has */
    RUN(NULL, st_path("p_in.ppm"), "--preset", "bogus");
    CHECKF(R.status == 2 && strstr(R.err, "unknown preset 'bogus'") && strstr(R.err, "this build has: unity"),
           "bad name: status %d: %s", R.status, R.err);
    RUN(NULL, st_path("p_in.ppm"), "--preset=");
    CHECK(R.status == 2 && strstr(R.err, "unknown preset ''") != NULL);
    /* a compiled-out preset, if this build leaves one out */
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (bloom_preset_available((bloom_preset_t)p))
            continue;
        RUN(NULL, st_path("p_in.ppm"), "--preset", bloom_preset_name((bloom_preset_t)p));
        CHECKF(R.status == 2 && strstr(R.err, "compiled out") && strstr(R.err, "BLOOM_USE_") &&
                   strstr(R.err, "this build has: unity"),
               "compiled-out %s: status %d: %s", bloom_preset_name((bloom_preset_t)p), R.status, R.err);
    }
    /* an option of another preset */
    RUN(NULL, st_path("p_in.ppm"), "--passes", "3");
    CHECKF(R.status == 2 && strstr(R.err, "--passes applies to the xna preset, not unity"), "%s", R.err);
    RUN(NULL, st_path("p_in.ppm"), "--aux", st_path("p_ramp.pgm"));
    CHECKF(R.status == 2 && strstr(R.err, "--aux applies to the attenuation or arm preset"), "%s", R.err);
    RUN(NULL, st_path("p_in.ppm"), "--weights", "0.5,2");
    CHECK(R.status == 2 && strstr(R.err, "--weights: bad value") != NULL);
    RUN(NULL, st_path("p_in.ppm"), "--tint", "1,1");
    CHECK(R.status == 2 && strstr(R.err, "--tint: bad value") != NULL);
    RUN(NULL, st_path("p_in.ppm"), "--passes", "9");
    CHECK(R.status == 2 && strstr(R.err, "--passes: bad value") != NULL);

    if (bloom_preset_available(BLOOM_PRESET_ARM)) { /* the mask is optional, the baked map is not */
        RUN(NULL, st_path("p_in.ppm"), "--preset", "arm", "--baked");
        CHECKF(R.status == 2 && strstr(R.err, bloom_status_str(BLOOM_E_AUX)) &&
                   strstr(R.err, "baked bloom map") && strstr(R.err, "--aux FILE"),
               "arm --baked without --aux: status %d: %s", R.status, R.err);
    }
    if (!bloom_preset_available(BLOOM_PRESET_ATTENUATION))
        return;
    CHECK(st_write_file(st_path("p_keep.ppm"), precious, sizeof precious - 1) == 0);
    /* the preset needs its depth plane: the engine's message, and the option */
    RUN(NULL, st_path("p_in.ppm"), "--preset", "attenuation", "-o", st_path("p_keep.ppm"));
    CHECKF(R.status == 2 && strstr(R.err, bloom_status_str(BLOOM_E_AUX)) && strstr(R.err, "depth plane") &&
               strstr(R.err, "--aux FILE"),
           "missing --aux: status %d: %s", R.status, R.err);
    /* an aux plane of the wrong size: names the file and both sizes */
    uint8_t small[5 * 4] = {0};
    CHECK(write_ppm8(st_path("p_small.pgm"), small, 5, 4, 1) == 0);
    RUN(NULL, st_path("p_in.ppm"), "--preset", "attenuation", "--aux", st_path("p_small.pgm"), "-o",
        st_path("p_keep.ppm"));
    char want[600];
    snprintf(want, sizeof want, "%s: --aux: the depth plane is 5x4 but the frame is 37x29",
             st_path("p_small.pgm"));
    CHECKF(R.status == 1 && strstr(R.err, want), "mis-sized --aux: status %d: %s", R.status, R.err);
    /* missing, RGB, not an image */
    RUN(NULL, st_path("p_in.ppm"), "--preset", "attenuation", "--aux", st_path("p_nothere.pgm"), "-o",
        st_path("p_keep.ppm"));
    snprintf(want, sizeof want, "%s: --aux: cannot open", st_path("p_nothere.pgm"));
    CHECKF(R.status == 1 && strstr(R.err, want), "missing --aux file: status %d: %s", R.status, R.err);
    RUN(NULL, st_path("p_in.ppm"), "--preset", "attenuation", "--aux", st_path("p_in.ppm"), "-o",
        st_path("p_keep.ppm"));
    CHECKF(R.status == 1 && strstr(R.err, "an RGB image; the aux plane is one channel"), "RGB --aux: %s",
           R.err);
    CHECK(st_write_file(st_path("p_junk.bin"), "GIF89a....", 10) == 0);
    RUN(NULL, st_path("p_in.ppm"), "--preset", "attenuation", "--aux", st_path("p_junk.bin"), "-o",
        st_path("p_keep.ppm"));
    CHECKF(R.status == 1 && strstr(R.err, "not a PGM or PNG image"), "junk --aux: %s", R.err);
    CHECKF(st_same_file(st_path("p_keep.ppm"), precious, sizeof precious - 1),
           "an aux error touched the output");
    CHECK(st_count_tmp_files() == 0);
    /* a sequence whose second image has another size: refused at that frame */
    uint8_t other[W * (H + 1) * 3];
    memset(other, 40, sizeof other);
    CHECK(write_ppm8(st_path("p_other.ppm"), other, W, H + 1, 3) == 0);
    RUN(NULL, st_path("p_in.ppm"), st_path("p_other.ppm"), "--preset", "attenuation", "--aux",
        st_path("p_ramp.pgm"), "-o", st_path("p_seq_%d.ppm"));
    CHECKF(R.status == 1 && strstr(R.err, "the frame is 37x30") && strstr(R.err, "(frame 1 of the sequence"),
           "sequence: %s", R.err);
}

void test_presets(void)
{
    make_scene(scene, W, H, 42);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            ramp8[y * W + x] = (uint8_t)(y * 255 / (H - 1));
            const int v = y * 65535 / (H - 1);
            ramp16[y * W + x] = (uint16_t)(v && (x & 1) ? v - 1 : v); /* not all multiples of 257 */
        }
    CHECK(write_ppm8(st_path("p_in.ppm"), scene, W, H, 3) == 0);
    CHECK(write_ppm8(st_path("p_ramp.pgm"), ramp8, W, H, 1) == 0);
    CHECK(st_write_png(st_path("p_ramp16.png"), ramp16, W, H, 1, 1) == 0);
    test_by_name();
    test_refusals();
}
