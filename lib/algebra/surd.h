// SPDX-License-Identifier: GPL-2.0-or-later
/** @file surd.h
 *  Square roots kept exact: √e with the squares of factors of known sign taken
 *  out of the root, and a quadratic surd √radicand held as a positive symbol
 *  while an expression c0 + c1·√radicand is simplified, signed and folded. */
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <utility>

namespace lagrange {

/// √product = outside · √inside with the squares of factors of known sign taken out:
/// √(4 g² l² m (M+m)) = 2 g l √(m (M+m)).
std::pair<GiNaC::ex, GiNaC::ex> square_root_parts_of_product(const GiNaC::ex& product);

/// √e = outside · √inside, inside a polynomial with the squares taken out.
std::pair<GiNaC::ex, GiNaC::ex> square_root_parts(const GiNaC::ex& e);

/// √e, simplified: squares of factors of known sign come out of the root.
GiNaC::ex square_root(const GiNaC::ex& e);

/// Every square root in e rewritten by square_root (used after a substitution).
GiNaC::ex simplify_square_roots(const GiNaC::ex& e);

/// A quadratic surd √radicand, held during the computation as a positive symbol
/// (GiNaC's expand would split √(m (M+m)) into √m √(M+m) and lose it).
struct surd {
    GiNaC::possymbol symbol{"surd"};
    GiNaC::ex radicand = 1;
    GiNaC::ex root() const { return GiNaC::sqrt(radicand); }
    GiNaC::ex restore(const GiNaC::ex& e) const { return e.subs(symbol == root()); }
};

/// e written as c0 + c1 s with s² = radicand and c0, c1 rational in the parameters
/// (denominators made free of s), each factored.
GiNaC::ex simplify_with(const GiNaC::ex& e, const surd& r);

/// The sign of c0 + c1·s (s = √radicand > 0) for every positive value of the
/// parameters, if it can be decided: from the signs of c0 and c1, and where they
/// differ, from the sign of c0² − c1²·radicand.
std::optional<int> sign_with(const GiNaC::ex& e, const surd& r);

/// A coefficient c0 + c1·s in its shortest exact form: c1·√r as ±√(c1² r) when
/// c0 = 0 and that is shorter (√(m (M+m))/(M+m) becomes √m/√(M+m)); otherwise
/// with the surd restored.
GiNaC::ex fold_surd(const GiNaC::ex& e, const surd& r);

} // namespace lagrange
