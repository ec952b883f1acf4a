// SPDX-License-Identifier: GPL-2.0-or-later
/** @file equilibrium_family.h
 *  Equilibria that are not isolated: where V = c·f² + V₀ (Størmer's effective potential
 *  ½(C/ρ − ρ/r³)²), every point of f = 0 is an equilibrium, and where ∇f ≠ 0 these
 *  points form a set of dimension n − 1 (a curve for two coordinates). Also the search
 *  for equilibria on the coordinate axes (all coordinates but one at 0), which finds
 *  points of such a set and the isolated equilibria beside it. */
#pragma once

#include "core/model.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace lagrange {

/// A set of equilibria given by one relation between the coordinates.
struct equilibrium_family {
    GiNaC::ex relation;         ///< the set is `relation = 0` (the numerator of f)
    std::size_t dimension = 1;  ///< n − 1: a curve for two coordinates
    int across = 0;             ///< the sign of c: +1, minima of V (stable across the set); −1, maxima
    GiNaC::ex potential;        ///< V on the set, V₀
};

/// The family f = 0 of V = c·f² + V₀ (c and V₀ free of the coordinates, c of known sign,
/// two or more coordinates) when it passes through `point` with ∇f ≠ 0 there (so that it
/// is a set of dimension n − 1 near the point, not an isolated zero of f).
std::optional<equilibrium_family> family_through(const model& scene, const GiNaC::ex& potential,
                                                 const std::vector<GiNaC::ex>& point);

/// Whether `point` lies on the family's set.
bool on_family(const model& scene, const equilibrium_family& family, const std::vector<GiNaC::ex>& point);

/// The points with every coordinate but one at 0 where each component of `gradient`
/// vanishes, the free one solved in closed form (solve_one). A power of q² counts as one
/// of q on the branch q > 0 (ρ on the axis z = 0 of ρ² + z²); its roots there must be positive.
std::vector<std::vector<GiNaC::ex>> axis_equilibria(const model& scene, const std::vector<GiNaC::ex>& gradient);

} // namespace lagrange
