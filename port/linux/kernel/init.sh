#!/bin/busybox sh
# /init of the test initramfs (make test-linux): loads vivid, vfb and bochs, runs
# bloom_cam against them, writes a tar of the results to /dev/vda and
# reports through isa-debug-exit (port 0xf4: 0 = every case ran).
/bin/busybox --install -s /bin
export PATH=/bin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
mkdir -p /out
log() { echo "guest: $*"; echo "$*" >> /out/guest.log; }
finish() { # status byte to isa-debug-exit, after the results are on the disk
    dmesg > /out/dmesg.txt; [ "$1" = 0 ] || dmesg | tail -n 25; ls /dev/vd* /sys/class/video4linux 2>&1
    (cd /out && tar cf /dev/vda .) || log "tar to /dev/vda failed"
    sync
    printf "\\$(printf %03o "$1")" | dd of=/dev/port bs=1 seek=244 count=1 2>/dev/null
    poweroff -f
}
for m in $(cat /modules.order); do
    insmod /modules/$m.ko $(grep "^$m " /modules.args | cut -d' ' -f2-) 2>>/out/guest.log ||
        { log "insmod $m failed"; finish 1; }
done
for v in /sys/class/vtconsole/vtcon*/bind; do echo 0 > "$v" 2>/dev/null; done
# devices by name, not by number
fb_by_id() { for f in /sys/class/graphics/fb[0-9]*; do
    [ "$(cat "$f/name")" = "$1" ] && { echo "/dev/${f##*/}"; return; }; done; }
vid=""; vidmp=""  # vivid's instances: 0 single-planar, 1 multi-planar (multiplanar=1,2)
for v in /sys/class/video4linux/video*; do
    case "$(cat "$v/name")" in *000-vid-cap*) vid="/dev/${v##*/}";; *001-vid-cap*) vidmp="/dev/${v##*/}";; esac
done
fb16=$(fb_by_id "$FB16_ID"); fb32=$(fb_by_id "$FB32_ID"); fbx=$(fb_by_id "$FBX_ID")
log "capture $vid, multi-planar $vidmp, 16 bpp $fb16 ($FB16_ID), 32 bpp $fb32 ($FB32_ID), XBGR $fbx ($FBX_ID)"
cpus=$(grep -c '^processor' /proc/cpuinfo)
log "cpus: $cpus"
for f in /sys/class/graphics/fb[0-9]*; do log "${f##*/}: $(cat $f/name) $(cat $f/virtual_size) $(cat $f/bits_per_pixel) bpp"; done
[ -n "$vid" ] && [ -n "$vidmp" ] && [ -n "$fb16" ] && [ -n "$fb32" ] && [ -n "$fbx" ] || { log "devices missing"; finish 1; }
/vctl "$vid" "OSD Text Mode" 2 2>>/out/guest.log
/vctl "$vidmp" "OSD Text Mode" 2 2>>/out/guest.log

# soak: SOAK_FRAMES frames (make soak-cam: 20 000; make test: a short run)
# with faults injected at pseudo-random intervals of 1..4 s (seed SOAK_SEED),
# in turn a flagged buffer, a disconnect and a 2 s stall, two rounds at
# least; the process's RSS, open descriptors and mappings after its first
# second of frames, 6 s after the first round of faults (every fault path
# run once: its code and buffers touched) and at the end, 6 s after the
# last fault (then SIGTERM)
snap() { # pid: "rss KB anon KB fds N maps N" (VmRSS and RssAnon of /proc/PID/status)
    echo "rss $(awk '/^VmRSS:/ { print $2 }' /proc/$1/status) anon $(awk '/^RssAnon:/ { print $2 }' /proc/$1/status)" \
        "fds $(ls /proc/$1/fd | wc -l) maps $(wc -l < /proc/$1/maps)"
}
soak_frames() { awk '/: last second: / { n += $4 } END { print n + 0 }' /out/soak.txt; }
alive() { [ -e /proc/$1/stat ] && read -r _ _ st _ < /proc/$1/stat && [ "$st" != Z ]; }  # (a zombie is not)
soak() {
    /bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --fps 30 --timeout 1000 --stats > /out/soak.txt 2>&1 &
    pid=$!
    wait_for '[ "$(soak_frames)" -gt 0 ] || ! alive $pid' || log "soak: no frames within 60 s"
    snap $pid > /out/soak-start.txt
    # at 5 frames a second at least (else it ends, and the check says so)
    seed=$SOAK_SEED; k=0; nf=0; nd=0; ns=0; t0=$(date +%s); tmax=$((SOAK_FRAMES / 5 + 120))
    while { [ "$(soak_frames)" -lt "$SOAK_FRAMES" ] || [ $k -lt 6 ]; } && alive $pid &&
        [ $(($(date +%s) - t0)) -lt $tmax ]; do
        seed=$(((seed * 1103515245 + 12345) % 2147483648))
        sleep $((1 + seed / 65536 % 4))
        case $((k % 3)) in
        0) /vctl "$vid" "Inject V4L2_BUF_FLAG_ERROR" 1 2>>/out/soak-faults.txt && nf=$((nf + 1));;
        1) /vctl "$vid" "Disconnect" 1 2>>/out/soak-faults.txt && nd=$((nd + 1));;
        2) /vctl "$vid" "Percentage of Dropped Buffers" 100 2>>/out/soak-faults.txt && ns=$((ns + 1))
           sleep 2; /vctl "$vid" "Percentage of Dropped Buffers" 0 2>>/out/soak-faults.txt;;
        esac
        k=$((k + 1))
        if [ $k = 3 ]; then sleep 6; alive $pid && snap $pid > /out/soak-warm.txt; fi
    done
    sleep 6
    alive $pid && snap $pid > /out/soak-end.txt
    kill -TERM $pid; wait $pid; echo "exit $?" >> /out/soak.txt
    echo "injected: $nf flagged, $nd disconnects, $ns stalls in $(($(date +%s) - t0)) s ($(soak_frames) frames counted by the second)" >> /out/soak.txt
    log "soak: $(tail -n 2 /out/soak.txt | tr '\n' ' ')start $(cat /out/soak-start.txt), after a round $(cat /out/soak-warm.txt 2>/dev/null), end $(cat /out/soak-end.txt 2>/dev/null)"
}
wait_for() { # condition... : true once it holds, false after 60 s
    n=0; until eval "$1"; do n=$((n + 1)); [ $n -ge 600 ] && return 1; sleep 0.1; done; }
if [ "$SOAK_ONLY" = 1 ]; then
    soak; log "done"; finish 0
fi

# name format fb extra-options...: capture -> bloom -> framebuffer, row by
# row (--threads 1) unless the options say otherwise
run() {
    name=$1; fmt=$2; fb=$3; shift 3
    pan=/sys/class/graphics/${fb#/dev/}/pan
    /bloom_cam --device "$vid" --fb "$fb" --format "$fmt" --size "$SIZE" --frames "$FRAMES" \
        --threshold 0.6 --intensity 1.5 --record "/out/$name.raw" --dump-fb "/out/$name.fb" \
        --stats --threads 1 "$@" > "/out/$name.txt" 2>&1 &
    pid=$!; seen=""
    # the pan offsets seen while it runs (shell builtins only: no fork per look)
    while [ -e /proc/$pid/stat ] && read -r _ _ st _ < /proc/$pid/stat && [ "$st" != Z ]; do
        read -r p < "$pan"; case " $seen " in *" $p "*) ;; *) seen="$seen $p";; esac
    done 2>/dev/null
    wait $pid; echo "exit $?" >> "/out/$name.txt"
    log "$name: $(tail -n 1 /out/$name.txt), pan seen:$seen"
    echo "/sys pan during:$seen" >> "/out/$name.txt"
    echo "/sys pan after: $(cat "$pan")" >> "/out/$name.txt"
}
run yuyv-16 yuyv "$fb16"
run rgb24-16 rgb24 "$fb16"
run grey-16 grey "$fb16"
run bloomonly-16 yuyv "$fb16" --mode bloom-only
# vfb's 32 bpp layout is XBGR8888: refused by name
run xbgr yuyv "$fbx"
run yuyv-32 yuyv "$fb32"
run rgb24-32 rgb24 "$fb32"
run grey-32 grey "$fb32"
run off-32 rgb24 "$fb32" --mode off
# a preset with its depth plane; the plane of the wrong size is refused
if [ "$ATT" = 1 ]; then
    run att-16 yuyv "$fb16" --preset attenuation --aux /depth.pgm
    run att-size yuyv "$fb16" --preset attenuation --aux /depth240.pgm
fi
for p in $PRESETS; do run "preset-$p" yuyv "$fb16" --preset "$p"; done
# --threads: the cases above on the pool of strip engines (cam_mt.c), both
# screens, every capture format and mode, the aux plane, every preset
run yuyv-16-t2 yuyv "$fb16" --threads 2
run rgb24-32-t3 rgb24 "$fb32" --threads 3
run grey-32-t2 grey "$fb32" --threads 2
run bloomonly-16-t3 yuyv "$fb16" --mode bloom-only --threads 3
run off-32-t2 rgb24 "$fb32" --mode off --threads 2
[ "$ATT" = 1 ] && run att-16-t3 yuyv "$fb16" --preset attenuation --aux /depth.pgm --threads 3
for p in $PRESETS; do run "preset-$p-t2" yuyv "$fb16" --preset "$p" --threads 2; done
# a capture larger than the screen (1280x720 on 720x576): cropped around the
# centre, through the scratch row (row by row) or the output frame (threads)
run crop-16 yuyv "$fb16" --size 1280x720
run crop-16-t2 yuyv "$fb16" --size 1280x720 --threads 2
# the other capture formats (cam_fmt.c), single-planar and through the
# multi-planar API (vivid's second instance: one plane, or two for NV..M);
# BT.709 and full range set with vivid's colorimetry controls; --format
# auto with a size and a frame rate vivid's webcam input offers
run nv12-16 nv12 "$fb16"
run nv21-32 nv21 "$fb32"
run nv16-32 nv16 "$fb32"
run nv61-16 nv61 "$fb16"
run uyvy-16 uyvy "$fb16"
run yvyu-32 yvyu "$fb32"
run rgb565-16 rgb565 "$fb16"
run nv12-16-t2 nv12 "$fb16" --threads 2
run auto-32 auto "$fb32" --size 320x180 --fps 30
/vctl "$vid" "Y'CbCr Encoding" 2 2>>/out/guest.log  # V4L2_YCBCR_ENC_709
/vctl "$vid" "Quantization" 1 2>>/out/guest.log     # V4L2_QUANTIZATION_FULL_RANGE
run nv12-709f-16 nv12 "$fb16"
/vctl "$vid" "Quantization" 0 2>>/out/guest.log
run uyvy-709-32 uyvy "$fb32"
/vctl "$vid" "Y'CbCr Encoding" 0 2>>/out/guest.log
run mp-yuyv-16 yuyv "$fb16" --device "$vidmp"
run mp-nv12-32 nv12 "$fb32" --device "$vidmp"
run mp-nv12m-16 nv12m "$fb16" --device "$vidmp"
run mp-nv12m-16-t2 nv12m "$fb16" --device "$vidmp" --threads 2
run mp-nv16m-32 nv16m "$fb32" --device "$vidmp"
run mp-nv61m-16 nv61m "$fb16" --device "$vidmp"
run mp-auto-16 auto "$fb16" --device "$vidmp" --size 320x180 --fps 30
# the GStreamer element (gst_cases.sh): vivid in the screen's own format ->
# tee -> the frames recorded, and bloom -> fbdevsink on the zeroed screen,
# read back after (fbgrab: "fb: xres yres xoffset yoffset line_length bpp");
# vivid's screen (RGB555 until asked) set to RGB565 for it, and put back
gst() { # name format fb
    name=$1; caps=video/x-raw,format=$2,width=${GSIZE%x*},height=${GSIZE#*x}; fb=$3
    echo "caps: $caps" > "/out/$name.txt"
    [ "$2" != RGB16 ] || echo "layout: $(/fbgrab "$fb" --rgb565 /tmp/$name.var 2>&1)" >> "/out/$name.txt"
    dd if=/dev/zero of="$fb" bs=65536 2>/dev/null
    env LD_LIBRARY_PATH=/usr/lib/gst GST_PLUGIN_SYSTEM_PATH_1_0=/usr/lib/gst-plugins \
        GST_PLUGIN_SYSTEM_PATH=/usr/lib/gst-plugins GST_PLUGIN_PATH_1_0= GST_PLUGIN_PATH= \
        GST_REGISTRY_1_0=/tmp/gst-registry.bin GST_REGISTRY=/tmp/gst-registry.bin GST_REGISTRY_FORK=no \
        GST_DEBUG='*:2' GST_DEBUG_NO_COLOR=1 \
        /usr/bin/gst-launch-1.0 v4l2src device="$vid" num-buffers="$FRAMES" ! "$caps" ! tee name=t \
        t. ! queue ! filesink location="/out/$name.raw" \
        t. ! queue ! bloom in-place=false threshold=0.6 intensity=1.5 ! \
        fbdevsink device="$fb" sync=false qos=false >> "/out/$name.txt" 2>&1
    echo "exit $?" >> "/out/$name.txt"
    echo "fb: $(/fbgrab "$fb" "/out/$name.fb" 2>&1)" >> "/out/$name.txt"
    [ "$2" != RGB16 ] || echo "restored: $(/fbgrab "$fb" --restore /tmp/$name.var 2>&1)" >> "/out/$name.txt"
    log "$name: $(grep '^exit' "/out/$name.txt"), $(tail -n 1 "/out/$name.txt")"
}
if [ "$GST" = 1 ]; then
    # a moving pattern, so the screen can only match the last frame recorded
    /vctl "$vid" "Horizontal Movement" 0 2>>/out/guest.log
    gst gst-16 RGB16 "$fb16"
    gst gst-32 BGRx "$fb32"
    /vctl "$vid" "Horizontal Movement" 3 2>>/out/guest.log
fi
# speed under emulation, 640x480 YUYV to the 32 bpp screen: without
# --threads (the guest's CPUs), then row by row
echo "cpus: $cpus" > /out/speed.txt
/bloom_cam --device "$vid" --fb "$fb32" --size 640x480 --format yuyv --frames 16 --stats >> /out/speed.txt 2>&1
echo "exit $?" >> /out/speed.txt
/bloom_cam --device "$vid" --fb "$fb32" --size 640x480 --format yuyv --frames 16 --stats -q --threads 1 \
    > /out/speed-t1.txt 2>&1
echo "exit $?" >> /out/speed-t1.txt

# GPIO through gpio-sim (configfs), when run.sh could build it: a bank of two
# lines, "frame" (bloom_cam's output) and "button" (an input whose pull is
# changed from sysfs). Every value the kernel sets on a line is traced
# (tracefs gpio_value), so the toggles are counted exactly, not sampled.
if [ "$GPIO" = 1 ]; then
    mount -t configfs none /sys/kernel/config
    mount -t tracefs none /sys/kernel/tracing
    T=/sys/kernel/tracing
    g=/sys/kernel/config/gpio-sim/cam
    { mkdir $g $g/bank0 $g/bank0/line0 $g/bank0/line1 && echo 2 > $g/bank0/num_lines &&
      echo frame > $g/bank0/line0/name && echo button > $g/bank0/line1/name &&
      echo 1 > $g/live; } 2>>/out/guest.log || log "gpio-sim setup failed"
    chip=$(cat $g/bank0/chip_name); sim=/sys/devices/platform/$(cat $g/dev_name)/$chip
    base=$(cat /sys/devices/platform/$(cat $g/dev_name)/gpio/gpiochip*/base | head -n 1)
    log "gpio-sim: $chip at $sim, base $base, lines $(cat $sim/sim_gpio0/value)$(cat $sim/sim_gpio1/value)"
    { echo "chip $chip base $base"; ls -l /sys/class/gpio/ $sim/; } > /out/gpio.txt 2>&1
    echo 1 > $T/events/gpio/gpio_value/enable; echo > $T/trace
    # frame line: stopped (SIGSTOP, waited for) at moments during the run, the
    # sysfs value must equal the last value traced for the line
    /bloom_cam --device "$vid" --fb "$fb16" --format yuyv --size "$SIZE" --frames "$GFRAMES" \
        --gpio-frame "$chip:frame" --stats > /out/gpio-frame.txt 2>&1 &
    pid=$!
    : > /out/gpio-samples.txt
    while kill -STOP $pid 2>/dev/null; do
        st=R
        while [ "$st" != T ] && [ "$st" != Z ] && [ -e /proc/$pid/stat ]; do
            read -r _ _ st _ < /proc/$pid/stat; done
        [ "$st" = T ] || break
        echo "$(cat $sim/sim_gpio0/value) $(grep -o "gpio_value: $base set [01]" $T/trace | tail -n 1 |
            sed 's/.* //')" >> /out/gpio-samples.txt
        kill -CONT $pid
        sleep 0.2
    done
    wait $pid; echo "exit $?" >> /out/gpio-frame.txt
    log "gpio-frame: $(tail -n 1 /out/gpio-frame.txt), $(wc -l < /out/gpio-samples.txt) samples"
    grep -o "gpio_value: $base set [01]" $T/trace | sed 's/.* //' | tr -d '\n' > /out/gpio-trace.txt
    cp $T/trace /out/gpio-trace-all.txt
    echo 0 > $T/events/gpio/gpio_value/enable
    # button: once bloom_cam holds the line with its edge interrupt (it has
    # recorded a frame, so the request returned) and its pull-up reads 1, a
    # pull-down from sysfs is a press: bloom -> off; stopped after a frame
    # recorded after the switch was announced, so the last frame shown is "off"
    button() { # name options...
        b=$1; shift
        /bloom_cam --device "$vid" --fb "$fb16" --format yuyv --size "$SIZE" \
            --threshold 0.6 --intensity 1.5 --gpio-button "$chip:button" \
            --record /out/$b.raw --dump-fb /out/$b.fb "$@" > /out/$b.txt 2>&1 &
        pid=$!
        if wait_for '[ -s /out/$b.raw ] && [ "$(cat $sim/sim_gpio1/value)" = 1 ]'; then
            echo pull-down > $sim/sim_gpio1/pull
            if wait_for 'grep -q "mode off" /out/$b.txt'; then
                s0=$(wc -c < /out/$b.raw)
                wait_for '[ "$(wc -c < /out/$b.raw)" -gt "$s0" ]' || log "$b: no frame after the switch"
            else
                log "$b: no mode change within 60 s"
            fi
        else
            log "$b: no frame, or the line never read 1 (pull-up), within 60 s"
        fi
        kill -TERM $pid; wait $pid; echo "exit $?" >> /out/$b.txt
        log "$b: $(tail -n 1 /out/$b.txt)"
    }
    button button --threads 1
    button button-t2 --threads 2
fi

# DRM/KMS (drm_init.sh): bochs-drm and cirrus, the screen read back while running
[ "$DRM" != 1 ] || . /drm_init.sh
# faults: a stop signal ends the run cleanly (exit 0, the screen restored);
# a bad frame is skipped and counted; a lost device is opened again
# (--reconnect) and the run goes on, or ends with exit 3 when it does not
# come back; the statuses are port/linux/README.md's
fb16pan=/sys/class/graphics/${fb16#/dev/}/pan
log "vt before the fault cases: $(/vtmode /dev/tty0 2>&1)"
stopcase() { # name signal: the signal while streaming
    /bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" > /out/$1.txt 2>&1 &
    pid=$!; sleep 2; echo "vt during: $(/vtmode /dev/tty0 2>&1)" > /out/$1.vt; kill -$2 $pid; wait $pid
    echo "exit $?" >> /out/$1.txt; cat /out/$1.vt >> /out/$1.txt
    echo "/sys pan after: $(cat $fb16pan)" >> /out/$1.txt
    echo "vt after: $(/vtmode /dev/tty0 2>&1)" >> /out/$1.txt
}
stopcase sigterm TERM
stopcase sighup HUP
stopcase sigquit QUIT
# SIGPIPE: --record into a pipe whose reader goes away
mkfifo /tmp/rec.fifo
head -c 100000 /tmp/rec.fifo > /dev/null &
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --record /tmp/rec.fifo > /out/sigpipe.txt 2>&1
echo "exit $?" >> /out/sigpipe.txt; echo "/sys pan after: $(cat $fb16pan)" >> /out/sigpipe.txt
echo "vt after: $(/vtmode /dev/tty0 2>&1)" >> /out/sigpipe.txt
rm -f /tmp/rec.fifo
# a stalled stream that does not recover: every buffer dropped -> timeouts,
# reopened until --reconnect gives up
/vctl "$vid" "Percentage of Dropped Buffers" 100 2>>/out/guest.log
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --timeout 1000 --reconnect 4 > /out/stall.txt 2>&1
echo "exit $?" >> /out/stall.txt
# the same without --reconnect: today's behaviour, the first timeout ends it
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --timeout 1000 --reconnect off > /out/stall-off.txt 2>&1
echo "exit $?" >> /out/stall-off.txt
# a stall that ends: frames again after 3 s, the run goes on to its frames
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --timeout 1000 --frames 60 > /out/stall-recover.txt 2>&1 &
pid=$!; sleep 3; /vctl "$vid" "Percentage of Dropped Buffers" 0 2>>/out/guest.log
wait $pid; echo "exit $?" >> /out/stall-recover.txt
# a buffer flagged V4L2_BUF_FLAG_ERROR: skipped, counted, the run goes on
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 90 > /out/bufferror.txt 2>&1 &
pid=$!; sleep 2; /vctl "$vid" "Inject V4L2_BUF_FLAG_ERROR" 1 2>>/out/guest.log
wait $pid; echo "exit $?" >> /out/bufferror.txt
# the device disappears and comes back (vivid, once every handle is closed)
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 90 --dump-fb /out/disconnect.fb > /out/disconnect.txt 2>&1 &
pid=$!; sleep 2; /vctl "$vid" "Disconnect" 1 2>>/out/guest.log
wait $pid; echo "exit $?" >> /out/disconnect.txt
echo "/sys pan after: $(cat $fb16pan)" >> /out/disconnect.txt
# ... and without --reconnect: the run ends, exit 3
sleep 1
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 90 --reconnect off > /out/disconnect-off.txt 2>&1 &
pid=$!; sleep 2; /vctl "$vid" "Disconnect" 1 2>>/out/guest.log
wait $pid; echo "exit $?" >> /out/disconnect-off.txt
echo "/sys pan after: $(cat $fb16pan)" >> /out/disconnect-off.txt
echo "vt after: $(/vtmode /dev/tty0 2>&1)" >> /out/disconnect-off.txt
sleep 1
# a fatal streaming error (vb2_queue_error): the queue is dead, reopened
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 90 > /out/fatal.txt 2>&1 &
pid=$!; sleep 2; /vctl "$vid" "Inject Fatal Streaming Error" 1 2>>/out/guest.log
wait $pid; echo "exit $?" >> /out/fatal.txt
# one VIDIOC_QBUF refused: that buffer is gone from the queue, the run goes on
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 90 > /out/qbuferror.txt 2>&1 &
pid=$!; sleep 2; /vctl "$vid" "Inject VIDIOC_QBUF Error" 1 2>>/out/guest.log
wait $pid; echo "exit $?" >> /out/qbuferror.txt
# VIDIOC_REQBUFS and VIDIOC_STREAMON refused at the start: the device fails, exit 3
/vctl "$vid" "Inject VIDIOC_REQBUFS Error" 1 2>>/out/guest.log
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 10 > /out/reqbufs.txt 2>&1
echo "exit $?" >> /out/reqbufs.txt
/vctl "$vid" "Inject VIDIOC_STREAMON Error" 1 2>>/out/guest.log
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 10 > /out/streamon.txt 2>&1
echo "exit $?" >> /out/streamon.txt
# the sequence number wraps past 2^32: no frames counted dropped for it
/vctl "$vid" "Wrap Sequence Number" 1 2>>/out/guest.log
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 200 --latest off > /out/seqwrap.txt 2>&1
echo "exit $?" >> /out/seqwrap.txt
/vctl "$vid" "Wrap Sequence Number" 0 2>>/out/guest.log
# MJPEG from v4l2loopback (mjpeg_cases.sh): loopfeed writes JPEG frames, one
# in ten corrupt and one in ten truncated; bloom_cam skips and counts those
# (mjpeg); and a camera that comes back in another size (mjpeg-resize):
# after 60 frames loopfeed leaves and returns as 640x480, bloom_cam times
# out, reconnects and makes its engines again for the new size
mjpeg() { # name frames loopfeed-extra...
    name=$1; nfr=$2; shift 2
    rm -f /out/loopfeed.txt
    /loopfeed "$loop" 320 240 /good.jpg /corrupt.jpg /trunc.jpg "$@" > /out/loopfeed.txt 2>&1 &
    fpid=$!
    wait_for '[ -s /out/loopfeed.txt ]' || log "loopfeed: nothing written within 60 s"
    /bloom_cam --device "$loop" --fb "$fb16" --format mjpeg --size 320x240 --frames "$nfr" --threshold 0.6 \
        --intensity 1.5 --timeout 1000 --dump-fb "/out/$name.fb" --stats --threads 1 > "/out/$name.txt" 2>&1
    echo "exit $?" >> "/out/$name.txt"
    kill $fpid; wait $fpid; sed 's/^/loopfeed: /' /out/loopfeed.txt >> "/out/$name.txt"
    log "$name: $(grep '^exit' "/out/$name.txt")"
}
if [ "$MJPEG" = 1 ]; then
    loop=""
    for v in /sys/class/video4linux/video*; do [ "$(cat "$v/name")" = loopcam ] && loop="/dev/${v##*/}"; done
    log "v4l2loopback: ${loop:-not found}"
    mjpeg mjpeg 40
    sleep 1
    mjpeg mjpeg-resize 100 60 640 480 /good2.jpg
fi
soak
log "done"
finish 0
