#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The symbolic-scaling table: the characteristic polynomial det(V − W T) of the planar
# N-link chain, every mass and length distinct, N = 2..max_N, ours (bench/characteristic_scaling:
# the determinant alone, and the whole stage: made primitive with factored coefficients)
# beside SymPy's Matrix.det(method='berkowitz') and det() (Bareiss) + Poly(., W) on the same
# matrices (the peer script ../shared/peers/chain_scaling_sympy.py, stages charpoly_berkowitz
# and charpoly_bareiss), in the same run, with the ratios.
#   bench/characteristic_scaling.sh [max_N] [sympy_limit_seconds]
# Needs a build (scripts/setup.sh) and python3 with sympy (Debian: python3-sympy).
set -euo pipefail
cd "$(dirname "$0")/.."
max_n=${1:-7}
limit=${2:-120}
peers=${LAGRANGE_PEERS:-../shared/peers}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
build=${LAGRANGE_BUILD:-build}
[ -x "$build/bench/characteristic_scaling" ] || scripts/setup.sh
"$build/bench/characteristic_scaling" "$max_n" 3 >"$work/ours.txt"
cp "$peers"/common.py "$peers"/chain_scaling_sympy.py "$work/"
python3 - "$work" "$max_n" "$limit" <<'PY'
import json, os, subprocess, sys
work, max_n, limit = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
ours, notes = {}, []
for line in open(os.path.join(work, "ours.txt")).read().splitlines()[1:]:
    if not line.split()[0].isdigit():
        notes.append(line)  # the cubic's closed-form frequencies, after the table
        continue
    n, det, full, terms = line.split()
    ours[int(n)] = (float(det), float(full), int(terms))
peer = {}
for stage in ("charpoly_berkowitz", "charpoly_bareiss"):
    for n in range(2, max_n + 1):
        reps = 3 if n <= 5 else 1
        out = subprocess.run([sys.executable, "chain_scaling_sympy.py", "--child", str(n), stage, str(reps),
                              str(limit)], cwd=work, capture_output=True, text=True)
        rows = [json.loads(l) for l in out.stdout.splitlines() if l.startswith("{")]
        if not rows or rows[-1].get("timeout"):
            break  # larger N take longer still
        peer[(stage, n)] = rows[-1]["median"]
import sympy
print(f"characteristic polynomial det(V - W T) of the planar N-link chain, all masses and lengths distinct")
print(f"lagrange: median of 3 (det: minor expansion; stage: + primitive part, factored coefficients);")
print(f"SymPy {sympy.__version__}: det(method='berkowitz') / det() (Bareiss) + Poly(., W), median of up to 3, "
      f"limit {limit:.0f} s")
print(f"{'N':>3} {'terms':>7} {'det_s':>9} {'stage_s':>9} {'berkowitz_s':>12} {'bareiss_s':>10} "
      f"{'berk/det':>9} {'berk/stage':>10} {'bareiss/stage':>13}")
def cell(v, width):
    return f"{v:{width}.4f}" if v is not None else f"{'>' + str(int(limit)):>{width}}"
def ratio(a, b, width):
    return f"{a / b:{width}.1f}" if a is not None and b else f"{'-':>{width}}"
for n in sorted(ours):
    det, full, terms = ours[n]
    b, r = peer.get(("charpoly_berkowitz", n)), peer.get(("charpoly_bareiss", n))
    print(f"{n:3d} {terms:7d} {det:9.4f} {full:9.4f} {cell(b, 12)} {cell(r, 10)} "
          f"{ratio(b, det, 9)} {ratio(b, full, 10)} {ratio(r, full, 13)}")
for note in notes:
    print("lagrange: " + note)
PY
