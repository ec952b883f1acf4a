// SPDX-License-Identifier: GPL-2.0-or-later
/** @file constraints.h
 *  Constraints in the equations of motion (§5 of the spec): M q̈ = f + Q + Aᵀλ with the
 *  rows of A the velocity coefficients a_kj of each constraint (∂f/∂q for a holonomic one,
 *  so Pfaffian constraints give the Lagrange–d'Alembert equations), and the constraints
 *  differentiated to the accelerations, A q̈ = −c; whether the Pfaffian ones are integrable
 *  (Frobenius); and, solved for q̈ and λ, the `multipliers` and the constraint forces
 *  they exert on the points. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace lagrange {

/// The constraints as the equations of motion use them.
struct constraint_equations {
    GiNaC::matrix matrix;          ///< A (m × n): row k holds a_kj of constraint k
    /// c_k with A q̈ = −c: the time derivative of Σ_j a_kj q̇_j + b_k without its q̈ terms.
    std::vector<GiNaC::ex> bias;
    /// Per constraint: for a Pfaffian one, whether it is integrable by itself (ω ∧ dω = 0, so
    /// that a holonomic form exists); holonomic ones are.
    std::vector<bool> integrable;
    /// Whether the constraints together are integrable (Frobenius: their common kernel is
    /// involutive); false means some motion is nonholonomic.
    bool jointly_integrable = true;
};

/// A, c and the integrability of the scene's constraints.
constraint_equations derive_constraint_equations(const model& scene);

/// The force one constraint exerts on one point.
struct constraint_point_force {
    std::string point;
    std::vector<GiNaC::ex> force; ///< 2 or 3 components, in q, q̇ and t
};

/// One constraint's multiplier and forces.
struct constraint_multiplier {
    std::string name;
    GiNaC::ex multiplier; ///< λ in the coordinates, velocities and t
    std::vector<constraint_point_force> forces; ///< on the points it acts on, in scene order
};

struct multipliers_result {
    std::vector<constraint_multiplier> constraints; ///< in scene order
    std::vector<GiNaC::ex> accelerations; ///< q̈ solved with λ, unsimplified, in coordinate order
    /// Points whose coordinates also move other points or bodies: the generalized constraint
    /// force on them cannot be split between the points, so they get none.
    std::vector<std::string> unattributed;
};

/// λ from [M −Aᵀ; A 0] [q̈; λ] = [f + Q; −c], solved as the embedding method does when every
/// constraint can be solved for a coordinate with a number as its coefficient (A q̈ = −c as q̈ = N u + p, then Nᵀ M N u = Nᵀ(f + Q − M p) for the free
/// accelerations u, and Aᵀλ = M q̈ − f − Q on the solved coordinates), else as a whole; and the force
/// of each constraint on each point P whose coordinates S move P alone: F = J (JᵀJ)⁻¹ λ a_S with J = ∂r_P/∂q_S, the force along
/// P's own motion that does the constraint's virtual work. Throws computation_error when the
/// system is singular.
multipliers_result derive_multipliers(const model& scene, const GiNaC::matrix& mass,
                                      const std::vector<GiNaC::ex>& forcing, const constraint_equations& constraints,
                                      const simplifier& simplify);

/// A quotient with numerator and denominator each in canonical trig form, then compacted.
GiNaC::ex simplify_ratio(const GiNaC::ex& e, const simplifier& simplify);

} // namespace lagrange
