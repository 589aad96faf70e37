#!/bin/sh
# make check-fpga-synth: the block still synthesizes.
#   - yosys elaborates bloom_top for both pixel formats and `check -assert`
#     finds no latch, no multiple driver, no combinational loop;
#   - the units that repeat per level (box, tent) go through synth_ice40
#     for the UP5K in the timing harness: each fits the UP5K's logic on its
#     own, and neither uses a MAC16 (the filters are adds and shifts).
# Place and route of the whole block is make fpga's (syn/synth.sh, long).
#   check.sh OUTDIR     (the generated bloom_rom.vh in OUTDIR/..)
set -u
out=$1
inc=$(dirname "$out")
mkdir -p "$out"
RTL="port/fpga/rtl/bloom_top.v port/fpga/rtl/bloom_box.v port/fpga/rtl/bloom_knee.v port/fpga/rtl/bloom_up.v
     port/fpga/rtl/bloom_out.v port/fpga/rtl/bloom_fifo.v"
# shellcheck disable=SC2086
RTL=$(echo $RTL)
pass=0
fail=0
ok() { pass=$((pass + 1)); echo "ok   $*"; }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
count() { awk -v c="$2" '$1 == c { n = $2 } END { print n + 0 }' "$1"; }

for fmt in 1 0; do
    ys="read_verilog -DSYNTHESIS -I$inc $RTL; chparam -set WMAX 320 -set HMAX 240 -set LMAX 5 -set FMT888 $fmt bloom_top;
        hierarchy -check -top bloom_top; proc; opt_clean; check -assert"
    if yosys -q -l "$out/elab_$fmt.log" -p "$ys" >/dev/null 2>&1; then
        ok "yosys elaborates bloom_top (FMT888=$fmt): no latch, no multiple driver, no combinational loop"
    else
        bad "yosys elaboration (FMT888=$fmt): $(grep -i 'error\|warning' "$out/elab_$fmt.log" | head -3)"
    fi
done
for unit in 0 1; do
    name=$(echo "box tent" | cut -d' ' -f$((unit + 1)))
    log=$out/unit_$name.log
    ys="read_verilog -DSYNTHESIS -I$inc $RTL port/fpga/syn/bloom_harness.v;
        chparam -set UNIT $unit bloom_harness; synth_ice40 -dsp -top bloom_harness; stat"
    if ! yosys -q -l "$log" -p "$ys" >/dev/null 2>&1; then
        bad "$name: yosys synth_ice40 failed: $(grep -i error "$log" | head -2)"
        continue
    fi
    luts=$(count "$log" SB_LUT4)
    mac=$(count "$log" SB_MAC16)
    ebr=$(count "$log" SB_RAM40_4K)
    if [ "$luts" -gt 0 ] && [ "$luts" -le 5280 ] && [ "$mac" -eq 0 ]; then
        ok "$name unit ($([ $unit = 0 ] && echo "level 1" || echo "the output's tent"), 320-wide frames), iCE40: $luts LUT4 of the UP5K's 5280, $ebr EBR, no MAC16"
    else
        bad "$name unit, iCE40: $luts LUT4 (UP5K 5280), $mac MAC16 (a filter must use none)"
    fi
done
echo "$pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
