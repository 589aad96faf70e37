# make test-linux's MJPEG cases (sourced by run.sh): a camera that sends
# Motion-JPEG, made of the kernel's v4l2loopback (Debian's
# v4l2loopback-dkms source, downloaded and built out of tree against the
# guest kernel's headers as gpio-sim is, never installed) fed in the guest by
# loopfeed (write() of JPEG frames at about 30 per second, one in ten
# corrupt and one in ten truncated: mkjpeg makes them on the host and checks
# that libjpeg warns about both). bloom_cam --format mjpeg reads it; the
# damaged frames must be skipped and counted, the run must end with its
# frames, and the screen must equal bloom_sim on the good JPEG. Then the
# camera leaves and comes back in another size (640x480): bloom_cam must
# make its engines again for it and go on, its screen bloom_sim's output of
# the new size's JPEG.
mjpeg_cases_n=7  # the cases mjpeg_checks counts, run or skipped
mj_off=""        # why the MJPEG cases are left out
mj_dir=""
MJ_SIZE=320x240
mjpeg_build() { # sets mj_dir (the cached v4l2loopback.ko), or mj_off
    [ -n "$HVER" ] || resolve_gpio || { refresh "$why" && resolve_gpio; } || { mj_off="$why"; return; }
    LVER=$(pick v4l2loopback-dkms "") ||
        { refresh "v4l2loopback-dkms not in apt's lists" && LVER=$(pick v4l2loopback-dkms ""); } ||
        { mj_off="v4l2loopback-dkms is not in apt's lists"; return; }
    mj_dir=$cache/v4l2loopback_${KVER}_headers-${HVER}_kbuild-${KBVER}_src-$LVER
    [ -f "$mj_dir/v4l2loopback.ko" ] && return
    g=$cache/loop-build && rm -rf "$g" && mkdir -p "$g/hdr" "$g/m" || { mj_off="cannot make $g"; return; }
    for pv in "$HPKG $HVER" "$CPKG $CVER" "$KBPKG $KBVER" "v4l2loopback-dkms $LVER"; do
        set -- $pv
        [ $# = 2 ] || continue
        get_deb "$1" "$2" || { mj_off="apt-get download $1=$2 failed (see $B/linux/kernel/download.log)"; return; }
        dpkg-deb -x "$deb" "$g/hdr" || { mj_off="cannot unpack $deb"; return; }
    done
    hd=$g/hdr/usr/src/linux-headers-$KVER
    sed -i "s#^include /usr/src/#include $g/hdr/usr/src/#" "$hd/Makefile"
    src=$(ls -d "$g/hdr/usr/src/v4l2loopback-"* 2>/dev/null | head -n 1)
    [ -f "$src/v4l2loopback.c" ] || { mj_off="no v4l2loopback.c in v4l2loopback-dkms $LVER"; return; }
    cp "$src"/*.c "$src"/*.h "$g/m/" && echo 'obj-m := v4l2loopback.o' > "$g/m/Kbuild" || { mj_off="cannot copy $src"; return; }
    t0=$(date +%s)
    make -C "$hd" M="$g/m" modules > "$g/build.log" 2>&1 ||
        { cp "$g/build.log" "$cache/loop-build.log"; mj_off="v4l2loopback build failed (see $B/linux/kernel/loop-build.log)"; return; }
    rm -rf "$mj_dir.tmp" && mkdir -p "$mj_dir.tmp" && cp "$g/m/v4l2loopback.ko" "$mj_dir.tmp/" &&
        mv "$mj_dir.tmp" "$mj_dir" && rm -rf "$g" || { mj_off="cannot write $mj_dir"; return; }
    echo "test-linux: built v4l2loopback $LVER for $KVER in $(($(date +%s) - t0)) s (cached)"
}
mjpeg_guest() { # root: the module (loaded last: it needs videodev, which vivid brings), loopfeed, the frames
    [ -z "$mj_off" ] || return
    cp "$mj_dir/v4l2loopback.ko" "$1/modules/" && echo v4l2loopback >> "$1/modules.order" &&
        echo "v4l2loopback video_nr=7 exclusive_caps=1 card_label=loopcam" >> "$1/modules.args" ||
        { mj_off="cannot copy v4l2loopback.ko"; return; }
    cc -std=c11 -O2 -static -D_POSIX_C_SOURCE=200809L "$here/loopfeed.c" -o "$1/loopfeed" ||
        { mj_off="building loopfeed failed"; return; }
    cc -std=c11 -O2 "$here/mkjpeg.c" -ljpeg -o "$work/mkjpeg" || { mj_off="building mkjpeg failed"; return; }
    "$work/mkjpeg" "${MJ_SIZE%x*}" "${MJ_SIZE#*x}" "$1/good.jpg" "$1/corrupt.jpg" "$1/trunc.jpg" &&
        "$work/mkjpeg" 640 480 "$1/good2.jpg" "$work/corrupt2.jpg" "$work/trunc2.jpg" ||
        { mj_off="mkjpeg failed"; return; }
}
mjpeg_screen() { # case jpeg size: the screen against bloom_sim on the JPEG, placed as last said
    c=$1; t=$r/$c.txt
    shown=$(sed -n 's/.*, \([0-9]*\)x\([0-9]*\) shown from \([0-9]*\),\([0-9]*\)$/\1 \2 \3 \4/p' "$t" | tail -n 1)
    rm -rf "$work/sim" && mkdir -p "$work/sim"
    if [ -n "$shown" ] && "$B/bloom_sim" "$2" --in-format rgb888 --out-format rgb565 \
            --threshold 0.6 --intensity 1.5 -q -o "$work/sim/good.ppm" > "$work/sim.log" 2>&1; then
        set -- $shown "$3"; part=""; [ "${1}x$2" = "$5" ] || part="part $3 $4 $2"
        if res=$("$work/fbcmp" "$r/$c.fb" rgb565 "$1" "$work/sim/good.ppm" $part 2>&1); then
            ok "$c: $5 MJPEG through v4l2loopback, framebuffer = bloom_sim on its good JPEG: $res"
        else
            bad "$c: $res"
        fi
    else
        bad "$c: no screen line, or bloom_sim failed"; sed 's/^/       /' "$t" "$work/sim.log" 2>/dev/null
    fi
}
mjpeg_checks() {
    if [ -n "$mj_off" ]; then
        i=0; while [ $i -lt $mjpeg_cases_n ]; do need "mjpeg case $((i + 1)) of $mjpeg_cases_n" "$mj_off"; i=$((i + 1)); done
        return
    fi
    c=mjpeg; t=$r/$c.txt
    fault_check $c 0 "bloom_cam: total: 40 frames"
    nb=$(sed -n 's/^bloom_cam: total: .* bad (\([0-9]*\) flagged, \([0-9]*\) short, \([0-9]*\) undecodable JPEG).*/\3/p' "$t" 2>/dev/null)
    if grep -q '^exit 0$' "$t" 2>/dev/null && [ "${nb:-0}" -ge 2 ] && grep -q "undecodable JPEG: " "$t"; then
        ok "$c: $nb damaged JPEG frames skipped and counted ($(grep -o 'frame [0-9]* undecodable JPEG: [^:]*' "$t" | head -n 1)), the run went on"
    else
        bad "$c: wanted damaged frames skipped and counted (got '${nb:-none}')"; sed 's/^/       /' "$t" 2>/dev/null
    fi
    mjpeg_screen $c "$work/root/good.jpg" "$MJ_SIZE"
    # the camera back in another size: the engines made again, the run goes on
    fault_check mjpeg-resize 0 "bloom_cam: total: 100 frames"
    fault_check mjpeg-resize 0 "bloom_cam: reconnect: renegotiated 640x480; frame at 40,48, 640x480 shown from 0,0"
    fault_check mjpeg-resize 0 "loopfeed: resized to 640x480 after 60 frames"
    mjpeg_screen mjpeg-resize "$work/root/good2.jpg" 640x480
}
