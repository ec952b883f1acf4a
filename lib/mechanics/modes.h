// SPDX-License-Identifier: GPL-2.0-or-later
/** @file modes.h
 *  The normal modes in closed form: the frequencies ω² as roots of the
 *  characteristic polynomial, a mode vector for each, and the normal coordinates. */
#pragma once

#include "core/model.h"
#include "mechanics/linearization.h"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace lagrange {

struct modes_result {
    bool closed_form = false;                 ///< false: no closed form found (numeric only)
    /// L has a part linear in the velocities (G ≠ 0, mechanics/gyroscopic.h): `frequencies`
    /// hold ω ≥ 0, not ω², and there are no real modes or normal coordinates.
    bool gyroscopic = false;
    /// The mode vectors and normal coordinates were asked for but left out: some ω² is a
    /// root of an irreducible cubic whose trigonometric form depends on the parameters,
    /// which makes each entry pages long (the numeric modes give them at values).
    bool vectors_left_out = false;
    /// For which roots they were left out, for the notes: "the roots of an irreducible cubic
    /// in the parameters, …" or "a repeated ω², whose modes … are not found in closed form".
    std::string vectors_left_out_why;
    std::vector<GiNaC::ex> frequencies;       ///< ω², ascending where the order is known [1/τ²]
    std::vector<std::vector<GiNaC::ex>> modes;///< one mode vector per frequency
    std::vector<GiNaC::ex> normal_coordinates;///< ζ_k = (Aᵀ T (q − q₀))_k with Aᵀ T A = I
    std::vector<GiNaC::ex> displacements;     ///< q − q₀ per coordinate (q where q₀ = 0)
    /// The same with the scene's `ratio` substituted (m -> rho*M), if it has one.
    std::vector<GiNaC::ex> frequencies_in_ratio;
    std::vector<std::vector<GiNaC::ex>> modes_in_ratio;
    std::vector<GiNaC::ex> normal_coordinates_in_ratio;
};

/// The roots ω² of the characteristic polynomial in closed form (every factor of
/// degree ≤ 3 in ω²), a mode vector for each and the normal coordinates; not
/// closed_form when some factor has a higher degree. Without `vectors`, the roots
/// alone; with them, still the roots alone when some root is an irreducible cubic's in
/// parameters (vectors_left_out).
modes_result symbolic_modes(const model& scene, const linearization_result& linear,
                            const characteristic_result& characteristic, bool vectors = true);

} // namespace lagrange
