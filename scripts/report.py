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
                                                    resolved scene as scene.<key> (run.json; run.<key>: any of it)
                      \\resultrange[fmt]{run}{key}   an object {min, max} as "a--b" ("a" if equal)
                    fmt: one of FORMATS below (default general). A key that does not exist or has
                    no finite value stops this script (exit 1) and the LaTeX run, naming it; with
                    --draft it is shown as a framed "missing" note instead. fmt? (e.g. err?): a
                    value the run may not have (null or absent, e.g. an equal wall time that the
                    runs' times do not reach) is shown as ---.
                      \\ifresult{run}{key}{A}{B}   A if the run has the value (not null), else B
                      \\verdict{run}{fig5}   the verdict of a run's item by its slug or study (summary.json figures)
  comparisons.tex   per run, its published quantities (summary.json "comparisons", made by the
                    executable from experiments/<name>/published.toml) against the reproduction, each by
                    its number (#1, #2, ...: \\cmpref{run}{key}) and description, never by its key.
  figure_items.tex  each figure's labels, \\figureitems{name} (figures/<name>.gp; report_tables.py), and with
                    figure_comparisons.tex each run's tables of comparisons (\\runcomparisons, \\comparisongrid).
  errata.tex        every comparison published.toml expects to differ: what was published, what
                    the project uses instead and why, and the ctest test that shows it.
  methods.tex       the method registry (`geomint-methods --json`).
  ledger.tex        with --papers: one row per figure and table of the papers (paper/papers.toml),
                    the studies that make it (run.json "study_list"), the verdict of their
                    comparisons, the command, the figure scripts that read its files and the tests.
  bibliography.tex  with --papers: the papers and their code.
  machine.tex       the CPU, compiler, flags and commit of the runs (run.json).
  hardcases.tex     with --junit: every hard case (ctest label hardcase) of the last ctest run, by
                    kind: what its name says it asserts, its result and time; a test of the check itself
                    apart, with the faults it plants marked; no path of the machine that ran it.
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
from xml.etree import ElementTree

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from paper_runs import why_not_paper_run  # noqa: E402
from report_records import LOOKUP, at, expand_record, label_problems, read_records, record_problems  # noqa: E402
from report_tables import comparison_numbers, comparison_ref, comparisons_tex, figure_comparisons_tex, \
    figure_items_tex, item_slug, key_refs, method_names_tex, methods_tex, named_items, rule_text, tolerances_tex  # noqa: E402
from tex_format import FORMATS, GREEK as GREEK_NAMES, ascii_math, code, is_number, longtable, number, prose, \
    quote_tex, repo_paths, tex_escape, value_text  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


TEXT_FORMATS = ("text", "vec", "tverdict")
HAS = re.compile(r"\\ifresult\{([^}]*)\}\{([^}]*)\}")  # \ifresult{run}{key}{if it has a value}{if not}
VERDICT = re.compile(r"\\verdict\{([^}]*)\}\{([^}]*)\}")  # \verdict{run}{fig5}: summary.json figures


def lookup_text(run, key, fmt, ranged):
    """The LaTeX of one lookup, or None if the value does not exist or cannot be shown."""
    tree, key = (run["run"], key.removeprefix("run.")) if key.startswith(("scene.", "run.")) else (run["summary"], key)
    v = at(tree, key)
    if ranged:
        if not isinstance(v, dict):
            return None
        a, b = number(v.get("min"), fmt), number(v.get("max"), fmt)
        return None if a is None or b is None else f"\\ensuremath{{{a}}}" if a == b else \
            f"\\ensuremath{{{a}}}--\\ensuremath{{{b}}}"
    if fmt == "text":  # (a string of the run: its ASCII math, "< 0.00063", h^2/24, as math)
        return ascii_math(v) if isinstance(v, str) else None
    if fmt == "tverdict":  # a timing's verdict against its reference (runner/timing.hpp), short
        return f"({TIMING_VERDICTS[v]})" if v in TIMING_VERDICTS else None
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
             r"\newcommand{\resultrange}[3][general]{\geomint@value{#2}{#1}{#3}{r}}",
             r"\newcommand{\ifresult}[4]{\@ifundefined{geomint@has@#1@#2}{#4}{#3}}",
             r"\newcommand{\verdict}[2]{\@ifundefined{geomint@verdict@#1@#2}{\PackageError{report}"
             r"{no verdict of #2 in the run #1}{Run make paper}}{\@nameuse{geomint@verdict@#1@#2}}}"]
    missing, seen = [], set()
    for path in tex_files:
        text = re.sub(r"(?<!\\)%.*", "", path.read_text(encoding="utf-8"))  # (not in LaTeX comments)
        for m in HAS.finditer(text):  # a value that may be absent (e.g. no overlap of wall times)
            run, key = m.group(1), m.group(2)
            if run in runs and at(runs[run]["summary"], key) is not None:
                lines.append(f"\\@namedef{{geomint@has@{run}@{key}}}{{}}")
        for m in VERDICT.finditer(text):  # a figure's verdict, computed by its run from its own comparisons
            run, name = m.group(1), m.group(2)
            items = named_items(runs[run], name) if run in runs else []  # (the one item of that name)
            verdict = ((runs[run]["summary"].get("figures") or {}).get(items[0]) or {}).get("verdict") \
                if len(items) == 1 else None
            if verdict is None:
                missing.append(f"{path.name}: {m.group(0)}")
            else:
                lines.append(f"\\@namedef{{geomint@verdict@{run}@{name}}}{{\\emph{{{tex_escape(verdict)}}}}}")
        for m in LOOKUP.finditer(text):
            ranged, fmt, run, key = bool(m.group(1)), m.group(2) or "general", m.group(3), m.group(4)
            if (run, key, fmt, ranged) in seen or "#" in run + key + fmt:  # (a macro's own parameters)
                continue
            seen.add((run, key, fmt, ranged))
            optional = fmt.endswith("?")  # [fmt?]: a value that may be absent, shown as ---
            fmt = fmt.rstrip("?")
            if fmt not in FORMATS and fmt not in TEXT_FORMATS:
                raise SystemExit(f"report.py: {path}: unknown format '{fmt}' in {m.group(0)}")
            text = lookup_text(runs[run], key, fmt, ranged) if run in runs else None
            if text is None and optional and run in runs and at(runs[run]["summary"], key) is None:
                text = "---"
            fmt += "?" if optional else ""
            if text is None:
                missing.append(f"{path.name}: {m.group(0)}")
                if not draft:
                    continue
                text = r"\fbox{\scriptsize missing: " + tex_escape(f"{run} {key}") + "}"
            lines.append(f"\\@namedef{{geomint@{run}@{fmt}@{key}@{'r' if ranged else 'v'}}}{{{text}}}")
    lines.append(r"\makeatother")
    return "\n".join(lines) + "\n", missing


ERRATA_SECTIONS = [  # (title, the comparisons it lists)
    # (an erratum quotes what the paper prints: the authors' code is not the paper, and its values never are errata)
    ("Errata", lambda c: c.get("expect") == "differs" and c.get("kind", "printed") == "printed"),
    ("Possible scanning errors", lambda c: c.get("expect") == "differs" and c.get("kind") == "scanning"),
    ("Conventions the papers leave open", lambda c: c.get("kind") == "convention"),
    ("Values from the authors' code", lambda c: c.get("kind") == "authors_code"),
    ("Observations of a sample the papers do not give", lambda c: c.get("kind") == "sample"),
]
ERRATA_INTRO = {
    "Errata": "A printed statement that derivation and a test contradict, quoted as the text of the paper here "
              "gives it (that text has no page numbers: section, equation or caption instead).",
    "Possible scanning errors": "A printed statement that does not hold as the scanned text gives it, where "
                                "the scan may have garbled it: flagged, not charged to the paper.",
    "Conventions the papers leave open": "A choice the paper does not state; the report computes both and "
                                         "compares only the one stated in the comparisons. Neither is an erratum.",
    "Values from the authors' code": "Numbers the papers do not print, taken from the code published with them "
                                     "and labelled so; they are never listed as published.",
    "Observations of a sample the papers do not give": "What a paper observes on one random sample (a trajectory "
                                                       "from a start it does not print); the reproduction's sample "
                                                       "may differ without contradicting it.",
}


def errata_tex(runs, tests):
    """The published statements the reproduction differs from, the possible scanning errors, the open
    conventions and the authors' code values (published.toml: expect, kind), one subsection each."""
    out = ["% Errata, scanning errors, open conventions, authors' code values (published.toml: expect, kind)."]
    numbers = comparison_numbers(runs)
    for title, selects in ERRATA_SECTIONS:
        items = []
        for name, run in runs.items():
            refs = key_refs(numbers, name)
            for key, c in (run["summary"].get("comparisons") or {}).items():
                if not selects(c):
                    continue
                test = c.get("test", "")
                if test and tests is not None and test not in tests:
                    raise SystemExit(f"report.py: {name}: {key} names the test '{test}', which ctest does not list")
                source = {"authors_code": "The authors' code gives", "convention": "Compared with"}.get(
                    c.get("kind"), "Printed")
                verdict = "" if c.get("kind") == "convention" else f", verdict: {c['verdict']}"
                quotes = "".join(f" {prose(q['at'])}: ``{quote_tex(q['text'])}''" for q in c.get("quotes", []))
                items.append(f"\\item \\textbf{{{prose(c['where'], refs)}.}}{quotes} {source}: "
                             f"{value_text(c.get('published'))}; reproduced: {value_text(c.get('reproduced'))} "
                             f"({comparison_ref(numbers, name, key)}{verdict}). {prose(c.get('note', ''), refs)}" +
                             (f" Shown by {code('ctest -R ' + test)}." if test else ""))
        out += [f"\\subsection*{{{title}}}", ERRATA_INTRO[title]]
        out += [r"\begin{enumerate}"] + items + [r"\end{enumerate}"] if items else ["None."]
    return "\n".join(out) + "\n"


def figure_scripts(run, files):
    """The figure scripts of a run (figures/<run>_*.gp) that read one of a study's files."""
    found = []
    for gp in sorted((ROOT / "figures").glob(f"{run}_*.gp")):
        text = gp.read_text(encoding="utf-8")
        if any(re.search(re.escape(f).replace(r"\*", r"[^'\" ]*"), text) for f in files):
            found.append(gp.name)
    return found


def short_value(c):
    """A comparison's published and reproduced values, short: "3.08e-6 / 3.11e-6"."""
    pub, rep = c.get("published"), c.get("reproduced")
    if isinstance(rep, dict) and len(rep) > 2:  # a table: its range
        nums = [x for x in rep.values() if is_number(x)]
        rep = {"min": min(nums), "max": max(nums)} if nums else None
        rep_text = f"${number(rep['min'], 'sci3')}$--${number(rep['max'], 'sci3')}$" if rep else "not computed"
    else:
        rep_text = value_text(rep)
    claim = {k: v for k, v in (c.get("compare") or {}).items() if k in ("above", "below")}
    if claim:  # a printed claim: its rule
        (rule, bound), = claim.items()
        pub_text = f"${'>' if rule == 'above' else '<'} {bound:g}$"
    else:
        pub_text = value_text(pub) if not isinstance(pub, dict) or len(pub) <= 2 else f"{len(pub)} values"
    label = "authors' code" if c.get("kind") == "authors_code" else "claim" if claim else "printed"
    return f"{label} {pub_text}, reproduced {rep_text}"


TIMING_VERDICTS = {"reference": "ref.", "indistinguishable": r"$\approx$", "faster": "faster", "slower": "slower",
                   "contradicts the work": "flagged"}
LEDGER_LINES = 6  # the most lines a ledger cell may take, and its characters per line at \scriptsize (one
LEDGER_CHARS = {"verdict": 17 * 5 // 6, "values": 27 * 5 // 6, "rerun": 35 * 5 // 6}  # line in 6 kept for breaks)


def visible(tex):
    """The characters a LaTeX fragment prints (roughly: commands and braces dropped, a reference as 'R12')."""
    tex = re.sub(r"\\(?:page)?ref\{[^}]*\}", "R12", re.sub(r"\\hyperref\[[^]]*\]", "", tex))
    return re.sub(r"\\[a-zA-Z@]+\*?|[{}$]", "", re.sub(r"\\([^a-zA-Z@])", r"\1", tex))


def ledger_cell(cell, text, where):
    """A cell of the ledger's row `where`, refused if it would run past LEDGER_LINES lines (details go to the
    experiment's section)."""
    if len(visible(text)) > LEDGER_LINES * LEDGER_CHARS[cell]:
        raise SystemExit(f"report.py: the ledger's {cell} cell of {visible(where)} would run past {LEDGER_LINES} "
                         f"lines: {visible(text)}")
    return text


def ledger_tex(runs, papers, tests):
    """One row per item of the papers, with the verdict its own run computed (summary.json "figures")
    from that item's own comparisons."""
    numbers = comparison_numbers(runs)
    makers = {}  # (paper, item) -> [(run name, study)]
    for name, run in runs.items():
        for st in run["run"].get("study_list", []):
            if st.get("ran"):
                for item in st.get("made", []):
                    paper_id, _, item_name = item.partition(" ")
                    makers.setdefault((paper_id, item_name), {}).setdefault(name, []).append(st)
    out = ["% The reproduction ledger (scripts/report.py from paper/papers.toml, run.json and summary.json).",
           longtable("scriptsize", 0.07, 0.1, 0.18, 0.28, 0.37),
           r"\toprule paper & in this report & verdict & its own values & rerun, figure, test\\ \midrule",
           r"\endhead"]
    for paper in papers["paper"]:
        for item in paper.get("item", []):  # (a paper with no items yet has no rows)
            where = f"{{[{paper['id']}]}} {tex_escape(item['name'])}"  # (braced: not \\[dimen])
            if "left_out" in item:  # (why, in the values' column)
                out.append(f"{where} & --- & left out & {ledger_cell('values', prose(item['left_out']), where)} & \\\\")
                continue
            done = makers.get((paper["id"], item["name"]), {})
            if not done:
                raise SystemExit(f"report.py: no run made [{paper['id']}] {item['name']} (papers.toml lists it)")
            figure = f"{paper['id']} {item['name']}"
            verdicts, values, commands, tests_cited, scripts = [], [], [], [], []
            for name, studies in done.items():  # one verdict per run: its own figure's comparisons
                summary = runs[name]["summary"]
                experiment = summary.get("experiment", name)
                scene = runs[name]["run"].get("scene_file", "")
                commands.append(code(f"build/bin/{experiment} " + " ".join(f"--study {st['name']}" for st in studies) +
                                     ("" if name == experiment else f" --scene {repo_paths(scene, [ROOT])}")))
                scripts += [s for st in studies for s in figure_scripts(name, st["files"]) if s not in scripts]
                f = (summary.get("figures") or {}).get(figure)
                if f is None:
                    raise SystemExit(f"report.py: {name}: summary.json has no verdict for {figure}")
                verdict = tex_escape(f["verdict"])
                comparisons = summary.get("comparisons") or {}
                refs = key_refs(numbers, name)
                for key, ch in (f.get("chosen") or {}).items():
                    verdict += f" ({refs.get(key) or prose(key)} = {value_text(ch.get('used'))}, " \
                               f"printed {value_text(ch.get('printed'))})"
                for what, co in (f.get("corrected") or {}).items():  # (what the printed one gives: its comparison)
                    verdict += (f" ({ascii_math(co['used'])} in {prose(what)}, printed {ascii_math(co['printed'])}: "
                                f"{refs.get(co['printed_gives']) or prose(co['printed_gives'])})")
                if f.get("unexpected"):
                    verdict += ": " + ", ".join(refs.get(k) or prose(k) for k in f["unexpected"]) + \
                        " differ unexpectedly"
                elif f.get("differs"):
                    verdict += r" (Section~\ref{sec:errata})"
                verdicts.append(verdict)
                for key in (f.get("differs", []) + f.get("reproduced", []))[:2]:  # (what differs first)
                    values.append(short_value(comparisons[key]))
                    if comparisons[key].get("test"):
                        tests_cited.append(comparisons[key]["test"])
                if f["verdict"] == "no printed value":
                    values.append("the paper prints no value or claim: shape compared by eye")
            own = [g for g in scripts if re.search(rf"_{item_slug(item['name'])}(?![0-9])", g)]
            scripts = own or scripts  # (a study's scripts that draw this item, where their names say so)
            tests_cited = tests_cited or [f"{runs[name]['summary'].get('experiment', name)}.studies" for name in done]
            if tests is not None:
                for t in tests_cited:
                    if t not in tests:
                        raise SystemExit(f"report.py: the ledger cites the test '{t}', which ctest does not list")
            shown = f"\\itemref{{{figure}}}"  # (paper/main.tex: the figure or table whose \\figureitems labels it)
            rerun = "; ".join(commands) + ("; " + ", ".join(code(f"figures/{g}") for g in scripts) if scripts else "") + \
                "; " + ", ".join(code(t) for t in dict.fromkeys(tests_cited))
            cells = {cell: ledger_cell(cell, text, where) for cell, text in
                     (("verdict", "; ".join(verdicts)), ("values", "; ".join(values)), ("rerun", rerun))}
            out.append(f"{where} & {shown} & {cells['verdict']} & {cells['values']} & {cells['rerun']}\\\\")
    out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def bibliography_tex(papers):
    """The four papers ([000] ...) and the other works (paper/papers.toml [[reference]], cited as
    \\cite{key})."""
    out = ["% The papers and the works they rely on (paper/papers.toml; scripts/report.py).",
           r"\begin{thebibliography}{BDH96}"]
    for p in papers["paper"] + papers.get("reference", []):
        ids = [f"doi:\\href{{https://doi.org/{p['doi']}}}{{{tex_escape(p['doi'])}}}" if "doi" in p else "",
               f"arXiv:\\href{{https://arxiv.org/abs/{p['arxiv']}}}{{{p['arxiv']}}}" if "arxiv" in p else ""]
        label, key = (p["id"], p.get("key", f"paper{p['id']}")) if "id" in p else (p["label"], p["key"])
        entry = f"\\bibitem[{tex_escape(label)}]{{{key}}} {tex_escape(p['authors'])}, \\emph{{{tex_escape(p['title'])}}}, " \
                f"{tex_escape(p['venue'])}, {p['year']}." + (" " + ", ".join(i for i in ids if i) + "." if any(ids) else "")
        if "code" in p:
            entry += f" The authors' code: \\url{{https://{p['code']}}}, commit \\texttt{{{p['code_commit']}}}."
        out.append(entry)
    out.append(r"\end{thebibliography}")
    return "\n".join(out) + "\n"


def method_citations(papers):
    """Registry name -> the \\cite of the works that define it (paper/papers.toml [[reference]] methods)."""
    cites = {}
    for r in (papers or {}).get("paper", []) + (papers or {}).get("reference", []):
        for m in r.get("methods", []):
            cites.setdefault(m, []).append(r.get("key", f"paper{r.get('id')}"))
    return {m: f" \\cite{{{','.join(keys)}}}" for m, keys in cites.items()}


def machine_tex(runs):
    seen = {}
    for run in runs.values():
        b, m, cap = run["run"].get("build", {}), run["run"].get("machine", {}), run["run"].get("lanes_cap")
        line = (f"{tex_escape(m.get('cpu', 'an unrecorded CPU'))} ({m.get('logical_cores', '?')} logical cores); "
                f"{tex_escape(b.get('compiler', '?'))}, {code(b.get('cxx_flags', ''))}; commit "
                f"\\texttt{{{tex_escape(b.get('git_commit', '?')[:12])}}}{' (with local changes)' if b.get('git_dirty') else ''}"
                + (f"; lane kernels capped at {tex_escape(cap)} (\\texttt{{GEOMINT\\_LANES}})" if cap else ""))
        seen.setdefault(line, []).append(run["run"].get("threads"))
    lines = [f"{line}; runs on {' or '.join(sorted({str(t) for t in threads}))} threads" for line, threads in seen.items()]
    return "% The machine and build of the runs (run.json).\n{\\sloppy " + r"\\ ".join(lines) + "\\par}\n"


def sentence(test_name):
    """A gtest name as words (LaTeX): Suite.ExplicitEulerAtItsBound -> 'explicit Euler at its bound'; a Greek
    letter with a number is the method of that index, as the registry writes it (phi4, Phi4: $\\Phi^{(4)}$)."""
    words = re.findall(r"[A-Z][a-z]+|[A-Z]+(?![a-z])|\d+(?:e\d+)?|[a-z]+", test_name.split(".")[-1])
    small = {"a", "an", "and", "are", "as", "at", "by", "for", "from", "in", "is", "its", "near", "not", "of", "on",
             "or", "than", "the", "to", "with", "without", "beyond", "below", "above", "stays", "stay", "gives"}
    out = [tex_escape(w.lower() if i and w.lower() in small else w) for i, w in enumerate(words)]
    for i in range(len(words) - 1):
        if words[i] in GREEK_NAMES and words[i + 1].isdigit():
            out[i], out[i + 1] = f"$\\{words[i].capitalize()}^{{({words[i + 1]})}}$", ""
    return " ".join(filter(None, out))


# The hard cases by kind, from the words of a test's name (the first kind that matches).
HARD_KINDS = [(r"^regression\.Cli\.", "Refusals by the command line (exit 2 before any work)"),
              (r"^verification\.", "Each registered method on both sides of its declared bounds"),
              ("Newton", "Newton's method"), ("Singular", "Singularities"),
              ("1e5|T100|Periods", "Long runs"), ("Refuse|Reject|FailsLoudly", "Refusals of what cannot be computed"),
              ("", "Stability bounds, instability and divergence")]


RELATIONS = {"<": "$<$", "<=": r"$\le$", ">": "$>$", ">=": r"$\ge$", "==": "$=$"}
HOLDS = {"<": lambda x, b: x < b, "<=": lambda x, b: x <= b, ">": lambda x, b: x > b, ">=": lambda x, b: x >= b,
         "==": lambda x, b: x == b}
# A test of the check itself (tests/unit/hard_case_test.cpp): it passes only if the check rejects the faults it
# plants, so a row of it that breaks its bound is the point of the test, and is shown as such.
META_KIND = "The check itself, on planted faults"


def shorten(text, n):
    """The first line of a message, cut to n characters."""
    line = text.splitlines()[0] if text else ""
    return line if len(line) <= n else line[: n - 1].rstrip() + "\u2026"


def case_holds(c):
    """Whether a HARDCASE line holds: the measured value within its bound, or the refusal naming every needle."""
    x, bound = c["measured"], c["bound"]
    if c["relation"] == "names":
        return x is not None and all(n in x for n in bound)
    if x is None:
        return False
    if c["relation"] == "near":
        return abs(x - bound) <= c["tolerance"]
    return c["relation"] in HOLDS and HOLDS[c["relation"]](x, bound)


def case_rows(output, passed=True, roots=()):
    """The measured values and bounds a test recorded (tests/hard_case.hpp: lines HARDCASE {json}), as rows, each
    with whether it holds; a row that does not hold in a test that passed is a fault the test planted."""
    def num(x):  # (an exit code or an iteration count as an integer)
        return str(int(x)) if float(x).is_integer() and abs(x) < 1e6 else number(x, "general")
    rows = []
    for line in re.findall(r"^HARDCASE (\{.*\})$", output or "", re.M):
        c = json.loads(line)
        holds = case_holds(c)
        result = "" if holds else "planted fault: rejected" if passed else "does not hold"
        what = prose(repo_paths(c["what"], roots))
        if c["relation"] == "names":  # a refusal: its message (no path of the machine), and what it must name
            said = ("accepted" if c["measured"] is None else
                    "refused: ``" + code(shorten(repo_paths(c["measured"], roots), 160)) + "''")
            needles = ", ".join("``" + code(repo_paths(n, roots)) + "''" for n in c["bound"])
            rows.append((f"\\multicolumn{{3}}{{@{{}}p{{0.84\\linewidth}}}}{{\\quad {what}: {said} "
                         f"(must name {needles})}} & {result}\\\\", holds))
            continue
        measured = "---" if c["measured"] is None else f"${num(c['measured'])}$"
        bound = (f"${num(c['bound'])} \\pm {num(c['tolerance'])}$" if c["relation"] == "near"
                 else f"{RELATIONS.get(c['relation'], tex_escape(c['relation']))} ${num(c['bound'])}$")
        rows.append((f"\\quad {what} & {measured} & {bound} & {result}\\\\", holds))
    return rows


def hard_cases_tex(junit, hard=None, roots=(ROOT,)):
    """The hard cases of the last ctest run (ctest -L hardcase --output-junit FILE), by kind, each with the
    measured values and bounds it recorded; with `hard` (the names of the tests labelled hardcase), not the
    fixtures the run needed (the quick runs). Paths in what the tests recorded are shown relative to `roots`
    (the source trees)."""
    cases = [(c.get("name"), c.get("time"), c.get("status"), c.findtext("system-out"))
             for c in ElementTree.fromstring(junit).iter("testcase") if hard is None or c.get("name") in hard]
    if not cases:
        raise SystemExit("report.py: the JUnit file lists no test")
    kinds, rows = {}, {}
    for case in cases:
        rows[case[0]] = case_rows(case[3], case[2] == "run", roots)
        planted = case[2] == "run" and not all(holds for _, holds in rows[case[0]])
        kind = META_KIND if planted else next(k for pattern, k in HARD_KINDS if re.search(pattern, case[0]))
        kinds.setdefault(kind, []).append(case)
    passed = sum(status == "run" for _, _, status, _ in cases)
    silent = [name for name, _, status, _ in cases if status == "run" and not rows[name]]
    if silent:  # (every hard case that passed shows what it measured: tests/hard_case.hpp)
        raise SystemExit("report.py: hard cases that passed recording no measured value and bound: " + ", ".join(silent))
    out = ["% The hard cases and their results (ctest -L hardcase --output-junit; scripts/report.py).",
           f"In this run {passed} of {len(cases)} hard cases passed. Each that passed records what it measured "
           "and the bound it is held to (the rows below its test): a value and a relation, or, for a refusal, "
           "the message and what it must name. The tests of the check itself come last: each plants faults, "
           "values beyond their bound and refusals that do not name what they must, and passes only if the check "
           "rejects every one; those rows are marked \\emph{planted fault: rejected}. In the messages, a path in "
           "the source tree is relative to it and DIR is a temporary directory of the test.",
           longtable("footnotesize", 0.52, 0.14, 0.2, 0.14),
           r"\toprule test, and what it measured & measured & bound & result, time (s)\\ \midrule", r"\endhead"]
    for kind in [k for _, k in HARD_KINDS] + [META_KIND]:
        if kind not in kinds:
            continue
        out.append(rf"\multicolumn{{4}}{{@{{}}l}}{{\emph{{{tex_escape(kind)} ({len(kinds[kind])})}}}}\\")
        for name, time, status, output in kinds[kind]:
            result = {"run": "passed", "fail": "FAILED"}.get(status, tex_escape(status))
            out.append(f"\\multicolumn{{3}}{{@{{}}p{{0.84\\linewidth}}}}{{{code(name)}: {sentence(name)}}} & "
                       f"{result}, {float(time):.2f}\\\\")
            out += [row for row, _ in rows[name]]
    out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def quick_tex(tests, quick_root, numbers=None, roots=(ROOT,)):
    """The quick scenes the tests run (ctest --show-only=json-v1), the tests that wait on each, and the
    tolerance bands with which each published comparison is applied to its run (QUICK/<id>/summary.json), each
    named by its number in Appendix A (`numbers`: comparison_numbers of the paper runs)."""
    props = {t["name"]: {p["name"]: p["value"] for p in t.get("properties", [])} for t in tests}
    out = ["% The quick scenes of the tests and their tolerance bands (scripts/report.py).",
           longtable("footnotesize", 0.3, 0.18, 0.18, 0.17, 0.17),
           r"\toprule quantity (Appendix~\ref{sec:comparisons}) & published & quick run & band & verdict\\ \midrule",
           r"\endhead"]
    for t in tests:
        if not t["name"].endswith(".quick_run"):
            continue
        run_id = t["name"][: -len(".quick_run")]
        fixtures = props[t["name"]].get("FIXTURES_SETUP", [])
        waiting = sorted(n for n, p in props.items() if set(p.get("FIXTURES_REQUIRED", [])) & set(fixtures))
        scene = next((a for a in t.get("command", []) if a.endswith(".toml")), "?")
        scene = repo_paths(scene, roots)
        out.append(rf"\multicolumn{{5}}{{@{{}}p{{0.95\linewidth}}@{{}}}}{{\textbf{{{code(run_id)}}}: "
                   rf"{code(scene)}, waited on by {len(waiting)} tests}}\\")
        quick = pathlib.Path(quick_root) / run_id
        summary = json.loads((quick / "summary.json").read_text(encoding="utf-8")) \
            if (quick / "summary.json").is_file() else {}
        scene = json.loads((quick / "run.json").read_text(encoding="utf-8")).get("scene", {}) \
            if (quick / "run.json").is_file() else {}
        comparisons = summary.get("comparisons", {})
        for key, c in comparisons.items():
            band = rule_text(c)
            ref = comparison_ref(numbers or {}, run_id, key)
            what = (f"{ref} ({tex_escape(c['figure'])})" if c.get("figure") else ref) if ref else \
                prose(expand_record(c["where"], summary, scene, run_id))
            out.append(f"{what} & {value_text(c.get('published'))} & {value_text(c.get('reproduced'))} & "
                       f"{tex_escape(band or '--')} & {tex_escape(c['verdict'])}\\\\")
    out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def load_runs(root, paper_scenes=None, program="report.py"):
    """The runs the report shows, by directory name in sorted order (the order of Appendix A's numbers): each
    root/<run>/summary.json with its run.json. With `paper_scenes` (ID=SCENE, as make passes them) a reviewer's
    rerun (<id>+<hash>) is left out, and a paper scene's run that is missing or not that scene's run stops
    the program (SystemExit naming why)."""
    runs, scenes = {}, dict(pair.partition("=")[::2] for pair in paper_scenes or [])
    for path in sorted(root.glob("*/summary.json")):
        if scenes and path.parent.name not in scenes and "+" in path.parent.name:
            continue  # (a reviewer's rerun, results/<id>+<hash>: not the report's)
        run_json = path.parent / "run.json"
        runs[path.parent.name] = {"summary": json.loads(path.read_text(encoding="utf-8")),
                                  "run": json.loads(run_json.read_text(encoding="utf-8")) if run_json.is_file() else {}}
    if not runs:
        raise SystemExit(f"{program}: no */summary.json in {root}")
    for run_id, scene in scenes.items():
        why = why_not_paper_run(runs[run_id]["run"], scene) if run_id in runs else "it has no summary.json"
        if why:
            raise SystemExit(f"{program}: {root / run_id} is not the run of the paper scene {scene}: {why} "
                             "(make figures reruns it)")
    return runs


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
    parser.add_argument("--paper-scenes", nargs="*", metavar="ID=SCENE",
                        help="report only these runs, each the run of its paper scene (scripts/paper_runs.py): a "
                             "run with --set overrides or without every study of its scene is refused")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    runs = load_runs(pathlib.Path(args.results), args.paper_scenes, "report.py")
    tex = [pathlib.Path(t) for t in args.tex] if args.tex is not None else \
        [ROOT / "paper" / "main.tex"] + sorted((ROOT / "paper" / "sections").rglob("*.tex"))
    read_records(runs, ROOT)
    texts = {str(t): t.read_text(encoding="utf-8") for t in tex}
    figure_items, wrong = figure_items_tex(runs, ROOT / "figures", texts)  # (a \\figureitems of no figure)
    wrong += record_problems(runs) + label_problems(texts)
    for w in wrong:  # (a description is the quantity's name: one per key, and what its record says)
        print(f"report.py: {w}", file=sys.stderr)
    if wrong:
        return 1
    tests, ctest, roots = None, [], [ROOT]
    if args.tests:
        listing = json.loads(pathlib.Path(args.tests).read_text(encoding="utf-8"))
        ctest, tests = listing["tests"], {t["name"] for t in listing["tests"]}
        roots += [pathlib.Path(f).parent.parent for f in listing.get("backtraceGraph", {}).get("files", [])
                  if pathlib.Path(f).parts[-2:] == ("tests", "CMakeLists.txt")]  # (the tree the tests ran from)
    results, missing = results_tex(runs, tex, args.draft)
    papers = tomllib.loads(pathlib.Path(args.papers).read_text(encoding="utf-8")) if args.papers else None
    figure_index, figure_tables = figure_comparisons_tex(runs, papers)
    files = {"results.tex": results, "comparisons.tex": comparisons_tex(runs), "tolerances.tex": tolerances_tex(runs),
             "figure_comparisons.tex": figure_index, **figure_tables, "figure_items.tex": figure_items,
             "errata.tex": errata_tex(runs, tests), "machine.tex": machine_tex(runs)}
    if args.methods:
        methods = json.loads(pathlib.Path(args.methods).read_text(encoding="utf-8"))
        files["methods.tex"] = methods_tex(methods, method_citations(papers))
        files["method_names.tex"] = method_names_tex(methods)
    if args.quick:
        files["quick.tex"] = quick_tex(ctest, args.quick, comparison_numbers(runs), roots)
    if args.junit:
        hard = {t["name"] for t in ctest for p in t.get("properties", []) if p["name"] == "LABELS"
                and "hardcase" in p["value"]} if ctest else None
        files["hardcases.tex"] = hard_cases_tex(pathlib.Path(args.junit).read_text(encoding="utf-8"), hard, roots)
    if papers:
        files["ledger.tex"] = ledger_tex(runs, papers, tests)
        files["bibliography.tex"] = bibliography_tex(papers)
        known = {r["key"] for r in papers.get("reference", [])} | {p.get("key", f"paper{p['id']}") for p in papers["paper"]}
        for path in tex:  # every \cite of the report names a work of papers.toml
            for keys in re.findall(r"\\cite\{([^}]*)\}", path.read_text(encoding="utf-8")):
                missing += [f"{path.name}: \\cite{{{k}}} (no [[reference]] key {k} in {args.papers})"
                            for k in keys.split(",") if k.strip() not in known]
    out.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        write(out / name, text)
    for m in missing:
        print(f"report.py: no value for {m}", file=sys.stderr)
    print(f"report.py: {len(runs)} runs: " + ", ".join(files) + (f"; {len(missing)} values missing" if missing else ""))
    return 1 if missing and not args.draft else 0


if __name__ == "__main__":
    sys.exit(main())
