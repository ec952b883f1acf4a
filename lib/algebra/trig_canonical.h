// SPDX-License-Identifier: GPL-2.0-or-later
/** @file trig_canonical.h
 *  Exact canonical form of trigonometric polynomials in the coordinates: equal as
 *  functions of the angles exactly when the forms are equal. */
#pragma once

#include <ginac/ginac.h>

#include <optional>

namespace lagrange {

/// Canonical form of `e` as a trigonometric polynomial in `angles`: every sin/cos
/// whose argument is a linear combination of the angles (rational coefficients,
/// plus a constant) is written as a sum of c·cos(n·q + ...) and c·sin(n·q) with
/// integer vectors n whose first nonzero entry is positive, products linearized,
/// and the result expanded. Two expressions are equal as functions of the angles
/// iff their canonical forms are equal (given canonical coefficients).
/// The arguments may hold more than the angles: each monomial of an expanded
/// argument that is not an angle and holds a symbol not declared positive (w*t, x/R,
/// a*x) counts as one more angle, after the given ones, ordered by its printed form.
/// So cos²(w t) + sin²(w t) and cos²(x/R) + sin²(x/R) are 1, and a product of sines
/// and cosines of w*t and q is a sum of cos(q ± w t), sin(q ± w t). Monomials of
/// positive parameters alone (th0) and constants (π/2) stay offsets.
/// Other subexpressions (sqrt, exp) are kept as atoms, their arguments canonicalized
/// recursively.
GiNaC::ex trig_canonical(const GiNaC::ex& e, const GiNaC::lst& angles);

/// trig_canonical by the general path only, without the shortcut through harmonic
/// polynomials (the two agree exactly where the shortcut applies; tests compare them).
GiNaC::ex trig_canonical_general(const GiNaC::ex& e, const GiNaC::lst& angles);

/// True if a and b are equal as trigonometric polynomials in `angles`.
bool trig_equal(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::lst& angles);

/// `e` as a polynomial in s = sin q and c = cos q (expanded), if every occurrence of q is
/// in a sine or cosine of an integer multiple of q plus terms free of q:
/// sin(nq + b) = sin nq cos b + cos nq sin b, with cos nq + i sin nq = (c + i s)ⁿ.
std::optional<GiNaC::ex> trigonometric_polynomial(const GiNaC::ex& e, const GiNaC::ex& q, const GiNaC::ex& s,
                                                  const GiNaC::ex& c);

} // namespace lagrange
