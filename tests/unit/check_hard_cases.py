#!/usr/bin/env python3
"""check_hard_cases.py SOURCE_DIR: the hard-cases chapter (scripts/report.py hard_cases_tex) shows each case's
measured value and bound from its HARDCASE lines (tests/hard_case.hpp), a refusal with its message and what it
must name, and refuses a hard case that records nothing; the fixtures a run needed are left out."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(sys.argv[1]) / "scripts"))
import report  # noqa: E402


def junit(cases):
    body = "".join(f'<testcase name="{n}" time="0.5" status="run"><system-out>{out}</system-out></testcase>'
                   for n, out in cases)
    return f'<?xml version="1.0"?><testsuite tests="{len(cases)}">{body}</testsuite>'


BOUND = 'HARDCASE {"what":"spectral radius at 0.999 x the bound","measured":0.93,"relation":"&lt;=","bound":1.0}'
REFUSAL = ('HARDCASE {"what":"a NaN step","measured":"decay.h = nan (from --set)","relation":"names",'
           '"bound":["decay.h"]}')
problems = []
tex = report.hard_cases_tex(junit([("Lobatto.StabilityBoundOfEquation10", BOUND), ("Scene.RejectsNan", REFUSAL),
                                   ("ti_drift.quick_run", "")]),
                            hard={"Lobatto.StabilityBoundOfEquation10", "Scene.RejectsNan"})
for needle in ("$0.9300$", r"$\le$ $1$", "refused: ``", r"decay.\allowbreak{}h = nan", "must name ``"):
    if needle not in tex:
        problems.append(f"the chapter lacks {needle!r}")
if "quick" in tex:
    problems.append("a fixture (a quick run) is listed as a hard case")
try:
    report.hard_cases_tex(junit([("Lobatto.StabilityBoundOfEquation10", BOUND), ("Scene.Silent", "no line")]))
    problems.append("a hard case that records nothing is accepted")
except SystemExit as e:
    if "Scene.Silent" not in str(e):
        problems.append(f"the refusal does not name the silent case: {e}")
for p in problems:
    print("check_hard_cases:", p)
print(f"check_hard_cases: {len(problems)} problems")
sys.exit(1 if problems else 0)
