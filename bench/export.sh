#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The exported code's speed beside its peers, in one run on this machine:
# - C: one call of the exported double pendulum's double_pendulum_rhs (compiled -O2, as the
#   engine compiles its own) against the engine's compiled right-hand side, measured by
#   bench/motion_rhs in the same run ("compiled_motion (native)"); the same for the 10-link
#   chain against bench/large_systems;
# - Python: one call of the exported module's rhs on a state (NumPy) against SymPy's path for
#   the same equations: LagrangesMethod's mass matrix and forcing lambdified to NumPy, then
#   numpy.linalg.solve (as the SymPy documentation's examples integrate them).
# Each figure is the best of RUNS measurements; both sides check that they agree first.
# Usage: bench/export.sh [runs]        (LAGRANGE_BUILD=dir for another build)
# Needs a C compiler and Debian's python3-numpy, python3-scipy and python3-sympy.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
build=${LAGRANGE_BUILD:-build}
python=/usr/bin/python3
cc=${LAGRANGE_CC:-cc}
[ -x "$build/lagrange" ] || cmake --build "$build" --target lagrange_cli >&2
[ -x "$build/bench/motion_rhs" ] || cmake --build "$build" --target motion_rhs >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$build/lagrange" export examples/double_pendulum.lag --to c -o "$work" >/dev/null
"$build/lagrange" export examples/double_pendulum.lag --to python -o "$work" >/dev/null
cat >"$work/harness.c" <<'C'
#define _POSIX_C_SOURCE 199309L
#include "double_pendulum.h"
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    const long calls = argc > 1 ? atol(argv[1]) : 10000000;
    const int runs = argc > 2 ? atoi(argv[2]) : 5;
    double x[4] = {0.3, -0.2, 0.1, 0.4}, dxdt[4], best = 1e30, sink = 0.0;
    int r;
    for (r = 0; r < runs; ++r) {
        long k;
        double start = seconds(), elapsed;
        for (k = 0; k < calls; ++k) {
            x[0] = 0.3 + 1e-9 * (double)(k & 1023); /* a state that changes, as in an integrator */
            double_pendulum_rhs(0.0, x, NULL, double_pendulum_default_p, dxdt);
            sink += dxdt[2];
        }
        elapsed = seconds() - start;
        if (elapsed < best)
            best = elapsed;
    }
    printf("%.3f %.17g\n", 1e9 * best / (double)calls, sink);
    return 0;
}
C
"$cc" -std=c99 -O2 -fno-math-errno -ffp-contract=off -c "$work/double_pendulum.c" -o "$work/dp.o"
"$cc" -std=c99 -O2 -o "$work/harness" "$work/harness.c" "$work/dp.o" -I"$work" -lm
exported_c=$("$work/harness" 10000000 "$runs" | cut -d' ' -f1)
engine_c=$("$build/bench/motion_rhs" 2>&1 | awk '/compiled_motion \(native\)/ {print $3}')
echo "C right-hand side of the double pendulum, per call:"
echo "  exported C        ${exported_c} ns"
echo "  engine (native)   ${engine_c} ns"
"$python" -c "print('  ratio exported/engine  %.2f' % ($exported_c / $engine_c))"
# Where the engine compiles its own code with AVX2 and FMA (for SLEEF's sines), the exported
# file compiled with the same flags.
if grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo; then
    "$cc" -std=c99 -O2 -mavx2 -mfma -fno-math-errno -ffp-contract=off -c "$work/double_pendulum.c" -o "$work/dp_avx2.o"
    "$cc" -std=c99 -O2 -o "$work/harness_avx2" "$work/harness.c" "$work/dp_avx2.o" -I"$work" -lm
    exported_avx2=$("$work/harness_avx2" 10000000 "$runs" | cut -d' ' -f1)
    echo "  exported C, -mavx2 -mfma as the engine  ${exported_avx2} ns"
    "$python" -c "print('  ratio exported/engine  %.2f' % ($exported_avx2 / $engine_c))"
fi

# The 10-link chain: the exported chain10_rhs against the engine's compiled q'' of the same chain
# (bench/large_systems, which also times it against a hand-written O(N) recursion).
[ -x "$build/bench/large_systems" ] || cmake --build "$build" --target large_systems >&2
"$build/bench/large_systems" --scene 10 >"$work/chain10.lag"
"$build/lagrange" export "$work/chain10.lag" --to c -o "$work" >/dev/null
sed -e 's/double_pendulum/chain10/g' -e 's/double x\[4\] = {0.3, -0.2, 0.1, 0.4}, dxdt\[4\]/double x[chain10_NX], dxdt[chain10_NX]/' \
    -e 's/    int r;/    int r, i;\n    for (i = 0; i < chain10_NX; ++i)\n        x[i] = 0.3 - 0.05 * i;/' \
    "$work/harness.c" >"$work/chain_harness.c"
"$cc" -std=c99 -O2 -fno-math-errno -ffp-contract=off -c "$work/chain10.c" -o "$work/chain10.o"
"$cc" -std=c99 -O2 -o "$work/chain_harness" "$work/chain_harness.c" "$work/chain10.o" -I"$work" -lm
exported_chain=$("$work/chain_harness" 1000000 "$runs" | cut -d' ' -f1)
engine_chain=$("$build/bench/large_systems" 10 | cut -d' ' -f5)
echo "C right-hand side of the 10-link chain, per call:"
echo "  exported C        ${exported_chain} ns"
echo "  engine (native)   ${engine_chain} ns"
"$python" -c "print('  ratio exported/engine  %.2f' % ($exported_chain / $engine_chain))"

OPENBLAS_NUM_THREADS=1 "$python" - "$work" "$runs" <<'PY'
import sys, timeit
import numpy as np
import sympy as sp
from sympy.physics.mechanics import (dynamicsymbols, ReferenceFrame, Point, Particle, Lagrangian,
                                     LagrangesMethod)

work, runs = sys.argv[1], int(sys.argv[2])
sys.path.insert(0, work)
import double_pendulum as exported

# SymPy's path for the same scene: two particles on rods of length l.
M, m, l, g = sp.symbols("M m l g", positive=True)
th, ph = dynamicsymbols("theta phi")
N = ReferenceFrame("N")
O = Point("O")
O.set_vel(N, 0)
P1 = O.locatenew("P1", l * sp.sin(th) * N.x - l * sp.cos(th) * N.y)
P2 = P1.locatenew("P2", l * sp.sin(ph) * N.x - l * sp.cos(ph) * N.y)
P1.set_vel(N, P1.pos_from(O).dt(N))
P2.set_vel(N, P2.pos_from(O).dt(N))
pa, pb = Particle("pa", P1, M), Particle("pb", P2, m)
pa.potential_energy = M * g * P1.pos_from(O).dot(N.y)
pb.potential_energy = m * g * P2.pos_from(O).dot(N.y)
LM = LagrangesMethod(Lagrangian(N, pa, pb), [th, ph])
LM.form_lagranges_equations()
a, b = sp.symbols("a b")
speeds = {th.diff(): a, ph.diff(): b}
arguments = [th, ph, a, b, M, m, l, g]
mass = sp.lambdify(arguments, LM.mass_matrix.subs(speeds), "numpy")
forcing = sp.lambdify(arguments, LM.forcing.subs(speeds), "numpy")
p = exported.DEFAULTS

def sympy_rhs(t, x):
    values = (*x, *p)
    qdd = np.linalg.solve(np.asarray(mass(*values), dtype=float), np.asarray(forcing(*values), dtype=float).ravel())
    return np.concatenate([x[2:], qdd])

x = np.array([0.3, -0.2, 0.1, 0.4])
ours, theirs = exported.rhs(0.0, x, p), sympy_rhs(0.0, x)
assert np.allclose(ours, theirs, rtol=1e-12, atol=1e-12), (ours, theirs)
calls = 20000
best = lambda f: min(timeit.repeat(lambda: f(0.0, x), number=calls, repeat=runs)) / calls * 1e6
e, s = best(lambda t, y: exported.rhs(t, y, p)), best(sympy_rhs)
print("Python right-hand side of the double pendulum, per call (NumPy, one state):")
print("  exported module   %.2f us" % e)
print("  SymPy lambdify    %.2f us  (LagrangesMethod M and F, numpy.linalg.solve)" % s)
print("  ratio SymPy/exported  %.2f" % (s / e))
PY
