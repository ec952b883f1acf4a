// SPDX-License-Identifier: GPL-2.0-or-later
/** @file equilibrium.h
 *  The equilibria of V and their stability: the scene's `equilibrium` line
 *  checked, or the solutions of ∂V/∂q = 0 found symbolically, each classified
 *  by the Hessian of V there. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/equilibrium_family.h"
#include "mechanics/lagrangian.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lagrange {

enum class stability { stable, unstable, marginal, unknown };
std::string to_string(stability s); ///< "stable", "unstable", "marginal", "unknown"

struct equilibrium_point {
    std::vector<GiNaC::ex> position; ///< one value per coordinate
    stability kind = stability::unknown;
};

struct equilibria_result {
    std::vector<equilibrium_point> points; ///< every equilibrium found (or the one given)
    std::size_t chosen = 0;                ///< the one to linearize about (the stable one by default)
    bool given = false;                    ///< from the scene's `equilibrium` line
    /// A set of equilibria that are not isolated (f = 0 of V = c·f²); `points` then holds
    /// one point of it (the one linearized about where chosen) and the equilibria off it.
    std::optional<equilibrium_family> family;
};

/// The `equilibrium` line if there is one (checked: ∂V/∂q = 0 there, else
/// computation_error), otherwise the solutions of ∂V/∂q = 0 found symbolically.
/// Throws computation_error when none is found.
equilibria_result find_equilibria(const model& scene, const lagrangian_result& lagrangian,
                                  const simplifier& simplify);

/// e with the coordinates at `at` and the velocities at zero. Where a value is not
/// a rational multiple of π, sines and cosines of multiple angles are first written
/// through sin q and cos q, so that q = acos(x) substitutes to exact roots.
GiNaC::ex evaluate_at(const GiNaC::ex& e, const model& scene, const std::vector<GiNaC::ex>& at);

/// e with tangents written as sin/cos, multiple angles through sin a and cos a, and for
/// every argument u of a sine or cosine sin² u = 1 − cos² u in numerator and denominator,
/// common factors cancelled: equal to e, and 0 exactly when e vanishes identically.
GiNaC::ex reduce_trigonometric(const GiNaC::ex& e);

/// ∂²V/∂qi∂qj at a point, each entry tidied (the V matrix of the linearization).
GiNaC::matrix potential_hessian(const model& scene, const GiNaC::ex& potential, const std::vector<GiNaC::ex>& at);

/// ∂²T/∂q̇i∂q̇j of the kinetic energy `kinetic` at a point, each entry tidied (the T
/// matrix of the linearization).
GiNaC::matrix kinetic_matrix(const model& scene, const GiNaC::ex& kinetic, const std::vector<GiNaC::ex>& at);

} // namespace lagrange
