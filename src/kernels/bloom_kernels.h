/* The row kernels (kernels/): box, knee, tent, composite, the fused output
 * path and their SSE2/AVX2/NEON twins, bit-identical to the C ones, and the
 * set an engine picks at bloom_init, with the rounding rules and the knee
 * and output parameters they apply. They use the base (bloom_internal.h)
 * and the pixel formats (pixel/), nothing above them. */
#ifndef BLOOM_KERNELS_H
#define BLOOM_KERNELS_H

#include "bloom_pixel.h"

/* Rounding without bias (sim/docs/fixed-point.md, "Rounding without
 * bias"). A rounding point whose ties are frequent (a shift of a sum of
 * integers) either rounds half to even, or is paired with one that rounds
 * half the other way: rounding every tie up adds +1/32 LSB per box and
 * +1/16 per tent pass on average, which the up chain sums.
 *   box:  sum / 16, half to even;
 *   tent: vertical pass (x + 4) >> 3 (half up), horizontal pass
 *         (x + 3) >> 3 (half down): the two ties cancel. */
#define BLOOM_BOX_RND(sum) (((sum) + 7u + (((sum) >> 4) & 1u)) >> 4)
#define BLOOM_VT_RND 4u
#define BLOOM_HT_RND 3u
/* The knee's epsilons of bloom-model.md in internal units:
 * soft = x^2 / (4K + 0.00004) is formed as 2x^2 / (8K + KNEE_E8), with
 * KNEE_E8 = round(0.00008 * 2^F); max(b, 0.00001) is b above
 * 2^F / 100000 (10.49 at F = 20) and makes the factor num * KNEE_TINY_F
 * below it (2^24 / (2^F / 100000), an integer for F <= 20). The factor
 * is Q24 (KNEE_FBITS): at Q16 its step was 8 internal LSB on a sample of
 * 0.5, and near the knee's lower edge, where most factors are small,
 * rounding it to the nearest step came out low on average. */
#define BLOOM_KNEE_E8 ((uint32_t)(((1ull << (BLOOM_LIN_BITS + 3)) + 50000u) / 100000u))
#define BLOOM_KNEE_FBITS 24
#define BLOOM_KNEE_TINY_F (100000u << (BLOOM_KNEE_FBITS - BLOOM_LIN_BITS))
/* b * 100000 < 2^F <=> b < ceil(2^F / 100000) (never an integer) */
#define BLOOM_KNEE_TINY_B ((uint32_t)(((1ull << BLOOM_LIN_BITS) + 99999u) / 100000u))

/* Knee parameters, Q12.20 (sim/docs/fixed-point.md step 3). */
typedef struct {
    uint32_t t, k;
} bloom_knee_t;

/* How the output kernel turns B into pixels. */
typedef struct {
    bloom_format_t in_fmt, out_fmt;
    bool linear, debug;
    uint32_t intensity; /* I_q, Q16.16 */
} bloom_out_t;

/* Row kernels. Samples are interleaved R, G, B uint32_t (Q16.16).
 * Samples are Q12.20. bloom_row_box: 4x4 box down of four source rows s[0..3] (width sw) into
 * dst (width dw = ceil(sw / 2)). */
void bloom_row_box_c(const uint32_t *const s[4], uint32_t *dst, int dw, int sw);
/* The same, reading encoded pixels of fmt (decoding on the fly). */
void bloom_row_box_src_c(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                         int sw);
/* The soft knee on a row of level-1 pixels, in place. */
bool bloom_row_knee_c(uint32_t *row, int w, const bloom_knee_t *kn); /* any non-zero */
/* Tent up: destination columns x0 .. x0+n-1 of the row whose parity is odd,
 * from rows u[0..2] (width sw). dst[i] (and add[i] if add is not NULL) is
 * column x0 + i; dst = tent + add. add may equal dst. */
void bloom_row_tent_c(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0, int n,
                      int sw);
/* Output: tent of u[0..2] onto the full-resolution row, composite with the
 * source row src, encode into dst. */
void bloom_row_out_c(const uint32_t *const u[3], int odd, const uint8_t *src, uint8_t *dst, int w, int sw,
                     const bloom_out_t *o);

/* The same box for destination columns xa .. xb-1 only (dst is the row). */
void bloom_row_box_range_c(const uint32_t *const s[4], uint32_t *dst, int xa, int xb, int sw);
/* Composite of n samples in place: bl[i] = min(((I*bl[i] + 32768) >> 16) + sv[i], 2^32 - 1). */
void bloom_row_composite_c(uint32_t *bl, const uint32_t *sv, int n, uint32_t intensity);

/* Flat kernels of the fast output path (bloom_row_out_k), on n samples in
 * 32-bit arithmetic that wraps: exact while the values stay below 2^29,
 * which holds for the default pipeline on 8/6/5-bit input (U <= 16 * 2^F).
 * vtent: dst[i] = (3 a[i] + 4 b[i] + c[i] + 4) >> 3; returns the OR of every dst[i].
 * htent_eo: e[i] = (3 v[i-3] + 4 v[i] + v[i+3] + 3) >> 3 and
 *           o[i] = (v[i-3] + 4 v[i] + 3 v[i+3] + 3) >> 3 (reads v[-3 .. n+2]);
 *           returns the OR of every e[i] and o[i] (0: the bloom is zero there).
 * scale: x[i] = low 32 bits of (I x[i] + 32768) >> 16. */
uint32_t bloom_row_vtent_c(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n);
uint32_t bloom_row_htent_eo_c(const uint32_t *v, uint32_t *e, uint32_t *o, int n);
void bloom_row_scale_c(uint32_t *x, int n, uint32_t intensity);

/* What the level-1 box keeps of a row for the next: D_1 row y reads
 * source rows 2y - 1 .. 2y + 2 (clamped), so its two lower rows are row
 * y + 1's two upper ones. For column pair j (source columns 2j - 1 and 2j,
 * clamped: D_1 pixel x reads pairs x and x + 1), sum[3j + ch] holds
 * channel ch decoded and summed over the two lower rows of D_1 row
 * tag[j] - 1, and row y takes it for its upper rows instead of decoding
 * them again where tag[j] = y (the caller sets y before each row; -1: none
 * kept, as bloom_begin sets them). The sums are exact (the box's are in 32
 * bits): the same bits, half the decoding where a row follows the one
 * before. RGB888 and XRGB8888 only (the others ignore kp); not in
 * BLOOM_SMALL builds. */
typedef struct {
    uint32_t *sum; /* 3 (w + 1) for D_1 rows of w pixels */
    int32_t *tag;  /* w + 1 */
    int32_t y;     /* the row being made */
} bloom_d1_keep_t;

/* Level-1 row: bloom_row_box_src_c then bloom_row_knee_c (returns its
 * result); with kp (NULL: nothing kept) the box keeps its lower rows' sums
 * for the next row (bloom_d1_keep_t). The SIMD twins write the zeros of
 * 4-pixel blocks whose 4 x 10 source codes are all at most the dark codes
 * dk (the knee zeroes them) without computing the box: same bits. */
bool bloom_row_d1_c(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw, int sw,
                    const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp);
/* bloom_row_box_src_c for destination pixels xa .. xb-1 only (dst is the
 * row); not in BLOOM_SMALL builds. */
void bloom_row_box_src_range_c(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst,
                               int xa, int xb, int sw);
/* The same with the sums of kp (NULL: the same as the range). */
void bloom_row_box_src_kept_c(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst,
                              int xa, int xb, int sw, bloom_d1_keep_t *kp);

/* A bloom sample b at most max(A c, H0) cannot change the 8-bit sRGB code
 * c it is added to: the bound is at most t[c + 1] - dec(c) - 1 for every c
 * (tests/test_simd.c checks it on the tables built in), so t[c] <= dec(c)
 * <= dec(c) + b < t[c + 1] and the encoder gives c back. Other sample
 * precisions (BLOOM_LIN_BITS < 20) keep b = 0 only. */
#if BLOOM_LIN_BITS == 20
#define BLOOM_KEEP8_A 12
#define BLOOM_KEEP8_H0 158
#else
#define BLOOM_KEEP8_A 0
#define BLOOM_KEEP8_H0 0
#endif

/* The row kernels an engine calls, picked at bloom_init (bloom_kernels_select):
 * the C ones, or SIMD twins that give the same bits. */
typedef void (*bloom_box_fn)(const uint32_t *const s[4], uint32_t *dst, int dw, int sw);
typedef void (*bloom_tent_fn)(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                              int n, int sw);
typedef void (*bloom_composite_fn)(uint32_t *bl, const uint32_t *sv, int n, uint32_t intensity);
typedef bool (*bloom_d1_fn)(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                            int sw, const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp);
typedef uint32_t (*bloom_vtent_fn)(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst,
                                   int n);
typedef uint32_t (*bloom_htent_eo_fn)(const uint32_t *v, uint32_t *e, uint32_t *o, int n);
typedef void (*bloom_scale_fn)(uint32_t *x, int n, uint32_t intensity);
typedef void (*bloom_eo_fn)(bloom_format_t in_fmt, bloom_format_t out_fmt, bool debug, const uint8_t *src,
                            const uint32_t *e, const uint32_t *o, uint8_t *dst, int n);
/* The tent through flat kernels for whole rows (x0 = 0, n = 2 sw or 2 sw - 1),
 * bloom_row.c: per chunk of low-resolution columns the vertical tent
 * (vt, which also ORs its inputs into *in_or), the horizontal tent into
 * even and odd columns (ht), the two interleaved with add (il); a chunk
 * whose rows hold a value of 2^29 or more (the flat sums could wrap) and
 * any other call go to exact. Same bits as bloom_row_tent_c. */
typedef uint32_t (*bloom_vtent_in_fn)(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst,
                                      int n, uint32_t *in_or);
typedef void (*bloom_il_add_fn)(const uint32_t *e, const uint32_t *o, const uint32_t *add, uint32_t *dst,
                                int n);
void bloom_row_tent_flat(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                         int n, int sw, bloom_vtent_in_fn vt, bloom_htent_eo_fn ht, bloom_il_add_fn il,
                         void (*exact)(const uint32_t *const u[3], int odd, const uint32_t *add,
                                       uint32_t *dst, int x0, int n, int sw));
/* dst pixels 0 .. n-1 = the even/odd columns e, o interleaved (pixel x is
 * column x / 2 of e or o), plus add if not NULL (add may equal dst). */
void bloom_row_il_add_c(const uint32_t *e, const uint32_t *o, const uint32_t *add, uint32_t *dst, int n);
/* bloom_row_il_add_c through a SIMD twin's blocks (blocks(e, o, add, dst,
 * nb): the first 8 nb pixels). The tail is one more block overlapping the
 * last (a tile's rows end anywhere): pixels written twice get the same
 * value, since dst is read by neither e, o nor add; where add is dst
 * (gamedev adds in place) the tail is C. The block starts on an even
 * pixel, so an odd n leaves C its last. Inlined with the twin's own blocks. */
typedef void (*bloom_il_blocks_fn)(const uint32_t *e, const uint32_t *o, const uint32_t *add, uint32_t *dst,
                                   int nb);
static inline void bloom_il_add_by8(bloom_il_blocks_fn blocks, const uint32_t *e, const uint32_t *o,
                                    const uint32_t *add, uint32_t *dst, int n)
{
    blocks(e, o, add, dst, n >> 3);
    int x = n & ~7;
    if (x == n)
        return;
    if (n > 8 && add != dst) {
        const int b = (n - 8) & ~1;
        blocks(e + 3 * (b >> 1), o + 3 * (b >> 1), add ? add + 3 * b : NULL, dst + 3 * b, 1);
        x = b + 8;
        if (x == n)
            return;
    }
    bloom_row_il_add_c(e + 3 * (x >> 1), o + 3 * (x >> 1), add ? add + 3 * x : NULL, dst + 3 * x, n - x);
}

/* 16-bit samples (cfg.sample_bits = 16; sim/docs/fixed-point.md, "16-bit
 * samples"): the rings of the default pipeline hold uint16_t, the value
 * v / 2^G. On 8/6/5-bit input every D_k is at most the knee's peak P (its
 * output for a white pixel, bound + 1: bloom_knee_peak) and U_k at most
 * (L - k + 1) times that, so G is the largest fraction (below F) that keeps
 * L * P, narrowed, within 16 bits: 16 at the default threshold 1.0 and
 * knee 0.5 (P = 0.125), 13 at threshold 0 with 5 levels. D_1 is made in
 * the internal format and narrowed by F - G bits (half to even); boxes
 * and tents run on 16-bit rows with 32-bit sums and the rounding of the
 * 32-bit kernels; U_1 is widened back (<< (F - G), exact) for the output's
 * tent. Not in builds without BLOOM_USE_S16. */
uint32_t bloom_knee_peak(const bloom_knee_t *kn);
static inline int bloom_s16_frac(int levels, uint32_t peak)
{
    int g = BLOOM_LIN_BITS - 1;
    while (g > 1 &&
           (uint64_t)levels * ((peak + (1u << (BLOOM_LIN_BITS - g - 1))) >> (BLOOM_LIN_BITS - g)) > 0xFFFFu)
        g--;
    return g; /* L * 2^G * peak < 2^16: 11 .. F - 1 */
}
/* dst[i] = src[i] / 2^sh rounded half to even (n samples); returns the OR
 * of the results (0: the row narrowed to zeros). */
uint32_t bloom_row_narrow16_c(const uint32_t *src, uint16_t *dst, int n, int sh);
/* dst[i] = (src[i] / 2^sh rounded half to even) + (add ? add[i] : 0). */
void bloom_row_narrow16_add_c(const uint32_t *src, const uint16_t *add, uint16_t *dst, int n, int sh);
/* bloom_row_box_c of 16-bit rows into 32-bit samples: each sum widened
 * (<< sh) and rounded as the 32-bit box rounds it. */
void bloom_row_box16w_c(const uint16_t *const s[4], uint32_t *dst, int dw, int sw, int sh);
/* The vertical tent of the flat output path (bloom_row_vtent_c) on 16-bit
 * rows widened by sh: dst[i] = (((3 a[i] + 4 b[i] + c[i]) << sh) + 4) >> 3,
 * the same integers; returns the OR of every dst[i]. */
uint32_t bloom_row_vtent16w_c(const uint16_t *a, const uint16_t *b, const uint16_t *c, uint32_t *dst, int n,
                              int sh);
/* bloom_row_tent_c (no add) of 16-bit rows widened by sh, into 32-bit samples. */
void bloom_row_tent16w_c(const uint16_t *const u[3], int odd, uint32_t *dst, int x0, int n, int sw, int sh);
/* bloom_row_box_c on 16-bit rows (sums in 32 bits; the same rounding). */
void bloom_row_box16_c(const uint16_t *const s[4], uint16_t *dst, int dw, int sw);
/* Either box for destination pixels xa .. xb-1 only: into 16-bit samples,
 * or (wide) into 32-bit ones widened by sh (dst is the row). */
void bloom_row_box16_range_c(const uint16_t *const s[4], void *dst, bool wide, int xa, int xb, int sw,
                             int sh);
/* The tent's interleave (bloom_row_tent16_k): pixels x0 .. np-1 from the
 * even columns' e and the odd columns' o (32-bit, 3 per column), plus add
 * (NULL: none), as 16-bit samples. */
void bloom_row_il16_c(const uint32_t *e, const uint32_t *o, const uint16_t *add, uint16_t *dst, int x0,
                      int np);
/* bloom_row_tent_c on 16-bit rows (add may be NULL or equal dst). */
void bloom_row_tent16_c(const uint16_t *const u[3], int odd, const uint16_t *add, uint16_t *dst, int x0,
                        int n, int sw);

/* The instruction set a kernel set uses. */
typedef enum { BLOOM_ISA_C, BLOOM_ISA_SSE2, BLOOM_ISA_AVX2, BLOOM_ISA_NEON } bloom_isa_t;

/* bloom_row_box_src_range_c and its twins. */
typedef void (*bloom_box_src_fn)(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst,
                                 int xa, int xb, int sw);

/* bloom_row_dark and its twins. */
typedef bool (*bloom_dark_fn)(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d);
/* The dark-row test that copies the row's bytes to `copy` as it reads them
 * (the frame call's early copy of a dark row: bloom_frame.c): true, the
 * row is dark and copied whole; false, it is not, and `copy` holds a part
 * of it (the twins stop at the first block with a bright byte; the row's
 * output is written whole at its turn). bloom_row_dark_copy and twins. */
typedef bool (*bloom_dark_copy_fn)(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d,
                                   uint8_t *copy);

/* The bytes of an n-pixel row that the SIMD dark tests read by vectors: the
 * 8-bit formats (RGB888, XRGB8888) only, 0 for the others (the C test
 * decodes them). Every twin's prologue. */
static inline int bloom_dark_row_bytes(bloom_format_t fmt, int n)
{
    return fmt == BLOOM_FMT_XRGB8888 ? 4 * n : fmt == BLOOM_FMT_RGB888 ? 3 * n : 0;
}

typedef struct {
    bloom_box_fn box;
    bloom_tent_fn tent;
    bloom_composite_fn composite;
    bloom_d1_fn d1;             /* box from the source and knee (compute_d1); NULL if BLOOM_SMALL */
    bloom_vtent_fn vtent;       /* NULL in BLOOM_SMALL builds */
    bloom_htent_eo_fn htent_eo; /* NULL in BLOOM_SMALL builds */
    bloom_scale_fn scale;       /* NULL in BLOOM_SMALL builds */
    bloom_eo_fn eo;             /* bloom_encode_eo or its AVX2 twin; NULL if BLOOM_SMALL */
    bloom_box_src_fn box_src;   /* the box from the source for pixels xa .. xb-1 (no knee: the
                                   presets' first stages); C in every set today (an AVX2
                                   one by table gathers took fewer instructions and more time:
                                   sim/docs/profile.md); NULL if BLOOM_SMALL */
#if !BLOOM_SMALL
    bloom_dark_fn dark;           /* the dark-row test of every pushed source row (bloom_row_dark; the
                           twins take RGB888 and XRGB8888 rows of a vector or more) */
    bloom_dark_copy_fn dark_copy; /* the same, copying the row (bloom_row_dark_copy) */
#endif
    const char *name; /* "c", "sse2", "avx2", "neon" */
    bloom_isa_t isa;  /* the same as a value: presets pick their own twins by it */
} bloom_kernels_t;
/* The kernels for flags (BLOOM_FLAG_NO_SIMD: the C ones). */
void bloom_kernels_select(bloom_kernels_t *k, uint32_t flags);
/* bloom_row_out_c with the kernels of k, for columns x0 .. w - 1 of the
 * row (x0 even; src and dst point at column x0: a tile's row written in
 * place, the columns before it read from u but not made). For 8/6/5-bit
 * sRGB input and output it takes the fast path (flat vertical tent,
 * horizontal tent into even/odd columns, fused composite and encode),
 * which relies on the bound of the default pipeline: u values at most
 * 16 * 2^F (sums of at most 16 decoded 8/6/5-bit samples). */
void bloom_row_out_k(const bloom_kernels_t *k, const uint32_t *const u[3], int odd, const uint8_t *src,
                     uint8_t *dst, int x0, int w, int sw, const bloom_out_t *o);
/* The 16-bit kernels of k's instruction set: the AVX2 twins with the AVX2
 * set (bloom_row16_avx2.c), the SSE2 ones with SSE2 (bloom_row16_sse2.c),
 * the NEON ones with NEON (bloom_row16_neon.c), the C ones otherwise; same
 * bits. */
uint32_t bloom_row_narrow16_k(const bloom_kernels_t *k, const uint32_t *src, uint16_t *dst, int n, int sh);
void bloom_row_narrow16_add_k(const bloom_kernels_t *k, const uint32_t *src, const uint16_t *add,
                              uint16_t *dst, int n, int sh);
uint32_t bloom_row_vtent16w_k(const bloom_kernels_t *k, const uint16_t *a, const uint16_t *b,
                              const uint16_t *c, uint32_t *dst, int n, int sh);
/* bloom_row_box16_c (wide: bloom_row_box16w_c) with the kernels of k. */
void bloom_row_box16_k(const bloom_kernels_t *k, const uint16_t *const s[4], void *dst, bool wide, int dw,
                       int sw, int sh);
/* bloom_row_tent16_c for a whole row (x0 = 0) through flat passes: the
 * vertical tent (bloom_row_vtent16w_k, sh 0), k's horizontal tent into
 * even and odd columns, the interleave with add. Same bits. */
void bloom_row_tent16_k(const bloom_kernels_t *k, const uint16_t *const u[3], int odd, const uint16_t *add,
                        uint16_t *dst, int n, int sw);
/* bloom_row_out_k on U_1 rows of 16-bit samples, widened by sh in its sums
 * (no widened copy of the rows). Not in builds without BLOOM_USE_S16. */
void bloom_row_out16_k(const bloom_kernels_t *k, const uint16_t *const u[3], int sh, int odd,
                       const uint8_t *src, uint8_t *dst, int x0, int w, int sw, const bloom_out_t *o);

/* Which SIMD twins this build has (bloom_row_sse2.c, bloom_row_neon.c). */
#if !BLOOM_NO_SIMD && defined(__SSE2__) && (defined(__x86_64__) || defined(_M_X64))
#define BLOOM_SIMD_SSE2 1
void bloom_row_box_sse2_any(const uint32_t *const s[4], uint32_t *dst, int dw, int sw);
void bloom_row_tent_sse2_any(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                             int n, int sw);
void bloom_row_composite_sse2_any(uint32_t *bl, const uint32_t *sv, int n, uint32_t intensity);
bool bloom_row_d1_sse2(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                       int sw, const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp);
uint32_t bloom_row_vtent_sse2(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n);
uint32_t bloom_row_htent_eo_sse2(const uint32_t *v, uint32_t *e, uint32_t *o, int n);
void bloom_row_scale_sse2(uint32_t *x, int n, uint32_t intensity);
bool bloom_row_dark_sse2(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d);
bool bloom_row_dark_copy_sse2(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d,
                              uint8_t *copy);
/* AVX2 twins (bloom_row_avx2.c), picked at run time by bloom_cpu_avx2(). */
#if !BLOOM_NO_AVX2 && !BLOOM_SMALL && (defined(__GNUC__) || defined(__clang__))
#define BLOOM_SIMD_AVX2 1
bool bloom_cpu_avx2(void);
bool bloom_row_d1_avx2(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                       int sw, const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp);
void bloom_row_tent_avx2(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                         int n, int sw);
uint32_t bloom_row_vtent_avx2(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n);
uint32_t bloom_row_htent_eo_avx2(const uint32_t *v, uint32_t *e, uint32_t *o, int n);
void bloom_encode_eo_avx2(bloom_format_t in_fmt, bloom_format_t out_fmt, bool debug, const uint8_t *src,
                          const uint32_t *e, const uint32_t *o, uint8_t *dst, int n);
void bloom_row_box_avx2(const uint32_t *const s[4], uint32_t *dst, int dw, int sw);
bool bloom_row_dark_avx2(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d);
bool bloom_row_dark_copy_avx2(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d,
                              uint8_t *copy);
#endif
#elif !BLOOM_NO_SIMD && defined(__aarch64__) && defined(__ARM_NEON)
#define BLOOM_SIMD_NEON 1
void bloom_row_box_neon_any(const uint32_t *const s[4], uint32_t *dst, int dw, int sw);
void bloom_row_tent_neon_any(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                             int n, int sw);
void bloom_row_composite_neon_any(uint32_t *bl, const uint32_t *sv, int n, uint32_t intensity);
bool bloom_row_d1_neon(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                       int sw, const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp);
uint32_t bloom_row_vtent_neon(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n);
uint32_t bloom_row_htent_eo_neon(const uint32_t *v, uint32_t *e, uint32_t *o, int n);
void bloom_row_scale_neon(uint32_t *x, int n, uint32_t intensity);
void bloom_row_tent_neon_flat(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                              int n, int sw);
void bloom_encode_eo_neon(bloom_format_t in_fmt, bloom_format_t out_fmt, bool debug, const uint8_t *src,
                          const uint32_t *e, const uint32_t *o, uint8_t *dst, int n);
bool bloom_row_dark_neon(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d);
bool bloom_row_dark_copy_neon(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d,
                              uint8_t *copy);
#endif
/* The dark-row test of a kernel set (bloom_row_dark itself where the sets
 * carry no slot for it: BLOOM_SMALL). */
#if BLOOM_SMALL
#define BLOOM_KERN_DARK(k) bloom_row_dark
#else
#define BLOOM_KERN_DARK(k) ((k)->dark)
#endif

/* Whether k holds SIMD twins (the C set is the one with the C box); a
 * constant false on targets without any (the fast output path drops out). */
static inline bool bloom_kernels_simd(const bloom_kernels_t *k)
{
#if defined(BLOOM_SIMD_SSE2) || defined(BLOOM_SIMD_NEON)
    return k->box != bloom_row_box_c;
#else
    (void)k;
    return false;
#endif
}

/* A row with B = 0: the source decoded and encoded again (no tent). */
void bloom_row_copy_c(const uint8_t *src, uint8_t *dst, int w, const bloom_out_t *o);

/* Whether bloom_row_copy_c is a copy of the bytes: one format, RGB888 or
 * RGB565 (decode then encode gives each code back, tests/test_fixed.c), no
 * debug view. bloom_process's early copy of dark rows relies on the same. */
static inline bool bloom_copy_is_bytes(const bloom_out_t *o)
{
    return !o->debug && o->in_fmt == o->out_fmt &&
           (o->in_fmt == BLOOM_FMT_RGB888 || o->in_fmt == BLOOM_FMT_RGB565);
}

/* The AVX2 twins of the 16-bit kernels (bloom_row16_avx2.c). */
#if defined(BLOOM_SIMD_AVX2) && BLOOM_USE_S16
uint32_t bloom_row_narrow16_avx2(const uint32_t *src, uint16_t *dst, int n, int sh);
void bloom_row_narrow16_add_avx2(const uint32_t *src, const uint16_t *add, uint16_t *dst, int n, int sh);
uint32_t bloom_row_vtent16w_avx2(const uint16_t *a, const uint16_t *b, const uint16_t *c, uint32_t *dst,
                                 int n, int sh);
void bloom_row_box16_avx2(const uint16_t *const s[4], uint16_t *dst, int dw, int sw);
void bloom_row_box16w_avx2(const uint16_t *const s[4], uint32_t *dst, int dw, int sw, int sh);
void bloom_row_il16_avx2(const uint32_t *e, const uint32_t *o, const uint16_t *add, uint16_t *dst, int np);
#endif
/* The NEON twins of the 16-bit kernels (bloom_row16_neon.c). */
#if defined(BLOOM_SIMD_NEON) && BLOOM_USE_S16
uint32_t bloom_row_narrow16_neon(const uint32_t *src, uint16_t *dst, int n, int sh);
void bloom_row_narrow16_add_neon(const uint32_t *src, const uint16_t *add, uint16_t *dst, int n, int sh);
uint32_t bloom_row_vtent16w_neon(const uint16_t *a, const uint16_t *b, const uint16_t *c, uint32_t *dst,
                                 int n, int sh);
void bloom_row_box16_neon(const uint16_t *const s[4], uint16_t *dst, int dw, int sw);
void bloom_row_box16w_neon(const uint16_t *const s[4], uint32_t *dst, int dw, int sw, int sh);
void bloom_row_il16_neon(const uint32_t *e, const uint32_t *o, const uint16_t *add, uint16_t *dst, int np);
#endif
/* The SSE2 twins of the 16-bit kernels (bloom_row16_sse2.c). */
#if defined(BLOOM_SIMD_SSE2) && BLOOM_USE_S16
uint32_t bloom_row_narrow16_sse2(const uint32_t *src, uint16_t *dst, int n, int sh);
uint32_t bloom_row_vtent16w_sse2(const uint16_t *a, const uint16_t *b, const uint16_t *c, uint32_t *dst,
                                 int n, int sh);
void bloom_row_box16_sse2(const uint16_t *const s[4], uint16_t *dst, int dw, int sw);
void bloom_row_box16w_sse2(const uint16_t *const s[4], uint32_t *dst, int dw, int sw, int sh);
#endif

#endif
