#!/bin/bash
# `make bench-peers` (issue 15, item 4): the engine against the bloom/glow
# filters users already have, on one 1920x1080 RGB frame (the scene of
# bloom_bench), one thread, every contender once per round in a rotated
# order; ratios are medians of per-round ratios, so that a slow spell of the
# shared machine hits both sides of a ratio. Writes PAGE (a peer that cannot
# be installed, built or run is listed there with the reason, never dropped).
#   bash sim/bench/peers.sh PEERS_DRV WORKDIR PAGE
# Knobs: PEERS_ROUNDS (9), PEERS_BUFFERS (GStreamer buffers per run, 100),
# PEERS_FFMPEG_FRAMES (50), PEERS_GEGL_FRAMES (5); MAKE, CC, PEERS_CFLAGS.
set -u
drv=$1 dir=$2 page=$3
W=1920 H=1080
ROUNDS=${PEERS_ROUNDS:-9} NBUF=${PEERS_BUFFERS:-100}
NFF=${PEERS_FFMPEG_FRAMES:-50} NGEGL=${PEERS_GEGL_FRAMES:-5} NPAIR=15
# The engine at bloom_bench's settings (threshold 0.60 linear, knee 0.5,
# intensity 1, 5 levels); the peers' own knobs as near as they have them:
# 203 = the sRGB code of linear 0.60, sigma 15 px = the spread of the
# engine's glow at 5 levels (method.md, "OpenCV, tutorial").
THR=0.6 CODE=203 SIGMA=15 GEGL_THR=60 GEGL_RADIUS=15 FREI0R_BLUR=0.1
mkdir -p "$dir"
rm -f "$dir/rounds.txt" "$dir/why.txt"
: > "$dir/rounds.txt"
: > "$dir/why.txt"
# why NAME REASON: NAME is not measured; the page says why.
why() { grep -q "^$1	" "$dir/why.txt" || printf '%s\t%s\n' "$1" "$2" >> "$dir/why.txt"; }
skipped() { grep -q "^$1	" "$dir/why.txt"; }
# what apt-get said about a package that did not install, else its state
apt_said() {
    grep "^$1:" "$dir/apt-failures.txt" 2>/dev/null | head -n 1 | grep . ||
        echo "package $1: $(dpkg-query -W -f='${Status} ${Version}' "$1" 2>&1)"
}
oneline() { tr '\n\t' '  ' | cut -c 1-300; }

sh sim/bench/peers_deps.sh "$dir/apt-failures.txt"
"$drv" scene "$dir/frame.rgb" $W $H || exit 1

# --- availability: each peer probed as it will run ---------------------------
export GST_PLUGIN_PATH="$PWD/build/gst" GST_REGISTRY="$dir/registry.bin"
if ! command -v gst-launch-1.0 >/dev/null 2>&1; then
    for p in gst-pass gst-convert gst-bloom gst-frei0r; do
        why $p "gst-launch-1.0 not found ($(apt_said gstreamer1.0-tools))"
    done
elif ! gst-inspect-1.0 rawvideoparse >/dev/null 2>&1; then
    for p in gst-pass gst-convert gst-bloom gst-frei0r; do
        why $p "element rawvideoparse (gstreamer1.0-plugins-bad) not found ($(apt_said gstreamer1.0-plugins-bad))"
    done
fi
if ! ${MAKE:-make} --no-print-directory gst > "$dir/gst-build.log" 2>&1; then
    why gst-bloom "make gst failed: $({ grep -m 2 -E 'error:|Error [0-9]' "$dir/gst-build.log" || tail -n 2 "$dir/gst-build.log"; } | oneline)"
fi
gst-inspect-1.0 frei0r-filter-glow >/dev/null 2>&1 ||
    why gst-frei0r "element frei0r-filter-glow not found (frei0r-plugins + gstreamer1.0-plugins-bad's frei0r wrapper) $(apt_said frei0r-plugins) $(apt_said gstreamer1.0-plugins-bad)"
if ! command -v ffmpeg >/dev/null 2>&1; then
    why ffmpeg-glow "ffmpeg not found ($(apt_said ffmpeg))"
fi
# shellcheck disable=SC2086,SC2046 # flags and pkg-config output are word lists
if ! pkg-config --exists gegl-0.4 2>/dev/null; then
    why gegl-bloom "pkg-config gegl-0.4 not found ($(apt_said libgegl-dev))"
elif ! ${CC:-cc} -std=c11 -Wall -Wextra -Werror ${PEERS_CFLAGS:--O2} -D_POSIX_C_SOURCE=200809L \
    $(pkg-config --cflags gegl-0.4 | sed 's/-I/-isystem /g') sim/bench/peers_gegl.c \
    $(pkg-config --libs gegl-0.4) -o "$dir/peers_gegl" 2> "$dir/gegl-build.log"; then
    why gegl-bloom "peers_gegl.c did not build: $({ grep -m 2 -E 'error:' "$dir/gegl-build.log" || head -n 2 "$dir/gegl-build.log"; } | oneline)"
fi

# --- the contenders ----------------------------------------------------------
# GStreamer: the file's frame again and again (multifilesrc loop, page cache)
# cut into video frames by rawvideoparse, one streaming thread (no queue),
# videoconvert n-threads=1; frei0r's glow takes RGBA only, so its pipeline
# converts RGB -> RGBA -> RGB, which gst-convert measures alone.
SRC="multifilesrc location=$dir/frame.rgb loop=true num-buffers=$NBUF ! rawvideoparse format=rgb width=$W height=$H framerate=25/1"
VC="videoconvert n-threads=1"
declare -A PIPE=(
    [gst-pass]="$VC ! video/x-raw,format=RGB"
    [gst-convert]="$VC ! video/x-raw,format=RGBA ! $VC ! video/x-raw,format=RGB"
    [gst-bloom]="bloom threshold=$THR knee=0.5 intensity=1"
    [gst-frei0r]="$VC ! video/x-raw,format=RGBA ! frei0r-filter-glow blur=$FREI0R_BLUR ! $VC ! video/x-raw,format=RGB"
)
# ffmpeg's usual glow: threshold on a copy, Gaussian blur, add back; planar
# GBR because gblur and blend take no packed RGB; ffmpeg-null is the same
# command without the filter (reading and writing the frames, start-up).
LUT="if(gt(val,$CODE),val,0)"
FFGLOW="format=gbrp,split[a][b];[b]lutrgb=r='$LUT':g='$LUT':b='$LUT',gblur=sigma=${SIGMA}[g];[a][g]blend=all_mode=addition,format=rgb24"
ffcmd() {
    ffmpeg -nostdin -hide_banner -loglevel error -threads 1 -filter_threads 1 -filter_complex_threads 1 \
        -stream_loop $((NFF - 1)) -f rawvideo -pix_fmt rgb24 -s ${W}x$H -i "$dir/frame.rgb" \
        -filter_complex "$1" -f rawvideo -y /dev/null
}
now_ms() { echo $(($(date +%s%N) / 1000)) | awk '{printf "%.3f", $1 / 1000}'; }
# run NAME ROUND: one measurement, appended to rounds.txt as "round name ms".
run() {
    local n=$1 r=$2 out t0 t1
    skipped "$n" && return
    case $n in
    gst-*)
        # "Execution ended after 0:00:01.234": PLAYING to EOS, no start-up
        # shellcheck disable=SC2086
        out=$(gst-launch-1.0 $SRC ! ${PIPE[$n]} ! fakesink sync=false 2>&1)
        t0=$(echo "$out" | sed -n 's/^Execution ended after \([0-9]*\):\([0-9]*\):\([0-9.]*\)$/\1 \2 \3/p')
        [ -n "$t0" ] || { why "$n" "gst-launch-1.0 failed: $(echo "$out" | grep -m 2 -E 'ERROR|rror' | oneline)"; return; }
        echo "$r $n $(echo "$t0" | awk -v n="$NBUF" '{print ($1 * 3600 + $2 * 60 + $3) * 1000 / n}')" >> "$dir/rounds.txt" ;;
    engine)
        out=$("$drv" time "$dir/frame.rgb" $W $H $NPAIR $THR) || { why memcpy "peers_drv failed"; why engine "peers_drv failed"; return; }
        echo "$out" | awk -v r="$r" '{print r, "memcpy", $1; print r, "engine", $2}' >> "$dir/rounds.txt" ;;
    gegl-bloom)
        out=$(GEGL_THREADS=1 "$dir/peers_gegl" "$dir/frame.rgb" $W $H "$NGEGL" $GEGL_THR $GEGL_RADIUS 2>&1) ||
            { why "$n" "peers_gegl failed: $(echo "$out" | oneline)"; return; }
        echo "$r $n $(echo "$out" | tail -n 1)" >> "$dir/rounds.txt" ;;
    ffmpeg-*)
        local f="null"
        [ "$n" = ffmpeg-glow ] && f=$FFGLOW
        t0=$(now_ms)
        out=$(ffcmd "$f" 2>&1) || { why ffmpeg-glow "ffmpeg failed: $(echo "$out" | oneline)"; return; }
        t1=$(now_ms)
        echo "$r $n $(awk -v a="$t0" -v b="$t1" -v n="$NFF" 'BEGIN {print (b - a) / n}')" >> "$dir/rounds.txt" ;;
    esac
}
skipped ffmpeg-glow && why ffmpeg-null "$(grep '^ffmpeg-glow	' "$dir/why.txt" | cut -f 2)"
ALL="gst-pass gst-convert gst-bloom gst-frei0r engine gegl-bloom ffmpeg-null ffmpeg-glow"
load0=$(cut -d ' ' -f 1 /proc/loadavg)
for r in $(seq 1 "$ROUNDS"); do
    # shellcheck disable=SC2086 # the list of contenders, split on purpose
    set -- $ALL
    for _ in $(seq 1 $(((r - 1) % $#))); do set -- "${@:2}" "$1"; done # rotate
    for n in "$@"; do run "$n" "$r"; done
    echo "bench-peers: round $r of $ROUNDS done"
done
load1=$(cut -d ' ' -f 1 /proc/loadavg)

# --- the page ----------------------------------------------------------------
# st MODE A [B [C [D]]]: median over the rounds of A (val), A/B (ratio),
# A-B (net) or (A-C)/(B-D), D = C unless given (netratio); "-" when a round
# lacks one of them.
st() {
    awk -v m="$1" -v a="$2" -v b="${3:-}" -v c="${4:-}" -v d="${5:-${4:-}}" '
        { v[$1, $2] = $3; R[$1] = 1 }
        END {
            n = 0
            for (r in R) {
                if (!((r, a) in v) || (b != "" && !((r, b) in v)) || (c != "" && !((r, c) in v)) || (d != "" && !((r, d) in v))) continue
                x = v[r, a]
                if (m == "ratio") x = v[r, a] / v[r, b]
                if (m == "net") x = v[r, a] - v[r, b]
                if (m == "netratio") { if (v[r, b] == v[r, d]) continue; x = (v[r, a] - v[r, c]) / (v[r, b] - v[r, d]) }
                s[++n] = x
            }
            if (!n) { print "-"; exit }
            for (i = 2; i <= n; i++) for (j = i; j > 1 && s[j - 1] > s[j]; j--) { t = s[j]; s[j] = s[j - 1]; s[j - 1] = t }
            x = n % 2 ? s[(n + 1) / 2] : (s[n / 2] + s[n / 2 + 1]) / 2
            printf(x >= 100 ? "%.0f" : x >= 10 ? "%.1f" : x >= 1 ? "%.2f" : "%.3f", x)
        }' "$dir/rounds.txt"
}
fps() { awk -v t="$(st val "$1")" 'BEGIN {if (t == "-") print "-"; else printf "%.1f", 1000 / t}'; }
pkgv() { dpkg-query -W -f='${Version}' "$1" 2>/dev/null || echo "not installed"; }
tmp="$page.tmp"
{
    echo "# Benchmark: the peers (GStreamer, ffmpeg, GEGL) at 1920x1080"
    echo
    echo "Generated by \`make bench-peers\` (also run by \`make bench\`; \`sim/bench/peers.sh\`); the method is below the tables. Times are medians on this machine only; compare by the ratios, medians of the ratios *within* each round. Back to [the engine's benchmark](bench.md)."
    echo
    echo "- Date: $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "- CPU: $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1), $(nproc) logical CPUs online"
    echo "- Load average (1 min) at start / end: $load0 / $load1 on $(nproc) CPUs"
    echo "- Frame: 1920x1080 RGB888 (6 220 800 bytes), the scene of \`bloom_bench\` (\`sim/bench/scene.c\`: \`tests/data/rocket_floodlights.ppm\` stretched, plus 24 light spots), written once by \`peers_drv scene\`; every contender reads these pixels"
    echo "- Rounds: $ROUNDS; per round each contender runs once, in an order rotated from round to round: GStreamer $NBUF buffers per pipeline, ffmpeg $NFF frames, the engine and the cold memcpy $NPAIR pairs (median per round), GEGL $NGEGL frames after one warm-up (median per round)"
    echo "- Versions: GStreamer $(pkgv gstreamer1.0-tools), gst-plugins-bad $(pkgv gstreamer1.0-plugins-bad), frei0r-plugins $(pkgv frei0r-plugins), ffmpeg $(pkgv ffmpeg), GEGL $(pkgv libgegl-dev); the engine and \`peers_drv\` by ${CC:-cc} $(${CC:-cc} -dumpversion) with \`${PEERS_CFLAGS:--O2}\`, the element by \`make gst\` (the project's \`CFLAGS\`)"
    echo
    echo "## GStreamer pipelines: the element \`bloom\` against frei0r's glow"
    echo
    echo "\`gst-launch-1.0 SRC ! FILTER ! fakesink sync=false\`, SRC = \`${SRC//$dir\//}\`; the time is gst-launch-1.0's \"Execution ended after\" (PLAYING to EOS) over the buffers. \"above pass-through\" subtracts the pass-through pipeline of the same round: the filter's own cost per frame."
    echo
    echo "| pipeline | FILTER | frames/s | ms/frame | ms/frame above pass-through | x bloom pipeline, time | x bloom, above pass-through |"
    echo "|---|---|---:|---:|---:|---:|---:|"
    for n in gst-pass gst-convert gst-bloom gst-frei0r; do
        case $n in gst-pass) d="pass-through (videoconvert, RGB to RGB: no work)" ;; gst-convert) d="videoconvert only: RGB -> RGBA -> RGB (frei0r's conversions)" ;;
        gst-bloom) d="this engine's element \`bloom\` (in place, RGB)" ;; gst-frei0r) d="\`frei0r-filter-glow\` with its conversions" ;; esac
        if skipped $n; then echo "| $d | not measured | - | - | - | - | - |"; continue; fi
        if [ $n = gst-pass ]; then net=- netx=-; else net=$(st net $n gst-pass) netx=$(st netratio $n gst-bloom gst-pass); fi
        echo "| $d | \`${PIPE[$n]}\` | $(fps $n) | $(st val $n) | $net | $(st ratio $n gst-bloom) | $netx |"
    done
    # frei0r's own share: its pipeline minus the conversions-only one.
    skipped gst-frei0r || skipped gst-convert ||
        echo "| frei0r's glow alone: its pipeline minus \"videoconvert only\" | - | - | - | $(st net gst-frei0r gst-convert) | - | $(st netratio gst-frei0r gst-bloom gst-convert gst-pass) |"
    echo
    echo "## The engine against ffmpeg's glow and GEGL's \`gegl:bloom\`"
    echo
    echo "| contender | ms/frame | x cold memcpy | x engine |"
    echo "|---|---:|---:|---:|"
    row() { if skipped "$2"; then echo "| $1 | not measured | - | - |"; else echo "| $1 | $3 | $4 | $5 |"; fi; }
    row "cold memcpy of the frame (glibc, fresh slots)" memcpy "$(st val memcpy)" 1.00 "$(st ratio memcpy engine)"
    row "this engine: \`bloom_process\`, RGB888 in and out (\`peers_drv\`)" engine "$(st val engine)" "$(st ratio engine memcpy)" 1.00
    # a difference of two runs over the medians of memcpy and the engine
    dq() { awk -v a="$1" -v b="$(st val "$2")" 'BEGIN {if (a == "-" || b == "-") print "-"; else printf(a / b >= 10 ? "%.1f" : "%.2f", a / b)}'; }
    x=$(st net gst-bloom gst-pass)
    row "this engine in GStreamer: element \`bloom\`, above pass-through" gst-bloom "$x" "$(dq "$x" memcpy)" "$(dq "$x" engine)"
    x=$(st net ffmpeg-glow ffmpeg-null)
    row "ffmpeg glow, filter only: whole command minus the same command with \`null\`" ffmpeg-glow "$x" "$(dq "$x" memcpy)" "$(dq "$x" engine)"
    row "ffmpeg glow, whole command per frame (read, filter, write, start-up)" ffmpeg-glow "$(st val ffmpeg-glow)" "$(st ratio ffmpeg-glow memcpy)" "$(st ratio ffmpeg-glow engine)"
    row "GEGL \`gegl:bloom\` (\`peers_gegl\`)" gegl-bloom "$(st val gegl-bloom)" "$(st ratio gegl-bloom memcpy)" "$(st ratio gegl-bloom engine)"
    echo
    echo "\"x\" columns are medians of the per-round ratios, except on the two rows that are a difference of two runs (the element above pass-through, ffmpeg filter only): the median difference over the median time of memcpy or of the engine."
    echo
    echo "## Not measured"
    echo
    if [ -s "$dir/why.txt" ]; then
        # shellcheck disable=SC2016 # the backquotes are Markdown
        sed 's/^\([^	]*\)	\(.*\)$/- `\1`: \2/' "$dir/why.txt"
    else
        echo "Nothing: every peer was installed, built and run."
    fi
    echo
    cat sim/bench/peers-method.md
} > "$tmp" && mv "$tmp" "$page"
cp "$dir/rounds.txt" "$dir/rounds-last.txt"
echo "bench-peers: wrote $page"
cat "$dir/why.txt"
