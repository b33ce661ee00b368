#!/usr/bin/env python3
"""The reproducers of issue 51, as a user types them, on the built executables (the library's own checks are
unit tests: Checkpoint.*, ResultsDir.*, Scene.*).

    reproducers.py BIN_DIR SOURCE_DIR WORK

1. Records out of their place: energy_map's map stopped after two rounds, records 0 and 1 of its log swapped,
   or record 0 replaced by the same task's record of a run with other scene values: --resume exits 2 naming
   the log and the record.
2. A staging directory that holds nothing but a killed run's temporary (the marker's, or the write probe's):
   the next run, with --resume or without, completes.
3. A result inside another: --out inside a complete results directory, or on a directory that holds one, exits 2
   and changes neither.
4. A checkpoint header that is a directory, or a symbolic link that loops: --resume exits 2 naming it.
5. A scene that cannot be read (/proc/self/mem), and a scene key with a newline: exit 2, one line, escaped.
Prints one line per failure and a tally; exits 1 on any.
"""
import shutil
import struct
import subprocess
import sys
from pathlib import Path

failures = []


def run(args):
    p = subprocess.run([str(a) for a in args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, timeout=60)
    return p.returncode, p.stderr.strip()


def expect(label, outcome, code, *needles, one_line=False):
    rc, err = outcome
    if rc != code or any(n not in err for n in needles) or (one_line and len(err.splitlines()) != 1):
        failures.append(label)
        print(f"FAIL {label}: exit {rc} (want {code} naming {needles}): {err[-300:]}", flush=True)


def records(log):
    """(offset, bytes) of each record of a checkpoint log (runner/checkpoint.hpp): count L, L doubles, check."""
    data, at, out = log.read_bytes(), 16, []
    while at < len(data):
        size = 16 + 8 * struct.unpack_from("<Q", data, at)[0]
        out.append((at, data[at:at + size]))
        at += size
    return out


def records_out_of_place(bins, work):
    base = [bins / "energy_map", "--quick", "--study", "map", "--threads", "1", "--set", "grid.nx=16", "--set",
            "grid.ny=16", "--set", "checkpoint.interval=0", "--set", "checkpoint.stop_after=2"]
    r1, r2 = work / "r1", work / "r2"
    expect("stop after two rounds", run([*base, "--out", r1]), 3)
    expect("another scene's run", run([*base, "--set", "pendulum.g=0.03", "--out", r2]), 3)
    log = Path(f"{r1}.partial") / "map.cartesian.checkpoint.log"
    kept = log.read_bytes()
    (a, ra), (b, rb) = records(log)[:2]
    log.write_bytes(kept[:a] + rb + ra + kept[b + len(rb):])
    expect("records 0 and 1 swapped", run([*base, "--resume", "--out", r1]), 2, str(log), "record 0")
    other = records(Path(f"{r2}.partial") / "map.cartesian.checkpoint.log")[0][1]
    log.write_bytes(kept[:a] + other + kept[a + len(ra):])
    expect("record 0 of another scene's run", run([*base, "--resume", "--out", r1]), 2, str(log), "record 0")
    header = Path(f"{r1}.partial") / "map.cartesian.checkpoint.json"
    log.write_bytes(kept)
    header.rename(header.with_suffix(".kept"))
    header.mkdir()
    expect("a header that is a directory", run([*base, "--resume", "--out", r1]), 2, str(header), "is a directory")
    header.rmdir()
    header.symlink_to(header.name)
    expect("a header that is a looping link", run([*base, "--resume", "--out", r1]), 2, str(header),
           "cannot be examined")


def temporaries_alone(bins, work):
    for temporary in ("..geomint-staging.tmp-4242", ".write-probe.tmp-4242"):
        for resume in ([], ["--resume"]):
            out = work / f"temp{temporary[:6]}{len(resume)}"
            Path(f"{out}.partial").mkdir(parents=True)
            (Path(f"{out}.partial") / temporary).write_text("x")
            expect(f"only {temporary} in DIR.partial, {resume}",
                   run([bins / "euler_compensation", "--quick", "--study", "decay", *resume, "--out", out]), 0)


def nested(bins, work):
    outer, holder = work / "outer", work / "holder"
    decay, jump = [bins / "euler_compensation", "--quick", "--study", "decay"], [bins / "triple_jump", "--quick"]
    expect("a complete outer run", run([*jump, "--out", outer]), 0)
    expect("a complete inner run", run([*decay, "--out", holder / "inner"]), 0)
    before = {d: sorted((p.name, p.read_bytes()) for p in d.iterdir()) for d in (outer, holder / "inner")}
    expect("--out inside a result", run([*decay, "--out", outer / "inner"]), 2, "lies inside the results directory",
           one_line=True)
    expect("--out holding a result", run([*jump, "--out", holder]), 2, "holds the results directory", one_line=True)
    if any(sorted((p.name, p.read_bytes()) for p in d.iterdir()) != files for d, files in before.items()):
        failures.append("nested: a complete result changed")
        print("FAIL nested: a complete result changed", flush=True)


def scenes(bins, work, source):
    expect("--scene /proc/self/mem", run([bins / "energy_map", "--scene", "/proc/self/mem", "--plan"]), 2,
           "/proc/self/mem", one_line=True)
    scene = work / "newline.toml"
    scene.write_text(f'base = "{source / "experiments/energy_map/quick.toml"}"\n"a\\nb" = 1\n')
    expect("a key with a newline", run([bins / "energy_map", "--scene", scene, "--plan"]), 2, "a\\nb", one_line=True)


def main():
    bins, source, work = (Path(a).resolve() for a in sys.argv[1:4])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    for check in (records_out_of_place, temporaries_alone, nested):
        check(bins, work)
    scenes(bins, work, source)
    print(f"issue 51's reproducers: {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
