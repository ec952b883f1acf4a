// SPDX-License-Identifier: GPL-2.0-or-later
/** @file forces.h
 *  The generalized forces beyond the Lagrangian, Q in M q̈ = f + Q: Rayleigh
 *  dissipation (`dissipation` lines and dampers) and applied forces (`force q = ...`
 *  and `force on P (...)` by virtual work). */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

struct generalized_forces {
    /// The whole Rayleigh function F: the `dissipation` lines plus ½ b (d/dt |r_A − r_B|)²
    /// of every damper; quadratic in the velocities.
    GiNaC::ex rayleigh;
    std::vector<GiNaC::ex> dissipative; ///< −∂F/∂q̇_i, one per coordinate
    std::vector<GiNaC::ex> applied;     ///< Σ `force q_i` + Σ F·∂r_P/∂q_i, one per coordinate
    std::vector<GiNaC::ex> total;       ///< Q_i = dissipative_i + applied_i
    bool any = false;                   ///< some Q_i is not identically zero
};

/// Q of a scene, with trigonometric parts in canonical form (`simplify.canonical`). All
/// zeros for a scene without dissipation, dampers or forces.
generalized_forces derive_generalized_forces(const model& scene, const simplifier& simplify);

/// The Rayleigh function of one damper: ½ b (d·ḋ)²/(d·d) with d = r_A − r_B.
GiNaC::ex damper_rayleigh(const model& scene, const damper& d, const simplifier& simplify);

/// Small oscillations about an equilibrium of V need generalized forces that vanish at
/// rest (all velocities 0, every input 0) at every position and time: dissipation always
/// does; applied forces must. Throws computation_error naming the first coordinate whose
/// applied force does not.
void require_forces_vanish_at_rest(const model& scene, const simplifier& simplify);

} // namespace lagrange
