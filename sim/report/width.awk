# Section 1's sample-width comparison: 32-bit against 16-bit row samples
# (cfg.sample_bits), with the fraction bits F and the level count N.
#   awk -F, -v out=DIR -f width.awk ICOUNT.tsv SWEEP.csv
# ICOUNT.tsv: "F L W Ir fnv" (callgrind, 640x480, the benchmark scene).
# SWEEP.csv: report_sweep's rows (column 24: the sample width). Only the
# 8-bit inputs are pooled here: 16-bit samples refuse RGBQ16 input, and
# both widths must be measured on the same samples to be compared.
# Writes DIR/width_table.md, DIR/width_default.md, DIR/widthp_WxH.dat and
# DIR/widthf_WxH.dat (time), DIR/widthp_ic.dat and DIR/widthf_ic.dat
# (instructions): "x mse F N W front default".
FNR == 1 { file++ }
file == 1 { split($0, q, /[ \t]+/); ic[q[1], q[2], q[3]] = q[4]; next }
FNR == 1 || $7 != "RGB888" { next }
{
    W = $24 == "" ? 32 : $24
    k = $1 SUBSEP $2 "x" $3 SUBSEP $4 SUBSEP W
    if (!(k in cnt)) { keys[++nk] = k; kF[k] = $1; kS[k] = $2 "x" $3; kL[k] = $4; kW[k] = W }
    cnt[k]++; xck[k] += $14; xwk[k] += $13; msek[k] += $17; exk[k] += $19; wsk[k] = $20
    if ($15 > pkk[k]) pkk[k] = $15
    sgk[k] += $21; abk[k] += $22; blk[k] += $23
    if (!(($2 "x" $3) in seen)) { seen[$2 "x" $3] = 1; sizes[++ns] = $2 "x" $3 }
}
# dominated within its size (and N if sameL) by cost c[] and mse[]
function dominated(i, sameL, c,    j) {
    for (j = 1; j <= n; j++) {
        if (j == i || S[j] != S[i] || (sameL && L[j] != L[i]) || !(j in c)) continue
        if (c[j] <= c[i] && mse[j] <= mse[i] && (c[j] < c[i] || mse[j] < mse[i])) return 1
    }
    return 0
}
function isdef(i) { return F[i] == 20 && L[i] == 5 && Wd[i] == 32 }
# plot data and front of the points of size s that have a cost in c[]
function plot(s, c, dat, fr,    i, a, b, t, nf, fx, fy, fl, m, lst) {
    print "# x mse F N W front default" > dat
    nf = 0
    for (i = 1; i <= n; i++) {
        if (S[i] != s || !(i in c)) continue
        m = mse[i] > 0 ? mse[i] : 1e-7
        g = !dominated(i, 0, c)
        printf "%.4f %.4g %d %d %d %d %d\n", c[i], m, F[i], L[i], Wd[i], g, isdef(i) > dat
        if (g) { fx[++nf] = c[i]; fy[nf] = m; fl[nf] = F[i] "/" L[i] "/" Wd[i] }
    }
    for (a = 2; a <= nf; a++) for (b = a; b > 1 && fx[b - 1] > fx[b]; b--) {
        t = fx[b]; fx[b] = fx[b - 1]; fx[b - 1] = t; t = fy[b]; fy[b] = fy[b - 1]; fy[b - 1] = t
        t = fl[b]; fl[b] = fl[b - 1]; fl[b - 1] = t
    }
    print "# x mse F/N/W" > fr
    lst = ""
    for (a = 1; a <= nf; a++) { print fx[a], fy[a], fl[a] > fr; lst = lst (a > 1 ? ", " : "") fl[a] }
    close(dat); close(fr)
    return lst
}
END {
    for (j = 1; j <= nk; j++) {
        k = keys[j]; c = cnt[k]; n++
        F[n] = kF[k]; S[n] = kS[k]; L[n] = kL[k]; Wd[n] = kW[k]
        xc[n] = xck[k] / c; xw[n] = xwk[k] / c; mse[n] = msek[k] / c; ex[n] = exk[k] / c
        pk[n] = pkk[k]; ws[n] = wsk[k]; sg[n] = sgk[k] / c; ab[n] = abk[k]; bl[n] = blk[k]
        id[S[n], F[n], L[n], Wd[n]] = n
        if (S[n] == "640x480" && (F[n], L[n], Wd[n]) in ic) xi[n] = ic[F[n], L[n], Wd[n]] / 307200
    }
    for (s = 1; s <= ns; s++)
        front[sizes[s]] = plot(sizes[s], xc, out "/widthp_" sizes[s] ".dat", out "/widthf_" sizes[s] ".dat")
    icfront = plot("640x480", xi, out "/widthp_ic.dat", out "/widthf_ic.dat")
    t = out "/width_table.md"
    print "| frame | N | samples | x cold memcpy, CPU (wall) | instr/px at 640x480 | peak LSB | exact % | " \
          "signed mean LSB | above / below | MSE | workspace bytes | Pareto by time: all / within N |" > t
    print "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|" > t
    for (s = 1; s <= ns; s++) for (l = 1; l <= 16; l++) for (w = 32; w >= 16; w -= 16) {
        if (!((sizes[s], 20, l, w) in id)) continue
        i = id[sizes[s], 20, l, w]
        printf "| %s | %d | %d-bit | %.2f (%.2f) | %s | %d | %.3f | %+.5f | %d / %d | %.6f | %d | %s / %s |\n",
            S[i], L[i], Wd[i], xc[i], xw[i], (i in xi) ? sprintf("%.1f", xi[i]) : "-", pk[i], ex[i], sg[i],
            ab[i], bl[i], mse[i], ws[i], dominated(i, 0, xc) ? "-" : "**front**",
            dominated(i, 1, xc) ? "-" : "front" > t
    }
    close(t)
    d = out "/width_default.md"
    for (s = 1; s <= ns; s++) {
        if (!((sizes[s], 20, 5, 32) in id) || !((sizes[s], 20, 5, 16) in id)) continue
        a = id[sizes[s], 20, 5, 32]; b = id[sizes[s], 20, 5, 16]
        printf "- **%s**, F 20, N 5: 16-bit samples run at %.2fx the cold memcpy against %.2fx for 32-bit " \
               "(%.2f times the time); MSE %.6f against %.6f, peak %d against %d LSB, %.3f %% against " \
               "%.3f %% exact, signed mean %+.5f against %+.5f LSB; workspace %d against %d bytes " \
               "(%.2fx). The 32-bit default is %s the front of all configurations by time, the " \
               "16-bit one %s it (front: %s).\n", sizes[s], xc[b], xc[a], xc[b] / xc[a], mse[b], mse[a],
               pk[b], pk[a], ex[b], ex[a], sg[b], sg[a], ws[b], ws[a], ws[b] / ws[a],
               dominated(a, 0, xc) ? "not on" : "**on**", dominated(b, 0, xc) ? "not on" : "**on**",
               front[sizes[s]] > d
    }
    if (("640x480", 20, 5, 32) in id && ("640x480", 20, 5, 16) in id) {
        a = id["640x480", 20, 5, 32]; b = id["640x480", 20, 5, 16]
        if ((a in xi) && (b in xi))
            printf "- Instructions (callgrind, 640x480, N 5, F 20): %.1f per pixel with 16-bit samples " \
                   "against %.1f (%.2fx). By instructions the front is %s.\n", xi[b], xi[a], xi[b] / xi[a],
                   icfront > d
    }
    close(d)
}
