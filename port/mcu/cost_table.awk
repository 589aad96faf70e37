# FIGURES.md's cost table (make figures) from sim/docs/targets.csv (make
# target-cost COST_WIDTHS='32 16'): Cortex-M4 and M7 at 320x240 RGB565,
# default preset, per level count and sample width: instructions, the cycle
# band and the frames per second at the CSV's clock.
#   awk -F, -f cost_table.awk sim/docs/targets.csv
NR == 1 { next }
$1 ~ /^Cortex-M/ {
    split($4, wh, "x"); px = wh[1] * wh[2]
    k = $1 SUBSEP $3 SUBSEP $2
    ins[k] = $5; lo[k] = $6; hi[k] = $7; clk[$1] = $8; fr = $4
    if (!($1 in seen)) { seen[$1] = 1; cpu[++nc] = $1 }
    if ($3 > maxl) maxl = $3
}
END {
    if (!nc) { print "(no Cortex-M rows in targets.csv: run make target-cost COST_WIDTHS='32 16')"; exit }
    print "| CPU | levels | samples | instructions / px | cycles / px (band) | frames / s (band) |"
    print "|---|---:|---:|---:|---:|---:|"
    for (c = 1; c <= nc; c++) for (l = 1; l <= maxl; l++) for (w = 32; w >= 16; w -= 16) {
        k = cpu[c] SUBSEP l SUBSEP w
        if (!(k in ins)) continue
        printf "| %s | %d%s | %d-bit | %.1f | %.0f–%.0f | %.1f–%.1f at %d MHz |\n", cpu[c], l,
            l == 5 ? " (default)" : "", w, ins[k], lo[k], hi[k], clk[cpu[c]] * 1e6 / (hi[k] * px),
            clk[cpu[c]] * 1e6 / (lo[k] * px), clk[cpu[c]]
    }
}
