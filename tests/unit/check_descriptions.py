#!/usr/bin/env python3
"""check_descriptions.py SOURCE_DIR: what the report says a comparison or a lookup compares agrees with the record
(scripts/report_records.py), from synthetic summaries and LaTeX, no run needed. A comparison's
{scene.KEY} and {summary.KEY|fmt} become the run's values and a key the run lacks stops the report; its fits (fit
sources of its key, of its entries, or of the windows of the CSV column it summarizes) are printed from the record.
Each planted fault fails: "largest" of a value at the end time, "at the end" of a largest value, "whole run" of a key
fitted over windows, a typed window the fits do not have, two comparisons of different keys under one description,
two lookups of different keys under one description in the text, and "largest" before a lookup of an end value."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(sys.argv[1]) / "scripts"))
import report_records as rt  # noqa: E402


def fit(quantity, y, a, b, kind="slope"):
    return {"quantity": quantity, "csv": "run.csv", "x": "t", "y": y, "where": {}, "kind": kind, "from": a, "to": b}


FITS = [fit("reproduced.rate", "e", 0.0, 100.0), fit("reproduced.rate_whole", "e", 0.0, 1000.0),
        fit("windows.csv#local#0", "e", 0.0, 500.0), fit("windows.csv#local#1", "e", 500.0, 1000.0)]
GOOD = {  # (key: where, note, summary key)
    "rate": ("900 Fig. 1: the drift rate fitted over t <= 100", "", "reproduced.rate"),
    "local": ("900 Fig. 1: the largest difference of a window's rate from the prediction", "", "local.max_diff"),
    "end": ("900 Fig. 2: |H - H0| at t = {scene.t_end} under A over that under B", "", "reproduced.H_err_at_t_end"),
    "peak": ("900 Fig. 3: the largest error, {summary.reproduced.rate|percent} of the rate", "", "reproduced.max_err"),
}
BAD = {
    "end": ("900 Fig. 2: the largest |H - H0| under A over that under B", "", "reproduced.H_err_at_t_end"),
    "peak": ("900 Fig. 3: the error at the end of the run", "", "reproduced.max_err"),
    "local": ("900 Fig. 1: each window's drift rate against that of the whole run", "", "local.max_diff"),
    "rate": ("900 Fig. 1: the drift rate fitted over t <= 500", "", "reproduced.rate"),
}
SUMMARY = {"reproduced": {"rate": 0.25, "H_err_at_t_end": 1.0, "max_err": 2.0}, "local": {"max_diff": 0.01}}


def runs(entries):
    comparisons = {k: {"where": w, "note": n, "summary": s, "verdict": "reproduced"} for k, (w, n, s) in entries.items()}
    return {"r": {"summary": {**SUMMARY, "fit_sources": FITS, "comparisons": comparisons}, "run": {"scene": {"t_end": 10}}}}


def expanded(entries):
    rs = runs(entries)
    for c in rs["r"]["summary"]["comparisons"].values():
        c["where"] = rt.expand_record(c["where"], rs["r"]["summary"], rs["r"]["run"]["scene"], "r")
    return rs


problems = []
good = expanded(GOOD)
if rt.record_problems(good):
    problems.append(f"clean comparisons fail: {rt.record_problems(good)}")
wheres = {k: c["where"] for k, c in good["r"]["summary"]["comparisons"].items()}
if "at t = 10 under" not in wheres["end"] or "25 % of the rate" not in wheres["peak"]:
    problems.append(f"placeholders not expanded: {wheres}")
try:
    rt.expand_record("at t = {scene.t_max}", SUMMARY, {"t_end": 10}, "r: end")
    problems.append("a placeholder of a key the run lacks passes")
except SystemExit as e:
    if "scene.t_max" not in str(e):
        problems.append(f"the refusal of a missing key does not name it: {e}")
if rt.expand_record("at t = {scene.t_max}", SUMMARY, {"t_end": 10}, "r: end", compared=False) != "at t = (not in this run)":
    problems.append("a comparison this scene does not make stops the report on a value it lacks")
phrase = rt.record_phrase(rt.key_fits(FITS, "local.max_diff"))
if "each of 2 windows" not in phrase or r"\texttt{run.csv:e}" not in phrase.replace(r"\allowbreak{}", ""):
    problems.append(f"the fits of a summarized column read: {phrase}")
for key, entry in BAD.items():  # each fault alone, the rest clean
    found = rt.record_problems(expanded({**GOOD, key: entry}))
    if len(found) != 1 or f"r: {key}:" not in found[0]:
        problems.append(f"the planted fault of '{key}' ({entry[0]}) gives {found}")
twins = expanded({**GOOD, "twin": (GOOD["rate"][0], "", "reproduced.rate_whole")})
if not any("under one description" in p for p in rt.record_problems(twins)):
    problems.append("two comparisons of different keys under one description pass")

# The report's text: a lookup's description is the words of its sentence before it.
TEXT = r"""The fitted rate is \result[sci3]{r}{reproduced.rate}. The largest error is \result[err]{r}{reproduced.max_err},
and the error at the end of the run is \result[err]{r}{reproduced.H_err_at_t_end}.
\paragraph{Fig.~2.} The run goes to $t=\result[int]{r}{scene.t_end}$ (\result[int]{r}{reproduced.steps} steps).
"""
if rt.label_problems({"good.tex": TEXT}):
    problems.append(f"clean text fails: {rt.label_problems({'good.tex': TEXT})}")
for bad, what in ((r"The fitted rate is \result[percent]{r}{reproduced.rate_whole}.", "under one description"),
                  (r"Here the largest error is \result[err]{r}{reproduced.H_err_at_t_end}.", "does not describe"),
                  (r"So the error at the end is \result[err]{r}{reproduced.max_err}.", "does not describe")):
    found = rt.label_problems({"bad.tex": TEXT + bad + "\n"})
    if len(found) != 1 or what not in found[0] or "bad.tex:4" not in found[0]:
        problems.append(f"'{bad}' gives {found}")
for p in problems:
    print("check_descriptions:", p)
print(f"check_descriptions: {len(problems)} problems")
sys.exit(1 if problems else 0)
