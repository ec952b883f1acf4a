// SPDX-License-Identifier: GPL-2.0-or-later
/** @file symmetries.h
 *  Symmetries of L: the conserved energy function and cyclic momenta, the Hamiltonian
 *  by the Legendre transform with Hamilton's equations, and Routh's reduction of the
 *  cyclic coordinates (the Routhian and the effective potential). */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/lagrangian.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace lagrange {

/// The coordinates that L holds only through their velocities (cyclic, or ignorable), in
/// coordinate order: L in canonical form has q̇ but not q.
std::vector<std::size_t> cyclic_coordinates(const model& scene, const lagrangian_result& lagrangian);

/// The energy function h = Σ q̇ ∂L/∂q̇ − L (conserved when ∂L/∂t = 0; not T + V where L
/// has parts of degree 1 or 0 from T, as in a turning frame) and the momentum of every
/// cyclic coordinate, simplified.
struct conserved_result {
    std::optional<GiNaC::ex> energy;  ///< h; none when L depends on t
    std::vector<std::size_t> cyclic;  ///< the cyclic coordinates
    std::vector<GiNaC::ex> momenta;   ///< p_q = ∂L/∂q̇ of each cyclic coordinate, in the same order
};

/// Throws computation_error when the scene has generalized forces (dissipation, applied
/// forces, inputs): then neither h nor the cyclic momenta need be conserved.
conserved_result conserved_quantities(const model& scene, const lagrangian_result& lagrangian,
                                      const equations_of_motion& equations, const simplifier& simplify);

/// The momentum symbol p_q of a coordinate (named `p_` + its name).
GiNaC::realsymbol momentum_symbol(const coordinate& c);

/// H(q, p) = Σ p q̇ − L with q̇ = M⁻¹(p − b) (L = ½ q̇ᵀM q̇ + bᵀq̇ − U): H = ½(p − b)ᵀM⁻¹(p − b) + U,
/// and Hamilton's equations q̇ = ∂H/∂p, ṗ = −∂H/∂q.
struct hamiltonian_result {
    std::vector<GiNaC::realsymbol> momenta; ///< p_q, one per coordinate
    GiNaC::ex hamiltonian;                  ///< H in the coordinates, the momenta and t
    std::vector<GiNaC::ex> velocities;      ///< q̇_i = ∂H/∂p_i
    std::vector<GiNaC::ex> forces;          ///< ṗ_i = −∂H/∂q_i
    /// The same without simplification, for the numeric check and the integrators.
    GiNaC::ex hamiltonian_raw;
    std::vector<GiNaC::ex> velocities_raw, forces_raw;
};

/// Throws computation_error when L is not quadratic in the velocities, or when the velocity
/// Hessian ∂²L/∂q̇² is singular (naming a coordinate with no kinetic energy where that is why).
hamiltonian_result derive_hamiltonian(const model& scene, const lagrangian_result& lagrangian,
                                      const equations_of_motion& equations, const simplifier& simplify);

/// Routh's reduction: with the cyclic momenta p_c held constant, ċ = M_cc⁻¹(p − b_c − M_ca ȧ)
/// and R = L − Σ p_c ċ_c, a Lagrangian of the remaining coordinates a:
/// R = ½ȧᵀ(M_aa − M_ac M_cc⁻¹ M_ca)ȧ + ȧᵀ(b_a + M_ac M_cc⁻¹(p − b_c)) − U_eff,
/// U_eff = U + ½(p − b_c)ᵀ M_cc⁻¹ (p − b_c).
struct reduced_result {
    std::vector<std::size_t> cyclic;        ///< the cyclic coordinates c
    std::vector<std::size_t> kept;          ///< the others, a
    std::vector<GiNaC::realsymbol> momenta; ///< p_c, constants of the reduced system
    GiNaC::ex routhian;                     ///< R(a, ȧ; p), simplified
    GiNaC::ex effective_potential;          ///< U_eff(a; p), simplified
    /// Unsimplified pieces: R's parts of degree 2, 1 and 0 in ȧ (R0 = −U_eff) as sums that
    /// keep M_cc's determinant as a denominator (what the steady motions differentiate).
    GiNaC::ex quadratic_raw, linear_raw, potential_raw;
    /// The steady motions ȧ = 0, ċ = const: for each kept coordinate whose condition
    /// ∂L/∂a = 0 can be solved for one cyclic rate, `lhs = rhs` (φ̇² = g/(l cos θ)).
    struct family_member {
        std::size_t coordinate;  ///< the kept coordinate whose condition this is
        GiNaC::ex lhs;           ///< the rate or its square
        std::vector<GiNaC::ex> rhs; ///< one or two values
    };
    std::vector<family_member> family;
    /// Equilibria of U_eff in closed form where one kept coordinate is not an angle and the
    /// condition is polynomial of degree ≤ 2 in it (Kepler: r0 = p²/(m k)).
    struct circular {
        std::size_t coordinate;
        std::vector<GiNaC::ex> values;
    };
    std::vector<circular> circular_orbits;
};

/// Throws computation_error when no coordinate is cyclic or L is not quadratic in the velocities.
/// The kinetic blocks are those of the equations' mass matrix M.
reduced_result reduce_cyclic(const model& scene, const lagrangian_result& lagrangian,
                             const equations_of_motion& equations, const simplifier& simplify);

/// e tidied for printing: multiple angles through single ones, sin² = 1 − cos² in
/// numerator and denominator, common factors cancelled, factored.
GiNaC::ex tidy_trigonometric(const GiNaC::ex& e);

} // namespace lagrange
