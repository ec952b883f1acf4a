// SPDX-License-Identifier: GPL-2.0-or-later
/** @file ode_helpers.h
 *  Test systems shared by the integrator and simulation tests. */
#pragma once

#include "numeric/ode.h"

#include <cmath>

namespace lagrange_test {

/// The nonlinear pendulum θ'' = −sin θ, with its Jacobian and energy ½θ'² − cos θ.
inline lagrange::ode_system pendulum_system()
{
    lagrange::ode_system s;
    s.dimension = 2;
    s.rhs = [](double, const double* x, double* f) {
        f[0] = x[1];
        f[1] = -std::sin(x[0]);
    };
    s.jacobian = [](double, const double* x, double* j) {
        j[0] = 0, j[1] = 1, j[2] = -std::cos(x[0]), j[3] = 0;
    };
    s.invariants.push_back({"energy", [](const double* x) { return 0.5 * x[1] * x[1] - std::cos(x[0]); }, 0});
    return s;
}

} // namespace lagrange_test
