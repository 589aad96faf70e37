#!/bin/sh
# make cost-selftest (run by make test-runner): the target cost counters
# on hand-written programs of known instruction counts and class mixes
# (port/mcu/cost_selftest.py says which). Installs the tools first when it
# can (port/mcu/cost_deps.sh); otherwise reports one named skip. Ends with
# "N passed, N failed, N skipped".
B=${B:-build}
CC=${CC:-cc}
ARM_CC=${ARM_CC:-arm-none-eabi-gcc}
A64_CC=${CROSS_CC_aarch64:-aarch64-linux-gnu-gcc}
A32_CC=${CROSS_CC_armhf:-arm-linux-gnueabihf-gcc}
d=$(dirname "$0")
o=$B/cost/selftest
mkdir -p "$o"
if ! sh "$d/cost_deps.sh" >"$o/deps.log" 2>&1; then
    echo "skipped: cost-selftest: $(tail -n 1 "$o/deps.log")"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
fail() { echo "  FAIL build: $1"; echo "0 passed, 1 failed, 0 skipped"; exit 1; }
"$ARM_CC" -mcpu=cortex-m4 -mthumb -nostdlib -Wl,-e,st_main -Wl,-Ttext=0 -Wl,-Tdata=0x20000000 \
    "$d/cost_selftest_m.S" -o "$o/m.elf" || fail "the Cortex-M program"
"$CC" -std=c11 -Wall -Wextra -Werror -O2 -fPIC -shared sim/bench/insn_plugin.c -o "$o/insn_plugin.so" ||
    fail "the QEMU plugin"
for n in 10 1000; do
    "$A64_CC" -nostdlib -static -DST_N=$n "$d/cost_selftest_a64.S" -o "$o/a64_$n" || fail "the aarch64 program"
    "$A32_CC" -nostdlib -static -DST_N=$n "$d/cost_selftest_a32.S" -o "$o/a32_$n" || fail "the armhf program"
done
exec /usr/bin/python3 "$d/cost_selftest.py" "$o/m.elf" "$o/insn_plugin.so" "$o/a64_10" "$o/a64_1000" \
    "$o/a32_10" "$o/a32_1000"
