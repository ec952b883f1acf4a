// SPDX-License-Identifier: GPL-2.0-or-later
/** @file operating_point.h
 *  Linearization about any operating point, with holonomic and Pfaffian constraints, in the
 *  independent coordinates and speeds: the meaning of SymPy's `Linearizer` (Peterson, Gede
 *  and Hubbard, Multibody Syst. Dyn. 33, 2015). With the constraints f(q) = 0 and
 *  A(q) q̇ + b(q) = 0, and q̈ = φ(q, q̇, u) solved from [M −Aᵀ; A 0] [q̈; λ] = [f + Q; −c]:
 *      δq = C₀ δq_I                      (f_q δq = 0),
 *      δq̇ = C₁ δq + C₂ δq̇_J              (the velocity constraints linearized),
 *  and the state x = (q_I, q̇_J) moves by ẋ = F(x, u), whose Jacobian at the point is
 *      A = [[(C₁C₀)_I, (C₂)_I], [((φ_q + φ_q̇ C₁) C₀)_J, (φ_q̇ C₂)_J]],  B = [[0], [(φ_u)_J]].
 *  Where F(x₀, u₀) ≠ 0 the point is not an equilibrium: the residual is kept beside A, B. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/equations_of_motion.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <string>
#include <vector>

namespace lagrange {

struct operating_linearization {
    std::vector<std::size_t> coordinates; ///< the independent coordinates q_I (indices, scene order)
    std::vector<std::size_t> speeds;      ///< the independent speeds q̇_J (indices, scene order)
    bool chosen = false;                  ///< chosen by the engine (no `independent` line)
    /// The point: every coordinate's value (its own symbol where it is left free), every
    /// velocity (solved for the dependent speeds not given), every input.
    std::vector<GiNaC::ex> position, velocity, inputs;
    std::vector<GiNaC::ex> state;         ///< q_I then q̇_J (the scene's symbols)
    GiNaC::matrix a, b;                   ///< ẋ ≈ F(x₀, u₀) + A δx + B δu
    std::vector<GiNaC::ex> residual;      ///< F(x₀, u₀) = (q̇_I, q̈_J) at the point
    std::vector<GiNaC::ex> accelerations; ///< q̈ at the point, every coordinate
    std::vector<GiNaC::ex> multipliers;   ///< λ at the point, one per constraint
    GiNaC::matrix configuration;          ///< C₀: δq = C₀ δq_I (n × |I|)
    enum class kind {
        equilibrium, ///< every velocity and acceleration is 0: F(x₀, u₀) = 0
        steady,      ///< every acceleration is 0, some velocity is not: a steady motion
        moving       ///< some acceleration is not 0
    };
    kind point_kind = kind::equilibrium;
    std::vector<std::size_t> moving;      ///< steady: the coordinates whose velocity is not 0
    /// det(sI − A) with its denominators cleared, leading coefficient positive, factored: the
    /// eigenvalues of A are its roots in `s` (named "s" unless the scene uses that name).
    GiNaC::ex characteristic;
    /// Why det(sI − A) was not expanded (A's coupled block too large to be worth it: the
    /// bicycle's); empty when `characteristic` holds it.
    std::string characteristic_left_out;
    GiNaC::realsymbol s;
    /// steady: whether the moving coordinates enter no equation (M, f, Q, the constraints),
    /// so that A and B hold all along the motion, not at this instant only.
    bool moving_cyclic = false;
};

/// Whether a scene's `state_space` is computed here: it has constraints or a
/// `linearize about` line.
bool linearizes_about_operating_point(const model& scene);

/// The states of A left when those whose row or column of A is 0 are taken out, again
/// until none is (indices, ascending): such a state's row or column of sI − A is s e_i, so
/// it gives a factor s of det(sI − A), an eigenvalue 0 at every parameter value, and the
/// rest is the determinant without it. The bicycle's position, heading and wheel angles
/// (ignorable coordinates) leave its 4 × 4 lean and steer block.
std::vector<std::size_t> coupled_states(const GiNaC::matrix& a);

/// A, B and the residual at the scene's `linearize about` point (else its `equilibrium`
/// line: at rest, or the steady motion it names). Throws scene_error, at the statement, when the point violates a
/// constraint (with the residual) or the `independent` line does not span the constraints;
/// computation_error when there is no point, the equations depend on t, or M with the
/// constraints is singular there.
operating_linearization linearize_about(const model& scene, const equations_of_motion& equations,
                                        const simplifier& simplify);

} // namespace lagrange
