#!/usr/bin/env python3
"""check_studies.py BIN SCENE FULL_DIR WORK_DIR [ARGS...]

Each study of a scene runs alone: for every study S that the full run of SCENE
with the options ARGS (its outputs in FULL_DIR) ran, `BIN --scene SCENE ARGS --study S` must
  - exit 0,
  - write exactly the CSV files S declares (`BIN --list-studies`; every
    declared name or pattern matched, nothing else) besides summary.json, run.json and
    figure_values.gp,
  - report studies == [S] in summary.json and run.json, and a wall time for S only,
  - write the same bytes as the full run in every CSV but timing*.csv (wall times), and in a
    work-precision set cost_*.csv the same cells but its wall times (same_csv.py).
"""
import fnmatch
import json
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import same_csv  # noqa: E402


def main() -> int:
    if len(sys.argv) < 5:
        print(__doc__, file=sys.stderr)
        return 2
    binary, scene, full, work = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3]), pathlib.Path(sys.argv[4])
    args = sys.argv[5:]
    listing = subprocess.run([binary, "--list-studies"], check=True, capture_output=True, text=True).stdout
    declared = {}
    for line in listing.splitlines():
        name, _makes, files = line.split("\t")
        declared[name] = files.split()
    ran = json.loads((full / "summary.json").read_text())["studies"]
    failures = []
    for study in ran:
        out = work / study
        shutil.rmtree(out, ignore_errors=True)
        result = subprocess.run([binary, "--scene", scene, *args, "--study", study, "--threads", "2", "--out", str(out)],
                                capture_output=True, text=True)
        if result.returncode != 0:
            failures.append(f"{study}: exit {result.returncode}: {result.stderr.strip()}")
            continue
        csvs = sorted(p.name for p in out.glob("*.csv"))
        others = sorted(p.name for p in out.iterdir() if p.suffix != ".csv")
        if others != ["figure_values.gp", "run.json", "summary.json"]:
            failures.append(f"{study}: unexpected files {others}")
        patterns = declared[study]
        undeclared = [f for f in csvs if not any(fnmatch.fnmatchcase(f, p) for p in patterns)]
        unmatched = [p for p in patterns if not any(fnmatch.fnmatchcase(f, p) for f in csvs)]
        if undeclared or unmatched:
            failures.append(f"{study}: wrote {csvs}; declared {patterns}")
        summary = json.loads((out / "summary.json").read_text())
        run = json.loads((out / "run.json").read_text())
        if summary.get("studies") != [study] or run.get("studies") != [study]:
            failures.append(f"{study}: summary/run studies are {summary.get('studies')} / {run.get('studies')}")
        if list(summary["timing"]["study_wall_s"]) != [study]:
            failures.append(f"{study}: wall times for {list(summary['timing']['study_wall_s'])}")
        for f in csvs:
            if f.startswith("timing"):
                continue
            if not (same_csv.same(out / f, full / f) if f.startswith("cost_") else (out / f).read_bytes() == (full / f).read_bytes()):
                failures.append(f"{study}: {f} differs from the run of the whole scene")
        print(f"{study}: {len(csvs)} CSV files, {summary['timing']['study_wall_s'][study]:.2f} s")
    for f in failures:
        print("FAIL " + f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
