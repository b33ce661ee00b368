#!/usr/bin/env python3
"""The report's two overview figures, drawn with matplotlib from the runs' summary.json, the data of the ledger.

    overview_figures.py RESULTS_ROOT OUT_DIR --methods METHODS_JSON [--paper-scenes ID=SCENE ...]

RESULTS_ROOT/<run>/summary.json are the runs, taken as scripts/report.py takes them (load_runs: the same runs in
the same order, so that a comparison has the number of its row in Appendix A). Writes into OUT_DIR:

  overview-comparisons.pdf  every published comparison (summary.json "comparisons", made by the executables from
                            experiments/<name>/published.toml), grouped by the paper's figure or table: each entry
                            (a value, or each value of a table) as its measured deviation over its tolerance on a
                            log axis. The deviation is the run's "difference" (relative for a relative tolerance);
                            the tolerance is the one the run resolved (report_tables.tolerance_at: typed, half a
                            unit in the last printed digit, or standard errors of the run). A claim (above, below)
                            draws its value over its bound (below) or its bound over its value (above). Left of 1
                            is within; a deviation of 0 sits on the left edge, one beyond the axis or not finite on
                            the right. The marker is the comparison's verdict; comparisons reported only, not
                            comparable or not computed are listed in their figure's group, not drawn.
  overview-cost.pdf         every comparison at equal accuracy of the cost studies (summary.json cost.<set>: the
                            work-precision sets of analysis/work_precision_set.hpp with error targets): for each
                            target, each method's wall time to reach it over that of the set's first method that
                            reaches it, with its interval and verdict as the run judged them (ratios_to: the
                            quartiles of the times per step carried over, runner/timing.hpp), a claim (faster,
                            slower) filled. The line at 1, and the band [1/(1+d), 1+d] of the measurement's drift d
                            (the control loop timed before and after it), which a claim's interval must clear.

A number that is not finite (NaN, inf) in what is drawn is refused, naming the run and the key. Run it with an
interpreter that has matplotlib (Debian's /usr/bin/python3, python3-matplotlib; make's MPL_PYTHON). The output is
the same bytes for the same input: no date in the PDFs.
"""
import argparse
import json
import math
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from report import TIMING_VERDICTS, load_runs  # noqa: E402
from report_tables import comparison_numbers, rule_text, tolerance_at  # noqa: E402
from tex_format import gnuplot_tex, is_number, number, sci_or_sig  # noqa: E402

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.transforms import blended_transform_factory
except ImportError:
    sys.exit(f"overview_figures.py: {sys.executable} has no matplotlib: run it with Debian's /usr/bin/python3 "
             "(apt-get install python3-matplotlib; make paper passes MPL_PYTHON)")

PROGRAM = "overview_figures.py"
# The font of the report's gnuplot figures (figures/common.gp: "Sans", DejaVu Sans), small enough for a row per
# comparison on one page; fixed metadata for the same bytes on every run.
STYLE = {"font.family": "DejaVu Sans", "mathtext.fontset": "dejavusans", "font.size": 6.5, "axes.linewidth": 0.6,
         "xtick.major.width": 0.6, "xtick.minor.width": 0.4, "pdf.fonttype": 42, "svg.hashsalt": "geomint",
         "path.simplify": False}
METADATA = {"CreationDate": None, "Creator": None}
WIDTH_IN = 6.3  # the report's text width (160 mm)
ROW_IN, COST_ROW_IN = 0.092, 0.11  # the height of a row of each figure
# The verdicts (summary.json "comparisons", runner/published.hpp) as drawn: (legend text, marker, colour, filled).
VERDICT_STYLES = {
    "reproduced": ("reproduced", "o", "#0072B2", True),
    "expected": ("differs, as the errata explain", "s", "#E69F00", True),
    "differs": ("differs", "X", "#D55E00", True),
    "convention": ("a convention, not judged", "D", "#555555", False),
}
NOT_DRAWN = {"reported": "reported, not compared", "not computed": "not computed by this scene"}
ITEM_KINDS = ("Fig.", "Table", "Sec.", "eq.")  # the order of a paper's items in the figure


def refuse_non_finite(tree, where):
    """SystemExit naming the first number of `tree` that is not finite (json reads NaN and Infinity as floats)."""
    if isinstance(tree, dict):
        for k, v in tree.items():
            refuse_non_finite(v, f"{where}.{k}")
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            refuse_non_finite(v, f"{where}.{i}")
    elif isinstance(tree, float) and not math.isfinite(tree):
        raise SystemExit(f"{PROGRAM}: {where} is {tree}, not a finite number: nothing drawn")


def mathtext(text):
    """Plain text for matplotlib: only a dollar sign is special."""
    return str(text).replace("$", r"\$")


def code(name):
    """A name of the code (a run, a set) in the typewriter font, as the report sets it."""
    return r"$\mathtt{" + name.replace("_", r"\_") + "}$"


def math_number(x, fmt=None):
    """A number as mathtext: two significant digits ($3.6\\times10^{-3}$, $0.11$), or a format of the report
    (tex_format.FORMATS)."""
    return f"${sci_or_sig(x, 2) if fmt is None else number(x, fmt)}$"


def paper_of(c, summary):
    """The paper a comparison belongs to, as "[004] ": its item's id ("004 Fig. 5"), else its `where` ("001 eq. (10):
    ..."), else the run's first item; "" if none names one."""
    for text in (c.get("figure"), c.get("where"), *(summary.get("figures") or {})):
        m = re.match(r"(\d{3})\b", text or "")
        if m:
            return f"[{m.group(1)}] "
    return ""


def item_order(group):
    """(paper, kind of item, its numbers) for sorting: Fig. 2 before Fig. 10, figures before tables and text."""
    paper, item = group
    kind = next((i for i, k in enumerate(ITEM_KINDS) if item.startswith(k)), len(ITEM_KINDS))
    return paper, kind, [int(n) for n in re.findall(r"\d+", item)], item


def verdict_style(c):
    if c.get("kind") == "convention":
        return "convention"
    if c["verdict"] == "differs":
        return "expected" if c.get("expect") == "differs" else "differs"
    return "reproduced"


def entry_positions(c):
    """Each compared entry of a comparison as its deviation over its tolerance (a claim: value over bound, or bound
    over value, the bound moved by the run's standard errors where the claim has them; a bound of 0, a sign: 0 where
    it holds), by entry key (None for a single value); inf where the run wrote no finite difference or the
    tolerance is 0."""
    (rule, bound), = c["compare"].items()
    diffs = c.get("difference")
    diffs = diffs if isinstance(diffs, dict) else {None: diffs}
    out = {}
    for key, d in diffs.items():
        if rule in ("above", "below"):  # (beyond the bound by the run's standard errors where it says so)
            margin = (c.get("tolerances") or {}).get("of", 0) if isinstance(c.get("tolerances"), dict) else 0
            limit = bound + margin if rule == "above" else bound - margin
            v = c["reproduced"][key] if key is not None else c["reproduced"]
            if d is None:
                out[key] = math.inf
            elif limit == 0:  # (a sign: the claim holds, at the left edge, or not, beyond the axis)
                out[key] = 0.0 if (v > 0 if rule == "above" else v < 0) else math.inf
            elif not limit > 0:
                raise SystemExit(f"{PROGRAM}: a claim with the bound {limit} cannot be drawn against it on a log axis")
            else:
                out[key] = max(v / limit if rule == "below" else limit / v if v > 0 else math.inf, 0.0)
        else:
            tol = tolerance_at(c, key)
            if tol is None:
                raise SystemExit(f"{PROGRAM}: no tolerance for the entry {key} of {c['where'][:60]}")
            out[key] = math.inf if d is None else abs(d) / tol if tol > 0 else 0.0 if d == 0 else math.inf
    return out


def tolerance_note(c):
    """The rule of a comparison as the report states it (report_tables.rule_text), with the derived tolerances."""
    text = mathtext(rule_text(c))
    (rule, tol), = c["compare"].items()
    if tol in ("printed", "stderr"):
        keys = list(c["difference"]) if isinstance(c.get("difference"), dict) else [None]
        vals = sorted({tolerance_at(c, k) for k in keys})
        text += " (" + "–".join(math_number(v) for v in dict.fromkeys((vals[0], vals[-1]))) + ")"
    if c.get("roundoff") and c["verdict"] != "not comparable":
        text += f"; {len(c['roundoff'])} at round-off"
    return text


def comparison_groups(runs):
    """{(paper, item): [rows]}: each comparison drawn as (number, style, {entry: position}, note), those not drawn
    gathered in one row per group and reason (None, reason, [numbers])."""
    numbers, groups = comparison_numbers(runs), {}
    for name, run in runs.items():
        for key, c in (run["summary"].get("comparisons") or {}).items():
            group = (paper_of(c, run["summary"]), c.get("figure", "")[4:] or "no figure")
            rows = groups.setdefault(group, [])
            n = numbers[(name, key)]
            if c["verdict"] in ("reproduced", "differs") and c.get("compare"):
                rows.append((n, verdict_style(c), entry_positions(c), tolerance_note(c)))
                continue
            why = NOT_DRAWN.get(c["verdict"]) or ("not comparable (round-off)" if c.get("roundoff")
                                                  else f"{c['verdict']} (this scene)")
            same = next((r for r in rows if r[0] is None and r[1] == why), None)
            if same:
                same[2].append(n)
            else:
                rows.append((None, why, [n], ""))
    return {g: groups[g] for g in sorted(groups, key=item_order)}


def log_limits(values, at_least=(1e-2, 1e2)):
    """Decades around the finite positive values, holding `at_least`."""
    finite = [v for v in values if 0 < v < math.inf]
    lo, hi = min(finite + [at_least[0]]), max(finite + [at_least[1]])
    return 10.0 ** (math.floor(math.log10(lo)) - 1), 10.0 ** (math.ceil(math.log10(hi)) + 1)


def row_axes(rows, row_in, top_in, left, right):
    """A figure of `rows` rows of row_in inches (plus top_in inches above them) and its log axes between the
    figure fractions left and right, y = row index from the top; and the keywords of a text in a row at a figure
    fraction x."""
    bottom_in = 0.45
    height = rows * row_in + top_in + bottom_in
    fig = plt.figure(figsize=(WIDTH_IN, height))
    ax = fig.add_axes([left, bottom_in / height, right - left, rows * row_in / height])
    ax.set_ylim(rows - 0.5, -0.5)
    ax.set_yticks([])
    ax.set_xscale("log")
    ax.tick_params(axis="x", which="both", labeltop=True, top=True, labelsize=6)
    return fig, ax, dict(transform=blended_transform_factory(fig.transFigure, ax.transData), va="center",
                         clip_on=False)


def comparisons_figure(runs, path):
    """Figure (a): every comparison's deviation over its tolerance, by figure (module docstring)."""
    groups = comparison_groups(runs)
    positions = [x for rows in groups.values() for r in rows if r[0] is not None for x in r[2].values()]
    lo, hi = log_limits(positions)
    n_rows = sum(len(rows) for rows in groups.values()) + 0.4 * (len(groups) - 1)
    left, right = 0.165, 0.535
    fig, ax, at = row_axes(n_rows, ROW_IN, 0.45, left, right)
    ax.set_xlim(lo, hi)
    ax.axvspan(1, hi, color="#f3f3f3", zorder=0)
    ax.axvline(1, color="black", lw=0.7, zorder=1)
    y = 0.0
    for (paper, item), rows in groups.items():
        if y > 0:
            ax.axhline(y - 0.7, color="#bbbbbb", lw=0.4)
        ax.text(0, y, f"{paper}{mathtext(item)}", ha="left", **at)
        for n, style, entries, note in rows:
            if n is None:  # not drawn: why, and which
                ax.text(left + 0.005, y, f"{style}: " + ", ".join(f"#{k}" for k in entries), ha="left",
                        style="italic", color="#555555", **at)
            else:
                _, marker, colour, filled = VERDICT_STYLES[style]
                xs = [min(max(x, lo), hi) for x in entries.values()]
                ax.scatter(xs, [y] * len(xs), marker=marker, s=9, linewidths=0.7, zorder=3, clip_on=False,
                           edgecolors=colour, facecolors=colour if filled else "none")
                ax.text(left - 0.006, y, f"#{n}", ha="right", **at)
                ax.text(right + 0.008, y, note, ha="left", fontsize=5.6, **at)
            y += 1
        y += 0.4
    ax.set_xlabel("deviation over tolerance (relative over relative, absolute over absolute, order over order);\n"
                  "a claim: value over bound (below), bound over value (above); left of 1: within", fontsize=6)
    handles = [Line2D([], [], ls="none", marker=m, color=c, markerfacecolor=c if f else "none", markersize=3.5,
                      label=t) for t, m, c, f in VERDICT_STYLES.values()]
    ax.legend(handles=handles, loc="lower left", bbox_to_anchor=(0, 1.0 + 0.3 / (n_rows * ROW_IN)), ncol=4,
              bbox_transform=blended_transform_factory(fig.transFigure, ax.transAxes),
              frameon=False, fontsize=6.5, handletextpad=0.3, columnspacing=1.2, borderaxespad=0)
    fig.savefig(path, metadata=METADATA)
    plt.close(fig)


def method_title(label, methods, summary, run):
    """A method of a cost set as the report names it: its registry title, the run's own label for a curve that is
    no registry method (work_precision.labels), or a Phi^(l) of a discretization (phi4_M) by both."""
    titles = {k: m["title"] for m in methods for k in (m["name"], m["label"])}
    if label in titles:
        return gnuplot_tex(titles[label], mathtext)
    own = ((summary.get("work_precision") or {}).get("labels") or {}).get(label)
    if own:
        return mathtext(own)
    first, _, second = label.partition("_")
    if first in titles and second in titles:
        return gnuplot_tex(titles[first], mathtext) + ", " + mathtext(second)
    raise SystemExit(f"{PROGRAM}: {run}: no title for the method {label} (not in the registry, --methods)")


def cost_sets(summary):
    """The work-precision sets of a run's cost sections (analysis/work_precision_set.hpp summary()), by name."""
    for section in ("cost",):
        for name, s in (summary.get(section) or {}).items():
            if isinstance(s, dict) and {"methods", "targets", "by_method"} <= set(s):
                yield name, s


def cost_groups(runs, methods):
    """[(header, drift, rows)]: per run, set and error target, each method's wall time to the target over the
    reference's (the set's first method that reaches it), as the run judged it (ratios_to of
    analysis/work_precision_set.hpp: the interval of the times per step carried over, the measurement's drift);
    rows (title, ratio, interval, verdict), and a row (None, text) for the methods that do not reach the target."""
    groups = []
    for name, run in runs.items():
        summary = run["summary"]
        paper = paper_of({}, summary)
        for set_name, s in cost_sets(summary):
            for at in s.get("ratios_to") or []:
                ref, by = at.get("reference"), at.get("by_method") or {}
                header = f"{paper}{code(name)}, set {code(set_name)}: error {math_number(at['target'], 'tol')}"
                missing = [method_title(m, methods, summary, name) for m in s["methods"] if m != ref and m not in by]
                rows = [(method_title(m, methods, summary, name), r["wall_ratio"], (r["min"], r["max"]), r["verdict"])
                        for m, r in by.items()]
                if ref is not None:
                    header += f", over {method_title(ref, methods, summary, name)}"
                if not rows:
                    rows.append((None, "no ratio: " + ("only " + method_title(ref, methods, summary, name) +
                                                      " reaches it" if ref else "no method reaches it")))
                elif missing:
                    rows.append((None, "not reaching it: " + ", ".join(missing)))
                groups.append((header, max((r["drift"] for r in by.values()), default=0), rows))
    return groups


def cost_figure(runs, methods, path):
    """Figure (b): every cost comparison at equal accuracy, its ratio with its interval (module docstring)."""
    groups = cost_groups(runs, methods)
    values = [v for _, _, rows in groups for r in rows if r[0] is not None for v in (r[1], *(r[2] or ()))]
    values += [v for _, d, _ in groups if d for v in (1 / (1 + d), 1 + d)]
    lo, hi = log_limits(values, (0.5, 2.0))
    n_rows = sum(len(rows) + 1 for _, _, rows in groups) + 0.3 * (len(groups) - 1)
    left, right = 0.36, 0.74
    fig, ax, at = row_axes(n_rows, COST_ROW_IN, 0.25, left, right)
    ax.set_xlim(lo, hi)
    ax.axvline(1, color="black", lw=0.7, zorder=1)
    y = 0.0
    for header, drift, rows in groups:
        if y > 0:
            ax.axhline(y - 0.65, color="#bbbbbb", lw=0.4)
        ax.text(0, y, header, ha="left", fontweight="bold", **at)
        if drift:
            ax.fill_betweenx([y + 0.5, y + len(rows) + 0.5], 1 / (1 + drift), 1 + drift, color="#dddddd", lw=0,
                             zorder=0)
        for title, *value in rows:
            y += 1
            if title is None:
                ax.text(0.012, y, value[0], ha="left", style="italic", color="#555555", **at)
                continue
            ratio, interval, verdict = value
            ax.text(0.012, y, title, ha="left", **at)
            claim = verdict in ("faster", "slower")
            ax.errorbar([ratio], [y], xerr=[[ratio - interval[0]], [interval[1] - ratio]], fmt="o", ms=2.6,
                        mfc="#0072B2" if claim else "none", color="#0072B2", elinewidth=0.8, capsize=1.5, zorder=3)
            ax.text(right + 0.008, y, f"{math_number(ratio, 'sig3')} ({math_number(interval[0], 'sig3')}–"
                    f"{math_number(interval[1], 'sig3')}): {TIMING_VERDICTS.get(verdict, verdict)}", ha="left", **at)
        y += 1.3
    ax.set_xlabel("wall time to the error target over the reference's (below 1: faster); bar: the quartile interval;\n"
                  "shaded: the drift around 1; filled: faster or slower, hollow: \u2248 (indistinguishable within the drift)",
                  fontsize=6)
    fig.savefig(path, metadata=METADATA)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results")
    parser.add_argument("out")
    parser.add_argument("--methods", required=True, help="the output of geomint-methods --json")
    parser.add_argument("--paper-scenes", nargs="*", metavar="ID=SCENE", help="as scripts/report.py takes them")
    args = parser.parse_args()
    runs = load_runs(pathlib.Path(args.results), args.paper_scenes, PROGRAM)
    for name, run in runs.items():
        for section in ("comparisons", "cost"):
            refuse_non_finite(run["summary"].get(section), f"{args.results}/{name}/summary.json {section}")
    methods = json.loads(pathlib.Path(args.methods).read_text(encoding="utf-8"))
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    plt.rcParams.update(STYLE)
    comparisons_figure(runs, out / "overview-comparisons.pdf")
    cost_figure(runs, methods, out / "overview-cost.pdf")
    print(f"{PROGRAM}: {len(runs)} runs: overview-comparisons.pdf, overview-cost.pdf in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
