# make test-linux's DRM cases (sourced by run.sh; the guest side is
# drm_init.sh): bloom_cam --display drm on bochs-drm (XRGB8888) and cirrus
# (RGB565; bochs has no RGB565 plane format, that refusal is a case too).
# Each screen read back while bloom_cam runs (drmgrab: the CRTC's
# framebuffer, through GETFB and MAP_DUMB) must equal bloom_sim's output of
# the last or the one before the last frame recorded when it was stopped
# (the last one may still be being drawn in the other buffer): never a
# frame half-drawn. The CRTC must be the one found after every way out.
drm_cases_n=23  # the cases drm_checks counts, run or skipped
drm_off=""
drm_guest() { # root: drmgrab and drm_init.sh into the initramfs; sets drm_off
    if ! grep -aq drmModePageFlip "$B/linux/bloom_cam.static"; then
        drm_off="bloom_cam.static was built without libdrm (Debian libdrm-dev, with libdrm.a)"; return
    fi
    cc -std=c11 -O2 -static -D_POSIX_C_SOURCE=200809L $(pkg-config --cflags libdrm) "$here/drmgrab.c" \
        $(pkg-config --libs libdrm) -o "$1/drmgrab" || { drm_off="building drmgrab failed"; return; }
    cp "$here/drm_init.sh" "$1/drm_init.sh"
}
drm_skip_all() { # why
    i=0; while [ $i -lt $drm_cases_n ]; do need "drm case $((i + 1)) of $drm_cases_n" "$1"; i=$((i + 1)); done
}
# name fbformat: the grabs against bloom_sim's frames of the recording
drm_grabs() {
    c=$1; ff=$2; t=$r/$c.txt
    geo=$(sed -n 's/.*): \([0-9]*x[0-9]*\) \([a-z0-9]*\), bytesperline \([0-9]*\),.*/\1 \2 \3/p' "$t" | head -n 1)
    at=$(sed -n 's/.*; frame at \([0-9]*\),\([0-9]*\), [0-9]*x[0-9]* shown from 0,0$/\1 \2/p' "$t" | head -n 1)
    rm -rf "$work/sim" && mkdir -p "$work/sim"
    if [ -z "$geo" ] || [ -z "$at" ] ||
        ! "$B/bloom_sim" "$r/$c.raw" --raw-size "${geo%% *}" --raw-format "$(echo "$geo" | cut -d' ' -f2)" \
            --raw-stride "${geo##* }" --in-format rgb888 --out-format "$ff" -q -o "$work/sim/f%04d.ppm" \
            --threshold 0.6 --intensity 1.5 > "$work/sim.log" 2>&1; then
        for k in 1 2 3; do bad "$c grab $k: no capture line, no placement, or bloom_sim failed"; done
        sed 's/^/       /' "$t" "$work/sim.log"; return
    fi
    w=${geo%%x*}
    for k in 1 2 3; do
        g=$(sed -n "s/^grab $k: frames \([0-9]*\) rest 0 geo \([0-9]*\) \([0-9]*\) \([0-9]*\) \([0-9]*\) \([0-9]*\)$/\1 \2 \3 \4 \5 \6/p" "$t")
        [ -n "$g" ] || { bad "$c grab $k: no grab line (or a partial frame recorded)"; grep '^grab\|^exit' "$t" | sed 's/^/       /'; continue; }
        set -- $g; n=$1; sw=$2; sh=$3; pitch=$4; bpp=$5; fbid=$6
        res=""; m=""
        for f in $n $((n - 1)); do
            p=$work/sim/f$(printf %04d $((f - 1))).ppm  # bloom_sim counts from 0
            [ -f "$p" ] && res=$("$work/fbcmp" "$r/$c.g$k" "$ff" "$w" "$p" "$pitch" $at 2>&1) && { m=$f; break; }
        done
        differ="frames $((n - 1)) and $n differ"
        cmp -s "$work/sim/f$(printf %04d $((n - 2))).ppm" "$work/sim/f$(printf %04d $((n - 1))).ppm" 2>/dev/null &&
            differ="frames $((n - 1)) and $n are the same"
        [ -z "$m" ] || [ "$k" != 1 ] || drm_ctl="$c $k $pitch $m $at"  # for the negative control
        if [ -n "$m" ]; then
            ok "$c grab $k: fb $fbid ${sw}x$sh ${bpp} bpp = bloom_sim's frame $m ($n recorded; $differ): $res"
        else
            bad "$c grab $k: fb $fbid ${sw}x$sh matches neither frame $n nor $((n - 1)) of bloom_sim: $res"
        fi
    done
}
# negative control: drm-32's first grab with the lowest bit of one pixel
# of the frame flipped (its centre's blue) must no longer match
drm_ctl=""
drm_negative() {
    set -- $drm_ctl
    if [ $# = 6 ]; then
        at=$(( ($6 + 90) * $3 + ($5 + 160) * 4 ))
        v=$(od -An -tu1 -j "$at" -N 1 "$r/$1.g$2" | tr -d ' ')
        cp "$r/$1.g$2" "$work/flip.g" &&
            printf "\\$(printf %03o $((v ^ 1)))" | dd of="$work/flip.g" bs=1 seek="$at" conv=notrunc 2>/dev/null
        p=$work/sim/f$(printf %04d $(($4 - 1))).ppm
        if ! cmp -s "$work/flip.g" "$r/$1.g$2" && ! "$work/fbcmp" "$work/flip.g" xrgb8888 320 "$p" "$3" "$5" "$6" \
            > "$work/flip.log" 2>&1 && grep -q '^fbcmp: 1 pixels differ$' "$work/flip.log"; then
            ok "negative control: one pixel of $1's grab $2 changed, fbcmp finds it ($(head -n 1 "$work/flip.log"))"
            return
        fi
    fi
    bad "negative control: a changed pixel of drm-32's grab was not found (or no grab matched: '$drm_ctl')"
}
drm_restored() { # name what: the CRTC after = the one before (held by drmgrab, or the console's)
    c=$1; t=$r/$c.txt
    held=$(sed -n 's/^held fb \([0-9]*\) mode \(.*\)$/fb \1 mode \2/p' "$t")
    before=$(sed -n 's/^before: crtc [0-9]* //p' "$t"); after=$(sed -n 's/^after: crtc [0-9]* //p' "$t")
    whose="drmgrab's, --vt off"; [ -n "$held" ] || { held=$before; whose="the console's"; }
    if [ -n "$before" ] && [ "$before" = "$held" ] && [ "$after" = "$held" ] && grep -q "^exit 0$" "$t"; then
        ok "$c: the CRTC restored $2 ($after, $whose; exit 0)"
    else
        bad "$c: CRTC held '$held', before '$before', after '$after' $2"; sed 's/^/       /' "$t"
    fi
}
drm_checks() {
    [ -z "$drm_off" ] || { drm_skip_all "$drm_off"; return; }
    if ! grep -q '^drm: bochs-drm /dev/dri/card[0-9]*, cirrus /dev/dri/card[0-9]*;' "$r/guest.log"; then
        drm_skip_all "the guest has no bochs-drm or no cirrus card: $(grep '^drm:' "$r/guest.log")"; return
    fi
    drm_grabs drm-32 xrgb8888
    drm_restored drm-32 "after SIGTERM"
    fault_check drm-32 0 "bloom_cam: stopping on SIGTERM"
    fault_check drm-32 0 "(preferred); CRTC as found: fb"
    fault_check drm-32 0 "two dumb buffers flipped on the vertical blank"
    if grep -q '^vt during: graphics$' "$r/drm-32.txt" && grep -q '^vt after: text$' "$r/drm-32.txt"; then
        ok "drm-32: the VT in graphics mode while drawing, text after"
    else
        bad "drm-32: the VT not graphics during, text after"; grep '^vt' "$r/drm-32.txt" | sed 's/^/       /'
    fi
    fault_check drm-32 0 "bloom_cam: --vt /dev/tty0: graphics mode while drawing"
    drm_negative
    drm_grabs drm-32-t2 xrgb8888
    drm_restored drm-32-t2 "after its frames"
    if grep -q '^grab 1: .* geo 640 480 ' "$r/drm-32-t2.txt" && grep -q ', mode 640x480 640x480@' "$r/drm-32-t2.txt"; then
        ok "drm-32-t2: --drm-mode 640x480 set (and read back 640x480)"
    else
        bad "drm-32-t2: --drm-mode 640x480 not what was set"; sed 's/^/       /' "$r/drm-32-t2.txt"
    fi
    drm_grabs drm-16 rgb565
    drm_restored drm-16 "after SIGTERM"
    fault_check drm-nomode 4 "--drm-mode 123x45: connector"
    fault_check drm-bochs565 4 "the primary plane scans out neither of the formats asked for"
    fault_check drm-auto 0 "bloom_cam: /dev/dri/card0 (bochs-drm): connector"
    b=$(sed -n 's/^before: crtc [0-9]* //p' "$r/drm-auto.txt"); a=$(sed -n 's/^after: crtc [0-9]* //p' "$r/drm-auto.txt")
    if [ -n "$b" ] && [ "$a" = "$b" ]; then
        ok "drm-auto: the CRTC as before ($a: the fbdev emulation's)"
    else
        bad "drm-auto: CRTC before '$b', after '$a'"
    fi
}
