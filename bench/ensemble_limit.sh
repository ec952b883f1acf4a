#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# `lagrange ensemble` against a hand-written DOP853 loop (build/bench/hand_loop, bench/hand_dop853.h)
# in the same run: the flip-time map of the equal-mass double pendulum
# (tests/scenes/ensemble_double_pendulum.lag) over theta, phi = -3.1..3.1:COUNT until t = UNTIL at
# the tolerance TOL, on 1 and 2 threads, the two sides taking turns, REPEATS times each (the fastest
# kept). Prints a Markdown table of points per second (over the integration alone, as each side
# reports it, and over the whole command's wall time for lagrange), the ratio to the hand loop, the
# DOP853 steps of each side (lagrange's include its error-estimate reruns, of one point in
# min(61, points/100), at TOL/1000), and the agreement of the flip times point by point.
#   bench/ensemble_limit.sh [COUNT] [UNTIL] [TOL] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
count=${1:-100}
until=${2:-10}
tolerance=${3:-1e-9}
repeats=${4:-5}
build=${LAGRANGE_BUILD:-build}
[ -x "$build/lagrange" ] || scripts/setup.sh
[ -x "$build/bench/hand_loop" ] || cmake --build "$build" --target hand_loop
lagrange=$PWD/$build/lagrange
hand=$PWD/$build/bench/hand_loop
scene=$PWD/tests/scenes/ensemble_double_pendulum.lag
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
points=$((count * count))
echo "flip-time map ${count}x${count} (${points} points), until t = $until, tolerance $tolerance, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg) at start"
echo
echo "| threads | lagrange points/s | hand loop points/s | lagrange / hand | lagrange wall points/s | lagrange steps | hand steps (+ reruns) | agreement (median, worst) |"
echo "|---:|---:|---:|---:|---:|---:|---:|---|"
for threads in 1 2; do
  best_engine="" best_wall="" best_hand=""
  for _ in $(seq "$repeats"); do
    start=$(date +%s.%N)
    "$lagrange" ensemble "$scene" --grid "theta=-3.1..3.1:$count, phi=-3.1..3.1:$count" --until "$until" \
      --tolerance "$tolerance" --measure flip_time --threads "$threads" -o "$work/engine.csv" 2>"$work/summary"
    end=$(date +%s.%N)
    wall=$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')
    seconds=$(sed -n 's/.* in \([0-9.e+-]*\) s (.*/\1/p' "$work/summary" | head -1)
    engine_steps=$(sed -n 's/.*; \([0-9]*\) integration steps.*/\1/p' "$work/summary" | head -1)
    read -r hand_seconds _ hand_steps rerun_steps < <("$hand" flip "$count" "$until" "$tolerance" "$threads" \
      "$work/hand.csv")
    awk -v a="$seconds" -v b="$best_engine" 'BEGIN { exit !(b == "" || a < b) }' && best_engine=$seconds
    awk -v a="$wall" -v b="$best_wall" 'BEGIN { exit !(b == "" || a < b) }' && best_wall=$wall
    awk -v a="$hand_seconds" -v b="$best_hand" 'BEGIN { exit !(b == "" || a < b) }' && best_hand=$hand_seconds
  done
  agreement=$(/usr/bin/python3 - "$work/engine.csv" "$work/hand.csv" <<'EOF'
import csv, math, statistics, sys
engine = list(csv.reader(open(sys.argv[1])))[1:]
hand = list(csv.reader(open(sys.argv[2])))[1:]
assert len(engine) == len(hand), "the two maps have different sizes"
differences, mismatched = [], 0
for a, b in zip(engine, hand):
    assert float(a[0]) == float(b[0]) and float(a[1]) == float(b[1]), f"other grid points: {a} {b}"
    u, v = float(a[2]), float(b[2])
    if math.isinf(u) and math.isinf(v):
        continue
    if math.isinf(u) != math.isinf(v) or math.isnan(u) or math.isnan(v):
        mismatched += 1
        continue
    differences.append(abs(u - v))
print(f"{statistics.median(differences):.2g}, {max(differences):.2g} over {len(differences)} flips"
      + (f"; {mismatched} points flip on one side only" if mismatched else ""))
EOF
)
  awk -v t="$threads" -v e="$best_engine" -v w="$best_wall" -v h="$best_hand" -v p="$points" -v es="$engine_steps" \
    -v hs="$hand_steps" -v rs="$rerun_steps" -v a="$agreement" \
    'BEGIN { printf "| %d | %.0f | %.0f | %.2f | %.0f | %d | %d (+ %d = %d) | %s |\n", t, p / e, p / h, h / e, p / w, es,
             hs, rs, hs + rs, a }'
done
echo
echo "(lagrange points/s: over the time lagrange reports for the ensemble's integration; wall: the whole"
echo "command, start-up included: parse, derive, compile or load the equations. lagrange / hand: the ratio"
echo "of points per second, above 1 when lagrange is faster. Steps: accepted DOP853 steps of all points; the
hand loop's reruns, of the points lagrange reruns for its error estimate, are counted but not timed.)"
