#!/usr/bin/env bash
# Render gnuplot figure scripts and check them.
#
#   tests/figures/render_figures.sh [--only-available] [--check-later LIST] RESULTS_DIR OUT_DIR SCRIPT...
#
# Runs, from the repository root (two levels above this file, so that the scripts'
# `load 'figures/common.gp'` works), for each SCRIPT:
#     gnuplot -e "results='RESULTS_DIR'; out='OUT_DIR'" SCRIPT
# and fails (exit 1, naming the script) if gnuplot exits non-zero, if it prints
# anything containing "warning" (any case) on stderr, or if OUT_DIR/NAME.pdf or
# OUT_DIR/NAME.png (NAME = script basename without .gp) is missing or empty, or if
# a word of the PDF leaves the canvas or overlaps another (check_figure_text.py;
# needs pdftotext from poppler-utils, which scripts/install-deps.sh figures installs).
# All scripts are tried; the exit status is 1 if any failed, 2 on a usage error.
# --check-later LIST appends each rendered PDF to the file LIST instead of checking its text, for one
# check_figure_text.py --remove-failing over all of them (make figures: one Python start, not one per figure).
# With GEOMINT_RENDER_PROGRESS="TOTAL START FILE" (make figures: TOTAL figures to render from START, seconds
# since the epoch, FILE listing those rendered so far), each "ok" line also says how many of them are done,
# the time so far and an estimate of the time left at that pace.
# --only-available skips (and names) each script whose input CSVs, as its
# "# Input:" line lists them, are not all in RESULTS_DIR: a run of some of the
# studies (--study) renders the figures of those studies only.
set -u

only_available=0
check_later=""
while [ $# -gt 0 ]; do
    case "$1" in
        --only-available) only_available=1; shift ;;
        --check-later) [ $# -ge 2 ] || { echo "render_figures: --check-later needs a file" >&2; exit 2; }
                       check_later=$2; shift 2 ;;
        *) break ;;
    esac
done

if [ $# -lt 3 ]; then
    echo "usage: $0 RESULTS_DIR OUT_DIR SCRIPT..." >&2
    exit 2
fi
for tool in gnuplot pdftotext; do
    if ! command -v $tool >/dev/null 2>&1; then
        echo "render_figures: $tool not found in PATH (scripts/install-deps.sh figures)" >&2
        exit 1
    fi
done

# Paths are relative to the caller's directory; make them absolute before cd.
abspath() { case "$1" in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
[ -z "$check_later" ] || check_later=$(abspath "$check_later")
results=$(abspath "$1")
out=$(abspath "$2")
shift 2
for p in "$results" "$out"; do
    case "$p" in *\'*) echo "render_figures: path must not contain a single quote: $p" >&2; exit 2 ;; esac
done
if [ ! -d "$results" ]; then
    echo "render_figures: results directory not found: $results" >&2
    exit 1
fi
scripts=()
for s in "$@"; do scripts+=("$(abspath "$s")"); done

# The CSVs named on a script's "# Input:" line that are missing from $results
# (a <placeholder> in a name matches anything).
missing_inputs() {
    local line f pattern
    line=$(grep -m1 '^# Input:' "$1") || return 0
    for f in $(printf '%s\n' "$line" | grep -o '[A-Za-z0-9_<>-]*\.csv'); do
        pattern=$(printf '%s' "$f" | sed 's/<[^>]*>/*/g')
        compgen -G "$results/$pattern" >/dev/null || printf '%s ' "$f"
    done
}

# " [k/TOTAL, T s so far, about L s left]" after a figure rendered under GEOMINT_RENDER_PROGRESS (above);
# nothing without it. (Bash arithmetic in milliseconds: no program started.)
progress() {
    [ -n "${GEOMINT_RENDER_PROGRESS:-}" ] || return 0
    local total start file done_ now ms left
    read -r total start file <<< "$GEOMINT_RENDER_PROGRESS"
    [ -n "$file" ] && [ "$total" -gt 0 ] 2>/dev/null || return 0
    printf '%s\n' "$1" >> "$file"                  # (one short line: an atomic append)
    mapfile -t done_ < "$file"
    now=${EPOCHREALTIME/[.,]/}; start=${start/./}; start=${start:0:${#now}}
    ms=$(( (now - start) / 1000 )); (( ms < 0 )) && ms=0
    left=$(( ms * (total - ${#done_[@]}) / ${#done_[@]} )); (( left < 0 )) && left=0
    printf ' [%d/%d, %d.%d s so far, about %d.%d s left]' "${#done_[@]}" "$total" $((ms / 1000)) $((ms % 1000 / 100)) \
        $((left / 1000)) $((left % 1000 / 100))
}

# (make figures runs this once per figure: no program is started here that a shell expansion can replace)
case "${BASH_SOURCE[0]}" in */*) here=${BASH_SOURCE[0]%/*} ;; *) here=. ;; esac
root=$(cd "$here/../.." && pwd)
cd "$root" || exit 1
[ -d "$out" ] || mkdir -p "$out" || exit 1
exec 3>&1                                          # (gnuplot's stdout, while its stderr is captured)

failed=()
for script in "${scripts[@]}"; do
    name=${script##*/}; name=${name%.gp}
    why=""
    if [ ! -f "$script" ]; then
        why="script not found"
    elif [ $only_available -eq 1 ] && missing=$(missing_inputs "$script") && [ -n "$missing" ]; then
        echo "skip $name: no ${missing% } in $results (its study did not run)"
        continue
    else
        rm -f "$out/$name.pdf" "$out/$name.png"        # no stale figure may pass the check
        err=$(gnuplot -e "results='$results'; out='$out'" "$script" 2>&1 >&3 3>&-)
        rc=$?
        if [ -n "$err" ]; then printf '%s\n' "$err" | sed "s|^|  $name: |" >&2; fi
        if [ $rc -ne 0 ]; then
            why="gnuplot exited with status $rc"
        elif [[ ${err,,} == *warning* ]]; then
            why="gnuplot printed a warning"
        else
            for ext in pdf png; do
                [ -s "$out/$name.$ext" ] || why="${why:+$why; }$out/$name.$ext missing or empty"
            done
            if [ -z "$why" ] && [ -n "$check_later" ]; then
                printf '%s\n' "$out/$name.pdf" >> "$check_later"   # (one short line: an atomic append)
            elif [ -z "$why" ] && ! err=$(python3 tests/figures/check_figure_text.py "$out/$name.pdf"); then
                printf '%s\n' "$err" | sed "s|^|  $name: |" >&2
                why="text off the canvas or overlapping"
            fi
        fi
    fi
    if [ -n "$why" ]; then
        echo "FAIL $name ($script): $why" >&2
        failed+=("$name")
    else
        echo "ok   $name -> $out/$name.pdf, $out/$name.png$(progress "$name")"
    fi
done

if [ ${#failed[@]} -gt 0 ]; then
    echo "render_figures: ${#failed[@]} of ${#scripts[@]} failed: ${failed[*]}" >&2
    exit 1
fi
