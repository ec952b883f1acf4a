// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gyroscopic_modes.h
 *  Numeric small oscillations of a gyroscopic linearization T q̈ − G q̇ + V q = 0 at each
 *  `values` point: T, V and G compiled once, then the quadratic eigenproblem
 *  (s²T − sG + V)x = 0 (numeric/quadratic_modes.h) per point. */
#pragma once

#include "core/model.h"
#include "mechanics/linearization.h"
#include "numeric/compiled_modes.h"

#include <vector>

namespace lagrange {

/// One entry per `values` point: the 2n eigenvalues s in `eigenvalues`; `omega` the n of
/// the upper half (ascending imaginary part): Im s for an oscillation, −|s| for a real s (a
/// growth or decay rate, as in numeric_modes); `error` the estimated error of each ω,
/// relative (absolute for ω = 0); `complex_modes` their vectors; `stability`: unstable when
/// some s has a real part beyond its error, marginal when some s is 0 within its error.
/// Throws computation_error as numeric_normal_modes does.
std::vector<numeric_modes> numeric_gyroscopic_modes(const model& scene, const linearization_result& linear);

} // namespace lagrange
