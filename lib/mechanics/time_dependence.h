// SPDX-License-Identifier: GPL-2.0-or-later
/** @file time_dependence.h
 *  Explicit time in L: whether L really depends on t once its sines and cosines are in
 *  canonical form (a hoop turned at a fixed rate, written with cos(w t), does not), the
 *  points that solve the equations of motion at every t when it does (a vertically
 *  driven pendulum at φ = 0 or π), and the equations linearized about such a point,
 *  whose coefficients depend on t (what the Floquet analysis integrates). */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/lagrangian.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

/// True if any expression the scene gives (energies, L, positions of points, bodies and
/// spring ends) contains t. Decides cheaply, before any stage, whether the time stage applies.
bool mentions_time(const model& scene);

struct time_dependence_result {
    /// L in canonical form contains t.
    bool depends_on_time = false;
    /// When it does: the points q0 (one value per coordinate, in order) at which q(t) = q0
    /// solves the equations of motion at every t.
    std::vector<std::vector<GiNaC::ex>> points;
    bool given = false; ///< the point is the scene's `equilibrium` line
};

/// Decides whether L depends on t and, if it does, finds the points that solve the
/// equations at every t: the scene's `equilibrium` line (checked), else each angle at 0
/// or π and the other coordinates from a linear system. Throws computation_error
///  - "no equilibrium: L depends on t and no point solves the equations at all t" when
///    it is proven that none exists (every equation at rest split into its parts
///    independent in t, and for one coordinate at a time those have no common root);
///  - a message asking for an `equilibrium` line when none was found but none is excluded;
///  - when the `equilibrium` line does not solve the equations at every t.
time_dependence_result analyze_time_dependence(const model& scene, const lagrangian_result& lagrangian,
                                               const equations_of_motion& equations, const simplifier& simplify);

/// The equations linearized about a point that solves them at every t:
/// M(t) δq̈ = K(t) δq + C(t) δq̇, with M the mass matrix, K = ∂f/∂q and C = ∂f/∂q̇ at the
/// point (velocities 0). Entries are expressions in t and the parameters.
struct periodic_linearization {
    GiNaC::matrix mass;
    GiNaC::matrix stiffness; ///< ∂f/∂q (the negative of the stiffness matrix in the usual sign)
    GiNaC::matrix velocity;  ///< ∂f/∂q̇
};

periodic_linearization linearize_about(const model& scene, const equations_of_motion& equations,
                                       const std::vector<GiNaC::ex>& point);

/// The angular frequencies ω of the time dependence of `e`: the coefficients of t in the
/// arguments of its sines and cosines. Throws computation_error if t appears otherwise
/// (a power of t, exp(t), a sine of t²): then e is not periodic in t.
std::vector<GiNaC::ex> time_frequencies(const GiNaC::ex& e, const GiNaC::symbol& time);

} // namespace lagrange
