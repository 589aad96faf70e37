#!/bin/sh
# make test-install: install into scratch prefixes, then build and run a
# program against the installed library with nothing but pkg-config:
#   - PREFIX=<scratch>: the files where they belong, the shared library's
#     soname and its exported symbols (exactly the functions bloom.h
#     declares), bloom.pc's paths; the program linked shared and static
#     prints the same output as when linked with the in-tree build;
#   - DESTDIR=<staging> PREFIX=/usr: everything under the staging root,
#     bloom.pc naming /usr, the program built through PKG_CONFIG_SYSROOT_DIR;
#   - make uninstall removes every file install put there.
# Prints one line per check and "N passed, N failed, N skipped".
B=${B:-build}
MAKE=${MAKE:-make}
CC=${CC:-cc}
pass=0; fail=0; skip=0
ok() { pass=$((pass + 1)); echo "  ok   $*"; }
bad() { fail=$((fail + 1)); echo "  FAIL $*"; }
finish() { echo "$pass passed, $fail failed, $skip skipped"; [ "$fail" -eq 0 ]; exit $?; }
if ! command -v pkg-config >/dev/null 2>&1; then
    echo "skipped: test-install: pkg-config not installed (Debian pkg-config)"
    skip=1; finish
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
log=$tmp/make.log
pre=$tmp/prefix
if ! $MAKE -s install PREFIX="$pre" >"$log" 2>&1; then
    bad "make install PREFIX=$pre"; tail -n 20 "$log"; finish
fi
ok "make install PREFIX=<scratch>"
gst=""
pkg-config --exists gstreamer-1.0 gstreamer-base-1.0 gstreamer-video-1.0 2>/dev/null && gst=" lib/gstreamer-1.0/libgstbloom.so"
want="bin/bloom_cam bin/bloom_demo bin/bloom_info bin/bloom_sim include/bloom.h include/bloom_config.h$gst lib/libbloom.a lib/libbloom.so lib/libbloom.so.1 lib/libbloom.so.1.0.0 lib/pkgconfig/bloom.pc"
got=$(cd "$pre" && find . \( -type f -o -type l \) | sed 's|^\./||' | sort | tr '\n' ' ' | sed 's/ $//')
[ "$got" = "$want" ] && ok "installed files: $got" || bad "installed files: $got (wanted $want)"
soname=$(readelf -d "$pre/lib/libbloom.so.1.0.0" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[ "$soname" = libbloom.so.1 ] && ok "soname $soname" || bad "soname '$soname'"
api=$(grep -o '^[a-z_][a-z_0-9 *]*[ *]bloom_[a-z0-9_]*(' include/bloom.h | sed 's/.*\(bloom_[a-z0-9_]*\)(/\1/' | sort -u)
exp=$(nm -D --defined-only "$pre/lib/libbloom.so.1.0.0" | awk '$2 == "T" { print $3 }' | sed 's/@.*//' | sort -u)
if [ "$api" = "$exp" ]; then
    ok "exports exactly the $(echo "$api" | wc -l) functions bloom.h declares"
else
    bad "exports differ from bloom.h:"; echo "$api" > "$tmp/api"; echo "$exp" > "$tmp/exp"; diff "$tmp/api" "$tmp/exp" | head
fi
# the element, found by GStreamer from where it was installed (and nowhere else)
if [ -z "$gst" ]; then
    echo "skipped: test-install: the GStreamer element: GStreamer's development packages are missing"
    skip=$((skip + 1))
elif ! command -v gst-inspect-1.0 >/dev/null 2>&1; then
    echo "skipped: test-install: the installed GStreamer element: gst-inspect-1.0 missing (gstreamer1.0-tools)"
    skip=$((skip + 1))
elif GST_PLUGIN_PATH="$pre/lib/gstreamer-1.0" GST_REGISTRY="$tmp/registry.bin" \
    gst-inspect-1.0 bloom 2>&1 | grep -q "Factory Details"; then
    ok "gst-inspect-1.0 finds the element bloom in $pre/lib/gstreamer-1.0"
else
    bad "gst-inspect-1.0 bloom with GST_PLUGIN_PATH=$pre/lib/gstreamer-1.0"
fi
export PKG_CONFIG_PATH="$pre/lib/pkgconfig"
[ "$(pkg-config --modversion bloom)" = 1.0.0 ] && ok "pkg-config --modversion bloom: 1.0.0" ||
    bad "pkg-config --modversion bloom: $(pkg-config --modversion bloom 2>&1)"
flags=$(pkg-config --cflags --libs bloom)
case $flags in *"-I$pre/include"*"-L$pre/lib"*) ok "pkg-config --cflags --libs bloom: $flags" ;;
    *) bad "pkg-config --cflags --libs bloom: $flags" ;; esac
src=port/pkgconfig/consumer.c
# shellcheck disable=SC2086
if $CC -std=c11 -Wall -Wextra -Werror "$src" $flags -o "$tmp/shared" 2>"$log" &&
    $CC -std=c11 -Wall -Wextra -Werror "$src" $(pkg-config --cflags bloom) \
        "$(pkg-config --variable=libdir bloom)/libbloom.a" -o "$tmp/static" 2>>"$log" &&
    $CC -std=c11 -Wall -Wextra -Werror -Iinclude "$src" "$B/libbloom.a" -o "$tmp/intree" 2>>"$log"; then
    ok "consumer built shared and static with pkg-config, and in tree"
else
    bad "consumer build"; cat "$log"; finish
fi
needed=$(readelf -d "$tmp/shared" | sed -n 's/.*(NEEDED).*\[\(libbloom[^]]*\)\]/\1/p')
[ "$needed" = libbloom.so.1 ] && ok "the shared consumer needs $needed" || bad "shared consumer NEEDED '$needed'"
s=$(LD_LIBRARY_PATH="$pre/lib" "$tmp/shared"); t=$("$tmp/static"); i=$("$tmp/intree")
if [ -n "$i" ] && [ "$s" = "$i" ] && [ "$t" = "$i" ]; then
    ok "shared, static and in-tree runs agree: $i"
else
    bad "outputs differ: shared '$s', static '$t', in tree '$i'"
fi
# staging: DESTDIR with the final prefix /usr
stage=$tmp/stage
if $MAKE -s install DESTDIR="$stage" PREFIX=/usr >"$log" 2>&1 && [ -f "$stage/usr/lib/libbloom.so.1.0.0" ] &&
    grep -qx 'prefix=/usr' "$stage/usr/lib/pkgconfig/bloom.pc"; then
    ok "make install DESTDIR=<staging> PREFIX=/usr: files under the staging root, bloom.pc names /usr"
else
    bad "DESTDIR install"; tail -n 20 "$log"
fi
# shellcheck disable=SC2046
if PKG_CONFIG_PATH="$stage/usr/lib/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$stage" \
    $CC -std=c11 "$src" $(PKG_CONFIG_PATH="$stage/usr/lib/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$stage" \
        pkg-config --cflags --libs bloom) -o "$tmp/staged" 2>"$log" &&
    [ "$(LD_LIBRARY_PATH="$stage/usr/lib" "$tmp/staged")" = "$i" ]; then
    ok "consumer built against the staging root through PKG_CONFIG_SYSROOT_DIR, same output"
else
    bad "staged build"; cat "$log"
fi
for d in "$pre" "$stage/usr"; do
    case $d in "$pre") args="PREFIX=$pre" ;; *) args="DESTDIR=$stage PREFIX=/usr" ;; esac
    # shellcheck disable=SC2086
    $MAKE -s uninstall $args >"$log" 2>&1
    left=$(find "$d" \( -type f -o -type l \) | wc -l)
    [ "$left" -eq 0 ] && ok "make uninstall $args: nothing left" || bad "make uninstall $args: $left files left"
done
finish
