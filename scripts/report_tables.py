"""The report's generated tables of comparisons and methods, and the labels of its figures (scripts/report.py
writes them): comparisons.tex (per run), one table per figure of the papers with \\runcomparisons{<run>} printing
those of a run and, where an item's comparisons form a grid, one in the paper's shape for \\comparisongrid{<run>}
{<name>}, the method registry (methods.tex), the methods' names for \\method (method_names.tex) and each figure's
items for \\figureitems{<name>} (figure_items.tex). The LaTeX never types an item's id ("000 Fig. 9"): a figure is
named by its gnuplot script (figures/<run>_<name>.gp), an item by its run and a name (named_items)."""
import math
import re

from report_records import key_fits, record_phrase
from tex_format import FORMATS, code, gnuplot_tex, is_number, key_text, longtable, number, prose, tex_escape, \
    value_text


COMPARISON_HEAD = [r"\toprule no. & quantity, where published & published & reproduced & difference & verdict\\ "
                   r"\midrule", r"\endhead"]
COMPARISON_COLUMNS = (0.06, 0.4, 0.13, 0.13, 0.12, 0.16)


def comparison_numbers(runs):
    """Each comparison's number, #1, #2, ... in the order of Appendix A (comparisons.tex), by (run, key): the
    report refers to a published quantity by it, never by its key in summary.json."""
    pairs = [(name, key) for name, run in runs.items() for key in run["summary"].get("comparisons") or {}]
    return {pair: i + 1 for i, pair in enumerate(pairs)}


def comparison_ref(numbers, run, key):
    """A reference to a comparison's row in Appendix A (its number, linked), or None if it has none."""
    n = numbers.get((run, key))
    return None if n is None else f"\\hyperref[cmp:{run}:{key}]{{\\#{n}}}"


def key_refs(numbers, run):
    """For a run's free text: each comparison key it may name, as its reference (a key of another run where
    only one run has it)."""
    owners = {}
    for r, key in numbers:
        owners.setdefault(key, []).append(r)
    refs = {key: comparison_ref(numbers, rs[0], key) for key, rs in owners.items() if len(rs) == 1}
    return refs | {key: comparison_ref(numbers, run, key) for r, key in numbers if r == run}


def rule_text(c):
    """A comparison's tolerance as published.toml gives it: typed ("rel 0.03", "abs 1e-13"), or derived, from the
    printed digits ("rel: half a unit in the last printed digit") or the run's standard error ("abs: 2 standard
    errors of the run")."""
    resolved = c.get("tolerances")  # (kStandardErrors as the run wrote it; "printed" of one value: a number)
    k = resolved.get("standard_errors", float("nan")) if isinstance(resolved, dict) else float("nan")
    origins = {"printed": "half a unit in the last printed digit",  # (runner/published.hpp)
               "stderr": f"{k:g} standard errors of the run"}
    return ", ".join(f"{k} {v:g}" if isinstance(v, (int, float)) else f"{k}: {origins.get(v, v)}"
                     for k, v in (c.get("compare") or {}).items())


def tolerance_at(c, key=None):
    """The tolerance a comparison applies to its entry `key` (None: its one value), as the run resolved it
    (runner/published.cpp, tolerance_at): typed, the number in compare; "printed", half a unit in the last
    printed digit of that value (summary "tolerances", keyed as published.toml prints the parameter: matched by
    value); "stderr", that many standard errors of the run (tolerances.of). None for a claim or a value only
    reported, and where the run wrote no number."""
    (rule, tol), = (c.get("compare") or {"": None}).items()
    if rule not in ("rel", "abs", "order"):
        return None
    resolved = c.get("tolerances")
    if tol == "stderr":
        tol = (resolved or {}).get("of")
    elif tol == "printed":
        tol = resolved
        if isinstance(resolved, dict):
            tol = next((v for k, v in resolved.items() if same_parameter(k, key)), None)
    return tol if is_number(tol) else None


def same_parameter(a, b):
    """Whether two keys of a value table name the same parameter: equal, or numbers within 1e-12 relative (a step
    printed "0.1" and written "0.10000000000000001"; runner/published.cpp matches them so)."""
    try:
        return a == b or abs(float(a) - float(b)) <= 1e-12 * abs(float(b))
    except (TypeError, ValueError):
        return False


def roundoff_text(c):
    """The entries of a table that measure round-off and are not compared ("not comparable (round-off) at 0.05")."""
    at = c.get("roundoff") or []
    return "not comparable (round-off) at " + ", ".join(f"{float(k):g}" if re.fullmatch(r"[-+\d.eE]+", k) else k
                                                         for k in at) if at else ""


def comparison_rows(run, comparisons, numbers, anchor=False, fits=()):
    """One row per comparison (summary.json "comparisons"): its number (with `anchor`, the row that references
    link to), what it is and where printed, the two values, their difference and the verdict with its rule,
    and below it its reason or note and, from `fits` (summary.json fit_sources), how its key was fitted."""
    out, refs = [], key_refs(numbers, run)
    for key, c in comparisons.items():
        how = rule_text(c)
        verdict = c["verdict"] + (f" ({tex_escape(how)})" if how else "")
        if roundoff_text(c) and c["verdict"] != "not comparable":  # (a table judged entry by entry)
            verdict += "; " + tex_escape(roundoff_text(c))
        if c.get("expect", "reproduced") != "reproduced":
            verdict += r", expected: " + tex_escape(c["expect"])
        number = (f"\\phantomsection\\label{{cmp:{run}:{key}}}\\#{numbers[(run, key)]}" if anchor
                  else comparison_ref(numbers, run, key))
        out.append(f"{number} & {prose(c['where'], refs)} & {value_text(c.get('published'))} & "
                   f"{value_text(c.get('reproduced'))} & {value_text(c.get('difference'))} & {verdict}\\\\")
        remarks = prose(" ".join(c[k] for k in ("reason", "note") if c.get(k)), refs)
        fitted = record_phrase(key_fits(fits, c.get("summary") or ""))
        remarks += (" " if remarks else "") + (f"From its fits: {fitted}." if fitted else "")
        if remarks:
            out.append(r"\multicolumn{6}{@{}p{0.95\linewidth}@{}}{\emph{" + remarks + r"}}\\")
    return out


def comparisons_tex(runs):
    out = ["% Published against reproduced, per run (scripts/report.py from summary.json \"comparisons\")."]
    numbers = comparison_numbers(runs)
    for name, run in runs.items():
        comparisons = run["summary"].get("comparisons") or {}
        if not comparisons:
            continue
        out += [f"\\subsection*{{\\texttt{{{tex_escape(name)}}}}}", longtable("footnotesize", *COMPARISON_COLUMNS),
                *COMPARISON_HEAD, *comparison_rows(name, comparisons, numbers, True, run["summary"].get("fit_sources")),
                r"\bottomrule",
                r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def tolerances_tex(runs):
    """Every tolerance typed as a number in a published.toml (not derived from the printed digits, the run's
    standard errors or the round-off floor), with the origin its `why` states and what it judged: one row per
    comparison, in the order of Appendix A."""
    numbers = comparison_numbers(runs)
    rows = []
    for name, run in runs.items():
        for key, c in (run["summary"].get("comparisons") or {}).items():
            if c.get("why") and c["verdict"] != "not computed":  # (another run of the study computes it)
                judged = value_text(c.get("reproduced") if next(iter(c["compare"])) in ("above", "below")
                                    else c.get("difference"))
                rows.append(f"{comparison_ref(numbers, name, key)} & {tex_escape(c.get('figure', ''))} & "
                            f"{tex_escape(rule_text(c))} & {judged} & {prose(c['why'], key_refs(numbers, name))}\\\\")
    return "\n".join(["% The typed tolerances and their origin (scripts/report.py from summary.json \"comparisons\": why).",
                      longtable("footnotesize", 0.06, 0.12, 0.12, 0.13, 0.5),
                      r"\toprule no. & item & tolerance & judged (difference, or value of a claim) & its origin\\ "
                      r"\midrule", r"\endhead", *rows, r"\bottomrule", r"\end{longtable}}"]) + "\n"


# In a grid, a comparison's `where` reads "<item>, <quantity>, <columns>: <definition>" (published.toml), e.g.
# "001 Table 1, Energy H(p, q), N = 10, 20, 40 meshes per period: max |H(p_j, q_j) - H_0|, j = 1..N".
SYMBOL = r"[A-Za-z](?:_\{?\w+\}?)?(?:\([^()]*\))?"  # a quantity's symbol: p, N, H_d, H(p, q)
QUANTITY_COLUMN = r">{\raggedright\arraybackslash}p{0.14\linewidth}"  # (a long name wraps)


def where_fields(item, c):
    """(quantity, columns) of a comparison's `where` written "<item>, <quantity>, <columns>: ...", else None."""
    m = re.match(re.escape(item) + r", ((?:[^,()]|\([^()]*\))+), ([^:]+):", c.get("where", ""))
    return m.groups() if m else None


def symbol_math(symbol):
    """A symbol as math: its subscript braced (H_d(p, q) -> H_{d}(p, q))."""
    return re.sub(r"_\{?(\w+)\}?", r"_{\1}", symbol)


def quantity_tex(text):
    """A quantity's name as `where` gives it ("Energy H(p, q)"), its trailing symbol as math."""
    m = re.search(rf"(?:^|(?<=\s)){SYMBOL}$", text)
    return prose(text) if m is None else prose(text[:m.start()]) + "$" + symbol_math(m.group(0)) + "$"


def grid_head(columns, key):
    """A key's column head: "$N=10$" where the columns read "N = 10, 20, 40 ...", else the key."""
    m = re.match(rf"({SYMBOL}) = ", columns)
    return f"${symbol_math(m.group(1))}={key_text(key)}$" if m else prose(key_text(key))


def grid_cell(v, fmt):
    """One published or reproduced value of a grid, --- where it has none."""
    text = number(v, fmt)
    return "---" if text is None else f"${text}$"


def comparison_grid(item, comparisons):
    """\\comparisongrid{001 Table 1}: an item's comparisons in the paper's shape, or None if they do not form a
    grid. A grid has a row per quantity (the value comparisons, published by key, all with the same keys) and a
    column pair, published and reproduced, per key; an order comparison (compare "order") fills the order column
    pair of the row whose quantity its `where` names, and a row without one shows its tolerance there instead."""
    values, orders = {}, {}
    for c in comparisons.values():
        fields = where_fields(item, c)
        if fields is None:
            return None
        if isinstance(c.get("published"), dict) and fields[0] not in values:
            values[fields[0]] = (c, fields[1])
        elif "order" in (c.get("compare") or {}) and is_number(c.get("published")) and fields[0] not in orders:
            orders[fields[0]] = (c, fields[1])
        else:
            return None
    key_sets = {frozenset(c["published"]) for c, _ in values.values()}
    order_heads = {columns for _, columns in orders.values()}
    if len(key_sets) != 1 or len(order_heads) > 1 or not set(orders) <= set(values):
        return None
    first, columns = next(iter(values.values()))
    keys = list(first["published"])
    if all(re.fullmatch(r"[-+]?[\d.]+(?:[eE][-+]?\d+)?", k) for k in keys):  # (numbers: by value, not as text)
        keys.sort(key=float)
    heads = [grid_head(columns, k) for k in keys] + [prose(h[:1].upper() + h[1:]) for h in order_heads]
    rows = []
    for quantity, (c, _) in values.items():
        digits = "err" if "abs" in (c.get("compare") or {}) else "sci4"  # (to an absolute tolerance: two digits)
        cells = [quantity_tex(quantity)]
        for k in keys:
            cells += [grid_cell(c["published"][k], "sci3"), grid_cell((c.get("reproduced") or {}).get(k), digits)]
        if quantity in orders:
            order = orders[quantity][0]
            cells += [grid_cell(order["published"], "porder"), grid_cell(order.get("reproduced"), "order")]
        elif orders:
            at_roundoff = c.get("verdict") == "not comparable" and c.get("roundoff")  # (every entry round-off)
            cells.append(rf"\multicolumn{{2}}{{c}}{{{tex_escape('round-off' if at_roundoff else rule_text(c))}}}")
        rows.append(" & ".join(cells) + r" \\")
    last = len(heads) - 1
    return "\n".join([f"% {item}: its comparisons as a grid, a row per quantity (scripts/report.py).",
                      rf"\begin{{tabular}}{{@{{}}{QUANTITY_COLUMN}{'r' * 2 * len(heads)}@{{}}}}", r"\toprule",
                      "".join(rf" & \multicolumn{{2}}{{c}}{{{h}}}" for h in heads) + r" \\",
                      "".join(rf"\cmidrule({'l' if i == last else 'lr'}){{{2 * i + 2}-{2 * i + 3}}}"
                              for i in range(len(heads))),
                      "Quantity" + " & Pub. & Rep." * len(heads) + r" \\", r"\midrule", *rows, r"\bottomrule",
                      r"\end{tabular}"]) + "\n"


def item_slug(name):
    """An item's name as figure scripts spell it (figures/<run>_<slug>*.gp): "Fig. 5.2" -> "fig52",
    "Table 1" -> "table1", "energy error" -> "energyerror" (the runner's item_slug, figure_values.gp item.<slug>)."""
    return re.sub(r"[^a-z0-9]", "", name.lower())


def made_items(run):
    """The ids of the items a run made, by study: its studies that ran (run.json study_list), as each declares them."""
    return {st["name"]: st.get("made", []) for st in run.get("run", {}).get("study_list", []) if st.get("ran")}


def named_items(run, name):
    """The ids `name` stands for in a run: the item it made whose name's slug is `name` ("fig52": "003 Fig. 5.2"),
    else the items of its study `name` ("first_integrals": "000 Sec. 5.2"); none for neither (a cost figure, one
    beyond the papers)."""
    made = made_items(run)
    items = dict.fromkeys(i for ids in made.values() for i in ids)
    return [i for i in items if item_slug(i.partition(" ")[2]) == name] or list(made.get(name, []))


def figure_comparisons_tex(runs, papers=None):
    """Each figure's table of comparisons: those of a run whose published.toml entries belong to it (summary.json
    "comparisons", field figure), a file per run and figure; \\runcomparisons{<run>} (paper/main.tex) prints every
    one of a run with a computed comparison, its items in the order of paper/papers.toml (`papers`), then the
    statements that are no item (an equation, a section) in published.toml's order. \\comparisongrid{<run>}{<name>}:
    an item's comparisons in the paper's shape where they form a grid, the item named by its slug or its study
    (named_items). Returns the index (the files of each run's tables, each comparison's number for
    \\cmpref{run}{key}) and the tables, by file name under generated/."""
    index = ["% The tables of each run's comparisons, for \\runcomparisons{<run>} and \\comparisongrid{<run>}{<name>} "
             "(scripts/report.py).", r"\makeatletter"]
    tables, numbers = {}, comparison_numbers(runs)
    order = [f"{p['id']} {item['name']}" for p in (papers or {}).get("paper", []) for item in p.get("item", [])]
    for name, run in runs.items():
        by_figure = {}
        for key, c in (run["summary"].get("comparisons") or {}).items():
            if c.get("figure"):
                by_figure.setdefault(c["figure"], {})[key] = c
        shown = []
        for figure in sorted(by_figure, key=lambda f: order.index(f) if f in order else len(order)):
            comparisons = by_figure[figure]
            slug = re.sub(r"[^a-z0-9]+", "-", f"{name} {figure}".lower()).strip("-") + ".tex"
            paper, _, item = figure.partition(" ")
            if any(c["verdict"] != "not computed" for c in comparisons.values()):  # (its study ran here)
                shown.append(f"\\input{{generated/comparisons-{slug}}}")
            tables["comparisons-" + slug] = "\n".join([f"% {figure}: its comparisons in {name} (scripts/report.py).",
                                                       f"\\noindent {{[{paper}]}} {tex_escape(item)}:",
                                                       longtable("footnotesize", *COMPARISON_COLUMNS),
                                                       *COMPARISON_HEAD,
                                                       *comparison_rows(name, comparisons, numbers,
                                                                        fits=run["summary"].get("fit_sources")),
                                                       r"\bottomrule", r"\end{longtable}}"]) + "\n"
            grid = comparison_grid(figure, comparisons)
            if grid:
                tables["comparisongrid-" + slug] = grid
                studies = [study for study, ids in made_items(run).items() if figure in ids]
                for key in dict.fromkeys([item_slug(item)] + studies):
                    index.append(f"\\@namedef{{geomint@comparisongrid@{name}@{key}}}{{generated/comparisongrid-{slug}}}")
        if shown:
            file = "runcomparisons-" + re.sub(r"[^a-z0-9]+", "-", name.lower()).strip("-") + ".tex"
            tables[file] = "\n".join(
                [f"% Every figure's comparisons in {name}, in the papers' order (scripts/report.py)."] + shown) + "\n"
            index.append(f"\\@namedef{{geomint@runcomparisons@{name}}}{{generated/{file}}}")
    index += [f"\\@namedef{{geomint@cmp@{run}@{key}}}{{\\#{n}}}" for (run, key), n in numbers.items()]  # (\\cmpref)
    index.append(r"\makeatother")
    return "\n".join(index) + "\n", tables


FIGURE_ITEMS, FIGREF = re.compile(r"\\figureitems\{([^}]*)\}"), re.compile(r"\\figref\{([^}]*)\}")


def figure_names(runs, figures):
    """Every name \\figureitems takes, with the ids of the items it shows: each figure script's (figures/<name>.gp,
    of the run whose name, the longest that does, begins it: <run>_<rest>, its items named_items(run, rest)), and
    <run>_<slug> of each item a run made (a table of the report that shows it)."""
    names = {}
    for run_name, run in runs.items():
        for item in dict.fromkeys(i for ids in made_items(run).values() for i in ids):
            names[f"{run_name}_{item_slug(item.partition(' ')[2])}"] = [item]
    for gp in sorted(figures.glob("*.gp")):
        owners = [r for r in runs if gp.stem.startswith(r + "_")]
        if owners:
            run_name = max(owners, key=len)
            names[gp.stem] = named_items(runs[run_name], gp.stem[len(run_name) + 1:])
    return names


def figure_items_tex(runs, figures, texts):
    """\\figureitems{<name>} after a figure's caption (paper/main.tex): \\label{figure:<name>} for \\figref{<name>}
    and \\label{item:<id>} of each item it shows (figure_names), for \\itemref{<id>} of the ledger. Returns the file
    and the problems of `texts` (LaTeX by file name): a name that no script or item has, a figure labelled twice,
    an item labelled by two figures, a \\figref to no \\figureitems."""
    names = figure_names(runs, figures)
    out = ["% Each figure's labels for \\figureitems{<name>}: figures/<name>.gp or <run>_<item slug>, its items from "
           "run.json (scripts/report.py).", r"\makeatletter"]
    out += [f"\\@namedef{{geomint@figure@{name}}}{{\\label{{figure:{name}}}" +
            "".join(f"\\label{{item:{i}}}" for i in items) + "}" for name, items in names.items()]
    problems, used, labelled, refs = [], {}, {}, []
    for file, text in texts.items():
        text = re.sub(r"(?<!\\)%.*", "", text)
        for m in FIGURE_ITEMS.finditer(text):
            name, at = m.group(1), f"{file}:{text.count(chr(10), 0, m.start()) + 1}"
            if "#" in name:  # (a macro's own parameter)
                continue
            if name not in names:
                problems.append(f"{at}: {m.group(0)}: no figure script figures/{name}.gp of a run, no item of that name")
            elif name in used:
                problems.append(f"{at}: {m.group(0)}: already at {used[name]}")
            used.setdefault(name, at)
            for item in names.get(name, []):
                if item in labelled and labelled[item] != name:
                    problems.append(f"{at}: {m.group(0)}: {item} is already labelled by \\figureitems{{{labelled[item]}}}")
                labelled.setdefault(item, name)
        refs += [(file, m.group(1)) for m in FIGREF.finditer(text) if "#" not in m.group(1)]
    problems += [f"{file}: \\figref{{{name}}}: no \\figureitems{{{name}}}" for file, name in refs if name not in used]
    return "\n".join(out + [r"\makeatother"]) + "\n", problems


def methods_tex(methods, cites=None):
    def bound(v):
        if v is None:
            return "---"
        return r"$\infty$" if v == "inf" or (is_number(v) and math.isinf(v)) else "$" + FORMATS["sig4"](v) + "$"
    out = ["% The method registry (geomint-methods --json; scripts/report.py).",
           longtable("footnotesize", 0.2, 0.11, 0.08, 0.09, 0.09, 0.16, 0.27),
           r"\toprule method & family & order & bound $h|\lambda|$ & bound $\omega h$ & properties & defined in\\ \midrule",
           r"\endhead"]
    for m in methods:
        order = str(m["order"]) + (f" ({m['kernel_order']})" if m["kernel_order"] != m["order"] else "")
        out.append(f"{code(m['name'])} & {tex_escape(m['family'])} & {order} & {bound(m.get('real_bound'))} & "
                   f"{bound(m.get('oscillatory_bound'))} & {', '.join(code(p) for p in m['properties'])} & "
                   f"{prose(m['citation'])}{(cites or {}).get(m['name'], '')}\\\\")
    out += [r"\bottomrule", r"\end{longtable}}"]
    return "\n".join(out) + "\n"


def method_names_tex(methods):
    """\\method{sti} and \\method[004]{sti} (paper/main.tex): a method's title, and its equations in a paper,
    as the registry gives them (geomint-methods --json), by registry name or label."""
    out = ["% The methods' names for \\method (geomint-methods --json; scripts/report.py).", r"\makeatletter"]
    for m in methods:
        for key in dict.fromkeys([m["name"], m["label"]]):
            out.append(f"\\@namedef{{geomint@method@{key}}}{{{gnuplot_tex(m['title'])}}}")
            for part in filter(None, m["equations"].split("; ")):
                paper, equations = part.split(" ", 1)
                out.append(f"\\@namedef{{geomint@method@{key}@{paper}}}{{{tex_escape(equations)}}}")
    out.append(r"\makeatother")
    return "\n".join(out) + "\n"
