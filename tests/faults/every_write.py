#!/usr/bin/env python3
"""Crash at every write (the SQLite way): every checkpointed study of one experiment, stopped after each of
its writes, leaves a state the next run cleans or continues without a person.

    every_write.py BIN WORK [--threads N] [--set KEY=VALUE ...]

For each study that reads checkpoint.stop_after, on the quick scene with a save after every round
(checkpoint.interval = 0) and the --set values on top (to keep it short), at N threads (1; more make larger
rounds, hence fewer writes: runner/checkpoint.hpp, default_round):
1. a reference run into WORK/<study>/ref (at another thread count), a complete results directory no later
   run may change; and a run into OUT, which holds a copy of it (the previous complete run at the same
   --out), that counts its writes (GEOMINT_FAULT_COUNT_WRITES, src/geomint/io/fault_point.hpp): K, each named;
2. for every k in 1..K, a run into OUT that crashes after write k (GEOMINT_FAULT_AFTER_WRITES=k: _exit(99),
   no cleanup), and where write k appends to a checkpoint log, also one that tears it (GEOMINT_FAULT_TORN:
   half of the append on disk). OUT must then be, byte for byte, the previous run or the complete new one.
   From the state it left (copied, so that both start from it), --resume into OUT (stopped after one round
   by checkpoint.stop_after = 1 where one is left, then resumed again: the log a resumed run appended is
   read back) and a fresh run (no --resume) must each end with exit 0, the reference's CSVs and
   summary.json (timings aside: same_csv.py, same_summary.py), and nothing beside DIR (no DIR.partial,
   DIR.lock or temporary);
3. for every k, SIGTERM raised after write k (GEOMINT_FAULT_SIGNAL_AT_WRITE=k): up to the write of
   run.json the run exits 3 (at a checkpoint write once its save is done, elsewhere at once) and leaves OUT
   as it was, and --resume then completes as above; after it (the complete results are being moved into
   place) the run ends with exit 0 and the complete results.
Every k runs: none is sampled. Prints one line per failure, naming write k, and a tally; exits 1 on any.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "regression"))
import run_faults  # noqa: E402
import same_summary  # noqa: E402

CRASH = 99  # the exit code of a crash at a fault point (io/fault_point.hpp)
failures = []


def fail(what):
    failures.append(what)
    print("FAIL " + what, flush=True)


def tree(d):
    """Every file under d (a directory, or nothing there), by its path relative to d, with its bytes."""
    d = Path(d)
    return {str(p.relative_to(d)): p.read_bytes() for p in sorted(d.rglob("*")) if p.is_file()} if d.is_dir() else None


def results(d):
    """What must be the same as the reference: the CSVs (run_faults.csv_bytes) and summary.json, timings aside."""
    return run_faults.csv_bytes(d), same_summary.masked(json.loads((Path(d) / "summary.json").read_text()))


def siblings(out):
    """DIR.partial and DIR.lock: what a run leaves beside DIR."""
    return [Path(f"{out}.partial"), Path(f"{out}.lock")]


def complete(out, want):
    """'' if out is a complete results directory with the reference's results, else what is wrong."""
    run_json = Path(out) / "run.json"
    if not run_json.is_file():
        return "no run.json"
    listed = set(json.loads(run_json.read_text())["files"]) | {"run.json"}
    present = {p.name for p in Path(out).iterdir()}
    if present != listed:
        return f"files {sorted(present ^ listed)} are in it or in run.json's list, not both"
    return "" if results(out) == want else "the results differ from the uninterrupted run"


def clean(out):
    """'' if nothing is left beside a complete DIR, else what is."""
    left = [str(p) for p in siblings(out) if p.exists()]
    return f"left {left}" if left else ""


def reset(out, ref):
    """OUT := a copy of the reference (the previous complete run at that --out), nothing beside it."""
    for p in [Path(out), *siblings(out)]:
        shutil.rmtree(p) if p.is_dir() else p.unlink(missing_ok=True)
    shutil.copytree(ref, out)


def copy_state(src, dst):
    """The state a stopped run left at --out src (DIR, DIR.partial, DIR.lock), the same at dst."""
    for s, d in zip([Path(src), *siblings(src)], [Path(dst), *siblings(dst)]):
        shutil.rmtree(d) if d.is_dir() else d.unlink(missing_ok=True)
        if s.is_dir():
            shutil.copytree(s, d, symlinks=True)
        elif s.exists():
            shutil.copy2(s, d)


def run(cmd, env_extra=None):
    """(exit code, the end of stderr) of a run with the variables env_extra set (exit None: it hangs)."""
    rc, _, err = run_faults.run(cmd, env=dict(os.environ, **(env_extra or {})))
    return rc, err.strip()[-300:]


def finish(label, base, out, want, resume):
    """From the state at out: --resume (stopped once after a round, then resumed) or a fresh run; then out must
    be complete with the reference's results and nothing beside it."""
    rc = None
    if resume:
        rc, err = run([*base, "--resume", "--set", "checkpoint.stop_after=1", "--out", str(out)])
        if rc not in (0, 3):
            return fail(f"{label}: --resume (stopped after a round) exits {rc}: {err}")
    if rc != 0:  # (not done yet)
        rc, err = run([*base, *(["--resume"] if resume else []), "--out", str(out)])
    what = "--resume" if resume else "a fresh run"
    if rc != 0:
        return fail(f"{label}: {what} exits {rc}: {err}")
    bad = complete(out, want) or clean(out)
    if bad:
        fail(f"{label}: after {what}: {bad}")


def scratch(work):
    """Where the runs write: a new directory on the tmpfs /dev/shm where there is one (a crash of the process,
    all this test makes, leaves a file system as it leaves tmpfs, and fsync costs nothing there), else work."""
    shm = Path("/dev/shm")
    if shm.is_dir() and os.access(shm, os.W_OK):
        return Path(tempfile.mkdtemp(prefix="geomint-every-write-", dir=shm))
    work.mkdir(parents=True, exist_ok=True)
    return work


def check_study(binary, study, settings, threads, work):
    scene = [binary, "--quick", "--study", study, *[a for s in settings for a in ("--set", s)]]
    base = [*scene, "--threads", str(threads)]
    ref, out, out2, counts = work / "ref", work / "out", work / "out-fresh", work / "writes.txt"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    t0 = time.monotonic()
    rc, err = run([*scene, "--threads", str(1 + threads % 2), "--out", str(ref)])
    if rc != 0:
        return fail(f"{study}: the uninterrupted run exits {rc}: {err}")
    want, ref_bytes = results(ref), tree(ref)
    reset(out, ref)
    rc, err = run([*base, "--out", str(out)], {"GEOMINT_FAULT_COUNT_WRITES": str(counts)})
    writes = counts.read_text().splitlines() if counts.exists() else []
    if rc != 0 or not writes:
        return fail(f"{study}: the counting run exits {rc} with {len(writes)} writes: {err}")
    last_before_commit = max(i for i, w in enumerate(writes, 1) if w.endswith(" rename run.json"))

    def crash(label, k, torn):
        """A crash after write k (torn: its append half written), then --resume, and a fresh run, from its state."""
        reset(out, ref)
        rc, err = run([*base, "--out", str(out)],
                      {"GEOMINT_FAULT_AFTER_WRITES": str(k), "GEOMINT_FAULT_TORN": "1" if torn else "0"})
        if rc != CRASH:
            return fail(f"{label}: a crash there exits {rc}, not {CRASH}: {err}")
        if tree(out) != ref_bytes and complete(out, want):
            fail(f"{label}: after a crash there DIR is neither the previous run nor the complete new one")
        copy_state(out, out2)
        finish(label, base, out, want, resume=True)
        finish(label, base, out2, want, resume=False)

    for k, write in enumerate(writes, 1):
        label = f"{study}: write {write}"
        crash(label + " (crash)", k, torn=False)
        if write.split()[1] == "append":
            crash(label + " (torn crash)", k, torn=True)
        reset(out, ref)
        rc, err = run([*base, "--out", str(out)], {"GEOMINT_FAULT_SIGNAL_AT_WRITE": str(k)})
        if rc != (3 if k <= last_before_commit else 0):
            fail(f"{label}: SIGTERM there exits {rc}: {err}")
        elif rc == 3 and tree(out) != ref_bytes:
            fail(f"{label}: SIGTERM there changed DIR")
        elif rc == 3:
            finish(label + " (SIGTERM)", base, out, want, resume=True)
        elif complete(out, want) or clean(out):
            fail(f"{label}: SIGTERM there exits 0 with {complete(out, want) or clean(out)}")
    if tree(ref) != ref_bytes:
        fail(f"{study}: the complete run in {ref} changed")
    appends = sum(w.split()[1] == "append" for w in writes)
    print(f"  {study}: {len(writes)} writes, each a crash (then --resume, and a fresh run) and a SIGTERM (then "
          f"--resume), and the {appends} appends torn ({time.monotonic() - t0:.1f} s)", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary")
    ap.add_argument("work", type=Path)
    ap.add_argument("--threads", type=int, default=1, help="of every run but the reference")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="a --set for every run")
    args = ap.parse_args()
    keys = json.loads(subprocess.run([args.binary, "--list-keys", "--json"], check=True, capture_output=True,
                                     text=True).stdout)
    studies = [study for _key, study in run_faults.checkpointed_studies(keys)]
    if not studies:
        sys.exit(f"{args.binary}: no study reads checkpoint.stop_after")
    root = scratch(args.work)
    print(f"runs in {root}", flush=True)
    for study in studies:
        check_study(args.binary, study, ["checkpoint.interval=0", *args.set], args.threads, root / study)
    if root != args.work:
        shutil.rmtree(root)
    print(f"{Path(args.binary).name}: {len(studies)} checkpointed studies; {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
