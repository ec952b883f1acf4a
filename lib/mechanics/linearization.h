/** @file linearization.h
 *  Small oscillations about an equilibrium: the kinetic and potential matrices
 *  T and V there, and the characteristic polynomial det(V − ω²T) made primitive. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "mechanics/lagrangian.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

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

/// det(V − ω²T) as a polynomial in ω, made primitive (see characteristic_coefficients).
characteristic_result characteristic_polynomial(const model& scene, const linearization_result& linear);

/// The primitive polynomial in w = ω² from det(V − w T): its coefficients, lowest
/// degree first, with every common factor removed and the leading one positive.
std::vector<GiNaC::ex> characteristic_coefficients(const GiNaC::matrix& kinetic, const GiNaC::matrix& potential,
                                                   const GiNaC::symbol& w);

} // namespace lagrange
