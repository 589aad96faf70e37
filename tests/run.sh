#!/bin/sh
# Run every test binary and then every check target; print one closing line
# "N passed, N failed, N skipped" summed over all of them, each skipped
# thing named above it; exit non-zero on any failure. The verdict on each
# program (tests/verdict.sh) counts a crash, a non-zero exit, a missing or
# inconsistent count as a failure, and under CI=true a skip too.
# Usage: run.sh BINDIR test_a test_b ... -- check_a check_b ...
# RUN_MAKE (default "make") runs the checks: the runner's self-test
# (tests/selftest/) points it at stand-ins.
here=$(dirname "$0")
. "$here/verdict.sh"
bindir=$1; shift
RUN_MAKE=${RUN_MAKE:-make}
pass=0; fail=0; skip=0
skips=$(mktemp)
log=$(mktemp)
count() { # name, exit status, log file, countless_ok
    verdict "$2" "$3" "$4"
    pass=$((pass + v_pass)); fail=$((fail + v_fail)); skip=$((skip + v_skip))
    line="$v_pass passed, $v_fail failed, $v_skip skipped"
    printf '%-22s %-38s %4ss\n' "$1" "$line" "$(( $(date +%s) - t0 ))"
    [ -n "$v_why" ] && echo "    FAILED: $1: $v_why"
    grep '^skipped: ' "$3" | sed "s/^skipped: /skipped: $1: /" >>"$skips"
    # the figures a test prints (and, on failure, what failed)
    grep -vE '^[0-9]+ passed, [0-9]+ failed' "$3" | sed 's/^/    /' | tail -n 40
}
# The test binaries are independent processes: two at a time (xargs -P 2),
# each into its own log; reported in order.
tdir=$(mktemp -d)
names=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    names="$names $1"
    shift
done
# shellcheck disable=SC2086
[ -n "$names" ] && printf '%s\n' $names | xargs -P 2 -I{} sh -c \
    't0=$(date +%s); "$1/$2" >"$3/$2.log" 2>&1; echo $? >"$3/$2.rc"; echo $(( $(date +%s) - t0 )) >"$3/$2.sec"' \
    sh "$bindir" {} "$tdir"
for n in $names; do
    t0=$(( $(date +%s) - $(cat "$tdir/$n.sec" 2>/dev/null || echo 0) ))
    [ -f "$tdir/$n.log" ] || echo "never ran" >"$tdir/$n.log"
    count "$n" "$(cat "$tdir/$n.rc" 2>/dev/null || echo 127)" "$tdir/$n.log" 0
done
rm -rf "$tdir"
[ "$1" = "--" ] && shift
for c in "$@"; do
    t0=$(date +%s)
    $RUN_MAKE -s -j2 "$c" >"$log" 2>&1
    count "$c" $? "$log" 1
done
rm -f "$log"
if [ -s "$skips" ]; then
    echo "skipped (what and why):"
    sed 's/^/  /' "$skips"
fi
rm -f "$skips"
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]
