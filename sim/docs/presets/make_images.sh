#!/bin/sh
# Before/after image of every preset this build carries (make preset-images):
# build/bloom_sim --side-by-side on a real photo into sim/docs/presets/NAME.png,
# four panels: input | fixed-point output | float model | |fixed - float| x 64.
#
#   sh sim/docs/presets/make_images.sh [BUILD_DIR]    (default build; needs BUILD/bloom_sim)
#
# The photo: tests/data/rocket_floodlights.ppm (640x427, sRGB; provenance in
# tests/data/README.md; its lights are a row of floodlights along the bottom),
# threshold 0.6 and intensity 1.5 for every preset (make demo's), the preset's
# other defaults. The presets that read a plane get one made here by a tiny
# C helper (no new dependencies):
#   attenuation  a depth plane, a horizontal ramp: near (0) at the left, far
#                (255) at the right, so the glow of the left lights is cut to
#                the maximum reduction and the right ones keep theirs;
#   arm          a mask: only the left half may bloom.
# Each run also checks the engine against the preset's bit-true model
# (--bittrue): a differing sample fails the script. An image above 1 MB is
# made again from the photo downscaled 2x (a box filter, in the helper).
set -eu
B=${1:-build}
SIM=$B/bloom_sim
IN=${PRESET_IMAGE:-tests/data/rocket_floodlights.ppm}
OUT=sim/docs/presets
W=$B/presets_img
CC=${CC:-cc}
LIMIT=1000000

[ -x "$SIM" ] || { echo "make_images.sh: $SIM missing (make sim)" >&2; exit 1; }
mkdir -p "$W"

# The helper: mkplane ramp|half REF.ppm OUT.pgm (a plane of REF's size:
# 0 at the left to 255 at the right, or 255 on the left half and 0 on the right),
# mkplane down2 IN.ppm OUT.ppm (2x2 box, odd edge kept).
cat > "$W/mkplane.c" <<'HELPER'
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
static int fail(const char *m) { fprintf(stderr, "mkplane: %s\n", m); return 1; }
static int num(FILE *f) /* the next header number, # comments skipped */
{
    int c = fgetc(f), v = -1;
    while (c == '#' || c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        if (c == '#')
            while (c != EOF && c != '\n')
                c = fgetc(f);
        c = fgetc(f);
    }
    while (c >= '0' && c <= '9')
        v = (v < 0 ? 0 : v * 10) + (c - '0'), c = fgetc(f);
    return v; /* the one whitespace byte after it is consumed */
}
int main(int argc, char **argv)
{
    FILE *f = argc == 4 ? fopen(argv[2], "rb") : NULL;
    int w = 0, h = 0;
    if (!f || fgetc(f) != 'P' || fgetc(f) != '6' || (w = num(f)) < 1 || (h = num(f)) < 1 ||
        num(f) != 255)
        return fail("usage: mkplane ramp|half|down2 REF.ppm (8-bit binary PPM) OUT");
    FILE *o = fopen(argv[3], "wb");
    if (!o)
        return fail("cannot write");
    if (!strcmp(argv[1], "down2")) {
        unsigned char *p = malloc((size_t)w * h * 3);
        if (!p || fread(p, 3, (size_t)w * h, f) != (size_t)w * h)
            return fail("down2: truncated");
        int w2 = (w + 1) / 2, h2 = (h + 1) / 2;
        fprintf(o, "P6\n%d %d\n255\n", w2, h2);
        for (int y = 0; y < h2; y++)
            for (int x = 0; x < w2; x++)
                for (int c = 0; c < 3; c++) {
                    int s = 0, n = 0;
                    for (int dy = 0; dy < 2; dy++)
                        for (int dx = 0; dx < 2; dx++)
                            if (2 * y + dy < h && 2 * x + dx < w)
                                s += p[((size_t)(2 * y + dy) * w + 2 * x + dx) * 3 + c], n++;
                    fputc((s + n / 2) / n, o);
                }
        free(p);
    } else {
        const int ramp = !strcmp(argv[1], "ramp");
        fprintf(o, "P5\n%d %d\n255\n", w, h);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                fputc(ramp ? (w > 1 ? (255 * x + (w - 1) / 2) / (w - 1) : 255)
                           : (x < w / 2 ? 255 : 0), o);
    }
    fclose(f);
    return fclose(o) ? fail("write failed") : 0;
}
HELPER
$CC -O2 -o "$W/mkplane" "$W/mkplane.c"

# the presets this build carries, from bloom_sim --help
presets=$("$SIM" --help | sed -n 's/^  This build has: \(.*\)\.$/\1/p' | tr -d ',')
[ -n "$presets" ] || { echo "make_images.sh: no preset list in bloom_sim --help" >&2; exit 1; }

run() { # NAME INPUT: OUT/NAME.png
    name=$1; img=$2
    set -- --preset "$name" --threshold 0.6 --intensity 1.5
    case $name in
    attenuation) "$W/mkplane" ramp "$img" "$W/depth.pgm"; set -- "$@" --aux "$W/depth.pgm" ;;
    arm) "$W/mkplane" half "$img" "$W/mask.pgm"; set -- "$@" --aux "$W/mask.pgm" ;;
    esac
    echo "== $name: $SIM $img $* --bittrue -q --side-by-side $OUT/$name.png"
    if ! "$SIM" "$img" "$@" --bittrue -q --side-by-side "$OUT/$name.png" > "$W/$name.log" 2>&1; then
        sed 's/^/   /' "$W/$name.log" >&2
        exit 1
    fi
    grep '^summary' "$W/$name.log" | sed 's/^/   /'
}

for p in $presets; do
    run "$p" "$IN"
    if [ "$(wc -c < "$OUT/$p.png")" -gt "$LIMIT" ]; then
        [ -f "$W/half.ppm" ] || "$W/mkplane" down2 "$IN" "$W/half.ppm"
        echo "   $OUT/$p.png is above $LIMIT bytes: again at half size"
        run "$p" "$W/half.ppm"
    fi
    echo "   $OUT/$p.png: $(wc -c < "$OUT/$p.png") bytes"
done
