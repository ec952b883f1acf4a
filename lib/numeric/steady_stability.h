// SPDX-License-Identifier: GPL-2.0-or-later
/** @file steady_stability.h
 *  The stability of a steady motion at the `values` points: the eigenvalues of the reduced
 *  system T q̈ − G q̇ + V q = 0 there. */
#pragma once

#include "core/model.h"
#include "mechanics/steady_motion.h"

#include <vector>

namespace lagrange {

/// One entry per `values` point that gives every parameter the reduced T, V and G use:
/// unstable where some Re s > 0 (to 1e-9 of the largest |s|), stable where every s is on the
/// imaginary axis and they are distinct (no secular growth), marginal where two coincide.
std::vector<steady_motion_result::at_point> steady_stability_at_values(const model& scene,
                                                                       const steady_motion_result& motion);

} // namespace lagrange
