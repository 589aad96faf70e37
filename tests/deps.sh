#!/bin/sh
# Install the Debian packages the build, the tests and the demo use, if any
# is missing. Idempotent and quiet when everything is there.
set -e
need=""
command -v cc >/dev/null 2>&1 || need="$need gcc"
command -v make >/dev/null 2>&1 || need="$need make"
command -v clang >/dev/null 2>&1 || need="$need clang"
command -v clang-format >/dev/null 2>&1 || need="$need clang-format"
ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.asan-x86_64.a >/dev/null 2>&1 ||
    need="$need libclang-rt-dev"
command -v arm-none-eabi-gcc >/dev/null 2>&1 || need="$need gcc-arm-none-eabi"
[ -d /usr/lib/arm-none-eabi/newlib ] || need="$need libnewlib-arm-none-eabi"
# host tools: the simulator's image libraries (bloom_sim); libjpeg is also
# bloom_cam's MJPEG decoder (the package's libjpeg.a for its static build)
command -v pkg-config >/dev/null 2>&1 || need="$need pkg-config"
[ -f /usr/include/png.h ] || need="$need libpng-dev"
[ -f /usr/include/jpeglib.h ] || need="$need libjpeg62-turbo-dev"
[ -d /usr/include/OpenEXR ] || need="$need libopenexr-dev"
# the Linux camera tool's GPIO module (libgpiod v1 on bookworm)
[ -f /usr/include/gpiod.h ] || need="$need libgpiod-dev"
# its DRM/KMS output (libdrm; libdrm.a for the static build of make test-linux)
[ -f /usr/include/xf86drmMode.h ] || need="$need libdrm-dev"
# the GStreamer element (port/gstreamer, make test-gst): headers, gstcheck,
# gst-inspect-1.0, and appsrc/appsink/videotestsrc/videoconvert
[ -f /usr/include/gstreamer-1.0/gst/check/gstcheck.h ] || need="$need libgstreamer1.0-dev"
[ -f /usr/include/gstreamer-1.0/gst/app/app.h ] || need="$need libgstreamer-plugins-base1.0-dev"
command -v gst-inspect-1.0 >/dev/null 2>&1 || need="$need gstreamer1.0-tools"
ls /usr/lib/*/gstreamer-1.0/libgstapp.so /usr/lib/*/gstreamer-1.0/libgstvideoconvertscale.so \
    >/dev/null 2>&1 || need="$need gstreamer1.0-plugins-base"
# the FPGA twin (port/fpga): two simulators, synthesis, iCE40 place and route
command -v g++ >/dev/null 2>&1 || need="$need g++"
command -v verilator >/dev/null 2>&1 || need="$need verilator"
command -v iverilog >/dev/null 2>&1 || need="$need iverilog"
command -v yosys >/dev/null 2>&1 || need="$need yosys"
command -v nextpnr-ice40 >/dev/null 2>&1 || need="$need nextpnr-ice40"
command -v icepack >/dev/null 2>&1 || need="$need fpga-icestorm"
[ -z "$need" ] && exit 0
echo "deps: installing$need"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $need
