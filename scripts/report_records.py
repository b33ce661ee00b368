"""What the report says a quantity is, from its record (scripts/report.py, report_tables.py use it): the run's
values in a comparison's `where` and `note` ({scene.KEY}, {summary.KEY}), the fits of a summary key (summary.json
fit_sources) in words, and the refusals of a description that disagrees with its record or names two keys."""
import math
import re
import tomllib

from tex_format import code, number, tex_escape

LOOKUP = re.compile(r"\\result(range)?(?:\[([^\]]*)\])?\{([^}]*)\}\{([^}]*)\}")  # \\result[fmt]{run}{key}


def at(tree, key):
    """The value at a dotted key (array elements by index), or None."""
    node = tree
    for part in key.split("."):
        if isinstance(node, dict) and part in node:
            node = node[part]
        elif isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        else:
            return None
    return node


# ---- What a comparison compares, from its record ---------------------------------------------------------------
# published.toml's `where` and `note` type what the paper says and what is compared, in words; what the run knows
# they take from it: {scene.<key>} (the resolved scene, run.json) and {summary.<key>} (summary.json), each with an
# optional |format (plain, percent, err: text, not math), and the fits of the compared key (summary.json
# fit_sources: its CSV, columns, rows and window), which comparison_rows prints under the row.
PLACEHOLDER = re.compile(r"\{((scene|summary)\.[\w.]+)(?:\|(plain|percent|err))?\}")
PLAIN = {"plain": lambda x: f"{x:g}", "percent": lambda x: f"{100 * x:.3g} %",
         "err": lambda x: re.sub(r"e([-+])0*(?=\d)", lambda m: "e" + m.group(1).strip("+"), f"{x:.2g}")}


def expand_record(text, summary, scene, where="", compared=True):
    """A `where` or `note` with its {scene.KEY} and {summary.KEY} replaced by the run's values; a key the run
    does not have stops the report, naming it, unless the comparison was not made under this scene (not
    `compared`: not comparable, not computed), where it reads "(not in this run)"."""
    def value(m):
        v = at(scene if m.group(2) == "scene" else summary, m.group(1).split(".", 1)[1])
        if not isinstance(v, (int, float)) or isinstance(v, bool) or not math.isfinite(v):
            if not compared:
                return "(not in this run)"
            raise SystemExit(f"report.py: {where}: {m.group(0)} is not a number of the run")
        return PLAIN[m.group(3) or "plain"](v)
    return PLACEHOLDER.sub(value, text or "")


FIT_KINDS = {  # runner/fits.hpp, FitRecord::kind
    "order": "least-squares slope of log {y} against log {x}, over the errors above {floor}",
    "power_law": "least-squares slope of log {y} against log {x}",
    "slope": "least-squares slope of {y} against {x}",
    "relative_ptp": "peak-to-peak of {y} relative to its value in the window's first row",
    "relative_amplitude": "half the peak-to-peak of {y} relative to its value in the window's first row",
    "ptp": "peak-to-peak of {y}",
    "ptp_about_line": "peak-to-peak of {y} about its least-squares line in {x}",
    "ptp_about_quadratic": "peak-to-peak of {y} about its least-squares quadratic in {x}"}


def key_fits(fits, key):
    """The fits of a summary key (summary.json fit_sources): its own, its entries' (key.<label>), or those of a
    CSV column it summarizes (<csv>#<column>#<window>, where the key's parent is named after the column:
    pendulum.local_slope.max_rel_difference over fig2_local_slope.csv#local_slope#0, #1, ...)."""
    parent = key.rsplit(".", 1)[0].rsplit(".", 1)[-1] if "." in key else None
    return [f for f in fits or [] if f["quantity"] == key or f["quantity"].startswith(key + ".")
            or (parent and re.fullmatch(rf"[^#]+#{re.escape(parent)}#\d+", f["quantity"]))]


def record_phrase(fits):
    """LaTeX: how the fitted numbers behind a comparison were computed, from their fit sources: kind, columns,
    CSV, rows and window (a set of windows by its first and last)."""
    groups = {}
    for f in fits:
        rows = ", ".join(f"{k} = {v}" for k, v in (f.get("where") or {}).items())
        groups.setdefault((f["csv"], f["x"], f["kind"], f.get("floor"), rows), []).append(f)
    out = []
    for (csv, x, kind, floor, rows), fs in groups.items():
        ys = list(dict.fromkeys(f["y"] for f in fs))
        what = FIT_KINDS.get(kind, kind + " of {y}").format(y=", ".join(code(f"{csv}:{y}") for y in ys), x=code(x),
                                                          floor=f"${number(floor or 0, 'sci')}$")  # (file:column)
        windows = list(dict.fromkeys((f["from"], f["to"]) for f in fs))
        span = [f"${number(a, 'plain')} \\le$ {code(x)} $\\le {number(b, 'plain')}$" for a, b in windows]
        span = span[0] if len(span) == 1 else (f"each of {len(span)} windows, {span[0]}, \\dots, {span[-1]}"
                                               if len(ys) == 1 else "windows " + "; ".join(span))
        out.append(what + (f" (rows with {tex_escape(rows)})" if rows else "") + f", over {span}")
    return "; ".join(out)


# A typed description against its record: words of an extremum where the key names a value at the end (or the
# reverse), and a window the fits of the key do not have.
SAYS_END = re.compile(r"(?:^|[._])(?:at_t_end|at_end|final)(?:$|[._])")
SAYS_MAX = re.compile(r"(?:^|[._])max(?:$|[._])")
TEXT_MAX = re.compile(r"\b(?:largest|max|maximum)\b(?!-norm)", re.I)
TEXT_END = re.compile(r"\b(?:at the end|final value|at t_end)\b", re.I)
TEXT_WHOLE = re.compile(r"\b(?:whole run|whole span)\b", re.I)
TEXT_WINDOW = re.compile(r"\b(t|h)\s*(?:<=|≤)\s*([-+\d.eE]+)|\b(t|h)\s+in\s+\[([-+\d.eE]+),\s*([-+\d.eE]+)\]")


def description_problems(name, key, c, fits):
    """What a comparison's typed `where` and `note` (placeholders expanded) say against its record: its summary
    key (c["summary"]) and that key's fits (key_fits)."""
    text, skey, problems = f"{c.get('where', '')} {c.get('note', '')}", c.get("summary") or "", []
    text = re.sub(r"(?<!\w)'[^']*'(?!\w)", "", text)  # (the paper's words, quoted, are not the description of the key)
    if SAYS_END.search(skey) and TEXT_MAX.search(text):
        problems.append(f"says '{TEXT_MAX.search(text).group(0)}' of {skey}, the value at the end")
    if SAYS_MAX.search(skey) and TEXT_END.search(text):
        problems.append(f"says '{TEXT_END.search(text).group(0)}' of {skey}, a largest value")
    fitted = key_fits(fits, skey)
    if fitted and TEXT_WHOLE.search(text):
        ends = {}
        for f in fits:  # the span of each CSV's fitted variable over all fits of the run
            lo, hi = ends.get((f["csv"], f["x"]), (f["from"], f["to"]))
            ends[(f["csv"], f["x"])] = (min(lo, f["from"]), max(hi, f["to"]))
        if not any((f["from"], f["to"]) == ends[(f["csv"], f["x"])] for f in fitted):
            problems.append(f"says 'whole run', but no fit of {skey} spans its CSV's whole range")
    for m in TEXT_WINDOW.finditer(text):
        x, bounds = (m.group(1), [m.group(2)]) if m.group(1) else (m.group(3), [m.group(4), m.group(5)])
        ours = [f for f in fitted if f["x"] == x]
        if ours and not any(all(float(b) in (f["from"], f["to"]) for b in bounds) for f in ours):
            problems.append(f"types the window '{m.group(0)}', which no fit of {skey} has")
    return [f"{name}: {key}: {p}" for p in problems]


def record_problems(runs):
    """The comparisons of every run against their records (description_problems), and two comparisons of
    different summary keys under the same description."""
    problems, seen = [], {}
    for name, run in runs.items():
        for key, c in (run["summary"].get("comparisons") or {}).items():
            problems += description_problems(name, key, c, run["summary"].get("fit_sources"))
            where, skey = " ".join(c.get("where", "").split()), c.get("summary")
            other = seen.setdefault(where, (name, key, skey))
            if skey and other[2] and other[2] != skey:
                problems.append(f"{name}: {key} and {other[0]}: {other[1]} compare different keys ({skey}, {other[2]}) "
                                f"under one description: {where}")
    return problems


def read_records(runs, root):
    """Each comparison with the summary key it compares (experiments/<experiment>/published.toml) and its `where`,
    `note` and `why` with the run's values in place of their placeholders (expand_record)."""
    for name, run in runs.items():
        path = root / "experiments" / run["summary"].get("experiment", name) / "published.toml"
        published = tomllib.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}
        for key, c in (run["summary"].get("comparisons") or {}).items():
            c.setdefault("summary", (published.get(key) or {}).get("summary"))
            for field in ("where", "note", "why"):
                if field in c:
                    c[field] = expand_record(c[field], run["summary"], run["run"].get("scene", {}), f"{name}: {key}",
                                             c.get("verdict") not in ("not comparable", "not computed"))


# The description of a lookup in the report's text: the words of its sentence before it (a table cell, an item,
# a caption and a paragraph start one), the lookups among them by their keys, math by its lookups alone.
SENTENCE = re.compile(r"(?<!\\)[.;:]\s+(?=[A-Z\\$])|&|\\item(?:\[[^]]*\])?|\\\\|\n\s*\n|"
                      r"\\(?:caption|paragraph|section|subsection)\*?\{")
DESCRIPTION_WORDS = (3, 7)  # a description: at least 3 words beside math and lookups; the last 7 words, lookups
# and math included, of its sentence before the lookup


def lookup_labels(text):
    """(description, run, key, line) of each \\result lookup of a LaTeX text (LOOKUP), its description as above."""
    text, out = re.sub(r"(?<!\\)%.*", "", text), []
    for m in LOOKUP.finditer(text):
        before = text[max(0, m.start() - 600):m.start()]
        starts = [b.end() for b in SENTENCE.finditer(before)]
        before = LOOKUP.sub(lambda k: f" #{k.group(3)}@{k.group(4)} ", before[starts[-1] if starts else 0:])
        before = re.sub(r"\$([^$]*)\$", lambda k: " $ " + " ".join(re.findall(r"#\S+", k.group(1))) + " ", before)
        words = re.findall(r"[\w#@.$'-]+", re.sub(r"\\[a-zA-Z]+\*?(?:\[[^]]*\])?|[{}~]", " ", before))
        out.append((" ".join(w.lower().strip(".") for w in words), m.group(3), m.group(4),
                    text.count("\n", 0, m.start()) + 1))
    return out


def label_problems(tex_texts):
    """Two lookups of different keys of one run under the same description (lookup_labels), and a description that
    says the largest value of a key that is the value at the end, or the reverse (SAYS_END, TEXT_MAX above)."""
    by_label, problems = {}, []
    for name, text in tex_texts.items():
        for label, run, key, line in lookup_labels(text):
            words = [w for w in label.split() if w != "$" and not w.startswith("#")]
            tail = " ".join(words[-6:])
            if SAYS_END.search(key) and TEXT_MAX.search(tail) or SAYS_MAX.search(key) and TEXT_END.search(tail):
                problems.append(f"{name}:{line}: '{tail}' does not describe {run} {key}")
            if len(words) >= DESCRIPTION_WORDS[0] and not key.startswith("scene."):  # (a scene's setting, not a result)
                by_label.setdefault((run, " ".join(label.split()[-DESCRIPTION_WORDS[1]:])), {}) \
                    .setdefault(key, f"{name}:{line}")
    for (run, label), keys in by_label.items():
        if len(keys) > 1:
            problems.append(f"{', '.join(keys.values())}: the keys {', '.join(keys)} of {run} under one description: "
                            f"'{label}'")
    return problems
