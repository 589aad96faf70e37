#!/bin/sh
# The Icarus bench (make test-fpga-icarus): each case's vectors from the C
# library (gen_vectors), one vvp run per case, one verdict line at the end.
#   icarus.sh BUILD_DIR GEN_VECTORS
set -u
B=$1
GEN=$2
RTL=port/fpga/rtl
mkdir -p "$B"
# one pixel format: compile, then every case; its lines into $B/run_<fmt>.out
run_fmt() { # fmt888 knee_ii
    fmt=$1 ii=$2
    vvp_file=$B/tb_$fmt.vvp
    if ! iverilog -g2005 -Wall -Wno-timescale -Wno-implicit-dimensions -I"$B/.." \
        -Ptb_icarus.FMT888="$fmt" -Ptb_icarus.KNEE_II="$ii" -o "$vvp_file" port/fpga/tb/tb_icarus.v $RTL/*.v \
        >"$B/iverilog_$fmt.log" 2>&1; then
        echo "FAIL iverilog:"
        cat "$B/iverilog_$fmt.log"
        return
    fi
    # name w h levels threshold knee intensity debug frames seed gap bp (gap, bp of 128)
    while read -r name w h lv t k i d f seed gap bp; do
        [ -z "$name" ] && continue
        p=$B/${name}_$fmt
        if ! "$GEN" "$p" "$fmt" "$w" "$h" "$lv" "$t" "$k" "$i" "$d" "$f" "$seed" "$gap" "$bp"; then
            echo "FAIL gen_vectors $name"
            continue
        fi
        vvp -n "$vvp_file" +case="$p" 2>&1 | grep -v '^VCD\|finish'
    done <<CASES
tiny 1 1 5 0.5 0.5 1.0 0 3 1 0 0
odd 7 5 2 0.3 0.5 2.0 0 3 2 30 30
qcif 33 17 4 0.6 0.5 1.0 0 2 3 20 20
extreme 40 30 5 0 1.0 10.0 1 2 4 10 40
hard 17 33 3 256 0 10.0 0 1 5 0 0
square 64 48 5 0.8 0.5 1.5 0 1 6 40 10
CASES
}
# the RGB888 one-pixel-per-clock knee and the RGB565 3-clock knee of the
# iCE40 build, side by side
run_fmt 1 1 >"$B/run_1.out" 2>&1 &
run_fmt 0 3 >"$B/run_0.out" 2>&1
wait
cat "$B/run_1.out" "$B/run_0.out"
pass=$(cat "$B/run_1.out" "$B/run_0.out" | grep -c '^ok ')
fail=$(cat "$B/run_1.out" "$B/run_0.out" | grep -c '^FAIL')
[ $((pass + fail)) -eq 12 ] || fail=$((fail + 12 - pass - fail))
echo "icarus: RGB888 (knee one pixel per clock) and RGB565 (knee every 3 clocks), no X reached the outputs"
echo "$pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
