#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Records or compares the output of every example, test scene and fuzz seed in every
# format, byte for byte: text, LaTeX and JSON of the default run, and the LaTeX report
# (its figures, PDFs with a creation date, are left out), with the exit code where it is
# not 0. A refactoring that changes no results leaves the recorded outputs identical.
#   scripts/compare_outputs.sh record DIR [BINARY]    write the outputs into DIR
#   scripts/compare_outputs.sh compare DIR [BINARY]   exit 1 and name each file that differs
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:?record or compare}
dir=${2:?folder of recorded outputs}
binary=${3:-build/lagrange}

produce() { # $1: output folder
    mkdir -p "$1"
    for scene in examples/*.lag tests/scenes/*.lag tests/fuzz_regressions/*.lag fuzz/seeds/*; do
        name=$(dirname "$scene" | tr / _)_$(basename "$scene" .lag)
        for format in text latex json; do
            timeout 60 "$binary" "$scene" --format "$format" >"$1/$name.$format" 2>&1 || echo "exit $?" >>"$1/$name.$format"
        done
        timeout 60 "$binary" report "$scene" -o "$1/$name.report.tex" >/dev/null 2>&1 || echo "exit $?" >"$1/$name.report.tex"
    done
}

case "$mode" in
record) produce "$dir" ;;
compare)
    fresh=$(mktemp -d)
    trap 'rm -rf "$fresh"' EXIT
    produce "$fresh"
    if diff -rq -x "*.pdf" "$dir" "$fresh"; then
        echo "compare_outputs: all $(ls "$dir" | grep -vc "\.pdf$") outputs identical"
    else
        exit 1
    fi
    ;;
*) echo "usage: $0 record|compare DIR [BINARY]" >&2; exit 2 ;;
esac
