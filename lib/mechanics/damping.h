// SPDX-License-Identifier: GPL-2.0-or-later
/** @file damping.h
 *  Damped small oscillations: the damping matrix C at the equilibrium, the
 *  characteristic polynomial det(K + sC + s²M) in s (q ∝ e^{st}) made primitive, its
 *  roots in closed form where every factor has degree ≤ 2 in s (the single damped
 *  oscillator's s = −γ ± i√(ω₀² − γ²) with its three regimes), and whether the damping
 *  is proportional (then the undamped mode shapes stay, with modal damping ratios). */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/linearization.h"
#include "mechanics/modes.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace lagrange {

/// A factor of the characteristic polynomial of degree ≤ 2 in s and its roots.
struct damped_factor {
    GiNaC::ex factor;            ///< a s² + b s + c (or b s + c), primitive
    std::vector<GiNaC::ex> roots; ///< −b/(2a) ± √(b² − 4ac)/(2a), or −c/b
    /// For a quadratic factor: γ = b/(2a), ω₀² = c/a, and the sign of ω₀² − γ² where it is
    /// known (at the parameters' domain): "underdamped" (s = −γ ± i√(ω₀² − γ²)),
    /// "critical" (a double root −γ), "overdamped" (two real roots), or "" when it depends
    /// on the parameters.
    GiNaC::ex decay;             ///< γ
    GiNaC::ex natural_squared;   ///< ω₀²
    GiNaC::ex discriminant;      ///< ω₀² − γ²: > 0 underdamped, 0 critical, < 0 overdamped
    std::string regime;
};

struct damping_result {
    GiNaC::matrix damping;        ///< C_ij = −∂Q_i/∂q̇_j at the equilibrium, at rest, inputs 0 [E·τ/(q_i q_j)]
    GiNaC::possymbol s;           ///< named "s" unless the scene uses that name [1/τ]
    GiNaC::ex polynomial;         ///< det(K + s(C − G) + s²M) made primitive (leading coefficient positive)
    /// G ≠ 0 (a part of L linear in the velocities): the polynomial holds it, as the
    /// equations T q̈ + (C − G) q̇ + K q = 0 do; there is then no proportional damping.
    bool gyroscopic = false;
    bool closed_form = false;     ///< every factor has degree ≤ 2 in s
    std::vector<damped_factor> factors; ///< when closed_form, in a fixed order
    /// C M⁻¹ K = K M⁻¹ C (Caughey–O'Kelly): the undamped mode shapes diagonalize C too.
    bool proportional = false;
    /// With proportional damping and closed-form modes: ζ_k = a_kᵀ C a_k / (2 ω_k) for mode
    /// vectors a_k normalized so that a_kᵀ M a_k = 1, in the order of the modes.
    std::vector<GiNaC::ex> modal_damping_ratios;
};

/// C, the characteristic polynomial in s and its closed forms at the linearization's
/// equilibrium (with the gyroscopic matrix G where L has one); `modes` (when given, with
/// closed forms, and G = 0) gives the modal damping ratios.
damping_result damped_oscillations(const model& scene, const linearization_result& linear,
                                   const simplifier& simplify, const modes_result* modes = nullptr);

/// C alone: −∂Q/∂q̇ at (q = at, q̇ = 0, inputs 0).
GiNaC::matrix damping_matrix(const model& scene, const std::vector<GiNaC::ex>& at, const simplifier& simplify);

} // namespace lagrange
