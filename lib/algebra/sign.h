/** @file sign.h
 *  The sign and the value of an expression, from its factored form or at a parameter
 *  point, where they can be told. */
#pragma once

#include <ginac/ginac.h>

#include <optional>

namespace lagrange {

/// e at `values`, if that evaluates to a real number.
std::optional<double> number_at(const GiNaC::ex& e, const GiNaC::exmap& values);

/// The sign of e: +1, −1, 0, or nothing if it cannot be told (also at `values`: then a
/// value within 1e-14 relative of 0 counts as 0).
std::optional<int> sign_at(const GiNaC::ex& e, const GiNaC::exmap& values);

} // namespace lagrange
