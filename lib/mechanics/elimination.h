// SPDX-License-Identifier: GPL-2.0-or-later
/** @file elimination.h
 *  Holonomic constraints eliminated explicitly: where a constraint is linear in one
 *  coordinate with a coefficient free of the coordinates (y1 + y2 = −l, x = l/2 sin θ),
 *  that coordinate is solved for, and the equations of motion of the coordinates kept
 *  are the multiplier form projected on the constraint manifold,
 *      Jᵀ (M q̈ − f − Q) = 0,  q = φ(q_kept, t),  J = ∂φ/∂q_kept,
 *  in which Jᵀ Aᵀ λ = 0 since the constraints hold along φ: the Euler–Lagrange equations
 *  of the reduced Lagrangian, with the generalized forces carried along. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/equations_of_motion.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <string>
#include <vector>

namespace lagrange {

/// A coordinate solved from a constraint.
struct eliminated_coordinate {
    std::size_t coordinate = 0; ///< index in the scene's coordinates
    std::size_t constraint = 0; ///< index in the scene's constraints
    GiNaC::ex value;            ///< in the kept coordinates, the parameters and t
};

struct elimination_result {
    std::vector<eliminated_coordinate> eliminated; ///< in constraint order
    /// Whether every constraint is eliminated (then `kept` and `equations` describe the motion).
    bool complete = false;
    std::vector<std::size_t> kept;   ///< the coordinates kept, in scene order
    /// One equation per kept coordinate, meaning `expr = 0`, simplified; empty unless asked for.
    std::vector<GiNaC::ex> equations;
};

/// Which holonomic constraints can be solved for a coordinate, and for which: the last
/// coordinate (in scene order) in which the constraint is linear with a coefficient free of
/// the coordinates, not solved for already; earlier solutions are substituted into later
/// constraints. Pfaffian constraints are never eliminated.
elimination_result find_eliminations(const model& scene, const simplifier& simplify);

/// The equations of the kept coordinates (see above); needs `complete`.
std::vector<GiNaC::ex> reduced_equations(const model& scene, const equations_of_motion& equations,
                                         const elimination_result& elimination, const simplifier& simplify);

} // namespace lagrange
