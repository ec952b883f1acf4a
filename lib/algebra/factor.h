/** @file factor.h
 *  GiNaC's factor() where it is quick, and a budget checkpoint before it.
 *
 *  GiNaC factors a multivariate polynomial by Hensel lifting from random evaluation
 *  points, so the run time of one call varies from draw to draw, and at high degree
 *  an unlucky draw is slow — one call that the stage's time budget cannot interrupt.
 *  Every stage factors through here: above `factor_max_degree` in some symbol (or a
 *  power of a sum above it) the expression is returned as it is — exact, only not
 *  factored. */
#pragma once

#include <ginac/ginac.h>

namespace lagrange {

/// The largest exponent of a symbol (or of a sum raised to a power) handed to factor().
/// Every polynomial of the examples and of the homework is far below it; a 16-coordinate
/// characteristic polynomial in ω² is at it.
constexpr int factor_max_degree = 16;

/// Whether some power in `e` has an integer exponent above factor_max_degree in absolute value.
bool too_large_to_factor(const GiNaC::ex& e);

/// budget_check(), then GiNaC::factor(e), or `e` itself when too_large_to_factor(e).
GiNaC::ex factor_if_quick(const GiNaC::ex& e);

/// e.normal() and factor_if_quick(e.normal()) of an expression with π: GiNaC's gcd wants
/// polynomials over the rationals, so π goes through as a positive symbol.
GiNaC::ex normal_with_pi(const GiNaC::ex& e);
GiNaC::ex factor_with_pi(const GiNaC::ex& e);

} // namespace lagrange
