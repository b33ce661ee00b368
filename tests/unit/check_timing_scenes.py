#!/usr/bin/env python3
"""check_timing_scenes.py SOURCE_DIR: every paper scene (experiments/<name>/<name>.toml) that times
anything does so under the full timing protocol of runner/timing.hpp: at least kTimingRepeats rounds."""
import pathlib
import re
import sys
import tomllib

source = pathlib.Path(sys.argv[1])
least = int(re.search(r"kTimingRepeats = (\d+);", (source / "src/geomint/runner/timing.hpp").read_text()).group(1))
problems, timed = [], 0
for scene in sorted(source.glob("experiments/*/*.toml")):
    if scene.stem != scene.parent.name:
        continue  # (quick and other scenes: not reported)
    repeats = tomllib.loads(scene.read_text(encoding="utf-8")).get("timing", {}).get("repeats")
    if repeats is not None:
        timed += 1
        if repeats < least:
            problems.append(f"{scene.relative_to(source)}: timing.repeats = {repeats}, fewer than the protocol's {least}")
for p in problems:
    print("check_timing_scenes:", p)
print(f"check_timing_scenes: {timed} paper scenes time, {len(problems)} problems")
sys.exit(1 if problems or not timed else 0)
