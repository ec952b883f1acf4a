#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Numeric normal modes beside scipy.linalg.eigh, in one run on this machine:
#  1. points per second for the double pendulum and a 6-mass chain (7 springs),
#     lagrange one point at a time and in batches, scipy.linalg.eigh(V, T) on the
#     same T and V (the first 20000 of the same random points), and the ratio;
#  2. error against run time for each numeric route over the double pendulum's sweep
#     m/M = 1e-16 … 1e16 (321 points): ours against a 60-digit CLN reference, scipy's
#     against a 50-digit mpmath one (as the peer ../shared/peers/dp_modes_accuracy_scipy.py);
#  3. that peer script itself (a private copy), its own per-call times beside our batch's.
# Times are thread CPU time (the machine is shared). Usage:
#   bench/modes.sh [points] [runs]        (LAGRANGE_BUILD=dir for another build)
# Needs Debian's python3-scipy and python3-mpmath (installed here if missing, as root
# or through sudo), and a build with bench/numeric_modes (scripts/setup.sh builds one).
set -euo pipefail
cd "$(dirname "$0")/.."
points=${1:-1000000}
runs=${2:-5}
build=${LAGRANGE_BUILD:-build}
python=/usr/bin/python3
if ! "$python" -c 'import scipy, mpmath, numpy' 2>/dev/null; then
    sudo_cmd=""
    [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
    $sudo_cmd apt-get install -y python3-scipy python3-mpmath >&2
fi
[ -x "$build/bench/numeric_modes" ] || cmake --build "$build" --target numeric_modes >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bench/numeric_modes" "$points" "$runs" all "$work" >"$work/ours.txt"
OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 "$python" - "$work" "$points" "$runs" <<'PY'
import os, sys, time
import numpy as np
import scipy, scipy.linalg as sla
import mpmath as mp

work, points, runs = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
lines = open(os.path.join(work, "ours.txt")).read().splitlines()
ours = {}
for line in lines[2:]:
    if not line.strip():
        break
    name, *rest = line.split()
    ours[name] = (" ".join(rest[:-2]), float(rest[-2]))
errors = []
for line in lines[lines.index(next(l for l in lines if l.startswith("route"))) + 1:]:
    parts = line.rsplit(None, 4)
    errors.append((parts[0].strip(), float(parts[1]), float(parts[2]), float(parts[3]), int(parts[4])))

def pendulum(p):
    M, m, l, g = p
    return (np.array([[(M + m) * l * l, m * l * l], [m * l * l, m * l * l]]),
            np.array([[(M + m) * g * l, 0.0], [0.0, m * g * l]]))

def chain(p):
    n = 6
    masses, springs = p[:n], p[n:]
    T = np.diag(masses)
    V = np.zeros((n, n))
    for i in range(n):
        V[i, i] = springs[i] + springs[i + 1]
        if i + 1 < n:
            V[i, i + 1] = V[i + 1, i] = -springs[i + 1]
    return T, V

def per_point(matrices, vectors):
    best = []
    for _ in range(3):
        start = time.thread_time_ns()
        for T, V in matrices:
            if vectors:
                sla.eigh(V, T)
            else:
                sla.eigh(V, T, eigvals_only=True)
        best.append((time.thread_time_ns() - start) / len(matrices))
    return sorted(best)[1]

scipy_ns = {}
for system, build in (("pendulum", pendulum), ("chain6", chain)):
    pts = np.loadtxt(os.path.join(work, system + ".txt"))
    matrices = [build(p) for p in pts]
    scipy_ns[system] = per_point(matrices, False)
    scipy_ns[system + "+modes"] = per_point(matrices, True)

print(f"numeric modes per second, one core (thread CPU time; lagrange: median of {runs} runs over {points} random "
      f"points; scipy {scipy.__version__} linalg.eigh(V, T) per call on the first 20000 of the same points)")
print(f"{'system':<36} {'lagrange route':<28} {'ns/point':>9} {'points/s':>10} {'scipy ns':>9} {'scipy pts/s':>11} {'ratio':>6}")
labels = {"pendulum": "double pendulum, ω", "pendulum+modes": "double pendulum, ω + modes",
          "chain6": "6-mass chain, ω", "chain6+modes": "6-mass chain, ω + modes"}
for key in ("pendulum", "pendulum+modes", "chain6", "chain6+modes"):
    for mode in ("single", "batch"):
        route, ns = ours[key + "/" + mode]
        peer = scipy_ns[key]
        print(f"{labels[key] + ' (' + mode + ')':<36} {route:<28} {ns:9.1f} {1e9 / ns:10.3g} {peer:9.0f} "
              f"{1e9 / peer:11.3g} {peer / ns:6.0f}")

# scipy on the sweep, against mpmath at 50 digits (the peer's reference formula)
sweep = np.loadtxt(os.path.join(work, "sweep.txt"))
worst, failed = 0.0, 0
start = time.thread_time_ns()
results = []
for p in sweep:
    T, V = pendulum(p)
    try:
        results.append(sla.eigh(V, T, eigvals_only=True))
    except (np.linalg.LinAlgError, ValueError):
        results.append(None)
elapsed = (time.thread_time_ns() - start) / len(sweep)
mp.mp.dps = 50
for p, lam in zip(sweep, results):
    M, m, l, g = (mp.mpf(float(x)) for x in p)
    a, b, c = M * l * l, 2 * (M + m) * g * l, (M + m) * g * g
    root = mp.sqrt(b * b - 4 * a * c)
    big = (b + root) / (2 * a)
    exact = [mp.sqrt(c / (a * big)), mp.sqrt(big)]
    if lam is None or not np.all(np.isfinite(lam)) or np.any(lam < 0):
        failed += 1
        continue
    for w2, ref in zip(np.sort(lam), exact):
        worst = max(worst, float(abs((mp.sqrt(mp.mpf(float(w2))) - ref) / ref)))

print()
print(f"double pendulum, m/M = 1e-16 ... 1e16 ({len(sweep)} points): worst relative error of ω and time per point")
print(f"{'route':<34} {'max rel error':>13} {'own bound':>10} {'ns/point':>10} {'failed':>7}")
for name, err, bound, ns, fails in errors:
    print(f"{'lagrange ' + name:<34} {err:13.3g} {bound:10.3g} {ns:10.1f} {fails:7d}")
print(f"{'scipy.linalg.eigh(V, T)':<34} {worst:13.3g} {'-':>10} {elapsed:10.1f} {failed:7d}")
PY

# 3. The peer script itself (../shared/peers/dp_modes_accuracy_scipy.py, in a private copy so
#    that the shared folder is left alone), in the same run: its own timing of scipy's
#    generalized solver on the double pendulum, against our batch time per point.
peer=../shared/peers/dp_modes_accuracy_scipy.py
if [ -f "$peer" ]; then
    mkdir -p "$work/peer"
    cp "$peer" "$(dirname "$peer")"/common.py "$work/peer/" 2>/dev/null || cp "$peer" "$work/peer/"
    (cd "$work/peer" && OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 "$python" "$(basename "$peer")" >peer.txt 2>&1) || true
    ours_ns=$(awk '$1 == "pendulum/batch" {print $(NF-1)}' "$work/ours.txt")
    echo
    echo "the peer script $(basename "$peer") (its own timing, wall time per call, median of 7), beside lagrange's batch:"
    grep "time per call" "$work/peer/peer.txt" |
        awk -v ours="$ours_ns" '{printf "  %-70s ratio %6.0f\n", $0, $(NF-1) * 1000 / ours}'
else
    echo
    echo "(the peer script $peer is not here: its own timing left out)"
fi
