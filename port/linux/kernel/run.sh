#!/bin/sh
# make test-linux: bloom_cam against the kernel's own vivid (V4L2 capture,
# 16 bpp RGB565 framebuffer), bochs-drm (qemu's std VGA: 32 bpp XRGB8888
# through DRM's fbdev emulation, given two pages with drm_kms_helper's
# drm_fbdev_overalloc=200 so the FBIOPAN_DISPLAY double-buffering is used)
# and vfb (32 bpp XBGR8888, refused) drivers, and the GStreamer element
# between them (v4l2src -> bloom -> fbdevsink, gst_cases.sh), in
# qemu-system-x86_64 (TCG) with a Debian kernel. The kernel package is
# downloaded (apt-get download) and unpacked into $B/linux/kernel once.
# The framebuffer contents are compared with bloom_sim run on the frames the
# guest recorded, row by row (--threads 1) and, cases NAME-tN, on N strips
# (the guest has $SMP CPUs, 2 by default; the engine line must name N), with a
# negative control (one flipped bit must be found); the fault cases, without
# --threads, run on the guest's CPUs and must end with their messages. GPIO goes
# through gpio-sim (built here, see below): the frame line's values are
# traced in the guest, the button is pressed by changing its pull in sysfs.
#
# Packages: the versions are resolved from what apt's lists offer when the
# test runs (apt-cache madison/show; an apt-get update first, once, as root,
# when the lists lack a package or a download fails): the image of the
# pinned ABI ($PIN below, or LINUX_TEST_KVER), else (gone from the archive)
# the newest linux-image-<series>-N-<flavour> of its series; the headers of
# that ABI at the image's version (else the newest of that ABI); the
# linux-kbuild and linux-source of the series at the image's version when
# offered, else the newest offered (not tied to one Debian revision). What
# is unpacked and built is cached under names holding those versions; with
# no lists or no network the newest cached build of the ABI is used. One
# line "test-linux: kernel ..., headers ..., kbuild ..., source ..." says
# what was used.
#
# Verdicts: every case left out is said on a line "skipped: test-linux WHAT:
# WHY" and counted; the closing line is "N passed, N failed, N skipped".
# Under CI (CI=true) a case left out for want of something this machine kind
# can have (qemu, a static busybox, the kernel packages, the gpio-sim build,
# libgpiod) is a failure naming it instead ("FAIL test-linux WHAT: WHY").
# qemu-system-x86 and busybox-static (and the GStreamer packages of
# gst_cases.sh) are first installed with apt-get when missing and run as root. passed + failed + skipped must equal the count
# port/linux/README.md states ("N cases with all six presets"), else one more failure.
# Env: LINUX_TEST_KVER, LINUX_TEST_TIMEOUT, LINUX_TEST_QEMU,
# LINUX_TEST_BUSYBOX, LINUX_TEST_NO_INSTALL (no apt-get install or update),
# LINUX_TEST_SMP (the guest's CPUs, default 2: bloom_cam's default --threads
# runs two strips in parallel, under MTTCG where qemu has it),
# LINUX_TEST_GPIO=0 (GPIO cases skipped), LINUX_TEST_GST=0 (GStreamer cases
# skipped), SOAK_FRAMES, SOAK_SEED, SOAK_ONLY=1 (the soak alone: make
# soak-cam), CI.
B=${B:-build}
PIN=6.1.0-56-amd64
KVER=${LINUX_TEST_KVER:-$PIN}
TIMEOUT=${LINUX_TEST_TIMEOUT:-480}
SMP=${LINUX_TEST_SMP:-2}
SIZE=320x240
FRAMES=3
GFRAMES=12  # frames of the GPIO frame-line case
# the soak (init.sh): its frames, the seed of its fault intervals, and
# whether it runs alone (make soak-cam: SOAK_FRAMES=20000 SOAK_ONLY=1)
SOAK_FRAMES=${SOAK_FRAMES:-450}
SOAK_SEED=${SOAK_SEED:-1}
SOAK_ONLY=${SOAK_ONLY:-0}
top=$(pwd)
cache=$top/$B/linux/kernel
work=$top/$B/linux/guest
here=$top/port/linux/kernel

# ---- verdicts --------------------------------------------------------------
pass=0; fail=0; nskip=0
ok() { pass=$((pass + 1)); echo "  ok   $*"; }
bad() { fail=$((fail + 1)); echo "  FAIL $*"; }
skip() { # what why: a case left out, counted
    nskip=$((nskip + 1)); echo "skipped: test-linux $1: $2"; }
need() { # what why: left out for want of something this machine kind can have
    if [ "${CI:-}" = true ]; then
        fail=$((fail + 1)); echo "FAIL test-linux $1: $2 (CI=true: this machine kind can run it)"
    else
        skip "$1" "$2"
    fi
}
closing() { echo "$pass passed, $fail failed, $nskip skipped"; [ "$fail" -eq 0 ] && exit 0; exit 1; }
whole() { need "(the whole test)" "$1"; closing; }     # nothing can run
die() { bad "test-linux: $1"; closing; }                # a step that cannot fail did
. "$here/gst_cases.sh"
. "$here/drm_cases.sh"
. "$here/mjpeg_cases.sh"
. "$here/soak_cases.sh"

QEMU=${LINUX_TEST_QEMU:-qemu-system-x86_64}
static_busybox() { # the path of a statically linked busybox, or nothing
    b=${LINUX_TEST_BUSYBOX:-$(command -v busybox 2>/dev/null)}
    [ -n "$b" ] && [ -x "$b" ] && ! readelf -l "$b" 2>/dev/null | grep -q INTERP && echo "$b"
}
mkdir -p "$cache/deb" || die "cannot make $cache"
# apt's lists refreshed (apt-get update), once, as root: true when they were
updated=0  # 0 not tried, 1 refreshed, 2 failed or not allowed
refresh() { # why
    [ "$updated" = 0 ] || return 1
    updated=2
    [ -z "$LINUX_TEST_NO_INSTALL" ] && [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1 || return 1
    echo "test-linux: apt-get update ($1)"
    apt-get update -q > "$top/$B/linux/apt-update.log" 2>&1 ||
        { echo "test-linux: apt-get update failed (see $B/linux/apt-update.log)"; return 1; }
    updated=1
}
# The host packages: installed here when missing (as root, through apt-get;
# LINUX_TEST_NO_INSTALL=1 turns this off), otherwise the test is left out.
pkgs=""
command -v "$QEMU" >/dev/null 2>&1 || pkgs="qemu-system-x86"
[ -n "$(static_busybox)" ] || pkgs="$pkgs busybox-static"
[ "$(uname -m)" != x86_64 ] || [ "${LINUX_TEST_GST:-1}" = 0 ] || pkgs="$pkgs$(gst_missing)"
if [ -n "$pkgs" ] && [ -z "$LINUX_TEST_NO_INSTALL" ] && [ "$(id -u)" = 0 ] &&
    command -v apt-get >/dev/null 2>&1; then
    echo "test-linux: installing$(echo " $pkgs" | tr -s ' ') (apt-get)"
    export DEBIAN_FRONTEND=noninteractive
    inst() { apt-get install -y -q --no-install-recommends $pkgs >"$top/$B/linux/apt.log" 2>&1; }
    inst || { refresh "apt-get install failed" && inst; } ||
        echo "test-linux: apt-get install failed (see $B/linux/apt.log)"
fi
command -v "$QEMU" >/dev/null 2>&1 ||
    whole "$QEMU not installed (Debian qemu-system-x86)"
bb=$(static_busybox)
[ -n "$bb" ] || whole "no static busybox${LINUX_TEST_BUSYBOX:+ at $LINUX_TEST_BUSYBOX} (Debian busybox-static)"

# ---- package versions, from apt's lists -------------------------------------
versions() { # package: the versions apt's lists offer, newest first
    apt-cache madison "$1" 2>/dev/null | awk -F'|' -v p="$1" '
        { n = $1; v = $2; gsub(/ /, "", n); gsub(/ /, "", v) }
        n == p && $3 ~ /Packages/ && !seen[v]++ { print v }'
}
pick() { # package preferred-version: that version when offered, else the newest offered
    vs=$(versions "$1")
    [ -n "$vs" ] || return 1
    if echo "$vs" | grep -qxF "$2"; then echo "$2"; else echo "$vs" | head -n 1; fi
}
img_of() { # abi: "package version" of its image (the unsigned one first), when offered
    for p in "linux-image-$1-unsigned" "linux-image-$1"; do
        v=$(versions "$p" | head -n 1)
        [ -n "$v" ] && { echo "$p $v"; return 0; }
    done
    return 1
}
series=${KVER%%-*}  # 6.1.0
flavour=${KVER#*-*-}  # amd64
newest_abi() { # the newest ABI of $series-N-$flavour whose image is offered
    re=$(echo "$series" | sed 's/\./\\./g')
    apt-cache pkgnames "linux-image-$series-" 2>/dev/null |
        sed -n "s/^linux-image-\($re-[0-9][0-9]*-$flavour\)\(-unsigned\)\{0,1\}\$/\1/p" |
        sort -u | sort -t- -k2,2nr | while read -r a; do
            img_of "$a" >/dev/null && { echo "$a"; break; }; done
}
cached() { # prefix: the newest complete cache directory "$cache/prefix*", or nothing
    ls -d "$cache/$1"* 2>/dev/null | grep -v '\.tmp$' | sort -V | tail -n 1
}
cached_series() { # the newest image of $series-N-$flavour unpacked in the cache, or nothing
    ls -d "$cache/image_$series-"* 2>/dev/null | grep -v '\.tmp$' |
        grep "/image_$(echo "$series" | sed 's/\./\\./g')-[0-9]*-${flavour}_" | sort -V | tail -n 1
}
deb=""
get_deb() { # package version: sets deb, the .deb in $cache/deb (downloaded once)
    deb=$(ls "$cache/deb/${1}_$(echo "$2" | sed 's/:/%3a/')_"*.deb 2>/dev/null | head -n 1)
    [ -n "$deb" ] && return 0
    (cd "$cache/deb" && apt-get download "$1=$2" >> "$cache/download.log" 2>&1) || return 1
    deb=$(ls "$cache/deb/${1}_$(echo "$2" | sed 's/:/%3a/')_"*.deb 2>/dev/null | head -n 1)
    [ -n "$deb" ]
}

# the kernel image: "IPKG IVER", KVER possibly moved to the newest of the series
why=""
resolve_image() {
    r=$(img_of "$KVER") || { refresh "linux-image-$KVER is not in apt's lists" && r=$(img_of "$KVER"); }
    if [ -z "$r" ] && [ "$updated" != 1 ] && [ -n "$(cached "image_${KVER}_")" ]; then
        # not offered and the lists could not be refreshed: what was unpacked before
        kroot=$(cached "image_${KVER}_"); r=$(cat "$kroot/package.txt")
        echo "test-linux: linux-image-$KVER is not in apt's lists (not refreshed): the cached $r is used"
    elif [ -z "$r" ] && a=$(newest_abi) && [ -n "$a" ]; then
        echo "test-linux: linux-image-$KVER is not in the archive: the newest of its series, linux-image-$a, is used"
        KVER=$a; r=$(img_of "$KVER")
    elif [ -z "$r" ] && [ "$updated" != 1 ] && kroot=$(cached_series) && [ -n "$kroot" ]; then
        # nothing of the series in the lists, which could not be refreshed: the newest cached
        r=$(cat "$kroot/package.txt"); KVER=${kroot##*/image_}; KVER=${KVER%_*}
        echo "test-linux: no linux-image-$series-*-$flavour in apt's lists (not refreshed): the cached $r is used"
    elif [ -z "$r" ]; then
        why="kernel package linux-image-$KVER is not in apt's lists, nor any linux-image-$series-*-$flavour"; return 1
    fi
    set -- $r; IPKG=$1; IVER=$2
    kroot=$cache/image_${KVER}_$IVER
}
fetch_image() {
    [ -f "$kroot/boot/vmlinuz-$KVER" ] && return 0
    get_deb "$IPKG" "$IVER" || { why="apt-get download $IPKG=$IVER failed (see $B/linux/kernel/download.log)"; return 1; }
    rm -rf "$kroot.tmp" && mkdir -p "$kroot.tmp" && dpkg-deb -x "$deb" "$kroot.tmp" &&
        [ -f "$kroot.tmp/boot/vmlinuz-$KVER" ] && echo "$IPKG $IVER" > "$kroot.tmp/package.txt" &&
        mv "$kroot.tmp" "$kroot" || { rm -rf "$kroot.tmp"; why="cannot unpack $deb"; return 1; }
}
resolve_image || whole "$why"
fetch_image || { refresh "$why" && resolve_image && fetch_image; } || whole "$why"
moddir=$kroot/lib/modules/$KVER/kernel
for m in vivid vfb bochs cirrus; do
    [ -n "$(find "$moddir" -name "$m.ko*" | head -n 1)" ] || whole "$KVER has no $m module"
done

# ---- gpio-sim (gpio_sim.sh) -----------------------------------------------------
. "$here/gpio_sim.sh"
gpio_off=""   # why the GPIO cases are left out
gpio_need=1   # and whether that is a failure under CI
gdir=""
gver="headers, kbuild, source: not used (GPIO cases left out)"
if [ "${LINUX_TEST_GPIO:-1}" = 0 ]; then gpio_off="LINUX_TEST_GPIO=0"; gpio_need=0
elif ! grep -aq gpiod_line_request_output "$B/linux/bloom_cam.static"; then
    gpio_off="bloom_cam.static was built without libgpiod (Debian libgpiod-dev)"
elif resolve_gpio || { refresh "$why" && resolve_gpio; }; then
    if [ ! -f "$gdir/gpio-sim.ko" ] || [ ! -f "$gdir/irq_sim.ko" ]; then
        t0=$(date +%s)
        build_gpio_sim; st=$?
        if [ "$st" = 2 ] && refresh "$why"; then  # the lists were stale
            if ! resolve_gpio; then st=1
            elif [ -f "$gdir/gpio-sim.ko" ] && [ -f "$gdir/irq_sim.ko" ]; then st=0
            else build_gpio_sim; st=$?
            fi
        fi
        if [ "$st" = 0 ]; then
            echo "test-linux: built gpio-sim and irq_sim for $KVER in $(($(date +%s) - t0)) s (cached)"
        elif [ "$st" = 2 ] && [ "$updated" != 1 ] && [ -n "$(cached "gpio-sim_${KVER}_${IVER}_")" ]; then
            echo "test-linux: $why: the gpio-sim built before is used"
            gdir=$(cached "gpio-sim_${KVER}_${IVER}_")
        else
            gpio_off="gpio-sim build: $why"; gdir=""
        fi
        rm -rf "$cache/gpio-build"
    fi
elif [ "$updated" != 1 ] && [ -n "$(cached "gpio-sim_${KVER}_${IVER}_")" ]; then
    echo "test-linux: $why (lists not refreshed): the gpio-sim built before is used"
    gdir=$(cached "gpio-sim_${KVER}_${IVER}_")
else
    gpio_off="gpio-sim build: $why"
fi
[ -n "$gpio_off" ] || gver=$(cat "$gdir/versions.txt")
echo "test-linux: kernel $IPKG $IVER, $gver"
mjpeg_build

# ---- initramfs -------------------------------------------------------------
rm -rf "$work" && mkdir -p "$work/root/bin" "$work/root/modules" "$work/root/proc" \
    "$work/root/sys" "$work/root/dev" "$work/root/out" "$work/res" || die "cannot make $work"
modfile() { find "$moddir" "$gdir" -name "$(echo "$1" | sed 's/[-_]/[-_]/g').ko*" 2>/dev/null | head -n 1; }
order=""
add_mod() { # dependencies first, each once (n and f set again after the recursion)
    case " $order " in *" $(echo "$1" | tr - _) "*) return 0;; esac
    f=$(modfile "$1"); [ -n "$f" ] || { why="module $1 not found"; return 1; }
    for d in $(tr '\0' '\n' < "$f" | sed -n 's/^depends=//p' | tr , ' '); do add_mod "$d" || return 1; done
    n=$(echo "$1" | tr - _); f=$(modfile "$1")
    case " $order " in *" $n "*) return 0;; esac
    case "$f" in *.ko) cp "$f" "$work/root/modules/$n.ko";;
                 *.ko.xz) xz -dc "$f" > "$work/root/modules/$n.ko";;
                 *.ko.zst) zstd -qdc "$f" > "$work/root/modules/$n.ko";; esac
    order="$order $n"
}
for m in virtio_pci virtio_blk vivid vfb bochs cirrus; do add_mod $m || die "$why"; done
[ -n "$gpio_off" ] || add_mod gpio-sim || die "$why"
echo "$order" | tr ' ' '\n' | grep . > "$work/root/modules.order"
# module options (insmod does not read them from the kernel command line, so
# drm_kms_helper.drm_fbdev_overalloc=200 there would be ignored: it is here)
cat > "$work/root/modules.args" <<ARGS
vivid n_devs=2 node_types=0x10101,0x1 num_inputs=1,1 input_types=0x00,0x00 multiplanar=1,2
vfb vfb_enable=1 mode_option=640x480-32 videomemorysize=2457600
drm_kms_helper drm_fbdev_overalloc=200
ARGS
cp "$bb" "$work/root/bin/busybox"
cp "$B/linux/bloom_cam.static" "$work/root/bloom_cam"
cc -std=c11 -O2 -static -D_POSIX_C_SOURCE=200809L "$here/vctl.c" -o "$work/root/vctl" || die "building the guest tools failed"
cc -std=c11 -O2 -static -D_POSIX_C_SOURCE=200809L "$here/vtmode.c" -o "$work/root/vtmode" || die "building the guest tools failed"
cc -std=c11 -O2 -D_POSIX_C_SOURCE=200809L "$here/fbcmp.c" -o "$work/fbcmp" || die "building the guest tools failed"
# the attenuation preset with a depth plane (--aux): vivid captures 320x180
# when asked for 320x240, so the plane of the capture's size is 320x180 (16-bit)
# and a 320x240 one must be refused naming both sizes
# and every other preset the build carries (those that need no plane), each
# checked against bloom_sim like the default
att=0
presets=$("$B/bloom_sim" --help | sed -n 's/^  This build has: \(.*\)\.$/\1/p' | tr -d ',' | tr ' ' '\n' |
    grep -v '^unity$' | grep -v '^attenuation$' | tr '\n' ' ')
# every preset of the engine (--help's --preset line): those compiled out are skips
all_presets=$("$B/bloom_sim" --help | sed -n 's/^  --preset NAME  *//p' | sed 's/ (default)//' | tr -d ',')
if "$B/bloom_sim" --help | grep -q '^  This build has:.*attenuation'; then
    att=1
    cc -std=c11 -O2 "$here/mkdepth.c" -o "$work/mkdepth" || die "building the guest tools failed"
    "$work/mkdepth" 320 180 65535 "$work/root/depth.pgm" && "$work/mkdepth" 320 240 255 "$work/root/depth240.pgm" || die "mkdepth failed"
fi
gpio_on=1; [ -z "$gpio_off" ] || gpio_on=0
gst_guest "$work/root"
gst_on=1; [ -z "$gst_off$gst_bad" ] || gst_on=0
drm_guest "$work/root"
drm_on=1; [ -z "$drm_off" ] || drm_on=0
mjpeg_guest "$work/root"
mj_on=1; [ -z "$mj_off" ] || mj_on=0
{ echo '#!/bin/busybox sh'; echo "SIZE=$SIZE FRAMES=$FRAMES GPIO=$gpio_on ATT=$att PRESETS='$presets' GFRAMES=$GFRAMES FB16_ID='vioverlay fb' FB32_ID='bochs-drmdrmfb' FBX_ID='Virtual FB' GST=$gst_on GSIZE=$GST_SIZE DRM=$drm_on SOAK_FRAMES=$SOAK_FRAMES SOAK_SEED=$SOAK_SEED SOAK_ONLY=$SOAK_ONLY MJPEG=$mj_on";
  sed 1d "$here/init.sh"; } > "$work/root/init"
chmod +x "$work/root/init" "$work/root/bin/busybox"
(cd "$work/root" && find . | "$bb" cpio -o -H newc 2>/dev/null) > "$work/initrd.cpio" || die "cannot write the initramfs"
dd if=/dev/zero of="$work/disk.img" bs=1M count=128 2>/dev/null

# ---- boot ------------------------------------------------------------------
timeout "$TIMEOUT" "$QEMU" -accel tcg -cpu max -m 512M -smp "$SMP" -nographic -vga std -device cirrus-vga -nic none \
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
    fail=$((fail + 1)); closing
fi

# ---- checks ----------------------------------------------------------------
r=$work/res
if [ "$SOAK_ONLY" = 1 ]; then
    soak_checks; closing
fi
compiled_out() { # preset: the reason its cases are skipped
    echo "the $1 preset is compiled out of this build (BLOOM_USE_$(echo "$1" | tr a-z A-Z)=0)"; }
frame_check() { # case fbformat sim-options...
    c=$1; ff=$2; shift 2
    t=$r/$c.txt
    grep -q '^exit 0$' "$t" 2>/dev/null || { bad "$c: bloom_cam failed"; sed 's/^/       /' "$t"; return; }
    # a case NAME-tN ran on N threads, any other row by row: said by the engine line
    case "$c" in
    *-t[0-9]*) nt=${c##*-t}; eng=$(grep -o "engine: .*, $nt threads ($nt strips), .*" "$t");;
    *) nt=1; eng=$(grep -o "engine: .*, 1 thread (row by row), .*" "$t");;
    esac
    [ -n "$eng" ] || { bad "$c: not on $nt thread(s)"; sed 's/^/       /' "$t"; return; }
    how=row-by-row; [ "$nt" = 1 ] || how="$nt threads, $(echo "$eng" | sed 's/.*bytes (\(.*\))$/\1/')"
    geo=$(sed -n 's/.*): \([0-9]*x[0-9]*\) \([a-z0-9]*\), bytesperline \([0-9]*\),.*/\1 \2 \3/p' "$t" | head -n 1)
    # the Y'CbCr rule the capture was converted with (the driver's colorimetry)
    ycc=$(sed -n 's/.*, ycbcr \(bt[0-9]*-[a-z]*\).*/\1/p' "$t" | head -n 1)
    # the part of the frame the screen shows: its size and first pixel
    shown=$(sed -n 's/.*, \([0-9]*\)x\([0-9]*\) shown from \([0-9]*\),\([0-9]*\)$/\1 \2 \3 \4/p' "$t" | head -n 1)
    [ -n "$geo" ] && [ -n "$shown" ] || { bad "$c: no capture or screen line"; sed 's/^/       /' "$t"; return; }
    set -- $geo $shown "$@"; wh=$1; fmt=$2; bpl=$3; sw=$4; sh=$5; sx=$6; sy=$7; shift 7
    w=${wh%x*}
    rm -rf "$work/sim" && mkdir -p "$work/sim"
    if ! "$B/bloom_sim" "$r/$c.raw" --raw-size "$wh" --raw-format "$fmt" --raw-stride "$bpl" ${ycc:+--raw-ycbcr $ycc} \
        --in-format rgb888 --out-format "$ff" -q -o "$work/sim/f%04d.ppm" "$@" > "$work/sim.log" 2>&1; then
        bad "$c: bloom_sim failed"; sed 's/^/       /' "$work/sim.log"; return
    fi
    last=$(ls "$work/sim"/f*.ppm | tail -n 1)
    n=$(ls "$work/sim"/f*.ppm | wc -l)
    part=""; [ "${sw}x$sh" = "$wh" ] || { part="part $sx $sy $sh"; w=$sw; }
    cp "$last" "$work/last-$c.ppm"  # for the negative control
    if res=$("$work/fbcmp" "$r/$c.fb" "$ff" "$w" "$last" $part 2>&1); then
        ok "$c: $wh $fmt${ycc:+ $ycc} ($how), framebuffer = bloom_sim on the recorded frame $n of $n: $res"
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
    skip att-16 "$(compiled_out attenuation)"
fi
for p in $presets; do
    frame_check "preset-$p" rgb565 $P --preset "$p"
done
for p in $all_presets; do
    case " unity attenuation $presets " in *" $p "*) ;; *) skip "preset-$p" "$(compiled_out "$p")";; esac
done
# --threads N: the same screens as the row-by-row cases above, bit for bit
frame_check yuyv-16-t2 rgb565 $P
frame_check rgb24-32-t3 xrgb8888 $P
frame_check grey-32-t2 xrgb8888 $P
frame_check bloomonly-16-t3 rgb565 $P --view bloom
frame_check off-32-t2 xrgb8888 --threshold 256 --knee 0 --intensity 0
if [ "$att" = 1 ]; then
    frame_check att-16-t3 rgb565 $P --preset attenuation --aux "$work/root/depth.pgm"
else
    skip att-16-t3 "$(compiled_out attenuation)"
fi
for p in $presets; do
    frame_check "preset-$p-t2" rgb565 $P --preset "$p"
done
for p in $all_presets; do
    case " unity attenuation $presets " in *" $p "*) ;; *) skip "preset-$p-t2" "$(compiled_out "$p")";; esac
done
# a 1280x720 capture on the 720x576 screen: the shown part of the frame
frame_check crop-16 rgb565 $P
frame_check crop-16-t2 rgb565 $P
# the other capture formats, single-planar and multi-planar (init.sh)
for c in nv12-16 nv21-32 nv16-32 nv61-16 uyvy-16 yvyu-32 rgb565-16 nv12-16-t2 auto-32 nv12-709f-16 \
    uyvy-709-32 mp-yuyv-16 mp-nv12-32 mp-nv12m-16 mp-nv12m-16-t2 mp-nv16m-32 mp-nv61m-16 mp-auto-16; do
    case "$c" in *-16*) frame_check "$c" rgb565 $P;; *) frame_check "$c" xrgb8888 $P;; esac
done
# negative control: the comparison must see the lowest bit of one pixel of
# yuyv-16-t2's screen flipped (pixel 160,90 of 320x180 RGB565: its blue LSB)
at=$((2 * (320 * 90 + 160)))
v=$(od -An -tu1 -j "$at" -N 1 "$r/yuyv-16-t2.fb" 2>/dev/null | tr -d ' ')
: > "$work/flip.log"
if [ -n "$v" ] && cp "$r/yuyv-16-t2.fb" "$work/flip.fb" &&
    printf "\\$(printf %03o $((v ^ 1)))" | dd of="$work/flip.fb" bs=1 seek="$at" conv=notrunc 2>/dev/null &&
    ! cmp -s "$work/flip.fb" "$r/yuyv-16-t2.fb" &&
    ! "$work/fbcmp" "$work/flip.fb" rgb565 320 "$work/last-yuyv-16-t2.ppm" > "$work/flip.log" 2>&1 &&
    grep -q '^fbcmp: 1 pixels differ$' "$work/flip.log"; then
    ok "negative control: one pixel of yuyv-16-t2's screen changed, fbcmp finds it ($(head -n 1 "$work/flip.log"))"
else
    bad "negative control: a changed pixel of yuyv-16-t2's screen was not found by fbcmp"
    sed 's/^/       /' "$work/flip.log" 2>/dev/null
fi
gst_checks
# bochs' fbdev has two pages (drm_fbdev_overalloc=200): the 32 bpp cases must
# have flipped with FBIOPAN_DISPLAY (the second page's offset seen in /sys
# while running) and put the pan back to 0,0; their pictures are checked above
pan_bad=""
for c in yuyv-32 rgb24-32 grey-32 off-32 rgb24-32-t3 grey-32-t2 off-32-t2; do
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
# exit statuses (port/linux/README.md): 0 stopped or done, 2 configuration,
# 3 camera lost, 4 display
# what the format cases must have gone through: vivid's colorimetry
# controls, the multi-planar API with one and two planes, --format auto's
# choice and --fps
fault_check nv12-709f-16 0 "ycbcr bt709-full"
fault_check uyvy-709-32 0 "ycbcr bt709-limited"
fault_check mp-nv12m-16 0 "NM12 in 2 planes (multi-planar API)"
fault_check mp-nv16m-32 0 "NM16 in 2 planes (multi-planar API)"
fault_check mp-yuyv-16 0 "YUYV (multi-planar API)"
fault_check auto-32 0 "bloom_cam: --format auto: rgb24 of "
fault_check auto-32 0 "formats not converted here; 320x180 offered, 30 fps offered)"
fault_check auto-32 0 ", 30 fps"
fault_check mp-auto-16 0 "formats not converted here; 320x180 offered, 30 fps offered)"
fault_check xbgr 4 "is 32 bpp XBGR8888; only 16 bpp RGB565 and 32 bpp XRGB8888 are supported"
for sig in SIGTERM SIGHUP SIGQUIT SIGPIPE; do
    c=$(echo $sig | tr 'A-Z' 'a-z')
    fault_check $c 0 "bloom_cam: stopping on $sig"
    fault_check $c 0 "/sys pan after: 0,0"
done
# the VT: graphics while drawing, text again after a stop signal and after a
# lost camera (exit 3)
fault_check sigterm 0 "vt during: graphics"
fault_check sigterm 0 "vt after: text"
fault_check sighup 0 "vt after: text"
fault_check sigquit 0 "vt after: text"
fault_check sigpipe 0 "vt after: text"
fault_check disconnect-off 3 "vt after: text"
# the double-buffered screen pans after the vertical blank (bochs-drm's fbdev
# emulation waits for it)
fault_check grey-32 0 "bloom_cam: pages shown after the vertical blank (FBIO_WAITFORVSYNC)"
fault_check stall 3 "bloom_cam: reconnect: /dev/video"
fault_check stall 3 "did not come back within 4 s (last: poll: no frame from the device within 1000 ms)"
fault_check stall-off 3 "bloom_cam: poll: no frame from the device within 1000 ms"
fault_check stall-recover 0 "bloom_cam: total: 60 frames"
fault_check stall-recover 0 "streams again"
fault_check bufferror 0 "flagged V4L2_BUF_FLAG_ERROR: skipped"
fault_check bufferror 0 "bloom_cam: total: 90 frames"
fault_check bufferror 0 "1 bad (1 flagged, 0 short, 0 undecodable JPEG)"
fault_check disconnect 0 "streams again"
fault_check disconnect 0 "bloom_cam: total: 90 frames"
fault_check disconnect 0 "1 reconnects"
fault_check disconnect 0 "/sys pan after: 0,0"
fault_check disconnect-off 3 ": No such device"  # VIDIOC_DQBUF or VIDIOC_QBUF, whichever sees it
fault_check disconnect-off 3 "/sys pan after: 0,0"
fault_check fatal 0 "streams again"
fault_check fatal 0 "bloom_cam: total: 90 frames"
fault_check qbuferror 0 "VIDIOC_QBUF"
fault_check qbuferror 0 "bloom_cam: total: 90 frames"
fault_check reqbufs 3 "bloom_cam: VIDIOC_REQBUFS: "
fault_check streamon 3 "bloom_cam: VIDIOC_STREAMON: "
fault_check seqwrap 0 "bloom_cam: total: 200 frames"
# across the wrap the count of dropped frames stays small (the driver's own
# drops under emulation), not 2^32
d=$(sed -n 's/^bloom_cam: total: [0-9]* frames, [0-9.]* fps, \([0-9]*\) dropped.*/\1/p' "$r/seqwrap.txt" 2>/dev/null)
if grep -q '^exit 0$' "$r/seqwrap.txt" 2>/dev/null && [ -n "$d" ] && [ "$d" -lt 1000 ]; then
    ok "seqwrap: the sequence number wrapped, $d frames counted dropped"
else
    bad "seqwrap: dropped '$d' (wanted a small count)"; sed 's/^/       /' "$r/seqwrap.txt" 2>/dev/null
fi
if [ "$att" = 1 ]; then
    fault_check att-size 2 "/depth240.pgm: the plane is 320x240 but the capture is 320x180"
else
    skip att-size "$(compiled_out attenuation)"
fi
if [ -n "$gpio_off" ]; then
    for c in "gpio-frame (line toggles)" "gpio-frame (sysfs value)" "button (mode switch)" "button (framebuffer)" \
        "button-t2 (mode switch)" "button-t2 (framebuffer)"; do
        if [ "$gpio_need" = 1 ]; then need "$c" "$gpio_off"; else skip "$c" "$gpio_off"; fi
    done
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
    fault_check button-t2 0 "bloom_cam: mode off"
    frame_check button-t2 rgb565 --threshold 256 --knee 0 --intensity 0
fi
# without --threads, as many threads as the guest has CPUs (the speed case)
cpus=$(sed -n 's/^cpus: //p' "$r/speed.txt" 2>/dev/null)
if [ -n "$cpus" ] && grep -q "^bloom_cam: engine: .*, $cpus threads\{0,1\} (" "$r/speed.txt"; then
    ok "threads: without --threads, $(grep -o "$cpus threads\{0,1\} ([^)]*)" "$r/speed.txt" | head -n 1) on the guest's $cpus CPUs"
else
    bad "threads: without --threads, not one thread per CPU (${cpus:-?} CPUs)"; sed 's/^/       /' "$r/speed.txt" 2>/dev/null
fi
# the figure is printed, never asserted (emulation speed varies)
if grep -q '^exit 0$' "$r/speed.txt" 2>/dev/null && grep -q '^exit 0$' "$r/speed-t1.txt" 2>/dev/null; then
    ok "speed: 640x480 yuyv, 16 frames to the 32 bpp screen, on ${cpus:-?} threads and row by row"
    grep -h "total:" "$r/speed.txt" |
        sed "s/^bloom_cam: total:/  emulated (qemu TCG, not a board) 640x480 YUYV -> 32 bpp, ${cpus:-?} threads:/"
    grep -h "total:" "$r/speed-t1.txt" |
        sed 's/^bloom_cam: total:/  emulated (qemu TCG, not a board) 640x480 YUYV -> 32 bpp, row by row:/'
else
    bad "speed: bloom_cam failed"; sed 's/^/       /' "$r/speed.txt" "$r/speed-t1.txt" 2>/dev/null
fi
drm_checks  # drm_cases.sh
mjpeg_checks  # mjpeg_cases.sh
soak_checks  # soak_cases.sh
# the count port/linux/README.md states ("74 cases with all six presets") is the count run
n=$((pass + fail + nskip))
want=$(sed -n 's/.*[^0-9]\([0-9][0-9]*\) cases with all six presets.*/\1/p' "$top/port/linux/README.md" | head -n 1)
if [ -z "$want" ]; then
    bad "case count: port/linux/README.md states none ('N cases with all six presets' not found)"
elif [ "$n" -ne "$want" ]; then
    bad "case count: $n cases ($pass passed + $fail failed + $nskip skipped), port/linux/README.md states $want ('$want cases with all six presets'): make them equal"
else
    echo "test-linux: $n cases, as port/linux/README.md states"
fi
closing
