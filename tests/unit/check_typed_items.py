#!/usr/bin/env python3
"""check_typed_items.py SOURCE_DIR: no LaTeX source of the report and no figure script types a paper item's id.

An item of a paper ("000 Fig. 9", "001 Table 1", "005 fourth order": "<paper> <item name>" as paper/papers.toml
lists it) is declared once, by the study that makes it (experiments/*/*.cpp, `.makes`); its run records it
(summary.json, run.json, figure_values.gp made.<study> and item.<slug>), the figures' titles read it from there
(figures/common.gp made_by, made_item) and the report names a figure by its script, a run by its name
(\\figureitems{euler_compensation_fig9}, \\figref, \\runcomparisons{run}, \\comparisongrid{run}{study}, \\verdict{run}
{fig9}: paper/main.tex). Fails, naming file:line, on each line of paper/main.tex, paper/sections/**/*.tex and
figures/*.gp, figures/*.gpi that holds, comments included,

  - the id of an item of paper/papers.toml ("000 Fig. 9", also inside \\ref{item:000 Fig. 9}), or
  - a figure, table or section of a paper by number after a space: "Fig. 9", "Fig 9", "Table 1", "Sec. 5.2".

The rule: prose about a paper with a non-breaking space is natural language, not an id, and is allowed: LaTeX's
"Fig.~9 of [000]", "Table~1 of [001]", "Section~5.2", and in a figure script's drawn text a non-breaking space
(U+00A0, figures/common.gp NBSP: "Sec." . NBSP . "4"). A generated file (paper/generated/, written by
scripts/report.py from the record) may hold ids; the ledger cites \\itemref{<id>} there. Before the sources, the
rule is checked on planted lines (one that types an id must fail, the allowed forms must pass).
"""
import pathlib
import re
import sys
import tomllib

GENERIC = re.compile(r"\b(?:Fig\.?|Table|Sec\.)[ \t]+[0-9]")  # (a plain space or tab: not ~, not U+00A0)


def item_ids(papers):
    """Every item id of paper/papers.toml: "<paper> <item name>"."""
    return [f"{p['id']} {item['name']}" for p in papers.get("paper", []) for item in p.get("item", [])]


def typed(text, ids):
    """(line, what) of each typed item id or numbered figure, table or section of a text."""
    found = []
    for n, line in enumerate(text.splitlines(), 1):
        hits = [f"the id '{i}'" for i in ids if i in line]
        hits += [f"'{m.group(0)}'" for m in GENERIC.finditer(line) if not any(m.group(0) in i for i in ids if i in line)]
        found += [(n, h) for h in hits]
    return found


def sources(root):
    paper = root / "paper"
    return [paper / "main.tex"] + sorted((paper / "sections").rglob("*.tex")) + \
        sorted((root / "figures").glob("*.gp")) + sorted((root / "figures").glob("*.gpi"))


def main():
    root = pathlib.Path(sys.argv[1])
    ids = item_ids(tomllib.loads((root / "paper" / "papers.toml").read_text(encoding="utf-8")))
    problems = []
    planted = {r"  \itemlabel{000 Fig. 9}": 1, r"as in Fig.~\ref{item:004 Fig. 4}": 1, "# Fig. 8 of Takács & Fülöp": 1,
               "Fig 9, Table 1 and Sec. 5.2": 3, r"\comparisons{005 fourth order}": 1,
               r"Fig.~9 of [000], Table~1 of [001], Section~5.2, \figref{ti_drift_fig4}": 0,
               '"other roots of Δ, Sec." . NBSP . "4"': 0, "other roots of Δ, Sec.\u00a04": 0}
    for line, expected in planted.items():  # (the rule itself)
        got = typed(line, list(dict.fromkeys(ids + ["000 Fig. 9", "004 Fig. 4", "005 fourth order"])))
        if len(got) != expected:
            problems.append(f"the rule finds {len(got)} typed ids, not {expected}, in the planted line {line!r}: {got}")
    for path in sources(root):
        for n, what in typed(path.read_text(encoding="utf-8"), ids):
            problems.append(f"{path.relative_to(root)}:{n}: {what} typed (the study declares it, the run records it: "
                            "name the figure by its script, the run by its name; prose about a paper with ~)")
    for p in problems:
        print(f"check_typed_items: {p}")
    print(f"check_typed_items: {len(sources(root))} files, {len(ids)} item ids, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
