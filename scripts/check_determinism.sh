#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Byte-identical output with address-space randomization on: runs every example, test
# scene, fuzz seed and fuzz regression RUNS times (default 5, each a separate process,
# so each with its own address layout) in every format (text, latex, json, and the
# report's .tex), and exits 1 naming each scene and format whose bytes differ.
#   scripts/check_determinism.sh [BUILD_DIR]      (RUNS=5 JOBS=2 by default)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
cli=$build/lagrange
[ -x "$cli" ] || { echo "check_determinism: no $cli (build the target lagrange_cli)" >&2; exit 2; }
runs=${RUNS:-5}
jobs=${JOBS:-2}
if [ "$(cat /proc/sys/kernel/randomize_va_space 2>/dev/null || echo 0)" = 0 ]; then
    echo "check_determinism: warning: address-space randomization is off on this machine" >&2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

scenes=()
for f in "$root"/examples/*.lag "$root"/tests/scenes/*.lag "$root"/fuzz/seeds/* "$root"/tests/fuzz_regressions/*.lag; do
    [ -f "$f" ] && scenes+=("$f")
done

# One scene and format: RUNS processes, each one's exit code, standard output and
# standard error (or the .tex) hashed; prints "SCENE FORMAT" when they are not all one.
one() {
    local scene=$1 format=$2 i dir hashes=""
    for ((i = 0; i < runs; i++)); do
        dir=$(mktemp -d "$work/run.XXXXXX")
        if [ "$format" = report ]; then
            (cd "$dir" && timeout 120 "$cli" report "$scene" -o report.tex >/dev/null 2>err; echo "exit $?" >>err) || true
            hashes+="$(cat "$dir/report.tex" "$dir/err" 2>/dev/null | sha1sum)"$'\n'
        else
            (cd "$dir" && timeout 120 "$cli" "$scene" --format "$format" >out 2>err; echo "exit $?" >>err) || true
            hashes+="$(cat "$dir/out" "$dir/err" | sha1sum)"$'\n'
        fi
        # A crash (a signal: exit 128 + N) fails too, even when every run crashes alike.
        if grep -qE '^exit (1(2[89]|[3-9][0-9])|2[0-9][0-9])$' "$dir/err"; then
            echo "${scene#"$root"/} $format crashed: $(tail -1 "$dir/err")"
        fi
        rm -rf "$dir"
    done
    if [ "$(printf '%s' "$hashes" | sort -u | wc -l)" -ne 1 ]; then
        echo "${scene#"$root"/} $format"
    fi
}
export -f one
export cli runs work root

start=$SECONDS
differ=$(for s in "${scenes[@]}"; do for f in text latex json report; do printf '%s\0%s\0' "$s" "$f"; done; done |
    xargs -0 -n 2 -P "$jobs" bash -c 'one "$0" "$1"' | sort)
elapsed=$((SECONDS - start))
if [ -n "$differ" ]; then
    echo "check_determinism: these differ from run to run, or crashed ($runs runs, ${elapsed}s):"
    echo "$differ" | sed 's/^/  /'
    exit 1
fi
echo "check_determinism: ${#scenes[@]} scenes x 4 formats x $runs runs identical (${elapsed}s)"
