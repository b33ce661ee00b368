#!/usr/bin/env python3
"""check_pdf.py PDF: the built report shows no unresolved reference, missing value or non-number.

Reads the text of the PDF (pdftotext, poppler-utils) and fails, naming the page and line, on
"??" (an undefined reference), "n/a", "nan" as C++ and Python print a NaN (not the word "NaN" or
the "Nan" of a test's name), "missing:" (a value report.py --draft could not
find), an "inf" standing alone or a figure "not yet rendered"; and if its first pages lack the
contents or the ledger.
"""
import re
import subprocess
import sys

BAD = [(re.compile(r"\?\?"), "an undefined reference"), (re.compile(r"\bn/a\b", re.I), "n/a"),
       (re.compile(r"(?<![\w.])-?(nan|NAN)\b"), "a NaN"), (re.compile(r"\bmissing:"), "a missing value"),
       (re.compile(r"(?<![\w.])-?inf\b"), "an infinity"), (re.compile(r"not yet rendered"), "a missing figure")]


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    text = subprocess.run(["pdftotext", "-layout", argv[1], "-"], capture_output=True, text=True, check=True).stdout
    pages = text.split("\f")
    problems = [f"{argv[1]}: p. {p + 1}: {what}: {line.strip()}"
                for p, page in enumerate(pages) for line in page.splitlines()
                for rx, what in BAD if rx.search(line)]
    front = "\n".join(pages[:4])
    for heading in ("Contents", "The reproduction ledger"):
        if heading not in front:
            problems.append(f"{argv[1]}: '{heading}' is not on the first pages")
    for p in problems:
        print(p)
    print(f"check_pdf.py: {len(pages)} pages, " + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
