# The DRM cases of the guest (make test-linux), sourced by init.sh when
# bloom_cam was built with libdrm (DRM=1): bloom_cam --display drm on
# bochs-drm (qemu's std VGA: XRGB8888 only) and cirrus (qemu's cirrus-vga,
# the one with RGB565). While it runs it is stopped (SIGSTOP) three times;
# each time the framebuffer on the CRTC is read back (drmgrab grab) with the
# number of frames recorded so far, for run.sh (drm_cases.sh) to compare
# with bloom_sim's frames of the recording: a frame shown half-drawn would
# match none. The CRTC is held beforehand by drmgrab (its own buffer and a
# 640x480 mode, the master dropped) and must be that again after the run;
# those runs leave the VT alone (--vt off): the VT put back in text mode
# gives the CRTC back to the console (the fbdev emulation's framebuffer and
# mode), whatever was on it before, as drm-32 (the VT in graphics mode
# while drawing) shows.
drm_by_driver() { for d in /sys/class/drm/card[0-9]*; do
    [ "$(basename "$(readlink "$d/device/driver")")" = "$1" ] && { echo "/dev/dri/${d##*/}"; return; }; done; }
bochs=$(drm_by_driver bochs-drm); cirrus=$(drm_by_driver cirrus)
log "drm: bochs-drm $bochs, cirrus $cirrus; $(ls /dev/dri 2>&1 | tr '\n' ' ')at $(cut -d' ' -f1 /proc/uptime) s"
/vctl "$vid" "Horizontal Movement" 0 2>>/out/guest.log  # each frame differs from the last
# name card hold(WxH|-) end(TERM|exit) bloom_cam-options...
drmcase() {
    dn=$1; card=$2; hs=$3; end=$4; shift 4  # not n: wait_for counts with it
    t=/out/$dn.txt; : > "$t"; hpid=""
    if [ "$hs" != - ]; then
        rm -f /tmp/hold.txt
        /drmgrab "$card" hold "$hs" > /tmp/hold.txt 2>> "$t" &
        hpid=$!
        wait_for '[ -s /tmp/hold.txt ] || ! kill -0 $hpid 2>/dev/null'
        echo "$(cat /tmp/hold.txt)" >> "$t"
    fi
    echo "before: $(/drmgrab "$card" crtc 2>&1 | head -n 1)" >> "$t"
    /bloom_cam --device "$vid" --display drm --drm-card "$card" --size "$SIZE" --threshold 0.6 \
        --intensity 1.5 --record "/out/$dn.raw" --stats "$@" >> "$t" 2>&1 &
    pid=$!
    wait_for 'grep -q ", bytesperline " "$t" || ! kill -0 $pid 2>/dev/null'
    fsz=$(sed -n 's/.*: [0-9]*x\([0-9]*\) [a-z0-9]*, bytesperline \([0-9]*\),.*/\1 \2/p' "$t" | head -n 1)
    case "$fsz" in [0-9]*" "[0-9]*) fsz=$(( ${fsz% *} * ${fsz#* } ));; *) fsz=0;; esac
    k=1
    [ "$fsz" -gt 0 ] || echo "no capture line: no grabs" >> "$t"
    for at in 3 10 17; do
        [ "$fsz" -gt 0 ] || break
        wait_for '[ "$(wc -c < /out/$dn.raw)" -ge $((at * fsz)) ] || ! kill -0 $pid 2>/dev/null'
        kill -STOP $pid 2>/dev/null || break
        st=R
        while [ "$st" != T ] && [ "$st" != Z ] && [ -e /proc/$pid/stat ]; do read -r _ _ st _ < /proc/$pid/stat; done
        sz=$(wc -c < "/out/$dn.raw")
        echo "grab $k: frames $((sz / fsz)) rest $((sz % fsz)) geo $(/drmgrab "$card" grab "/out/$dn.g$k" 2>&1)" >> "$t"
        kill -CONT $pid
        k=$((k + 1))
    done
    echo "vt during: $(/vtmode /dev/tty0 2>&1)" >> "$t"
    [ "$end" != TERM ] || kill -TERM $pid
    wait $pid; echo "exit $?" >> "$t"
    echo "after: $(/drmgrab "$card" crtc 2>&1 | head -n 1)" >> "$t"
    echo "vt after: $(/vtmode /dev/tty0 2>&1)" >> "$t"
    [ -z "$hpid" ] || { kill -TERM $hpid; wait $hpid; }
    log "$dn: $(grep '^exit' "$t"), $(grep -c '^grab' "$t") grabs, at $(cut -d' ' -f1 /proc/uptime) s"
}
if [ -n "$bochs" ]; then
    # the connector's preferred mode, row by row, the VT in graphics mode, stopped by SIGTERM
    drmcase drm-32 "$bochs" - TERM --threads 1
    # --drm-mode, on two threads, to the end of its frames
    drmcase drm-32-t2 "$bochs" 800x600 exit --threads 2 --drm-mode 640x480 --frames 90 --vt off
    # refused: a mode the connector lacks; RGB565, which bochs cannot scan out
    /bloom_cam --device "$vid" --display drm --drm-card "$bochs" --size "$SIZE" --frames 3 \
        --drm-mode 123x45 > /out/drm-nomode.txt 2>&1
    echo "exit $?" >> /out/drm-nomode.txt
    /bloom_cam --device "$vid" --display drm --drm-card "$bochs" --size "$SIZE" --frames 3 \
        --drm-format rgb565 > /out/drm-bochs565.txt 2>&1
    echo "exit $?" >> /out/drm-bochs565.txt
    # auto: no --fb, no --display: the first card with a connected connector
    echo "before: $(/drmgrab /dev/dri/card0 crtc 2>&1 | head -n 1)" > /out/drm-auto.txt
    /bloom_cam --device "$vid" --size "$SIZE" --frames 3 --threads 1 >> /out/drm-auto.txt 2>&1
    echo "exit $?" >> /out/drm-auto.txt
    echo "after: $(/drmgrab /dev/dri/card0 crtc 2>&1 | head -n 1)" >> /out/drm-auto.txt
fi
[ -z "$cirrus" ] || drmcase drm-16 "$cirrus" 640x480 TERM --threads 1 --drm-format rgb565 --drm-mode 640x480 --vt off
/vctl "$vid" "Horizontal Movement" 3 2>>/out/guest.log
log "drm: done at $(cut -d' ' -f1 /proc/uptime) s"
