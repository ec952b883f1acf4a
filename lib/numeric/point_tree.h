// SPDX-License-Identifier: GPL-2.0-or-later
/** @file point_tree.h
 *  The accelerations of a tree of point masses and bodies by the articulated-body recursion
 *  (Featherstone, Rigid Body Dynamics Algorithms, 2008, ch. 7), written as a sequence of
 *  intermediate quantities: O(n) steps, where M q̈ = f has n² entries of M and an O(n³)
 *  factor. The right-hand side's form for long chains (compiled_motion, the export).
 *
 *  A scene is such a tree when it has no `T` or `L` lines, constraints, rolling contacts or
 *  free bodies, no position moves with t, no `V` line holds a velocity, and each point's and
 *  each body centre's position is a constant plus a sum of displacements d_j(q_j), one per
 *  coordinate, with the sets of coordinates they move with the paths from the root of a
 *  tree of coordinates. Each coordinate then carries a node: the points and centres that
 *  hang at it (it is the deepest coordinate they move with) at their displacements (its
 *  attachments), and the bodies that turn with it, and with nothing else. A child's subtree
 *  must hang at one attachment of its parent. Chains and branching pendulums in absolute
 *  angles, rods with several masses, a cart-pole, compound pendulums whose rods turn with
 *  their own angle are such trees; relative angles (a rod that turns with an earlier
 *  coordinate) and two coordinates in one displacement (a spherical joint) are not.
 *
 *  Attachment a of coordinate j moves along s_a = ∂d_a/∂q_j with the velocity-product
 *  acceleration c_a = ∂s_a/∂q_j q̇_j²; its bodies turn with rotational energy ½ k(q_j) q̇_j².
 *  Inwards, each attachment's articulated inertia I_a (3 × 3: its mass, plus what its
 *  children pass up) and bias p_a; the node passes Σ I_a − U Uᵀ/D and
 *  Σ (I_a c_a + p_a) + U u/D to its parent's attachment, with U = Σ I_a s_a,
 *  D = k + Σ s_a·I_a s_a and u = τ_j − ½ k′ q̇_j² − Σ s_a·(I_a c_a + p_a). Outwards,
 *  q̈_j = (u − U·a)/D with a the acceleration of the attachment it hangs at, and
 *  a_a = a + c_a + s_a q̈_j. Gravity is the root's acceleration −g; τ_j = −∂V/∂q_j + Q_j holds
 *  the rest of V (springs, `V` lines) and the generalized forces. */
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

/// The recursion of the scene, or nothing when the scene is not such a tree (see above).
/// `at` is applied to every mass, displacement, rotational energy, force and gravity before
/// the recursion is built (the values of the parameters, for compiled code; the identity
/// keeps them symbols). Each node must move a mass or turn a body, and no mass may be a
/// negative number: then its pivot D is positive wherever M is regular.
std::optional<point_tree_recursion> point_tree_accelerations(
    const model& scene, const equations_of_motion& equations,
    const std::function<GiNaC::ex(const GiNaC::ex&)>& at = [](const GiNaC::ex& e) { return e; });

} // namespace lagrange
