#!/usr/bin/env python3
"""check_palette.py SOURCE_DIR METHODS_BIN: one colour per method, distinct where methods meet.

The palette of figures/common.gp (PALETTE, keyed by registry name) has an entry for every method
of the registry (METHODS_BIN --names) and no other; and in every paper scene
(experiments/<name>/*.toml but quick* and published.toml) each list of methods (a key ending in
"methods") has as many colours as methods: methods drawn in one figure never share a colour.
"""
import pathlib
import re
import subprocess
import sys
import tomllib


def method_lists(node, key=""):
    if isinstance(node, dict):
        for k, v in node.items():
            yield from method_lists(v, f"{key}.{k}" if key else k)
    elif key.endswith("methods") and isinstance(node, list) and all(isinstance(m, str) for m in node):
        yield key, node


def main(argv):
    source, methods_bin = pathlib.Path(argv[1]), argv[2]
    palette = dict(re.findall(r'" ([A-Za-z0-9_]+):(#[0-9A-Fa-f]{6})"', (source / "figures" / "common.gp").read_text()))
    registry = subprocess.run([methods_bin, "--names"], capture_output=True, text=True, check=True).stdout.split()
    problems = [f"the palette has no colour for {m}" for m in registry if m not in palette]
    problems += [f"the palette names {m}, which the registry does not have" for m in palette if m not in registry]
    scenes = [p for p in sorted((source / "experiments").glob("*/*.toml"))
              if not p.name.startswith("quick") and p.name != "published.toml"]
    lists = 0
    for scene in scenes:
        for key, methods in method_lists(tomllib.loads(scene.read_text(encoding="utf-8"))):
            lists += 1
            colours = {}
            for m in methods:
                c = palette.get(m, "").upper()
                if c and c in colours:
                    problems.append(f"{scene.relative_to(source)}: {key}: {colours[c]} and {m} share the colour {c}")
                colours.setdefault(c, m)
    for p in problems:
        print(p)
    print(f"palette: {len(palette)} methods, {lists} method lists in {len(scenes)} scenes: "
          + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
