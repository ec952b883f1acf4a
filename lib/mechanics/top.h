// SPDX-License-Identifier: GPL-2.0-or-later
/** @file top.h
 *  The heavy symmetric top: Routh's reduction of its two cyclic angles and the
 *  sleeping-top criterion. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/lagrangian.h"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace lagrange {

/// A top: a body turned by z-x-z Euler angles that are three coordinates (φ, θ, ψ), with
/// φ and ψ cyclic. Routh's procedure with the cyclic momenta fixed at their sleeping
/// values p_φ = p_ψ = I3 ω3 gives V_eff(θ); its curvature at θ = 0 decides whether the
/// sleeping (vertical) top is stable.
struct top_result {
    std::string body;
    GiNaC::ex nutation;            ///< θ, the angle from the vertical
    GiNaC::ex pivot_moment;        ///< I1 about the fixed point: ∂²T/∂θ̇²
    GiNaC::ex spin_moment;         ///< I3: ∂²T/∂ψ̇²
    GiNaC::ex spin;                ///< the symbol ω3 = φ̇ cos θ + ψ̇ (conserved)
    GiNaC::ex effective_potential; ///< V_eff(θ) at p_φ = p_ψ = I3 ω3
    GiNaC::ex curvature;           ///< the coefficient of θ² in V_eff about θ = 0
    GiNaC::ex condition;           ///< 8 I1 × curvature: the sleeping top is stable when it is > 0
    /// Steady precession at the angle θ (θ̇ = 0, φ̇ = Ω, ω3 fixed): a2 Ω² + a1 Ω + a0 = 0
    /// (I1 cos θ Ω² − I3 ω3 Ω + M g l = 0), with a0's sign made positive where known.
    GiNaC::ex precession;                 ///< the symbol Ω
    std::vector<GiNaC::ex> precession_quadratic; ///< a0, a1, a2
    GiNaC::ex slow_precession;            ///< (−a1 − √(a1² − 4 a2 a0))/(2 a2): slow for ω3 > 0
    GiNaC::ex fast_precession;            ///< (−a1 + √(a1² − 4 a2 a0))/(2 a2)
    /// ω² of small nutation about a steady precession: V_eff''(θ)/I1 at the momenta of the
    /// precession, with the gravity strength eliminated by the condition above
    /// ((I3 ω3 − 2 I1 Ω cos θ)²/I1² + Ω² sin² θ). Empty where it could not be formed.
    GiNaC::ex nutation_frequency_squared;
};

/// The top analysis for every body that qualifies (none: empty).
std::vector<top_result> analyze_tops(const model& scene, const lagrangian_result& lagrangian,
                                     const simplifier& simplify);

} // namespace lagrange
