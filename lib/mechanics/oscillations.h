/** @file oscillations.h
 *  Small oscillations: equilibria and their stability, the linearization (T and V
 *  matrices), the characteristic polynomial det(V − ω²T) made primitive, and the
 *  symbolic frequencies, mode vectors, normal coordinates and asymptotic limits. */
#pragma once

#include "mechanics/lagrangian.h"
#include "core/model.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace lagrange {

enum class stability { stable, unstable, marginal, unknown };
std::string to_string(stability s); ///< "stable", "unstable", "marginal", "unknown"

struct equilibrium_point {
    std::vector<GiNaC::ex> position; ///< one value per coordinate
    stability kind = stability::unknown;
};

struct equilibria_result {
    std::vector<equilibrium_point> points; ///< every equilibrium found (or the one given)
    std::size_t chosen = 0;                ///< the one to linearize about (the stable one by default)
    bool given = false;                    ///< from the scene's `equilibrium` line
};

/// The `equilibrium` line if there is one (checked: ∂V/∂q = 0 there, else
/// computation_error), otherwise the solutions of ∂V/∂q = 0 found symbolically.
/// Throws computation_error when none is found.
equilibria_result find_equilibria(const model& scene, const lagrangian_result& lagrangian,
                                  const simplifier& simplify);

struct linearization_result {
    std::vector<GiNaC::ex> at;  ///< the equilibrium
    GiNaC::matrix kinetic;      ///< T_ij = ∂²T/∂q̇i∂q̇j at the equilibrium
    GiNaC::matrix potential;    ///< V_ij = ∂²V/∂qi∂qj at the equilibrium
};

/// T and V at `at`. Throws computation_error if T is not positive definite
/// (naming a coordinate with no kinetic energy where that is the cause).
linearization_result linearize(const model& scene, const lagrangian_result& lagrangian,
                               const std::vector<GiNaC::ex>& at, const simplifier& simplify);

struct characteristic_result {
    GiNaC::possymbol omega;  ///< named "omega" unless the scene uses that name
    GiNaC::ex polynomial;    ///< det(V − ω²T) made primitive, coefficients factored
};

characteristic_result characteristic_polynomial(const model& scene, const linearization_result& linear);

struct modes_result {
    bool closed_form = false;                 ///< false: no closed form found (numeric only)
    std::vector<GiNaC::ex> frequencies;       ///< ω², ascending where the order is known
    std::vector<std::vector<GiNaC::ex>> modes;///< one mode vector per frequency
    std::vector<GiNaC::ex> normal_coordinates;///< ζ_k = (Aᵀ T q)_k with Aᵀ T A = I
    /// The same with the scene's `ratio` substituted (m -> rho*M), if it has one.
    std::vector<GiNaC::ex> frequencies_in_ratio;
    std::vector<std::vector<GiNaC::ex>> modes_in_ratio;
    std::vector<GiNaC::ex> normal_coordinates_in_ratio;
};

modes_result symbolic_modes(const model& scene, const linearization_result& linear,
                            const characteristic_result& characteristic);

/// Two modes whose frequencies agree to leading order: they beat.
struct beat {
    std::size_t lower = 0, upper = 0; ///< indices of the two modes (ascending frequency)
    GiNaC::ex difference;             ///< ω_upper − ω_lower to leading order
    GiNaC::ex period;                 ///< 2π/(ω_upper − ω_lower) to leading order
};

struct asymptotic_result {
    std::string label; ///< "rho -> 0" or "rho -> oo"
    std::vector<GiNaC::ex> frequencies;        ///< ω², the leading term times (1 + corrections) until they differ
    std::vector<std::vector<GiNaC::ex>> modes;
    std::vector<GiNaC::ex> normal_coordinates; ///< leading term of each coefficient
    std::vector<beat> beats;                   ///< pairs with the same leading ω²
    /// Each ω² as {leading term, 1, correction, …} (ω² = leading·(1 + correction + …)),
    /// for printing in series order; empty where no series was found.
    std::vector<std::vector<GiNaC::ex>> frequency_series;
};

/// The leading behaviour of the frequencies and modes in the scene's `limit`.
asymptotic_result asymptotic_limit(const model& scene, const modes_result& modes);

} // namespace lagrange
