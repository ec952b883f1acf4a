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

/// Every velocity and every input at 0: the substitution that puts a generalized force at rest.
GiNaC::exmap at_rest(const model& scene);

/// The Rayleigh function of one damper: ½ b (d·ḋ)²/(d·d) with d = r_A − r_B.
GiNaC::ex damper_rayleigh(const model& scene, const damper& d, const simplifier& simplify);

/// Small oscillations about an equilibrium of V need generalized forces that vanish at
/// rest (all velocities 0, every input 0) at the equilibrium: dissipation always does.
/// Applied forces that vanish at rest at every position and time are checked here; others
/// are taken when the scene names its equilibrium (a static `equilibrium` line, no
/// constraints), and force_stiffness checks them at that point. Otherwise throws
/// computation_error naming the first coordinate whose applied force does not vanish.
void require_forces_vanish_at_rest(const model& scene, const simplifier& simplify);

/// The stiffness of the generalized forces at `at`: K_f,ij = −∂Q_i/∂q_j at (q = at, q̇ = 0,
/// inputs 0), which the linearized equations M q̈ + (C − G) q̇ + (V + K_f) q = 0 add to V's
/// Hessian; not symmetric for circulatory forces (the bicycle's v²K₂). Throws
/// computation_error when some Q_i does not vanish at that point (then `at` is no
/// equilibrium of the motion) or K_f depends on time there. All zeros without forces.
GiNaC::matrix force_stiffness(const model& scene, const std::vector<GiNaC::ex>& at, const simplifier& simplify);

} // namespace lagrange
