#!/bin/sh
# Run every test binary and the build checks; print one closing line
# "N passed, N failed" summed over all of them; exit non-zero on any failure.
# Usage: run.sh BINDIR test_a test_b ...
bindir=$1; shift
pass=0; fail=0
log=$(mktemp)
count() { # name, exit status, log file
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$3" | tail -n 1)
    if [ -n "$line" ]; then
        p=${line%% passed*}; f=${line#*, }; f=${f%% failed*}
    else
        p=0; f=0
    fi
    [ "$2" -ne 0 ] && [ "$f" -eq 0 ] && f=1
    pass=$((pass + p)); fail=$((fail + f))
    printf '%-22s %s\n' "$1" "${line:-exit $2}"
    # the figures a test prints (and, on failure, what failed)
    grep -vE '^[0-9]+ passed, [0-9]+ failed' "$3" | sed 's/^/    /' | tail -n 40
}
for t in "$@"; do
    "$bindir/$t" >"$log" 2>&1; count "$t" $? "$log"
done
# Build checks count one each.
for c in freestanding clang-build check-tables; do
    if make -s "$c" >"$log" 2>&1; then echo "1 passed, 0 failed" >>"$log"; count "$c" 0 "$log"
    else count "$c" 1 "$log"; fi
done
rm -f "$log"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
