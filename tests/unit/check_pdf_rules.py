#!/usr/bin/env python3
"""check_pdf_rules.py SOURCE_DIR: scripts/check_pdf.py fails on what it promises to, from synthetic
input (no LaTeX run needed): a planted overfull table 12 pt too wide and a float too large for the
page fail, a 3 pt overfull line passes; "(s)" plurals, "nan" and "??" on a page fail, "NaN" and the
ordinary text of the report pass, as does a "nan" quoted from a refusal; a raw summary key in a LaTeX
source fails, one in code, a path, math or a value lookup passes."""
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
for p in problems:
    print("check_pdf_rules:", p)
print(f"check_pdf_rules: {len(problems)} problems")
sys.exit(1 if problems else 0)
