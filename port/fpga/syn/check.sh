#!/bin/sh
# make check-fpga-synth: the block still synthesizes.
#   - yosys elaborates bloom_top for both pixel formats (RGB565 with the
#     3-clock knee and its queue, as the iCE40 build): no latch cell, and
#     `check -assert` finds no multiple driver and no combinational loop;
#   - each unit goes through synth_ice40 for the UP5K in the harness
#     (syn/bloom_harness.v): box and tent, which repeat per level, must use
#     no MAC16 (the filters are adds and shifts); every unit must fit the
#     UP5K's 5280 LUTs on its own. Their sizes are the figures of
#     port/fpga/README.md ("What stands in the way of the UP5K").
# Place and route of the whole block is make fpga's (syn/synth.sh, long).
#   check.sh OUTDIR     (the generated bloom_rom.vh in OUTDIR/..)
set -u
out=$1
inc=$(dirname "$out")
mkdir -p "$out"
# the RTL's files: FPGA_RTL of port/fpga/fpga.mk, the one list of them
RTL=${FPGA_RTL:?"run through make (FPGA_RTL lists the RTL)"}
pass=0
fail=0
ok() { pass=$((pass + 1)); echo "ok   $*"; }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
count() { awk -v c="$2" '$1 == c { n = $2 } END { print n + 0 }' "$1"; }

# the yosys runs, two at a time (two cores)
elab() { # fmt knee_ii
    yosys -q -l "$out/elab_$1.log" -p "read_verilog -DSYNTHESIS -I$inc $RTL;
        chparam -set WMAX 320 -set HMAX 240 -set LMAX 5 -set FMT888 $1 -set KNEE_II $2 bloom_top;
        hierarchy -check -top bloom_top; proc; opt_clean;
        select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr t:\$sr; check -assert" >/dev/null 2>&1
    echo $? >"$out/elab_$1.rc"
}
unit() { # unit number, name
    yosys -q -l "$out/unit_$2.log" -p "read_verilog -DSYNTHESIS -I$inc $RTL port/fpga/syn/bloom_harness.v;
        chparam -set UNIT $1 bloom_harness; synth_ice40 -dsp -top bloom_harness; stat" >/dev/null 2>&1
    echo $? >"$out/unit_$2.rc"
}
elab 1 1 &
elab 0 3
wait
unit 0 box &
unit 1 tent
wait
unit 2 knee &
unit 3 composite
wait

for fmt in 1 0; do
    ii=$([ "$fmt" = 1 ] && echo 1 || echo 3)
    if [ "$(cat "$out/elab_$fmt.rc")" = 0 ]; then
        ok "yosys elaborates bloom_top (FMT888=$fmt, KNEE_II=$ii): no latch, no multiple driver, no combinational loop"
    else
        bad "yosys elaboration (FMT888=$fmt): $(grep -i 'error\|warning\|assert' "$out/elab_$fmt.log" | head -3)"
    fi
done
for unit in 0 1 2 3; do
    name=$(echo "box tent knee composite" | cut -d' ' -f$((unit + 1)))
    what=$(echo "level-1_box output_tent 3-clock_knee RGB565_composite" | cut -d' ' -f$((unit + 1)) | tr _ ' ')
    log=$out/unit_$name.log
    if [ "$(cat "$out/unit_$name.rc")" != 0 ]; then
        bad "$name: yosys synth_ice40 failed: $(grep -i error "$log" | head -2)"
        continue
    fi
    luts=$(count "$log" SB_LUT4)
    mac=$(count "$log" SB_MAC16)
    ebr=$(count "$log" SB_RAM40_4K)
    figs="$luts LUT4 of the UP5K's 5280, $ebr EBR, $mac MAC16"
    if [ "$luts" -eq 0 ] || [ "$luts" -gt 5280 ]; then
        bad "$what (320-wide frames), iCE40: $figs: more than the UP5K's logic"
    elif [ "$unit" -le 1 ] && [ "$mac" -ne 0 ]; then
        bad "$what, iCE40: $figs (a filter must use no multiplier)"
    else
        ok "$what (320-wide frames), iCE40: $figs"
    fi
done
echo "$pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
