// SPDX-License-Identifier: GPL-2.0-or-later
/** @file assumptions.h
 *  What the derivation assumes of the values of a scene's symbols, and the one check
 *  that a value agrees with it. Every place that gives a parameter a number (a scene's
 *  `values` line, --values, --sweep, --grid of an ensemble, the Python module, which
 *  goes through --values' parser) calls parameter_value_contradiction and reports what
 *  it returns as a bad input (exit 2), located at the value.
 *
 *  - Parameters (`parameters a b …`) are GiNaC `possymbol`s, real and positive. The
 *    simplifier and GiNaC itself use that everywhere, silently: √(l²) = l, |m| = m,
 *    (a·b)^p = a^p·b^p, ω² sorted by the sign of parameter expressions, the stability of
 *    an equilibrium read from the signs of V's coefficients. At a value ≤ 0 the results
 *    are those of a different system, so such a value is refused rather than computed
 *    with (docs/reliability.md, "Assumptions").
 *  - Coordinates, velocities, inputs and multipliers are `realsymbol`s: real. Initial
 *    states and inputs' values are checked to be real where they are read.
 *  A mass, a body's dimension or a moment that is not positive at the values is refused
 *  by the scene's lowering (check_physical), as it names the quantity, not the value. */
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <string>

namespace lagrange {

/// Why `value` cannot be a value of the parameter `name`: "parameter `l` is assumed
/// positive (…), so its value -2 contradicts the derivation", and the like for a value
/// that is not a real number or not finite; nothing when the value agrees. `value` is
/// evaluated numerically (evalf).
std::optional<std::string> parameter_value_contradiction(const std::string& name, const GiNaC::ex& value);
std::optional<std::string> parameter_value_contradiction(const std::string& name, double value);

} // namespace lagrange
