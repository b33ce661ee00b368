#!/usr/bin/env python3
"""check_paper_runs.py SOURCE_DIR BUILD_DIR WORK_DIR: make reruns a results directory that is not its
paper scene's run, whatever its timestamps (scripts/paper_runs.py and the Makefile's rule): a run with
--set overrides, one without every study of its scene, one of another scene; the paper run itself is
left alone."""
import json
import os
import pathlib
import shutil
import subprocess
import sys

source, build, work = (pathlib.Path(a).resolve() for a in sys.argv[1:4])
shutil.rmtree(work, ignore_errors=True)
scene = "experiments/euler_compensation/euler_compensation.toml"
study_list = [{"name": s, "ran": True} for s in ("decay", "gompertz", "oscillator", "convergence", "cost")]
paper = {"scene_file": scene, "overrides": [], "scene": {}, "studies": [s["name"] for s in study_list],
         "study_list": study_list}
cases = {"paper": (paper, False),
         "set": (dict(paper, overrides=["convergence.t_end=40"]), True),
         "one_study": (dict(paper, studies=["convergence"]), True),
         "quick_scene": (dict(paper, scene_file="experiments/euler_compensation/quick.toml"), True),
         "scene_studies": (dict(paper, scene={"studies": ["decay"]}, studies=["decay"]), False)}
problems = []
for name, (run, stale) in cases.items():
    results = work / name
    (results / "euler_compensation").mkdir(parents=True)
    run_json = results / "euler_compensation" / "run.json"
    run_json.write_text(json.dumps(run))
    listed = subprocess.run([sys.executable, str(source / "scripts" / "paper_runs.py"), "stale", str(results),
                             f"euler_compensation={scene}"], cwd=source, capture_output=True, text=True).stdout.split()
    if (listed == ["euler_compensation"]) != stale:
        problems.append(f"{name}: paper_runs.py lists {listed}, expected {'a rerun' if stale else 'none'}")
    if name in ("paper", "set"):  # make's rule, with run.json newer than the binary and the scenes
        os.utime(run_json, None)
        dry = subprocess.run(["make", "-n", "-C", str(source), f"BUILD={build}", f"RESULTS={results}",
                              str(run_json)], capture_output=True, text=True)
        reruns = "--scene" in dry.stdout
        if reruns != stale:
            problems.append(f"{name}: make {'does not rerun' if stale else 'reruns'} it: {dry.stdout}{dry.stderr}")
for p in problems:
    print("check_paper_runs:", p)
print(f"check_paper_runs: {len(cases)} cases, {len(problems)} problems")
sys.exit(1 if problems else 0)
