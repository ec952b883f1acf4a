// SPDX-License-Identifier: GPL-2.0-or-later
/** @file exported_system.h
 *  The equations of motion as the functions that exported code evaluates (`lagrange
 *  export`): M(t, q, q̇, u, p) and F(t, q, q̇, u, p) of M q̈ = F, the energy function, and
 *  the derivatives that make the Jacobians of ẋ = f(t, x, u, p), x = (q, q̇), and for a tree
 *  of point masses q̈ by the articulated-body recursion, each compiled once into
 *  straight-line programs with their common subexpressions shared. Parameters and inputs
 *  stay symbols: the exported functions take them as arguments. */
#pragma once

#include "core/model.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/linearization.h"
#include "mechanics/symmetries.h"
#include "program/expression_program.h"

#include <optional>
#include <string>
#include <vector>

namespace lagrange {

struct exported_system {
    std::size_t coordinates = 0; ///< n; the state has 2n entries
    std::vector<std::string> state_names;     ///< q₁ … qₙ, then their velocities `q_dot` [units of q, q/time]
    std::vector<std::string> parameter_names; ///< in the scene's order
    std::vector<std::string> input_names;     ///< in the scene's order
    /// Each program reads the symbols (q₁ … qₙ, q̇₁ … q̇ₙ, t, p₁ … p_P, u₁ … u_m) in that order.
    expression_program mass;        ///< M, row-major n × n [the kinetic energy's unit / (q/time)²]
    expression_program mass_and_forcing; ///< M then F in one program (their common parts once): the right-hand side's
    expression_program forcing;     ///< F (n): ∂L/∂q − (dM/dt) q̇ − ∂p/∂t + Q
    /// q̈ (n) by the articulated-body recursion (numeric/point_tree.h), O(n) where solving
    /// M q̈ = F is O(n³): the right-hand side's form, as the engine's own, when the scene is a
    /// tree of point masses with at least recursive_coordinates coordinates. A zero pivot
    /// of the recursion (where M is singular) makes a q̈ infinite or NaN.
    std::optional<expression_program> recursion;
    expression_program energy;      ///< h = Σ q̇ ∂L/∂q̇ − L (1) [energy]
    /// ∂M/∂q_k for each k (n³, k slowest), ∂F/∂q (n², row i = F_i), ∂F/∂q̇ (n²), ∂F/∂u (n·m)
    expression_program derivatives;
    std::vector<double> defaults; ///< each parameter's value in the scene's first `values` line, NaN where none
    /// At the equilibrium the linearization is about, as functions of the parameters only: the
    /// state there (2n: q at rest, then q̇ = 0), then T and V of the small oscillations
    /// (n × n each, row-major). Absent when the export was given no linearization, or its
    /// point depends on more than the parameters.
    std::optional<expression_program> linear;
    /// With constraints (M q̈ = F + Aᵀλ, A q̈ = −c): their names, and one program of A (m × n,
    /// row-major), c (m) and the residuals g (m: f(q, t) of a holonomic one, A q̇ + b of a
    /// Pfaffian one), m = the number of constraints; and for the Jacobian, ∂A/∂q_k (m × n each,
    /// k slowest), ∂c/∂q (m × n, row r = c_r), ∂c/∂q̇ (m × n) and ∂c/∂u (m × inputs).
    std::vector<std::string> constraint_names;
    std::optional<expression_program> constraint_parts;
    std::optional<expression_program> constraint_derivatives;
    /// What the motion conserves: the energy function h (named `energy`) where L does not
    /// depend on t, then the momentum ∂L/∂q̇ of each cyclic coordinate (named `p_` + its name).
    /// Absent when the export was given none, or nothing is conserved.
    std::vector<std::string> conserved_names;
    std::optional<expression_program> conserved;
};

/// The exported system of `scene`, with `linear` from `linearization` and `conserved` from
/// `conserved` when given. Throws computation_error for expressions that cannot be compiled.
exported_system export_system(const model& scene, const equations_of_motion& equations,
                              const linearization_result* linearization = nullptr,
                              const conserved_result* conserved = nullptr);

} // namespace lagrange
