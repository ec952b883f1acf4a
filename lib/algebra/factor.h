// SPDX-License-Identifier: GPL-2.0-or-later
/** @file factor.h
 *  GiNaC's factor() where it is quick, and a budget checkpoint before it.
 *
 *  GiNaC factors a multivariate polynomial by Hensel lifting from random evaluation
 *  points, so the run time of one call varies from draw to draw, and at high degree
 *  an unlucky draw is slow — one call that the stage's time budget cannot interrupt.
 *  Every stage factors through here: above `factor_max_degree` in some symbol (or a
 *  power of a sum above it) the expression is returned as it is — exact, only not
 *  factored.
 *
 *  GiNaC's factor() is also slow on large polynomials in many symbols, the coefficients
 *  of a chain's characteristic polynomial among them: it factors the leading coefficient
 *  in every symbol before it lifts. Such a polynomial (more than four terms in more than
 *  three symbols) is factored by FLINT (algebra/integer_polynomial.h); the factors are
 *  the same, each irreducible factor written expanded rather than in GiNaC's nested
 *  form. */
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

/// The largest exponent of a symbol (or of a sum raised to a power) handed to factor().
/// Every polynomial of the examples and of the homework is far below it; a 16-coordinate
/// characteristic polynomial in ω² is at it.
constexpr int factor_max_degree = 16;

/// Whether some power in `e` has an integer exponent above factor_max_degree in absolute value.
bool too_large_to_factor(const GiNaC::ex& e);

/// budget_check(), then GiNaC::factor(e), or `e` itself when too_large_to_factor(e).
GiNaC::ex factor_if_quick(const GiNaC::ex& e);

/// The gcd of polynomials (zeros skipped; 0 if all are zero): by FLINT for polynomials
/// with integer coefficients, with a positive leading coefficient; else GiNaC's gcd.
GiNaC::ex polynomial_content(const std::vector<GiNaC::ex>& polynomials);

/// e.normal() and factor_if_quick(e.normal()) of an expression with π: GiNaC's gcd wants
/// polynomials over the rationals, so π goes through as a positive symbol.
GiNaC::ex normal_with_pi(const GiNaC::ex& e);
GiNaC::ex factor_with_pi(const GiNaC::ex& e);

} // namespace lagrange
