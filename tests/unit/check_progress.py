#!/usr/bin/env python3
"""check_progress.py SOURCE_DIR: the first run's progress lines (README "Progress").

- scripts/build_progress.py passes a build's output through, adds the time so far and the time left at the
  pace so far to a CMake percentage line (50 % after 5 s: about 5 s left), ends with the build's wall time,
  and exits with the build's status;
- tests/figures/render_figures.sh under GEOMINT_RENDER_PROGRESS="TOTAL START FILE" ends each "ok" line with
  "[k/TOTAL, ... so far, about ... left]", k counting the figures rendered so far.
Exit 1 listing what is wrong."""
import os
import pathlib
import subprocess
import sys
import tempfile
import time

source = pathlib.Path(sys.argv[1]).resolve()
problems = []

fake_build = "import sys, time; time.sleep(5.2); print('[ 50%] Building CXX object x.o'); sys.exit(3)"
r = subprocess.run([sys.executable, source / "scripts/build_progress.py", sys.executable, "-c", fake_build],
                   capture_output=True, text=True)
lines = r.stdout.splitlines()
if r.returncode != 3:
    problems.append(f"build_progress.py exits {r.returncode}, not the build's 3")
if not lines or not lines[0].startswith("[ 50%] Building CXX object x.o  (5 s so far, about 5 s left)"):
    problems.append(f"the percentage line reads {lines[:1]}")
if not lines or not (lines[-1].startswith("== build: ") and lines[-1].endswith("failed (3)")):
    problems.append(f"the last line reads {lines[-1:]}")

with tempfile.TemporaryDirectory() as tmp:
    tmp = pathlib.Path(tmp)
    (tmp / "results").mkdir()
    script = tmp / "progress_probe.gp"
    script.write_text("set terminal pdfcairo; set output out.'/progress_probe.pdf'; plot x\n"
                      "set terminal pngcairo; set output out.'/progress_probe.png'; plot x\n")
    env = dict(os.environ, GEOMINT_RENDER_PROGRESS=f"2 {time.time():.9f} {tmp / 'rendered'}")
    for k in (1, 2):
        r = subprocess.run([source / "tests/figures/render_figures.sh", "--check-later", tmp / "unchecked",
                            tmp / "results", tmp / "out", script], capture_output=True, text=True, env=env)
        out = r.stdout.strip()
        if r.returncode != 0 or f"[{k}/2, " not in out or " so far, about " not in out or not out.endswith(" left]"):
            problems.append(f"render_figures.sh, figure {k} of 2: exit {r.returncode}, {out!r} {r.stderr.strip()!r}")
for p in problems:
    print("check_progress:", p)
print(f"check_progress: {len(problems)} problems")
sys.exit(1 if problems else 0)
