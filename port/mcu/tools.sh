# Sourced by test_firmware.sh and figures.sh: tool checks and the qemu run.
# Environment (from mcu.mk): B, MAKE, ARM_CC, ARM_SIZE, QEMU_ARM,
# MCU_BUILDS, MCU_LEVELS.
B=${B:-build}
MAKE=${MAKE:-make}
ARM_CC=${ARM_CC:-arm-none-eabi-gcc}
ARM_SIZE=${ARM_SIZE:-arm-none-eabi-size}
QEMU_ARM=${QEMU_ARM:-qemu-system-arm}
MCU_BUILDS=${MCU_BUILDS:-full rgb565 min minnc}
MCU_LEVELS=${MCU_LEVELS:-5 7}
MCU_OUT=$B/mcu

mcu_board() { # cpu -> QEMU machine
    case $1 in m4) echo mps2-an386 ;; m7) echo mps2-an500 ;; esac
}

mcu_have_cc() {
    command -v "$ARM_CC" >/dev/null 2>&1 || return 1
    # newlib (memcpy, memset) for the multilib the firmware links against
    lib=$("$ARM_CC" -mthumb -mcpu=cortex-m4 -mfloat-abi=soft -print-file-name=libc.a)
    [ -f "$lib" ]
}

mcu_have_qemu() {
    command -v "$QEMU_ARM" >/dev/null 2>&1 &&
        "$QEMU_ARM" -machine help 2>/dev/null | grep -q '^mps2-an500'
}

# Install Debian packages when running as root; quiet, never fatal.
mcu_apt() {
    [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1 || return 1
    export DEBIAN_FRONTEND=noninteractive
    apt-get install -y -qq --no-install-recommends "$@" >/dev/null 2>&1 ||
        { apt-get update -qq >/dev/null 2>&1 &&
          apt-get install -y -qq --no-install-recommends "$@" >/dev/null 2>&1; }
}

# Succeeds when the cross compiler and the emulator are usable, installing
# them first if possible; otherwise prints "skipped: ..." and fails.
mcu_tools() {
    mcu_have_cc || mcu_apt gcc-arm-none-eabi libnewlib-arm-none-eabi
    if ! mcu_have_cc; then
        echo "skipped: $ARM_CC with newlib not available (Debian gcc-arm-none-eabi, libnewlib-arm-none-eabi)"
        return 1
    fi
    mcu_have_qemu || mcu_apt qemu-system-arm
    if ! mcu_have_qemu; then
        echo "skipped: qemu-system-arm not available (or without the mps2-an386/an500 boards)"
        return 1
    fi
}

# Build everything under $B/mcu; on failure show the end of the log.
mcu_build() {
    mkdir -p "$MCU_OUT"
    if ! $MAKE --no-print-directory mcu-build >"$MCU_OUT/build.log" 2>&1; then
        tail -n 30 "$MCU_OUT/build.log"
        return 1
    fi
}

# Run one firmware: cpu build levels -> $MCU_OUT/<cpu>-<build>/fw_l<levels>.txt,
# returns qemu's exit status (the firmware's). Semihosting output goes to
# stderr; the serial port and the monitor are off, stdin is closed.
mcu_run() {
    mcu_run_elf "$1" "$MCU_OUT/$1-$2/fw_l$3.elf"
}

# The same for any image: cpu elf -> ${elf%.elf}.txt, qemu's exit status.
mcu_run_elf() {
    elf=$2
    timeout 120 "$QEMU_ARM" -machine "$(mcu_board "$1")" -display none -monitor none \
        -serial null -semihosting-config enable=on,target=native -kernel "$elf" \
        </dev/null >"${elf%.elf}.txt" 2>&1
}
