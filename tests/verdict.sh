# Sourced by tests/run.sh and tests/runbin.sh: the one place that turns a
# program's exit status and log into a verdict, so that no check can count
# a crash as a pass.
#
# Protocol (every test binary and check follows it):
#   - the last line of the count is "N passed, N failed, N skipped"
#     (the ", N skipped" part may be absent: 0);
#   - each skipped thing is named above it on a line "skipped: WHAT: WHY";
#   - the exit status is 0 exactly when nothing failed.
# The verdict adds a failure when the exit status is not 0 (a crash, an
# abort, the canary status), when no closing line was printed, when the
# program ran nothing at all, when failures were counted but the status is
# 0, and when the skip count differs from the skips named. Under CI
# (CI=true) every skip is a failure, except "skipped: cpu ...": a CPU
# feature the machine lacks (AVX2), which no install can provide.

# verdict STATUS LOGFILE [COUNTLESS_OK]: sets v_pass v_fail v_skip v_why
# (why the verdict added failures, empty if it did not). With COUNTLESS_OK=1
# a log without a closing line and status 0 is one pass (a make target whose
# recipe is its own check, such as a compile).
verdict() {
    v_why=""
    set -- "$1" "$2" "${3:-0}" \
        "$(awk '/^[0-9]+ passed, [0-9]+ failed(, [0-9]+ skipped)?$/ {
                    p += $1; f += $3; s += ($5 == "" ? 0 : $5); n++ }
                END { printf "%d %d %d %d", n, p, f, s }' "$2")"
    # shellcheck disable=SC2086
    set -- "$1" "$2" "$3" $4
    st=$1 n=$4 v_pass=$5 v_fail=$6 v_skip=$7
    named=$(grep -c '^skipped: ' "$2")
    if [ "$n" -eq 0 ]; then
        if [ "$3" = 1 ] && [ "$st" -eq 0 ]; then
            v_skip=$named
            [ "$named" -eq 0 ] && v_pass=1
        else
            v_why="no closing line"
        fi
    elif [ "$v_skip" -ne "$named" ]; then
        v_why="$v_skip skipped counted, $named named"
    fi
    if [ "$st" -gt 128 ] && [ "$st" -lt 160 ]; then
        v_why="${v_why:+$v_why; }killed by signal $(kill -l "$((st - 128))" 2>/dev/null || echo $((st - 128)))"
    elif [ "$st" -ne 0 ]; then
        v_why="${v_why:+$v_why; }exit status $st"
    elif [ "$v_fail" -gt 0 ]; then
        v_why="${v_why:+$v_why; }$v_fail failed but exit status 0"
    fi
    [ "$n" -gt 0 ] && [ $((v_pass + v_fail + v_skip)) -eq 0 ] && v_why="${v_why:+$v_why; }ran nothing"
    if [ "${CI:-}" = true ]; then
        ci=$(grep '^skipped: ' "$2" | grep -vc '^skipped: cpu')
        if [ "$ci" -gt 0 ]; then
            v_why="${v_why:+$v_why; }$ci skipped under CI (CI=true: this machine kind can run them)"
            v_skip=$((v_skip - ci))
            [ "$v_skip" -lt 0 ] && v_skip=0
            v_fail=$((v_fail + ci))
        fi
    fi
    [ -n "$v_why" ] && [ "$v_fail" -eq 0 ] && v_fail=1
    return 0
}
