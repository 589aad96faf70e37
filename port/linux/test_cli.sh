#!/bin/sh
# bloom_cam's command line and its messages when there is no device to use
# (host, no kernel drivers). Usage: test_cli.sh path/to/bloom_cam
cam=$1
pass=0; fail=0
out=$(mktemp); trap 'rm -f "$out"' EXIT
expect() { # want_status want_text args...
    want=$1; text=$2; shift 2
    "$cam" "$@" >"$out" 2>&1; st=$?
    if [ "$st" -eq "$want" ] && grep -qF -- "$text" "$out"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAIL: bloom_cam $*: status $st (want $want), output:"; sed 's/^/    /' "$out"
        echo "    (wanted '$text')"
    fi
}
expect 0 "usage: bloom_cam" --help
expect 0 "  --threads N           N strips of each frame on N threads, 0..64 (0, default: the" --help
expect 2 "bloom_cam: --threads: '65' is not 0..64 (0: the online CPUs)" --threads 65
expect 2 "bloom_cam: --threads: 'x' is not 0..64 (0: the online CPUs)" --threads x
# a valid count gets as far as the device, whatever it is; exit statuses:
# 2 configuration, 3 the camera (missing, lost), port/linux/README.md
for n in 0 1 3; do
    expect 3 "bloom_cam: open /nonexistent/video9: No such file or directory" --threads "$n" --device /nonexistent/video9
done
expect 2 "bloom_cam: unknown option '--nope'" --nope
expect 2 "bloom_cam: --format: 'h264' is not auto, rgb24, yuyv, uyvy, yvyu, nv16" --format h264
expect 3 "bloom_cam: open /nonexistent/video9: No such file or directory" --device /nonexistent/video9
expect 2 "bloom_cam: VIDIOC_QUERYCAP: Inappropriate ioctl for device" --device /dev/null
expect 2 "bloom_cam: --reconnect: 'soon' is not off, on or 1..31536000 seconds" --reconnect soon
expect 2 "bloom_cam: --latest: 'maybe' is not on or off" --latest maybe
expect 2 "bloom_cam: --preset: unknown preset 'bogus' (this build has: unity" --preset bogus
expect 2 "bloom_cam: --passes applies to the xna preset, not unity" --passes 2
expect 2 "bloom_cam: VIDIOC_QUERYCAP: Inappropriate ioctl for device" --preset unity --device /dev/null
if "$cam" --gpio-frame gpiochip0:0 --device /nonexistent 2>&1 | grep -q "built without libgpiod"; then
    expect 2 "built without libgpiod" --gpio-frame gpiochip0:0
else
    expect 3 "bloom_cam: open /nonexistent: No such file" --gpio-frame gpiochip0:0 --device /nonexistent
fi
echo "bloom_cam command line without devices"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
