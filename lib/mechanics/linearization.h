// SPDX-License-Identifier: GPL-2.0-or-later
/** @file linearization.h
 *  Small oscillations about an equilibrium: the kinetic, potential and gyroscopic
 *  matrices T, V and G there, and the characteristic polynomial det(V − ω²T + iωG)
 *  made primitive. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/lagrangian.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

struct linearization_result {
    std::vector<GiNaC::ex> at;  ///< the equilibrium [q_i]
    GiNaC::matrix kinetic;      ///< T_ij = ∂²T/∂q̇i∂q̇j at the equilibrium [E·τ²/(q_i q_j)]
    /// V_ij = ∂²U/∂qi∂qj at the equilibrium (U = −L0, lagrangian.h), plus the stiffness
    /// K_f = −∂Q/∂q of position-dependent applied forces there (`force_stiffness`): the K of
    /// T q̈ + (C − G) q̇ + K q = 0. Not symmetric when those forces are circulatory.
    /// [E/(q_i q_j)]
    GiNaC::matrix potential;
    /// G_ij = ∂aⱼ/∂qi − ∂aᵢ/∂qj at the equilibrium, with L1 = Σ aᵢ(q) q̇ᵢ: antisymmetric; the
    /// linearized equations are T q̈ − G q̇ + V q = 0. All zero when L has no part linear in
    /// the velocities. [E·τ/(q_i q_j)]
    GiNaC::matrix gyroscopic;
    bool has_gyroscopic() const; ///< whether some entry of G is not identically 0
    /// K_f = −∂Q/∂q at the equilibrium, at rest, inputs 0 (mechanics/forces.h), already in
    /// `potential`; empty (0 × 0) or zero when no applied force depends on the position.
    GiNaC::matrix force_stiffness = GiNaC::matrix(0, 0);
    bool has_force_stiffness() const; ///< whether some entry of K_f is not identically 0
    /// Whether `potential` is not symmetric (circulatory forces): there are then no real
    /// mode shapes nor normal coordinates, and the eigenvalues s of det(s²T + s(C − G) + K)
    /// are found numerically (numeric/quadratic_modes.h).
    bool circulatory() const;
};

/// T and V (with the applied forces' stiffness) at `at`. Throws computation_error if T
/// is not positive definite (naming a coordinate with no kinetic energy where that is the
/// cause), or an applied force does not vanish at `at` (forces.h, force_stiffness).
linearization_result linearize(const model& scene, const lagrangian_result& lagrangian,
                               const std::vector<GiNaC::ex>& at, const simplifier& simplify);

struct characteristic_result {
    GiNaC::possymbol omega;  ///< named "omega" unless the scene uses that name
    /// det(V − ω²T + iωG) made primitive, coefficients factored: real, and even in ω
    /// (G is antisymmetric), so a polynomial in ω² whether or not G is 0.
    GiNaC::ex polynomial;
    /// false: factoring the coefficients ran out of its share of the time budget, so they
    /// are primitive but not factored
    bool factored = true;
};

/// det(V − ω²T + iωG) as a polynomial in ω, made primitive (see characteristic_coefficients).
characteristic_result characteristic_polynomial(const model& scene, const linearization_result& linear);

/// The primitive polynomial in w = ω² from det(V − w T): its coefficients, lowest
/// degree first, with every common factor removed and the leading one positive, each
/// factored. With `factored`, factoring that runs past half the stage's remaining time
/// budget is given up: the coefficients come unfactored and *factored is set to false.
std::vector<GiNaC::ex> characteristic_coefficients(const GiNaC::matrix& kinetic, const GiNaC::matrix& potential,
                                                   const GiNaC::symbol& w, bool* factored = nullptr);

/// The same for det(V − wT + i√w G), w = ω²: det(V + xG + x²T) in x = iω, whose odd
/// coefficients vanish for an antisymmetric G, with x² = −w.
std::vector<GiNaC::ex> characteristic_coefficients(const GiNaC::matrix& kinetic, const GiNaC::matrix& potential,
                                                   const GiNaC::matrix& gyroscopic, const GiNaC::symbol& w,
                                                   bool* factored = nullptr);

} // namespace lagrange
