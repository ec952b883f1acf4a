#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# A Poincaré section against two peers in the same run: Hénon–Heiles at E = 1/12, section
# x = 0 with x' > 0, ORBITS orbits of CROSSINGS crossings at the tolerance TOL, by `lagrange
# poincare` on 1 thread and on all cores (the fastest of REPEATS runs each); by the hand-written
# DOP853 loop (build/bench/hand_loop poincare, bench/hand_dop853.h: the same tableau and step
# control, a hand-written right-hand side, the crossings located on the dense output) from the
# same starts, for as many crossings or until t = 1000 as `poincare`, taking turns with it on as
# many threads; and by SciPy's DOP853 (bench/poincare_scipy.py: solve_ivp with events, a Python
# right-hand side) from the same starts until the same times. Prints a Markdown table of time,
# crossings, DOP853 steps, the worst energy error relative to E, the ratio of each time to
# lagrange's on 1 thread and of lagrange's to the hand loop's on as many threads; then how far the
# hand loop's crossings are from lagrange's (chaotic orbits part by the rounding of the two
# right-hand sides).
#   bench/poincare.sh [ORBITS] [CROSSINGS] [TOL] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
orbits=${1:-200}
crossings=${2:-100}
tolerance=${3:-1e-9}
repeats=${4:-3}
build=${LAGRANGE_BUILD:-build}
[ -x "$build/lagrange" ] || scripts/setup.sh
[ -x "$build/bench/hand_loop" ] || cmake --build "$build" --target hand_loop
lagrange=$PWD/$build/lagrange
hand=$PWD/$build/bench/hand_loop
scene=$PWD/tests/scenes/henon_heiles.lag
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(poincare "$scene" --section "x = 0, x' > 0" --energy 0.08333333333333333 --orbits "$orbits"
      --crossings "$crossings" --tolerance "$tolerance")
faster() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(b == "" || a < b) }'; }
# run THREADS: prints "wall orbits hand" of the fastest of the repeats: the whole command's wall time,
# the time `poincare` reports for its orbits (start-up left out), and the hand loop's, which takes
# its turn after each run of lagrange; the summary of lagrange's last run is left in $work/summary.
run() {
  local wall seconds hand_seconds best="" best_seconds="" best_hand=""
  for _ in $(seq "$repeats"); do
    /usr/bin/env time -f "%e" -o "$work/time" "$lagrange" "${args[@]}" --threads "$1" -o "$work/section$1.csv" \
      2>"$work/summary"
    wall=$(tail -1 "$work/time")
    seconds=$(sed -n 's/.* in \([0-9.e+-]*\) s;.*/\1/p' "$work/summary" | head -1)
    read -r hand_seconds _ _ < <("$hand" poincare "$work/section1.csv" "$tolerance" "$crossings" 1000 "$1" \
      "$work/hand$1.csv")
    if faster "$wall" "$best"; then best=$wall; fi
    if faster "$seconds" "$best_seconds"; then best_seconds=$seconds; fi
    if faster "$hand_seconds" "$best_hand"; then best_hand=$hand_seconds; fi
  done
  echo "$best $best_seconds $best_hand"
}
# The hand loop starts from lagrange's first rows: one run of lagrange writes them first.
"$lagrange" "${args[@]}" --threads 1 -o "$work/section1.csv" 2>/dev/null
read -r one one_seconds hand_one <<<"$(run 1)"
points=$(($(wc -l <"$work/section1.csv") - 1))
worst=$(sed -n 's/.*within \([^ ]*\) of E.*/\1/p' "$work/summary")
steps=$(sed -n 's/.*; \([0-9]*\) integration steps.*/\1/p' "$work/summary" | head -1)
read -r all all_seconds hand_all <<<"$(run "$(nproc)")"
cmp -s "$work/section1.csv" "$work/section$(nproc).csv" || { echo "error: the thread counts wrote other bytes" >&2; exit 1; }
read -r _ hand_points hand_steps < <("$hand" poincare "$work/section1.csv" "$tolerance" "$crossings" 1000 1 "$work/hand.csv")
comparison=$(/usr/bin/python3 - "$work/section1.csv" "$work/hand.csv" <<'EOF'
import csv, statistics, sys
def read(name):
    orbits = {}
    for row in list(csv.reader(open(name)))[1:]:
        orbits.setdefault(int(row[0]), []).append([float(v) for v in row[1:]])
    return orbits
engine, hand = read(sys.argv[1]), read(sys.argv[2])
assert engine.keys() == hand.keys(), "other orbits"
def energy(x, y, vx, vy):
    return 0.5 * (vx * vx + vy * vy) + 0.5 * (x * x + y * y) + x * x * y - y ** 3 / 3
e = energy(*engine[0][0][1:])
worst_energy, differences, first_ten, close = 0.0, [], [], 0
for k in engine:
    for p in hand[k]:
        worst_energy = max(worst_energy, abs(energy(*p[1:]) - e) / e)
    for i, (a, b) in enumerate(zip(engine[k], hand[k])):
        d = max(abs(u - v) for u, v in zip(a, b))
        differences.append(d)
        close += d <= 1e-8
        if i < 10:
            first_ten.append(d)
print(f"{worst_energy:.3g}|{len(differences)} crossings side by side, {close} ({100 * close / len(differences):.1f}%) "
      f"within 1e-8 in (t, x, y, x', y'), median difference {statistics.median(differences):.2g}; over the "
      f"first 10 crossings of every orbit the worst is {max(first_ten):.2g}")
EOF
)
hand_worst=${comparison%%|*}
read -r peer_wall peer_points peer_worst <<<"$(/usr/bin/python3 bench/poincare_scipy.py "$work/section1.csv" "$tolerance")"
echo "Hénon–Heiles, E = 1/12, $orbits orbits x $crossings crossings, tolerance $tolerance, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo
echo "| run | s | crossings | steps | worst energy error / E | time / lagrange 1 thread | lagrange / hand loop |"
echo "|---|---:|---:|---:|---:|---:|---:|"
row() {
  awk -v l="$1" -v t="$2" -v c="$3" -v s="$4" -v e="$5" -v b="$one" -v h="$6" \
    'BEGIN { printf "| %s | %.3f | %d | %s | %s | %.2f | %s |\n", l, t, c, s, e, t / b,
             h == "" ? "-" : sprintf("%.2f", t / h) }'
}
row "lagrange poincare, 1 thread, whole command" "$one" "$points" "$steps" "$worst" "$hand_one"
row "lagrange poincare, 1 thread, orbits" "$one_seconds" "$points" "$steps" "$worst" "$hand_one"
row "lagrange poincare, $(nproc) threads, whole command" "$all" "$points" "$steps" "$worst" "$hand_all"
row "lagrange poincare, $(nproc) threads, orbits" "$all_seconds" "$points" "$steps" "$worst" "$hand_all"
row "hand-written DOP853 loop, 1 thread" "$hand_one" "$hand_points" "$hand_steps" "$hand_worst" "$hand_one"
row "hand-written DOP853 loop, $(nproc) threads" "$hand_all" "$hand_points" "$hand_steps" "$hand_worst" "$hand_all"
row "SciPy solve_ivp DOP853 + events (Python rhs)" "$peer_wall" "$peer_points" "-" "$peer_worst" ""
echo
echo "(whole command: wall time, start-up included; orbits: the time \`poincare\` reports for its orbits.)"
echo "The hand loop against lagrange: ${comparison#*|}."
