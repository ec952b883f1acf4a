// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_constraints.h
 *  Self-verification of the results with constraints, by routes that do not share their
 *  derivation: the multipliers against the index-1 system solved numerically with the
 *  constraint rows and their derivative taken by finite differences of the constraints as
 *  written, and the constraint forces by their virtual work; the reduced linearization
 *  against V on the constraint manifold (dependent coordinates solved by Newton's method)
 *  and T along its tangent vectors, by finite differences. */
#pragma once

#include "core/model.h"
#include "mechanics/constrained_linearization.h"
#include "mechanics/constraints.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/lagrangian.h"
#include "verify/verify.h"

#include <vector>

namespace lagrange {

/// Throws computation_error "verification failed: …" when a multiplier or force disagrees.
verification_entry check_multipliers(const model& scene, const equations_of_motion& equations,
                                     const multipliers_result& multipliers);

/// Adds the `equilibrium` (when `point`) and `linearization` entries; throws on disagreement.
void check_constrained_linearization(const model& scene, const lagrangian_result& lagrangian,
                                     const constrained_linearization& constrained, bool point,
                                     std::vector<verification_entry>& entries);

} // namespace lagrange
