#!/bin/sh
# Debian packages of `make bench-peers` only (sim/bench/peers.sh), kept out
# of tests/deps.sh: no test needs ffmpeg, frei0r or GEGL. Installs what is
# missing, unpinned; never fails, so that one peer that cannot be installed
# does not stop the others: what apt-get said for a package that did not
# install goes to the file $1 ("package: reason" lines), which peers.sh
# quotes on the page.
#   sh sim/bench/peers_deps.sh FAILURES_FILE
out=${1:-/dev/null}
: > "$out"
need=""
has() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q 'ok installed'; }
# the element's build and gst-launch-1.0 (as tests/deps.sh), the peers:
# ffmpeg's filters, frei0r's glow and its GStreamer wrapper (gst-plugins-bad's
# frei0r plugin), GEGL's headers and library for peers_gegl.c
for p in gcc make pkg-config libgstreamer1.0-dev libgstreamer-plugins-base1.0-dev \
    gstreamer1.0-tools gstreamer1.0-plugins-base gstreamer1.0-plugins-bad \
    frei0r-plugins ffmpeg libgegl-dev; do
    has "$p" || need="$need $p"
done
[ -z "$need" ] && exit 0
echo "bench peers deps: installing$need"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq || true
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $need >/dev/null 2>&1 && exit 0
# One at a time, to know which one failed and why.
for p in $need; do
    log=$($SUDO apt-get install -y -qq --no-install-recommends "$p" 2>&1) ||
        echo "$p: apt-get install failed: $(echo "$log" | grep -E '^E:' | head -n 2 | tr '\n' ' ')" >> "$out"
done
exit 0
