#!/usr/bin/env python3
"""check_figure_text.py [--remove-failing] PDF...: the text of a rendered figure is on its canvas and readable.

For each page of each PDF (pdftotext -bbox, poppler-utils) it fails, naming the figure and the
words, when a word's box leaves the page (a clipped title or axis label) or when two words
overlap by more than a third of the smaller one (labels drawn over each other).
--remove-failing removes a failing figure (NAME.pdf and NAME.png), so that no make takes it for done.
"""
import html
import itertools
import os
import re
import subprocess
import sys

SLACK = 0.5  # points: a glyph's box may touch the page edge
WORD = re.compile(r'<word xMin="([-\d.]+)" yMin="([-\d.]+)" xMax="([-\d.]+)" yMax="([-\d.]+)">(.*?)</word>')


def pages(pdf):
    xml = subprocess.run(["pdftotext", "-bbox", pdf, "-"], capture_output=True, text=True, check=True).stdout
    for m in re.finditer(r'<page width="([\d.]+)" height="([\d.]+)">(.*?)</page>', xml, re.S):
        words = [(float(a), float(b), float(c), float(d), html.unescape(t)) for a, b, c, d, t in WORD.findall(m.group(3))]
        yield float(m.group(1)), float(m.group(2)), words


def problems(pdf):
    for width, height, words in pages(pdf):
        for x0, y0, x1, y1, text in words:
            if x0 < -SLACK or y0 < -SLACK or x1 > width + SLACK or y1 > height + SLACK:
                yield f"'{text}' leaves the canvas ({x0:.1f}, {y0:.1f})-({x1:.1f}, {y1:.1f}) of {width:g} x {height:g} pt"
        by_x = sorted(words)
        for i, a in enumerate(by_x):  # (each word against those that start left of its right edge)
            for b in itertools.takewhile(lambda w: w[0] < a[2], by_x[i + 1:]):
                dx, dy = min(a[2], b[2]) - max(a[0], b[0]), min(a[3], b[3]) - max(a[1], b[1])
                smaller = min((a[2] - a[0]) * (a[3] - a[1]), (b[2] - b[0]) * (b[3] - b[1]))
                if dx > 0 and dy > 0 and dx * dy > smaller / 3:
                    yield f"'{a[4]}' and '{b[4]}' overlap"


def main(argv):
    remove = argv[1:2] == ["--remove-failing"]
    found = 0
    for pdf in argv[1 + remove:]:
        failed = False
        for p in problems(pdf):
            print(f"{pdf}: {p}")
            found += 1
            failed = True
        if failed and remove:
            for f in (pdf, pdf[:-len(".pdf")] + ".png"):
                if os.path.exists(f):
                    os.remove(f)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
