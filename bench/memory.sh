#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Run time and peak memory (GNU time's maximum resident set size) of the command
# line for (1) the planar N-link chain, every mass and length distinct: equations
# (and, with values, the numeric modes; the symbolic characteristic polynomial is
# left to the budget), and (2) a numeric sweep of the double pendulum with 1e4, 1e5
# and 1e6 points, streamed to a file. Prints one table.
#   bench/memory.sh [max_N] [sweep_max_points]
# Needs a build (scripts/setup.sh) and GNU time (Debian package `time`).
set -euo pipefail
cd "$(dirname "$0")/.."
max_n=${1:-12}
max_points=${2:-1000000}
build=${LAGRANGE_BUILD:-build}
[ -x /usr/bin/time ] || LAGRANGE_WITH_TIME=1 LAGRANGE_SETUP_ONLY=1 scripts/setup.sh
[ -x "$build/lagrange" ] || scripts/setup.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

chain() { # N -> scene text
  python3 - "$1" <<'PY'
import sys
n = int(sys.argv[1])
x, y, pts = [], [], []
for i in range(1, n + 1):
    x.append(f"l{i}*sin(q{i})"); y.append(f"-l{i}*cos(q{i})")
    pts.append(f"point P{i} mass m{i} at ({' + '.join(x)}, {' + '.join(y)})")
print("parameters g " + " ".join(f"m{i} l{i}" for i in range(1, n + 1)))
print("coordinates " + " ".join(f"q{i}" for i in range(1, n + 1)))
print("\n".join(pts))
print("gravity g along (0, -1)")
print("equilibrium " + ", ".join(f"q{i} = 0" for i in range(1, n + 1)))
print("values g = 9.81, " + ", ".join(f"m{i} = {1 + i / 10}, l{i} = {1 + i / 20}" for i in range(1, n + 1)))
PY
}

measure() { # label, args... -> "seconds peak_MB exit"
  local label=$1; shift
  set +e
  /usr/bin/time -f "%e %M" -o "$work/time.txt" "$@" >"$work/out.txt" 2>"$work/err.txt"
  local code=$?
  set -e
  read -r seconds kb <"$work/time.txt" || true
  awk -v l="$label" -v s="$seconds" -v k="$kb" -v c="$code" 'BEGIN { printf "%-34s %9s %9.1f %5s\n", l, s, k / 1024, c }'
}

printf "%-34s %9s %9s %5s\n" "run" "seconds" "peak_MB" "exit"
for n in $(seq 2 "$max_n"); do
  chain "$n" >"$work/chain$n.lag"
  measure "chain N=$n equations" "$build/lagrange" "$work/chain$n.lag" --want equations -o "$work/eq.txt"
done
for n in 4 8 "$max_n"; do
  measure "chain N=$n equations+numeric" "$build/lagrange" "$work/chain$n.lag" --want equations,characteristic,numeric \
    -o "$work/eqn.txt"
done
points=10000
while [ "$points" -le "$max_points" ]; do
  measure "sweep $points points (double pend.)" "$build/lagrange" examples/double_pendulum.lag \
    --sweep "m=1e-16..1e16:$points:log" -o "$work/sweep.txt"
  points=$((points * 10))
done
