/** @file sign.h
 *  Exact decisions about expressions whose symbols are positive parameters:
 *  whether one vanishes, its sign for every positive value of the parameters,
 *  and a tidy form with numerator and denominator factored. */
#pragma once

#include <ginac/ginac.h>

#include <optional>

namespace lagrange {

/// True if e is zero as a rational function of its symbols and atoms.
bool vanishes(const GiNaC::ex& e);

/// e with numerator and denominator each factored; e itself if GiNaC fails
/// (budget_exceeded passes through).
GiNaC::ex tidy(const GiNaC::ex& e);

/// The sign of e for every positive value of the parameters, if it can be decided:
/// from the signs of the factors, powers and terms, else from those of the
/// numerator and denominator of its normal form (expanded or factored).
std::optional<int> sign_of(const GiNaC::ex& e);

} // namespace lagrange
