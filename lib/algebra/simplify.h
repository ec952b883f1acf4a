// SPDX-License-Identifier: GPL-2.0-or-later
/** @file simplify.h
 *  The simplifier that the mechanics stages use: the exact canonical form of
 *  trigonometric polynomials in the coordinates (trig_canonical.h), then the rules,
 *  then a compact grouping by velocities and accelerations. */
#pragma once

#include "algebra/rules.h"
#include "algebra/trig_canonical.h"

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

class harmonic_polynomial;

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
