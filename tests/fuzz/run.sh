#!/bin/sh
# The fuzz runner of tests/fuzz.mk (tests/fuzz/README.md), one fuzzer at a
# time and one worker each (the machine's cores are shared).
#   run.sh test   make test-fuzz: per target, replay its corpus (every file
#                 once, at full length), then fuzz for FUZZ_TEST_TIME seconds
#                 (default 10) from it in a fresh work directory; one pass or
#                 fail per target, then "N passed, N failed, N skipped"
#   run.sh fuzz   make fuzz: each target FUZZ_TIME seconds (default 300), new
#                 inputs kept in build/fuzz/work/<target>, crashes in
#                 build/fuzz/artifacts/; the execution counts at the end
# A target passes only when libFuzzer exits 0 (its own status, never through
# a pipe): a crash, a leak, a timeout or running out of memory fails it.
# Environment (from the make rule): B, CLANG, MAKE, FUZZ_TARGETS, EXR (no:
# built without OpenEXR, fuzz_exr is skipped), FUZZ_TIME.
mode=${1:-test}
B=${B:-build}
CLANG=${CLANG:-clang}
MAKE=${MAKE:-make}
FUZZ_TARGETS=${FUZZ_TARGETS:-"ppm pfm png jpeg exr y4m raw aux cam_opts cam_conv api"}
dir=$B/fuzz
here=$(dirname "$0")

# Largest input per target: the readers' files stay small (fast runs, and the
# corpora's sizes), the API's and the command line's inputs are parsed bytes.
max_len() {
    case $1 in
    aux) echo 8192 ;; cam_opts) echo 1024 ;; cam_conv) echo 4096 ;; api) echo 2048 ;;
    *) echo 16384 ;;
    esac
}

unavailable() {
    if [ "$mode" = test ]; then
        echo "skipped: test-fuzz: $1"
        echo "0 passed, 0 failed, 1 skipped"
        exit 0
    fi
    echo "fuzz: $1" >&2
    exit 1
}

mkdir -p "$dir"
command -v "$CLANG" >/dev/null 2>&1 || unavailable "$CLANG not found (clang with its libFuzzer runtime is needed)"
printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n);\n%s\n' \
    'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { (void)d; (void)n; return 0; }' \
    >"$dir/probe.c"
"$CLANG" -fsanitize=fuzzer,address,undefined "$dir/probe.c" -o "$dir/probe" >"$dir/probe.log" 2>&1 ||
    unavailable "$CLANG cannot link -fsanitize=fuzzer (no libFuzzer runtime): $(head -n 1 "$dir/probe.log")"

if ! $MAKE --no-print-directory fuzz-build >"$dir/build.log" 2>&1; then
    tail -n 30 "$dir/build.log"
    n=0
    for t in $FUZZ_TARGETS; do
        echo "FAILED: fuzz_$t: not built (make fuzz-build, $dir/build.log)"
        n=$((n + 1))
    done
    echo "0 passed, $n failed, 0 skipped"
    exit 1
fi

pass=0 fail=0 skip=0
mkdir -p "$dir/logs" "$dir/artifacts"
for t in $FUZZ_TARGETS; do
    bin=$dir/fuzz_$t
    corpus=$here/corpus/$t
    if [ "$t" = exr ] && [ "${EXR:-yes}" = no ]; then
        echo "skipped: fuzz_exr: the simulator is built without OpenEXR (libopenexr-dev)"
        skip=$((skip + 1))
        continue
    fi
    dict=""
    [ -f "$here/$t.dict" ] && dict="-dict=$here/$t.dict"
    # the API's inputs are programs: long ones from the start
    [ "$t" = api ] && dict="$dict -len_control=0"
    log=$dir/logs/$t.log
    if [ "$mode" = test ]; then
        # every seed once, whole; then a short run from them
        nseeds=$(find "$corpus" -type f | wc -l)
        find "$corpus" -type f | sort | xargs -r "$bin" -rss_limit_mb=2048 -timeout=30 >"$log.replay" 2>&1
        st=$?
        if [ "$st" -ne 0 ]; then
            echo "FAILED: fuzz_$t: replaying $corpus: exit status $st ($log.replay)"
            grep -E "check failed|ERROR: |SUMMARY|^Running" "$log.replay" | grep -B1 -E "check failed|ERROR|SUMMARY" | tail -n 6
            fail=$((fail + 1))
            continue
        fi
        work=$dir/test/$t
        rm -rf "$work"
        mkdir -p "$work"
        # shellcheck disable=SC2086
        "$bin" -max_total_time="${FUZZ_TEST_TIME:-10}" -rss_limit_mb=2048 -timeout=30 -max_len="$(max_len "$t")" \
            -print_final_stats=1 -artifact_prefix="$dir/artifacts/$t-" $dict "$work" "$corpus" >"$log" 2>&1
        st=$?
        runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
        if [ "$st" -ne 0 ]; then
            echo "FAILED: fuzz_$t: exit status $st after ${runs:-?} runs ($log; the input in $dir/artifacts/)"
            grep -E "check failed|ERROR: |SUMMARY" "$log" | tail -n 4
            fail=$((fail + 1))
        else
            echo "fuzz_$t: $nseeds seeds replayed, ${runs:-?} runs in ${FUZZ_TEST_TIME:-10} s: ok"
            pass=$((pass + 1))
        fi
    else
        work=$dir/work/$t
        mkdir -p "$work"
        echo "fuzz_$t: ${FUZZ_TIME:-300} s ($log)"
        # shellcheck disable=SC2086
        "$bin" -max_total_time="${FUZZ_TIME:-300}" -rss_limit_mb=2048 -timeout=30 -max_len="$(max_len "$t")" \
            -print_final_stats=1 -artifact_prefix="$dir/artifacts/$t-" $dict "$work" "$corpus" >"$log" 2>&1
        st=$?
        runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
        if [ "$st" -ne 0 ]; then
            echo "FAILED: fuzz_$t: exit status $st after ${runs:-?} runs"
            grep -E "check failed|ERROR: |SUMMARY|Test unit written" "$log" | tail -n 4
            fail=$((fail + 1))
        else
            echo "fuzz_$t: ${runs:-?} runs, $(find "$work" -type f | wc -l) inputs in $work"
            pass=$((pass + 1))
        fi
    fi
done
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]
