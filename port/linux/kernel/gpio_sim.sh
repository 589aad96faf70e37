# make test-linux: gpio-sim and irq_sim built for the guest kernel (sourced
# by run.sh; resolve_gpio also gives mjpeg_cases.sh the headers' versions).
# Debian's kernels build neither gpio-sim nor irq_sim: both are built here
# out of tree from linux-source (the image's version when offered, else the
# newest of the series) against linux-headers of the image's ABI with their
# -common and linux-kbuild, downloaded (apt-get download) and unpacked into
# the cache, never installed; the .ko files are kept per resolved versions.
# Two changes: irq_sim gets a MODULE_LICENSE, and irq_to_desc (not exported)
# gives way to generic_handle_irq. LINUX_TEST_GPIO=0 leaves the GPIO cases out.
resolve_gpio() { # sets HPKG HVER CPKG CVER KBPKG KBVER SPKG SVER, or why
    HPKG=linux-headers-$KVER; CPKG=""; CVER=""; KBPKG=""; KBVER=""
    SPKG=linux-source-$(echo "$KVER" | cut -d. -f1-2)
    HVER=$(pick "$HPKG" "$IVER") || { why="$HPKG is not in apt's lists"; return 1; }
    deps=$(apt-cache show "$HPKG=$HVER" 2>/dev/null | sed -n 's/^Depends: //p' | head -n 1 |
        tr , '\n' | sed 's/^ *//; s/ *$//')
    for d in $(echo "$deps" | sed 's/ //g'); do  # name(=version) or name(>=version)
        n=${d%%(*}
        case "$n" in
        linux-headers-*)
            CPKG=$n; CVER=$(echo "$d" | sed -n 's/.*(=\(.*\))$/\1/p')
            [ -n "$CVER" ] || CVER=$(pick "$n" "$HVER") || { why="$n is not in apt's lists"; return 1; }
            versions "$n" | grep -qxF "$CVER" || { why="$n $CVER is not in apt's lists"; return 1; };;
        linux-kbuild-*)
            KBPKG=$n; KBVER=$(pick "$n" "$HVER") || { why="$n is not in apt's lists"; return 1; };;
        esac
    done
    [ -n "$KBPKG" ] || { why="$HPKG $HVER: no linux-kbuild in its Depends (apt-cache show)"; return 1; }
    SVER=$(pick "$SPKG" "$IVER") || { why="$SPKG is not in apt's lists"; return 1; }
    gdir=$cache/gpio-sim_${KVER}_${IVER}_headers-${HVER}_kbuild-${KBVER}_source-$SVER
}
build_gpio_sim() { # sets why on failure; status 2 when a download failed
    g=$cache/gpio-build && rm -rf "$g" && mkdir -p "$g/hdr" "$g/m" || { why="cannot make $g"; return 1; }
    for pv in "$HPKG $HVER" "$CPKG $CVER" "$KBPKG $KBVER" "$SPKG $SVER"; do
        set -- $pv
        [ $# = 2 ] || continue
        get_deb "$1" "$2" || { why="apt-get download $1=$2 failed (see $B/linux/kernel/download.log)"; return 2; }
        [ "$1" = "$SPKG" ] || dpkg-deb -x "$deb" "$g/hdr" || { why="cannot unpack $deb"; return 1; }
    done
    hd=$g/hdr/usr/src/linux-headers-$KVER
    [ -f "$hd/Makefile" ] || { why="no $hd/Makefile in $HPKG"; return 1; }
    sed -i "s#^include /usr/src/#include $g/hdr/usr/src/#" "$hd/Makefile"
    cc=$(sed -n 's/^CC = .*)\(gcc-[0-9]*\)$/\1/p' "$hd/.kernelvariables")
    command -v "${cc:-gcc}" >/dev/null 2>&1 || { why="no ${cc:-gcc} (the kernel's compiler)"; return 1; }
    sd=$SPKG
    dpkg-deb --fsys-tarfile "$deb" | tar xO "./usr/src/$sd.tar.xz" | tar xJ -C "$g" "$sd/drivers/gpio/gpio-sim.c" \
            "$sd/drivers/gpio/gpiolib.h" "$sd/kernel/irq/irq_sim.c" ||
        { why="cannot unpack gpio-sim.c and irq_sim.c from $SPKG $SVER"; return 1; }
    cp "$g/$sd"/drivers/gpio/gpio-sim.c "$g/$sd"/drivers/gpio/gpiolib.h "$g/$sd/kernel/irq/irq_sim.c" "$g/m/"
    sed -i 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_irq(irqnum);/' "$g/m/irq_sim.c"
    grep -q 'generic_handle_irq(irqnum)' "$g/m/irq_sim.c" || { why="irq_sim.c: irq_to_desc call not found"; return 1; }
    printf '#include <linux/module.h>\nMODULE_LICENSE("GPL");\n' >> "$g/m/irq_sim.c"
    echo 'obj-m := irq_sim.o gpio-sim.o' > "$g/m/Kbuild"
    make -C "$hd" M="$g/m" modules > "$g/build.log" 2>&1 ||
        { cp "$g/build.log" "$cache/gpio-build.log"; why="module build failed (see $B/linux/kernel/gpio-build.log)"; return 1; }
    rm -rf "$gdir.tmp" && mkdir -p "$gdir.tmp" && cp "$g/m/irq_sim.ko" "$g/m/gpio-sim.ko" "$gdir.tmp/" &&
        echo "headers $HPKG $HVER (and $CPKG $CVER), kbuild $KBPKG $KBVER, source $SPKG $SVER" > "$gdir.tmp/versions.txt" &&
        mv "$gdir.tmp" "$gdir" && rm -rf "$g" || { why="cannot write $gdir"; return 1; }
}
