/** @file simplify.h
 *  Exact canonical form of trigonometric polynomials in the coordinates, and the
 *  simplifier that the mechanics stages use (canonical form, then rules, then a
 *  compact grouping by velocities and accelerations). */
#pragma once

#include "algebra/rules.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

class harmonic_polynomial;

/// Canonical form of `e` as a trigonometric polynomial in `angles`: every sin/cos
/// whose argument is a linear combination of the angles (rational coefficients,
/// plus a constant) is written as a sum of c·cos(n·q + ...) and c·sin(n·q) with
/// integer vectors n whose first nonzero entry is positive, products linearized,
/// and the result expanded. Two expressions are equal as functions of the angles
/// iff their canonical forms are equal (given canonical coefficients).
/// Other subexpressions (sqrt, exp, sin of non-linear arguments) are kept as atoms,
/// their arguments canonicalized recursively.
GiNaC::ex trig_canonical(const GiNaC::ex& e, const GiNaC::lst& angles);

/// trig_canonical by the general path only, without the shortcut through harmonic
/// polynomials (the two agree exactly where the shortcut applies; tests compare them).
GiNaC::ex trig_canonical_general(const GiNaC::ex& e, const GiNaC::lst& angles);

/// True if a and b are equal as trigonometric polynomials in `angles`.
bool trig_equal(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::lst& angles);

/// Writes `e` as a sum over the distinct monomials in `variables` (e.g. the
/// accelerations and velocities) and in the functions of `angles` (cos(theta-phi)),
/// each coefficient factored: the compact form
/// (M+m)*l^2*theta_ddot + m*l^2*cos(theta-phi)*phi_ddot + ...
GiNaC::ex collect_compact(const GiNaC::ex& e, const GiNaC::lst& variables, const GiNaC::lst& angles = {});

/// collect_compact(to_ex(p), variables, angles), grouped in the harmonic polynomial.
GiNaC::ex collect_compact(const harmonic_polynomial& p, const GiNaC::lst& variables, const GiNaC::lst& angles = {});

/// What the mechanics stages call: canonical trig form in `angles`, then the rules,
/// then collect_compact over `variables`.
struct simplifier {
    GiNaC::lst angles;
    GiNaC::lst variables;
    std::vector<rewrite_rule> rules;

    /// trig_canonical in the angles: the exact form to compute with.
    GiNaC::ex canonical(const GiNaC::ex& e) const;
    /// The rules, then collect_compact: the form to show, from a canonical form.
    GiNaC::ex compact(const GiNaC::ex& canonical_form) const;
    /// compact(to_ex(canonical_form)), without building the expanded expression when
    /// no rule can fire.
    GiNaC::ex compact(const harmonic_polynomial& canonical_form) const;
    /// compact() of several harmonic polynomials over one space, sharing what is
    /// learned about their common parts.
    std::vector<GiNaC::ex> compact(const std::vector<harmonic_polynomial>& canonical_forms) const;
    /// compact(canonical(e)).
    GiNaC::ex operator()(const GiNaC::ex& e) const;

private:
    GiNaC::ex compact_harmonic(const harmonic_polynomial& canonical_form, rewrite_screen& screen) const;
};

} // namespace lagrange
