// SPDX-License-Identifier: GPL-2.0-or-later
/** @file steady_motion.h
 *  Steady motions (relative equilibria): the non-cyclic coordinates at rest, the cyclic
 *  ones turning at constant rates. On the reduced system of Routh's procedure a steady
 *  motion is an equilibrium of the effective potential; its small oscillations are
 *  those of the Routhian, with the gyroscopic term the reduction leaves. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/equilibrium.h"
#include "mechanics/lagrangian.h"
#include "mechanics/linearization.h"
#include "mechanics/modes.h"
#include "mechanics/symmetries.h"

#include <ginac/ginac.h>

#include <complex>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

struct steady_motion_result {
    std::vector<std::size_t> kept, cyclic; ///< as in reduced_result
    std::vector<GiNaC::ex> position;       ///< a0, one per kept coordinate
    std::vector<GiNaC::ex> rates;          ///< one per cyclic coordinate: given, or solved for
    std::vector<bool> rate_given;
    std::vector<GiNaC::ex> momenta;        ///< p_c at the steady motion
    /// When the condition ∂L/∂a = 0 does not hold identically, it is solved for one
    /// unknown (a rate left out, else a rate named by a parameter): `lhs = rhs`, such as
    /// Ω² = g/(l cos θ0). Every result below uses it.
    std::optional<std::pair<GiNaC::ex, GiNaC::ex>> relation;
    /// What was substituted to impose it: one symbol (a rate left out, or a parameter) and
    /// its value in the others.
    GiNaC::exmap solution;
    linearization_result linear;           ///< reduced T, V and G at the steady motion
    characteristic_result characteristic;  ///< det(V − ω²T + iωG), in the kept coordinates
    modes_result modes;                    ///< the frequencies of small oscillations about it
    /// The symbols that stood for the rates left out (named as the velocities, `phi_dot`).
    std::vector<GiNaC::realsymbol> unknown_rates;
    /// Its stability on the reduced system, where the signs decide it for every value of the
    /// parameters: stable when the reduced V is positive definite (Routh; with G too, by
    /// Kelvin–Tait); unstable when det V < 0 (an odd number of negative stiffnesses, which no
    /// gyroscopic term stabilizes: Kelvin–Tait–Chetaev) or, without G, when an ω² is negative;
    /// otherwise unknown, and `stability_reason` says on what it depends.
    stability verdict = stability::unknown;
    std::string stability_reason;
    /// At each `values` point (numeric/steady_stability.h): the eigenvalues s of
    /// T q̈ − G q̇ + V q = 0 and the verdict there.
    struct at_point {
        std::vector<std::pair<std::string, double>> values;
        std::vector<std::complex<double>> eigenvalues;
        stability verdict = stability::unknown;
    };
    std::vector<at_point> at_values;
};

/// The scene's steady motion (`equilibrium theta = th0, phi' = Omega`). Throws
/// computation_error when a coordinate given a rate is not cyclic, a non-cyclic coordinate
/// has no value, or the point is not a steady motion and the condition cannot be solved.
steady_motion_result steady_motion(const model& scene, const lagrangian_result& lagrangian,
                                   const reduced_result& reduced, const simplifier& simplify);

} // namespace lagrange
