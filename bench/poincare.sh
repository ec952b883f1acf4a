#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# A Poincaré section against a SciPy peer in the same run: Hénon–Heiles at E = 1/12, section
# x = 0 with x' > 0, ORBITS orbits of CROSSINGS crossings at the tolerance TOL, by `lagrange
# poincare` on 1 thread and on all cores (the fastest of REPEATS runs each), and by SciPy's
# DOP853 (bench/poincare_scipy.py: solve_ivp with events, a Python right-hand side) from the same
# starts until the same times. Prints a Markdown table of wall time, crossings, the worst
# energy error relative to E, and the ratio of each time to lagrange's on 1 thread.
#   bench/poincare.sh [ORBITS] [CROSSINGS] [TOL] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
orbits=${1:-200}
crossings=${2:-100}
tolerance=${3:-1e-9}
repeats=${4:-3}
build=${LAGRANGE_BUILD:-build}
[ -x "$build/lagrange" ] || scripts/setup.sh
lagrange=$PWD/$build/lagrange
scene=$PWD/tests/scenes/henon_heiles.lag
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(poincare "$scene" --section "x = 0, x' > 0" --energy 0.08333333333333333 --orbits "$orbits"
      --crossings "$crossings" --tolerance "$tolerance")
# run THREADS: the fastest wall time of the repeats; the summary of the last run in $work/summary
run() {
  local best="" wall
  for _ in $(seq "$repeats"); do
    /usr/bin/env time -f "%e" -o "$work/time" "$lagrange" "${args[@]}" --threads "$1" -o "$work/section$1.csv" \
      2>"$work/summary"
    wall=$(tail -1 "$work/time")
    if [ -z "$best" ] || awk -v a="$wall" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$wall; fi
  done
  echo "$best"
}
one=$(run 1)
points=$(($(wc -l <"$work/section1.csv") - 1))
worst=$(sed -n 's/.*within \([^ ]*\) of E.*/\1/p' "$work/summary")
all=$(run "$(nproc)")
cmp -s "$work/section1.csv" "$work/section$(nproc).csv" || { echo "error: the thread counts wrote other bytes" >&2; exit 1; }
peer=$(/usr/bin/python3 bench/poincare_scipy.py "$work/section1.csv" "$tolerance")
read -r peer_wall peer_points peer_worst <<<"$peer"
echo "Hénon–Heiles, E = 1/12, $orbits orbits x $crossings crossings, tolerance $tolerance, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo
echo "| run | wall s | crossings | worst energy error / E | time / lagrange 1 thread |"
echo "|---|---:|---:|---:|---:|"
row() { awk -v l="$1" -v t="$2" -v c="$3" -v e="$4" -v b="$one" 'BEGIN { printf "| %s | %.3f | %d | %s | %.2f |\n", l, t, c, e, t / b }'; }
row "lagrange poincare, 1 thread" "$one" "$points" "$worst"
row "lagrange poincare, $(nproc) threads" "$all" "$points" "$worst"
row "SciPy solve_ivp DOP853 + events (Python rhs)" "$peer_wall" "$peer_points" "$peer_worst"
