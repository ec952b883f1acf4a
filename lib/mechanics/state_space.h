// SPDX-License-Identifier: GPL-2.0-or-later
/** @file state_space.h
 *  The linearized input–output system at the equilibrium: the state-space form
 *  ẋ = A x + B u with x = (q, q̇), and the Laplace transfer function H(s) of each input
 *  to each coordinate from (s²M + s(C − G) + K) X(s) = B_q U(s). */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/linearization.h"
#include "mechanics/operating_point.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <vector>

namespace lagrange {

struct state_space_result {
    std::vector<GiNaC::ex> state;  ///< q₁ … qₙ, then q̇₁ … q̇ₙ (the scene's symbols)
    std::vector<GiNaC::ex> inputs; ///< the inputs' symbols, in scene order
    /// A = [[0, I], [−M⁻¹K, M⁻¹(G − C)]]: 2n × 2n, ∂(q̇, q̈)/∂(q, q̇) at the equilibrium, at
    /// rest, inputs 0. [1/τ, or q_i/(q_j τ) across coordinates]
    GiNaC::matrix a;
    /// B = [[0], [M⁻¹ B_q]]: 2n × m, ∂(q̇, q̈)/∂u there. [q_i/(τ² u_k) in its lower half]
    GiNaC::matrix b;
    GiNaC::matrix damping;      ///< C (damping.h), n × n [E·τ/(q_i q_j)]
    GiNaC::matrix input_matrix; ///< B_q = ∂Q/∂u at the equilibrium, at rest, inputs 0: n × m [E/(q_i u_k)]
};

/// B_q = ∂Q/∂u at (q = at, q̇ = 0, inputs 0): n × m, m = the number of inputs. Throws
/// computation_error when an entry depends on time there.
GiNaC::matrix input_matrix(const model& scene, const std::vector<GiNaC::ex>& at, const simplifier& simplify);

/// A and B at the linearization's equilibrium with the damping matrix `damping`. Throws
/// computation_error when the scene has no inputs (B would have no columns) — unless
/// `allow_no_inputs` — or M cannot be inverted.
state_space_result derive_state_space(const model& scene, const linearization_result& linear,
                                      const GiNaC::matrix& damping, const simplifier& simplify,
                                      bool allow_no_inputs = false);

/// H(s) of one input to one coordinate: X_q(s) = H(s) U(s).
struct transfer_function {
    std::size_t input = 0;      ///< index into model::inputs
    std::size_t coordinate = 0; ///< index into model::coordinates
    GiNaC::ex numerator;        ///< a polynomial in s
    GiNaC::ex denominator;      ///< a polynomial in s, primitive, leading coefficient positive
    GiNaC::ex function() const { return numerator / denominator; }
};

struct transfer_result {
    GiNaC::possymbol s;                    ///< named "s" unless the scene uses that name
    std::vector<transfer_function> entries; ///< by input, then by coordinate (scene order)
};

/// Every H(s) by Cramer's rule on s²M + s(C − G) + K, common factors cancelled, the
/// denominator made primitive in s (its coefficients' common factor moved into the
/// numerator, its leading coefficient positive).
transfer_result transfer_functions(const model& scene, const linearization_result& linear,
                                   const state_space_result& system);

/// The state-space form of a linearization about an operating point: its state, A and B
/// (no C or B_q: the transfer functions come from A and B).
state_space_result operating_state_space(const model& scene, const operating_linearization& point);

/// H(s) of each input to each coordinate from (sI − A) X = B U by Cramer's rule, a dependent
/// coordinate through δq = C₀ δq_I.
transfer_result operating_transfer(const model& scene, const operating_linearization& point,
                                   const state_space_result& system);

} // namespace lagrange
