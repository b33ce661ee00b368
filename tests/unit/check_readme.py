#!/usr/bin/env python3
"""The README's table "What reproduces what" stays true.

    check_readme.py README.md SOURCE_DIR BIN_DIR

Every path the table names exists; every experiment appears in it, and with it every study
it runs (`<name> --study <study>`, from `<name> --list-studies`); every figure script
(figures/*.gp but the shared common.gp) appears in it. Exit 1 listing what is wrong.
"""
import pathlib
import re
import subprocess
import sys


def table(readme: str) -> list[str]:
    """The rows of the table under the heading "What reproduces what"."""
    section = readme.split("## What reproduces what", 1)[1].split("\n## ", 1)[0]
    return [line for line in section.splitlines() if line.startswith("|") and not line.startswith("|---")][1:]


def main() -> int:
    readme, source, bins = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    rows = table(readme.read_text(encoding="utf-8"))
    problems = []
    if not rows:
        problems.append("no table under 'What reproduces what'")
    text = "\n".join(rows)
    for token in re.findall(r"`([^`]+)`", text):
        first = token.split()[0]
        if "/" in first and not first.startswith("--"):
            if not (source / first).exists():
                problems.append(f"{first}: named in the table, but there is no such file")
    experiments = sorted({p.parent.name for p in (source / "experiments").glob("*/*.cpp")})  # (README Layout)
    for name in experiments:
        listing = subprocess.run([str(bins / name), "--list-studies"], capture_output=True, text=True, check=True)
        studies = [line.split("\t")[0] for line in listing.stdout.splitlines() if line.strip()]
        mine = [row for row in rows if f"`{name}" in row]
        if not mine:
            problems.append(f"experiment {name} has no row")
        for study in studies:
            if not any(f"--study {study}`" in row for row in mine):
                problems.append(f"{name}: study {study} has no row (`{name} --study {study}`)")
    for script in sorted((source / "figures").glob("*.gp")):
        if script.name != "common.gp" and f"figures/{script.name}" not in text:
            problems.append(f"figures/{script.name} has no row")
    for p in problems:
        print(p)
    print(f"{len(rows)} rows, {len(experiments)} experiments: " + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
