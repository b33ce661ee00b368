#!/usr/bin/env python3
"""The generated parts of the reproduction report, from data only.

    report.py RESULTS_ROOT OUT_DIR [--methods METHODS_JSON] [--papers PAPERS_TOML] [--tests CTEST_JSON]
              [--quick QUICK_ROOT] [--junit JUNIT_XML] [--tex FILE ...] [--draft]

RESULTS_ROOT/<run>/summary.json and run.json are the runs (<run> is the directory name). Writes
into OUT_DIR:

  results.tex       the value of every lookup the report's LaTeX files make (--tex, by default
                    paper/main.tex and paper/sections/**/*.tex):
                      \\result[fmt]{run}{key}        a number or text of summary.json (dotted key,
                                                    array elements by index from 0), or of the
                                                    resolved scene as scene.<key> (run.json)
                      \\resultrange[fmt]{run}{key}   an object {min, max} as "a--b" ("a" if equal)
                    fmt: one of FORMATS below (default general). A key that does not exist or has
                    no finite value stops this script (exit 1) and the LaTeX run, naming it; with
                    --draft it is shown as a framed "missing" note instead.
  comparisons.tex   per run, its published quantities (summary.json "comparisons", made by the
                    executable from experiments/<name>/published.toml) against the reproduction.
  errata.tex        every comparison published.toml expects to differ: what was published, what
                    the project uses instead and why, and the ctest test that shows it.
  methods.tex       the method registry (`geomint-methods --json`).
  ledger.tex        with --papers: one row per figure and table of the papers (paper/papers.toml),
                    the studies that make it (run.json "study_list"), the verdict of their
                    comparisons, the command, the figure scripts that read its files and the tests.
  bibliography.tex  with --papers: the papers and their code.
  machine.tex       the CPU, compiler, flags and commit of the runs (run.json).
  hardcases.tex     with --junit: every hard case (ctest label hardcase) of the last ctest run, by
                    kind: what its name says it asserts, its result and time.
  quick.tex         with --tests and --quick: each quick scene the tests run, how many tests wait
                    on it, and each published comparison applied to it with its tolerance band.

It computes nothing: every number is copied from the JSON and formatted.
"""
import argparse
import json
import math
import os
import pathlib
import re
import sys
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent
NA = None  # a value that cannot be shown


def sci(x, digits=2):
    """m\\times10^{e} with `digits` significant digits."""
    if x == 0:
        return "0"
    mant, exp = f"{x:.{digits - 1}e}".split("e")
    return mant if int(exp) == 0 else rf"{mant}\times10^{{{int(exp)}}}"


def sig(x, n):
    """Fixed notation with n significant digits, trailing zeros kept; large integers unrounded."""
    if x == 0:
        return "0"
    return f"{x:.{max(0, n - 1 - math.floor(math.log10(abs(x))))}f}"


def sci_or_sig(x, n):
    """Scientific below 1e-3 and from 1e4, else n significant digits."""
    return "0" if x == 0 else sci(x, n) if abs(x) < 1e-3 or abs(x) >= 1e4 else sig(x, n)


def grouped(x):
    n = int(round(x))
    return f"{n:,}".replace(",", r"\,") if abs(n) >= 10000 else f"{n}"


def tolerance(x):
    mant, exp = f"{x:.1e}".split("e")
    return f"10^{{{int(exp)}}}" if mant == "1.0" else sci(x)


FORMATS = {  # name -> math-mode text of a finite number
    "general": lambda x: "0" if x == 0 else sci(x) if abs(x) < 1e-3 or abs(x) >= 1e4 else sig(x, 4),
    "order": lambda x: f"{x:.3f}",
    "porder": lambda x: f"{x:.0f}" if float(x).is_integer() else f"{x:.3f}",
    "dorder": lambda x: f"{x:+.3f}",
    "int": grouped,
    "intplain": lambda x: f"{int(round(x))}",
    "err": lambda x: "0" if x == 0 else sci(x) if abs(x) < 1e-3 or abs(x) >= 1e4 else sig(x, 2),
    "sci": sci,
    "sci1": lambda x: sci(x, 1),
    "sci01": lambda x: "0" if x == 0 else sci(x) if abs(x) < 1e-2 else sig(x, 2),
    "fixed3": lambda x: f"{x:.3f}",
    "fixed5": lambda x: f"{x:.5f}",
    "sig3": lambda x: sig(x, 3),
    "sig4": lambda x: sig(x, 4),
    "sig5": lambda x: sig(x, 5),
    "sig7": lambda x: sig(x, 7),
    "sci3": lambda x: sci_or_sig(x, 3),
    "sci4": lambda x: sci_or_sig(x, 4),
    "us": lambda x: sig(x * 1e6, 2) if x > 0 else NA,
    "tol": tolerance,
    "ns": lambda x: f"{x:.1f}",
    "ns3": lambda x: sig(x, 3) if x > 0 else NA,
    "percent": lambda x: "0\\,\\%" if x == 0 else sig(100 * x, 3) + "\\,\\%",
    "ratio": lambda x: f"{x:.1f}",
    "seconds": lambda x: f"{x:.2g}" if abs(x) < 100 else f"{x:.0f}",
    "plain": lambda x: f"{x:g}",
}
TEXT_FORMATS = ("text", "vec")
LOOKUP = re.compile(r"\\result(range)?(?:\[([^\]]*)\])?\{([^}]*)\}\{([^}]*)\}")


def tex_escape(text):
    repl = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{",
            "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}", "<": r"\textless{}",
            ">": r"\textgreater{}", "|": r"\textbar{}"}
    return "".join(repl.get(c, c) for c in str(text))


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def number(v, fmt):
    """Math-mode text of a number in a format, or None if it has none (null, NaN, inf, out of domain)."""
    if not is_number(v) or not math.isfinite(v):
        return None
    return FORMATS[fmt](v)


def at(tree, key):
    """The value at a dotted key (array elements by index), or None."""
    node = tree
    for part in key.split("."):
        if isinstance(node, dict) and part in node:
            node = node[part]
        elif isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        else:
            return None
    return node


def lookup_text(run, key, fmt, ranged):
    """The LaTeX of one lookup, or None if the value does not exist or cannot be shown."""
    tree, key = (run["run"].get("scene", {}), key[6:]) if key.startswith("scene.") else (run["summary"], key)
    v = at(tree, key)
    if ranged:
        if not isinstance(v, dict):
            return None
        a, b = number(v.get("min"), fmt), number(v.get("max"), fmt)
        return None if a is None or b is None else f"\\ensuremath{{{a}}}" if a == b else \
            f"\\ensuremath{{{a}}}--\\ensuremath{{{b}}}"
    if fmt == "text":
        return tex_escape(v) if isinstance(v, str) else None
    if fmt == "vec":
        ok = isinstance(v, list) and v and all(is_number(x) and math.isfinite(x) for x in v)
        return f"\\ensuremath{{({', '.join(f'{x:g}' for x in v)})}}" if ok else None
    content = number(v, fmt)
    return None if content is None else f"\\ensuremath{{{content}}}"


def results_tex(runs, tex_files, draft):
    lines = ["% The values the report looks up (scripts/report.py from results/<run>/summary.json, run.json).",
             r"\makeatletter",
             r"\newcommand{\geomint@value}[4]{\@ifundefined{geomint@#1@#2@#3@#4}{\PackageError{report}"
             r"{no value '#3' (format #2) in the run #1}{Run make paper; check the key in results/#1/summary.json}}"
             r"{\@nameuse{geomint@#1@#2@#3@#4}}}",
             r"\newcommand{\result}[3][general]{\geomint@value{#2}{#1}{#3}{v}}",
             r"\newcommand{\resultrange}[3][general]{\geomint@value{#2}{#1}{#3}{r}}"]
    missing, seen = [], set()
    for path in tex_files:
        text = re.sub(r"(?<!\\)%.*", "", path.read_text(encoding="utf-8"))  # (not in LaTeX comments)
        for m in LOOKUP.finditer(text):
            ranged, fmt, run, key = bool(m.group(1)), m.group(2) or "general", m.group(3), m.group(4)
            if (run, key, fmt, ranged) in seen or "#" in run + key + fmt:  # (a macro's own parameters)
                continue
            seen.add((run, key, fmt, ranged))
            if fmt not in FORMATS and fmt not in TEXT_FORMATS:
                raise SystemExit(f"report.py: {path}: unknown format '{fmt}' in {m.group(0)}")
            text = lookup_text(runs[run], key, fmt, ranged) if run in runs else None
            if text is None:
                missing.append(f"{path.name}: {m.group(0)}")
                if not draft:
                    continue
                text = r"\fbox{\scriptsize missing: " + tex_escape(f"{run} {key}") + "}"
            lines.append(f"\\@namedef{{geomint@{run}@{fmt}@{key}@{'r' if ranged else 'v'}}}{{{text}}}")
    lines.append(r"\makeatother")
    return "\n".join(lines) + "\n", missing


def value_text(v):
    """A published or reproduced value: a number, or a table of them keyed by a parameter."""
    if isinstance(v, dict):  # keyed by a name, or by a number written as %.17g (shown as %g)
        return "; ".join(f"{tex_escape(key_text(k))}: {value_text(x)}" for k, x in v.items())
    if is_number(v):
        return "$" + (number(v, "sci3") or tex_escape(v)) + "$" if math.isfinite(v) else tex_escape(v)
    return "not computed" if v is None else tex_escape(v)


def key_text(k):
    try:
        return f"{float(k):g}"
    except ValueError:
        return k


def code(text):
    """Typewriter text that may break after its dots, slashes and underscores."""
    return r"\texttt{" + re.sub(r"(\.|/|\\_)", r"\1\\allowbreak{}", tex_escape(text)) + "}"


def comparisons_tex(runs):
    out = ["% Published against reproduced, per run (scripts/report.py from summary.json \"comparisons\")."]
    for name, run in runs.items():
        comparisons = run["summary"].get("comparisons") or {}
        if not comparisons:
            continue
        out += [f"\\subsection*{{\\texttt{{{tex_escape(name)}}}}}",
                r"{\footnotesize\begin{longtable}{@{}p{0.2\linewidth}p{0.24\linewidth}p{0.12\linewidth}"
                r"p{0.12\linewidth}p{0.1\linewidth}p{0.12\linewidth}@{}}",
                r"\toprule quantity & where published & published & reproduced & difference & verdict\\ \midrule",
                r"\endhead"]
        for key, c in comparisons.items():
            how = ", ".join(f"{k} {v:g}" for k, v in (c.get("compare") or {}).items())
            verdict = c["verdict"] + (f" ({tex_escape(how)})" if how else "")
            if c.get("expect", "reproduced") != "reproduced":
                verdict += r", expected: " + tex_escape(c["expect"])
            out.append(f"\\texttt{{{tex_escape(key)}}} & {tex_escape(c['where'])} & {value_text(c.get('published'))} & "
                       f"{value_text(c.get('reproduced'))} & {value_text(c.get('difference'))} & {verdict}\\\\")
            remarks = [c[k] for k in ("reason", "note") if c.get(k)]
            if remarks:
                out.append(r"\multicolumn{6}{@{}p{0.95\linewidth}@{}}{\emph{" + tex_escape(" ".join(remarks)) + r"}}\\")
        out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def errata_tex(runs, tests):
    out = ["% The published statements the reproduction differs from (published.toml: expect = differs)."]
    items = []
    for name, run in runs.items():
        for key, c in (run["summary"].get("comparisons") or {}).items():
            if c.get("expect", "reproduced") == "reproduced":
                continue
            test = c.get("test", "")
            if tests is not None and test not in tests:
                raise SystemExit(f"report.py: {name}: {key} names the test '{test}', which ctest does not list")
            items.append(f"\\item \\textbf{{{tex_escape(c['where'])}.}} Published {value_text(c.get('published'))}; "
                         f"the printed statement gives {value_text(c.get('reproduced'))} "
                         f"(\\texttt{{{tex_escape(name)}}}, verdict: {c['verdict']}). {tex_escape(c.get('note', ''))} "
                         f"Shown by {code('ctest -R ' + test)}.")
    out += [r"\begin{enumerate}"] + items + [r"\end{enumerate}"] if items else ["No published statement differs."]
    return "\n".join(out) + "\n"


def methods_tex(methods):
    def bound(v):
        if v is None:
            return "---"
        return r"$\infty$" if v == "inf" or (is_number(v) and math.isinf(v)) else "$" + FORMATS["sig4"](v) + "$"
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


def made_items(makes):
    """The (paper, item) pairs a study's "makes" names: "003 Figs 5.2, 5.4" -> ("003", "Fig. 5.2"), ..."""
    m = re.match(r"(\d{3}) (Figs?|Tables?|Sec)\.? ([\d., ]+)", makes)
    if not m:
        return []
    kind = {"Fig": "Fig.", "Figs": "Fig.", "Table": "Table", "Tables": "Table", "Sec": "Sec."}[m.group(2)]
    return [(m.group(1), f"{kind} {n.strip().rstrip('.')}") for n in m.group(3).split(",") if n.strip()]


def figure_scripts(run, files):
    """The figure scripts of a run (figures/<run>_*.gp) that read one of a study's files."""
    found = []
    for gp in sorted((ROOT / "figures").glob(f"{run}_*.gp")):
        text = gp.read_text(encoding="utf-8")
        if any(re.search(re.escape(f).replace(r"\*", r"[^'\" ]*"), text) for f in files):
            found.append(gp.name)
    return found


def ledger_tex(runs, papers, tests):
    makers = {}  # (paper, item) -> [(run name, study)]
    for name, run in runs.items():
        for st in run["run"].get("study_list", []):
            if st.get("ran"):
                for item in made_items(st["makes"]):
                    makers.setdefault(item, []).append((name, st))
    out = ["% The reproduction ledger (scripts/report.py from paper/papers.toml, run.json and summary.json).",
           r"{\scriptsize\begin{longtable}{@{}>{\raggedright}p{0.07\linewidth}>{\raggedright}p{0.08\linewidth}"
           r">{\raggedright}p{0.25\linewidth}>{\raggedright}p{0.22\linewidth}>{\raggedright\arraybackslash}p{0.3\linewidth}@{}}",
           r"\toprule paper & in this report & verdict & published / reproduced & rerun, figure, test\\ \midrule",
           r"\endhead"]
    for paper in papers["paper"]:
        for item in paper["item"]:
            where = f"{{[{paper['id']}]}} {tex_escape(item['name'])}"  # (braced: not \\[dimen])
            if "left_out" in item:
                out.append(f"{where} & --- & left out: {tex_escape(item['left_out'])} & & \\\\")
                continue
            done = makers.get((paper["id"], item["name"]), [])
            if not done:
                raise SystemExit(f"report.py: no run made [{paper['id']}] {item['name']} (papers.toml lists it)")
            verdicts, values, commands, tests_cited, scripts, backing = [], [], [], [], [], []
            for name, st in done:
                experiment = runs[name]["summary"].get("experiment", name)
                scene = runs[name]["run"].get("scene_file", "")
                commands.append(code(f"build/bin/{experiment} --study {st['name']}" +
                                     ("" if name == experiment else f" --scene {scene}")))
                scripts += figure_scripts(name, st["files"])
                tests_cited.append(f"{experiment}.studies")
                for key, c in (runs[name]["summary"].get("comparisons") or {}).items():
                    # this figure's own comparisons (published.toml `figure`), not its study's other figures'
                    if c.get("study") != st["name"] or c.get("figure") != f"{paper['id']} {item['name']}" \
                            or c["verdict"] in ("not comparable", "not computed"):
                        continue
                    verdicts.append((c["verdict"], c.get("expect", "reproduced"), key, c))
                    if c["verdict"] == "differs":  # the file that states the discrepancy and its reason
                        backing.append(f"experiments/{experiment}/published.toml")
                    if c.get("test"):
                        tests_cited.append(c["test"])
            unexpected = [k for v, e, k, _ in verdicts if v == "differs" and e != "differs"]
            errata = [k for v, e, k, _ in verdicts if v == "differs" and e == "differs"]
            compared = sum(v == "reproduced" for v, _, _, _ in verdicts)
            reported = sum(v == "reported" for v, _, _, _ in verdicts)
            if unexpected:
                verdict = "discrepant: " + ", ".join(f"\\texttt{{{tex_escape(k)}}}" for k in unexpected) + " differ"
            elif "partial" in item:
                verdict = "partial: " + tex_escape(item["partial"])
            else:
                verdict = "reproduced"
            details = ([f"{compared} within tolerance"] if compared else []) + \
                      ([f"{reported} reported"] if reported else []) + \
                      ([r"errata (Section~\ref{sec:errata}): " + ", ".join(f"\\texttt{{{tex_escape(k)}}}" for k in errata)]
                       if errata else []) + ([] if verdicts else ["the paper prints no number to compare"])
            verdict += " (" + "; ".join(details + [code(f) for f in dict.fromkeys(backing)]) + ")"
            for _, _, key, c in verdicts[:2]:
                values.append(f"{value_text(c.get('published'))} / {value_text(c.get('reproduced'))}")
            if tests is not None:
                for t in tests_cited:
                    if t not in tests:
                        raise SystemExit(f"report.py: the ledger cites the test '{t}', which ctest does not list")
            label = item.get("label", "")
            shown = (f"{'Table' if label.startswith('tab:') else 'Figure'}~\\ref{{{label}}}, p.~\\pageref{{{label}}}"
                     if label else "")
            rerun = "; ".join(commands) + ("; " + ", ".join(code(f"figures/{g}") for g in scripts) if scripts else "") + \
                "; " + ", ".join(code(t) for t in dict.fromkeys(tests_cited))
            out.append(f"{where} & {shown} & {verdict} & {'; '.join(values)} & {rerun}\\\\")
    out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def bibliography_tex(papers):
    out = ["% The papers (paper/papers.toml; scripts/report.py).", r"\begin{thebibliography}{000}"]
    for p in papers["paper"]:
        ids = [f"doi:\\href{{https://doi.org/{p['doi']}}}{{{tex_escape(p['doi'])}}}" if "doi" in p else "",
               f"arXiv:\\href{{https://arxiv.org/abs/{p['arxiv']}}}{{{p['arxiv']}}}" if "arxiv" in p else ""]
        entry = f"\\bibitem[{p['id']}]{{paper{p['id']}}} {tex_escape(p['authors'])}, \\emph{{{tex_escape(p['title'])}}}, " \
                f"{tex_escape(p['venue'])}, {p['year']}. " + ", ".join(i for i in ids if i) + "."
        if "code" in p:
            entry += f" The authors' code: \\url{{https://{p['code']}}}, commit \\texttt{{{p['code_commit']}}}."
        out.append(entry)
    out.append(r"\end{thebibliography}")
    return "\n".join(out) + "\n"


def machine_tex(runs):
    seen = {}
    for run in runs.values():
        b, m = run["run"].get("build", {}), run["run"].get("machine", {})
        line = (f"{tex_escape(m.get('cpu', 'an unrecorded CPU'))} ({m.get('logical_cores', '?')} logical cores); "
                f"{tex_escape(b.get('compiler', '?'))}, \\texttt{{{tex_escape(b.get('cxx_flags', ''))}}}; commit "
                f"\\texttt{{{tex_escape(b.get('git_commit', '?')[:12])}}}{' (with local changes)' if b.get('git_dirty') else ''}")
        seen.setdefault(line, []).append(run["run"].get("threads"))
    lines = [f"{line}, {', '.join(sorted({str(t) for t in threads}))} threads" for line, threads in seen.items()]
    return "% The machine and build of the runs (run.json).\n" + r"\\ ".join(lines) + "\n"


def sentence(test_name):
    """A gtest name as words: Suite.ExplicitEulerAtItsBound -> 'explicit Euler at its bound'."""
    words = re.findall(r"[A-Z][a-z]+|[A-Z]+(?![a-z])|\d+(?:e\d+)?|[a-z]+", test_name.split(".")[-1])
    small = {"a", "an", "and", "are", "as", "at", "by", "for", "from", "in", "is", "its", "near", "not", "of", "on",
             "or", "than", "the", "to", "with", "without", "beyond", "below", "above", "stays", "stay", "gives"}
    return " ".join(w.lower() if i and w.lower() in small else w for i, w in enumerate(words))


# The hard cases by kind, from the words of a test's name (the first kind that matches).
HARD_KINDS = [(r"^regression\.Cli\.", "Refusals by the command line (exit 2 before any work)"),
              (r"^verification\.", "Each registered method on both sides of its declared bounds"),
              ("Newton", "Newton's method"), ("Singular", "Singularities"),
              ("1e5|T100|Periods", "Long runs"), ("Refuse|Reject|FailsLoudly", "Refusals of what cannot be computed"),
              ("", "Stability bounds, instability and divergence")]


def hard_cases_tex(junit, hard=None):
    """The hard cases of the last ctest run (ctest -L hardcase --output-junit FILE), by kind; with `hard`
    (the names of the tests labelled hardcase), not the fixtures the run needed (the quick runs)."""
    cases = [c for c in re.findall(r'<testcase name="([^"]+)"[^>]*time="([^"]+)" status="([^"]+)"', junit)
             if hard is None or c[0] in hard]
    if not cases:
        raise SystemExit("report.py: the JUnit file lists no test")
    kinds = {}
    for case in cases:
        kind = next(k for pattern, k in HARD_KINDS if re.search(pattern, case[0]))
        kinds.setdefault(kind, []).append(case)
    passed = sum(status == "run" for _, _, status in cases)
    out = ["% The hard cases and their results (ctest -L hardcase --output-junit; scripts/report.py).",
           f"In this run {passed} of {len(cases)} hard cases passed.",
           r"{\footnotesize\begin{longtable}{@{}>{\raggedright}p{0.4\linewidth}>{\raggedright}p{0.38\linewidth}"
           r"p{0.08\linewidth}r@{}}",
           r"\toprule test & what it asserts & result & time (s)\\ \midrule", r"\endhead"]
    for _, kind in HARD_KINDS:
        if kind not in kinds:
            continue
        out.append(rf"\multicolumn{{4}}{{@{{}}l}}{{\emph{{{tex_escape(kind)} ({len(kinds[kind])})}}}}\\")
        for name, time, status in kinds[kind]:
            result = {"run": "passed", "fail": "FAILED"}.get(status, tex_escape(status))
            shown = re.sub(r"(?<=[a-z0-9.])(?=[A-Z])", r"\\allowbreak{}", tex_escape(name))  # breaks between words
            out.append(f"\\texttt{{{shown}}} & {tex_escape(sentence(name))} & {result} & {float(time):.2f}\\\\")
    out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def quick_tex(tests, quick_root):
    """The quick scenes the tests run (ctest --show-only=json-v1), the tests that wait on each, and the
    tolerance bands with which each published comparison is applied to its run (QUICK/<id>/summary.json)."""
    props = {t["name"]: {p["name"]: p["value"] for p in t.get("properties", [])} for t in tests}
    out = ["% The quick scenes of the tests and their tolerance bands (scripts/report.py).",
           r"{\footnotesize\begin{longtable}{@{}>{\raggedright}p{0.3\linewidth}p{0.15\linewidth}p{0.15\linewidth}"
           r"p{0.14\linewidth}p{0.14\linewidth}@{}}",
           r"\toprule quantity & published & quick run & band & verdict\\ \midrule", r"\endhead"]
    for t in tests:
        if not t["name"].endswith(".quick_run"):
            continue
        run_id = t["name"][: -len(".quick_run")]
        fixtures = props[t["name"]].get("FIXTURES_SETUP", [])
        waiting = sorted(n for n, p in props.items() if set(p.get("FIXTURES_REQUIRED", [])) & set(fixtures))
        scene = next((a for a in t.get("command", []) if a.endswith(".toml")), "?")
        scene = os.path.relpath(scene, ROOT) if os.path.isabs(scene) else scene
        out.append(rf"\multicolumn{{5}}{{@{{}}p{{0.95\linewidth}}@{{}}}}{{\textbf{{{tex_escape(run_id)}}}: "
                   rf"{code(scene)}, waited on by {len(waiting)} tests}}\\")
        summary = pathlib.Path(quick_root) / run_id / "summary.json"
        comparisons = json.loads(summary.read_text(encoding="utf-8")).get("comparisons", {}) if summary.is_file() else {}
        for key, c in comparisons.items():
            band = ", ".join(f"{k} {v:g}" for k, v in (c.get("compare") or {}).items()) or "--"
            out.append(f"{code(key)} & {value_text(c.get('published'))} & "
                       f"{value_text(c.get('reproduced'))} & {tex_escape(band)} & {tex_escape(c['verdict'])}\\\\")
    out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def write(path, text):
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results")
    parser.add_argument("out")
    parser.add_argument("--methods", help="the output of geomint-methods --json")
    parser.add_argument("--papers", help="paper/papers.toml: the papers' figures and tables, the bibliography")
    parser.add_argument("--tests", help="ctest --show-only=json-v1: the tests the report may cite")
    parser.add_argument("--quick", help="with --tests: the directory of the tests' quick runs (quick.tex)")
    parser.add_argument("--tex", nargs="*", help="the LaTeX files whose lookups to resolve")
    parser.add_argument("--junit", help="ctest -L hardcase --output-junit FILE: the hard cases and their results")
    parser.add_argument("--draft", action="store_true", help="show a missing value as a note, do not stop")
    args = parser.parse_args()
    root, out = pathlib.Path(args.results), pathlib.Path(args.out)
    runs = {}
    for path in sorted(root.glob("*/summary.json")):
        run_json = path.parent / "run.json"
        runs[path.parent.name] = {"summary": json.loads(path.read_text(encoding="utf-8")),
                                  "run": json.loads(run_json.read_text(encoding="utf-8")) if run_json.is_file() else {}}
    if not runs:
        print(f"report.py: no */summary.json in {root}", file=sys.stderr)
        return 1
    tex = [pathlib.Path(t) for t in args.tex] if args.tex is not None else \
        [ROOT / "paper" / "main.tex"] + sorted((ROOT / "paper" / "sections").rglob("*.tex"))
    tests, ctest = None, []
    if args.tests:
        ctest = json.loads(pathlib.Path(args.tests).read_text(encoding="utf-8"))["tests"]
        tests = {t["name"] for t in ctest}
    results, missing = results_tex(runs, tex, args.draft)
    files = {"results.tex": results, "comparisons.tex": comparisons_tex(runs), "errata.tex": errata_tex(runs, tests),
             "machine.tex": machine_tex(runs)}
    if args.methods:
        files["methods.tex"] = methods_tex(json.loads(pathlib.Path(args.methods).read_text(encoding="utf-8")))
    if args.quick:
        files["quick.tex"] = quick_tex(ctest, args.quick)
    if args.junit:
        hard = {t["name"] for t in ctest for p in t.get("properties", []) if p["name"] == "LABELS"
                and "hardcase" in p["value"]} if ctest else None
        files["hardcases.tex"] = hard_cases_tex(pathlib.Path(args.junit).read_text(encoding="utf-8"), hard)
    if args.papers:
        papers = tomllib.loads(pathlib.Path(args.papers).read_text(encoding="utf-8"))
        files["ledger.tex"] = ledger_tex(runs, papers, tests)
        files["bibliography.tex"] = bibliography_tex(papers)
    out.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        write(out / name, text)
    for m in missing:
        print(f"report.py: no value for {m}", file=sys.stderr)
    print(f"report.py: {len(runs)} runs: " + ", ".join(files) + (f"; {len(missing)} values missing" if missing else ""))
    return 1 if missing and not args.draft else 0


if __name__ == "__main__":
    sys.exit(main())
