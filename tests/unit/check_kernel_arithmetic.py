#!/usr/bin/env python3
"""Each counted kernel's arithmetic alone issues exactly the instructions counted for it.

    check_kernel_arithmetic.py HEADER OBJECT...
    check_kernel_arithmetic.py --loops OBJECT FUNCTION

HEADER is src/geomint/sweep/arithmetic_counts.hpp, whose OpMix constants are the counts of the kernels'
objects (bench/README.md); each OBJECT an arithmetic_ceiling_<isa>.cpp.o. In each object, the loop of every
`issue<OpMix{...}>` (its longest backward jump) must hold the instructions of that mix, kind by kind (other
vector arithmetic is not counted, and none is issued), and the mixes of an object must be those of the header's
list for its instruction set (kAvx512Mixes, kAvx2Mixes). A compiler that folded an operation with a constant
(a + 0, a and all-ones), merged two or left one out would fail it.

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


def header_mixes(header):
    """{isa: {the values of each OpMix of its list}} from the header (OpMix name{fma, add, ...} and kAvx512Mixes{...})."""
    text = open(header).read()
    values = {name: tuple(int(x) for x in body.split(","))
              for name, body in re.findall(r"(k\w+)\{(\d+(?:, \d+){%d})\}" % (len(FIELDS) - 1), text)}
    return {isa.lower(): {values[n.strip()] for n in names.split(",")}
            for isa, names in re.findall(r"inline constexpr std::array k(Avx\d+)Mixes\{([^}]*)\};", text)}


def check(header, objects):
    declared, errors = header_mixes(header), []
    if not declared:
        return ["no list of mixes in " + header]
    for obj in objects:
        isa = re.search(r"arithmetic_ceiling_(\w+)\.cpp\.o$", obj).group(1)
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
