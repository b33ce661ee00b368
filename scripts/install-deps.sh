#!/usr/bin/env bash
# Install the Debian packages a target needs, and only those that are missing.
#   scripts/install-deps.sh [build|figures|paper]...   (default: build)
# build   : compiler, CMake, the header libraries, GoogleTest, Open MPI (the ctest label mpi), gnuplot
#           and pdftotext (the figure test renders every script and checks its text, so `make test`
#           needs them), and matplotlib, for the report's two overview figures alone
#           (scripts/overview_figures.py; ctest report.overview_figures draws them on a fixture)
# figures : build + numpy (the numpy peer of make bench)
# paper   : figures + TeX Live and latexmk
set -euo pipefail

build=(g++ cmake make pkg-config git libeigen3-dev libboost-dev libtomlplusplus-dev
       libcli11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev libsleef-dev libqhull-dev
       libopenmpi-dev openmpi-bin gnuplot-nox fonts-dejavu-core poppler-utils python3 python3-sympy
       python3-gmpy2 python3-matplotlib)
figures=("${build[@]}" python3-numpy)
paper=("${figures[@]}" latexmk texlive-latex-base texlive-latex-recommended
       texlive-latex-extra texlive-fonts-recommended)

want=()
for target in "${@:-build}"; do
  case "$target" in
    build)   want+=("${build[@]}") ;;
    figures) want+=("${figures[@]}") ;;
    paper)   want+=("${paper[@]}") ;;
    *) echo "install-deps.sh: unknown target '$target' (allowed: build, figures, paper)" >&2; exit 2 ;;
  esac
done

missing=()
for pkg in $(printf '%s\n' "${want[@]}" | sort -u); do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "install-deps.sh: installing ${missing[*]}" >&2
sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps.sh: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
