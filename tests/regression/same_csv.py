#!/usr/bin/env python3
"""same_csv.py A B: exit 0 if the CSV files A and B have the same header and rows, the wall-time
columns of a work-precision set (wall_s, wall_q1_s, wall_q3_s, wall_spread: cost_*.csv,
analysis/work_precision_set.hpp) aside; every other cell must be the same text. A blank line (gnuplot's
separator of data blocks, e.g. map_grid.csv) is a row of no cells, and must be where it is in both."""
import csv
import sys

WALL = {"wall_s", "wall_q1_s", "wall_q3_s", "wall_spread"}


def cells(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    keep = [i for i, c in enumerate(rows[0]) if c not in WALL]
    return rows[0], [[r[i] for i in keep] if r else [] for r in rows[1:]]


def same(a, b):
    return cells(a) == cells(b)


if __name__ == "__main__":
    sys.exit(0 if same(sys.argv[1], sys.argv[2]) else 1)
