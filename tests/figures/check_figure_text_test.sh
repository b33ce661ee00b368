#!/usr/bin/env bash
# check_figure_text.py refuses a figure with a word off the canvas and two words drawn over each other,
# naming them, and with --remove-failing removes that figure (PDF and PNG) and keeps a clean one.
#   tests/figures/check_figure_text_test.sh WORKDIR
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=${1:?usage: $0 WORKDIR}
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
figure() {  # NAME LABELS...: a small plot with the given gnuplot label commands, as NAME.pdf and NAME.png
    local name=$1; shift
    for term in "pdfcairo size 3in,2in" "pngcairo size 300,200"; do
        ext=${term%%cairo*}
        printf 'set terminal %s\nset output "%s.%s"\n%s\nplot x notitle\n' "$term" "$name" "$ext" "$(printf '%s\n' "$@")" | gnuplot || exit 1
    done
}
figure bad 'set label "OVERLAPPING" at graph 0.5, graph 0.5' 'set label "OVERLAPPING" at graph 0.52, graph 0.5' \
           'set label "OFFCANVAS" at screen 0.97, screen 0.5'
figure good 'set label "APART" at graph 0.2, graph 0.5' 'set label "ALSO" at graph 0.7, graph 0.5'
fail=0
python3 "$here/check_figure_text.py" good.pdf >out.txt || { echo "FAIL: a clean figure was refused:"; cat out.txt; fail=1; }
python3 "$here/check_figure_text.py" --remove-failing good.pdf bad.pdf >out.txt && { echo "FAIL: the planted figure passed"; fail=1; }
grep -q "'OF' leaves the canvas" out.txt || { echo "FAIL: the word off the canvas is not named:"; cat out.txt; fail=1; }
grep -q "'OVERLAPPING' and 'OVERLAPPING' overlap" out.txt || { echo "FAIL: the overlap is not named:"; cat out.txt; fail=1; }
[ -e bad.pdf ] || [ -e bad.png ] && { echo "FAIL: --remove-failing kept the failing figure"; fail=1; }
[ -s good.pdf ] && [ -s good.png ] || { echo "FAIL: --remove-failing removed the clean figure"; fail=1; }
[ $fail = 0 ] && echo "ok: refused and removed the planted figure, kept the clean one"
exit $fail
