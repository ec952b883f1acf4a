// SPDX-License-Identifier: GPL-2.0-or-later
/** @file contact.h
 *  The `contact` product: the force the ground exerts on each rolling wheel at its contact
 *  point (our extension; SymPy finds it with auxiliary speeds, `test_aux_dep`). Each
 *  constraint of `rolls W on ground` holds the contact point P along a vector e_k (its
 *  velocity form is e_k·v_P), so its generalized force λ_k a_k is that of the force λ_k e_k
 *  at P, and the ground's force is F = Σ_k λ_k e_k, with λ solved in q and q̇. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/constraints.h"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace lagrange {

/// The ground's force on one wheel.
struct contact_force {
    std::string body;
    std::vector<GiNaC::ex> point; ///< the contact point, scene frame [length]
    std::vector<GiNaC::ex> force; ///< scene frame, in q, q̇ and t [E/length]
};

struct contact_result {
    std::vector<contact_force> contacts; ///< one per `rolls` line, in scene order
};

/// F = Σ_k λ_k e_k for each `rolls` line. Throws computation_error when the scene has no
/// `rolls` line, or a wheel's height holds by the coordinates themselves (its normal force is
/// then no multiplier: the height needs a coordinate of its own and the `W_contact`
/// constraint, as SymPy's test_aux_dep gives it the dependent coordinate q3).
contact_result derive_contact_forces(const model& scene, const multipliers_result& multipliers,
                                     const simplifier& simplify);

} // namespace lagrange
