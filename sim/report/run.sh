#!/bin/sh
# make report (issue 3, sections 2-4): runs the report tools and writes
# DOCS/report.md, DOCS/report_*.png and DOCS/report_*.csv.
#   sh sim/report/run.sh BUILD DOCS
# BUILD holds f16..f20/{report_sweep,report_icount}, f16/report_stab,
# f20/report_stab, f20/report_skip and f20/report_tiles (sim/report.mk
# builds them).
# Phase 1, nothing timed, both cores: float-model references and the sweep's
# instruction counts | the stability matrix and the skip instruction counts.
# Phase 2, timed, one process at a time: the sweep per F, the skip timings,
# the tilings (section 4).
# Environment knobs: REPORT_SIZES, REPORT_RUNS, REPORT_RUNS_BIG, REPORT_DATA,
# REPORT_CC, REPORT_FLAGS (for the text only).
set -e
bld=$1
docs=$2
here=$(dirname "$0")
data=${REPORT_DATA:-tests/data}
sizes=${REPORT_SIZES:-640x480,1280x720,1920x1080}
runs=${REPORT_RUNS:-7}
runs_big=${REPORT_RUNS_BIG:-5}
inputs="rocket hubble studio hall scene scene-hubble"
out=$bld/out
ref=$bld/ref
rm -rf "$out" "$ref"
mkdir -p "$out" "$ref" "$docs"
t0=$(date +%s)
date_utc=$(date -u '+%Y-%m-%d %H:%M UTC')
load0=$(cut -d' ' -f1-3 /proc/loadavg)
cpu=$(grep -m1 '^model name' /proc/cpuinfo | sed 's/^[^:]*: *//')
fam=$(grep -m1 '^cpu family' /proc/cpuinfo | sed 's/^[^:]*: *//')
mod=$(grep -m1 '^model[[:space:]]*:' /proc/cpuinfo | sed 's/^[^:]*: *//')
[ -n "$fam" ] && [ -n "$mod" ] && cpu="$cpu (family $fam, model $mod; /proc/cpuinfo)"
ncpu=$(nproc)

# One bloom_process under callgrind: prints "Ir checksum".
cg() {
    tag=$1
    shift
    valgrind --tool=callgrind --callgrind-out-file="$out/cg.$tag.out" \
        --toggle-collect=bloom_process "$@" > "$out/cg.$tag.stdout" 2> "$out/cg.$tag.log" ||
        { cat "$out/cg.$tag.log" >&2; return 1; }
    ir=$(sed -n 's/.*Collected : *\([0-9][0-9]*\).*/\1/p' "$out/cg.$tag.log")
    echo "$ir $(sed 's/.* fnv1a //' "$out/cg.$tag.stdout")"
}

job_a() {
    "$bld/f20/report_sweep" --ref "$ref" --model-only --data "$data" --sizes "$sizes" \
        --inputs "$(echo $inputs | tr ' ' ,)"
    for f in 16 17 18 19 20; do
        for l in 1 2 3 4 5 6 7 8; do
            echo "$f $l 32 $(cg a "$bld/f$f/report_icount" "$data" scene 640 480 $l 0.6)"
            echo "$f $l 16 $(cg a "$bld/f$f/report_icount" "$data" scene 640 480 $l 0.6 s16)"
        done
    done > "$out/sweep_icount.tsv"
    # the error at the Cortex-M frame size (320x240) for the targets'
    # section: errors only (one untimed round), F 20, both widths
    "$bld/f20/report_sweep" --ref "$ref" --csv "$out/err320.csv" --data "$data" --sizes 320x240 \
        --levels 1-7 --inputs "$(echo $inputs | tr ' ' ,)" --runs 1 --warmup 0 --ring-mb 16 > "$out/err320.log"
}

job_b() {
    "$bld/f20/report_stab" --out "$out" --data "$data"
    "$bld/f16/report_stab" --out "$out" --data "$data" --curves-only
    for s in 1920x1080 640x480; do
        for sc in dark sparse scene grid; do
            echo "$s $sc skip $(cg b "$bld/f20/report_icount" "$data" $sc ${s%x*} ${s#*x} 5 1.0)"
            echo "$s $sc noskip $(cg b "$bld/f20/report_icount" "$data" $sc ${s%x*} ${s#*x} 5 1.0 noskip)"
        done
    done > "$out/skip_icount.tsv"
    cg b "$bld/f20/report_icount" "$data" scene 640 480 5 1.0 > "$out/repeat.txt"
    # section 4: every tiling of sim/bench/tile_strips.h, one frame each
    for l in 3 5 7; do
        for s in 0 64 128 256 480 512 960; do
            echo "$l $s $(cg b "$bld/f20/report_tiles" --once $l $s --data "$data")"
        done
    done > "$out/tiles_icount.tsv"
}

echo "report: phase 1 (untimed, 2 jobs): float-model references, stability matrix, callgrind counts"
job_a > "$out/job_a.log" 2>&1 &
pa=$!
job_b > "$out/job_b.log" 2>&1 &
pb=$!
ok=0
wait $pa || ok=1
wait $pb || ok=$((ok + 2))
if [ $ok != 0 ]; then
    tail -n 20 "$out/job_a.log" "$out/job_b.log" >&2
    echo "report: phase 1 failed" >&2
    exit 1
fi
t1=$(date +%s)
load1=$(cut -d' ' -f1-3 /proc/loadavg)

echo "report: phase 2 (timed, one process at a time): sweep F = 16..20 ($sizes), skip paths, tiles"
# F rotates innermost, so that the five builds see the same stretch of
# machine load for each size and input (they are separate processes).
i=0
for s in $(echo "$sizes" | tr , ' '); do
    for inp in $inputs; do
        for f in 16 17 18 19 20; do
            i=$((i + 1))
            "$bld/f$f/report_sweep" --ref "$ref" --csv "$out/sweep.$i.csv" --data "$data" \
                --sizes "$s" --inputs "$inp" --runs "$runs" --runs-big "$runs_big" >> "$out/sweep.log"
        done
    done
    echo "report:   $s done ($(($(date +%s) - t1)) s)"
done
"$bld/f20/report_skip" --out "$out" --data "$data" --icount "$out/skip_icount.tsv" > "$out/skip.log"
"$bld/f20/report_tiles" --out "$out" --data "$data" --icount "$out/tiles_icount.tsv" --runs "$runs_big" \
    > "$out/tiles.log"
t2=$(date +%s)
load2=$(cut -d' ' -f1-3 /proc/loadavg)

# ---- merge -------------------------------------------------------------------
{
    head -n 1 "$out/sweep.1.csv"
    j=1
    while [ $j -le $i ]; do tail -n +2 "$out/sweep.$j.csv"; j=$((j + 1)); done
} > "$docs/report_sweep.csv"
awk -F, -v out="$out" -f "$here/sweep.awk" "$out/sweep_icount.tsv" "$docs/report_sweep.csv"
awk -F, -v out="$out" -f "$here/width.awk" "$out/sweep_icount.tsv" "$docs/report_sweep.csv"
cp "$out/err320.csv" "$docs/report_err320.csv"
# the targets' costs: make target-cost's CSV (a header alone when it has
# not run: the section then has x86-64 only)
tcsv=$docs/targets.csv
[ -r "$tcsv" ] || { tcsv=$out/targets-none.csv; echo "target" > "$tcsv"; }
awk -F, -v out="$out" -f "$here/targets.awk" "$out/sweep_icount.tsv" "$tcsv" \
    "$docs/report_err320.csv" "$docs/report_sweep.csv"
for c in levels intensity; do
    { cat "$out/${c}_f20.csv"; tail -n +2 "$out/${c}_f16.csv"; } > "$out/$c.csv"
    cp "$out/$c.csv" "$docs/report_$c.csv"
done
cp "$out/stability.csv" "$docs/report_stability.csv"
cp "$out/skip.csv" "$docs/report_skip.csv"
cp "$out/tiles.csv" "$docs/report_tiles.csv"
{
    echo "kind,frame,scene,F,levels,mode,threshold,instructions,output_fnv1a,sample_bits"
    awk '{ printf "sweep,640x480,scene,%s,%s,skip,0.6,%s,%s,%s\n", $1, $2, $4, $5, $3 }' "$out/sweep_icount.tsv"
    awk '{ printf "skip,%s,%s,20,5,%s,1.0,%s,%s,32\n", $1, $2, $3, $4, $5 }' "$out/skip_icount.tsv"
} > "$docs/report_icount.csv"
icpanel=$(grep -vc '^#' "$out/pareto_ic.dat" || true)
gnuplot -e "out='$out'; docs='$docs'; sizes='$(echo "$sizes" | tr , ' ')'; icpanel=$icpanel; \
inputs='rocket hubble scene-hubble studio hall point hdr-point'" "$here/plots.gp"

rep1=$(awk '$1 == "640x480" && $2 == "scene" && $3 == "skip" { print $4 }' "$out/skip_icount.tsv")
rep2=$(cut -d' ' -f1 "$out/repeat.txt")
if [ "$rep1" = "$rep2" ]; then repeat="identical ($rep1 instructions both times)"
else repeat="DIFFERENT ($rep1, then $rep2)"; fi
t3=$(date +%s)
sh "$here/write_md.sh" "$out" "$docs/report.md" "$date_utc" "$cpu" "$ncpu" "$load0" "$load1" \
    "$load2" "$((t1 - t0))" "$((t2 - t1))" "$((t3 - t0))" "$repeat" "$sizes" "$runs" "$runs_big"
echo "report: wrote $docs/report.md, report_*.png, report_*.csv in $((t3 - t0)) s" \
    "(phase 1 $((t1 - t0)) s, phase 2 $((t2 - t1)) s)"
