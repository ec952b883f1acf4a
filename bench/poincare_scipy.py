#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The peer of bench/poincare.sh: the same Hénon–Heiles orbits integrated by SciPy's DOP853
(solve_ivp, its events located on the dense output by root finding), from the starts that
`lagrange poincare` wrote (each orbit's first row), each until that orbit's last crossing.

    poincare_scipy.py SECTION.csv TOLERANCE

Prints one line: `seconds crossings worst_energy_error` (the error relative to E, the
energy of the well's minimum being 0)."""
import sys
import time

import numpy
from scipy.integrate import solve_ivp


def rhs(t, s):
    x, y, vx, vy = s
    return [vx, vy, -x - 2 * x * y, -y - x * x + y * y]


def section(t, s):
    return s[0]


section.direction = 1


def energy(s):
    x, y, vx, vy = s
    return 0.5 * (vx * vx + vy * vy) + 0.5 * (x * x + y * y) + x * x * y - y ** 3 / 3


def main():
    table = numpy.loadtxt(sys.argv[1], delimiter=",", skiprows=1, ndmin=2)
    tolerance = float(sys.argv[2]) / 12  # per step, as lagrange's DOP853 (simulate's rule)
    orbits = sorted(set(table[:, 0].astype(int).tolist()))
    starts = {k: table[table[:, 0] == k][0, 2:6] for k in orbits}
    ends = {k: table[table[:, 0] == k][-1, 1] for k in orbits}
    e = energy(starts[orbits[0]])
    began = time.perf_counter()
    crossings, worst = 0, 0.0
    for k in orbits:
        run = solve_ivp(rhs, (0, ends[k] * (1 + 1e-9) + 1e-9), starts[k], method="DOP853", rtol=tolerance,
                        atol=tolerance, events=section)
        points = run.y_events[0][run.t_events[0] > 0]  # SciPy also reports the start, on the section
        crossings += 1 + len(points)  # the start is the first crossing, as lagrange counts
        for p in points:
            worst = max(worst, abs(energy(p) - e) / e)
    seconds = time.perf_counter() - began
    print(f"{seconds:.3f} {crossings} {worst:.3g}")


if __name__ == "__main__":
    main()
