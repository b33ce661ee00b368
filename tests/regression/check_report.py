#!/usr/bin/env python3
"""check_report.py SOURCE_DIR RESULTS_ROOT WORK_DIR METHODS_BIN

The generic report script (scripts/report.py) on the quick runs: it writes its files, every
comparison of every summary.json has its row in comparisons.tex, the ledger names every figure and
table of paper/papers.toml, quick.tex lists a quick run's comparisons (by number) and the tests that wait on it,
a \\result lookup of an existing key (of summary.json, and run.<key> of run.json) is defined and one of a missing
key stops the script naming the key, and the script stays generic (no experiment name in it, at
most 600 lines).
"""
import json
import pathlib
import shutil
import subprocess
import sys
import tomllib


def cited_tests(results, runs):
    """The tests the report cites: each comparison's test and each run's `<run>.studies`."""
    names = {f"{run}.studies" for run in runs}
    for run in runs:
        comparisons = json.loads((results / run / "summary.json").read_text(encoding="utf-8")).get("comparisons", {})
        names |= {c["test"] for c in comparisons.values() if c.get("test")}
    return sorted(names)


def main() -> int:
    source, all_results, work, methods_bin = (pathlib.Path(a) for a in sys.argv[1:5])
    script = source / "scripts" / "report.py"
    problems = []
    text = script.read_text(encoding="utf-8")
    if len(text.splitlines()) > 600:
        problems.append(f"{script}: {len(text.splitlines())} lines (at most 600)")
    for exp in sorted({p.parent.name for p in (source / "experiments").glob("*/*.cpp")}):
        if exp in text:
            problems.append(f"{script} names the experiment {exp}")
    work.mkdir(parents=True, exist_ok=True)
    methods = work / "methods.json"
    methods.write_text(subprocess.run([str(methods_bin), "--json"], capture_output=True, text=True, check=True).stdout)
    # The quick runs (<name>, and <name>-<v> of a second paper scene), copied: other tests write and remove
    # directories of their own beside them while this one runs.
    results = work / "results"
    shutil.rmtree(results, ignore_errors=True)
    for exp_dir in sorted({p.parent for p in (source / "experiments").glob("*/*.cpp")}):
        exp = exp_dir.name
        variants = [p.stem for p in exp_dir.glob("*.toml")
                    if p.stem not in (exp, "published", "quick") and not p.stem.startswith("quick-")
                    and "\n# scale: cluster" not in "\n" + p.read_text(encoding="utf-8")]  # (not a paper scene)
        for run in [exp] + [f"{exp}-{v}" for v in variants]:
            if (all_results / run / "summary.json").exists():
                shutil.copytree(all_results / run, results / run)
    runs = sorted(p.parent.name for p in results.glob("*/summary.json"))
    lookups_tex = work / "lookups.tex"  # every run's wall time, in two formats, and a value of its run.json
    lookups_tex.write_text("".join(f"\\result{{{r}}}{{timing.wall_s}} \\result[sci]{{{r}}}{{timing.wall_s}} "
                                   f"\\result[plain]{{{r}}}{{run.timing_protocol.floor_ms}}\n" for r in runs),
                           encoding="utf-8")
    command = [sys.executable, str(script), str(results), str(work), "--methods", str(methods),
               "--papers", str(source / "paper" / "papers.toml")]
    junit = work / "junit.xml"  # a ctest JUnit report: a passed and a failed hard case, and a fixture
    junit.write_text('<testsuite><testcase name="Suite.StaysBounded" classname="x" time="0.5" status="run">'
                     '<system-out>[ RUN ]\nHARDCASE {"what":"max |z|","measured":0.5,"relation":"&lt;=","bound":1.0}\n'
                     '</system-out></testcase>'
                     '<testcase name="Suite.DivergesBeyondTheBound" classname="x" time="1.5" status="fail"/>'
                     '<testcase name="exp.quick_run" classname="x" time="2.5" status="run"/></testsuite>',
                     encoding="utf-8")
    run0 = runs[0]  # a ctest test list: the quick run of run0 and one test that waits on it
    ctest_json = work / "tests.json"
    ctest_json.write_text(json.dumps({"tests": [
        {"name": f"{run0}.quick_run", "command": ["exe", "--scene", f"experiments/{run0}/quick.toml"],
         "properties": [{"name": "FIXTURES_SETUP", "value": [f"{run0}_quick"]}]},
        {"name": "Suite.WaitsOnIt", "properties": [{"name": "FIXTURES_REQUIRED", "value": [f"{run0}_quick"]}]}] +
        [{"name": name} for name in cited_tests(results, runs)] +
        [{"name": name, "properties": [{"name": "LABELS", "value": ["unit", "hardcase"]}]}
         for name in ("Suite.StaysBounded", "Suite.DivergesBeyondTheBound")]}))
    subprocess.run(command + ["--tex", str(lookups_tex), "--junit", str(junit), "--tests", str(ctest_json),
                              "--quick", str(results)], check=True)
    quick = (work / "quick.tex").read_text(encoding="utf-8") if (work / "quick.tex").is_file() else ""
    if "waited on by 1 tests" not in quick:
        problems.append("quick.tex does not count the tests that wait on a quick run")
    for key, c in json.loads((results / run0 / "summary.json").read_text(encoding="utf-8")).get("comparisons", {}).items():
        if f"\\hyperref[cmp:{run0}:{key}]" not in quick or c["verdict"] not in quick:
            problems.append(f"quick.tex: no row for {run0}'s comparison {key} (its number) with its verdict")
    hard = (work / "hardcases.tex").read_text(encoding="utf-8") if (work / "hardcases.tex").is_file() else ""
    if "Stays Bounded} & passed" not in hard or "Diverges beyond the Bound} & FAILED" not in hard:
        problems.append("hardcases.tex does not list the JUnit report's tests with their results")
    if r"max $|z|$ & $0.5000$ & $\le$ $1$" not in hard:
        problems.append("hardcases.tex does not show a case's measured value and bound (HARDCASE line)")
    if "quick" in hard:
        problems.append("hardcases.tex lists a fixture that is not labelled hardcase")
    for name in ("results.tex", "comparisons.tex", "errata.tex", "methods.tex", "ledger.tex", "bibliography.tex",
                 "machine.tex"):
        if not (work / name).is_file():
            problems.append(f"{name} not written")
    names = (work / "method_names.tex").read_text(encoding="utf-8") if (work / "method_names.tex").is_file() else ""
    for line in (r"\@namedef{geomint@method@sti@004}{(1.6)}", r"\@namedef{geomint@method@phi4}{$\Phi^{(4)}_h$}",
                 r"\@namedef{geomint@method@rowlands_printed}{Rowlands, printed processors $h^2$/24}"):
        if line not in names:  # (\method: the registry's titles as LaTeX, its equations per paper)
            problems.append(f"method_names.tex has no {line}")
    comparisons = (work / "comparisons.tex").read_text(encoding="utf-8").replace("\\allowbreak{}", "")
    lookups = (work / "results.tex").read_text(encoding="utf-8")
    ledger = (work / "ledger.tex").read_text(encoding="utf-8")
    for run in runs:
        summary = json.loads((results / run / "summary.json").read_text(encoding="utf-8"))
        for key in summary.get("comparisons", {}):
            if f"\\label{{cmp:{run}:{key}}}" not in comparisons:
                problems.append(f"{run}: comparison {key} has no row (\\label{{cmp:{run}:{key}}}) in comparisons.tex")
        for fmt in ("general", "sci"):
            if f"geomint@{run}@{fmt}@timing.wall_s@v" not in lookups:
                problems.append(f"{run}: no \\result[{fmt}] for timing.wall_s")
        floor = json.loads((results / run / "run.json").read_text(encoding="utf-8"))["timing_protocol"]["floor_ms"]
        if f"geomint@{run}@plain@run.timing_protocol.floor_ms@v}}{{\\ensuremath{{{floor:g}}}}}" not in lookups:
            problems.append(f"{run}: \\result{{{run}}}{{run.timing_protocol.floor_ms}} is not run.json's {floor:g}")
    papers = tomllib.loads((source / "paper" / "papers.toml").read_text(encoding="utf-8"))
    for paper in papers["paper"]:
        for item in paper.get("item", []):
            if f"{{[{paper['id']}]}} {item['name']}" not in ledger:
                problems.append(f"ledger: no row for [{paper['id']}] {item['name']}")
    lookups_tex.write_text("\\result{" + runs[0] + "}{no.such.key}\n", encoding="utf-8")
    missing = subprocess.run(command + ["--tex", str(lookups_tex)], capture_output=True, text=True)
    if missing.returncode == 0 or "no.such.key" not in missing.stderr:
        problems.append("a missing key does not stop report.py with its name")
    for p in problems:
        print(p)
    print("report: " + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
