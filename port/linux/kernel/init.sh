#!/bin/busybox sh
# /init of the test initramfs (make test-linux): loads vivid and vfb, runs
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
vid=""
for v in /sys/class/video4linux/video*; do
    case "$(cat "$v/name")" in *vid-cap*) vid="/dev/${v##*/}"; break;; esac
done
fb16=$(fb_by_id "$FB16_ID"); fb32=$(fb_by_id "$FB32_ID")
log "capture $vid, 16 bpp $fb16 ($FB16_ID), 32 bpp $fb32 ($FB32_ID)"
for f in /sys/class/graphics/fb[0-9]*; do log "${f##*/}: $(cat $f/name) $(cat $f/virtual_size) $(cat $f/bits_per_pixel) bpp"; done
[ -n "$vid" ] && [ -n "$fb16" ] && [ -n "$fb32" ] || { log "devices missing"; finish 1; }
/vctl "$vid" "OSD Text Mode" 2 2>>/out/guest.log

# name format fb extra-options...: capture -> bloom -> framebuffer
run() {
    name=$1; fmt=$2; fb=$3; shift 3
    /bloom_cam --device "$vid" --fb "$fb" --format "$fmt" --size "$SIZE" --frames "$FRAMES" \
        --threshold 0.6 --intensity 1.5 --record "/out/$name.raw" --dump-fb "/out/$name.fb" \
        --stats "$@" > "/out/$name.txt" 2>&1
    echo "exit $?" >> "/out/$name.txt"
    log "$name: $(tail -n 1 /out/$name.txt)"
    echo "/sys pan after: $(cat /sys/class/graphics/${fb#/dev/}/pan)" >> "/out/$name.txt"
}
run yuyv-16 yuyv "$fb16"
run rgb24-16 rgb24 "$fb16"
run grey-16 grey "$fb16"
run bloomonly-16 yuyv "$fb16" --mode bloom-only
# vfb's 32 bpp layout is XBGR8888 (refused); vivid's screen at 32 bpp instead
fbset -fb "$fb16" -depth 32 >> /out/guest.log 2>&1 || log "fbset -depth 32 failed"
log "$fb16 now $(cat /sys/class/graphics/${fb16#/dev/}/bits_per_pixel) bpp"
[ "$(cat /sys/class/graphics/${fb16#/dev/}/bits_per_pixel)" = 32 ] && fb32=$fb16
run yuyv-32 yuyv "$fb32"
run rgb24-32 rgb24 "$fb32"
run grey-32 grey "$fb32"
run off-32 rgb24 "$fb32" --mode off
# speed under emulation, 640x480 YUYV to the 32 bpp screen
/bloom_cam --device "$vid" --fb "$fb32" --size 640x480 --frames 8 --stats -q > /out/speed.txt 2>&1
echo "exit $?" >> /out/speed.txt

# faults: each must end with its message and a clean stop
# SIGTERM while streaming
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" > /out/sigterm.txt 2>&1 &
pid=$!; sleep 2; kill -TERM $pid; wait $pid; echo "exit $?" >> /out/sigterm.txt
echo "/sys pan after: $(cat /sys/class/graphics/${fb16#/dev/}/pan)" >> /out/sigterm.txt
# a stalled stream: every buffer dropped -> poll timeout
/vctl "$vid" "Percentage of Dropped Buffers" 100 2>>/out/guest.log
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --timeout 1500 > /out/stall.txt 2>&1
echo "exit $?" >> /out/stall.txt
/vctl "$vid" "Percentage of Dropped Buffers" 0 2>>/out/guest.log
# a buffer flagged V4L2_BUF_FLAG_ERROR
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 300 > /out/bufferror.txt 2>&1 &
pid=$!; sleep 2; /vctl "$vid" "Inject V4L2_BUF_FLAG_ERROR" 1 2>>/out/guest.log
wait $pid; echo "exit $?" >> /out/bufferror.txt
# the device disappears
/bloom_cam --device "$vid" --fb "$fb16" --size "$SIZE" --frames 300 > /out/disconnect.txt 2>&1 &
pid=$!; sleep 2; /vctl "$vid" "Disconnect" 1 2>>/out/guest.log
wait $pid; echo "exit $?" >> /out/disconnect.txt
echo "/sys pan after: $(cat /sys/class/graphics/${fb16#/dev/}/pan)" >> /out/disconnect.txt
log "done"
finish 0
