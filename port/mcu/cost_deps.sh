#!/bin/sh
# Debian packages of the target cost tools (port/mcu/mcu_cost.mk): unicorn
# and capstone for Python (the Cortex-M counter, port/mcu/mcu_count.py),
# qemu-user with plugin support (the -static builds have none) for the
# Cortex-A counter, the cross compilers and the Cortex-M toolchain.
# Installs only what is missing, as root or through sudo; prints what is
# still missing and fails when it cannot. Quiet when everything is there.
need=""
py=/usr/bin/python3
[ -x $py ] || need="$need python3"
$py -c 'import unicorn' 2>/dev/null || need="$need python3-unicorn"
$py -c 'import capstone' 2>/dev/null || need="$need python3-capstone"
command -v qemu-aarch64 >/dev/null 2>&1 && command -v qemu-arm >/dev/null 2>&1 || need="$need qemu-user"
command -v aarch64-linux-gnu-gcc >/dev/null 2>&1 || need="$need gcc-aarch64-linux-gnu"
[ -f /usr/aarch64-linux-gnu/lib/libc.a ] || need="$need libc6-dev-arm64-cross"
command -v arm-linux-gnueabihf-gcc >/dev/null 2>&1 || need="$need gcc-arm-linux-gnueabihf"
[ -f /usr/arm-linux-gnueabihf/lib/libc.a ] || need="$need libc6-dev-armhf-cross"
command -v arm-none-eabi-gcc >/dev/null 2>&1 || need="$need gcc-arm-none-eabi"
[ -d /usr/lib/arm-none-eabi/newlib ] || need="$need libnewlib-arm-none-eabi"
[ -z "$need" ] && exit 0
SUDO=""
[ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null && SUDO="sudo -n"
if [ "$(id -u)" -ne 0 ] && [ -z "$SUDO" ]; then
    echo "cost deps: missing$need (not root, no sudo)"
    exit 1
fi
echo "cost deps: installing$need"
export DEBIAN_FRONTEND=noninteractive
# shellcheck disable=SC2086
{ $SUDO apt-get install -y -qq --no-install-recommends $need ||
  { $SUDO apt-get update -qq && $SUDO apt-get install -y -qq --no-install-recommends $need; }; } >/dev/null 2>&1
if ! $py -c 'import unicorn, capstone' 2>/dev/null || ! command -v qemu-aarch64 >/dev/null 2>&1; then
    echo "cost deps: installing$need failed"
    exit 1
fi
