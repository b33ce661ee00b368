#!/usr/bin/env python3
"""check_pdf.py PDF [--log LOG] [--tex SOURCE...]: the built report shows no unresolved reference, missing value,
non-number or layout fault.

Reads the text of the PDF (pdftotext, poppler-utils) and fails, naming the page and line, on
"??" (an undefined reference), "n/a", "nan" as C++ and Python print a NaN (not the word "NaN", the
"Nan" of a test's name, a "nan" inside a quotation or typed as an argument, "h=nan": the input a refusal
names), "missing:" (a value report.py --draft could not
find), an "inf" standing alone, a figure "not yet rendered" or an "(s)" plural; and if its first
pages lack the contents or the ledger. With the LaTeX log (--log, paper/main.log) it also fails on an
overfull box more than 5 pt too wide or too high (text past the margin) and on a float too large
for the page (a table or figure that runs into the page number). With the LaTeX sources (--tex, the
sections and what report.py generated) it fails on a raw summary key in the text: a word with an
underscore outside \\texttt, \\path, math and the value lookups (\\result ...).
"""
import re
import subprocess
import sys

BAD = [(re.compile(r"\?\?"), "an undefined reference"), (re.compile(r"\bn/a\b", re.I), "n/a"),
       (re.compile(r"(?<![\w.=])-?(nan|NAN)\b"), "a NaN"), (re.compile(r"\bmissing:"), "a missing value"),
       (re.compile(r"(?<![\w.=])-?inf\b"), "an infinity"), (re.compile(r"not yet rendered"), "a missing figure"),
       (re.compile(r"\w\(s\)"), 'an "(s)" plural')]
QUOTABLE = ("a NaN", "an infinity")  # what a quotation may hold: the input "decay.h = nan" a refusal names
QUOTED = re.compile(r"“[^”]*(”|$)|^[^“]*”")  # a quotation (a refusal's message, a paper's words) on a line
OVERFULL = re.compile(r"^Overfull \\[hv]box \((\d+(?:\.\d+)?)pt too (wide|high)\)(.*)$", re.M)
FLOAT = re.compile(r"Float too large for page by (\d+(?:\.\d+)?)pt")
TOLERANCE_PT = 5.0


def text_problems(pages):
    """What the PDF's text shows wrong, page by page (pages: the text of each page)."""
    problems = [f"p. {p + 1}: {what}: {line.strip()}"
                for p, page in enumerate(pages) for line in page.splitlines()
                for rx, what in BAD if rx.search(QUOTED.sub("“”", line) if what in QUOTABLE else line)]
    front = "\n".join(pages[:4])
    problems += [f"'{heading}' is not on the first pages" for heading in ("Contents", "The reproduction ledger")
                 if heading not in front]
    return problems


def log_problems(log):
    """Layout faults in a LaTeX log: overfull boxes beyond TOLERANCE_PT, floats too large for the page."""
    problems = [f"overfull box, {m.group(1)} pt too {m.group(2)}:{m.group(3)}"
                for m in OVERFULL.finditer(log) if float(m.group(1)) > TOLERANCE_PT]
    problems += [f"a float {m.group(1)} pt too large for the page" for m in FLOAT.finditer(log)]
    return problems


# What a LaTeX source may hold with an underscore: code and paths (\\texttt, \\path, \\url), a value looked up
# by its key (\\result, \\ifresult, \\verdict), a method by its registry name (\\method), labels, references,
# math, and comments.
SOURCE_EXEMPT = [re.compile(p, re.S) for p in (
    r"(?<!\\)%[^\n]*", r"\\(?:texttt|path|url|href|label|ref|eqref|cite|input|includegraphics|hyperref|pageref|InputIfFileExists|"
    r"figorbox|exe|genfile|missingbox)"
    r"(?:\[[^]]*\])?\{(?:[^{}]|\{(?:[^{}]|\{[^{}]*\})*\})*\}",
    r"\\(?:result\w*|ifresult|verdict|method)(?:\[[^]]*\])?(?:\{[^{}]*\})+", r"\\@namedef\{[^{}]*\}",
    r"\$\$.*?\$\$", r"(?<!\\)\$.*?(?<!\\)\$", r"\\\[.*?\\\]", r"\\\(.*?\\\)",
    r"\\begin\{(equation|align|gather|multline)\*?\}.*?\\end\{\1\*?\}")]
RAW_KEY = re.compile(r"\b\w+(?:\\?_(?:\\allowbreak\{\})?\w+)+")


def source_problems(name, text):
    """Raw summary keys in a LaTeX source: a word with an underscore in the text (outside code, paths, math)."""
    for rx in SOURCE_EXEMPT:
        text = rx.sub(lambda m: "\n" * m.group(0).count("\n"), text)
    return [f"{name}:{text.count(chr(10), 0, m.start()) + 1}: a raw key in the text: {m.group(0)}"
            for m in RAW_KEY.finditer(text)]


def main(argv):
    args = argv[2:]
    log = args[args.index("--log") + 1] if "--log" in args else None
    sources = args[args.index("--tex") + 1:] if "--tex" in args else []
    if len(argv) < 2 or (log is None and args and args[0] != "--tex"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    text = subprocess.run(["pdftotext", "-layout", argv[1], "-"], capture_output=True, text=True, check=True).stdout
    pages = text.split("\f")
    problems = text_problems(pages)
    if log:
        with open(log, encoding="latin-1") as f:
            problems += log_problems(f.read())
    for source in sources:
        with open(source, encoding="utf-8") as f:
            problems += source_problems(source, f.read())
    for p in problems:
        print(f"{argv[1]}: {p}")
    print(f"check_pdf.py: {len(pages)} pages, " + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
