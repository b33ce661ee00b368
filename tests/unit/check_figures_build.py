#!/usr/bin/env python3
"""check_figures_build.py SOURCE_DIR BUILD_DIR: `make figures` builds what it runs and nothing else.

- The front door's `make figures` builds the CMake target geomint_figures, and no other build command
  (`make -n figures`: each `cmake --build` it would run names that target);
- that target compiles no source under tests/ or bench/, and compiles every experiment's sources
  (`make -n -B geomint_figures` in the build tree: every compile command it would run).
Exit 1 listing what is wrong."""
import pathlib
import re
import subprocess
import sys

source, build = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
problems = []


def dry_run(args, cwd):
    r = subprocess.run(["make", "-n", *args], cwd=cwd, capture_output=True, text=True)
    if r.returncode != 0:
        problems.append(f"make -n {' '.join(args)} failed: {r.stderr.strip()[-300:]}")
    return r.stdout.splitlines()


front = [l for l in dry_run(["figures", f"BUILD={build}", "RESULTS=/nonexistent/results"], source)
         if "cmake --build" in l]
if not front:
    problems.append("make -n figures runs no cmake --build")
for line in front:
    if not re.search(r"--target geomint_figures(\s|$)", line):
        problems.append(f"make figures builds more than geomint_figures: {line.strip()}")

compiled = set()
for line in dry_run(["-B", "geomint_figures"], build):
    m = re.search(r" -c (\S+\.(?:cpp|cxx|cc))\b", line)
    if m:
        compiled.add(pathlib.Path(m.group(1)))
for f in sorted(compiled):  # (a test's source, or a unity batch of them under BUILD_DIR/tests)
    for root in (build, source):
        if f.is_relative_to(root):
            rel = f.relative_to(root)
            if rel.parts[0] in ("tests", "bench"):
                problems.append(f"geomint_figures compiles {rel}")
            break
for f in sorted(source.glob("experiments/*/*.cpp")):
    if f not in compiled:
        problems.append(f"geomint_figures does not compile {f.relative_to(source)}")
for p in problems:
    print("check_figures_build:", p)
print(f"check_figures_build: {len(compiled)} sources compiled by geomint_figures, {len(problems)} problems")
sys.exit(1 if problems else 0)
