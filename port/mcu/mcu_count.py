#!/usr/bin/python3
"""Exact instruction counts of a Cortex-M firmware under emulation, by class,
and a cycle estimate from them (issue 21, section 4).

The firmware image (an ELF for port/mcu/mps2.ld) runs from its reset vector
in unicorn (Debian python3-unicorn: QEMU's Thumb-2 translator as a library)
with the Cortex-M4 or Cortex-M7 CPU model; semihosting (bkpt 0xAB:
SYS_WRITE0, SYS_EXIT_EXTENDED) is answered here, so the image is the one
that also runs under qemu-system-arm. Instructions are counted only while a
region function runs (from its entry to its return address, callees
included: bloom_init and bloom_process by default), per call.

Two counting methods, which the self-test holds equal:
  block  a hook per executed translation block; each block's instructions
         are decoded once (python3-capstone) into a class histogram, and a
         block's successor tells whether its closing branch was taken.
         Exact: a block is straight-line code, entered at its start and left
         at its end (a fault would end it early; a fault ends the run here).
  insn   a hook per executed instruction (slow; for the self-test).

Classes: load (LDR*, LDRD, LDM, POP), store (STR*, STRD, STM, PUSH), mul
(every multiply and multiply-accumulate, the DSP extension's included), div
(SDIV, UDIV), taken / not-taken branch (B, BL, BX, BLX, CBZ, CBNZ, TBB,
TBH, and loads, pops and moves that write the PC), dsp (the DSP
extension's packed and saturating arithmetic, SEL, USAD8...), it, other.
An instruction inside an IT block is counted whether or not its condition
passes (it is issued either way).
"""
import bisect
import struct
import sys

import capstone
from capstone import arm_const as C
import unicorn
from unicorn import arm_const as U

FLASH, RAM, SCS = 0x00000000, 0x20000000, 0xE000E000
MEM = 4 << 20
HALT = 0x00FFFFF0  # in the flash window, never code: the harness's return address
CPUS = {"m4": (U.UC_CPU_ARM_CORTEX_M4, 0x410FC241), "m7": (U.UC_CPU_ARM_CORTEX_M7, 0x411FC272)}
CLASSES = ("load", "store", "mul", "div", "taken", "nottaken", "dsp", "it", "other")


# ---- ELF32 (little-endian ARM): loadable segments and symbols -------------
def read_elf(path):
    data = open(path, "rb").read()
    if data[:4] != b"\x7fELF" or data[4] != 1 or data[5] != 1:
        raise SystemExit(f"{path}: not a little-endian ELF32 file")
    e_phoff, e_shoff = struct.unpack_from("<II", data, 28)
    e_phentsize, e_phnum, e_shentsize, e_shnum = struct.unpack_from("<HHHH", data, 42)
    segs = []
    for i in range(e_phnum):
        p_type, p_off, p_vaddr, p_paddr, p_filesz, p_memsz = struct.unpack_from("<IIIIII", data,
                                                                                e_phoff + i * e_phentsize)
        if p_type == 1:
            segs.append((p_vaddr, p_paddr, data[p_off:p_off + p_filesz], p_memsz))
    secs = [struct.unpack_from("<IIIIIIIIII", data, e_shoff + i * e_shentsize) for i in range(e_shnum)]
    syms, funcs = {}, []
    for s in secs:
        if s[1] != 2:  # SHT_SYMTAB
            continue
        strtab = secs[s[6]]
        for off in range(s[4], s[4] + s[5], 16):
            name, value, size, info = struct.unpack_from("<IIIB", data, off)
            if name and (info & 15) in (1, 2):  # object, function
                end = data.index(b"\0", strtab[4] + name)
                syms[data[strtab[4] + name:end].decode()] = value
                if info & 15 == 2 and size:
                    funcs.append((value & ~1, size, data[strtab[4] + name:end].decode()))
    return segs, syms, sorted(funcs)


# ---- decoding and classes --------------------------------------------------
_md = capstone.Cs(capstone.CS_ARCH_ARM, capstone.CS_MODE_THUMB | capstone.CS_MODE_MCLASS)
_md.detail = True


def _ids(*names):
    return {getattr(C, "ARM_INS_" + n) for n in names if hasattr(C, "ARM_INS_" + n)}


LOAD1 = _ids("LDR", "LDRB", "LDRH", "LDRSB", "LDRSH", "LDRT", "LDRBT", "LDRHT", "LDRSBT", "LDRSHT", "LDREX",
             "LDREXB", "LDREXH")
STORE1 = _ids("STR", "STRB", "STRH", "STRT", "STRBT", "STRHT", "STREX", "STREXB", "STREXH")
LOAD2, STORE2 = _ids("LDRD"), _ids("STRD")
LOADM, STOREM = _ids("LDM", "LDMDB", "POP"), _ids("STM", "STMDB", "PUSH")
MUL = _ids("MUL", "MLA", "MLS", "SMULL", "UMULL", "SMLAL", "UMLAL", "UMAAL", "SMULBB", "SMULBT", "SMULTB",
           "SMULTT", "SMULWB", "SMULWT", "SMLABB", "SMLABT", "SMLATB", "SMLATT", "SMLAWB", "SMLAWT", "SMLALBB",
           "SMLALBT", "SMLALTB", "SMLALTT", "SMLAD", "SMLADX", "SMLSD", "SMLSDX", "SMLALD", "SMLALDX", "SMLSLD",
           "SMLSLDX", "SMMUL", "SMMULR", "SMMLA", "SMMLAR", "SMMLS", "SMMLSR", "SMUAD", "SMUADX", "SMUSD",
           "SMUSDX")
DIV = _ids("SDIV", "UDIV")
DSP = _ids(*[p + op for p in ("S", "U", "Q", "SH", "UQ", "UH")
             for op in ("ADD16", "ADD8", "SUB16", "SUB8", "ASX", "SAX")],
           "QADD", "QSUB", "QDADD", "QDSUB", "SEL", "USAD8", "USADA8", "SSAT16", "USAT16", "SXTAB16",
           "SXTB16", "UXTAB16", "UXTB16", "PKHBT", "PKHTB")
BRANCH = _ids("B", "BL", "BX", "BLX", "CBZ", "CBNZ", "TBB", "TBH")
IT = _ids("IT")


def decode(code, addr):
    """Instructions of code at addr: a list of dicts (class and what the
    cycle models read)."""
    out, end = [], addr
    for i in _md.disasm(code, addr):
        end = i.address + i.size
        rd, wr = i.regs_access()
        ops = i.operands
        pc_write = C.ARM_REG_PC in wr
        if i.id in (LOADM | STOREM):
            nregs = sum(1 for o in ops if o.type == C.ARM_OP_REG) - (0 if i.id in _ids("POP", "PUSH") else 1)
        else:
            nregs = 2 if i.id in LOAD2 | STORE2 else 1
        mem = [o.mem for o in ops if o.type == C.ARM_OP_MEM]
        addr_regs = {r for m in mem for r in (m.base, m.index) if r}
        if i.id in LOAD1 | LOAD2 | LOADM:
            cls = "load"
        elif i.id in STORE1 | STORE2 | STOREM:
            cls = "store"
        elif i.id in MUL:
            cls = "mul"
        elif i.id in DIV:
            cls = "div"
        elif i.id in DSP:
            cls = "dsp"
        elif i.id in IT:
            cls = "it"
        else:
            cls = "other"
        out.append({
            "cls": cls, "id": i.id, "size": i.size, "text": f"{i.mnemonic} {i.op_str}",
            "branch": i.id in BRANCH or (pc_write and cls != "store"),
            "cond_branch": i.id in BRANCH and (i.cc not in (C.ARM_CC_AL, C.ARM_CC_INVALID) or
                                              i.id in _ids("CBZ", "CBNZ")),
            "single": i.id in LOAD1 | STORE1, "wide": i.id in LOAD2 | STORE2 | LOADM | STOREM,
            "nregs": nregs, "tb": i.id in _ids("TBB", "TBH"),
            "reg_offset": any(m.index for m in mem), "addr_regs": addr_regs,
            "writes": set(wr), "dst": ops[0].reg if ops and ops[0].type == C.ARM_OP_REG else 0,
        })
    if end != addr + len(code):
        raise RuntimeError(f"could not decode the code at {end:#x} (block {addr:#x}+{len(code)})")
    return out


# ---- cycle models ------------------------------------------------------------
def m4_block_cycles(ins, taken, bound):
    """Cortex-M4 cycles of one pass over a block (ins) whose last instruction
    branched (taken) or not, at bound "lo" (P = 1, divides 2 cycles, IT
    folded, no address-generation stalls) or "hi" (P = 3, divides 12, IT 1
    cycle, a load or store whose address register the instruction before
    wrote stalls a cycle). Timings: Cortex-M4 TRM r0p1 (ARM 100166_0001_00),
    3.3.1 table 3-1 and 3.3.2 load/store timings."""
    P, div, it = (1, 2, 0) if bound == "lo" else (3, 12, 1)
    cyc, prev = 0, None
    for k, x in enumerate(ins):
        last = k == len(ins) - 1
        c = 1
        if x["cls"] == "it":
            c = it
        elif x["cls"] == "div":
            c = div
        elif x["wide"]:
            c = 1 + x["nregs"]  # LDM/STM/PUSH/POP/LDRD/STRD: 1 + N, never pipelined
        elif x["single"]:
            piped = prev is not None and prev["single"] and prev["cls"] == "load" and \
                not (prev["dst"] in x["addr_regs"])
            if x["cls"] == "store" and not x["reg_offset"]:
                c = 1  # STR Rx,[Ry,#imm]: the store overlaps the next instruction
            else:
                c = 1 if piped else 2
        if bound == "hi" and (x["single"] or x["wide"]) and prev is not None and \
                prev["cls"] not in ("load", "store") and prev["writes"] & x["addr_regs"]:
            c += 1
        if x["branch"]:
            if x["tb"]:
                c = 2 + P
            elif last and taken:
                c += P  # B/BL/BX/BLX/CBZ taken: 1 + P; LDR/POP to PC: their cost + P
            elif not x["cond_branch"]:
                c += P  # an unconditional branch is always taken
        cyc += c
        prev = x
    return cyc


def m7_block_cycles(ins, taken, bound):
    """Cortex-M7 cycles of a block, bounds only: its TRM (ARM DDI 0489)
    describes a dual-issue six-stage pipeline with branch prediction and
    gives no instruction timing table. lo: perfect pairing (half a cycle an
    instruction, LDM/STM/PUSH/POP a 64-bit pair a cycle), divides 2,
    branches predicted; hi: single issue, divides 12, every taken branch
    2 cycles more (a miss in the branch target cache). Caches (or TCM)
    always hit."""
    cyc = 0.0
    for k, x in enumerate(ins):
        if x["cls"] == "div":
            c = 2 if bound == "lo" else 12
        elif x["wide"]:
            c = (x["nregs"] + 1) // 2 if bound == "lo" else x["nregs"]
        else:
            c = 0.5 if bound == "lo" else 1
        if bound == "hi" and x["branch"] and (k == len(ins) - 1 and taken or not x["cond_branch"]):
            c += 2
        cyc += c
    return cyc


MODELS = {"m4": m4_block_cycles, "m7": m7_block_cycles}


# ---- the run -----------------------------------------------------------------
class Run:
    def __init__(self, elf, cpu, regions=("bloom_init", "bloom_process"), method="block", patch=None):
        self.segs, self.syms, self.funcs = read_elf(elf)
        self.func_starts = [f[0] for f in self.funcs]
        self.cpu, self.method = cpu, method
        self.entry = {}
        for r in regions:
            if r not in self.syms:
                raise SystemExit(f"{elf}: no symbol {r}")
            self.entry[self.syms[r] & ~1] = r
        self.uc = uc = unicorn.Uc(unicorn.UC_ARCH_ARM, unicorn.UC_MODE_THUMB | unicorn.UC_MODE_MCLASS)
        uc.ctl_set_cpu_model(CPUS[cpu][0])
        for base in (FLASH, RAM):
            uc.mem_map(base, MEM)
        uc.mem_map(SCS, 0x1000)
        uc.mem_write(SCS + 0xD00, struct.pack("<I", CPUS[cpu][1]))  # SCB->CPUID
        # Loaded where a flash programmer puts them: .data's initialisers at
        # their load address, which the reset handler copies to RAM; .bss and
        # the rest are mapped zeroed.
        for _vaddr, paddr, blob, _memsz in self.segs:
            uc.mem_write(paddr, blob)
        for name, blob in (patch or {}).items():  # patched in the image, before the copy
            uc.mem_write(self._load_addr(self.syms[name]), blob)
        self.out, self.status = [], None
        self.calls = []  # per region call: (name, {key: count}) keyed by block or instruction
        self.inside, self.ret, self.cur, self.prev = None, None, None, None
        uc.hook_add(unicorn.UC_HOOK_INTR, self._intr)
        # one hook for both: a "block" of the per-instruction hook is one instruction
        uc.hook_add(unicorn.UC_HOOK_BLOCK if method == "block" else unicorn.UC_HOOK_CODE, self._block)
        self.blocks = {}

    def _load_addr(self, vaddr):
        for v, p, blob, _memsz in self.segs:
            if v <= vaddr < v + len(blob):
                return vaddr - v + p
        raise SystemExit(f"{vaddr:#x} is not in a loaded segment")

    def _enter_leave(self, addr):
        if self.inside is None:
            name = self.entry.get(addr)
            if name is not None:
                self.inside, self.ret = name, self.uc.reg_read(U.UC_ARM_REG_LR) & ~1
                self.cur, self.prev = {}, None
                self.calls.append((name, self.cur))
        elif addr == self.ret:
            self.inside = None

    def _block(self, uc, addr, size, _):
        if self.prev is not None:  # the successor of the previous block inside a region
            k = (self.prev, addr)
            self.cur[k] = self.cur.get(k, 0) + 1
            self.prev = None
        self._enter_leave(addr)
        if self.inside is not None:
            self.prev = (addr, size)

    def _intr(self, uc, intno, _):
        pc = uc.reg_read(U.UC_ARM_REG_PC)
        if uc.mem_read(pc, 2) != b"\xab\xbe":  # bkpt 0xAB
            raise SystemExit(f"exception {intno} at {pc:#x}: not a semihosting call")
        op, arg = uc.reg_read(U.UC_ARM_REG_R0), uc.reg_read(U.UC_ARM_REG_R1)
        if op == 0x04:  # SYS_WRITE0
            s = bytearray()
            while (c := uc.mem_read(arg + len(s), 1)) != b"\0":
                s += c
            self.out.append(s.decode())
        elif op in (0x18, 0x20):  # SYS_EXIT, SYS_EXIT_EXTENDED
            reason, status = struct.unpack("<II", uc.mem_read(arg, 8)) if op == 0x20 else (arg, 0)
            self.status = status if reason == 0x20026 else (status or 1)
            uc.emu_stop()
            return
        else:
            raise SystemExit(f"semihosting call {op:#x} not served")
        uc.reg_write(U.UC_ARM_REG_PC, (pc + 2) | 1)

    def run(self, limit=2_000_000_000):
        """From reset to the firmware's semihosting exit; returns its status."""
        sp, reset = struct.unpack("<II", self.uc.mem_read(FLASH, 8))
        self.uc.reg_write(U.UC_ARM_REG_SP, sp)
        self.uc.emu_start(reset | 1, HALT, count=limit)
        if self.status is None:
            raise SystemExit("the firmware stopped without exiting through semihosting")
        return self.status

    def call(self, func, args=()):
        """Call func(args...) directly and return r0 (the self-test's way)."""
        for r, v in zip((U.UC_ARM_REG_R0, U.UC_ARM_REG_R1, U.UC_ARM_REG_R2, U.UC_ARM_REG_R3), args):
            self.uc.reg_write(r, v)
        self.uc.reg_write(U.UC_ARM_REG_SP, RAM + MEM - 16)
        self.uc.reg_write(U.UC_ARM_REG_LR, HALT | 1)
        self.uc.emu_start(self.syms[func] | 1, HALT)
        return self.uc.reg_read(U.UC_ARM_REG_R0)

    def _decoded(self, addr, size):
        k = (addr, size)
        if k not in self.blocks:
            self.blocks[k] = decode(bytes(self.uc.mem_read(addr, size)), addr)
        return self.blocks[k]

    def function_of(self, addr):
        i = bisect.bisect_right(self.func_starts, addr) - 1
        if i >= 0 and addr < self.funcs[i][0] + self.funcs[i][1]:
            return self.funcs[i][2]
        return "?"

    def by_function(self, counts):
        """Instructions of one call's counts per function (blocks never
        straddle functions)."""
        f = {}
        for ((addr, size), _nxt), n in counts.items():
            name = self.function_of(addr)
            f[name] = f.get(name, 0) + n * len(self._decoded(addr, size))
        return f

    def tally(self, counts):
        """Classes and cycle bounds of one call's counts."""
        t = dict.fromkeys(CLASSES, 0)
        t.update(insns=0, m4_lo=0, m4_hi=0, m7_lo=0.0, m7_hi=0.0)
        for ((addr, size), nxt), n in counts.items():
            ins = self._decoded(addr, size)
            taken = nxt != addr + size
            for k, x in enumerate(ins):
                cls = x["cls"]
                if x["branch"]:  # a POP or LDR to the PC counts as a branch
                    if k == len(ins) - 1:
                        cls = "taken" if taken else "nottaken"
                    else:  # never seen: translation blocks end at branches
                        cls = "nottaken" if x["cond_branch"] else "taken"
                t[cls] += n
                t["insns"] += n
            for m in ("m4", "m7"):
                for b in ("lo", "hi"):
                    t[f"{m}_{b}"] += n * MODELS[m](ins, taken, b)
        return t


def main(argv):
    import argparse
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("elf")
    ap.add_argument("--cpu", choices=CPUS, required=True)
    ap.add_argument("--job", help="fw_cost_job: preset,levels,width,height,strip")
    ap.add_argument("--method", choices=("block", "insn"), default="block")
    a = ap.parse_args(argv)
    patch = {"fw_cost_job": struct.pack("<5i", *map(int, a.job.split(",")))} if a.job else None
    r = Run(a.elf, a.cpu, method=a.method, patch=patch)
    st = r.run()
    for line in r.out:
        sys.stdout.write(line)
    print(f"status {st}")
    for name in ("bloom_init", "bloom_process"):
        calls = [c for n, c in r.calls if n == name]
        tot = dict.fromkeys(CLASSES + ("insns", "m4_lo", "m4_hi", "m7_lo", "m7_hi"), 0)
        for c in calls:
            for k, v in r.tally(c).items():
                tot[k] += v
        print(f"count {name} calls {len(calls)} " + " ".join(f"{k} {v:.10g}" for k, v in tot.items()))
    return 0 if st == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
