// SPDX-License-Identifier: GPL-2.0-or-later
/** @file orientation.h
 *  The orientation of a body as a sequence of rotations about its own axes
 *  (`rotations(z q1, x q2, …)`, `zxz(φ, θ, ψ)`; the matrices are in algebra/rotation.h):
 *  the body-frame angular velocity, and the rotational kinetic energy by a route that
 *  does not use ω. */
#pragma once

#include "algebra/rotation.h"
#include "core/model.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

/// The body-frame angular velocity of R = R_{a1}(q1) ⋯ R_{an}(qn): ω = Σ_k (R_{k+1} ⋯ R_n)ᵀ e_{a_k} q̇_k,
/// each rate the total time derivative of its angle in `scene`; entries unsimplified.
std::vector<GiNaC::ex> sequence_angular_velocity(const std::vector<char>& axes, const std::vector<GiNaC::ex>& angles,
                                                 const model& scene);

/// ½ ∫ |Ṙ r|² dm = ½ tr(Ṙ J Ṙᵀ), with J = ½ tr(I) 1 − I the second moments ∫ r rᵀ dm about
/// the centre of mass: the rotational kinetic energy from the rate of R itself, without ω.
GiNaC::ex rotational_energy_from_rate(const GiNaC::matrix& rotation, const GiNaC::matrix& tensor, const model& scene);

} // namespace lagrange
