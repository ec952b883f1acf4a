#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The whole Whipple bicycle beside SymPy, in one run on this machine: `lagrange --want
# state_space,critical` on examples/bicycle.lag (reading the scene, the Lagrangian of four
# bodies, the rolling constraints, the symbolic linearization about upright running at speed
# v, and the weave and capsize speeds) against SymPy's KanesMethod linearization of the same
# bicycle as its test_kane3.py::test_bicycle writes it (bench/bicycle_sympy.py: the equations,
# then A at the benchmark's values, with v symbolic). Prints lagrange's best wall time over
# RUNS runs, SymPy's one run (or "> TIMEOUT s" when it does not finish), their ratio, and the
# eigenvalues at v = 5 m/s of both.
# Usage: bench/bicycle.sh [runs] [sympy-timeout-seconds]   (LAGRANGE_BUILD=dir for another build)
# Needs python3 with sympy (SymPy 1.14 was measured).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
limit=${2:-1800}
build=${LAGRANGE_BUILD:-build}
python=${PYTHON:-python3}
[ -x "$build/lagrange" ] || cmake --build "$build" --target lagrange_cli >&2
out=/tmp/bicycle_bench.$$.json
trap 'rm -f "$out"' EXIT
best=1e9
for _ in $(seq "$runs"); do
    start=$(date +%s.%N)
    "$build/lagrange" --want state_space,critical --format json examples/bicycle.lag >"$out"
    end=$(date +%s.%N)
    best=$("$python" -c "print(min($best, $end - $start))")
done
ours=$("$python" - "$out" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
speeds = " ".join(repr(c["value"]) for c in d["critical"]["crossings"])
eig = sorted((complex(re, im) for re, im in d["state_space"]["numeric"][0]["eigenvalues"] if abs(complex(re, im)) > 1e-9),
             key=lambda z: (z.imag, z.real))
print(f"speeds {speeds}; eigenvalues at v = 5: " + " ".join(repr(z) for z in eig))
PY
)
printf 'lagrange (whole run): %.3f s  %s\n' "$best" "$ours"
if sympy=$(timeout "$limit" "$python" bench/bicycle_sympy.py); then
    seconds=$(head -1 <<<"$sympy")
    printf 'SymPy KanesMethod + linearize: %s s  eigenvalues at v = 5: %s\n' "$seconds" "$(tail -1 <<<"$sympy")"
    "$python" -c "print(f'ratio SymPy / lagrange: {$seconds / $best:.1f}')"
else
    printf 'SymPy KanesMethod + linearize: > %s s (stopped)\n' "$limit"
    "$python" -c "print(f'ratio SymPy / lagrange: > {$limit / $best:.0f}')"
fi
