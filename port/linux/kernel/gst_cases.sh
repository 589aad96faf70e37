# Sourced by run.sh (make test-linux): the GStreamer element `bloom`
# (port/gstreamer, build/gst/libgstbloom.so) between the kernel's own
# drivers, in the same guest:
#
#   v4l2src (vivid) ! video/x-raw,format=F,width=320,height=180 ! tee name=t
#     t. ! queue ! filesink      (the frames the pipeline consumed)
#     t. ! queue ! bloom in-place=false ! fbdevsink sync=false qos=false
#
# gst-16: F = RGB16 (vivid's RGB565) on vivid's 16 bpp RGB565 screen;
# gst-32: F = BGRx (vivid's XRGB32) on bochs-drm's 32 bpp XRGB8888 screen.
# No videoconvert anywhere: vivid captures the screen's own format, the
# element gives the same format out, fbdevsink copies rows (centred, as it
# always does). Every frame reaches the sink (sync=false, qos=false: no
# frame is dropped for lateness under emulation) and the tee hands both
# branches the same buffers, so the screen holds the element's output of the
# last frame recorded. The screen is zeroed first, read back after (fbgrab:
# its geometry and the visible page), and its centred 320x180 compared bit
# for bit (fbcmp) with bloom_sim run on the recorded frames (RGB565 dumps
# directly; BGRx through raw2ppm, the same codes, as XRGB8888 in and out).
#
# The guest gets gst-launch-1.0, the plugins coreelements, video4linux2,
# fbdevsink and libgstbloom.so, their ldd closure and the dynamic loader,
# copied from the host (so the host must be x86-64); GST_PLUGIN_SYSTEM_PATH
# is the copied plugins only, GST_REGISTRY a file in the guest's /tmp.
# Host packages (installed by run.sh's apt-get path when missing):
# gstreamer1.0-tools, gstreamer1.0-plugins-good (v4l2src),
# gstreamer1.0-plugins-bad (fbdevsink), libgstreamer1.0-dev and
# libgstreamer-plugins-base1.0-dev (to build the element).
# LINUX_TEST_GST=0 leaves the GStreamer cases out (skipped, not a failure).
GST_SIZE=320x180  # one of vivid's webcam sizes (v4l2src takes no nearest size)
gst_cases="gst-16 gst-32"
gst_plugdir() { # the host's GStreamer plugin directory
    d=/usr/lib/$(cc -print-multiarch 2>/dev/null)/gstreamer-1.0
    [ -d "$d" ] || d=$(ls -d /usr/lib/*/gstreamer-1.0 2>/dev/null | head -n 1)
    echo "$d"
}
gst_missing() { # the Debian packages the GStreamer cases lack
    d=$(gst_plugdir); m=""
    command -v gst-launch-1.0 >/dev/null 2>&1 && [ -f "$d/libgstcoreelements.so" ] || m="$m gstreamer1.0-tools"
    [ -f "$d/libgstvideo4linux2.so" ] || m="$m gstreamer1.0-plugins-good"
    [ -f "$d/libgstfbdevsink.so" ] || m="$m gstreamer1.0-plugins-bad"
    command -v pkg-config >/dev/null 2>&1 || m="$m pkgconf"
    [ -f /usr/include/gstreamer-1.0/gst/gst.h ] || m="$m libgstreamer1.0-dev"
    [ -f /usr/include/gstreamer-1.0/gst/video/video.h ] || m="$m libgstreamer-plugins-base1.0-dev"
    echo "$m"
}
gst_off=""   # why the GStreamer cases are left out
gst_need=1   # and whether that is a failure under CI
gst_bad=""   # a step that failed: the cases are failures
gst_guest() { # root: the element and what it needs into the initramfs; sets gst_off or gst_bad
    root=$1
    [ "${LINUX_TEST_GST:-1}" != 0 ] || { gst_off="LINUX_TEST_GST=0"; gst_need=0; return; }
    [ "$(uname -m)" = x86_64 ] ||
        { gst_off="the host is $(uname -m): its GStreamer cannot run in the x86-64 guest"; gst_need=0; return; }
    m=$(gst_missing)
    [ -z "$m" ] || { gst_off="GStreamer packages missing:$m"; return; }
    if ! ${MAKE:-make} --no-print-directory B="$B" "$B/gst/libgstbloom.so" > "$top/$B/linux/gst-build.log" 2>&1; then
        gst_bad="make $B/gst/libgstbloom.so failed (see $B/linux/gst-build.log)"; return
    fi
    d=$(gst_plugdir)
    mkdir -p "$root/usr/bin" "$root/usr/lib/gst" "$root/usr/lib/gst-plugins" "$root/lib64" "$root/tmp" &&
        cp "$(command -v gst-launch-1.0)" "$root/usr/bin/" &&
        cp "$d/libgstcoreelements.so" "$d/libgstvideo4linux2.so" "$d/libgstfbdevsink.so" \
            "$top/$B/gst/libgstbloom.so" "$root/usr/lib/gst-plugins/" ||
        { gst_bad="cannot copy GStreamer into the initramfs"; return; }
    deps=$(ldd "$root/usr/bin/gst-launch-1.0" "$root"/usr/lib/gst-plugins/*.so 2>&1)
    if echo "$deps" | grep -q 'not found'; then
        gst_bad="ldd: $(echo "$deps" | grep 'not found' | sort -u | tr -s ' \t' ' ' | tr '\n' ';')"; return
    fi
    for l in $(echo "$deps" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }' | sort -u); do
        cp -L "$l" "$root/usr/lib/gst/" || { gst_bad="cannot copy $l"; return; }
    done
    ld=$(readelf -l "$root/usr/bin/gst-launch-1.0" | sed -n 's/.*interpreter: \(.*\)\]$/\1/p')
    case "$ld" in /lib64/*) cp -L "$ld" "$root$ld" || { gst_bad="cannot copy $ld"; return; };;
                  *) gst_bad="gst-launch-1.0's loader is '$ld', not in /lib64"; return;; esac
    cc -std=c11 -O2 -static -D_POSIX_C_SOURCE=200809L "$here/fbgrab.c" -o "$root/fbgrab" &&
        cc -std=c11 -O2 "$here/raw2ppm.c" -o "$work/raw2ppm" || gst_bad="building fbgrab or raw2ppm failed"
}
gst_check() { # case fbformat bytes-per-pixel sim-options...
    c=$1; ff=$2; bpp=$3; shift 3
    t=$r/$c.txt
    grep -q '^exit 0$' "$t" 2>/dev/null || { bad "$c: gst-launch-1.0 failed"; sed 's/^/       /' "$t" 2>/dev/null; return; }
    w=${GST_SIZE%x*}; h=${GST_SIZE#*x}; fsz=$((w * h * bpp))
    sz=$(wc -c < "$r/$c.raw" 2>/dev/null || echo 0); n=$((sz / fsz))
    [ "$sz" -gt 0 ] && [ $((n * fsz)) -eq "$sz" ] && [ "$n" -eq "$FRAMES" ] ||
        { bad "$c: recorded $sz bytes, wanted $FRAMES frames of $fsz ($GST_SIZE packed)"; return; }
    set -- $(sed -n 's/^fb: //p' "$t") "$@"  # xres yres xoffset yoffset line_length bpp
    [ $# -ge 6 ] || { bad "$c: no screen geometry (fbgrab)"; sed 's/^/       /' "$t"; return; }
    xres=$1; yres=$2; stride=$5; shift 6
    rm -rf "$work/sim" && mkdir -p "$work/sim"
    if [ "$ff" = rgb565 ]; then
        set -- "$r/$c.raw" --raw-size "$GST_SIZE" --raw-format rgb565 "$@"
    else
        "$work/raw2ppm" "$r/$c.raw" "$w" "$h" $((w * 4)) "$work/sim/in%04d.ppm" > /dev/null ||
            { bad "$c: raw2ppm failed"; return; }
        set -- "$work/sim"/in*.ppm "$@"
    fi
    if ! "$B/bloom_sim" "$@" --format "$ff" -q -o "$work/sim/f%04d.ppm" > "$work/sim.log" 2>&1; then
        bad "$c: bloom_sim failed"; sed 's/^/       /' "$work/sim.log"; return
    fi
    last=$(ls "$work/sim"/f*.ppm | tail -n 1)
    # vivid's pattern moves (init.sh): the last frame is not the one before
    if cmp -s "$last" "$(ls "$work/sim"/f*.ppm | tail -n 2 | head -n 1)"; then
        bad "$c: the last two frames recorded are identical (vivid's Horizontal Movement not in effect)"
    elif res=$("$work/fbcmp" "$r/$c.fb" "$ff" "$w" "$last" "$stride" $(((xres - w) / 2)) $(((yres - h) / 2)) 2>&1); then
        ok "$c: v4l2src $(sed -n 's/^caps: //p' "$t") -> bloom -> fbdevsink ${xres}x$yres, screen = bloom_sim on the recorded frame $n of $n (vivid's pattern moving: not frame $((n - 1))): $res"
    else
        bad "$c: $res"
    fi
}
gst_checks() {
    if [ -n "$gst_bad" ]; then
        for c in $gst_cases; do bad "$c: $gst_bad"; done
    elif [ -n "$gst_off" ]; then
        for c in $gst_cases; do
            if [ "$gst_need" = 1 ]; then need "$c" "$gst_off"; else skip "$c" "$gst_off"; fi
        done
    else
        gst_check gst-16 rgb565 2 $P
        gst_check gst-32 xrgb8888 4 $P
    fi
}
