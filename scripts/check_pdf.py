#!/usr/bin/env python3
"""check_pdf.py PDF [--log LOG] [--tex SOURCE...]: the built report shows no unresolved reference, missing value,
non-number, layout fault, path of the machine that built it, ASCII math or raw summary key.

Reads the text of the PDF (pdftotext, poppler-utils) and fails, naming the page and line, on
"??" (an undefined reference), "n/a", "nan" as C++ and Python print a NaN (not the word "NaN", the
"Nan" of a test's name, a "nan" inside a quotation or typed as an argument, "h=nan": the input a refusal
names), "missing:" (a value report.py --draft could not
find), an "inf" standing alone, a figure "not yet rendered", an "(s)" plural or an absolute path (a "/" at
the start of a word followed by a name and another "/", or /work, /tmp, /home, /root, /usr and the other
top-level directories: in code too; a relative path such as experiments/ti_drift/lj.cpp and a URL pass); and if
its first pages lack the contents or the ledger. With the fonts of its text (pdftohtml -xml) it fails on ASCII
math outside typewriter text (code, a program's message): "^" or "ˆ" between two characters as a power,
"->", "<=", ">=", "!=" and "sqrt(" (math set as math shows none of them). With the LaTeX log (--log,
paper/main.log) it also fails on an overfull box more than 5 pt too wide or too high (text past the margin) and on
a float too large for the page (a table or figure that runs into the page number). With the LaTeX sources (--tex,
the sections and what report.py generated) it fails on a raw summary key in the text: a word with an underscore
outside \\texttt, \\path, math and the value lookups (\\result ...); on ASCII math in the text outside those
(\\textasciicircum, "->", "<=", ">=" also as \\textless{}= and \\textgreater{}=, "sqrt(", a Greek letter spelled out
such as omega); and on the key of a published comparison (a row \\label{cmp:<run>:<key>} of Appendix A) printed
anywhere, code included: a comparison is named by its number (\\cmpref) and its description.
"""
import re
import subprocess
import sys

BAD = [(re.compile(r"\?\?"), "an undefined reference"), (re.compile(r"\bn/a\b", re.I), "n/a"),
       (re.compile(r"(?<![\w.=])-?(nan|NAN)\b"), "a NaN"), (re.compile(r"\bmissing:"), "a missing value"),
       (re.compile(r"(?<![\w.=])-?inf\b"), "an infinity"), (re.compile(r"not yet rendered"), "a missing figure"),
       (re.compile(r"\w\(s\)"), 'an "(s)" plural'),
       (re.compile(r"(?:^|(?<=[\s(\[“\"'=,;]))/(?!proc/self\b|dev/)(?:(?:work|tmp|home|root|usr|var|etc|opt|mnt|srv|"
                   r"scratch|private|Users|run|nfs|data)\b|[\w.+-]+/[\w.*+-])"), "an absolute path")]
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


# Typewriter fonts (code, a program's message), and ASCII math in what is not typewriter: a power, an arrow, a
# relation typed as two characters, a square root as a function call.
MONOSPACE = re.compile(r"TT\d|Mono|Courier|Typewriter", re.I)
ASCII_MATH = [(re.compile(r"[\w)\]}][ ]?[\^ˆ][ ]?[-\w({]"), "an ASCII power"),
              (re.compile(r"-[ ]?>"), "an ASCII arrow ->"), (re.compile(r"[<>!][ ]?="), "an ASCII relation"),
              (re.compile(r"\bsqrt ?\("), "sqrt( as text")]
XML_TEXT = re.compile(r'<text top="(-?\d+)" left="(-?\d+)" width="(\d+)" height="(\d+)" font="(\d+)">(.*?)</text>',
                      re.S)


def font_lines(xml):
    """The lines of each page of pdftohtml -xml output: (page, the line's text, its text with each run in a
    typewriter font replaced by "\x01"). Runs are joined in the order of the line, by a space across a gap; a
    run that starts over the one before (an accent such as the hat of q-hat) is kept apart by "\x01" too."""
    mono = {m.group(1) for m in re.finditer(r'<fontspec id="(\d+)"[^>]*family="([^"]*)"', xml)
            if MONOSPACE.search(m.group(2))}
    lines = []
    for number, page in re.findall(r'<page number="(\d+)"(.*?)</page>', xml, re.S):
        rows = {}
        for top, left, width, height, font, text in XML_TEXT.findall(page):
            text = re.sub(r"<[^>]+>", "", text).replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", '"') \
                .replace("&apos;", "'").replace("&amp;", "&")
            rows.setdefault(int(top) + int(height), []).append((int(left), int(width), text, font in mono))
        for bottom in sorted(rows):
            full, prose, end = "", "", None
            for left, width, text, is_code in sorted(rows[bottom]):
                glue = "" if end is None else "\x01" if left < end - 1 else " " if left > end + 1 else ""
                full += glue.replace("\x01", "") + text
                prose += glue + ("\x01" if is_code else text)
                end = left + width
            lines.append((int(number), full, prose))
    return lines


def math_problems(lines):
    """ASCII math outside typewriter text, line by line (lines: font_lines)."""
    return [f"p. {page}: {what} outside code: {full.strip()}" for page, full, prose in lines
            for rx, what in ASCII_MATH if rx.search(prose)]


def log_problems(log):
    """Layout faults in a LaTeX log: overfull boxes beyond TOLERANCE_PT, floats too large for the page."""
    problems = [f"overfull box, {m.group(1)} pt too {m.group(2)}:{m.group(3)}"
                for m in OVERFULL.finditer(log) if float(m.group(1)) > TOLERANCE_PT]
    problems += [f"a float {m.group(1)} pt too large for the page" for m in FLOAT.finditer(log)]
    return problems


# What a LaTeX source may hold with an underscore: code and paths (\\texttt, \\path, \\url), a value looked up
# by its key (\\result, \\ifresult, \\verdict), a method by its registry name (\\method), a figure by its script
# and a run by its name (\\figureitems, \\figref, \\runcomparisons, \\comparisongrid), labels, references,
# math, and comments.
SOURCE_EXEMPT = [re.compile(p, re.S) for p in (
    r"(?<!\\)%[^\n]*", r"\\(?:texttt|path|url|href|label|ref|eqref|cite|input|includegraphics|hyperref|pageref|InputIfFileExists|"
    r"figorbox|exe|genfile|missingbox)"
    r"(?:\[[^]]*\])?\{(?:[^{}]|\{(?:[^{}]|\{[^{}]*\})*\})*\}",
    r"\\(?:result\w*|ifresult|verdict|method|cmpref|figureitems|figref|runcomparisons|comparisongrid)"
    r"(?:\[[^]]*\])?(?:\{[^{}]*\})+", r"\\@namedef\{[^{}]*\}",
    r"\$\$.*?\$\$", r"(?<!\\)\$.*?(?<!\\)\$", r"\\\[.*?\\\]", r"\\\(.*?\\\)",
    r"\\begin\{(equation|align|gather|multline)\*?\}.*?\\end\{\1\*?\}")]
RAW_KEY = re.compile(r"\b\w+(?:\\?_(?:\\allowbreak\{\})?\w+)+")
GREEK = ("alpha|beta|gamma|delta|zeta|theta|kappa|lambda|sigma|omega|Gamma|Delta|Theta|Lambda|Sigma|Phi|Psi|Omega|mu|"
         "phi|psi")  # (not epsilon: the machine epsilon is a word)
SOURCE_MATH = [(re.compile(r"\\textasciicircum|\\\^\{\}"), "an ASCII power"),
               (re.compile(r"-\s*(?:\\textgreater\b(?:\{\})?|>)"), "an ASCII arrow ->"),
               (re.compile(r"(?:\\textless|\\textgreater)\b(?:\{\})?\s*=|[<>!]="), "an ASCII relation"),
               (re.compile(r"\bsqrt\s*\("), "sqrt( as text"),
               (re.compile(rf"(?<![\\\w])(?:{GREEK})(?![\w])"), "a Greek letter spelled out")]
# A comparison's key (its row in Appendix A: \\label{cmp:<run>:<key>}, its number: \\@namedef{geomint@cmp@<run>@<key>})
# may be named only in a reference, a value lookup or a quoted message of a program (``\\texttt{...}'').
COMPARISON_KEY = re.compile(r"\\label\{cmp:[^:{}]+:([^{}]+)\}|\\@namedef\{geomint@cmp@[^@{}]+@([^{}]+)\}")
KEY_EXEMPT = re.compile(r"(?<!\\)%[^\n]*|\\(?:label|ref|pageref|cmpref|hyperref|result\w*|ifresult|verdict|figureitems|"
                        r"figref|runcomparisons|comparisongrid)"
                        r"(?:\[[^]]*\])?(?:\{[^{}]*\})*|\\@namedef\{[^{}]*\}"
                        r"|``\\texttt\{(?:[^{}]|\{[^{}]*\})*\}''")  # (a program's words)


def comparison_keys(texts):
    """The keys of the published comparisons that the sources list (Appendix A's rows, their numbers)."""
    return {a or b for text in texts for a, b in COMPARISON_KEY.findall(text)}


def source_problems(name, text, keys=()):
    """Raw summary keys and ASCII math in a LaTeX source: a word with an underscore, ^, ->, <=, >=, sqrt( or a Greek
    letter by name in the text (outside code, paths, math); and a comparison's key (`keys`) anywhere."""
    def line(t, at):
        return t.count("\n", 0, at) + 1
    shown = re.sub(r"\\allowbreak(?:\{\}| )|\\-", "", KEY_EXEMPT.sub(lambda m: "\n" * m.group(0).count("\n"), text))
    shown = shown.replace("\\_", "_")
    problems = [f"{name}:{line(shown, m.start())}: a comparison's key, not its number: {m.group(0)}"
                for key in sorted(keys) for m in re.finditer(rf"(?<![\w.:@]){re.escape(key)}(?![\w])", shown)]
    for rx in SOURCE_EXEMPT:
        text = rx.sub(lambda m: "\n" * m.group(0).count("\n"), text)
    problems += [f"{name}:{line(text, m.start())}: a raw key in the text: {m.group(0)}" for m in RAW_KEY.finditer(text)]
    return problems + [f"{name}:{line(text, m.start())}: {what} in the text: {m.group(0)}"
                       for rx, what in SOURCE_MATH for m in rx.finditer(text)]


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
    xml = subprocess.run(["pdftohtml", "-xml", "-i", "-q", "-stdout", argv[1]], capture_output=True, text=True,
                         check=True).stdout  # (poppler-utils, as pdftotext)
    problems += math_problems(font_lines(xml))
    texts = {}
    for source in sources:
        with open(source, encoding="utf-8") as f:
            texts[source] = f.read()
    keys = comparison_keys(texts.values())
    for source, text in texts.items():
        problems += source_problems(source, text, keys)
    for p in problems:
        print(f"{argv[1]}: {p}")
    print(f"check_pdf.py: {len(pages)} pages, " + ("ok" if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
