#!/bin/sh
# Synthesis of the FPGA twin with the open tools from Debian.
#
#   synth.sh table OUTDIR README   (make fpga) the resource and Fmax table:
#       every build below through yosys (and nextpnr for the iCE40s), the
#       table written into README between its two table markers.
set -u
mode=$1
out=$2
inc=$(dirname "$out")
mkdir -p "$out"
# the RTL's files: FPGA_RTL of port/fpga/fpga.mk, the one list of them
RTL=${FPGA_RTL:?"run through make (FPGA_RTL lists the RTL)"}
# json_num FILE KEY: the first number after "KEY" in a nextpnr report
json_num() { tr -d '\n ' <"$1" | grep -o "\"$2\":{[^}]*}" | head -1; }
# stat_count LOG REGEX: the cells whose type matches, in the log's last stat
stat_count() {
    awk -v c="^($2)\$" '/^=== / { n = 0 } $1 ~ c { n += $2 } END { print n + 0 }' "$1"
}

# pnr NAME DEVICE PACKAGE JSON: nextpnr-ice40 at 25 MHz; sets lc, lc_max, fmax
pnr() {
    lc="" lc_max="" fmax=""
    if nextpnr-ice40 "--$2" --package "$3" --json "$4" --freq 25 --report "$out/$1.report.json" \
        --timing-allow-fail --asc "$out/$1.asc" >"$out/$1.pnr.log" 2>&1; then
        u=$(json_num "$out/$1.report.json" ICESTORM_LC)
        lc=$(echo "$u" | grep -o '"used":[0-9]*' | cut -d: -f2)
        lc_max=$(echo "$u" | grep -o '"available":[0-9]*' | cut -d: -f2)
        fmax=$(tr -d '\n ' <"$out/$1.report.json" | grep -o '"achieved":[0-9.]*' | head -1 | cut -d: -f2)
        return 0
    fi
    return 1
}

[ "$mode" = table ] || { echo "usage: synth.sh table OUTDIR README"; exit 2; }
readme=$3
tab=$out/table.md
ws_of() { # W H L FMT888: the C engine's workspace for the same configuration, bytes
    "$inc/gen_vectors" --workspace "$1" "$2" "$3" "$4"
}
mem_bits() { # params...: the memory bits the RTL infers (its arrays, before mapping)
    yosys -q -l "$out/mem.log" -p "read_verilog -DSYNTHESIS -I$inc $RTL; chparam $* bloom_top;
        hierarchy -top bloom_top; flatten; stat" >/dev/null 2>&1
    awk '/Number of memory bits/ { n = $NF } END { print n + 0 }' "$out/mem.log"
}
{
    echo "| build | device | logic | flip-flops | block RAM | DSP | Fmax | on-chip memory / C workspace |"
    echo "|---|---|---|---|---|---|---|---|"
} >"$tab"
# name, device, yosys pass, parameters (W H L FMT888 KNEE_II)
while read -r name dev W H L F II; do
    [ -z "$name" ] && continue
    p="-set WMAX $W -set HMAX $H -set LMAX $L -set FMT888 $F -set KNEE_II $II"
    bits=$(mem_bits "$p")
    ws=$(ws_of "$W" "$H" "$L" "$F")
    memcol="$(((bits + 8191) / 8192)) KB / $(((ws + 1023) / 1024)) KB"
    fmt=$([ "$F" = 1 ] && echo RGB888 || echo RGB565)
    label="${W}x$H $fmt, $L level$([ "$L" = 1 ] || echo s), knee every $II clock$([ "$II" = 1 ] || echo s)"
    log=$out/$name.yosys.log
    case $dev in
    up5k | hx8k)
        flags=$([ "$dev" = up5k ] && echo "-dsp -spram" || echo "")
        # shellcheck disable=SC2086
        yosys -q -l "$log" -p "read_verilog -DSYNTHESIS -I$inc $RTL port/fpga/syn/bloom_board.v;
            chparam $p bloom_board;
            synth_ice40 $flags -top bloom_board -json $out/$name.json; stat" >/dev/null 2>&1
        luts=$(stat_count "$log" SB_LUT4)
        ffs=$(stat_count "$log" 'SB_DFF[A-Z]*')
        ebr=$(stat_count "$log" SB_RAM40_4K)
        spram=$(stat_count "$log" SB_SPRAM256KA)
        dsp=$(stat_count "$log" SB_MAC16)
        if [ "$dev" = up5k ]; then cap="5280 LUT, 30 EBR, 4 SPRAM, 8 MAC16"; else cap="7680 LUT, 32 EBR"; fi
        if pnr "$name" "$dev" "$([ "$dev" = up5k ] && echo sg48 || echo ct256)" "$out/$name.json"; then
            fm="$fmax MHz"
        else
            fm="does not fit ($cap)"
        fi
        echo "| $label | iCE40 $(echo "$dev" | tr a-z A-Z) | $luts LUT4 | $ffs | $ebr EBR, $spram SPRAM | $dsp MAC16 | $fm | $memcol |" >>"$tab"
        ;;
    xc7)
        yosys -q -l "$log" -p "read_verilog -DSYNTHESIS -I$inc $RTL; chparam $p bloom_top;
            synth_xilinx -family xc7 -top bloom_top; stat" >/dev/null 2>&1
        luts=$(stat_count "$log" 'LUT[1-6]')
        ffs=$(stat_count "$log" 'FD[CPRSE]*')
        b36=$(stat_count "$log" RAMB36E1)
        b18=$(stat_count "$log" RAMB18E1)
        dsp=$(stat_count "$log" DSP48E1)
        echo "| $label | Xilinx 7-series (estimate) | $luts LUT | $ffs | $b36 RAMB36 + $b18 RAMB18 | $dsp DSP48E1 | (no place and route) | $memcol |" >>"$tab"
        ;;
    ecp5)
        yosys -q -l "$log" -p "read_verilog -DSYNTHESIS -I$inc $RTL; chparam $p bloom_top;
            synth_ecp5 -top bloom_top; stat" >/dev/null 2>&1
        luts=$(stat_count "$log" LUT4)
        ffs=$(stat_count "$log" TRELLIS_FF)
        bram=$(stat_count "$log" DP16KD)
        dsp=$(stat_count "$log" MULT18X18D)
        echo "| $label | Lattice ECP5 (estimate) | $luts LUT4 | $ffs | $bram DP16KD | $dsp MULT18X18D | (no place and route) | $memcol |" >>"$tab"
        ;;
    esac
    echo "$name: $(tail -1 "$tab")"
done <<BUILDS
up5k_qvga up5k 320 240 5 0 3
up5k_small up5k 64 48 1 0 3
hx8k_small hx8k 64 48 1 0 3
xc7_hd3 xc7 1920 1080 3 1 1
xc7_hd5 xc7 1920 1080 5 1 1
ecp5_hd3 ecp5 1920 1080 3 1 1
ecp5_hd5 ecp5 1920 1080 5 1 1
BUILDS
# into README, between the markers
awk -v tab="$tab" '
    /<!-- fpga-table:begin -->/ { print; while ((getline l < tab) > 0) print l; skip = 1; next }
    /<!-- fpga-table:end -->/ { skip = 0 }
    !skip { print }' "$readme" >"$readme.tmp" && mv "$readme.tmp" "$readme"
echo "table written into $readme"
