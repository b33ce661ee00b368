#!/usr/bin/env python3
"""Runs a build command and passes its output through, adding to each of CMake's progress lines
("[ 45%] Building CXX object ...") the time elapsed and an estimate of the time left.

    scripts/build_progress.py COMMAND [ARG...]

The estimate extrapolates the pace so far: elapsed * (100 - p) / p at p percent. CMake's percent counts
build steps (mostly object files), not seconds, so a step that compiles slowly (a precompiled header, a
unity batch) makes it uneven; it is printed from 5 % and 5 s on, as "about". The exit status is the
command's; the last line gives the build's wall time.
"""
import re
import subprocess
import sys
import time

PERCENT = re.compile(r"^\[\s*(\d+)%\]")


def clock(seconds):
    m, s = divmod(int(round(seconds)), 60)
    return f"{m} min {s:02d} s" if m else f"{s} s"


def main(argv):
    if not argv:
        sys.exit(__doc__)
    start = time.monotonic()
    with subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, bufsize=1) as proc:
        for line in proc.stdout:
            line = line.rstrip("\n")
            m = PERCENT.match(line)
            elapsed = time.monotonic() - start
            if m and int(m.group(1)) >= 5 and elapsed >= 5 and int(m.group(1)) < 100:
                p = int(m.group(1))
                line += f"  ({clock(elapsed)} so far, about {clock(elapsed * (100 - p) / p)} left)"
            print(line, flush=True)
    print(f"== build: {clock(time.monotonic() - start)}" + ("" if proc.returncode == 0 else f", failed ({proc.returncode})"),
          flush=True)
    return proc.returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
