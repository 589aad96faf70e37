# Section 1 on the targets: cost on each CPU the engine is meant for,
# against the error of the same configuration, over the level count N and
# the sample width W (F 20: the fraction bits change no instruction count).
#   awk -F, -v out=DIR -f targets.awk ICOUNT.tsv TARGETS.csv ERR320.csv SWEEP.csv
# ICOUNT.tsv  "F L W Ir fnv", callgrind at 640x480 (x86-64 instructions)
# TARGETS.csv make target-cost's level sweep (sim/bench/targets.py): Cortex-M4
#             and M7 instructions and cycle bands at 320x240 RGB565, aarch64
#             (NEON) instructions at 640x480 RGB888
# ERR320.csv  report_sweep rows at 320x240 (errors only), SWEEP.csv at every
#             size: the error at each target's frame size, 8-bit inputs
#             pooled (16-bit samples refuse RGBQ16 input)
# The engine's output does not depend on the CPU (every build is bit-exact
# with the bit-true model), so an error measured here is the target's.
# Writes DIR/targets_table.md, DIR/tgt_K.dat, DIR/tgtf_K.dat for K in
# x86, a64, m4, m7 ("cost mse N W front default lo hi").
FNR == 1 { file++ }
file == 1 { split($0, q, /[ \t]+/); if (q[1] == 20) ic[q[2], q[3]] = q[4]; next }
file == 2 {
    if (FNR == 1) next
    k = $1 == "Cortex-M4" ? "m4" : $1 == "Cortex-M7" ? "m7" : $1 == "aarch64" ? "a64" : ""
    if (k == "") next
    fr[k] = $4; clk[k] = $8
    ipx[k, $3, $2] = $5
    if ($6 != "") { lo[k, $3, $2] = $6; hi[k, $3, $2] = $7 }
    have[k, $3, $2] = 1
    next
}
FNR == 1 || $7 != "RGB888" || $1 != 20 { next }
{
    W = $24 == "" ? 32 : $24
    e = $2 "x" $3 SUBSEP $4 SUBSEP W
    if (file == 4 && (e in from3)) next # 320x240 from ERR320 only
    if (file == 3) from3[e] = 1
    cnt[e]++; msek[e] += $17; exk[e] += $19; sgk[e] += $21; abk[e] += $22; blk[e] += $23
    if ($15 > pk[e]) pk[e] = $15
}
function slug(k) { return k == "x86" ? "x86-64 (callgrind)" : k == "a64" ? "aarch64 (NEON, qemu-user)" : \
                          k == "m4" ? "Cortex-M4" : "Cortex-M7" }
END {
    fr["x86"] = "640x480"
    for (l = 1; l <= 16; l++) for (w = 16; w <= 32; w += 16)
        if ((l, w) in ic) { ipx["x86", l, w] = ic[l, w] / 307200; have["x86", l, w] = 1 }
    split("x86 a64 m4 m7", K, " ")
    t = out "/targets_table.md"
    for (kk = 1; kk <= 4; kk++) {
        k = K[kk]; n = 0
        if (!(k in fr)) continue
        for (l = 1; l <= 16; l++) for (w = 32; w >= 16; w -= 16) {
            e = fr[k] SUBSEP l SUBSEP w
            if (!((k, l, w) in have) || !(e in cnt)) continue
            n++; N[n] = l; Wd[n] = w; E[n] = e
            cyc = (k, l, w) in lo
            c[n] = cyc ? (lo[k, l, w] + hi[k, l, w]) / 2 : ipx[k, l, w]
            m[n] = msek[e] / cnt[e] > 0 ? msek[e] / cnt[e] : 1e-7
        }
        if (!n) continue
        dat = out "/tgt_" k ".dat"; ff = out "/tgtf_" k ".dat"
        print "# cost mse N W front default lo hi" > dat
        cyc = (k, 5, 32) in lo
        printf "\n**%s**, %s (%s):\n\n", slug(k), fr[k], cyc ? "estimated cycles per pixel, the middle " \
               "of the band; frames/s at " clk[k] " MHz from the band" : "instructions per pixel" > t
        printf "| N | samples | %s | %s | MSE | peak LSB | exact %% | signed mean LSB | above / below | " \
               "Pareto: all / within N |\n", cyc ? "cycles / px (band)" : "instructions / px", cyc ? "frames / s" : \
               "x the 32-bit N 5" > t
        print "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|" > t
        nf = 0; base = 0; split(fr[k], wh, "x"); px = wh[1] * wh[2]
        for (i = 1; i <= n; i++) if (N[i] == 5 && Wd[i] == 32) base = c[i]
        for (i = 1; i <= n; i++) {
            dom = 0; domn = 0
            for (j = 1; j <= n; j++)
                if (j != i && c[j] <= c[i] && m[j] <= m[i] && (c[j] < c[i] || m[j] < m[i])) {
                    dom = 1
                    if (N[j] == N[i]) domn = 1
                }
            e = E[i]; d = N[i] == 5 && Wd[i] == 32
            printf "%.3f %.4g %d %d %d %d %s %s\n", c[i], m[i], N[i], Wd[i], !dom, d,
                cyc ? lo[k, N[i], Wd[i]] : c[i], cyc ? hi[k, N[i], Wd[i]] : c[i] > dat
            if (!dom) { fx[++nf] = c[i]; fy[nf] = m[i]; fl[nf] = N[i] "/" Wd[i] }
            if (cyc) {
                col = sprintf("%.1f (%.1f–%.1f) | %.1f–%.1f", c[i], lo[k, N[i], Wd[i]], hi[k, N[i], Wd[i]],
                              clk[k] * 1e6 / (hi[k, N[i], Wd[i]] * px), clk[k] * 1e6 / (lo[k, N[i], Wd[i]] * px))
            } else
                col = sprintf("%.1f | %s", c[i], base ? sprintf("%.2f", c[i] / base) : "-")
            printf "| %d%s | %d-bit | %s | %.6f | %d | %.3f | %+.5f | %d / %d | %s |\n", N[i],
                d ? " (default)" : "", Wd[i], col, msek[e] / cnt[e], pk[e], exk[e] / cnt[e], sgk[e] / cnt[e],
                abk[e], blk[e], (dom ? "-" : "**front**") " / " (domn ? "-" : "front") > t
        }
        for (a = 2; a <= nf; a++) for (b = a; b > 1 && fx[b - 1] > fx[b]; b--) {
            x = fx[b]; fx[b] = fx[b - 1]; fx[b - 1] = x; x = fy[b]; fy[b] = fy[b - 1]; fy[b - 1] = x
            x = fl[b]; fl[b] = fl[b - 1]; fl[b - 1] = x
        }
        print "# cost mse N/W" > ff
        for (a = 1; a <= nf; a++) print fx[a], fy[a], fl[a] > ff
        close(dat); close(ff)
    }
    close(t)
}
