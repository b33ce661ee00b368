"""The report's generated tables of comparisons and methods (scripts/report.py writes them):
comparisons.tex (per run), one table per figure for \\comparisons{<paper> <item>}, the method registry
(methods.tex) and the methods' names for \\method (method_names.tex)."""
import math
import re

from tex_format import FORMATS, code, gnuplot_tex, is_number, longtable, prose, tex_escape, value_text


COMPARISON_HEAD = [r"\toprule quantity & where published & published & reproduced & difference & verdict\\ \midrule",
                   r"\endhead"]


def comparison_rows(comparisons):
    """One row per comparison (summary.json "comparisons"): key, where printed, the two values, their
    difference and the verdict with its rule, and its reason or note below it."""
    out = []
    for key, c in comparisons.items():
        how = ", ".join(f"{k} {v:g}" for k, v in (c.get("compare") or {}).items())
        verdict = c["verdict"] + (f" ({tex_escape(how)})" if how else "")
        if c.get("expect", "reproduced") != "reproduced":
            verdict += r", expected: " + tex_escape(c["expect"])
        out.append(f"{code(key)} & {prose(c['where'])} & {value_text(c.get('published'))} & "
                   f"{value_text(c.get('reproduced'))} & {value_text(c.get('difference'))} & {verdict}\\\\")
        remarks = [c[k] for k in ("reason", "note") if c.get(k)]
        if remarks:
            out.append(r"\multicolumn{6}{@{}p{0.95\linewidth}@{}}{\emph{" + prose(" ".join(remarks)) + r"}}\\")
    return out


def comparisons_tex(runs):
    out = ["% Published against reproduced, per run (scripts/report.py from summary.json \"comparisons\")."]
    for name, run in runs.items():
        comparisons = run["summary"].get("comparisons") or {}
        if not comparisons:
            continue
        out += [f"\\subsection*{{\\texttt{{{tex_escape(name)}}}}}",
                longtable("footnotesize", 0.2, 0.26, 0.13, 0.13, 0.12, 0.16), *COMPARISON_HEAD,
                *comparison_rows(comparisons), r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def figure_comparisons_tex(runs):
    """\\comparisons{000 Fig. 9} (paper/main.tex): the table of one figure's comparisons, those of the run
    that makes it whose published.toml entries belong to it (summary.json "comparisons", field figure).
    Returns the index (the file of each figure's table) and the tables, by file name under generated/."""
    index = ["% The table of each figure's comparisons, for \\comparisons{<paper> <item>} (scripts/report.py).",
             r"\makeatletter"]
    tables = {}
    for run in runs.values():
        by_figure = {}
        for key, c in (run["summary"].get("comparisons") or {}).items():
            by_figure.setdefault(c.get("figure", ""), {})[key] = c
        for figure, comparisons in by_figure.items():
            if figure:
                name = "comparisons-" + re.sub(r"[^a-z0-9]+", "-", figure.lower()).strip("-") + ".tex"
                index.append(f"\\@namedef{{geomint@comparisons@{figure}}}{{generated/{name}}}")
                paper, _, item = figure.partition(" ")
                tables[name] = "\n".join([f"% {figure}: its comparisons (scripts/report.py).",
                                          f"\\noindent {{[{paper}]}} {tex_escape(item)}:",
                                          longtable("footnotesize", 0.2, 0.26, 0.13, 0.13, 0.12, 0.16),
                                          *COMPARISON_HEAD, *comparison_rows(comparisons), r"\bottomrule",
                                          r"\end{longtable}}"]) + "\n"
    index.append(r"\makeatother")
    return "\n".join(index) + "\n", tables


def methods_tex(methods, cites=None):
    def bound(v):
        if v is None:
            return "---"
        return r"$\infty$" if v == "inf" or (is_number(v) and math.isinf(v)) else "$" + FORMATS["sig4"](v) + "$"
    out = ["% The method registry (geomint-methods --json; scripts/report.py).",
           longtable("footnotesize", 0.2, 0.11, 0.08, 0.09, 0.09, 0.16, 0.27),
           r"\toprule method & family & order & bound $h|\lambda|$ & bound $\omega h$ & properties & defined in\\ \midrule",
           r"\endhead"]
    for m in methods:
        order = str(m["order"]) + (f" ({m['kernel_order']})" if m["kernel_order"] != m["order"] else "")
        out.append(f"{code(m['name'])} & {tex_escape(m['family'])} & {order} & {bound(m.get('real_bound'))} & "
                   f"{bound(m.get('oscillatory_bound'))} & {', '.join(code(p) for p in m['properties'])} & "
                   f"{prose(m['citation'])}{(cites or {}).get(m['name'], '')}\\\\")
    out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def method_names_tex(methods):
    """\\method{sti} and \\method[004]{sti} (paper/main.tex): a method's title, and its equations in a paper,
    as the registry gives them (geomint-methods --json), by registry name or label."""
    out = ["% The methods' names for \\method (geomint-methods --json; scripts/report.py).", r"\makeatletter"]
    for m in methods:
        for key in dict.fromkeys([m["name"], m["label"]]):
            out.append(f"\\@namedef{{geomint@method@{key}}}{{{gnuplot_tex(m['title'])}}}")
            for part in filter(None, m["equations"].split("; ")):
                paper, equations = part.split(" ", 1)
                out.append(f"\\@namedef{{geomint@method@{key}@{paper}}}{{{tex_escape(equations)}}}")
    out.append(r"\makeatother")
    return "\n".join(out) + "\n"
