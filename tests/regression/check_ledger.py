#!/usr/bin/env python3
"""check_ledger.py SOURCE_DIR WORK_DIR

The reproduction ledger (scripts/report.py) from a fixture of summaries: every row takes its verdict
and its values from its own figure's comparisons (summary.json "figures", made by the runner), never
from another figure of the same run ([004] Fig. 5, study poincare, from Fig. 4's, study ensemble, whose
ensemble it cuts) or of another scene ([003] Figs 5.5 and 5.6, the free particle's, from the harmonic
scene's Fig. 5.3), and names the study that made it. Also: the errata chapter lists an
open convention and an authors'-code value in their own sections, never as errata or as published, an
erratum with the paper's words it quotes, no ledger cell past 6 lines, and report.py refuses a results directory that is not its paper scene's run, and a \\cite of a work
that paper/papers.toml does not list.
"""
import json
import pathlib
import shutil
import subprocess
import sys


def comparison(figure, published, reproduced, verdict, **extra):
    return {"study": "s", "figure": figure, "where": f"{figure}: printed", "published": published,
            "reproduced": reproduced, "verdict": verdict, **extra}


FIXTURE = {  # run id -> (experiment, scene file, {study: items made}, comparisons)
    "ti_drift": ("ti_drift", "experiments/ti_drift/ti_drift.toml", {"ensemble": ["004 Fig. 4"],
                                                                            "poincare": ["004 Fig. 5"]}, {
        "sigma4": comparison("004 Fig. 4", 0.54e-6, 0.551e-6, "reproduced"),
        "side5": comparison("004 Fig. 5", "> 0.5", 0.0742, "differs", expect="differs", kind="sample",
                            note="another trajectory", test="x.Side"),
        "one_side5": comparison("004 Fig. 5", "> 0.8", 0.9258, "reproduced"),
        "norm": comparison("004 Fig. 4", 2, 2.31, "differs", kind="convention", note="the norm is not stated"),
        "bounded14": comparison("004 Sec. 1.4", 1, 1.18e6, "differs", expect="differs", note="from rest", test="x.Rest",
                                quotes=[{"at": "004 Sect. 1.4", "text": "remains bounded (converges to one) when ωh → 2 √ 3."}]),
    }),
    "measure_cloud": ("measure_cloud", "experiments/measure_cloud/measure_cloud.toml", {"energies": ["003 Fig. 5.3"]}, {
        "kmod3": comparison("003 Fig. 5.3", "< 0.00063", {"M": 4.02e-6, "T": 8.06e-6}, "reproduced"),
        "cloud": comparison("003 Fig. 5.3", 1.33e-4, 1.331e-4, "reproduced", kind="authors_code"),
        "full_cloud": comparison("003 Fig. 5.3", 1.33e-4, 2.9e-6, "differs", expect="differs", kind="authors_code",
                                 note="the full 600-cell", test="x.Cloud"),
    }),
    "measure_cloud-free": ("measure_cloud", "experiments/measure_cloud/free.toml",
                           {"energies": ["003 Fig. 5.5", "003 Fig. 5.6"]}, {
        "drift55": comparison("003 Fig. 5.5", "> 1", {"M": 9.75, "T": 9.70}, "reproduced"),
        "err56": comparison("003 Fig. 5.6", "> 1", {"M": 5.597, "T": 5.849}, "reproduced"),
    }),
}
PAPERS = """
[[paper]]
id = "003"
authors = "A"
title = "T"
venue = "V"
year = 2020
  [[paper.item]]
  name = "Fig. 5.3"
  [[paper.item]]
  name = "Fig. 5.5"
  [[paper.item]]
  name = "Fig. 5.6"
[[paper]]
id = "004"
authors = "A"
title = "T"
venue = "V"
year = 2020
  [[paper.item]]
  name = "Fig. 4"
  [[paper.item]]
  name = "Fig. 5"
"""


VERDICTS = {  # summary.json "figures" as the runner computes them (runner/published.cpp, figure_verdict)
    "004 Fig. 4": {"verdict": "reproduced", "reproduced": ["sigma4"], "conventions": ["norm"]},
    "004 Fig. 5": {"verdict": "partly reproduced", "reproduced": ["one_side5"], "differs": ["side5"]},
    "003 Fig. 5.3": {"verdict": "reproduced", "reproduced": ["kmod3", "cloud"]},
    "003 Fig. 5.5": {"verdict": "reproduced", "reproduced": ["drift55"]},
    "003 Fig. 5.6": {"verdict": "reproduced", "reproduced": ["err56"]},
}


def write_fixture(results, papers_file):
    for run_id, (experiment, scene, made, comparisons) in FIXTURE.items():
        d = results / run_id
        d.mkdir(parents=True)
        figures = {item: VERDICTS[item] for items in made.values() for item in items}
        (d / "summary.json").write_text(json.dumps({"experiment": experiment, "comparisons": comparisons,
                                                    "figures": figures}))
        study_list = [{"name": s, "makes": "", "made": items, "files": [], "ran": True} for s, items in made.items()]
        (d / "run.json").write_text(json.dumps({"scene_file": scene, "overrides": [], "studies": list(made),
                                                "scene": {}, "study_list": study_list}))
    papers_file.write_text(PAPERS)


def rows(ledger):
    """Ledger row text by item, e.g. "[004] Fig. 5" -> its row."""
    out = {}
    for line in ledger.splitlines():
        if line.startswith("{["):
            paper, _, rest = line[2:].partition("]}")
            out[f"[{paper}]{rest.split('&')[0].rstrip()}"] = line
    return out


def main():
    global SOURCE
    SOURCE, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    shutil.rmtree(work, ignore_errors=True)
    results, out, papers = work / "results", work / "out", work / "papers.toml"
    write_fixture(results, papers)
    report = [sys.executable, str(SOURCE / "scripts" / "report.py"), str(results), str(out), "--papers", str(papers),
              "--tex"]
    subprocess.run(report, check=True, capture_output=True, text=True)
    ledger = rows((out / "ledger.tex").read_text(encoding="utf-8"))
    errata = (out / "errata.tex").read_text(encoding="utf-8")
    problems = []

    def expect(cond, what):
        if not cond:
            problems.append(what)
    fig4, fig5 = ledger.get("[004] Fig. 4", ""), ledger.get("[004] Fig. 5", "")
    expect("partly reproduced" in fig5, f"[004] Fig. 5 is not 'partly reproduced': {fig5}")
    expect("0.0742" in fig5.replace("7.42", "0.0742") or "7.42" in fig5, f"[004] Fig. 5 lacks its measured share: {fig5}")
    expect("5.51" not in fig5 and "5.4" not in fig5, f"[004] Fig. 5 shows Fig. 4's sigma: {fig5}")
    expect("5.51" in fig4, f"[004] Fig. 4 lacks its sigma: {fig4}")
    expect("study poincare" in fig5 and "study ensemble" not in fig5, f"[004] Fig. 5 is not rerun by its study: {fig5}")
    expect("study ensemble" in fig4 and "study poincare" not in fig4, f"[004] Fig. 4 is not rerun by its study: {fig4}")
    for item, own, other in (("[003] Fig. 5.5", "9.7", "4.02"), ("[003] Fig. 5.6", "5.6", "4.02"),
                             ("[003] Fig. 5.3", "4.02", "9.7")):
        row = ledger.get(item, "")
        expect(own in row and other not in row, f"{item} does not show its own values ({own}, not {other}): {row}")
    conventions = errata.split("Conventions the papers leave open")[1].split("subsection")[0]
    code = errata.split("Values from the authors' code")[1].split("subsection")[0]
    only_errata = errata.split("subsection*{Errata}")[1].split("subsection")[0]
    expect("norm" in conventions and "norm" not in only_errata, "the open convention is listed as an erratum")
    expect("The authors' code gives" in code and "Printed: $1.33" not in errata, "an authors' code value shows as printed")
    expect("side5" not in only_errata and "side5" in errata, "an observation of a sample is listed as an erratum")
    expect("full" not in only_errata and "full" in code,  # (the authors' code is not the paper: never an erratum)
           "an authors'-code value that the reproduction differs from is filed as an erratum")
    expect(r"004 Sect. 1.4: ``remains bounded (converges to one) when $\omega$h $\to$ 2 $\surd$ 3.''" in only_errata,
           "an erratum does not quote the paper's words (with its Unicode symbols as math)")
    # every \cite names a work of papers.toml (its [[reference]] keys, or paperNNN)
    cites = work / "cites.tex"
    cites.write_text("\\cite{paper004} \\cite{nowhere1999}\n")
    cited = subprocess.run(report + [str(cites)], capture_output=True, text=True)
    expect(cited.returncode != 0 and "nowhere1999" in cited.stderr and "paper004" not in cited.stderr,
           f"an unknown \\cite key passes: exit {cited.returncode}, {cited.stderr.strip()}")
    # the text looks a figure's verdict up (\verdict{run}{name}: the item of the run by the slug of its name, or by
    # the study that made it, never by its id); a name that is no item the run made stops the script
    verdicts = work / "verdicts.tex"
    for name in ("fig5", "poincare"):
        verdicts.write_text(f"\\verdict{{ti_drift}}{{{name}}}\n")
        subprocess.run(report + [str(verdicts)], check=True, capture_output=True, text=True)
        expect(f"\\@namedef{{geomint@verdict@ti_drift@{name}}}{{\\emph{{partly reproduced}}}}" in
               (out / "results.tex").read_text(encoding="utf-8"),
               f"\\verdict{{ti_drift}}{{{name}}} is not defined as the verdict of 004 Fig. 5 in its run")
    verdicts.write_text("\\verdict{ti_drift}{fig9}\n")
    judged = subprocess.run(report + [str(verdicts)], capture_output=True, text=True)
    expect(judged.returncode != 0 and "fig9" in judged.stderr, "a verdict of an item the run did not make passes")
    # a ledger cell that would run past 6 lines stops the script, naming it (details go to the experiment's section)
    summary_file = results / "ti_drift" / "summary.json"
    kept = summary_file.read_text()
    summary = json.loads(kept)
    summary["comparisons"]["sigma4"]["test"] = "regression.TiDrift." + "AVeryLongTestName" * 12
    summary_file.write_text(json.dumps(summary))
    long_cell = subprocess.run(report, capture_output=True, text=True)
    expect(long_cell.returncode != 0 and "rerun cell of [004] Fig. 4" in long_cell.stderr,
           f"a ledger cell of 8 lines passes: exit {long_cell.returncode}, {long_cell.stderr.strip()}")
    summary_file.write_text(kept)
    # a reviewer's rerun (--set) in a paper run's directory is refused, naming the directory
    run = json.loads((results / "ti_drift" / "run.json").read_text())
    run["overrides"] = ["ensemble.size=8"]
    (results / "ti_drift" / "run.json").write_text(json.dumps(run))
    scenes = ["--paper-scenes"] + [f"{r}={f[1]}" for r, f in FIXTURE.items()]
    refused = subprocess.run(report[:-1] + scenes + ["--tex"], capture_output=True, text=True)
    expect(refused.returncode != 0 and "ti_drift" in refused.stderr and "--set" in refused.stderr,
           f"a run with --set was reported: exit {refused.returncode}, {refused.stderr.strip()}")
    for p in problems:
        print("check_ledger:", p)
    print(f"check_ledger: {len(ledger)} rows, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
