#!/usr/bin/env python3
"""check_pdf_rules.py SOURCE_DIR: scripts/check_pdf.py fails on what it promises to, from synthetic
input (no LaTeX run needed): a planted overfull table 12 pt too wide and a float too large for the
page fail, a 3 pt overfull line passes; "(s)" plurals, "nan", "??" and an absolute path (/work, /tmp, /home,
/root, /usr, any /a/b) on a page fail, "NaN", a relative path, a URL and the ordinary text of the report pass, as
does a "nan" quoted from a refusal; ASCII math on an appendix page (->, <=, sqrt(, a power h^2 as the text font
sets it) fails outside typewriter text and passes in it, as do math and a hat accent; a raw summary key and ASCII
math in a LaTeX source fail, in code, a path, math or a value lookup they pass; a published comparison's key
printed anywhere (code too) fails, in its reference, its label or a program's quoted message it passes."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(sys.argv[1]) / "scripts"))
import check_pdf  # noqa: E402

LOG = r"""
Overfull \hbox (12.00003pt too wide) in alignment at lines 40--52
 [] [] [] []
Overfull \hbox (3.1pt too wide) in paragraph at lines 7--9
LaTeX Warning: Float too large for page by 18.5pt on input line 210.
"""
GOOD = ["Contents\nThe reproduction ledger\n", "The standard deviation is NaN-free; 1 episode was found.\n"]
problems = []
log = check_pdf.log_problems(LOG)
if len(log) != 2 or "12.00003" not in log[0] or "18.5" not in log[1]:
    problems.append(f"the log rules found {log}")
if check_pdf.text_problems(GOOD):
    problems.append(f"clean pages fail: {check_pdf.text_problems(GOOD)}")
for bad in ("1 episode(s)", "value nan here", "see Table ??"):
    if not check_pdf.text_problems(GOOD + [bad]):
        problems.append(f"'{bad}' passes")
if check_pdf.text_problems(GOOD + ["refused: “decay.h = nan (from --set): must be a finite number > 0”\n"]):
    problems.append("a NaN inside a quoted refusal fails")
if not check_pdf.text_problems(GOOD + ["the order is nan “quoted”\n"]):
    problems.append("a NaN outside the quotation passes")
# raw summary keys in the LaTeX sources: flagged in the text, not in code, paths, math or value lookups
SOURCE = r"""The order \result[order]{ti_drift}{orders.sv_phase} of \texttt{sv\_phase} in \path{a_b.csv}, $p_x$, \[H_0\]
% a comment with raw_key
\label{sec:raw_key} see Fig.~\ref{fig:ec_fig2} and \verdict{ti_drift}{004 Fig. 5}.
"""
if check_pdf.source_problems("good.tex", SOURCE):
    problems.append(f"clean sources fail: {check_pdf.source_problems('good.tex', SOURCE)}")
for bad in (r"the key se\_compensated\_energy\_rms differs", r"lj\_printed\_step\_stable", "t_end in the text"):
    found = check_pdf.source_problems("bad.tex", SOURCE + bad + "\n")
    if len(found) != 1 or ":4:" not in found[0]:
        problems.append(f"'{bad}' gives {found}")
if not check_pdf.text_problems(["no contents here"]):
    problems.append("a report without contents and ledger in front passes")
# absolute paths of the machine that built the report fail on any page, in code too; relative paths and URLs pass
for bad in ("--scene /work/main/build/test-results/cli-1/deep.toml", "delete /tmp/geomint checkpoint test 365/",
            "(in /home/user/geomint/experiments/x.toml)", "“/root/x: no such file”", "at /usr", "in /opt/a/b",
            "the directory /scratch/run"):
    found = check_pdf.text_problems(GOOD + [bad + "\n"])
    if len(found) != 1 or "p. 3: an absolute path" not in found[0]:
        problems.append(f"'{bad}' gives {found}")
for good in ("experiments/ti_drift/lj.cpp and DIR/tasks.checkpoint.json", "https://doi.org/10.1007/s10543 and 1/2",
             "s/step, and/or, --out /proc/self/x (the same on every machine), /dev/null"):
    if check_pdf.text_problems(GOOD + [good + "\n"]):
        problems.append(f"'{good}' fails: {check_pdf.text_problems(GOOD + [good + chr(10)])}")


def page(runs):
    """pdftohtml -xml of an appendix page (p. 105): runs (left, width, text, font) on one line; font 0 is the
    text's (CMR10), 1 typewriter (CMTT10), 2 math italic (CMMI10)."""
    texts = "".join(f'<text top="100" left="{x}" width="{w}" height="12" font="{f}">{t}</text>' for x, w, t, f in runs)
    return ('<pdf2xml><page number="105"><fontspec id="0" size="13" family="ABCDEF+CMR10" color="#000000"/>'
            '<fontspec id="1" size="13" family="ABCDEF+CMTT10" color="#000000"/>'
            f'<fontspec id="2" size="13" family="ABCDEF+CMMI10" color="#000000"/>{texts}</page></pdf2xml>')


MATH = {"an arrow": [(100, 60, "when omega h -", 0), (160, 8, "&gt;", 2), (170, 60, " 2 sqrt(3)", 0)],
        "a relation": [(100, 60, "last stable point of x ", 0), (160, 8, "&lt;", 2), (168, 30, "= 0.3", 0)],
        "a power": [(100, 200, "the printed coefficient hˆ2/24 in (32)", 0)],
        "a square root": [(100, 200, "stable for h omega &lt; sqrt(42 - 6 sqrt(29))", 0)]}
for what, runs in MATH.items():
    found = check_pdf.math_problems(check_pdf.font_lines(page(runs)))
    if not found or not found[0].startswith("p. 105: "):
        problems.append(f"ASCII math in an appendix ({what}) gives {found}")
    code_runs = [(x, w, t, 1 if f == 0 else f) for x, w, t, f in runs]
    if check_pdf.math_problems(check_pdf.font_lines(page(code_runs))):
        problems.append(f"ASCII math in typewriter text (a program's message, {what}) fails")
for what, runs in {"math": [(100, 40, "when ", 0), (140, 20, "ωh", 2), (160, 10, "→", 0), (170, 30, "2", 0)],
                   "a hat accent over q": [(100, 80, "With ˆ", 0), (172, 7, "q", 2), (181, 40, "= sin(", 0)],
                   "a superscript": [(100, 30, "h", 2), (130, 5, "2", 0), (136, 20, "/24", 0)]}.items():
    if check_pdf.math_problems(check_pdf.font_lines(page(runs))):
        problems.append(f"{what} fails: {check_pdf.math_problems(check_pdf.font_lines(page(runs)))}")
# ASCII math in a LaTeX source (an appendix table, as report.py wrote it before) fails; as math or code it passes
for bad in (r"coefficient h\textasciicircum{}2/\allowbreak{}24", r"when omega h -\textgreater{} 2",
            r"x \textless{}= 0.3", r"$x$ \textgreater{}= 1", "of 2 sqrt(3)", "the volume in mu(4)", "x -> y"):
    found = check_pdf.source_problems("appendix.tex", SOURCE + bad + "\n")
    if not found or not all(":4:" in f for f in found):
        problems.append(f"ASCII math '{bad}' in a source gives {found}")
CLEAN_MATH = (r"$h^{2}/24$, $\omega h \to 2 \sqrt{3}$, $x \le 0.3$, \texttt{h omega \textgreater{}= 2 sqrt(3)}, the "
              r"machine epsilon, ``\texttt{2\textasciicircum{}53}''")
if check_pdf.source_problems("appendix.tex", SOURCE + CLEAN_MATH + "\n"):
    problems.append(f"math set as math fails: {check_pdf.source_problems('appendix.tex', SOURCE + CLEAN_MATH)}")
# a published comparison's key (its row: \label{cmp:run:key}) printed anywhere fails, code included
ROWS = r"\phantomsection\label{cmp:measure_cloud:ptp_phi4_mu4_full_cloud}\#41 & 003 Figs 5.2, 5.4 & \\" + "\n"
keys = check_pdf.comparison_keys([ROWS])
if keys != {"ptp_phi4_mu4_full_cloud"}:
    problems.append(f"the keys of the rows are {keys}")
for bad in (r"\texttt{ptp\_\allowbreak{}phi4\_\allowbreak{}mu4\_\allowbreak{}full\_\allowbreak{}cloud} & 003",
            r"(entry \texttt{ptp\_phi4\_mu4\_full\_cloud})"):
    found = check_pdf.source_problems("quick.tex", SOURCE + bad + "\n", keys)
    if len(found) != 1 or ":4: a comparison's key" not in found[0]:
        problems.append(f"the key in '{bad}' gives {found}")
for good in (ROWS, r"(entry \cmpref{measure_cloud}{ptp_phi4_mu4_full_cloud}, "
                   r"\hyperref[cmp:x:ptp_phi4_mu4_full_cloud]{\#41})",
             r"refused: ``\texttt{ptp\_phi4\_mu4\_full\_cloud: no such run}''"):
    if check_pdf.source_problems("comparisons.tex", SOURCE + good + "\n", keys):
        problems.append(f"'{good}' fails: {check_pdf.source_problems('comparisons.tex', SOURCE + good, keys)}")
for p in problems:
    print("check_pdf_rules:", p)
print(f"check_pdf_rules: {len(problems)} problems")
sys.exit(1 if problems else 0)
