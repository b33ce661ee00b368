#!/usr/bin/env python3
"""check_palette.py SOURCE_DIR METHODS_BIN [--gpi]: one colour and marker per method, distinct where methods meet.

Every method of the registry (METHODS_BIN --json) has a colour "#rrggbb", a marker (a gnuplot point
type 1-15) and its equations in the form "000 (26)–(28); 004 (1.3)" (or none); no two methods share
both colour and marker, so methods drawn in one figure are told apart whichever of them a scene names;
and in every paper scene (experiments/<name>/*.toml but quick* and published.toml) each list of methods
(a key ending in "methods", naming methods by registry name or label) has as many (colour, marker)
pairs as methods. With --gpi: figures/methods.gpi is what METHODS_BIN --gnuplot writes (run
`make methods-gpi` after changing the registry).
"""
import json
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
    if argv[3:] == ["--gpi"]:
        generated = subprocess.run([methods_bin, "--gnuplot"], capture_output=True, text=True, check=True).stdout
        committed = (source / "figures" / "methods.gpi").read_text(encoding="utf-8")
        if generated != committed:
            print("figures/methods.gpi differs from the registry (geomint-methods --gnuplot): run make methods-gpi")
            return 1
        print("figures/methods.gpi: current")
        return 0
    registry = json.loads(subprocess.run([methods_bin, "--json"], capture_output=True, text=True, check=True).stdout)
    palette, owner = {}, {}
    problems = []
    for m in registry:
        if not re.fullmatch(r"#[0-9A-Fa-f]{6}", m["colour"]):
            problems.append(f"{m['name']}: colour {m['colour']!r} is not #rrggbb")
        if m["equations"] and not re.fullmatch(r"\d{3} [^;]+(; \d{3} [^;]+)*", m["equations"]):
            problems.append(f"{m['name']}: equations {m['equations']!r} are not 'PPP (eq); PPP (eq)'")
        if not (isinstance(m.get("marker"), int) and 1 <= m["marker"] <= 15):
            problems.append(f"{m['name']}: marker {m.get('marker')!r} is not a gnuplot point type 1-15")
        look = (m["colour"].upper(), m.get("marker"))
        if look in owner:
            problems.append(f"{m['name']} and {owner[look]} share the colour {look[0]} and the marker {look[1]}")
        owner.setdefault(look, m["name"])
        palette[m["name"]] = palette[m["label"]] = look
    scenes = [p for p in sorted((source / "experiments").glob("*/*.toml"))
              if not p.name.startswith("quick") and p.name != "published.toml"]
    lists = 0
    for scene in scenes:
        for key, methods in method_lists(tomllib.loads(scene.read_text(encoding="utf-8"))):
            lists += 1
            looks = {}
            for m in methods:
                look = palette.get(m)
                if look and look in looks:
                    problems.append(f"{scene.relative_to(source)}: {key}: {looks[look]} and {m} share colour and marker {look}")
                looks.setdefault(look, m)
    for p in problems:
        print(p)
    print(f"palette: {len(registry)} methods, {lists} method lists in {len(scenes)} scenes: "
          + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
