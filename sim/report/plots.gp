# The report's plots (make report). Variables from the command line:
#   out   directory of the data files (pareto_*.dat, front_*.dat, levels.csv,
#         intensity.csv, written by run.sh and sweep.awk)
#   docs  directory the PNG files go to
#   sizes frame sizes of the sweep, "640x480 1280x720 1920x1080"
#   inputs the inputs of the stability curves
#   icpanel 1 when pareto_ic.dat has points (640x480 was swept)
set terminal pngcairo noenhanced size 1400,1000 font "DejaVu Sans,10"
set encoding utf8
set grid
set key top left font ",9"
# one colour per F, 16..20 (colour-blind safe), for the sweep panels
fcol(F) = word("#9400d3 #009e73 #e69f00 #56b4e9 #0072b2", F - 15)

# ---- error against run time, one panel per size, Pareto front marked -------
set output docs."/report_pareto.png"
set multiplot layout 2,2 title "Error against run time: MSE vs the float model (RGB888, 8-bit LSB²) against CPU time / cold memcpy of the frame\nlabels = level count N; colours = fraction bits F; line = Pareto front; ring = default (F 20, N 5)"
set logscale y
set format y "%.0e"
set xlabel "engine CPU time / cold memcpy CPU time (same rounds)"
set ylabel "MSE (LSB²)"
do for [s in sizes] {
    set title s
    d = out."/pareto_".s.".dat"
    f = out."/front_".s.".dat"
    plot for [F=16:20] d using ($3 == F ? $1 : NaN):2 with points pt 7 ps 1.1 lc rgb fcol(F) title sprintf("F %d", F), \
         d using 1:2:(sprintf("%d", $4)) with labels offset 0.9,0.5 font ",8" notitle, \
         f using 1:2 with lines lw 2 lc rgb "black" title "Pareto front", \
         d using ($6 > 0 ? $1 : NaN):2 with points pt 6 ps 3 lw 2 lc rgb "red" title "default"
}
# the fourth panel: the same at 640x480 against instructions (repeatable)
if (icpanel) {
set title "640x480 against instructions per pixel (callgrind, benchmark scene): repeatable"
set xlabel "instructions per output pixel, one bloom_process call"
d = out."/pareto_ic.dat"
f = out."/front_ic.dat"
plot for [F=16:20] d using ($3 == F ? $1 : NaN):2 with points pt 7 ps 1.1 lc rgb fcol(F) title sprintf("F %d", F), \
     d using 1:2:(sprintf("%d", $4)) with labels offset 0.9,0.5 font ",8" notitle, \
     f using 1:2 with lines lw 2 lc rgb "black" title "Pareto front", \
     d using ($6 > 0 ? $1 : NaN):2 with points pt 6 ps 3 lw 2 lc rgb "red" title "default"
}
unset multiplot

# ---- sample width: 32- against 16-bit rows (width.awk), 8-bit inputs --------
set output docs."/report_width.png"
set multiplot layout 2,2 title "Sample width: MSE vs the float model (8-bit inputs, RGB888) against cost\ndiscs = 32-bit rows, triangles = 16-bit; colours = fraction bits F; labels = level count N; line = Pareto front; ring = default (F 20, N 5, 32-bit)"
set xlabel "engine CPU time / cold memcpy CPU time (same rounds)"
do for [s in sizes] {
    set title s
    d = out."/widthp_".s.".dat"
    f = out."/widthf_".s.".dat"
    plot for [F=16:20] d using (($3 == F && $5 == 32) ? $1 : NaN):2 with points pt 7 ps 1.0 lc rgb fcol(F) title sprintf("F %d", F), \
         for [F=16:20] d using (($3 == F && $5 == 16) ? $1 : NaN):2 with points pt 9 ps 1.2 lc rgb fcol(F) notitle, \
         d using 1:2:(sprintf("%d", $4)) with labels offset 0.9,0.5 font ",8" notitle, \
         f using 1:2 with lines lw 2 lc rgb "black" title "Pareto front", \
         d using ($7 > 0 ? $1 : NaN):2 with points pt 6 ps 3 lw 2 lc rgb "red" title "default"
}
if (icpanel) {
set title "640x480 against instructions per pixel (callgrind): repeatable"
set xlabel "instructions per output pixel, one bloom_process call"
d = out."/widthp_ic.dat"
f = out."/widthf_ic.dat"
plot for [F=16:20] d using (($3 == F && $5 == 32) ? $1 : NaN):2 with points pt 7 ps 1.0 lc rgb fcol(F) title sprintf("F %d", F), \
     for [F=16:20] d using (($3 == F && $5 == 16) ? $1 : NaN):2 with points pt 9 ps 1.2 lc rgb fcol(F) notitle, \
     d using 1:2:(sprintf("%d", $4)) with labels offset 0.9,0.5 font ",8" notitle, \
     f using 1:2 with lines lw 2 lc rgb "black" title "Pareto front", \
     d using ($7 > 0 ? $1 : NaN):2 with points pt 6 ps 3 lw 2 lc rgb "red" title "default"
}
unset multiplot

# ---- the targets (targets.awk): F 20, N and the sample width ------------------
set output docs."/report_targets.png"
set multiplot layout 2,2 title "Error against cost on the targets (F 20): MSE vs the float model (8-bit inputs) against each CPU's cost per pixel\ndiscs = 32-bit rows, triangles = 16-bit; labels = level count N; line = Pareto front; ring = default (N 5, 32-bit); bars: Cortex-M cycle band"
do for [k in "x86 a64 m4 m7"] {
    d = out."/tgt_".k.".dat"
    f = out."/tgtf_".k.".dat"
    set title (k eq "x86" ? "x86-64, 640x480 RGB888 (callgrind)" : k eq "a64" ? "aarch64 NEON, 640x480 RGB888 (qemu-user plugin)" : \
               k eq "m4" ? "Cortex-M4, 320x240 RGB565 (unicorn, TRM timings)" : "Cortex-M7, 320x240 RGB565 (unicorn, TRM timings)")
    set xlabel ((k eq "m4" || k eq "m7") ? "estimated cycles per pixel (band)" : "instructions per pixel")
    plot d using ($4 == 32 ? $1 : NaN):2:7:8 with xerrorbars pt 7 ps 1.0 lc rgb "#0072b2" title "32-bit", \
         d using ($4 == 16 ? $1 : NaN):2:7:8 with xerrorbars pt 9 ps 1.2 lc rgb "#e69f00" title "16-bit", \
         d using 1:2:(sprintf("%d", $3)) with labels offset 0.9,0.5 font ",8" notitle, \
         f using 1:2 with lines lw 2 lc rgb "black" title "Pareto front", \
         d using ($6 > 0 ? $1 : NaN):2 with points pt 6 ps 3 lw 2 lc rgb "red" title "default"
}
unset multiplot

# ---- stability curves ----------------------------------------------------------
set datafile separator ","
set key top left font ",9"
set ylabel "error, 8-bit LSB"
do for [c in "levels intensity"] {
    set output docs."/report_".c.".png"
    col = 5
    if (c eq "levels") { set terminal pngcairo noenhanced size 1800,800 font "DejaVu Sans,10" }
    else { set terminal pngcairo noenhanced size 1400,800 font "DejaVu Sans,10" }
    set output docs."/report_".c.".png"
    set multiplot layout 1,(c eq "levels" ? 3 : 2) title (c eq "levels" ? \
        "Error against level count N (left, middle: 1024x768, threshold 0.6, intensity 1; L built stops at 9)\nsolid: F 20 (default build); dashed: F 16 (peaks of F 16 drawn 0.05 higher so that both show)" : \
        "Error against intensity (320x240, 5 levels, threshold 0.6; 10.0 is the largest allowed)\nsolid: F 20 (default build); dashed: F 16 (peaks of F 16 drawn 0.05 higher so that both show)")
    set xlabel (c eq "levels" ? "level count N (requested)" : "intensity (gamma space)")
    set title "mean |error| (LSB)"
    set logscale y
    set format y "%.0e"
    set yrange [1e-5:*]
    plot for [i=1:words(inputs)] out."/".c.".csv" using col:((strcol(2) eq word(inputs, i) && $1 == 20) ? ($8 > 0 ? $8 : 1e-7) : NaN) \
             with linespoints lc i pt 7 ps 0.6 dt 1 title word(inputs, i), \
         for [i=1:words(inputs)] out."/".c.".csv" using col:((strcol(2) eq word(inputs, i) && $1 == 16) ? ($8 > 0 ? $8 : 1e-7) : NaN) \
             with linespoints lc i pt 6 ps 0.6 dt 2 notitle
    set title "peak |error| (LSB)"
    unset logscale y
    set format y "%g"
    set yrange [0:*]
    plot for [i=1:words(inputs)] out."/".c.".csv" using col:((strcol(2) eq word(inputs, i) && $1 == 20) ? $7 : NaN) \
             with linespoints lc i pt 7 ps 0.6 dt 1 title word(inputs, i), \
         for [i=1:words(inputs)] out."/".c.".csv" using col:((strcol(2) eq word(inputs, i) && $1 == 16) ? $7 + 0.05 : NaN) \
             with linespoints lc i pt 6 ps 0.6 dt 2 notitle
    if (c eq "levels") {
        set title "the stiffest case: intensity 10, 1024x768, F 20\n(peak |error|; dashed: the bound from the measured dB; worst-case bound: table)"
        set xrange [1:9]
        set yrange [0:6]
        plot for [i=1:3] out."/stress_f20.csv" using ((strcol(2) eq word("point hdr-point scene-hubble", i)) ? $5 : NaN):7 \
                 with linespoints lc i pt 7 ps 0.8 title word("point hdr-point scene-hubble", i), \
             for [i=1:3] out."/stress_f20.csv" using ((strcol(2) eq word("point hdr-point scene-hubble", i)) ? $5 : NaN):($11 + 0.05 * i) \
                 with lines lc i dt 2 notitle
        set autoscale x
    }
    set autoscale y
    unset multiplot
}
