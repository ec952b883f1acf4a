// SPDX-License-Identifier: GPL-2.0-or-later
/** @file point_tree.h
 *  The accelerations of a tree of point masses by the articulated-body recursion
 *  (Featherstone, Rigid Body Dynamics Algorithms, 2008, ch. 7), written as a sequence of
 *  intermediate quantities: O(n) steps, where M q̈ = f has n² entries of M and an O(n³)
 *  factor. The right-hand side's form for long chains (compiled_motion, the export).
 *
 *  A scene is such a tree when it has point masses only (no bodies, `T` or `L` lines,
 *  constraints or rolling contacts), no position moves with t, no `V` line holds a
 *  velocity, and each point's position is a constant plus a sum of displacements d_j(q_j),
 *  one per coordinate, with the same d_j in every point that moves with q_j, and with the
 *  points' coordinate sets the paths from the root of a tree: a chain or a branching
 *  pendulum in absolute angles, a bead on a wire carrying a pendulum. Relative angles,
 *  two masses on one rod and two coordinates in one displacement (a spherical joint) are
 *  not such trees: their displacements turn with an earlier coordinate.
 *
 *  Each coordinate j then moves a node (its points and everything hanging from them) along
 *  s_j = ∂d_j/∂q_j, with the velocity-product acceleration c_j = ∂s_j/∂q_j q̇_j². Inwards,
 *  each node's articulated inertia I_j (d × d, its mass plus its children's I − U Uᵀ/D) and
 *  bias p_j; outwards, q̈_j = (τ_j − s_j·p_j − U_j·(a_parent + c_j))/D_j with U_j = I_j s_j and
 *  D_j = s_j·U_j, and a_j = a_parent + c_j + s_j q̈_j. Gravity is the root's acceleration −g;
 *  τ_j = −∂V/∂q_j + Q_j holds the rest of V (springs, `V` lines) and the generalized forces. */
#pragma once

#include "core/model.h"
#include "mechanics/equations_of_motion.h"
#include "program/expression_program.h"

#include <ginac/ginac.h>

#include <functional>
#include <optional>
#include <vector>

namespace lagrange {

/// The recursion: `definitions` in order, then q̈_i in the scene's coordinate order, in the
/// state symbols (state_symbols), the parameters and the definitions' symbols.
struct point_tree_recursion {
    std::vector<program_definition> definitions;
    std::vector<GiNaC::ex> accelerations;
};

/// The recursion of the scene's points, or nothing when the scene is not such a tree (see
/// above). `at` is applied to every mass, displacement, force and gravity before the
/// recursion is built (the values of the parameters, for compiled code; the identity keeps
/// them symbols); a node mass that is then a number must be positive (a massless node, or
/// a non-positive mass, can make M singular, which the recursion would not notice).
std::optional<point_tree_recursion> point_tree_accelerations(
    const model& scene, const equations_of_motion& equations,
    const std::function<GiNaC::ex(const GiNaC::ex&)>& at = [](const GiNaC::ex& e) { return e; });

} // namespace lagrange
