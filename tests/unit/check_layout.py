#!/usr/bin/env python3
"""The experiments keep the shape of the README's layout: one study, one file.

    check_layout.py SOURCE_DIR BIN_DIR

For every experiment (a directory experiments/<name> with a .cpp file):
- every study it lists (`<name> --list-studies`) is declared by `Study <x>_study()` in a file of its own
  (experiments/<name>/<file>.cpp returns a Study whose name is the study's, and no other);
- no --plan rate is typed in a study (a number as ns_per_step, as a TimedCall's rate or as a k...Ns constant):
  rates come from experiments/plan_rates.toml (runner/plan_rates.hpp);
- main.cpp has under 100 lines, no source file of the directory more than 400, and no function more
  than 80 (a function: from a line in column 0 that opens a definition to the next line in column 0
  that starts with '}', the style of this tree);
- no source file of an experiment includes a header of its experiment's directory: what a reader opens beside
  the study is its scene, its gnuplot script and the library's headers (a system header among them), and what
  several studies share lives in the library;
- over all experiments, the median study file (a .cpp other than main.cpp and <name>.cpp) has at most 120 lines.
Exit 1 listing what is wrong.
"""
import pathlib
import re
import statistics
import subprocess
import sys

MAX_MAIN, MAX_FILE, MAX_FUNCTION, MEDIAN_STUDY = 100, 400, 80, 120
LOCAL_INCLUDE = re.compile(r'^#include "([^/"]+\.hpp)"', re.M)
TYPED_RATE = re.compile(r"ns_per_step\s*=\s*[0-9]|TimedCall\{[^{}]*,\s*[0-9][0-9.e]*\}|constexpr double k\w*Ns\w*\s*=")
NOT_A_FUNCTION = ("//", "#", "namespace", "}", "template", "using", "struct", "class", "enum", "static_assert",
                  "constexpr", "inline constexpr", "extern", "[[")


def functions(lines):
    """(first line number, length) of every definition whose body opens at column 0 scope."""
    out, start = [], None
    for i, line in enumerate(lines):
        if start is None:
            if line and not line[0].isspace() and not line.startswith(NOT_A_FUNCTION) and not line.endswith(";"):
                start = i
        elif line.startswith("}"):
            out.append((start + 1, i - start + 1))
            start = None
        elif line and not line[0].isspace() and line.endswith(";") and "{" not in "".join(lines[start:i + 1]):
            start = None  # a declaration over several lines
    return out


def main() -> int:
    source, bins = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    problems, study_lines = [], []
    for d in sorted({p.parent for p in (source / "experiments").glob("*/*.cpp")}):  # (with or without a main.cpp)
        name = d.name
        listing = subprocess.run([str(bins / name), "--list-studies"], capture_output=True, text=True, check=True)
        studies = [line.split("\t")[0] for line in listing.stdout.splitlines() if line.strip()]
        sources = sorted(d.glob("*.cpp")) + sorted(d.glob("*.hpp"))
        owner = {}
        for f in sources:
            text = f.read_text(encoding="utf-8")
            lines = text.splitlines()
            limit = MAX_MAIN if f.name == "main.cpp" else MAX_FILE
            if f.suffix == ".cpp" and f.stem not in ("main", name):
                study_lines.append(len(lines))
            for local in LOCAL_INCLUDE.findall(text):
                problems.append(f"{f.relative_to(source)}: includes {local}, a header of its experiment (what "
                                f"studies share belongs in the library: src/geomint/)")
            if f.suffix == ".hpp":
                problems.append(f"{f.relative_to(source)}: a header in an experiment's directory (src/geomint/)")
            if len(lines) > limit:
                problems.append(f"{f.relative_to(source)}: {len(lines)} lines (at most {limit})")
            for i, line in enumerate(lines, 1):
                if TYPED_RATE.search(line):
                    problems.append(f"{f.relative_to(source)}:{i}: a --plan rate typed in a study (experiments/plan_rates.toml)")
            for first, length in functions(lines):
                if length > MAX_FUNCTION:
                    problems.append(f"{f.relative_to(source)}:{first}: a function of {length} lines (at most {MAX_FUNCTION})")
            for m in re.finditer(r"^Study \w+_study\([^)]*\) \{.*?^  (?:return |Study st)\{(?:\.name = )?\"(\w+)\"", text, re.M | re.S):
                owner.setdefault(m.group(1), []).append(f)
        for study in studies:
            files = owner.get(study, [])
            if len(files) != 1:
                problems.append(f"{name}: study {study} is declared in {len(files)} files (one: experiments/{name}/<study>.cpp)")
            elif sum(len(v) for k, v in owner.items() if files[0] in v) > 1:
                problems.append(f"{files[0].relative_to(source)}: declares more than one study")
    median = statistics.median(study_lines) if study_lines else 0
    if median > MEDIAN_STUDY:
        problems.append(f"the median study file has {median:g} lines (at most {MEDIAN_STUDY}; {len(study_lines)} files)")
    for p in problems:
        print(p)
    print("layout: " + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
