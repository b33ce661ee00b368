#!/usr/bin/env python3
"""check_quotes.py SOURCE_DIR SEEDS_DIR: every quotation in experiments/*/published.toml (quotes = [{ at, text }])
is the paper's own words: a verbatim part of the text of the paper its `at` names (SEEDS_DIR/<id>_*.txt),
up to runs of white space. Where the scan garbled a symbol, the quotation may give it as read if its `at`
says so, once per symbol: `scan "p;" read as p_x` (the text is checked with each reading put back as scanned).
Skipped (exit 77) where the papers' text is not present."""
import pathlib
import re
import sys
import tomllib

source, seeds = (pathlib.Path(a) for a in sys.argv[1:3])
if not seeds.is_dir():
    print(f"check_quotes: no papers' text in {seeds}: skipped")
    sys.exit(77)


def squeeze(text):
    return re.sub(r"\s+", " ", text).strip()


READING = re.compile(r'scan "([^"]+)" read as ([A-Za-z0-9_^{}]+)')


def as_scanned(q):
    """The quotation's text with the readings its `at` declares put back as the scan gives them."""
    text = q["text"]
    for scanned, read in READING.findall(q["at"]):
        text = text.replace(read, scanned)
    return text


papers = {p.name[:3]: squeeze(p.read_text(encoding="utf-8")) for p in seeds.glob("[0-9][0-9][0-9]_*.txt")}
problems, checked = [], 0
for toml in sorted(source.glob("experiments/*/published.toml")):
    for key, entry in tomllib.loads(toml.read_text(encoding="utf-8")).items():
        for q in entry.get("quotes", []):
            paper = q["at"][:3]
            checked += 1
            if paper not in papers:
                problems.append(f"{toml.parent.name}/{key}: 'at' names no paper: {q['at']}")
            elif squeeze(as_scanned(q)) not in papers[paper]:
                problems.append(f"{toml.parent.name}/{key}: not in the text of {paper}: {q['text'][:80]}")
for p in problems:
    print("check_quotes:", p)
print(f"check_quotes: {checked} quotations, {len(problems)} problems")
sys.exit(1 if problems or not checked else 0)
