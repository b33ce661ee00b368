#!/usr/bin/env python3
"""Each counted kernel's count is its object's, and its arithmetic alone issues exactly that.

    check_kernel_arithmetic.py HEADER OBJECT...
    check_kernel_arithmetic.py --loops OBJECT FUNCTION

HEADER is src/geomint/sweep/arithmetic_counts.hpp, whose OpMix constants are the counts of the kernels'
objects (bench/README.md); the OBJECTs are the library's arithmetic_ceiling_<isa>.cpp.o and the kernels'
(RECOUNT below); others are ignored.

- Each kernel's mix must be read off its own object as it is now. The step total of a loop of the kernel's
  function is its own instructions plus, for each loop nested in it (a pass over the batch's vectors),
  passes - 1 times that loop's. Of the loops whose step total has the mix's estimates and divisions, those
  that hold no other such loop are the kernel's steps (the one without a test, the replay with its tests, and
  the like); one of them must have exactly the mix, kind by kind. A kernel changed without a recount of its
  mix fails here, and so does a count read off a loop around the step (the AVX2 Lennard-Jones lanes' loop
  over their groups of registers).
- In each arithmetic object, the loop of every `issue<OpMix{...}>` (its longest backward jump) must hold the
  instructions of that mix, kind by kind (other vector arithmetic is not counted, and none is issued), and the
  mixes of an object must be those of the header's list for its instruction set (kAvx512Mixes, kAvx2Mixes). A
  compiler that folded an operation with a constant (a + 0, a and all-ones), merged two or left one out would
  fail it.

--loops prints the counts of every loop of FUNCTION (a substring of its demangled name) in OBJECT: how the
kernels' own counts are read (bench/README.md). Exit 1 listing what is wrong.
"""
import collections
import re
import subprocess
import sys

FIELDS = ("fma", "add", "minmax", "logic", "estimate", "div", "trajectory_steps")
KIND = [  # (the instruction's mnemonic, the OpMix field it counts for)
    (re.compile(r"v(mul|f[n]?m(add|sub)\d{3})[ps]d$"), "fma"),
    (re.compile(r"v(add|sub)[ps]d$"), "add"),
    (re.compile(r"v(min|max)[ps]d$|vcmp\w*[ps]d$"), "minmax"),
    (re.compile(r"v(p?andn?|p?xor|p?or)(pd|q|d)?$"), "logic"),
    (re.compile(r"vrsqrt(14pd|ps)$|vrcp(14pd|ps)$"), "estimate"),
    (re.compile(r"vdiv[ps]d$"), "div"),
    (re.compile(r"vcvt(pd2ps|ps2pd)y?$"), "convert"),  # AVX2's estimate from single precision: two per rsqrt
]
# The counted kernels: header constant -> (object, a substring of the kernel's function). A pass over a register of
# lanes computes WIDTH of the mix's trajectory-steps: the energy map's pass loops run trajectory_steps / WIDTH times
# per step (64 trajectories, 8 or 4 to a register), the Lennard-Jones lanes' step is one register.
RECOUNT = {
    "kEnergyMapAvx512Cartesian": ("energy_map_kernel_avx512", "batch<false>"),
    "kEnergyMapAvx512Polar": ("energy_map_kernel_avx512", "batch<true>"),
    "kEnergyMapAvx2Cartesian": ("energy_map_kernel_avx2", "batch<false>"),
    "kEnergyMapAvx2Polar": ("energy_map_kernel_avx2", "batch<true>"),
    "kLennardJonesAvx512": ("ensemble_kernel_avx512", "simplified_ti_steps<geomint::LennardJones<9> >"),
    "kLennardJonesAvx2": ("ensemble_kernel_avx2", "simplified_ti_steps<geomint::LennardJones<9> >"),
}
WIDTH = {"avx512": 8, "avx2": 4}  # doubles per register
LINE = re.compile(r"^\s+([0-9a-f]+):\s+(\S+)\s*(.*)$")
JUMP = re.compile(r"^j\w+$")


def disassemble(obj):
    """{demangled function name: [(address, mnemonic, operands)]}."""
    out = subprocess.run(["objdump", "-d", "-C", "--no-show-raw-insn", obj], capture_output=True, text=True, check=True)
    functions, current = {}, None
    for line in out.stdout.splitlines():
        head = re.match(r"^[0-9a-f]+ <(.*)>:$", line)
        if head:
            current = functions.setdefault(head.group(1), [])
        elif current is not None and (m := LINE.match(line)):
            current.append((int(m.group(1), 16), m.group(2), m.group(3)))
    return functions


def loops(instructions):
    """(start, end) address of every backward jump within the function, longest first."""
    found = []
    for address, mnemonic, operands in instructions:
        target = re.match(r"([0-9a-f]+)\b", operands)
        if JUMP.match(mnemonic) and target and int(target.group(1), 16) <= address:
            found.append((int(target.group(1), 16), address))
    return sorted(set(found), key=lambda r: r[0] - r[1])


def mix(instructions, start, end):
    """Counts per OpMix field (and 'convert') of the vector instructions in [start, end]."""
    counts = collections.Counter()
    for address, mnemonic, operands in instructions:
        if not start <= address <= end:
            continue
        regs = re.findall(r"%[xyz]mm\d+", operands)
        if mnemonic.startswith(("vxor", "vpxor")) and len(regs) == 3 and len(set(regs)) == 1:
            continue  # a zeroing idiom, no arithmetic
        for pattern, field in KIND:
            if pattern.match(mnemonic):
                counts[field] += 1
                break
    return counts


def header_values(header):
    """{name: the values of each OpMix constant} of the header (OpMix name{fma, add, ...})."""
    text = open(header).read()
    return {name: tuple(int(x) for x in body.split(","))
            for name, body in re.findall(r"(k\w+)\{(\d+(?:, \d+){%d})\}" % (len(FIELDS) - 1), text)}


def header_mixes(header):
    """{isa: {the values of each OpMix of its list}} from the header (OpMix constants and kAvx512Mixes{...})."""
    values = header_values(header)
    return {isa.lower(): {values[n.strip()] for n in names.split(",")}
            for isa, names in re.findall(r"inline constexpr std::array k(Avx\d+)Mixes\{([^}]*)\};", open(header).read())}


def step_total(instructions, loop, all_loops, passes):
    """The counts of `loop` plus passes - 1 times those of each loop nested in it (not in another nested one)."""
    inner = [r for r in all_loops if r != loop and loop[0] <= r[0] and r[1] <= loop[1]]
    outermost = [r for r in inner if not any(o != r and o[0] <= r[0] and r[1] <= o[1] for o in inner)]
    total = mix(instructions, *loop)
    for r in outermost:
        for field, n in mix(instructions, *r).items():
            total[field] += (passes - 1) * n
    return total


def recount(header, objects):
    """Problems of each counted kernel's mix against its own object (RECOUNT)."""
    values, errors = header_values(header), []
    by_stem = {re.sub(r"\.cpp\.o$", "", obj.rsplit("/", 1)[-1]): obj for obj in objects}
    for name, (stem, function) in RECOUNT.items():
        if name not in values:
            errors.append(f"{name}: not in {header}")
            continue
        if stem not in by_stem:
            errors.append(f"{name}: no object {stem}.cpp.o among the arguments")
            continue
        want = dict(zip(FIELDS, values[name]))
        passes = want["trajectory_steps"] // WIDTH[stem.rsplit("_", 1)[-1]]
        found = [(n, ins) for n, ins in disassemble(by_stem[stem]).items() if function in n]
        if len(found) != 1:
            errors.append(f"{name}: {len(found)} functions named like {function} in {stem}.cpp.o")
            continue
        fname, instructions = found[0]
        all_loops = loops(instructions)
        totals = {r: step_total(instructions, r, all_loops, passes) for r in all_loops}
        steps = [r for r, t in totals.items() if t["estimate"] == want["estimate"] and t["div"] == want["div"]]
        innermost = [r for r in steps if not any(o != r and r[0] <= o[0] and o[1] <= r[1] for o in steps)]
        converts = 2 * want["estimate"] if "avx2" in stem else 0
        if not any(all(totals[r][f] == want[f] for f in FIELDS[:-1]) and totals[r]["convert"] == converts
                   for r in innermost):
            seen = "; ".join(f"[{r[0]:x}, {r[1]:x}] " + ", ".join(f"{k} {v}" for k, v in sorted(totals[r].items()))
                             for r in innermost) or "none"
            errors.append(f"{name}: no step loop of {fname[:50]} in {stem}.cpp.o holds the header's mix {values[name][:-1]};"
                          f" the loops with its estimates and divisions hold: {seen} (a recount: --loops)")
    return errors


def check(header, objects):
    declared = header_mixes(header)
    if not declared:
        return ["no list of mixes in " + header]
    errors = recount(header, objects)
    for obj in objects:
        arithmetic = re.search(r"arithmetic_ceiling_(\w+)\.cpp\.o$", obj)
        if not arithmetic:
            continue
        isa = arithmetic.group(1)
        expected = declared.get(isa, set())
        seen = set()
        for name, instructions in disassemble(obj).items():
            m = re.search(r"issue<geomint::OpMix\{([\d, ]*)\}>", name)
            if not m:
                continue
            values = [int(x) for x in m.group(1).split(",") if x.strip()]
            want = tuple(values + [0] * (len(FIELDS) - len(values)))  # (trailing zero members are not printed)
            seen.add(want)
            found = loops(instructions)
            if not found:
                errors.append(f"{obj}: {name}: no loop")
                continue
            got = mix(instructions, *found[0])
            for field, n in zip(FIELDS[:-1], want):
                if got[field] != n:
                    errors.append(f"{obj}: {name}: {got[field]} {field} instructions in its loop, the mix has {n}")
            if got["convert"] != (2 * want[FIELDS.index("estimate")] if isa == "avx2" else 0):
                errors.append(f"{obj}: {name}: {got['convert']} conversions for {want[FIELDS.index('estimate')]} estimates")
        if seen != expected:
            errors.append(f"{obj}: mixes {sorted(seen)}, the header's for {isa} {sorted(expected)}")
    return errors


def main(argv):
    if len(argv) == 4 and argv[1] == "--loops":
        functions = disassemble(argv[2])
        for name, instructions in functions.items():
            if argv[3] in name:
                for start, end in sorted(loops(instructions)):
                    counts = mix(instructions, start, end)
                    print(f"{name[:60]} [{start:x}, {end:x}]: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
        return 0
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    errors = check(argv[1], argv[2:])
    for e in errors:
        print("check_kernel_arithmetic:", e, file=sys.stderr)
    print(f"check_kernel_arithmetic: {len(argv) - 2} objects, {'ok' if not errors else f'{len(errors)} problems'}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
