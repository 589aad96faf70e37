#!/bin/sh
# make test-runner: the runner's self-test. Stand-in test binaries that
# crash, abort, exit with the canary status, print a wrong count, hide a
# skip or print nothing, and stand-in checks built as the real ones are
# (tests/runbin.sh in a recipe), go through the same machinery as the real
# run (tests/run.sh); each bad one must be reported as a failure, the good
# ones as passes, and the run's exit status must be non-zero. The real run
# stays green: this script's own verdict is its closing line.
B=${B:-build}
sb=$B/selftest
mkdir -p "$sb"
cc -std=c11 -O0 tests/selftest/standin.c -o "$sb/standin" || { echo "0 passed, 1 failed, 0 skipped"; exit 1; }
for n in good skip cpuskip segv abort canary wrongcount hiddenskip nosummary empty; do
    ln -sf standin "$sb/$n"
done
pass=0; fail=0
expect() { # what, condition (shell test), output file
    if eval "$2"; then pass=$((pass + 1)); echo "  ok   $1"
    else fail=$((fail + 1)); echo "  FAIL $1 (wanted: $2)"; sed 's/^/       /' "$3"; fi
}
line_of() { grep "^$1 " "$2" | head -n 1; }
failed_in() { line_of "$1" "$2" | sed -n 's/.* \([0-9]*\) failed.*/\1/p'; }

out=$sb/run.out
env -u CI RUN_MAKE="make -s -f tests/selftest/stand.mk SB=$sb" sh tests/run.sh "$sb" \
    good skip cpuskip segv abort canary wrongcount hiddenskip nosummary empty missing -- \
    chk-good chk-segv chk-exit chk-compile chk-fail-compile chk-skip >"$out" 2>&1
st=$?
for n in segv abort canary wrongcount hiddenskip nosummary empty missing \
         chk-segv chk-exit chk-fail-compile; do
    expect "$n counted as a failure" '[ "$(failed_in '"$n"' "$out")" -ge 1 ] 2>/dev/null' "$out"
done
for n in good chk-good chk-compile; do
    expect "$n counted as a pass, no failure" '[ "$(failed_in '"$n"' "$out")" = 0 ]' "$out"
done
expect "skip and chk-skip counted as skips, named" \
    'grep -q "^  skipped: skip: standin: the thing it needs is absent" "$out" &&
     grep -q "^  skipped: chk-skip: chk-skip: its tool is not installed" "$out" &&
     line_of chk-skip "$out" | grep -q "0 failed, 1 skipped"' "$out"
expect "the run exits non-zero" '[ "$st" -ne 0 ]' "$out"
expect "the closing line sums them (11 failed, 4 skipped: hiddenskip's too)" \
    'tail -n 1 "$out" | grep -qx "[0-9]* passed, 11 failed, 4 skipped"' "$out"

# under CI a skip is a failure, a CPU-feature skip is not
out2=$sb/run-ci.out
CI=true RUN_MAKE="make -s -f tests/selftest/stand.mk SB=$sb" sh tests/run.sh "$sb" \
    good skip cpuskip -- chk-skip >"$out2" 2>&1
st2=$?
expect "CI=true: skip and chk-skip fail, cpuskip stays a skip" \
    '[ "$(failed_in skip "$out2")" = 1 ] && [ "$(failed_in chk-skip "$out2")" = 1 ] &&
     [ "$(failed_in cpuskip "$out2")" = 0 ] && [ "$st2" -ne 0 ] &&
     tail -n 1 "$out2" | grep -qx "[0-9]* passed, 2 failed, 1 skipped"' "$out2"
# and a run of good ones only is green
out3=$sb/run-good.out
RUN_MAKE="make -s -f tests/selftest/stand.mk SB=$sb" sh tests/run.sh "$sb" good -- chk-good chk-compile >"$out3" 2>&1
st3=$?
expect "good ones only: exit 0, closing line 0 failed" \
    '[ "$st3" -eq 0 ] && tail -n 1 "$out3" | grep -qx "[0-9]* passed, 0 failed, 0 skipped"' "$out3"
expect "check_layout.sh catches planted breaks, no false ones" 'B=$B sh tests/selftest/check_layout_selftest.sh >"$sb/layout.out" 2>&1' "$sb/layout.out"
# the target cost counters on programs of known counts (issue 21)
skip=0
if make -s cost-selftest B="$B" >"$sb/cost.out" 2>&1; then
    if grep -q '^skipped:' "$sb/cost.out"; then
        skip=$((skip + 1)); grep '^skipped:' "$sb/cost.out" # named, as tests/verdict.sh wants
    else
        pass=$((pass + 1)); echo "  ok   the cost counters count known programs exactly ($(tail -n 1 "$sb/cost.out"))"
    fi
else
    fail=$((fail + 1)); echo "  FAIL the cost counters on known programs"; sed 's/^/       /' "$sb/cost.out"
fi
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]
