#!/usr/bin/env python3
"""check_pdf_rules.py SOURCE_DIR: scripts/check_pdf.py fails on what it promises to, from synthetic
input (no LaTeX run needed): a planted overfull table 12 pt too wide and a float too large for the
page fail, a 3 pt overfull line passes; "(s)" plurals, "nan" and "??" on a page fail, "NaN" and the
ordinary text of the report pass."""
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
if not check_pdf.text_problems(["no contents here"]):
    problems.append("a report without contents and ledger in front passes")
for p in problems:
    print("check_pdf_rules:", p)
print(f"check_pdf_rules: {len(problems)} problems")
sys.exit(1 if problems else 0)
