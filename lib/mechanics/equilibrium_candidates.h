// SPDX-License-Identifier: GPL-2.0-or-later
/** @file equilibrium_candidates.h
 *  Points where equations in the coordinates hold, in closed form: the roots of one
 *  equation in one coordinate, and for several coordinates each angle coordinate (one
 *  inside a function) at 0 or π with the others solved from what remains (a linear
 *  system, or a polynomial system in two coordinates). The one search behind the
 *  equilibria of V (equilibrium.cpp) and the points that solve the equations at every t
 *  (time_dependence.cpp); each caller checks the candidates by its own rule. */
#pragma once

#include "core/model.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace lagrange {

/// The real roots of e = 0 in the one coordinate q, where they can be found in closed
/// form: a polynomial's linear factors and quadratic ones of known real roots, or a
/// trigonometric polynomial's roots in cos q. A rational e: those of its numerator
/// (the caller checks them).
std::vector<GiNaC::ex> solve_one(const GiNaC::ex& e, const GiNaC::symbol& q);

/// The coordinates inside a function (angles) of some equation, and the others, by index.
struct angle_split {
    std::vector<std::size_t> angles, others;
};
angle_split split_angles(const model& scene, const std::vector<GiNaC::ex>& equations);

/// The caller's test of a candidate point (one value per coordinate).
using point_check = std::function<bool(const std::vector<GiNaC::ex>&)>;

/// The point with the coordinates in `fixed` at their values and the `others` solved from
/// the linear system that remains (free directions at 0), if `solves` accepts it.
std::optional<std::vector<GiNaC::ex>> point_with_angles(const model& scene, const std::vector<GiNaC::ex>& equations,
                                                        const GiNaC::exmap& fixed,
                                                        const std::vector<std::size_t>& others,
                                                        const point_check& solves);

/// Every choice of 0 or π for the angles of `split`, each completed by point_with_angles
/// or else from a polynomial system in two others (the resultant); the points `solves`
/// accepts. 2^angles choices: the caller bounds their number.
std::vector<std::vector<GiNaC::ex>> points_at_angle_choices(const model& scene,
                                                            const std::vector<GiNaC::ex>& equations,
                                                            const angle_split& split, const point_check& solves);

} // namespace lagrange
