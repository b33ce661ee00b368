#!/usr/bin/env python3
"""How reproducible the timing protocol's times are at each floor (runner/timing.hpp, bench/README.md).

    timing_floor.py ROOT

ROOT/<floor>-<k>/<run>/*.csv: the k-th run, at that floor, of one or more cost studies (every CSV with
the columns wall_s and wall_spread). For each floor, over its runs: per configuration (a CSV row), the
standard deviation of the logarithm of its time relative to the geometric mean of its CSV (what a
comparison within a run uses) and of its time itself; the median of each over the configurations, and
the median within-run spread (interquartile range over median)."""
import csv
import math
import pathlib
import statistics
import sys


def times(run_dir):
    out = {}
    for f in sorted(run_dir.glob("*/*.csv")):
        with f.open() as fh:
            rows = list(csv.DictReader(fh))
        if not rows or "wall_s" not in rows[0]:
            continue
        logs = [math.log(float(r["wall_s"])) for r in rows]
        mean = sum(logs) / len(logs)
        for i, r in enumerate(rows):
            out[(str(f.relative_to(run_dir)), i)] = (logs[i] - mean, logs[i], float(r["wall_spread"]))
    return out


def main():
    root = pathlib.Path(sys.argv[1])
    floors = sorted({d.name.split("-")[0] for d in root.iterdir() if d.is_dir()}, key=float)
    print("floor_s runs configurations sd_log_relative sd_log_time within_run_spread")
    for floor in floors:
        runs = [times(d) for d in sorted(root.glob(f"{floor}-*"))]
        keys = sorted(set.intersection(*(set(r) for r in runs)))
        rel = statistics.median(statistics.stdev(r[k][0] for r in runs) for k in keys)
        abs_ = statistics.median(statistics.stdev(r[k][1] for r in runs) for k in keys)
        spread = statistics.median(r[k][2] for r in runs for k in keys)
        print(f"{floor} {len(runs)} {len(keys)} {rel:.4f} {abs_:.4f} {spread:.4f}")


if __name__ == "__main__":
    main()
