// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gyroscopic_modes.h
 *  Numeric small oscillations of a gyroscopic linearization T q̈ − G q̇ + V q = 0 at one
 *  parameter point: the quadratic eigenproblem (s²T − sG + V)x = 0
 *  (numeric/quadratic_modes.h). numeric/point_modes.h evaluates T, V and G and calls it. */
#pragma once

#include "numeric/compiled_modes.h"

#include <Eigen/Dense>

namespace lagrange {

/// The modes of T q̈ − G q̇ + V q = 0 with T, V, G evaluated at one point: the 2n
/// eigenvalues s in `eigenvalues`; `omega` the n of the upper half (ascending imaginary
/// part): Im s for an oscillation, −|s| for a real s (a growth or decay rate, as in
/// numeric_modes); `error` the estimated error of each ω, relative (absolute for ω = 0);
/// `growth_rate` of each (0 unless it grows); `complex_modes` their vectors; `stability`:
/// unstable when some s has a real part beyond its error, marginal when some s is 0 within
/// its error. `values` and `method` are left to the caller. Throws computation_error
/// (without a location) as solve_quadratic_modes.
numeric_modes gyroscopic_modes_at(const Eigen::MatrixXd& kinetic, const Eigen::MatrixXd& potential,
                                  const Eigen::MatrixXd& gyroscopic);

} // namespace lagrange
