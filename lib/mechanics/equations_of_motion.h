// SPDX-License-Identifier: GPL-2.0-or-later
/** @file equations_of_motion.h
 *  The equations of motion, derived once from L and read by everyone who needs them:
 *  the printers and the report (the Euler–Lagrange residuals, simplified, and their
 *  grouping by accelerations) and the compiled right-hand side (M(q) q̈ = f). */
#pragma once

#include "algebra/simplify.h"
#include "core/errors.h"
#include "core/model.h"
#include "mechanics/constraints.h"
#include "mechanics/forces.h"
#include "mechanics/lagrangian.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lagrange {

/// The equations grouped as 𝓜(q) q̈ + f(q, q̇) = 0: 𝓜_ij is the coefficient of
/// q̈_j in equation i, f_i what is left. Nothing if an equation is not linear in
/// the accelerations.
struct acceleration_form {
    GiNaC::matrix mass;
    std::vector<GiNaC::ex> rest;
};
std::optional<acceleration_form> group_by_accelerations(const model& scene, const std::vector<GiNaC::ex>& equations);

/// The equations of motion of a scene. The form M q̈ = f is what the integrators solve; the
/// residuals are what is printed. Both come from the same L here and nowhere else. Later
/// terms (generalized forces, constraint multipliers) are added here, to both forms.
struct equations_of_motion {
    GiNaC::ex lagrangian;                ///< the L they come from (lagrangian_result::lagrangian)
    std::vector<GiNaC::ex> momenta;      ///< p_i = ∂L/∂q̇_i [E·τ/q_i]
    GiNaC::matrix mass;                  ///< M_ij = ∂p_i/∂q̇_j (n × n) [E·τ²/(q_i q_j)]
    std::vector<GiNaC::ex> forcing;      ///< f_i = ∂L/∂q_i − Σ_j ∂p_i/∂q_j q̇_j − ∂p_i/∂t + Q_i [E/q_i]
    /// Q: dissipation, dampers and applied forces (mechanics/forces.h), in `forcing` and the residuals.
    generalized_forces forces;
    GiNaC::ex energy;                    ///< the energy function h = Σ q̇_i p_i − L [E]
    GiNaC::ex potential;                 ///< V as built (lagrangian_result::potential_built) [E]
    /// The scene's constraints, when it has some: then M q̈ = f + Aᵀλ with A q̈ = −c, and the
    /// residuals below less Σ_k a_ki λ_k.
    std::optional<constraint_equations> constraints;
    /// d/dt ∂L/∂q̇ − ∂L/∂q − Q, each meaning `expr = 0`, simplified: set when they are printed.
    std::optional<std::vector<GiNaC::ex>> residuals;
    /// The residuals as 𝓜(q) q̈ + f = 0, when they are linear in the accelerations.
    std::optional<acceleration_form> grouped;
    /// Why the residuals were asked for and not printed (too large to read: the whole Whipple
    /// bicycle's); empty when they were not asked for or are set.
    std::string too_large_to_print;
};

/// The most terms an equation may have, expanded in canonical form, to be printed: beyond it
/// an equation is pages of text that nobody reads, and compacting it (the rules' matcher over
/// the whole sum) takes longer than the time budget. The 30-link chain's largest has 930 terms,
/// the whole bicycle's yaw equation 2143.
inline constexpr std::size_t printed_equation_terms = 1000;

/// An equation of motion with more than printed_equation_terms terms, asked to be printed.
class equations_too_large : public computation_error {
public:
    using computation_error::computation_error;
};

/// M, f, the momenta and the energy function of L (unsimplified: what the compiled
/// right-hand side evaluates), and with `printed` also the simplified residuals and
/// their grouping by accelerations, unless an equation has more than printed_equation_terms
/// terms (then `too_large_to_print` says so, and what to ask for instead).
equations_of_motion derive_equations_of_motion(const model& scene, const lagrangian_result& lagrangian,
                                               const simplifier& simplify, bool printed);

/// The Euler–Lagrange equations d/dt(∂L/∂q̇) − ∂L/∂q, one per coordinate, each
/// meaning `expr = 0`, simplified and grouped by accelerations and velocities. Throws
/// equations_too_large, before compacting, when one has more than printed_equation_terms terms.
std::vector<GiNaC::ex> derive_equations(const model& scene, const lagrangian_result& lagrangian,
                                        const simplifier& simplify);

} // namespace lagrange
