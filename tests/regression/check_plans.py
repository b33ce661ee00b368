#!/usr/bin/env python3
"""check_plans.py BUILD_DIR WORK_DIR EXPERIMENT...: --plan matches the run. Each experiment's quick scene runs
on 2 threads into WORK_DIR (alone: the test runs serially, so that no other test's load is in the times),
and the same binary's --plan --json of that scene estimates each study's wall time; a study that took at
least 50 ms must have been planned within a factor of 10 of its run (a ratio of plan and run, not a timing
assertion)."""
import json
import pathlib
import shutil
import subprocess
import sys

FACTOR, SHORTEST_S = 10.0, 0.05
build, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
shutil.rmtree(work, ignore_errors=True)
problems, compared = [], 0
for experiment in sys.argv[3:]:
    binary, out = str(build / "bin" / experiment), work / experiment
    plan = json.loads(subprocess.run([binary, "--quick", "--threads", "2", "--plan", "--json"], capture_output=True,
                                     text=True, check=True).stdout)
    subprocess.run([binary, "--quick", "--threads", "2", "--out", str(out)], capture_output=True, check=True)
    ran = json.loads((out / "run.json").read_text(encoding="utf-8"))["study_wall_s"]
    for st in plan["studies"]:
        actual, planned = ran.get(st["study"]), st["wall_s"]
        if actual is None or actual < SHORTEST_S:
            continue
        compared += 1
        ratio = planned / actual if planned else 0.0
        line = f"{experiment} {st['study']}: planned {planned:.3g} s, ran {actual:.3g} s (ratio {ratio:.3g})"
        print("check_plans:", line)
        if not 1 / FACTOR <= ratio <= FACTOR:
            problems.append(line)
shutil.rmtree(work, ignore_errors=True)
for p in problems:
    print("check_plans: off by more than 10x:", p)
print(f"check_plans: {compared} studies compared, {len(problems)} off by more than {FACTOR:g}x")
sys.exit(1 if problems or not compared else 0)
