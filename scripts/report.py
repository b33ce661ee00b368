#!/usr/bin/env python3
"""The generic part of the reproduction report, from data only.

    report.py RESULTS_ROOT OUT_DIR [--methods METHODS_JSON]

For every RESULTS_ROOT/<id>/summary.json (an experiment's run; <id> is the directory name) it
writes into OUT_DIR:

  results.tex       \\result[fmt]{<id>}{<dotted key>}: any number of any summary.json (timings
                    included) as a lookup. fmt: g (default, 4 significant digits), sig2, sig3,
                    sci2, sci3, pct1 (a fraction as percent) or full (%.17g). A key that does not
                    exist stops the LaTeX run, naming it.
  comparisons.tex   per run, the table of its published quantities (summary.json "comparisons",
                    made by the executable from experiments/<name>/published.toml): quantity, where
                    it was published, published, reproduced, difference, verdict, note.
  errata.tex        every comparison that published.toml expects to differ, with its explanation.
  methods.tex       the method registry (`geomint-methods --json`): order, bounds, properties, citation.

It computes nothing: every number is copied from the JSON and formatted.
"""
import argparse
import json
import math
import pathlib
import sys

FORMATS = {
    "g": lambda v: tex_number(v, "%.4g"),
    "sig2": lambda v: tex_number(v, "%.2g"),
    "sig3": lambda v: tex_number(v, "%.3g"),
    "sci2": lambda v: tex_number(v, "%.1e", force_exponent=True),
    "sci3": lambda v: tex_number(v, "%.2e", force_exponent=True),
    "pct1": lambda v: tex_number(100 * v, "%.1f") + r"\,\%",
    "full": lambda v: tex_number(v, "%.17g"),
}
VERDICTS = {"reproduced": "reproduced", "differs": "differs", "reported": "reported",
            "not comparable": "not comparable", "not computed": "not computed"}


def tex_escape(s: str) -> str:
    """Plain text for LaTeX: the special characters as themselves."""
    out = []
    for c in str(s):
        out.append({"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
                    "^": r"\^{}", "_": r"\_", "%": r"\%", "~": r"\~{}"}.get(c, c))
    return "".join(out)


def tex_number(v: float, fmt: str, force_exponent: bool = False) -> str:
    """A number in math mode: 1.23e-05 as 1.23\\cdot 10^{-5}; NaN and infinities as words."""
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise ValueError(f"not a number: {v!r}")
    if math.isnan(v):
        return "NaN"
    if math.isinf(v):
        return r"$\infty$" if v > 0 else r"$-\infty$"
    s = fmt % v
    if "e" in s:
        mantissa, exponent = s.split("e")
        exponent = int(exponent)
        if exponent == 0 and not force_exponent:
            return f"${mantissa}$"
        return f"${mantissa}\\cdot 10^{{{exponent}}}$"
    return f"${s}$"


def scalars(node, prefix=""):
    """The (dotted key, number) leaves of a JSON tree; array elements by index from 0."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from scalars(v, f"{prefix}.{k}" if prefix else str(k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from scalars(v, f"{prefix}.{i}")
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield prefix, node


def value_text(v) -> str:
    """A published or reproduced value: a number, or a table of them keyed by a parameter."""
    if isinstance(v, dict):
        return "; ".join(f"{tex_escape(k)}: {value_text(x)}" for k, x in v.items())
    if v is None:
        return "---"
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return tex_number(v, "%.3g")
    return tex_escape(v)


def results_tex(runs: dict) -> str:
    lines = [
        "% \\result[fmt]{run}{key}: a number of results/<run>/summary.json (scripts/report.py).",
        r"\makeatletter",
        r"\newcommand{\result}[3][g]{\@ifundefined{geomint@#2@#3@#1}"
        r"{\PackageError{report}{no value '#3' (format #1) in the summary of #2}{Run make paper; "
        r"check the key in results/#2/summary.json}}{\@nameuse{geomint@#2@#3@#1}}}",
    ]
    for run, summary in runs.items():
        for key, v in scalars(summary):
            for fmt, f in FORMATS.items():
                lines.append(f"\\@namedef{{geomint@{run}@{key}@{fmt}}}{{{f(v)}}}")
    lines.append(r"\makeatother")
    return "\n".join(lines) + "\n"


def comparisons_tex(runs: dict) -> str:
    out = ["% Published against reproduced, per run (scripts/report.py from summary.json \"comparisons\")."]
    for run, summary in runs.items():
        comparisons = summary.get("comparisons") or {}
        if not comparisons:
            continue
        out += [f"\\subsection*{{\\texttt{{{tex_escape(run)}}}}}",
                r"{\footnotesize\begin{longtable}{@{}p{0.2\linewidth}p{0.24\linewidth}p{0.12\linewidth}"
                r"p{0.12\linewidth}p{0.1\linewidth}p{0.12\linewidth}@{}}",
                r"\toprule quantity & where published & published & reproduced & difference & verdict\\ \midrule",
                r"\endhead"]
        for key, c in comparisons.items():
            compare = c.get("compare") or {}
            how = ", ".join(f"{k} {v:g}" for k, v in compare.items())
            verdict = VERDICTS[c["verdict"]] + (f" ({tex_escape(how)})" if how else "")
            if c.get("expect", "reproduced") != "reproduced":
                verdict += r", expected: " + tex_escape(c["expect"])
            out.append(f"\\texttt{{{tex_escape(key)}}} & {tex_escape(c['where'])} & {value_text(c.get('published'))} & "
                       f"{value_text(c.get('reproduced'))} & {value_text(c.get('difference'))} & {verdict}\\\\")
            remarks = [c[k] for k in ("reason", "note") if c.get(k)]
            if remarks:
                out.append(r"\multicolumn{6}{@{}p{0.95\linewidth}@{}}{\emph{" + tex_escape(" ".join(remarks)) + r"}}\\")
        out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def errata_tex(runs: dict) -> str:
    out = ["% The published statements the reproduction expects to differ from (published.toml: expect)."]
    items = []
    for run, summary in runs.items():
        for key, c in (summary.get("comparisons") or {}).items():
            if c.get("expect", "reproduced") != "reproduced":
                items.append(f"\\item \\texttt{{{tex_escape(run)}: {tex_escape(key)}}} --- {tex_escape(c['where'])}. "
                             f"Published {value_text(c.get('published'))}, reproduced {value_text(c.get('reproduced'))} "
                             f"(verdict: {VERDICTS[c['verdict']]}). {tex_escape(c.get('note', ''))}")
    if items:
        out += [r"\begin{itemize}"] + items + [r"\end{itemize}"]
    else:
        out.append("No published statement is expected to differ.")
    return "\n".join(out) + "\n"


def methods_tex(methods: list) -> str:
    def bound(v):
        if v is None:
            return "---"
        return r"$\infty$" if v == "inf" or (isinstance(v, float) and math.isinf(v)) else tex_number(v, "%.4g")
    out = ["% The method registry (geomint-methods --json; scripts/report.py).",
           r"{\footnotesize\begin{longtable}{@{}p{0.2\linewidth}p{0.1\linewidth}p{0.07\linewidth}p{0.08\linewidth}"
           r"p{0.08\linewidth}p{0.14\linewidth}p{0.25\linewidth}@{}}",
           r"\toprule method & family & order & bound $h|\lambda|$ & bound $\omega h$ & properties & defined in\\ \midrule",
           r"\endhead"]
    for m in methods:
        order = str(m["order"]) + (f" ({m['kernel_order']})" if m["kernel_order"] != m["order"] else "")
        out.append(f"\\texttt{{{tex_escape(m['name'])}}} & {tex_escape(m['family'])} & {order} & {bound(m.get('real_bound'))} & "
                   f"{bound(m.get('oscillatory_bound'))} & {tex_escape(', '.join(m['properties']))} & "
                   f"{tex_escape(m['citation'])}\\\\")
    out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results")
    parser.add_argument("out")
    parser.add_argument("--methods", help="the output of geomint-methods --json")
    args = parser.parse_args()
    root, out = pathlib.Path(args.results), pathlib.Path(args.out)
    runs = {}
    for path in sorted(root.glob("*/summary.json")):
        runs[path.parent.name] = json.loads(path.read_text(encoding="utf-8"))
    if not runs:
        print(f"report.py: no */summary.json in {root}", file=sys.stderr)
        return 1
    out.mkdir(parents=True, exist_ok=True)
    files = {"results.tex": results_tex(runs), "comparisons.tex": comparisons_tex(runs), "errata.tex": errata_tex(runs)}
    if args.methods:
        files["methods.tex"] = methods_tex(json.loads(pathlib.Path(args.methods).read_text(encoding="utf-8")))
    for name, text in files.items():
        (out / name).write_text(text, encoding="utf-8")
    print(f"report.py: {len(runs)} runs: " + ", ".join(files))
    return 0


if __name__ == "__main__":
    sys.exit(main())
