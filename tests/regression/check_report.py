#!/usr/bin/env python3
"""check_report.py SOURCE_DIR RESULTS_ROOT WORK_DIR METHODS_BIN

The generic report script (scripts/report.py) on the quick runs: it writes its four files, every
comparison of every summary.json appears in comparisons.tex, every \\result lookup of a number is
defined, and the script stays generic (no experiment name in it, at most 600 lines).
"""
import json
import pathlib
import subprocess
import sys


def main() -> int:
    source, results, work, methods_bin = (pathlib.Path(a) for a in sys.argv[1:5])
    script = source / "scripts" / "report.py"
    problems = []
    text = script.read_text(encoding="utf-8")
    if len(text.splitlines()) > 600:
        problems.append(f"{script}: {len(text.splitlines())} lines (at most 600)")
    for exp in sorted(p.parent.name for p in (source / "experiments").glob("*/main.cpp")):
        if exp in text:
            problems.append(f"{script} names the experiment {exp}")
    work.mkdir(parents=True, exist_ok=True)
    methods = work / "methods.json"
    methods.write_text(subprocess.run([str(methods_bin), "--json"], capture_output=True, text=True, check=True).stdout)
    subprocess.run([sys.executable, str(script), str(results), str(work), "--methods", str(methods)], check=True)
    for name in ("results.tex", "comparisons.tex", "errata.tex", "methods.tex"):
        if not (work / name).is_file():
            problems.append(f"{name} not written")
    comparisons = (work / "comparisons.tex").read_text(encoding="utf-8")
    lookups = (work / "results.tex").read_text(encoding="utf-8")
    for path in sorted(results.glob("*/summary.json")):
        summary = json.loads(path.read_text(encoding="utf-8"))
        run = path.parent.name
        for key in summary.get("comparisons", {}):
            if key.replace("_", "\\_") not in comparisons:
                problems.append(f"{run}: comparison {key} not in comparisons.tex")
        if f"geomint@{run}@timing.wall_s@g" not in lookups:  # a number every run has: its wall time
            problems.append(f"{run}: no \\result for timing.wall_s")
    for p in problems:
        print(p)
    print("report: " + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
