#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The reduced bicycle's critical speeds beside numpy, in one run on this machine:
# `lagrange --want critical` on examples/bicycle_reduced.lag (the whole run: reading the
# scene, the symbolic linearization, 401 eigenvalue points and the refinement of both
# crossings) against a numpy/scipy script that does the same numerically from the
# benchmark's matrices written out (eig of the 4 × 4 companion matrix on the same grid,
# brentq on the largest real part of the weave pair and of the real eigenvalues). Prints
# the best wall time of each over RUNS runs, their ratio, and both answers.
# Usage: bench/critical_speeds.sh [runs]        (LAGRANGE_BUILD=dir for another build)
# Needs Debian's python3-numpy and python3-scipy.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
build=${LAGRANGE_BUILD:-build}
python=/usr/bin/python3
[ -x "$build/lagrange" ] || cmake --build "$build" --target lagrange_cli >&2
best_ours=1e9
for _ in $(seq "$runs"); do
    start=$(date +%s.%N)
    "$build/lagrange" --want critical --format json examples/bicycle_reduced.lag >/tmp/critical_speeds.$$.json
    end=$(date +%s.%N)
    best_ours=$("$python" -c "print(min($best_ours, $end - $start))")
done
ours=$("$python" -c "import json; d = json.load(open('/tmp/critical_speeds.$$.json'))['critical']['crossings']; print(' '.join(repr(c['value']) for c in d))")
rm -f /tmp/critical_speeds.$$.json
OPENBLAS_NUM_THREADS=1 "$python" - "$runs" "$best_ours" "$ours" <<'PY'
import sys, time
import numpy as np
from scipy.optimize import brentq

runs, best_ours, ours = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
# Meijaard et al. (2007), eq. (5.4)
M = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1 = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0 = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2 = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])
g = 9.81
Minv = np.linalg.inv(M)

def eigenvalues(v):
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Minv @ (g * K0 + v * v * K2), -Minv @ (v * C1)]])
    return np.linalg.eigvals(A)

def kth_real(v, k):
    return np.sort(eigenvalues(v).real)[::-1][k]

def run():
    grid = np.linspace(0, 10, 401)
    parts = np.array([np.sort(eigenvalues(v).real)[::-1] for v in grid])
    found = []
    for k in range(4):
        for i in range(400):
            a, b = parts[i, k], parts[i + 1, k]
            if abs(a) > 1e-12 and abs(b) > 1e-12 and (a > 0) != (b > 0):
                root = brentq(kth_real, grid[i], grid[i + 1], args=(k,), xtol=1e-15)
                if all(abs(f - root) > 1e-9 for f in found):
                    found.append(root)
    return sorted(found)

best = 1e9
for _ in range(runs):
    start = time.perf_counter()
    theirs = run()
    best = min(best, time.perf_counter() - start)
print(f"lagrange (whole run, symbolic linearization included): {best_ours:.4f} s  speeds {ours}")
print(f"numpy + scipy brentq (matrices given):                 {best:.4f} s  speeds {' '.join(repr(x) for x in theirs)}")
print(f"ratio lagrange / numpy: {best_ours / best:.2f}")
PY
