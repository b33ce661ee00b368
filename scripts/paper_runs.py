#!/usr/bin/env python3
"""Is a results directory the run of its paper scene? For make figures, make paper and report.py.

    paper_runs.py stale RESULTS_ROOT ID=SCENE ...   print the ids whose run is missing or is not
                                                    the paper scene's (make reruns them)

A run is its paper scene's when its run.json records that scene file (the path make passes), no
--set overrides and every study the scene selects (its `studies`, or all studies of the
experiment): a reviewer's `make experiment ... ARGS='--set ...'` writes elsewhere (README), and a
run made by hand into results/<id> with other values is rerun rather than reported.
"""
import json
import pathlib
import sys


def why_not_paper_run(run, scene):
    """None if run.json `run` is the run of the scene file `scene` (a path as make gives it), else why."""
    if pathlib.Path(run.get("scene_file", "")).resolve() != pathlib.Path(scene).resolve():
        return f"it ran the scene {run.get('scene_file')}, not {scene}"
    if run.get("overrides"):
        return "it ran with --set " + " ".join(run["overrides"])
    selected = run.get("scene", {}).get("studies") or [st["name"] for st in run.get("study_list", [])]
    missing = [s for s in selected if s not in run.get("studies", [])]
    if missing:
        return "it did not run the studies " + ", ".join(missing)
    return None


def stale(root, pairs):
    for pair in pairs:
        run_id, _, scene = pair.partition("=")
        path = pathlib.Path(root) / run_id / "run.json"
        try:
            run = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue  # no run yet: make's own rule makes it
        why = why_not_paper_run(run, scene)
        if why:
            print(run_id)
            print(f"paper_runs.py: {path.parent}: rerun: {why}", file=sys.stderr)


if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] != "stale":
        sys.exit(__doc__)
    stale(sys.argv[2], sys.argv[3:])
