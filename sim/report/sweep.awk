# The error-against-run-time table, the Pareto fronts and the plot data, from
# the report_sweep CSV (one row per F, size, N and input; pooled here).
#   awk -F, -v out=DIR -f sweep.awk ICOUNT.tsv SWEEP.csv
# ICOUNT.tsv: "F L W Ir fnv" of one bloom_process at 640x480 (callgrind),
# W the row sample width. This file takes the 32-bit rows only (all six
# inputs); width.awk compares the widths.
# Writes DIR/sweep_table.md, DIR/sweep_default.md, DIR/pareto_WxH.dat,
# DIR/front_WxH.dat. x = CPU-time ratio to the cold memcpy of the same rounds;
# y = MSE in 8-bit LSB^2 against the float model. CSV fields 21-23: signed
# mean (engine - model), samples above and below (engine > / < model).
FNR == 1 { file++ }
file == 1 { split($0, q, /[ \t]+/); if (q[3] == 32) ic[q[1], q[2]] = q[4]; next }
FNR == 1 { next }
$24 == 16 { next }
{   # pool the inputs of one (F, size, N): equal sample counts, so plain means
    k = $1 SUBSEP $2 "x" $3 SUBSEP $4
    if (!(k in cnt)) { keys[++nk] = k; kF[k] = $1; kS[k] = $2 "x" $3; kL[k] = $4 }
    cnt[k]++; LBk[k] = $5; msk[k] += $10; xck[k] += $14; xwk[k] += $13
    if ($15 > pkk[k]) pkk[k] = $15
    meank[k] += $16; msek[k] += $17; exk[k] += $19; wsk[k] = $20
    sgk[k] += $21; abk[k] += $22; blk[k] += $23
    sz = $2 "x" $3
    if (!(sz in seen)) { seen[sz] = 1; sizes[++ns] = sz }
}
function pool(    j, k, c) {
    for (j = 1; j <= nk; j++) {
        k = keys[j]; c = cnt[k]; n++
        F[n] = kF[k]; S[n] = kS[k]; L[n] = kL[k]; LB[n] = LBk[k]
        ms[n] = msk[k] / c; xc[n] = xck[k] / c; xw[n] = xwk[k] / c; pk[n] = pkk[k]
        mean[n] = meank[k] / c; mse[n] = msek[k] / c; ex[n] = exk[k] / c; ws[n] = wsk[k]
        sg[n] = sgk[k] / c; ab[n] = abk[k]; bl[n] = blk[k]
        psnr[n] = mse[n] > 0 ? sprintf("%.2f", 10 * log(255 * 255 / mse[n]) / log(10)) : "inf"
        cntS[S[n]]++
    }
}
# Dominated within its size (and N if sameL) by cost x (xc, or xi: instructions).
function dominated(i, sameL, useic,    j, a, b) {
    for (j = 1; j <= n; j++) {
        if (j == i || S[j] != S[i] || (sameL && L[j] != L[i])) continue
        a = useic ? xi[j] : xc[j]; b = useic ? xi[i] : xc[i]
        if (a <= b && mse[j] <= mse[i] && (a < b || mse[j] < mse[i])) return 1
    }
    return 0
}
END {
    pool()
    t = out "/sweep_table.md"
    print "| frame | F | N (L) | engine ms, CPU | x cold memcpy, CPU (wall) | instr/px at 640x480 | " \
          "peak LSB | mean \\|e\\| LSB | MSE | PSNR dB | exact % | signed mean LSB | above / below | " \
          "workspace bytes | Pareto: all / within N |" > t
    print "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|" > t
    for (s = 1; s <= ns; s++) {
        dat = out "/pareto_" sizes[s] ".dat"; fr = out "/front_" sizes[s] ".dat"
        print "# x_cpu mse F L front default" > dat
        nf = 0
        for (l = 1; l <= 16; l++) for (f = 16; f <= 20; f++) for (i = 1; i <= n; i++) {
            if (S[i] != sizes[s] || L[i] != l || F[i] != f) continue
            g = !dominated(i, 0, 0); w = !dominated(i, 1, 0)
            front[i] = g; lfront[i] = w
            ipx = (sizes[s] == "640x480" && (F[i], L[i]) in ic) ? sprintf("%.1f", ic[F[i], L[i]] / 307200) : "-"
            printf "| %s | %d | %d (%d) | %.3f | %.2f (%.2f) | %s | %d | %.5f | %.6f | %s | %.3f | %+.5f | " \
                "%d / %d | %d | %s%s |\n",
                sizes[s], F[i], L[i], LB[i], ms[i], xc[i], xw[i], ipx, pk[i], mean[i], mse[i], psnr[i],
                ex[i], sg[i], ab[i], bl[i], ws[i], g ? "**front**" : "-", w ? " / front" : " / -" > t
            printf "%.4f %.4g %d %d %d %d\n", xc[i], (mse[i] > 0 ? mse[i] : 1e-7), F[i], L[i], g,
                (F[i] == 20 && L[i] == 5) > dat
            if (g) { fx[++nf] = xc[i]; fy[nf] = (mse[i] > 0 ? mse[i] : 1e-7); fl[nf] = F[i] "/" L[i] }
            if (F[i] == 20 && L[i] == 5) def[s] = i
            if (F[i] == 16 && L[i] == 5) f16[s] = i
        }
        for (a = 2; a <= nf; a++) for (b = a; b > 1 && fx[b - 1] > fx[b]; b--) {
            tx = fx[b]; fx[b] = fx[b - 1]; fx[b - 1] = tx; ty = fy[b]; fy[b] = fy[b - 1]; fy[b - 1] = ty
            tl = fl[b]; fl[b] = fl[b - 1]; fl[b - 1] = tl
        }
        print "# x_cpu mse F/L" > fr
        frl = ""
        for (a = 1; a <= nf; a++) { print fx[a], fy[a], fl[a] > fr; frl = frl (a > 1 ? ", " : "") "F" fl[a] }
        frontlist[s] = frl
        close(dat); close(fr)
    }
    # 640x480 by instruction count (callgrind: repeatable), the plot's fourth panel
    dat = out "/pareto_ic.dat"; fr = out "/front_ic.dat"
    print "# instr_per_px mse F L front default" > dat
    nf = 0; frl = ""
    for (i = 1; i <= n; i++) if (S[i] == "640x480" && (F[i], L[i]) in ic) xi[i] = ic[F[i], L[i]] / 307200
    for (i = 1; i <= n; i++) if (i in xi) {
        g = !dominated(i, 0, 1)
        printf "%.3f %.4g %d %d %d %d\n", xi[i], (mse[i] > 0 ? mse[i] : 1e-7), F[i], L[i], g,
            (F[i] == 20 && L[i] == 5) > dat
        if (g) { fx[++nf] = xi[i]; fy[nf] = (mse[i] > 0 ? mse[i] : 1e-7); fl[nf] = F[i] "/" L[i] }
        if (F[i] == 20 && L[i] == 5) icfront = g
        if (F[i] == 20 && L[i] == 5) iclfront = !dominated(i, 1, 1)
    }
    for (a = 2; a <= nf; a++) for (b = a; b > 1 && fx[b - 1] > fx[b]; b--) {
        tx = fx[b]; fx[b] = fx[b - 1]; fx[b - 1] = tx; ty = fy[b]; fy[b] = fy[b - 1]; fy[b - 1] = ty
        tl = fl[b]; fl[b] = fl[b - 1]; fl[b - 1] = tl
    }
    print "# instr_per_px mse F/L" > fr
    for (a = 1; a <= nf; a++) { print fx[a], fy[a], fl[a] > fr; frl = frl (a > 1 ? ", " : "") "F" fl[a] }
    close(dat); close(fr)
    d = out "/sweep_default.md"
    for (s = 1; s <= ns; s++) {
        i = def[s]; j = f16[s]
        if (!i) continue
        # the most accurate F at N = 5, and the spread of the five F's times
        hi = i; lo = i; top = i
        for (k = 1; k <= n; k++) if (S[k] == sizes[s] && L[k] == 5) {
            if (mse[k] < mse[hi]) hi = k
            if (xc[k] < xc[lo]) lo = k
            if (xc[k] > xc[top]) top = k
        }
        printf "- **%s**: the default (F 20, N 5) runs at %.2fx the cold memcpy (CPU; %.2fx wall), " \
               "MSE %.6f, peak %d LSB, %.3f %% exact, signed mean %+.5f LSB (%d above, %d below); " \
               "%s the Pareto front of all %d configurations " \
               "(front: %s) and %s the front of the five F at N = 5 (lowest MSE at N = 5: F %d). " \
               "The five F at N = 5 measured %.2fx to %.2fx, a %.0f %% spread for the same instructions " \
               "(below): that spread is this run's timing noise.", sizes[s], xc[i], xw[i], mse[i], pk[i],
               ex[i], sg[i], ab[i], bl[i], front[i] ? "**on**" : "not on", cntS[sizes[s]], frontlist[s],
               lfront[i] ? "**on**" : "not on", F[hi], xc[lo], xc[top], 100 * (xc[top] / xc[lo] - 1) > d
        split(sizes[s], wh, "x")
        printf " Workspace %d bytes, 1/%.0f of one RGB888 frame.", ws[i], wh[1] * wh[2] * 3 / ws[i] > d
        if (j) printf " F 16 at N 5: MSE %.6f (%.1fx the default's), time %.2fx.", mse[j],
                      (mse[i] > 0 ? mse[j] / mse[i] : 0), xc[j] > d
        printf "\n" > d
    }
    lo = ""; hi = ""
    for (f = 16; f <= 20; f++) if ((f, 5) in ic) {
        if (lo == "" || ic[f, 5] + 0 < lo + 0) lo = ic[f, 5]
        if (hi == "" || ic[f, 5] + 0 > hi + 0) hi = ic[f, 5]
    }
    if (lo != "")
        printf "- Instructions (callgrind, one 640x480 frame of the benchmark scene, N 5): the five F " \
               "take %d to %d, a %.3f %% spread: the fraction bits change shifts and table contents, " \
               "not the work per pixel, so on this 64-bit host they buy no speed.\n", lo, hi,
               100 * (hi / lo - 1) > d
    if (nf)
        printf "- By instructions per pixel instead of time (640x480, the repeatable figure; " \
               "fourth panel of the plot): the front is %s; the default is %s it, and %s the " \
               "front of its N.\n", frl, icfront ? "**on**" : "not on", iclfront ? "**on**" : "not on" > d
}
