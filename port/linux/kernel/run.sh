#!/bin/sh
# make test-linux: bloom_cam against the kernel's own vivid (V4L2 capture,
# 16 bpp RGB565 framebuffer), bochs-drm (qemu's std VGA: 32 bpp XRGB8888
# through DRM's fbdev emulation, given two pages with drm_kms_helper's
# drm_fbdev_overalloc=200 so the FBIOPAN_DISPLAY double-buffering is used)
# and vfb (32 bpp XBGR8888, refused) drivers, in
# qemu-system-x86_64 (TCG) with a pinned Debian kernel. The kernel package
# is downloaded (apt-get download) and unpacked into $B/linux/kernel once.
# The framebuffer contents are compared with bloom_sim run on the frames the
# guest recorded; the fault cases must end with their messages. GPIO goes
# through gpio-sim (built here, see below): the frame line's values are
# traced in the guest, the button is pressed by changing its pull in sysfs.
# Prints "skipped: ..." (exit 0) when qemu, a static busybox or the kernel
# package is not available (qemu-system-x86 and busybox-static are first
# installed with apt-get when missing and run as root). Env: LINUX_TEST_KVER,
# LINUX_TEST_TIMEOUT, LINUX_TEST_QEMU, LINUX_TEST_BUSYBOX, LINUX_TEST_NO_INSTALL,
# LINUX_TEST_GPIO=0 (no GPIO cases).
B=${B:-build}
KVER=${LINUX_TEST_KVER:-6.1.0-56-amd64}
TIMEOUT=${LINUX_TEST_TIMEOUT:-170}
SIZE=320x240
FRAMES=3
GFRAMES=12  # frames of the GPIO frame-line case
top=$(pwd)
cache=$top/$B/linux/kernel
work=$top/$B/linux/guest
here=$top/port/linux/kernel

QEMU=${LINUX_TEST_QEMU:-qemu-system-x86_64}
static_busybox() { # the path of a statically linked busybox, or nothing
    b=${LINUX_TEST_BUSYBOX:-$(command -v busybox 2>/dev/null)}
    [ -n "$b" ] && [ -x "$b" ] && ! readelf -l "$b" 2>/dev/null | grep -q INTERP && echo "$b"
}
# The host packages: installed here when missing (as root, through apt-get;
# LINUX_TEST_NO_INSTALL=1 turns this off), otherwise the test is skipped.
need=""
command -v "$QEMU" >/dev/null 2>&1 || need="qemu-system-x86"
[ -n "$(static_busybox)" ] || need="$need busybox-static"
if [ -n "$need" ] && [ -z "$LINUX_TEST_NO_INSTALL" ] && [ "$(id -u)" = 0 ] &&
    command -v apt-get >/dev/null 2>&1; then
    echo "test-linux: installing$(echo " $need" | tr -s ' ') (apt-get)"
    export DEBIAN_FRONTEND=noninteractive
    inst() { apt-get install -y -q --no-install-recommends $need >"$top/$B/linux/apt.log" 2>&1; }
    mkdir -p "$top/$B/linux"
    inst || { apt-get update -q >/dev/null 2>&1 && inst; } ||
        echo "test-linux: apt-get install failed (see $B/linux/apt.log)"
fi
command -v "$QEMU" >/dev/null 2>&1 ||
    { echo "skipped: qemu-system-x86_64 not installed (Debian qemu-system-x86)"; exit 0; }
bb=$(static_busybox)
[ -n "$bb" ] || { echo "skipped: no static busybox (Debian busybox-static)"; exit 0; }
kroot=$cache/$KVER
if [ ! -f "$kroot/boot/vmlinuz-$KVER" ]; then
    mkdir -p "$cache/deb" && rm -rf "$kroot.tmp" && mkdir -p "$kroot.tmp"
    kdl() { apt-get download "linux-image-$KVER-unsigned" >/dev/null 2>&1 ||
        apt-get download "linux-image-$KVER" >/dev/null 2>&1; }
    # apt's lists refreshed once (as root) when the package is not in them
    (cd "$cache/deb" && { ls linux-image-"$KVER"*.deb >/dev/null 2>&1 || kdl ||
        { [ -z "$LINUX_TEST_NO_INSTALL" ] && [ "$(id -u)" = 0 ] &&
          apt-get update -q >/dev/null 2>&1 && kdl; }; }) &&
        dpkg -x "$(ls "$cache/deb"/linux-image-"$KVER"*.deb | head -n 1)" "$kroot.tmp" &&
        mv "$kroot.tmp" "$kroot" ||
        { rm -rf "$kroot.tmp"; echo "skipped: kernel package linux-image-$KVER not available"; exit 0; }
fi
moddir=$kroot/lib/modules/$KVER/kernel
for m in vivid vfb bochs; do
    [ -n "$(find "$moddir" -name "$m.ko*" | head -n 1)" ] ||
        { echo "skipped: $KVER has no $m module"; exit 0; }
done

# ---- gpio-sim ---------------------------------------------------------------
# Debian's kernels build neither gpio-sim nor irq_sim: both are built here
# out of tree from linux-source (the image's own version) against the
# matching linux-headers, downloaded (apt-get download) and unpacked into the
# cache, never installed; the .ko files are kept per kernel ABI. Two changes:
# irq_sim gets a MODULE_LICENSE, and irq_to_desc (not exported) gives way to
# generic_handle_irq. LINUX_TEST_GPIO=0 leaves the GPIO cases out.
gdir=$cache/gpio-sim-$KVER
build_gpio_sim() { # prints why not, on failure
    ver=$(dpkg-deb -f "$(ls "$cache/deb"/linux-image-"$KVER"*.deb | head -n 1)" Version) || return 1
    series=$(echo "$KVER" | cut -d. -f1-2)
    g=$cache/gpio-build && rm -rf "$g" && mkdir -p "$g/hdr" "$g/m" || return 1
    (cd "$cache/deb" && for p in "linux-headers-$KVER" "linux-source-$series"; do
        ls "$p"_"$ver"_*.deb >/dev/null 2>&1 || apt-get download "$p=$ver" >/dev/null 2>&1 ||
            { echo "apt-get download $p=$ver failed"; exit 1; }; done) || return 1
    hdeb=$(ls "$cache/deb/linux-headers-$KVER"_"$ver"_*.deb)
    deps=$(dpkg-deb -f "$hdeb" Depends | tr , '\n' | sed 's/^ *//; s/ .*//' | grep '^linux-\(headers\|kbuild\)')
    (cd "$cache/deb" && for p in $deps; do
        ls "$p"_"$ver"_*.deb >/dev/null 2>&1 || apt-get download "$p=$ver" >/dev/null 2>&1 ||
            { echo "apt-get download $p=$ver failed"; exit 1; }; done) || return 1
    for p in "linux-headers-$KVER" $deps; do
        dpkg -x "$(ls "$cache/deb/$p"_"$ver"_*.deb)" "$g/hdr" || return 1; done
    hd=$g/hdr/usr/src/linux-headers-$KVER
    sed -i "s#^include /usr/src/#include $g/hdr/usr/src/#" "$hd/Makefile"
    cc=$(sed -n 's/^CC = .*)\(gcc-[0-9]*\)$/\1/p' "$hd/.kernelvariables")
    command -v "${cc:-gcc}" >/dev/null 2>&1 || { echo "no ${cc:-gcc} (the kernel's compiler)"; return 1; }
    sd=linux-source-$series
    dpkg-deb --fsys-tarfile "$(ls "$cache/deb/linux-source-$series"_"$ver"_*.deb)" |
        tar xO "./usr/src/$sd.tar.xz" | tar xJ -C "$g" "$sd/drivers/gpio/gpio-sim.c" \
            "$sd/drivers/gpio/gpiolib.h" "$sd/kernel/irq/irq_sim.c" ||
        { echo "cannot unpack gpio-sim.c and irq_sim.c from $sd"; return 1; }
    cp "$g/$sd"/drivers/gpio/gpio-sim.c "$g/$sd"/drivers/gpio/gpiolib.h "$g/$sd/kernel/irq/irq_sim.c" "$g/m/"
    sed -i 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_irq(irqnum);/' "$g/m/irq_sim.c"
    grep -q 'generic_handle_irq(irqnum)' "$g/m/irq_sim.c" || { echo "irq_sim.c: irq_to_desc call not found"; return 1; }
    printf '#include <linux/module.h>\nMODULE_LICENSE("GPL");\n' >> "$g/m/irq_sim.c"
    echo 'obj-m := irq_sim.o gpio-sim.o' > "$g/m/Kbuild"
    make -C "$hd" M="$g/m" modules > "$g/build.log" 2>&1 ||
        { echo "module build failed (see $g/build.log)"; return 1; }
    mkdir -p "$gdir" && cp "$g/m/irq_sim.ko" "$g/m/gpio-sim.ko" "$gdir/" && rm -rf "$g"
}
gpio_off=""
if [ "${LINUX_TEST_GPIO:-1}" = 0 ]; then gpio_off="LINUX_TEST_GPIO=0"
elif ! grep -aq gpiod_line_request_output "$B/linux/bloom_cam.static"; then
    gpio_off="bloom_cam.static was built without libgpiod (Debian libgpiod-dev)"
elif [ -f "$gdir/gpio-sim.ko" ] && [ -f "$gdir/irq_sim.ko" ]; then :
else
    t0=$(date +%s)
    gpio_off=$(build_gpio_sim) || gpio_off=${gpio_off:-gpio-sim build failed}
    [ -n "$gpio_off" ] || echo "test-linux: built gpio-sim and irq_sim for $KVER in $(($(date +%s) - t0)) s (cached)"
fi

# ---- initramfs -------------------------------------------------------------
rm -rf "$work" && mkdir -p "$work/root/bin" "$work/root/modules" "$work/root/proc" \
    "$work/root/sys" "$work/root/dev" "$work/root/out" "$work/res" || exit 1
modfile() { find "$moddir" "$gdir" -name "$(echo "$1" | sed 's/[-_]/[-_]/g').ko*" 2>/dev/null | head -n 1; }
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
for m in virtio_pci virtio_blk vivid vfb bochs; do add_mod $m || exit 1; done
[ -n "$gpio_off" ] || add_mod gpio-sim || exit 1
echo "$order" | tr ' ' '\n' | grep . > "$work/root/modules.order"
# module options (insmod does not read them from the kernel command line, so
# drm_kms_helper.drm_fbdev_overalloc=200 there would be ignored: it is here)
cat > "$work/root/modules.args" <<ARGS
vivid n_devs=1 node_types=0x10101 num_inputs=1 input_types=0x00
vfb vfb_enable=1 mode_option=640x480-32 videomemorysize=2457600
drm_kms_helper drm_fbdev_overalloc=200
ARGS
cp "$bb" "$work/root/bin/busybox"
cp "$B/linux/bloom_cam.static" "$work/root/bloom_cam"
cc -std=c11 -O2 -static -D_POSIX_C_SOURCE=200809L "$here/vctl.c" -o "$work/root/vctl" || exit 1
cc -std=c11 -O2 -D_POSIX_C_SOURCE=200809L "$here/fbcmp.c" -o "$work/fbcmp" || exit 1
# the attenuation preset with a depth plane (--aux): vivid captures 320x180
# when asked for 320x240, so the plane of the capture's size is 320x180 (16-bit)
# and a 320x240 one must be refused naming both sizes
# and every other preset the build carries (those that need no plane), each
# checked against bloom_sim like the default
att=0
presets=$("$B/bloom_sim" --help | sed -n 's/^  This build has: \(.*\)\.$/\1/p' | tr -d ',' | tr ' ' '\n' |
    grep -v '^unity$' | grep -v '^attenuation$' | tr '\n' ' ')
if "$B/bloom_sim" --help | grep -q '^  This build has:.*attenuation'; then
    att=1
    cc -std=c11 -O2 "$here/mkdepth.c" -o "$work/mkdepth" || exit 1
    "$work/mkdepth" 320 180 65535 "$work/root/depth.pgm" && "$work/mkdepth" 320 240 255 "$work/root/depth240.pgm" || exit 1
fi
gpio_on=1; [ -z "$gpio_off" ] || gpio_on=0
{ echo '#!/bin/busybox sh'; echo "SIZE=$SIZE FRAMES=$FRAMES GPIO=$gpio_on ATT=$att PRESETS='$presets' GFRAMES=$GFRAMES FB16_ID='vioverlay fb' FB32_ID='bochs-drmdrmfb' FBX_ID='Virtual FB'";
  sed 1d "$here/init.sh"; } > "$work/root/init"
chmod +x "$work/root/init" "$work/root/bin/busybox"
(cd "$work/root" && find . | "$bb" cpio -o -H newc 2>/dev/null) > "$work/initrd.cpio" || exit 1
dd if=/dev/zero of="$work/disk.img" bs=1M count=64 2>/dev/null

# ---- boot ------------------------------------------------------------------
timeout "$TIMEOUT" "$QEMU" -accel tcg -cpu max -m 512M -smp 1 -nographic -vga std -nic none \
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
if [ "$att" = 1 ]; then
    frame_check att-16 rgb565 $P --preset attenuation --aux "$work/root/depth.pgm"
else
    echo "  (attenuation preset cases left out: compiled out of this build)"
fi
for p in $presets; do
    frame_check "preset-$p" rgb565 $P --preset "$p"
done
# bochs' fbdev has two pages (drm_fbdev_overalloc=200): the 32 bpp cases must
# have flipped with FBIOPAN_DISPLAY (the second page's offset seen in /sys
# while running) and put the pan back to 0,0; their pictures are checked above
pan_bad=""
for c in yuyv-32 rgb24-32 grey-32 off-32; do
    t=$r/$c.txt
    grep -q ", double-buffered;" "$t" 2>/dev/null && grep -q '^/sys pan during:.* 0,[1-9]' "$t" &&
        grep -q '^/sys pan after: 0,0$' "$t" || pan_bad="$pan_bad $c"
done
if [ -z "$pan_bad" ]; then
    ok "pan: the 32 bpp cases double-buffered, /sys pan seen:$(sed -n 's/^\/sys pan during://p' "$r/yuyv-32.txt"), 0,0 after"
else
    bad "pan: not double-buffered, never panned, or not restored:$pan_bad"
    for c in $pan_bad; do grep -h "buffered\|/sys pan" "$r/$c.txt" | sed "s/^/       $c: /"; done
fi
fault_check() { # case exit-status text
    if grep -q "^exit $2\$" "$r/$1.txt" 2>/dev/null && grep -qF -- "$3" "$r/$1.txt"; then
        ok "$1: '$3', exit $2"
    else
        bad "$1: wanted '$3' and exit $2"; sed 's/^/       /' "$r/$1.txt" 2>/dev/null
    fi
}
fault_check xbgr 1 "is 32 bpp XBGR8888; only 16 bpp RGB565 and 32 bpp XRGB8888 are supported"
fault_check sigterm 0 "bloom_cam: stopping on SIGTERM"
fault_check sigterm 0 "/sys pan after: 0,0"
fault_check stall 1 "bloom_cam: poll: no frame from the device within 1500 ms"
fault_check bufferror 1 "flagged V4L2_BUF_FLAG_ERROR"
fault_check disconnect 1 ": No such device"  # VIDIOC_DQBUF or VIDIOC_QBUF, whichever sees it
fault_check disconnect 1 "/sys pan after: 0,0"
if [ "$att" = 1 ]; then
    fault_check att-size 1 "/depth240.pgm: the plane is 320x240 but the capture is 320x180"
fi
if [ -n "$gpio_off" ]; then
    echo "  (GPIO cases left out: $gpio_off)"
else
    # the kernel set the frame line: 0 when requested, then high and low once per
    # frame, and 0 again when released
    want=0$(i=0; while [ $i -lt "$GFRAMES" ]; do printf 10; i=$((i + 1)); done)0
    got=$(cat "$r/gpio-trace.txt" 2>/dev/null)
    if grep -q '^exit 0$' "$r/gpio-frame.txt" 2>/dev/null && [ "$got" = "$want" ]; then
        ok "gpio-frame: $GFRAMES frames, the line set 1 then 0 once per frame (traced: $got)"
    else
        bad "gpio-frame: wanted the line set $want, got '$got'"; sed 's/^/       /' "$r/gpio-frame.txt" 2>/dev/null
    fi
    ns=$(grep -c . "$r/gpio-samples.txt" 2>/dev/null); nh=$(grep -c '^1 ' "$r/gpio-samples.txt" 2>/dev/null)
    if [ "${ns:-0}" -gt 0 ] && awk '$1 != ($2 == "" ? 0 : $2) { exit 1 }' "$r/gpio-samples.txt"; then
        ok "gpio-frame: the sysfs value equals the last value set, at each of $ns stops ($nh while high)"
    else
        bad "gpio-frame: sysfs value and last value set differ (or no samples)"
        sed 's/^/       /' "$r/gpio-samples.txt" 2>/dev/null
    fi
    fault_check button 0 "bloom_cam: mode off"
    frame_check button rgb565 --threshold 256 --knee 0 --intensity 0
fi
# the figure is printed, never asserted (emulation speed varies)
if grep -q '^exit 0$' "$r/speed.txt" 2>/dev/null; then
    ok "speed: 640x480 yuyv, 16 frames to the 32 bpp screen"
    grep -h "total:" "$r/speed.txt" |
        sed 's/^bloom_cam: total:/  emulated (qemu TCG, not a board) 640x480 YUYV -> 32 bpp:/'
else
    bad "speed: bloom_cam failed"; sed 's/^/       /' "$r/speed.txt" 2>/dev/null
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
