#!/bin/sh
# Run one test program inside a make recipe without losing its verdict:
#   sh tests/runbin.sh LABEL [FILTER] -- PROGRAM ARGS...
# prints LABEL, the program's lines matching the extended regex FILTER (all
# lines when FILTER is empty), then the verdict as one closing line
# "N passed, N failed, N skipped"; exits non-zero when the verdict has a
# failure. Never pipe a test binary into tail or grep: the pipe's status is
# the filter's, and a crash would pass.
here=$(dirname "$0")
. "$here/verdict.sh"
label=$1; shift
filter=""
if [ "$1" != "--" ]; then filter=$1; shift; fi
[ "$1" = "--" ] && shift
log=$(mktemp)
"$@" >"$log" 2>&1
st=$?
verdict "$st" "$log" 0
echo "$label"
if [ -n "$filter" ]; then
    grep -vE '^[0-9]+ passed, [0-9]+ failed' "$log" | grep -E "$filter|^skipped: "
else
    grep -vE '^[0-9]+ passed, [0-9]+ failed' "$log"
fi
[ -n "$v_why" ] && { echo "FAILED: $*: $v_why"; grep -vE '^[0-9]+ passed, [0-9]+ failed' "$log" | tail -n 20; }
rm -f "$log"
echo "$v_pass passed, $v_fail failed, $v_skip skipped"
[ "$v_fail" -eq 0 ]
