// SPDX-License-Identifier: GPL-2.0-or-later
/** @file sign.h
 *  Exact decisions about expressions whose symbols are positive parameters:
 *  whether one vanishes, its sign for every positive value of the parameters,
 *  a tidy form with numerator and denominator factored; and the value and sign of an
 *  expression at a parameter point. */
#pragma once

#include <ginac/ginac.h>

#include <optional>

namespace lagrange {

/// True if e is zero as a rational function of its symbols and atoms.
bool vanishes(const GiNaC::ex& e);

/// Whether every entry of `m` vanishes.
bool is_zero_matrix(const GiNaC::matrix& m);

/// e with numerator and denominator each factored; e itself if GiNaC fails
/// (budget_exceeded passes through).
GiNaC::ex tidy(const GiNaC::ex& e);

/// The sign of e for every positive value of the parameters, if it can be decided:
/// from the signs of the factors, powers and terms, else from those of the
/// numerator and denominator of its normal form (expanded or factored).
std::optional<int> sign_of(const GiNaC::ex& e);

/// e at `values`, if that evaluates to a real number.
std::optional<double> number_at(const GiNaC::ex& e, const GiNaC::exmap& values);

/// The sign of e: +1, −1, 0, or nothing if it cannot be told (also at `values`: then a
/// value within 1e-14 relative of 0 counts as 0).
std::optional<int> sign_at(const GiNaC::ex& e, const GiNaC::exmap& values);

} // namespace lagrange
