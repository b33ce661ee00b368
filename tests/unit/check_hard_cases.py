#!/usr/bin/env python3
"""check_hard_cases.py SOURCE_DIR: the hard-cases chapter (scripts/report.py hard_cases_tex) shows each case's
measured value and bound from its HARDCASE lines (tests/hard_case.hpp), a refusal with its message and what it
must name, and refuses a hard case that records nothing; the fixtures a run needed are left out. A test of the
check itself (it passes with rows that break their bound: faults it planted) is listed apart, each such row marked
as a planted fault the check rejected, never as a bare "passed" beside a broken bound; a row that breaks its bound
in a test that failed says it does not hold. A path of the machine that ran the tests is shown relative to its
source tree, or as DIR/<name> for a temporary directory."""
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
# a test of the check itself: its planted faults (a value beyond its bound, a refusal not naming a needle, an
# accepted input) are marked, the row that holds is not; the same row in a test that failed does not hold
PLANTED = ['HARDCASE {"what":"a","measured":0.5,"relation":"&lt;","bound":1.0}',
           'HARDCASE {"what":"a","measured":1.5,"relation":"&lt;=","bound":1.0}',
           'HARDCASE {"what":"a step","measured":"dt = -1: positive","relation":"names","bound":["dt","finite"]}',
           'HARDCASE {"what":"a step","measured":null,"relation":"names","bound":["dt"]}']
tex = report.hard_cases_tex(junit([("HardCase.HoldsOnlyOnItsSide", "\n".join(PLANTED)),
                                   ("Lobatto.StabilityBoundOfEquation10", BOUND)]))
meta = tex.split(report.META_KIND)[-1] if report.META_KIND in tex else ""
if "HardCase.HoldsOnlyOnItsSide" not in meta.replace("\\allowbreak{}", "") or "Lobatto" in meta:
    problems.append("the test of the check itself is not listed apart from the others")
rows = [line for line in meta.splitlines() if "\\quad" in line]
marks = ["planted fault: rejected" in line for line in rows]
if marks != [False, True, True, True]:
    problems.append(f"planted faults marked {marks}, not [False, True, True, True]: {rows}")
if "planted fault" not in tex.split(r"\endhead")[0]:
    problems.append("the chapter does not say what a planted fault is")
failed = junit([("HardCase.HoldsOnlyOnItsSide", PLANTED[1])]).replace('status="run"', 'status="fail"')
tex = report.hard_cases_tex(failed)
if "does not hold" not in tex or "planted" in tex.split(r"\endhead")[1] or "FAILED" not in tex:
    problems.append("a row that breaks its bound in a failed test is not shown as not holding")
# paths of the machine that ran the tests
PATHS = ('HARDCASE {"what":"x --scene /work/main/build/t/deep.toml","measured":"/work/main/experiments/x/quick.toml: '
         'bad; delete /tmp/geomint_test_1/tasks.checkpoint.*","relation":"names","bound":["bad"]}')
tex = report.hard_cases_tex(junit([("Scene.RejectsDeep", PATHS)]), roots=["/work/main"]).replace("\\allowbreak{}", "")
if "/work" in tex or "/tmp" in tex or any(p not in tex for p in ("build/t/deep", "experiments/x/quick", "DIR/tasks")):
    problems.append(f"the paths of the machine are shown: {tex.splitlines()[-3]}")
for p in problems:
    print("check_hard_cases:", p)
print(f"check_hard_cases: {len(problems)} problems")
sys.exit(1 if problems else 0)
