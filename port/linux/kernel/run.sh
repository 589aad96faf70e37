#!/bin/sh
# make test-linux: bloom_cam against the kernel's own vivid (V4L2 capture,
# 16 bpp framebuffer) and vfb (32 bpp framebuffer) drivers, in
# qemu-system-x86_64 (TCG) with a pinned Debian kernel. The kernel package
# is downloaded (apt-get download) and unpacked into $B/linux/kernel once.
# The framebuffer contents are compared with bloom_sim run on the frames the
# guest recorded; the fault cases must end with their messages.
# Prints "skipped: ..." (exit 0) when qemu, a static busybox or the kernel
# package is not available. Env: LINUX_TEST_KVER, LINUX_TEST_TIMEOUT.
B=${B:-build}
KVER=${LINUX_TEST_KVER:-6.1.0-56-amd64}
TIMEOUT=${LINUX_TEST_TIMEOUT:-170}
SIZE=320x240
FRAMES=3
top=$(pwd)
cache=$top/$B/linux/kernel
work=$top/$B/linux/guest
here=$top/port/linux/kernel

command -v qemu-system-x86_64 >/dev/null 2>&1 ||
    { echo "skipped: qemu-system-x86_64 not installed (Debian qemu-system-x86)"; exit 0; }
bb=$(command -v busybox 2>/dev/null)
if [ -z "$bb" ] || readelf -l "$bb" 2>/dev/null | grep -q INTERP; then
    echo "skipped: no static busybox (Debian busybox-static)"; exit 0
fi
kroot=$cache/$KVER
if [ ! -f "$kroot/boot/vmlinuz-$KVER" ]; then
    mkdir -p "$cache/deb" && rm -rf "$kroot.tmp" && mkdir -p "$kroot.tmp"
    (cd "$cache/deb" && { ls linux-image-"$KVER"*.deb >/dev/null 2>&1 ||
        apt-get download "linux-image-$KVER-unsigned" >/dev/null 2>&1 ||
        apt-get download "linux-image-$KVER" >/dev/null 2>&1; }) &&
        dpkg -x "$(ls "$cache/deb"/linux-image-"$KVER"*.deb | head -n 1)" "$kroot.tmp" &&
        mv "$kroot.tmp" "$kroot" ||
        { rm -rf "$kroot.tmp"; echo "skipped: kernel package linux-image-$KVER not available"; exit 0; }
fi
moddir=$kroot/lib/modules/$KVER/kernel
for m in vivid vfb; do
    [ -n "$(find "$moddir" -name "$m.ko*" | head -n 1)" ] ||
        { echo "skipped: $KVER has no $m module"; exit 0; }
done

# ---- initramfs -------------------------------------------------------------
rm -rf "$work" && mkdir -p "$work/root/bin" "$work/root/modules" "$work/root/proc" \
    "$work/root/sys" "$work/root/dev" "$work/root/out" "$work/res" || exit 1
modfile() { find "$moddir" -name "$(echo "$1" | sed 's/[-_]/[-_]/g').ko*" | head -n 1; }
order=""
add_mod() { # dependencies first, each once
    local n f d
    n=$(echo "$1" | tr - _)
    case " $order " in *" $n "*) return 0;; esac
    f=$(modfile "$1"); [ -n "$f" ] || { echo "test-linux: module $1 not found"; return 1; }
    for d in $(tr '\0' '\n' < "$f" | sed -n 's/^depends=//p' | tr , ' '); do add_mod "$d" || return 1; done
    case " $order " in *" $n "*) return 0;; esac
    case "$f" in *.ko) cp "$f" "$work/root/modules/$n.ko";;
                 *.ko.xz) xz -dc "$f" > "$work/root/modules/$n.ko";;
                 *.ko.zst) zstd -qdc "$f" > "$work/root/modules/$n.ko";; esac
    order="$order $n"
}
for m in virtio_pci virtio_blk vivid vfb; do add_mod $m || exit 1; done
echo "$order" | tr ' ' '\n' | grep . > "$work/root/modules.order"
cat > "$work/root/modules.args" <<ARGS
vivid n_devs=1 node_types=0x10101 num_inputs=1 input_types=0x00
vfb vfb_enable=1 mode_option=640x480-32 videomemorysize=2457600
ARGS
cp "$bb" "$work/root/bin/busybox"
cp "$B/linux/bloom_cam.static" "$work/root/bloom_cam"
cc -std=c11 -O2 -static -D_POSIX_C_SOURCE=200809L "$here/vctl.c" -o "$work/root/vctl" || exit 1
cc -std=c11 -O2 -D_POSIX_C_SOURCE=200809L "$here/fbcmp.c" -o "$work/fbcmp" || exit 1
{ echo '#!/bin/busybox sh'; echo "SIZE=$SIZE FRAMES=$FRAMES FB16_ID='vioverlay fb' FB32_ID='Virtual FB'";
  sed 1d "$here/init.sh"; } > "$work/root/init"
chmod +x "$work/root/init" "$work/root/bin/busybox"
(cd "$work/root" && find . | "$bb" cpio -o -H newc 2>/dev/null) > "$work/initrd.cpio" || exit 1
dd if=/dev/zero of="$work/disk.img" bs=1M count=64 2>/dev/null

# ---- boot ------------------------------------------------------------------
timeout "$TIMEOUT" qemu-system-x86_64 -accel tcg -cpu max -m 512M -smp 1 -nographic \
    -no-reboot -kernel "$kroot/boot/vmlinuz-$KVER" -initrd "$work/initrd.cpio" \
    -append "console=ttyS0 quiet loglevel=3 panic=-1 rdinit=/init" \
    -device isa-debug-exit,iobase=0xf4,iosize=0x04 \
    -drive file="$work/disk.img",format=raw,if=virtio > "$work/console.log" 2>&1
st=$?
(cd "$work/res" && tar xf ../disk.img 2>/dev/null)
sed 's/^/    /' "$work/res/guest.log" 2>/dev/null
if [ "$st" -ne 1 ]; then
    echo "test-linux: the guest did not finish (qemu status $st; 1 = finished, 3 = failed, 124 = timeout)"
    tail -n 30 "$work/console.log"
    echo "0 passed, 1 failed"; exit 1
fi

# ---- checks ----------------------------------------------------------------
pass=0; fail=0
ok() { pass=$((pass + 1)); echo "  ok   $*"; }
bad() { fail=$((fail + 1)); echo "  FAIL $*"; }
r=$work/res
frame_check() { # case fbformat sim-options...
    c=$1; ff=$2; shift 2
    t=$r/$c.txt
    grep -q '^exit 0$' "$t" 2>/dev/null || { bad "$c: bloom_cam failed"; sed 's/^/       /' "$t"; return; }
    geo=$(sed -n 's/.*): \([0-9]*x[0-9]*\) \([a-z0-9]*\), bytesperline \([0-9]*\),.*/\1 \2 \3/p' "$t" | head -n 1)
    set -- $geo "$@"; wh=$1; fmt=$2; bpl=$3; shift 3
    w=${wh%x*}
    rm -rf "$work/sim" && mkdir -p "$work/sim"
    if ! "$B/bloom_sim" "$r/$c.raw" --raw-size "$wh" --raw-format "$fmt" --raw-stride "$bpl" \
        --in-format rgb888 --out-format "$ff" -q -o "$work/sim/f%04d.ppm" "$@" > "$work/sim.log" 2>&1; then
        bad "$c: bloom_sim failed"; sed 's/^/       /' "$work/sim.log"; return
    fi
    last=$(ls "$work/sim"/f*.ppm | tail -n 1)
    n=$(ls "$work/sim"/f*.ppm | wc -l)
    if res=$("$work/fbcmp" "$r/$c.fb" "$ff" "$w" "$last" 2>&1); then
        ok "$c: $wh $fmt, framebuffer = bloom_sim on the recorded frame $n of $n: $res"
    else
        bad "$c: $res"
    fi
}
P="--threshold 0.6 --intensity 1.5"
frame_check yuyv-16 rgb565 $P
frame_check yuyv-32 xrgb8888 $P
frame_check rgb24-16 rgb565 $P
frame_check rgb24-32 xrgb8888 $P
frame_check grey-16 rgb565 $P
frame_check grey-32 xrgb8888 $P
frame_check bloomonly-16 rgb565 $P --view bloom
frame_check off-32 xrgb8888 --threshold 256 --knee 0 --intensity 0
fault_check() { # case exit-status text
    if grep -q "^exit $2\$" "$r/$1.txt" 2>/dev/null && grep -qF -- "$3" "$r/$1.txt"; then
        ok "$1: '$3', exit $2"
    else
        bad "$1: wanted '$3' and exit $2"; sed 's/^/       /' "$r/$1.txt" 2>/dev/null
    fi
}
fault_check sigterm 0 "bloom_cam: stopping on SIGTERM"
fault_check sigterm 0 "/sys pan after: 0,0"
fault_check stall 1 "bloom_cam: poll: no frame from the device within 1500 ms"
fault_check bufferror 1 "flagged V4L2_BUF_FLAG_ERROR"
fault_check disconnect 1 ": No such device"  # VIDIOC_DQBUF or VIDIOC_QBUF, whichever sees it
fault_check disconnect 1 "/sys pan after: 0,0"
grep -h "total:" "$r/speed.txt" | sed 's/^bloom_cam: total:/  emulated (TCG) 640x480 YUYV -> 32 bpp:/'
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
