#!/bin/sh
# Run every test binary and then every check target; print one closing line
# "N passed, N failed[, N skipped]" summed over all of them; exit non-zero on
# any failure. A check that prints a line starting "skipped:" (its tool or
# emulator is missing) counts as skipped, never as passed.
# Usage: run.sh BINDIR test_a test_b ... -- check_a check_b ...
bindir=$1; shift
pass=0; fail=0; skip=0
log=$(mktemp)
count() { # name, exit status, log file
    # sum every closing line the program printed (a check may run several)
    line=$(awk '/^[0-9]+ passed, [0-9]+ failed/ { p += $1; f += $3; n++ }
                END { if (n) printf "%d passed, %d failed", p, f }' "$3")
    if [ -n "$line" ]; then
        p=${line%% passed*}; f=${line#*, }; f=${f%% failed*}
    else
        p=0; f=0
    fi
    [ "$2" -ne 0 ] && [ "$f" -eq 0 ] && f=1
    pass=$((pass + p)); fail=$((fail + f))
    printf '%-22s %-28s %4ss\n' "$1" "${line:-exit $2}" "$(( $(date +%s) - t0 ))"
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
printf '%s\n' $names | xargs -P 2 -I{} sh -c \
    't0=$(date +%s); "$1/$2" >"$3/$2.log" 2>&1; echo $? >"$3/$2.rc"; echo $(( $(date +%s) - t0 )) >"$3/$2.sec"' \
    sh "$bindir" {} "$tdir"
for n in $names; do
    t0=$(( $(date +%s) - $(cat "$tdir/$n.sec" 2>/dev/null || echo 0) ))
    count "$n" "$(cat "$tdir/$n.rc" 2>/dev/null || echo 1)" "$tdir/$n.log"
done
rm -rf "$tdir"
[ "$1" = "--" ] && shift
for c in "$@"; do
    t0=$(date +%s)
    if make -s -j2 "$c" >"$log" 2>&1; then
        if grep -q '^skipped:' "$log"; then
            skip=$((skip + 1))
            printf '%-22s %s\n' "$c" "$(grep '^skipped:' "$log" | head -n 1)"
            continue
        fi
        grep -qE '^[0-9]+ passed, [0-9]+ failed' "$log" || echo "1 passed, 0 failed" >>"$log"
        count "$c" 0 "$log"
    else
        count "$c" 1 "$log"
    fi
done
rm -f "$log"
if [ "$skip" -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ "$fail" -eq 0 ]
