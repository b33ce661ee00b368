#!/usr/bin/env python3
"""check_palette.py SOURCE_DIR METHODS_BIN [--gpi | --scripts [DIR]]: one colour and marker per method, distinct
where methods meet, and no figure script that types a method's name.

Every method of the registry (METHODS_BIN --json) has a colour "#rrggbb", a marker (a gnuplot point
type 1-15) and its equations in the form "000 (26)–(28); 004 (1.3)" (or none); no two methods share
both colour and marker, so methods drawn in one figure are told apart whichever of them a scene names;
and in every paper scene (experiments/<name>/*.toml but quick* and published.toml) each list of methods
(a key ending in "methods", naming methods by registry name or label) has as many (colour, marker)
pairs as methods. With --gpi: figures/methods.gpi is what METHODS_BIN --gnuplot writes (run
`make methods-gpi` after changing the registry).
With --scripts: no figure script (DIR/*.gp and *.gpi, default SOURCE_DIR/figures, but the generated methods.gpi)
types a method's name: no method_colour('rk4'), method_key("stormer_verlet", ...) or any function of a method
(METHOD_FUNCTIONS) called on a quoted text, and no quoted text that is a registry name (a look or key of a method
kept per name, e.g. C_SE = method_colour('symplectic_euler_pq'), or m eq "rk4"; names, not labels: a label such
as M or T is also a script's variable): a figure's methods come from the run (scene_words, summary_words) and
their look from the registry. The check is first tried on planted lines (PLANTED), which it must refuse.
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


# The functions of a method m in figures/methods.gpi and figures/common.gp (m their first argument).
METHOD_FUNCTIONS = ("method_colour", "method_point", "method_title", "method_equations", "method_key",
                    "method_styles", "method_look", "method_ls", "method_fit_ls", "further_point")
CALL = re.compile(r"\b(" + "|".join(METHOD_FUNCTIONS) + r")\(\s*$")
# Lines that type a method's name, as figures/common.gp did: each must be refused.
PLANTED = ["C_SE    = method_colour('symplectic_euler_pq')       # (symplectic) Euler without compensation",
           'CONV_CURVE_TITLE(c) = method_title("stormer_verlet") . ", closed form"',
           "C_M = method_colour(c eq 'sv_rel_H' ? 'stormer_verlet' : 'takahashi_imada')"]


def quoted(line):
    """(text before the quote, quoted text) of each quoted text of a gnuplot line, up to its comment."""
    out, i = [], 0
    while i < len(line):
        c = line[i]
        if c == "#":
            break
        if c in "'\"":
            j, text = i + 1, ""
            while j < len(line):
                if c == '"' and line[j] == "\\":
                    text += line[j:j + 2]
                    j += 2
                    continue
                if line[j] == c:
                    if c == "'" and line[j + 1:j + 2] == "'":  # ('' is a quote inside '...')
                        text, j = text + "'", j + 2
                        continue
                    break
                text += line[j]
                j += 1
            out.append((line[:i], text))
            i = j + 1
            continue
        i += 1
    return out


def typed_methods(name, text, names):
    """What in a script (its name, its text) types a method's name: a problem per line."""
    for number, line in enumerate(text.splitlines(), 1):
        for before, q in quoted(line):
            if CALL.search(before):
                yield f"{name}:{number}: {CALL.search(before).group(1)}() of a typed name '{q}': {line.strip()}"
            elif q in names:
                yield f"{name}:{number}: the method name '{q}' typed: {line.strip()}"


def check_scripts(figures, names):
    problems = []
    for k, line in enumerate(PLANTED, 1):
        if not list(typed_methods(f"planted {k}", line, names)):
            problems.append(f"the check let through the planted line {line!r}")
    scripts = [p for p in sorted(figures.glob("*.gp")) + sorted(figures.glob("*.gpi")) if p.name != "methods.gpi"]
    for script in scripts:
        problems += typed_methods(script.name, script.read_text(encoding="utf-8"), names)
    for p in problems:
        print(p)
    print(f"figure scripts: {len(scripts)} in {figures}, no method name typed: "
          + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


def main(argv):
    source, methods_bin = pathlib.Path(argv[1]), argv[2]
    if argv[3:4] == ["--scripts"]:
        listing = subprocess.run([methods_bin, "--json"], capture_output=True, text=True, check=True).stdout
        figures = pathlib.Path(argv[4]) if len(argv) > 4 else source / "figures"
        return check_scripts(figures, {m["name"] for m in json.loads(listing)})
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
