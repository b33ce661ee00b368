#!/usr/bin/env python3
"""check_report_tables.py SOURCE_DIR: \\comparisongrid, \\runcomparisons and \\figureitems (scripts/report_tables.py)
from a synthetic summary and run.json, no run needed. An item whose value comparisons share one key set gets a grid,
named by its run and the slug of its name or its study: a row per quantity named by its `where`, a column pair per
key (in numeric order, headed by the parameter `where` names), the order column filled from the order comparison of
the same quantity and, for a quantity without one, its tolerance. An item whose keys differ, or whose order names a
quantity no value comparison has, gets none. A run's tables of comparisons come in the order of papers.toml, then
the statements that are no item. A figure script <run>_<name>.gp labels the item whose slug is its name or the
items of the study it names, none else; a \\figureitems of no figure, an item labelled twice and a \\figref to
no figure are problems. The table of typed tolerances lists each comparison with a `why`, and no other."""
import pathlib
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(sys.argv[1]) / "scripts"))
import report_tables  # noqa: E402


def value(item, quantity, published, reproduced, compare):
    """A value comparison published by mesh n, as summary.json "comparisons" carries it."""
    return {"figure": item, "where": f"{item}, {quantity}, n = 5, 10 meshes: the largest error",
            "published": published, "reproduced": reproduced, "compare": compare, "verdict": "reproduced"}


def order(item, quantity, published, reproduced):
    return {"figure": item, "where": f"{item}, {quantity}, order: the slope of the errors",
            "published": published, "reproduced": reproduced, "compare": {"order": 0.3}, "verdict": "reproduced"}


GRID, UNEQUAL, UNPAIRED = "900 Table 2", "900 Table 3", "900 Table 4"
comparisons = {  # (keys as the summary writes them: "10" before "5")
    "b_err": value(GRID, "Energy B(x, y)", {"10": 2.5e-4, "5": 8e-4}, {"10": 2.4567e-4, "5": 8.0123e-4}, {"rel": 0.1}),
    "c_err": value(GRID, "Discrete energy C_d(x, y)", {"10": 1.1e-15, "5": 2.2e-15}, {"10": 3.3e-15, "5": 4.4e-15},
                   {"abs": 1e-13}),
    "slope": order(GRID, "Energy B(x, y)", 2, 1.98765),
    "u_err": value(UNEQUAL, "State u", {"10": 1.0, "5": 2.0}, {"10": 1.0, "5": 2.0}, {"rel": 0.1}),
    "v_err": value(UNEQUAL, "State v", {"10": 1.0, "20": 2.0}, {"10": 1.0, "20": 2.0}, {"rel": 0.1}),
    "w_err": value(UNPAIRED, "State w", {"10": 1.0, "5": 2.0}, {"10": 1.0, "5": 2.0}, {"rel": 0.1}),
    "w_order": order(UNPAIRED, "State z", 2, 2.0),
}
comparisons["eq_err"] = {**value("900 eq. (7)", "State e", 1.0, 1.0, {"rel": 0.1}), "where": "900 eq. (7): e"}
study_list = [{"name": "grid_study", "ran": True, "made": [GRID]}, {"name": "other", "ran": True, "made": [UNEQUAL]},
              {"name": "idle", "ran": False, "made": [UNPAIRED]}, {"name": "cost", "ran": True, "made": []}]
runs = {"run": {"summary": {"comparisons": comparisons}, "run": {"study_list": study_list}}}
papers = {"paper": [{"id": "900", "item": [{"name": "Table 4"}, {"name": "Table 3"}, {"name": "Table 2"}]}]}
index, tables = report_tables.figure_comparisons_tex(runs, papers)
problems = []
grid = tables.get("comparisongrid-run-900-table-2.tex", "")
for expected in (r"\@namedef{geomint@comparisongrid@run@table2}{generated/comparisongrid-run-900-table-2.tex}",
                 r"\@namedef{geomint@comparisongrid@run@grid_study}{generated/comparisongrid-run-900-table-2.tex}",
                 r"\@namedef{geomint@runcomparisons@run}{generated/runcomparisons-run.tex}"):
    if expected not in index:
        problems.append(f"the index has no {expected}")
inputs = [line for line in tables.get("runcomparisons-run.tex", "").splitlines() if line.startswith("\\input")]
if inputs != [f"\\input{{generated/comparisons-run-900-{s}.tex}}" for s in ("table-4", "table-3", "table-2", "eq-7")]:
    problems.append(f"runcomparisons-run.tex is not in the order of papers.toml, then the others: {inputs}")
for expected in (r" & \multicolumn{2}{c}{$n=5$} & \multicolumn{2}{c}{$n=10$} & \multicolumn{2}{c}{Order} \\",
                 r"Quantity & Pub. & Rep. & Pub. & Rep. & Pub. & Rep. \\",
                 r"Energy $B(x, y)$ & $8.00\times10^{-4}$ & $8.012\times10^{-4}$ & $2.50\times10^{-4}$ & "
                 r"$2.457\times10^{-4}$ & $2$ & $1.988$ \\",
                 r"Discrete energy $C_{d}(x, y)$ & $2.20\times10^{-15}$ & $4.4\times10^{-15}$ & $1.10\times10^{-15}$ & "
                 r"$3.3\times10^{-15}$ & \multicolumn{2}{c}{abs 1e-13} \\"):
    if expected not in grid:
        problems.append(f"the grid of {GRID} has no line {expected}")
for item in (UNEQUAL, UNPAIRED):
    slug = item.lower().replace(" ", "-")
    if f"comparisongrid-run-{slug}.tex" in tables or f"comparisongrid@run@{slug.replace('-', '')[3:]}" in index:
        problems.append(f"{item} gets a grid")
    if f"comparisons-run-{slug}.tex" not in tables:
        problems.append(f"{item} lost its list of comparisons")
# A figure's labels: by the slug of an item the run made, by a study's name, none for a study that makes none (or one
# that did not run), and the problems of the LaTeX that uses them.
with tempfile.TemporaryDirectory() as d:
    for name in ("run_table2", "run_other", "run_table4", "run_cost", "run_cost_more", "elsewhere_table2"):
        (pathlib.Path(d) / f"{name}.gp").write_text("", encoding="utf-8")
    names = report_tables.figure_names(runs, pathlib.Path(d))
    expected = {"run_table2": [GRID], "run_other": [UNEQUAL], "run_table4": [], "run_cost": [], "run_cost_more": [],
                "run_table3": [UNEQUAL]}
    if names != expected:
        problems.append(f"figure_names: {names}, not {expected}")
    tex, wrong = report_tables.figure_items_tex(runs, pathlib.Path(d), {"a.tex": "\\figureitems{run_other}\n"
                                                "\\figureitems{run_table3}\n\\figureitems{run_nothing}\n"
                                                "\\figref{run_other} \\figref{run_cost}\n% \\figureitems{run_cost}"})
    if r"\@namedef{geomint@figure@run_table2}{\label{figure:run_table2}\label{item:900 Table 2}}" not in tex:
        problems.append(f"figure_items.tex does not label run_table2 and its item: {tex}")
    for needle in ("a.tex:2: \\figureitems{run_table3}: 900 Table 3 is already labelled by \\figureitems{run_other}",
                   "a.tex:3: \\figureitems{run_nothing}: no figure", "a.tex: \\figref{run_cost}: no \\figureitems"):
        if not any(w.startswith(needle) for w in wrong):
            problems.append(f"figure_items_tex does not find '{needle}' in {wrong}")
    if len(wrong) != 3:
        problems.append(f"figure_items_tex: {len(wrong)} problems, not 3: {wrong}")
# The typed tolerances: a row for each comparison that states the origin of its typed number (`why`), none for
# a derived one, none for one this run did not compute.
typed = {"t_err": {**value(GRID, "State t", 1.0, 1.02, {"rel": 0.1}), "difference": 0.02, "why": "two standard errors of 100 samples"},
         "p_err": value(GRID, "State p", 1.0, 1.0, {"rel": "printed"}),
         "n_err": {**value(GRID, "State n", 1.0, None, {"rel": 0.1}), "why": "w", "verdict": "not computed"}}
listed = report_tables.tolerances_tex({"run": {"summary": {"comparisons": typed}}})
if "rel 0.1 & $0.0200$ & two standard errors of 100 samples\\\\" not in listed:
    problems.append("the table of typed tolerances has no row for t_err with its origin")
if "cmp:run:p_err" in listed or "cmp:run:n_err" in listed:
    problems.append("the table of typed tolerances lists a derived or an uncomputed one")
for p in problems:
    print("check_report_tables:", p)
if problems:
    print(grid)
print(f"check_report_tables: {len(problems)} problems")
sys.exit(1 if problems else 0)
