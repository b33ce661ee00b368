#!/usr/bin/env python3
"""same_summary.py A B: exit 0 if the summary.json files A and B are the same but for their timings; else print
the fields that differ and exit 1.

The timings are the fields README.md lists as such (section "Timings in summary.json"), the only ones that may
differ between two runs of one scene and binary (other --threads or ranks, a resumed run): everything under
`timing`, and under `cost` every key whose name holds `wall`, `ns_per_step`, `timing` or `faster`, and the keys
`ratios_to`, `spread`, `crossover` and `indistinguishable`, with all below them. They are compared only in
that both have them.
"""
import json
import sys

TIMING_WORDS = ("wall", "ns_per_step", "timing", "faster")  # under cost: a key whose name holds one
TIMING_KEYS = {"ratios_to", "spread", "crossover", "indistinguishable"}  # under cost: these keys


def is_timing(path):
    """Whether the field at `path` (its keys from the top of summary.json) is a timing (README.md)."""
    if path[:1] == ("timing",):
        return True
    return path[:1] == ("cost",) and any(
        isinstance(k, str) and (k in TIMING_KEYS or any(w in k for w in TIMING_WORDS)) for k in path[1:])


def masked(t, path=()):
    """`t` with each timing replaced by the word "timing"."""
    if path and is_timing(path):
        return "timing"
    if isinstance(t, dict):
        return {k: masked(v, path + (k,)) for k, v in t.items()}
    if isinstance(t, list):
        return [masked(v, path + (i,)) for i, v in enumerate(t)]
    return t


def fields(t, path=()):
    """(dotted path, value) of every leaf of `t`."""
    items = t.items() if isinstance(t, dict) else enumerate(t) if isinstance(t, list) else None
    if items is None:
        yield ".".join(map(str, path)), t
        return
    for k, v in items:
        yield from fields(v, path + (k,))


def differences(a, b):
    """The dotted paths of the fields, timings aside, that differ between the summaries a and b (or that one lacks)."""
    one, two, missing = dict(fields(masked(a))), dict(fields(masked(b))), object()
    return sorted(k for k in one.keys() | two.keys() if one.get(k, missing) != two.get(k, missing))


if __name__ == "__main__":
    differ = differences(*(json.load(open(f)) for f in sys.argv[1:3]))
    if differ:
        print(f"summary.json fields that differ, timings aside ({len(differ)}): " + ", ".join(differ[:20]),
              file=sys.stderr)
    sys.exit(1 if differ else 0)
