#!/bin/sh
# test-cross (tests/cross.mk): cross-build for each ARM Linux architecture,
# run under qemu-user from the repo root, and require
#   - every unit test binary to pass by tests/verdict.sh (exit 0, a closing
#     line "N passed, 0 failed, N skipped", nothing crashed),
#   - tests/corpus_hash's listing to be byte-identical to the host's,
#   - bloom_demo's four images to be byte-identical to the host's,
#   - bloom_info to run (its workspace figures differ on 32-bit: pointers).
# Prints one line per item and a closing "N passed, N failed"; prints
# "skipped: ..." (exit 0) when a cross compiler or qemu-user is missing and
# cannot be installed. Environment (tests/cross.mk sets it): B, MAKE,
# CROSS_ARCHS, CROSS_CC_<arch>, CROSS_TESTS (unit tests to emulate),
# CROSS_SKIP_TESTS (built only, named in the output).
B=${B:-build}
MAKE=${MAKE:-make}
CROSS_ARCHS=${CROSS_ARCHS:-aarch64 armhf}
CROSS_CC_aarch64=${CROSS_CC_aarch64:-aarch64-linux-gnu-gcc}
CROSS_CC_armhf=${CROSS_CC_armhf:-arm-linux-gnueabihf-gcc}
CROSS_TESTS=${CROSS_TESTS-$(for f in tests/test_*.c; do basename "$f" .c; done)}
CROSS_SKIP_TESTS=${CROSS_SKIP_TESTS-}
out=$B/cross
export B MAKE CROSS_ARCHS CROSS_CC_aarch64 CROSS_CC_armhf
jobs=$(nproc 2>/dev/null || echo 2)

# ---- one job, run by xargs -P (below): "job ARCH NAME" ----------------
if [ "${1:-}" = job ]; then
    arch=$2; name=$3; dir=$out/$arch
    qemu=$(cat "$dir/.qemu")
    t0=$(date +%s)
    case $name in
    corpus_hash)
        "$qemu" "$dir/corpus_hash" >"$dir/corpus.txt" 2>"$dir/corpus_hash.log"; rc=$?
        if [ $rc -eq 0 ] && cmp -s "$out/host/corpus.txt" "$dir/corpus.txt"; then
            res="identical to host ($(tail -n 1 "$dir/corpus.txt"))"; ok=1
        else
            res="exit $rc, DIFFERS from host: $(diff "$out/host/corpus.txt" "$dir/corpus.txt" |
                grep -c '^>') lines; first: $(diff "$out/host/corpus.txt" "$dir/corpus.txt" |
                grep '^>' | head -n 1)"; ok=0
        fi ;;
    bloom_demo)
        rm -rf "$dir/demo"
        "$qemu" "$dir/bloom_demo" tests/data/rocket_floodlights.ppm "$dir/demo" \
            --threshold 0.6 --intensity 1.5 >"$dir/bloom_demo.log" 2>&1; rc=$?
        ok=1; res="4 images identical to host"
        for f in before after bloom_only side_by_side; do
            cmp -s "$out/host/demo/$f.ppm" "$dir/demo/$f.ppm" || { ok=0; res="exit $rc, $f.ppm DIFFERS"; }
        done
        [ $rc -eq 0 ] || { ok=0; res="exit $rc: $(tail -n 1 "$dir/bloom_demo.log")"; } ;;
    bloom_info)
        "$qemu" "$dir/bloom_info" >"$dir/bloom_info.log" 2>&1; rc=$?
        if [ $rc -eq 0 ]; then ok=1; res="runs"; else ok=0; res="exit $rc"; fi ;;
    *)
        BLOOM_DATA_DIR=tests/data "$qemu" "$dir/$name" >"$dir/$name.log" 2>&1; rc=$?
        # the same verdict as on the host (a crash never passes)
        . tests/verdict.sh
        verdict "$rc" "$dir/$name.log" 0
        res="$v_pass passed, $v_fail failed, $v_skip skipped"
        ok=$((v_fail == 0))
        [ -z "$v_why" ] || res="$res ($v_why)" ;;
    esac
    printf '%s %s %ss %s\n' "$ok" "$name" "$(($(date +%s) - t0))" "$res" >"$dir/$name.result"
    exit 0
fi

# ---- tools: install what is missing, else skip ------------------------
qemu_name() { case $1 in aarch64) echo aarch64 ;; armhf) echo arm ;; esac; }
find_qemu() { # the qemu-user binary for an arch, static build preferred
    for q in "qemu-$(qemu_name "$1")-static" "qemu-$(qemu_name "$1")"; do
        command -v "$q" 2>/dev/null && return 0
    done
    return 1
}
sysroot() { case $1 in aarch64) echo /usr/aarch64-linux-gnu ;; armhf) echo /usr/arm-linux-gnueabihf ;; esac; }
cc_of() { eval "echo \$CROSS_CC_$1"; }
missing() { # "package:what" for everything absent
    for a in $CROSS_ARCHS; do
        case $a in aarch64) d=arm64 ;; armhf) d=armhf ;;
        *) echo "unknown-arch:$a"; continue ;; esac
        command -v "$(cc_of "$a")" >/dev/null 2>&1 || echo "gcc-$(basename "$(sysroot "$a")"):$(cc_of "$a")"
        [ -f "$(sysroot "$a")/lib/libc.a" ] || echo "libc6-dev-$d-cross:$(sysroot "$a")/lib/libc.a"
        find_qemu "$a" >/dev/null || echo "qemu-user-static:qemu-$(qemu_name "$a")"
    done
}
need=$(missing)
if [ -n "$need" ]; then
    pkgs=$(echo "$need" | cut -d: -f1 | sort -u | tr '\n' ' ' | sed 's/ $//')
    SUDO=""
    [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null && SUDO="sudo -n"
    if [ "$(id -u)" -eq 0 ] || [ -n "$SUDO" ]; then
        mkdir -p "$out"
        echo "cross: installing $pkgs"
        export DEBIAN_FRONTEND=noninteractive
        # shellcheck disable=SC2086
        { $SUDO apt-get install -y -qq --no-install-recommends $pkgs ||
          { $SUDO apt-get update -qq && $SUDO apt-get install -y -qq --no-install-recommends $pkgs; }; } \
            >"$out/apt.log" 2>&1
    fi
    need=$(missing)
    if [ -n "$need" ]; then
        echo "skipped: test-cross: missing $(echo "$need" | cut -d: -f2 | tr '\n' ' ')(Debian: $pkgs)"
        exit 0
    fi
fi

# ---- build ------------------------------------------------------------
t0=$(date +%s)
blog=$(mktemp)
if ! $MAKE -s -j"$jobs" "$B/corpus_hash" "$B/bloom_demo" cross-build CROSS_ARCHS="$CROSS_ARCHS" >"$blog" 2>&1; then
    tail -n 30 "$blog"; rm -f "$blog"
    echo "cross-build failed"
    echo "0 passed, 1 failed"
    exit 1
fi
rm -f "$blog"
echo "cross: built $CROSS_ARCHS in $(($(date +%s) - t0))s (-O2 -static)"

# ---- host reference, then the emulated jobs ---------------------------
t0=$(date +%s)
mkdir -p "$out/host"
"$B/corpus_hash" >"$out/host/corpus.txt" || { echo "host corpus_hash failed"; echo "0 passed, 1 failed"; exit 1; }
rm -rf "$out/host/demo"
"$B/bloom_demo" tests/data/rocket_floodlights.ppm "$out/host/demo" --threshold 0.6 --intensity 1.5 \
    >"$out/host/bloom_demo.log" 2>&1 || { echo "host bloom_demo failed"; echo "0 passed, 1 failed"; exit 1; }
echo "cross: host reference in $(($(date +%s) - t0))s: $(tail -n 1 "$out/host/corpus.txt")"

t0=$(date +%s)
# the slow ones first, so that xargs -P keeps both cores busy to the end
names=""
for t in test_conformance test_extreme corpus_hash test_core bloom_demo; do
    case " $CROSS_TESTS corpus_hash bloom_demo " in *" $t "*) names="$names $t" ;; esac
done
for t in $CROSS_TESTS bloom_info; do
    case " $names " in *" $t "*) ;; *) names="$names $t" ;; esac
done
for a in $CROSS_ARCHS; do
    find_qemu "$a" >"$out/$a/.qemu"
    rm -f "$out/$a"/*.result
done
# per architecture: the tests one architecture leaves out (CROSS_SKIP_armhf:
# test_tiles there runs the C kernels, which the host's test_tiles already
# runs under BLOOM_FLAG_NO_SIMD, and takes over 5 minutes under qemu-arm)
skip_on() { # arch test
    eval "sk=\${CROSS_SKIP_$1-}"
    case " $sk " in *" $2 "*) return 0 ;; esac
    return 1
}
CROSS_SKIP_armhf=${CROSS_SKIP_armhf-test_tiles}
for n in $names; do for a in $CROSS_ARCHS; do skip_on "$a" "$n" || echo "$a $n"; done; done |
    xargs -P "$jobs" -n 2 sh "$0" job

pass=0; fail=0
for a in $CROSS_ARCHS; do
    echo "$a ($(cat "$out/$a/.qemu")):"
    for n in $names; do
        skip_on "$a" "$n" && continue
        r=$out/$a/$n.result
        if [ -f "$r" ] && [ "$(cut -c1 "$r")" = 1 ]; then pass=$((pass + 1)); s=ok; else fail=$((fail + 1)); s=FAIL; fi
        printf '  %-4s %s\n' "$s" "$(cut -d' ' -f2- "$r" 2>/dev/null || echo "$n: no result")"
        # what failed, with the lines the test printed just before
        [ $s = FAIL ] && [ -f "$out/$a/$n.log" ] &&
            grep -B2 'CHECK failed' "$out/$a/$n.log" | head -n 6 | sed 's/^/         /'
    done
done
[ -n "$CROSS_SKIP_TESTS" ] && echo "cross: built, not emulated: $CROSS_SKIP_TESTS" \
    "(corpus_hash covers their frames; CROSS_SKIP_TESTS= runs them)"
for a in $CROSS_ARCHS; do
    eval "sk=\${CROSS_SKIP_$a-}"
    [ -n "$sk" ] && echo "cross: built, not emulated on $a: $sk (CROSS_SKIP_$a= runs them)"
done
echo "cross: emulated runs in $(($(date +%s) - t0))s on $jobs cores"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
