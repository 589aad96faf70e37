#!/usr/bin/python3
"""The target cost counters checked on programs of known counts (issue 21,
section 4; port/mcu/cost_selftest.sh builds them, make test-runner runs it).

  cost_selftest.py M_ELF PLUGIN A64_10 A64_1000 A32_10 A32_1000

M_ELF is cost_selftest_m.S linked at the boards' addresses: st_main calls
st_loop(N); only st_loop is a counted region. Its class mix per call,
counted by hand from the source:
  loads 2N, stores N+1 (the push), mul N, div N, dsp N, it N,
  other 3N+3, taken N (N-1 loop branches and the return), not taken 1,
  instructions 11N+5,
and the cycle models' figures at N = 10, worked by hand from the rules in
mcu_count.py (the first block runs from st_loop's entry through one pass
of the loop; the loop block 9 times, the last not taken; the exit block):
  M4 lo: 19 + 8 * 13 + 12 + 6 = 141     M4 hi: 32 + 8 * 26 + 23 + 8 = 271
  M7 lo: 10 + 9 * 7 + 2.5 = 75.5        M7 hi: 29 + 8 * 24 + 22 + 6 = 249
The block method (the one the tables use) must give these; the
instruction hook must give them less the N condition-failed ADDEQ
(unicorn calls no code hook for an IT-block instruction whose condition
fails, which is why the tables count by block: such an instruction is
still issued). The function must return 15 N (its computation ran right).
A64_* / A32_* are the aarch64 and armhf programs of exactly 2N + 4
instructions, N = 10 and 1000, counted whole by the QEMU plugin.
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mcu_count  # noqa: E402

passed = failed = 0


def check(what, got, want):
    global passed, failed
    if got == want:
        passed += 1
        print(f"  ok   {what}: {got}")
    else:
        failed += 1
        print(f"  FAIL {what}: got {got}, want {want}")


def expected(n):
    return {"load": 2 * n, "store": n + 1, "mul": n, "div": n, "dsp": n, "it": n, "other": 3 * n + 3,
            "taken": n, "nottaken": 1, "insns": 11 * n + 5}


def m_side(elf):
    for n in (1, 10):
        for method in ("block", "insn"):
            r = mcu_count.Run(elf, "m4", regions=("st_loop",), method=method)
            check(f"M {method} N={n}: st_loop returns 15 N", r.call("st_main", (n,)), 15 * n)
            check(f"M {method} N={n}: one region call", len(r.calls), 1)
            t = r.tally(r.calls[0][1])
            want = expected(n)
            if method == "insn":  # the condition-failed ADDEQ, unseen by the hook
                want.update(other=want["other"] - n, insns=want["insns"] - n)
            check(f"M {method} N={n}: class counts", {k: t[k] for k in want}, want)
            if method == "block" and n == 10:
                check("M block N=10: cycle bounds (m4 lo, hi; m7 lo, hi)",
                      (t["m4_lo"], t["m4_hi"], t["m7_lo"], t["m7_hi"]), (141, 271, 75.5, 249))


def a_side(plugin, progs):
    for arch, qemu, n, prog in progs:
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "count")
            st = subprocess.run([qemu, "-plugin", f"{plugin},out={out}", prog], capture_output=True).returncode
            got = open(out).read().split() if os.path.exists(out) else ["none", "none"]
            check(f"A {arch} N={n}: exit status", st, 0)
            check(f"A {arch} N={n}: instructions", got[1], str(2 * n + 4))


def main(argv):
    if len(argv) != 6:
        print(__doc__)
        return 2
    m_side(argv[0])
    a_side(argv[1], [("aarch64", "qemu-aarch64", 10, argv[2]), ("aarch64", "qemu-aarch64", 1000, argv[3]),
                     ("armhf", "qemu-arm", 10, argv[4]), ("armhf", "qemu-arm", 1000, argv[5])])
    print(f"{passed} passed, {failed} failed, 0 skipped")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
