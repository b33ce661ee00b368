#!/usr/bin/env python3
"""The wall time of each paper scene's run, printed at the end of `make figures`.

    scripts/figure_times.py [--rendering-from T] RESULTS SINCE ID...

Reads RESULTS/<id>/run.json (wall_s, threads, study_wall_s) of each id; SINCE is the time (seconds
since the epoch) `make figures` started: a run.json older than that is marked as not rerun (its
results were up to date). T is when the rendering started (after the runs): its wall time is the
line before the last. The last line is the wall time of this `make figures`, rendering included.
"""
import json
import sys
import time
from pathlib import Path


def main(argv):
    rendering_from = None
    if argv[:1] == ["--rendering-from"] and len(argv) > 1:
        rendering_from, argv = float(argv[1]), argv[2:]
    if len(argv) < 3:
        sys.exit(__doc__)
    results, since, ids = Path(argv[0]), float(argv[1]), argv[2:]
    rows, total = [], 0.0
    for i in ids:
        run = results / i / "run.json"
        if not run.exists():
            rows.append((i, "-", "", "no run.json"))
            continue
        info = json.loads(run.read_text())
        wall = float(info["wall_s"])
        studies = info.get("study_wall_s", {})
        slowest = max(studies.items(), key=lambda kv: kv[1]) if studies else ("", 0.0)
        fresh = run.stat().st_mtime >= since
        if fresh:
            total += wall
        note = f"{info.get('threads', '?')} threads; slowest study {slowest[0]} {slowest[1]:.1f} s"
        rows.append((i, f"{wall:.1f}", "" if fresh else "(not rerun)", note))
    width = max(len(r[0]) for r in rows)
    print("== wall time per experiment (run.json)")
    for i, wall, fresh, note in rows:
        print(f"   {i:<{width}}  {wall:>7} s  {fresh:<12} {note}")
    now = time.time()
    print(f"   {'runs of this make':<{width}}  {total:7.1f} s")
    if rendering_from is not None:
        print(f"   {'rendering':<{width}}  {now - rendering_from:7.1f} s")
    print(f"== make figures: {now - since:.1f} s")


if __name__ == "__main__":
    main(sys.argv[1:])
