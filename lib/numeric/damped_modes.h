// SPDX-License-Identifier: GPL-2.0-or-later
/** @file damped_modes.h
 *  Numeric damped small oscillations at one parameter point: the quadratic eigenproblem
 *  (s²M + s(C − G) + K)x = 0 of M q̈ + (C − G) q̇ + K q = 0 (numeric/quadratic_modes.h),
 *  with the damping ratio −Re s/|s| of each eigenvalue. numeric/point_modes.h evaluates
 *  the matrices and calls it. */
#pragma once

#include "core/model.h"
#include "mechanics/linearization.h"
#include "numeric/compiled_modes.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

/// Adds to `entry` (the numeric modes at one point) the damped eigenvalues with the
/// damping matrix C, all four matrices evaluated at that point: `eigenvalues` (all 2n s,
/// quadratic_modes order), `eigenvalue_error`, `damping_ratio`, `stability`, the mode of
/// each eigenvalue (`damped_modes`, largest component 1, with its backward error) and
/// whether the damping is proportional at the point (then the modes are real), and sets
/// `damped`. `omega` and `modes` stay those of the undamped system (C = 0). Throws
/// computation_error (without a location) as solve_quadratic_modes.
void add_damped_eigenvalues(numeric_modes& entry, const Eigen::MatrixXd& kinetic, const Eigen::MatrixXd& potential,
                            const Eigen::MatrixXd& damping, const Eigen::MatrixXd& gyroscopic);

/// −Re s/|s|; NaN for s = 0, which has no damping ratio.
double damping_ratio(std::complex<double> s);

/// Evaluates `matrices` (entries in the scene's parameters) at one `values` point: each
/// result row-major in a matrix of the same size. `used_only`: a parameter that none of them
/// uses needs no value. Throws computation_error naming the parameter without a value, or
/// an entry that is not finite, with `where`.
std::vector<Eigen::MatrixXd> matrices_at(const model& scene, const std::vector<const GiNaC::matrix*>& matrices,
                                         const value_point& point);

} // namespace lagrange
