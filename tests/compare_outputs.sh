#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Records or compares the output of every example in every format, byte for byte:
# text, LaTeX and JSON of the default run, and the LaTeX report (its figures, PDFs with
# a creation date, are left out). A refactoring that
# changes no results leaves the recorded outputs identical.
#   tests/compare_outputs.sh record DIR [BINARY]    write the outputs into DIR
#   tests/compare_outputs.sh compare DIR [BINARY]   exit 1 and name each file that differs
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:?record or compare}
dir=${2:?folder of recorded outputs}
binary=${3:-build/lagrange}

produce() { # $1: output folder
    mkdir -p "$1"
    for scene in examples/*.lag; do
        name=$(basename "$scene" .lag)
        for format in text latex json; do
            "$binary" "$scene" --format "$format" >"$1/$name.$format" 2>&1 || echo "exit $?" >>"$1/$name.$format"
        done
        "$binary" report "$scene" -o "$1/$name.report.tex" >/dev/null 2>&1 || echo "exit $?" >"$1/$name.report.tex"
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
