#!/bin/sh
# Debian packages for `make bench` (OpenCV 4 development files, a C++
# compiler, pkg-config), `make icount` (valgrind) and `make profile`
# (linux-perf). Installs only what is missing; quiet when everything is there.
#   sh sim/bench/deps.sh bench|icount|profile
set -e
need=""
case "${1:-bench}" in
bench)
    command -v c++ >/dev/null 2>&1 || need="$need g++"
    command -v pkg-config >/dev/null 2>&1 || need="$need pkg-config"
    if ! pkg-config --exists opencv4 2>/dev/null; then
        need="$need libopencv-dev"
    fi
    ;;
icount)
    command -v valgrind >/dev/null 2>&1 || need="$need valgrind"
    command -v callgrind_annotate >/dev/null 2>&1 || need="$need valgrind"
    ;;
profile)
    command -v perf >/dev/null 2>&1 || need="$need linux-perf"
    ;;
*)
    echo "usage: deps.sh bench|icount|profile" >&2
    exit 2
    ;;
esac
[ -z "$need" ] && exit 0
echo "bench deps: installing$need"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
# Refresh the package lists only when apt does not know a package yet.
for p in $need; do
    if ! apt-cache show "$p" >/dev/null 2>&1; then
        $SUDO apt-get update -qq
        break
    fi
done
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $need
