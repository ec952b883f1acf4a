// SPDX-License-Identifier: GPL-2.0-or-later
/** @file constrained_linearization.h
 *  Small oscillations of a scene with holonomic constraints: the equilibrium given by the
 *  scene, checked on the constraints (g(q*) = 0 and ∇V = Aᵀλ* there), and T and V reduced to
 *  independent coordinates on the tangent space of the constraints there:
 *  δq = N δq_I with A N = 0, T_I = Nᵀ T N and V_I = Nᵀ (∇²V − Σ λ*_k ∇²g_k) N. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/equilibrium.h"
#include "mechanics/lagrangian.h"
#include "mechanics/linearization.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

struct constrained_linearization {
    equilibria_result equilibria;         ///< the scene's equilibrium, with its stability
    linearization_result linear;          ///< T and V in the independent coordinates
    std::vector<std::size_t> independent; ///< their indices in the scene's coordinates
    std::vector<GiNaC::ex> multipliers;   ///< λ* at the equilibrium, one per constraint
};

/// Throws computation_error when the scene has no `equilibrium` line, a Pfaffian
/// constraint, or when the point given is not on the constraints or not an equilibrium there.
constrained_linearization linearize_with_constraints(const model& scene, const lagrangian_result& lagrangian,
                                                     const simplifier& simplify);

} // namespace lagrange
