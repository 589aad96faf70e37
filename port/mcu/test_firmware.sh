#!/bin/sh
# test-firmware (port/mcu/mcu.mk): every firmware build (m4/m7 x full/rgb565/
# min/minnc x 5/7 levels) runs under qemu-system-arm on its board and must
#   - exit 0 (the firmware's own status over semihosting SYS_EXIT_EXTENDED),
#   - report the CPU the board models (CPUID),
#   - print the same "frame" lines (input and output FNV-1a of the 320x240
#     RGB565 framebuffer) as the host build of the same code.
# and the tiles case (fw_tiles.c: 640x480 RGB565 in strips with a 32 KB
# workspace, on the RGB565-only build) on both boards must print the host's
# "frame" lines for the same frame rendered untiled, from a workspace that
# is at most 32 KB while the untiled one exceeds the 64 KB SRAM.
# Prints one line per run and "N passed, N failed"; "skipped: ..." (exit 0)
# when the cross compiler or qemu is missing and cannot be installed.
. "$(dirname "$0")/tools.sh"

mcu_tools || exit 0
if ! mcu_build; then
    echo "firmware: build failed"
    echo "0 passed, 1 failed"
    exit 1
fi

pass=0; fail=0
for l in $MCU_LEVELS; do
    host=$MCU_OUT/host/fw_host_l$l
    if ! "$host" >"$host.txt" 2>&1; then
        echo "host build, $l levels: FAILED: $(grep '^error' "$host.txt" | head -n 1)"
        fail=$((fail + 1))
        continue
    fi
    grep '^frame' "$host.txt" >"$host.frame"
    for cpu in m4 m7; do
        case $cpu in m4) want=Cortex-M4 ;; m7) want=Cortex-M7 ;; esac
        for b in $MCU_BUILDS; do
            mcu_run "$cpu" "$b" "$l"; rc=$?
            out=$MCU_OUT/$cpu-$b/fw_l$l.txt
            sum=$(grep '^frame.*output fnv1a' "$out" | sed 's/.*output fnv1a \(0x[0-9a-f]*\).*/\1/')
            stack=$(grep '^stack bloom_process' "$out" | sed 's/.*: //')
            what="firmware $(echo $want | tr 'A-Z' 'a-z') ($(mcu_board $cpu)) $b, $l levels"
            if [ $rc -ne 0 ]; then
                why="exit $rc$( [ $rc -eq 124 ] && echo ' (timeout)'): $(grep -E '^(error|fault)' "$out" | head -n 1)"
            elif ! grep -q "^cpu: $want " "$out"; then
                why="not run on a $want: $(grep '^cpu' "$out")"
            elif ! grep '^frame' "$out" | cmp -s - "$host.frame"; then
                why="checksum ${sum:-missing} differs from host $(grep 'output fnv1a' "$host.frame" |
                    sed 's/.*output fnv1a \(0x[0-9a-f]*\).*/\1/')"
            else
                echo "$what: checksum $sum = host (stack of bloom_process $stack)"
                pass=$((pass + 1))
                continue
            fi
            echo "$what: FAILED: $why"
            fail=$((fail + 1))
        done
    done
done
# The tiles case: the host renders the frame untiled (and checks its own
# strips against it); the firmware renders it in strips only.
host=$MCU_OUT/host/fw_host_tiles
if ! "$host" >"$host.txt" 2>&1; then
    echo "host build, tiles: FAILED: $(grep '^error' "$host.txt" | head -n 1)"
    fail=$((fail + 1))
else
    grep '^frame' "$host.txt" >"$host.frame"
    hsum=$(sed -n 's/.*output fnv1a \(0x[0-9a-f]*\).*/\1/p' "$host.frame")
    for cpu in m4 m7; do
        case $cpu in m4) want=Cortex-M4 ;; m7) want=Cortex-M7 ;; esac
        mcu_run_elf "$cpu" "$MCU_OUT/$cpu-rgb565/fw_tiles.elf"; rc=$?
        out=$MCU_OUT/$cpu-rgb565/fw_tiles.txt
        sum=$(sed -n 's/^frame.*output fnv1a \(0x[0-9a-f]*\).*/\1/p' "$out")
        ws=$(sed -n 's/^tiles: workspace declared \([0-9]*\) bytes.*/\1/p' "$out")
        untiled=$(sed -n 's/^tiles: untiled workspace \([0-9]*\) bytes.*/\1/p' "$out")
        sram=$(sed -n 's/^tiles: on-chip SRAM \([0-9]*\) bytes.*/\1/p' "$out")
        strip=$(sed -n 's/^tiles: strip width \([0-9]*\) .*/\1/p' "$out")
        what="firmware $(echo $want | tr 'A-Z' 'a-z') ($(mcu_board $cpu)) rgb565, tiles 640x480"
        if [ $rc -ne 0 ]; then
            why="exit $rc$( [ $rc -eq 124 ] && echo ' (timeout)'): $(grep -E '^(error|fault)' "$out" | head -n 1)"
        elif ! grep -q "^cpu: $want " "$out"; then
            why="not run on a $want: $(grep '^cpu' "$out")"
        elif [ -z "$ws" ] || [ "$ws" -gt 32768 ] || [ -z "$untiled" ] || [ "$untiled" -le "${sram:-0}" ]; then
            why="workspace ${ws:-?} bytes (at most 32768), untiled ${untiled:-?} (must exceed the SRAM, ${sram:-?})"
        elif ! grep '^frame' "$out" | cmp -s - "$host.frame"; then
            why="checksum ${sum:-missing} differs from the host's untiled $hsum"
        else
            echo "$what: strips of $strip columns, workspace $ws bytes (untiled $untiled > SRAM $sram): checksum $sum = host untiled"
            pass=$((pass + 1))
            continue
        fi
        echo "$what: FAILED: $why"
        fail=$((fail + 1))
    done
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
