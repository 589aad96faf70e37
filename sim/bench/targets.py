#!/usr/bin/python3
"""make target-cost (issue 21, section 4): instructions and estimated cycles
per frame on Cortex-M4 and Cortex-M7 (port/mcu/mcu_count.py over the cost
bench firmware), instructions per pixel on Cortex-A under qemu-user
(sim/bench/insn_plugin.c over bloom_icount), written to a Markdown page.

  targets.py --build DIR --widths '32' --builds 'full rgb565 min'
             --archs 'aarch64 armhf' --out sim/docs/targets.md

Every Cortex-M run must print the host build's checksum of the same job,
and every Cortex-A frame the same output checksum at both repeat counts,
or the page is not written. COST_JOBS=N runs N emulations at once. The
results are kept in DIR/results.json; --page-only writes the page from
them without running anything (a change to the page's text)."""
import argparse
import concurrent.futures as cf
import json
import os
import platform
import struct
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "port", "mcu"))
import mcu_count  # noqa: E402

PRESETS = ["default", "gamedev", "xna", "attenuation", "arm", "cod"]  # bloom_preset_t order
CLOCK = {"m4": 168e6, "m7": 480e6}
CPUNAME = {"m4": "Cortex-M4", "m7": "Cortex-M7"}
CLS = ("load", "store", "mul", "div", "taken", "nottaken", "dsp", "it", "other")


def fail(msg):
    sys.exit(f"target-cost: {msg}")


# ---- Cortex-M ----------------------------------------------------------------
def m_jobs(builds, width="32"):
    """(build, preset, levels, width, height, strip, label) of every run. With
    16-bit samples: unity, attenuation, xna and arm, and not the minimal build
    (it has none: BLOOM_USE_S16 is 0 with BLOOM_SMALL)."""
    s16 = width == "16"
    jobs = [("full", 0, lv, 320, 240, 0, "levels") for lv in range(1, 8)]
    jobs += [("full", p, 0, 320, 240, 0, "preset") for p in range(1, len(PRESETS))
             if not s16 or PRESETS[p] == "attenuation"]
    jobs += [(b, 0, 5, 320, 240, 0, "build") for b in builds if b != "full" and not (s16 and b == "min")]
    jobs += [("rgb565", 0, 5, 640, 480, s, "strips") for s in (0, 320, 64)]
    return jobs


def m_run(elf, cpu, job):
    _b, p, lv, w, h, s, _l = job
    r = mcu_count.Run(elf, cpu, patch={"fw_cost_job": struct.pack("<5i", p, lv, w, h, s)})
    st = r.run()
    frame = [ln.strip() for ln in r.out if ln.startswith("frame")]
    res = {"status": st, "frame": frame[0] if frame else "(none)"}
    for name in ("bloom_init", "bloom_process"):
        tot = {}
        calls = [c for n, c in r.calls if n == name]
        for c in calls:
            for k, v in r.tally(c).items():
                tot[k] = tot.get(k, 0) + v
        res[name] = tot
        res[name + "_calls"] = len(calls)
        if name == "bloom_process":
            fn = {}
            for c in calls:
                for k, v in r.by_function(c).items():
                    fn[k] = fn.get(k, 0) + v
            res["functions"] = fn
    return res


def host_frame(host, job):
    _b, p, lv, w, h, s, _l = job
    env = dict(os.environ, FW_COST_JOB=f"{p} {lv} {w} {h} {s}")
    out = subprocess.run([host], env=env, capture_output=True, text=True)
    if out.returncode:
        fail(f"host bench failed on job {job}: {out.stdout}{out.stderr}")
    return [ln for ln in out.stdout.splitlines() if ln.startswith("frame")][0]


# ---- Cortex-A ----------------------------------------------------------------
QEMU = {"aarch64": "qemu-aarch64", "armhf": "qemu-arm"}
A_ROWS = [("aarch64", "RGB888->RGB888", "NEON"), ("aarch64", "RGB888->RGB888,C-only", "C only"),
          ("armhf", "RGB888->RGB888", "C (no SIMD twins)")]
A_SIZES = [(640, 480), (1920, 1080)]
# The level sweep of make report's targets section: aarch64, NEON, 640x480
# (5 levels is in the table above).
A_LEVELS = [lv for lv in range(1, 9) if lv != 5]


def a_count(plugin, binary, arch, row, w, h, repeat, levels=0):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "n")
        lv = ["--levels", str(levels)] if levels else []
        r = subprocess.run([QEMU[arch], "-plugin", f"{plugin},out={out}", binary, "--repeat", str(repeat)] + lv +
                           [row, str(w), str(h)], capture_output=True, text=True)
        if r.returncode or not os.path.exists(out):
            fail(f"{arch} {row} {w}x{h}: {r.stdout}{r.stderr}")
        return int(open(out).read().split()[1]), r.stdout.strip()


def a_run(plugin, build, w32, arch, row, w, h, third, levels=0):
    binary = os.path.join(build, f"w{w32}", arch, "bloom_icount")
    c1, o1 = a_count(plugin, binary, arch, row, w, h, 1, levels)
    c2, o2 = a_count(plugin, binary, arch, row, w, h, 2, levels)
    if o1 != o2:
        fail(f"{arch} {row} {w}x{h}: the output differs with the repeat count")
    res = {"frame": c2 - c1, "out": o1, "setup": 2 * c1 - c2}
    if third:
        c3, _ = a_count(plugin, binary, arch, row, w, h, 3)
        res["third"] = c3 - c2
    return res


# ---- the page ------------------------------------------------------------------
def fmt(n):
    return f"{n:,.0f}".replace(",", " ")


def f1(x):
    return f"{x:.1f}"


def band(lo, hi, nd=1):
    return f"{lo:.{nd}f}–{hi:.{nd}f}"


def versions():
    def first(cmd):
        try:
            return subprocess.run(cmd, capture_output=True, text=True).stdout.splitlines()[0]
        except (OSError, IndexError):
            return "?"
    import unicorn
    import capstone
    return {"arm-none-eabi-gcc": first(["arm-none-eabi-gcc", "-dumpversion"]),
            "aarch64-linux-gnu-gcc": first(["aarch64-linux-gnu-gcc", "-dumpversion"]),
            "arm-linux-gnueabihf-gcc": first(["arm-linux-gnueabihf-gcc", "-dumpversion"]),
            "qemu": first(["qemu-aarch64", "--version"]).replace("qemu-aarch64 version ", ""),
            "unicorn": unicorn.__version__, "capstone": capstone.__version__, "python": platform.python_version()}


METHOD = """## Method

**Cortex-M4 and Cortex-M7: exact instruction counts.** The cost bench
firmware (`port/mcu/fw_cost.c`, linked as the other firmwares are, with
`fw_main.c`, `startup.c`, `semihost.c` and the core built for the CPU) runs
from its reset vector in unicorn ({unicorn}, Debian `python3-unicorn`:
QEMU's Thumb-2 translator as a library) with the Cortex-M4 or Cortex-M7 CPU
model; `port/mcu/mcu_count.py` answers its semihosting calls and writes the
job (preset, levels, frame size, strip width) into the image before the
reset handler copies `.data`. Only the engine's calls are counted: from the
entry of `bloom_init` / `bloom_process` to their return address, callees
(newlib's `memcpy`/`memset` included) with them. Counting is by translation
block: a hook per executed block, each block decoded once with capstone
({capstone}) into a class histogram, and the address of the next block
telling whether the block's closing branch was taken. That is exact for
straight-line blocks (a fault would end one early; a fault ends the run).
Why unicorn and not QEMU's `-icount` with the SysTick: the SysTick of the
MPS2 models counts virtual time, one tick per 2^shift ns, not instructions,
and it gives a total only; a block hook gives the exact count and the class
mix the cycle estimate needs. Instructions inside an IT block are counted
whether their condition passes or not (they are issued; unicorn's
per-instruction hook skips the failing ones, which is why blocks are used).
Every run printed the host build's checksum of the same job.

**Classes.** load: `LDR*`, `LDRD`, `LDM`, `POP` (without the PC); store:
`STR*`, `STRD`, `STM`, `PUSH`; mul: every multiply and multiply-accumulate
(`MUL`, `MLA`, `MLS`, `UMULL`, `SMLAL`, the DSP extension's `SMLAD`,
`SMULBB`...); div: `SDIV`, `UDIV`; taken / not taken: branches (`B`, `BL`,
`BX`, `BLX`, `CBZ`, `CBNZ`, `TBB`, `TBH`, and `POP`/`LDR`/`MOV` writing the
PC, counted here and not as loads); dsp: the DSP extension's packed and
saturating arithmetic (`UADD8`, `QADD16`, `SEL`, `USAD8`, `UXTB16`...);
it: `IT`; other: the rest (ALU, moves, shifts, compares, extends).

**Cortex-M4 cycles** (Cortex-M4 Technical Reference Manual r0p1, ARM
100166_0001_00, section 3.3.1 "Table of processor instructions", table 3-1,
and 3.3.2 "Load/store timings"), from the same blocks, as a band:
ALU, moves, shifts, saturation, `MUL`/`MLA`/`MLS`, the long multiplies and
the DSP instructions 1 cycle; `SDIV`/`UDIV` 2 (low) to 12 (high), their
early termination depending on the operands, not modelled; a single `LDR`
2 cycles, 1 when it follows a single `LDR` whose result it does not use for
its address (pipelined); `STR` with an immediate offset 1 (the write
overlaps the next instruction), with a register offset as a load; `LDRD`,
`STRD`, `LDM`, `STM`, `PUSH`, `POP` 1 + N (N registers); a taken branch
1 + P, P the pipeline refill, 1 (low) to 3 (high); not taken 1; `TBB`/`TBH`
2 + P; a load or `POP` to the PC its own cost + P; `IT` 0 (low: folded into
the instruction before) or 1 (high); high also adds the TRM's one-cycle stall
of a load or store whose address register the instruction just before
wrote. Assumed: zero-wait-state memory for code and data (an STM32F4 at
168 MHz runs its flash at 5 wait states behind the ART accelerator, which
hits on loops; the frame in external SDRAM would cost more), no
interrupts, no bus contention with DMA or the display.

**Cortex-M7 cycles.** The Cortex-M7 TRM (ARM DDI 0489) describes a
six-stage dual-issue pipeline with branch prediction, and publishes no
instruction timing table, so the M7 figures are bounds, not an estimate:
low = every pair of instructions issued together (half a cycle each,
`LDM`/`STM`/`PUSH`/`POP` one cycle per pair of registers on the 64-bit
path), divides 2 cycles, every branch predicted; high = single issue (1
cycle each, `LDM` and kin 1 per register), divides 12, every taken branch
2 cycles more. Assumed: caches on and always hitting, or the code and the
rows in the TCMs; the frame's own reads and writes not stalling.

**Not modelled** (either core): wait states, cache misses and the
framebuffer's external RAM, write-buffer stalls, the DSP multiplies'
operand dependencies, divide early termination (hence the band),
interrupts. Frames per second are the clock over the band's cycles per
frame (`bloom_process` for a whole frame; in strips, every strip's
`bloom_init` too, since one workspace is re-carved per strip).

**Cortex-A: exact instruction counts.** `bloom_icount` (sim/bench/icount.c:
the benchmark scene, one `bloom_process` call a repeat) cross-built static
with `-O2` for aarch64 (NEON twins) and armhf (hard float, no SIMD twins),
run under qemu-user ({qemu}) with `sim/bench/insn_plugin.c`, a TCG plugin
adding each executed translation block's instruction count to a counter
(Debian's qemu-user loads plugins; it ships none, nor the plugin header, so
the plugin declares the five calls it uses). The frame is the difference
between the runs with one and two frame calls, so start-up, the scene and
`bloom_init` cancel; at 640×480 a third call costs the same as the second
(column "3rd − 2nd"). Both runs must print the same output checksum.
Times: only under the assumption stated with them.

**The self-test** (`make cost-selftest`, in `make test-runner`): both
counters on hand-written programs of known counts
(`port/mcu/cost_selftest_m.S`: a Thumb-2 loop of every class, its counts
and both cores' cycle bands worked by hand; `cost_selftest_a64.S` and
`cost_selftest_a32.S`: 2N + 4 instructions).

**Sample widths.** `make target-cost COST_WIDTHS='32 16'` builds and
costs each width with its own flags (`COST_CFLAGS_16` sets
`cfg.sample_bits = 16` in the benches) and gives each its rows (the column
"samples"); the targets run the default preset (16-bit samples also take
attenuation, xna and arm), and 16-bit samples are not in the
minimal build, which leaves them out (`BLOOM_USE_S16` 0 with `BLOOM_SMALL`).
"""


def page(a, mres, ares, secs):
    v = versions()
    o = ["# Cost on the targets", "",
         "Generated by `make target-cost` (port/mcu/mcu_cost.mk, sim/bench/targets.py); do not edit by hand.",
         f"arm-none-eabi-gcc {v['arm-none-eabi-gcc']} (`-Os -mthumb -mfloat-abi=soft`, as the firmware), "
         f"aarch64-linux-gnu-gcc {v['aarch64-linux-gnu-gcc']} and arm-linux-gnueabihf-gcc "
         f"{v['arm-linux-gnueabihf-gcc']} (`-O2 -static`), qemu-user {v['qemu']}, unicorn {v['unicorn']}, "
         f"capstone {v['capstone']}. Frame: the firmware's 320×240 RGB565 scene (`fw_app.c`; 640×480 repeats it "
         f"shifted, as `fw_tiles.c`), source to destination. This generation took {secs:.0f} s"
         + (" (`make target-cost-a`: the Cortex-A counts; the Cortex-M ones are the previous run's)."
            if getattr(a, "a_only", False) else "."), ""]
    # headline per CPU: default, 5 levels, full build
    o += ["## Headline", "", "| target | frame | instructions / pixel | cycles / pixel | frames / s |",
          "|---|---|---|---|---|"]
    for (w, cpu, job), r in mres.items():
        if job == ("full", 0, 5, 320, 240, 0, "levels"):
            t, n = r["bloom_process"], 320 * 240
            o.append(f"| {CPUNAME[cpu]} ({w}-bit samples) | 320×240 RGB565, default, 5 levels | "
                     f"{f1(t['insns'] / n)} | {band(t[cpu + '_lo'] / n, t[cpu + '_hi'] / n)} | "
                     f"{band(CLOCK[cpu] / t[cpu + '_hi'], CLOCK[cpu] / t[cpu + '_lo'])} at "
                     f"{CLOCK[cpu] / 1e6:.0f} MHz |")
    for (w, arch, row, (fw, fh)), r in ares.items():
        if row == "RGB888->RGB888" and fw == 1920:
            o.append(f"| {arch} ({w}-bit samples) | 1920×1080 RGB888, default, 5 levels | "
                     f"{f1(r['frame'] / (fw * fh))} | — | — |")
    o += ["", METHOD.format(**v)]

    def mrow(w, cpu, job, r, first):
        _b, p, lv, fw, fh, s, _l = job
        n = fw * fh
        t = dict(r["bloom_process"])
        if s:  # strips: every strip engine's init is part of the frame
            for k, x in r["bloom_init"].items():
                t[k] = t.get(k, 0) + x
        mix = " | ".join(f"{100.0 * t[c] / t['insns']:.1f}" for c in CLS)
        lvl = r["frame"].split(" levels ")[1].split()[0]
        return (f"| {CPUNAME[cpu]} | {w} | {first} | {lvl} | {fmt(t['insns'])} | {f1(t['insns'] / n)} | {mix} | "
                f"{band(t[cpu + '_lo'] / n, t[cpu + '_hi'] / n)} | "
                f"{band(CLOCK[cpu] / t[cpu + '_hi'], CLOCK[cpu] / t[cpu + '_lo'])} |")

    head = ("| CPU | samples | {} | levels | instructions / frame | / pixel | % load | % store | % mul | % div | "
            "% taken | % not taken | % dsp | % it | % other | cycles / pixel (band) | frames / s at 168 / 480 MHz |")
    sep = "|---" * 17 + "|"
    sections = [
        ("levels", "## Cortex-M: 320×240 RGB565, default preset, every level count",
         "The full build (every format and preset compiled in). 7 is the deepest pyramid 320×240 allows "
         "(`bloom_query`). `bloom_process` only; `bloom_init` is in the last section.", "build",
         lambda job: "full"),
        ("preset", "## Cortex-M: 320×240 RGB565, each preset",
         "The full build, each preset at its own defaults (`bloom_config_preset`) and its level count; "
         "attenuation and arm read a one-byte plane (a horizontal ramp). The default is the row at 5 levels "
         "above.", "preset", lambda job: PRESETS[job[1]]),
        ("build", "## Cortex-M: 320×240 RGB565, default preset, the smaller builds",
         "RGB565 only (`-DBLOOM_USE_RGB888=0 ...`, default preset only) and minimal (`BLOOM_SMALL`: the "
         "pull-driven scheduler of the ≤ 8 KB core, FIGURES.md), 5 levels; the full build is above.",
         "build", lambda job: job[0]),
        ("strips", "## Cortex-M: 640×480 RGB565 whole and in strips",
         "The RGB565-only build at 5 levels: the whole frame (its workspace does not fit a 64 KB SRAM), and "
         "in vertical strips of 320 and of 64 columns (64: what `fw_tiles.c` takes for a 32 KB workspace); "
         "a strip row counts every strip's `bloom_init` and `bloom_process`, the engines being re-carved out "
         "of one workspace per frame.", "strip", lambda job: "whole" if not job[5] else f"{job[5]} columns"),
    ]
    for label, title, text, col, name in sections:
        o += [title, "", text, "", head.format(col), sep]
        for (w, cpu, job), r in mres.items():
            if job[6] == label:
                o.append(mrow(w, cpu, job, r, name(job)))
        o.append("")
    o += ["## Cortex-M: where the instructions go", "",
          "`bloom_process` by function (its callees, each counted alone; inlined code is its caller's), "
          "Cortex-M4, full build, 320×240, 5 levels: the default preset and cod, the dearest.", "",
          "| preset | function | instructions | % of the frame | / pixel |", "|---|---|---|---|---|"]
    for (w, cpu, job), r in mres.items():
        if cpu == "m4" and job[0] == "full" and job[1] in (0, 5) and job[2] in (5, 0) and "functions" in r:
            fn, tot = r["functions"], r["bloom_process"]["insns"]
            for name, n in sorted(fn.items(), key=lambda kv: -kv[1])[:8]:
                o.append(f"| {PRESETS[job[1]]} ({w}-bit) | `{name}` | {fmt(n)} | {100.0 * n / tot:.1f} | "
                         f"{f1(n / (job[3] * job[4]))} |")
    o += ["", "## Cortex-M: `bloom_init`", "",
          "Instructions of one `bloom_init` (its dry run plans the engine in the workspace), full build, "
          "default preset, 320×240; once per engine, not per frame (except in strips).", "",
          "| CPU | samples | levels | instructions | M4/M7 cycles (band) |", "|---|---|---|---|---|"]
    for (w, cpu, job), r in mres.items():
        if job[6] == "levels":
            t = r["bloom_init"]
            o.append(f"| {CPUNAME[cpu]} | {w} | {job[2]} | {fmt(t['insns'])} | "
                     f"{fmt(t[cpu + '_lo'])}–{fmt(t[cpu + '_hi'])} |")
    o += ["", "## Cortex-A: instructions per pixel under qemu-user", "",
          "One `bloom_process` call, default preset (threshold of the benchmark scene), RGB888 in and out, "
          "5 levels, `sim/bench/icount.c`'s scene. The time column assumes a sustained 1 instruction per "
          "cycle at 1.5 GHz (a Cortex-A53 class core; a guess, not a measurement: the count is exact, the "
          "rate is not).", "",
          "| arch | samples | kernels | frame | instructions / frame | / pixel | 3rd − 2nd call | "
          "ms at 1 IPC, 1.5 GHz | output |", "|---|---|---|---|---|---|---|---|---|"]
    for (w, arch, row, (fw, fh)), r in ares.items():
        kern = [k for aa, rr, k in A_ROWS if aa == arch and rr == row][0]
        third = "—" if "third" not in r else ("same" if r["third"] == r["frame"] else
                                             f"{r['third'] - r['frame']:+d}")
        o.append(f"| {arch} | {w} | {kern} | {fw}×{fh} | {fmt(r['frame'])} | {f1(r['frame'] / (fw * fh))} | "
                 f"{third} | {r['frame'] / 1.5e9 * 1e3:.1f} | `{r['out'].split('output-fnv1a ')[-1]}` |")
    o.append("")
    return "\n".join(o)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--widths", default="32")
    ap.add_argument("--builds", default="full rgb565 min")
    ap.add_argument("--archs", default="aarch64 armhf")
    ap.add_argument("--out", required=True)
    ap.add_argument("--page-only", action="store_true")
    ap.add_argument("--cortex-a-only", action="store_true",
                    help="run the Cortex-A counts again, keep the last run's Cortex-M results")
    a = ap.parse_args()
    saved = os.path.join(a.build, "results.json")
    if a.page_only:
        d = json.load(open(saved))
        mres = {(w, cpu, tuple(job)): r for w, cpu, job, r in d["m"]}
        ares = {(w, arch, row, tuple(size)): r for w, arch, row, size, r in d["a"]}
        lres = {(w, lv): r for w, lv, r in d.get("al", [])}
        a.a_only = d.get("a_only", False)
        write(a, mres, ares, lres, d["secs"])
        return
    t0 = time.time()
    widths, builds, archs = a.widths.split(), a.builds.split(), a.archs.split()
    jobs = int(os.environ.get("COST_JOBS", "1"))
    work = []
    for w in widths:
        host = os.path.join(a.build, f"w{w}", "host", "fw_host_cost")
        for cpu in ("m4", "m7"):
            for job in m_jobs(builds, w):
                work.append((w, cpu, job, os.path.join(a.build, f"w{w}", f"{cpu}-{job[0]}", "fw_cost.elf"), host))
    mres = {}
    if a.cortex_a_only:  # (a change that moves only the Cortex-A kernels)
        d = json.load(open(saved))
        mres = {(w, cpu, tuple(job)): r for w, cpu, job, r in d["m"]}
        work = []
    with cf.ProcessPoolExecutor(max_workers=jobs) as ex:
        futs = {(w, cpu, job): ex.submit(m_run, elf, cpu, job) for w, cpu, job, elf, _h in work}
        for w, cpu, job, _elf, host in work:
            r = futs[(w, cpu, job)].result()
            want = host_frame(host, job)
            if r["status"] != 0 or r["frame"] != want:
                fail(f"{cpu} {job}: the firmware printed {r['frame']!r} (status {r['status']}), "
                     f"the host {want!r}")
            mres[(w, cpu, job)] = r
            t = r["bloom_process"]
            print(f"target-cost: {CPUNAME[cpu]} w{w} {job[0]} {PRESETS[job[1]]} levels {job[2]} "
                  f"{job[3]}x{job[4]} strip {job[5]}: {t['insns'] / (job[3] * job[4]):.1f} instructions/pixel",
                  flush=True)
    plugin = os.path.join(a.build, "insn_plugin.so")
    ares = {}
    for w in widths:
        for arch, row, _k in A_ROWS:
            if arch not in archs:
                continue
            for fw, fh in A_SIZES:
                r = a_run(plugin, a.build, w, arch, row, fw, fh, third=fw == 640)
                ares[(w, arch, row, (fw, fh))] = r
                print(f"target-cost: {arch} w{w} {row} {fw}x{fh}: {r['frame'] / (fw * fh):.1f} "
                      "instructions/pixel", flush=True)
    lres = {}
    if "aarch64" in archs:
        for w in widths:
            for lv in A_LEVELS:
                r = a_run(plugin, a.build, w, "aarch64", "RGB888->RGB888", 640, 480, third=False, levels=lv)
                lres[(w, lv)] = r
                print(f"target-cost: aarch64 w{w} 640x480 levels {lv}: {r['frame'] / 307200:.1f} "
                      "instructions/pixel", flush=True)
    secs = time.time() - t0
    with open(saved, "w") as f:
        json.dump({"secs": secs, "m": [[w, cpu, list(job), r] for (w, cpu, job), r in mres.items()],
                   "a": [[w, arch, row, list(size), r] for (w, arch, row, size), r in ares.items()],
                   "al": [[w, lv, r] for (w, lv), r in lres.items()], "a_only": a.cortex_a_only}, f)
    a.a_only = a.cortex_a_only
    write(a, mres, ares, lres, secs)


def csv_rows(mres, ares, lres):
    """The level sweep per target for make report's section 1 (targets.csv):
    Cortex-M cycles at 320x240 RGB565 (full build, default preset), aarch64
    NEON instructions at 640x480 RGB888, both sample widths."""
    rows = ["target,sample_bits,levels,frame,instructions_per_px,cycles_lo_per_px,cycles_hi_per_px,clock_mhz"]
    for (w, cpu, job), r in sorted(mres.items(), key=lambda kv: (kv[0][1], kv[0][0], kv[0][2][2])):
        if job[6] == "levels":
            t, n = r["bloom_process"], job[3] * job[4]
            rows.append(f"{CPUNAME[cpu]},{w},{job[2]},{job[3]}x{job[4]},{t['insns'] / n:.3f},"
                        f"{t[cpu + '_lo'] / n:.3f},{t[cpu + '_hi'] / n:.3f},{CLOCK[cpu] / 1e6:.0f}")
    a = {(w, 5): r for (w, arch, row, size), r in ares.items()
         if arch == "aarch64" and row == "RGB888->RGB888" and size == (640, 480)}
    a.update(lres)
    for (w, lv), r in sorted(a.items(), key=lambda kv: (kv[0][0], kv[0][1])):
        rows.append(f"aarch64,{w},{lv},640x480,{r['frame'] / 307200:.3f},,,")
    return "\n".join(rows) + "\n"


def write(a, mres, ares, lres, secs):
    text = page(a, mres, ares, secs)
    with open(a.out + ".tmp", "w") as f:
        f.write(text)
    os.replace(a.out + ".tmp", a.out)
    csv = os.path.join(os.path.dirname(a.out), "targets.csv")
    with open(csv + ".tmp", "w") as f:
        f.write(csv_rows(mres, ares, lres))
    os.replace(csv + ".tmp", csv)
    print(f"target-cost: wrote {a.out} and {csv}")


if __name__ == "__main__":
    main()
