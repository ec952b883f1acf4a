// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_operating_point.h
 *  The check of a linearization about an operating point (mechanics/operating_point.h):
 *  A, B and the residual against central differences of the full nonlinear constrained
 *  dynamics in the independent states. */
#pragma once

#include "core/model.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/operating_point.h"
#include "verify/verify.h"

namespace lagrange {

/// At up to two parameter points (the free coordinates at seeded values): the state
/// x = (q_I, q̇_J) is moved by ±h in each entry (and each input), the dependent coordinates
/// found by Newton's method on the holonomic constraints, the dependent speeds from
/// A q̇ + b = 0, q̈ from [M −Aᵀ; A 0] [q̈; λ] = [f + Q; −c], all compiled from the equations as
/// derived; A and B must match the central differences of ẋ = (q̇_I, q̈_J), and the residual
/// its value at the point. The entry `state_space`. Throws computation_error
/// "verification failed: …" on a disagreement.
verification_entry verify_operating_point(const model& scene, const equations_of_motion& equations,
                                          const operating_linearization& point);

} // namespace lagrange
