// SPDX-License-Identifier: GPL-2.0-or-later
/** @file verify.h
 *  Self-verification: every symbolic result is checked numerically, by a route that
 *  does not share the symbolic derivation, before it is printed. The reference is the
 *  Lagrangian as built (before simplification), compiled once and evaluated in
 *  double-double; derivatives of it are taken by finite differences. The points are
 *  seeded, so the checks (and their messages) are the same on every run.
 *
 *  What is checked, one file per family (verify_results dispatches to them):
 *  - verify.cpp: the equations of motion, equilibria and linearization (T, V) against the
 *    Lagrangian as built, by finite differences in double-double;
 *  - check_modes.cpp: the characteristic polynomial, ω², modes and normal coordinates
 *    against the pencil (V, T) at parameter points (LU and Eigen's generalized solver);
 *  - check_asymptotic.cpp: the limits against the exact frequencies near the limit;
 *  - check_damping.cpp: C, the damped eigenvalues and the transfer function, against the
 *    Rayleigh function and the forces as the scene gave them;
 *  - check_constraints.cpp: the multipliers, constraint forces and reduced linearization;
 *  - check_symmetries.cpp: conserved quantities, the Hamiltonian, the effective potential
 *    and steady motions;
 *  - check_bodies.cpp: inertia tensors by cubature, Euler's equations and the free body's
 *    solutions;
 *  - check_floquet.cpp: the multipliers against the flow of the full equations.
 *  points.h holds what they share: the seeded points, the tolerance and the messages. */
#pragma once

#include "bodies/euler.h"
#include "bodies/inertia.h"
#include "core/model.h"
#include "mechanics/asymptotic.h"
#include "numeric/floquet.h"
#include "mechanics/damping.h"
#include "mechanics/constrained_linearization.h"
#include "mechanics/constraints.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/equilibrium.h"
#include "mechanics/lagrangian.h"
#include "mechanics/linearization.h"
#include "mechanics/modes.h"
#include "mechanics/steady_motion.h"
#include "mechanics/symmetries.h"
#include "mechanics/state_space.h"

#include <set>
#include <string>
#include <vector>

namespace lagrange {

/// One checked (or uncheckable) product: `item` is its JSON key, `how` says how it was
/// checked, or, when `checked` is false, why it could not be.
struct verification_entry {
    std::string item;
    std::string how;
    bool checked = true;
};

struct verification_result {
    std::vector<verification_entry> entries; ///< in product order
};

/// The results the checks read, one line each: the type and the name, which is also the
/// name of the field of `analysis` (engine/analysis.h) that verification_input_of copies.
/// `transfer` is checked only with `state_space`; with `constrained`, `linearization` is
/// the reduced one; `inertia` goes with `euler` (check_bodies.h).
#define LAGRANGE_VERIFIED_RESULTS(X)                                                                      \
    X(lagrangian_result, lagrangian)                                                                      \
    X(equations_of_motion, equations)                                                                     \
    X(equilibria_result, equilibria)                                                                      \
    X(linearization_result, linearization)                                                                \
    X(characteristic_result, characteristic)                                                              \
    X(modes_result, modes)                                                                                \
    X(damping_result, damping)                                                                            \
    X(conserved_result, conserved)                                                                        \
    X(hamiltonian_result, hamiltonian)                                                                    \
    X(reduced_result, reduced)                                                                            \
    X(steady_motion_result, steady)                                                                       \
    X(state_space_result, state_space)                                                                    \
    X(transfer_result, transfer)                                                                          \
    X(multipliers_result, multipliers)                                                                    \
    X(constrained_linearization, constrained)                                                             \
    X(asymptotic_result, asymptotic)                                                                      \
    X(std::vector<floquet_point>, floquet)                                                                \
    X(std::vector<inertia_result>, inertia)                                                               \
    X(std::vector<euler_result>, euler)

/// What the checks read; a null pointer is a product that was not computed.
struct verification_input {
#define LAGRANGE_VERIFIED_FIELD(type, name) const type* name = nullptr;
    LAGRANGE_VERIFIED_RESULTS(LAGRANGE_VERIFIED_FIELD)
#undef LAGRANGE_VERIFIED_FIELD
};

/// Checks every result given (`shown`: the products printed, which name the entries of
/// the frequencies, modes and normal coordinates). Throws computation_error
/// "verification failed: …" naming the product and the point when a result disagrees
/// with its numeric reference.
verification_result verify_results(const model& scene, const verification_input& input,
                                   const std::set<product>& shown);

/// The damping matrix C against the Rayleigh function and the forces as the scene wrote
/// them (beside the equilibrium, at up to two parameter points), and det(K + sC + s²M)
/// against the printed polynomial at complex s: the entries `damping` and
/// `damped_characteristic` (check_damping.cpp). Throws computation_error
/// "verification failed: …" on a disagreement.
std::vector<verification_entry> verify_damping(const model& scene, const linearization_result& linear,
                                               const damping_result& damping);

/// A and B against M⁻¹ of the linearization's T, V, G with C and ∂Q/∂u taken from the
/// statements by differences; each H(s) (when `transfer` is given) against
/// (s²M + s(C − G) + K)⁻¹ ∂Q/∂u by LU at complex s: the entries `state_space` and
/// `transfer`. Throws computation_error "verification failed: …" on a disagreement.
std::vector<verification_entry> verify_linear_system(const model& scene, const linearization_result& linear,
                                                     const state_space_result& system,
                                                     const transfer_result* transfer);

/// The asymptotic ω² against the eigenvalues of (V, T) with the limit's variable (a
/// parameter, or a ratio of two) at 10⁻⁴ and 10⁻⁸ (10⁴ and 10⁸ for a limit at ∞), the other
/// parameters at the first `values` line: the entry `asymptotic`
/// (check_asymptotic.cpp). Throws computation_error "verification failed: …" when
/// the leading terms do not approach the eigenvalues.
verification_entry verify_asymptotic(const model& scene, const linearization_result& linear,
                                     const asymptotic_result& limit);

/// The Floquet multipliers of each point and `values` line against the monodromy of the
/// nonlinear equations' own flow, by central differences of solutions started beside the
/// point (check_floquet.cpp): the entry `floquet`. Throws computation_error
/// "verification failed: …" on a disagreement.
verification_entry verify_floquet(const model& scene, const equations_of_motion& equations,
                                  const std::vector<floquet_point>& points);

} // namespace lagrange
