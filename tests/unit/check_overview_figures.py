#!/usr/bin/env python3
"""check_overview_figures.py SOURCE_DIR WORK_DIR

The report's overview figures (scripts/overview_figures.py) drawn from a fixture of two runs written here, no run
needed: every kind of comparison (a relative tolerance from the printed digits, an absolute one on a table with
entries at round-off, an order, standard errors, a claim, a tolerance of 0, a convention, an expected difference,
values only reported, not comparable) and work-precision sets (a ratio with its interval and verdict, one
indistinguishable within the drift, a target only one method reaches). Checks where entries and ratios are drawn, the text of both PDFs (pdftotext:
groups, numbers, rules, verdicts, method titles as the registry gives them; no nan or inf, no ASCII math or
other fault scripts/check_pdf.py refuses), the same bytes on a second run, and that a NaN or an infinity in a
summary is refused with a message naming it.
"""
import copy
import json
import math
import pathlib
import re
import shutil
import subprocess
import sys

SOURCE, WORK = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
sys.path.insert(0, str(SOURCE / "scripts"))
import check_pdf  # noqa: E402
import overview_figures as ov  # noqa: E402  (exits with its message where matplotlib is missing)


def comparison(figure, verdict, compare=None, **extra):
    return {"study": "s", "figure": figure, "where": f"{figure}: printed", "verdict": verdict,
            **({"compare": compare} if compare else {}), **extra}


ALPHA = {  # (#1 to #9, in this order)
    "val": comparison("900 Fig. 1", "reproduced", {"rel": "printed"}, published=2.50e-11, reproduced=2.5025e-11,
                      tolerances=0.002, difference=0.001),
    "tab": comparison("900 Fig. 1", "reproduced", {"abs": "printed"}, published={"0.1": 2.5e-11, "0.05": 5e-14},
                      reproduced={"0.10000000000000001": 2.5e-11, "0.050000000000000003": -3e-13},
                      tolerances={"0.1": 5e-14, "0.05": 5e-17}, roundoff=["0.050000000000000003"],
                      difference={"0.10000000000000001": 2.5e-14}),
    "claim": comparison("900 Fig. 1", "reproduced", {"above": 0.8}, published="> 0.8", reproduced={"M": 1.6, "T": 0.9},
                        difference={"M": 0.8, "T": 0.1}),
    "said": comparison("900 Fig. 1", "reported", published=3.0, reproduced=3.1),
    "ord": comparison("900 Table 2", "differs", {"order": 0.3}, published=4, reproduced=2.0, difference=-2.0,
                      expect="differs", test="x.Y"),
    "se": comparison("900 Table 2", "reproduced", {"abs": "stderr"}, published=0.5, reproduced=0.55, difference=0.05,
                     tolerances={"standard_error": 0.05, "standard_errors": 2.0, "of": 0.1, "from": "r.se"}),
    "exact": comparison("900 Table 2", "reproduced", {"abs": 0.0}, published=120, reproduced=120, difference=0.0),
    "conv": comparison("900 eq. (3)", "differs", {"abs": 1e-12}, published=0.0, reproduced=0.06, difference=0.06,
                       kind="convention", expect="differs", test="x.Z"),
    "floor": comparison("900 Table 2", "not comparable", {"abs": "printed"}, published={"10": 2.66e-15},
                        reproduced={"10": 1.4e-14}, tolerances={"10": 5e-18}, roundoff=["10"]),
}
BETA = {  # (#10, #11)
    "below": comparison("901 Fig. 5.3", "reproduced", {"below": 0.1}, published="< 0.1", reproduced=0.01,
                        difference=-0.09),
    "step": comparison("901 Sec. 5.3", "differs", {"abs": 0.0}, published=0, reproduced=8, difference=8.0,
                       expect="differs", test="x.W"),
}


def method(*reach):
    """One method of a work-precision set (analysis/work_precision_set.hpp summary()): the wall time to reach each
    target (None: it does not)."""
    return {"wall_s_to": list(reach)}


def ratios(target, reference, **by):
    """ratios_to at one target: each method's ratio, interval, drift and verdict, as the run writes them."""
    return {"target": target, "reference": reference,
            "by_method": {m: dict(zip(("wall_ratio", "min", "max", "drift", "verdict"), r)) for m, r in by.items()}}


COST_ALPHA = {"method": "median over rounds",  # (not a set)
              "pair": {"methods": ["sv", "ti", "phi4_M"], "targets": [1e-4], "spread": {"max": 0.25, "median": 0.1},
                       "by_method": {"sv": method(2e-5), "ti": method(1e-6), "phi4_M": method(None)},
                       "ratios_to": [ratios(1e-4, "sv", ti=(0.05, 0.0432, 0.0611, 0.02, "faster"))]},
              "lone": {"methods": ["lobatto", "midpoint"], "targets": [0.1], "spread": None,
                       "by_method": {"lobatto": method(0.3), "midpoint": method(None)},
                       "ratios_to": [ratios(0.1, "lobatto")]}}
COST_BETA = {"start_0": {"methods": ["cartesian", "polar"], "targets": [4e-5], "spread": {"max": 0.01},
                         "by_method": {"cartesian": method(4e-4), "polar": method(6e-4)},
                         "ratios_to": [ratios(4e-5, "cartesian", polar=(1.5, 1.45, 1.55, 0.1, "indistinguishable"))]}}
METHODS = [{"name": n, "label": l, "title": t} for n, l, t in (
    ("stormer_verlet", "sv", "Störmer–Verlet"), ("takahashi_imada", "ti", "Takahashi–Imada"),
    ("phi4", "phi4", "Φ^{(4)}_h"), ("conformal_M", "M", "Ψ_{h,E}, M"), ("lobatto", "lobatto", "Lobatto"),
    ("implicit_midpoint", "midpoint", "implicit midpoint"))]


def write_runs(root, alpha=ALPHA, cost_alpha=COST_ALPHA):
    shutil.rmtree(root, ignore_errors=True)
    for name, comparisons, cost, extra in (("alpha", alpha, cost_alpha, {}),
                                           ("beta", BETA, COST_BETA, {"work_precision": {"labels": {
                                               "cartesian": "Cartesian (73)", "polar": "polar (72)"}}})):
        (root / name).mkdir(parents=True)
        (root / name / "summary.json").write_text(json.dumps({"comparisons": comparisons, "cost": cost, **extra}),
                                                  encoding="utf-8")
    return root


def draw(results, out):
    shutil.rmtree(out, ignore_errors=True)
    return subprocess.run([sys.executable, str(SOURCE / "scripts" / "overview_figures.py"), str(results), str(out),
                           "--methods", str(WORK / "methods.json")], capture_output=True, text=True)


problems = []


def expect(what, ok):
    if not ok:
        problems.append(what)


WORK.mkdir(parents=True, exist_ok=True)
(WORK / "methods.json").write_text(json.dumps(METHODS), encoding="utf-8")

# Where an entry is drawn: its deviation over its tolerance; a claim, its value against its bound.
expect("a relative tolerance from the printed digits", math.isclose(ov.entry_positions(ALPHA["val"])[None], 0.5))
expect("a table: only the entries compared, each over its own printed tolerance",
       ov.entry_positions(ALPHA["tab"]) == {"0.10000000000000001": 2.5e-14 / 5e-14})
expect("a claim above a bound: bound over value", ov.entry_positions(ALPHA["claim"]) == {"M": 0.5, "T": 0.8 / 0.9})
expect("a claim below a bound: value over bound", math.isclose(ov.entry_positions(BETA["below"])[None], 0.1))
sign = comparison("900 Fig. 1", "reproduced", {"above": 0}, published="> 0", reproduced={"M": 0.13, "T": 0.0},
                  difference={"M": 0.13, "T": 0.0})
expect("a sign (a bound of 0): held at 0, missed beyond the axis", ov.entry_positions(sign) == {"M": 0.0, "T": math.inf})
margin = comparison("900 Fig. 1", "differs", {"above": 0.5}, published="> 0.5", reproduced=0.55, difference=0.05,
                    tolerances={"standard_error": 0.1, "standard_errors": 2, "of": 0.2})
expect("a claim with standard errors: the bound moved by them", math.isclose(ov.entry_positions(margin)[None], 0.7 / 0.55))
expect("standard errors: the run's tolerance", math.isclose(ov.entry_positions(ALPHA["se"])[None], 0.5))
expect("a tolerance of 0 met: 0", ov.entry_positions(ALPHA["exact"])[None] == 0.0)
expect("a tolerance of 0 missed: beyond the axis", ov.entry_positions(BETA["step"])[None] == math.inf)
# A ratio at equal error with its interval, drift and verdict as the run judged them (ratios_to).
groups = ov.cost_groups({"alpha": {"summary": {"cost": COST_ALPHA}}, "beta": {"summary": {
    "cost": COST_BETA, "work_precision": {"labels": {"cartesian": "Cartesian (73)", "polar": "polar (72)"}}}}}, METHODS)
ti = groups[0][2][0]
expect(f"the ratio of ti to sv, its interval and verdict: {ti}", ti == ("Takahashi–Imada", 0.05, (0.0432, 0.0611), "faster"))
expect(f"a method that does not reach the target is listed: {groups[0][2][1:]}",
       groups[0][2][1:] == [(None, "not reaching it: Φ^{(4)}_h, M")] or "not reaching it" in str(groups[0][2][1:]))
expect(f"the band of a set is its measurement's drift: {groups[2][1]}", groups[2][1] == 0.1)
expect(f"a target only one method reaches: no ratio: {groups[1][2]}",
       groups[1][2] == [(None, "no ratio: only Lobatto reaches it")])

runs = write_runs(WORK / "runs")
result = draw(runs, WORK / "out")
expect(f"overview_figures.py failed: {result.stderr}", result.returncode == 0)
texts = {}
for name in ("overview-comparisons", "overview-cost"):
    pdf = WORK / "out" / f"{name}.pdf"
    if not pdf.is_file():
        problems.append(f"no {pdf.name}")
        continue
    text = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
    texts[name] = text
    for m in re.finditer(r"(?<![\w.])-?(nan|inf)\b", text, re.I):
        problems.append(f"{pdf.name}: '{m.group(0)}' in the text")
    xml = subprocess.run(["pdftohtml", "-xml", "-i", "-q", "-stdout", str(pdf)], capture_output=True, text=True,
                         check=True).stdout
    problems += [f"{pdf.name}: {p}" for p in check_pdf.text_problems(text.split("\f"))
                 + check_pdf.math_problems(check_pdf.font_lines(xml)) if "is not on the first pages" not in p]
    problems += [f"{pdf.name}: a raw key in the text: {k}" for k in ("stormer_verlet", "phi4_M", "conformal")
                 if k in text]
for label in ("[900] Fig. 1", "[900] Table 2", "[900] eq. (3)", "[901] Fig. 5.3", "[901] Sec. 5.3", "#1", "#11",
              "reported, not compared: #4", "not comparable (round-off): #9", "1 at round-off",
              "rel: half a unit in the last printed digit", "abs: 2 standard errors of the run", "above 0.8",
              "below 0.1", "order 0.3", "reproduced", "differs, as the errata explain", "a convention, not judged"):
    expect(f"overview-comparisons.pdf lacks '{label}'", label in texts.get("overview-comparisons", ""))
for label in ("alpha", "pair", "over Störmer–Verlet", "Takahashi–Imada", "polar (72)", "over Cartesian (73)",
              "1.50 (1.45–1.55): ≈", "indistinguishable within the drift", "no ratio: only Lobatto reaches it", "not reaching it", ", M",
              "0.0500 (0.0432–0.0611): faster"):
    expect(f"overview-cost.pdf lacks '{label}'", label in texts.get("overview-cost", ""))

# The same bytes from the same data (no date in the PDFs).
again = draw(runs, WORK / "again")
for name in ("overview-comparisons.pdf", "overview-cost.pdf"):
    expect(f"{name} differs on a second run", again.returncode == 0 and
           (WORK / "out" / name).read_bytes() == (WORK / "again" / name).read_bytes())

# A NaN or an infinity in a summary is refused, naming where, and nothing is drawn.
nan_alpha = copy.deepcopy(ALPHA)
nan_alpha["val"]["difference"] = float("nan")
inf_cost = copy.deepcopy(COST_ALPHA)
inf_cost["pair"]["ratios_to"][0]["by_method"]["ti"]["wall_ratio"] = float("inf")
for what, runs, where in (("a NaN", write_runs(WORK / "nan", alpha=nan_alpha),
                           "alpha/summary.json comparisons.val.difference"),
                          ("an infinity", write_runs(WORK / "inf", cost_alpha=inf_cost),
                           "alpha/summary.json cost.pair.ratios_to.0.by_method.ti.wall_ratio")):
    refused = draw(runs, WORK / "refused")
    message = refused.stderr.strip()
    expect(f"{what} is not refused with a message naming {where}: exit {refused.returncode}, '{message}'",
           refused.returncode != 0 and where in message and "not a finite number" in message
           and len(message.splitlines()) == 1)
    expect(f"{what}: a figure was drawn", not any((WORK / "refused").glob("*.pdf")))

for p in problems:
    print(f"check_overview_figures.py: {p}")
print(f"check_overview_figures.py: {'ok' if not problems else f'{len(problems)} problems'}")
sys.exit(1 if problems else 0)
