// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gyroscopic.h
 *  Gyroscopic systems: L1 = Σ aᵢ(q) q̇ᵢ (magnetic fields, the Coriolis terms of a moving
 *  frame, spinning rotors) gives the antisymmetric matrix G; stability by the
 *  Kelvin–Tait–Chetaev theorems; the frequencies ω ≥ 0 in closed form. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/equilibrium.h"
#include "mechanics/lagrangian.h"
#include "mechanics/linearization.h"
#include "mechanics/modes.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

/// G_ij = ∂aⱼ/∂qi − ∂aᵢ/∂qj at `at`, with aᵢ = ∂L1/∂q̇ᵢ of `velocity_linear` = L1.
GiNaC::matrix gyroscopic_matrix(const model& scene, const GiNaC::ex& velocity_linear, const std::vector<GiNaC::ex>& at);

/// Stability of T q̈ − G q̇ + V q = 0 (Kelvin–Tait–Chetaev): V positive definite is stable
/// whatever G; an odd number of negative eigenvalues of V (det V < 0) is unstable whatever
/// G; otherwise stable exactly when every root w = ω² of det(V − wT + i√w G) is real,
/// positive and simple (gyroscopic stabilization), decided by a Sturm sequence — for
/// every positive value of the parameters if the signs allow, else at each of the scene's
/// `values` points when they all agree. `potential_verdict` is the verdict from V alone.
stability gyroscopic_stability(const model& scene, const GiNaC::matrix& kinetic, const GiNaC::matrix& potential,
                               const GiNaC::matrix& gyroscopic, stability potential_verdict);

/// The same at an equilibrium of `lagrangian`, with T, V and G evaluated there (what
/// find_equilibria uses for each point when L has a part linear in the velocities).
stability gyroscopic_stability_at(const model& scene, const lagrangian_result& lagrangian,
                                  const std::vector<GiNaC::ex>& at, stability potential_verdict,
                                  const simplifier& simplify);

/// The frequencies ω ≥ 0 of a gyroscopic linearization from its characteristic
/// polynomial: square roots of the roots w of each factor of degree ≤ 2 in w = ω², nested
/// roots taken apart where they denest (the Penning trap's √(ω0² + ωc²/4) ± ωc/2),
/// ascending where the order is known. No mode vectors (they are complex) and no normal
/// coordinates. Not closed_form when a factor has a higher degree or a root w is not known
/// to be ≥ 0.
modes_result gyroscopic_modes(const model& scene, const linearization_result& linear,
                              const characteristic_result& characteristic);

} // namespace lagrange
