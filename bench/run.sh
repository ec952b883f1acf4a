#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Runs the N-link chain benchmark beside SymPy's LagrangesMethod (the peer script
# in ../shared/peers, stage `eom`) on the same machine, in the same run, and prints
# one table: N, our median, SymPy's median, and the ratio.
#   bench/run.sh [max_N] [sympy_limit_seconds]
# Needs a build (scripts/setup.sh) and python3 with sympy (Debian: python3-sympy).
set -euo pipefail
cd "$(dirname "$0")/.."
max_n=${1:-12}
limit=${2:-120}
peers=${LAGRANGE_PEERS:-../shared/peers}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
build=${LAGRANGE_BUILD:-build}
[ -x "$build/bench/chain_equations" ] || scripts/setup.sh
"$build/bench/chain_equations" "$max_n" 7 >"$work/ours.txt"
cp "$peers"/common.py "$peers"/chain_scaling_sympy.py "$work/"
python3 - "$work" "$max_n" "$limit" <<'PY'
import json, os, subprocess, sys
work, max_n, limit = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
ours = {}
for line in open(os.path.join(work, "ours.txt")).read().splitlines()[1:]:
    n, med, mn, terms = line.split()
    ours[int(n)] = float(med) / 1000.0
peer = {}
skip = False
for n in range(2, max_n + 1):
    if skip:
        break
    reps = 3 if n <= 6 else 1
    out = subprocess.run([sys.executable, "chain_scaling_sympy.py", "--child", str(n), "eom", str(reps), str(limit)],
                         cwd=work, capture_output=True, text=True)
    rows = [json.loads(l) for l in out.stdout.splitlines() if l.startswith("{")]
    if not rows or rows[-1].get("timeout"):
        skip = True
        continue
    peer[n] = rows[-1]["median"]
import sympy
print(f"planar N-link pendulum, equations of motion (lagrange: median of 7; SymPy {sympy.__version__} "
      f"LagrangesMethod.form_lagranges_equations: median of up to 3, limit {limit:.0f} s)")
print(f"{'N':>3} {'lagrange_ms':>12} {'sympy_ms':>12} {'ratio':>9}")
for n in sorted(ours):
    p = peer.get(n)
    ratio = f"{p / ours[n]:9.0f}" if p else f"{'-':>9}"
    ps = f"{p * 1000:12.1f}" if p else f"{'>' + str(int(limit)) + ' s':>12}"
    print(f"{n:3d} {ours[n] * 1000:12.3f} {ps} {ratio}")
PY
