// SPDX-License-Identifier: GPL-2.0-or-later
/** @file canonical_order.h
 *  An order of expressions, and a choice of signs, that do not depend on GiNaC's
 *  internal order. GiNaC orders the operands of sums and products by hash values, which
 *  it seeds from the addresses of type names and from symbol serials: they change from
 *  process to process (address-space randomization) and with the symbols a process made
 *  before. It also picks the sign of a sum that is a factor, (a − b)·c or −(b − a)·c, by
 *  that order. Code whose result depends on an order or a sign (the order in which a
 *  compiled program adds terms and multiplies factors, which root comes first) chooses
 *  by these keys instead, so the same scene gives the same bytes in every process. */
#pragma once

#include <ginac/ginac.h>

#include <map>
#include <string>
#include <utility>

namespace lagrange {

/// A term as a numeric coefficient times a rest whose key does not depend on signs:
/// every sum among the rest's factors is taken with its canonical sign (the leading
/// term, by key, positive) and the −1s go to the coefficient. x·(a − b) and
/// −x·(b − a) have the same rest and the same coefficient.
struct canonical_term {
    GiNaC::numeric coefficient;
    std::string rest; ///< "1" for a number
};

/// A factor with its canonical sign: the key of the factor taken with that sign, and
/// whether the factor is the negative of it.
struct canonical_factor {
    bool negative = false;
    std::string key;
};

/// Keys built from names, numbers and structure only (symbols by name, numbers by
/// value, the operands of sums and products sorted), remembered per expression.
class canonical_keys {
public:
    /// The key of e's value (of −e's if `negated`): equal values written with factors of
    /// either sign, in any GiNaC order, have equal keys.
    std::string key(const GiNaC::ex& e, bool negated = false);
    canonical_term term(const GiNaC::ex& e);
    canonical_factor factor(const GiNaC::ex& e);
    /// A sum's canonical sign: negative if its leading term (least rest) has a negative
    /// coefficient (the real part's sign, else the imaginary part's).
    canonical_factor sum(const GiNaC::ex& e);

private:
    std::map<GiNaC::ex, canonical_term, GiNaC::ex_is_less> terms_;
    std::map<GiNaC::ex, canonical_factor, GiNaC::ex_is_less> factors_;
};

/// Whether e is canonically negative: a sum whose leading term is negative, a product
/// whose coefficient is negative once its factor sums have their canonical signs, a
/// negative number. e or −e is, unless e is 0: choose the sign of a numerator and
/// denominator pair, or of a polynomial, by it.
bool canonically_negative(const GiNaC::ex& e);

/// e.normal().numer_denom() with the denominator's canonical sign: normal() gives the
/// pair a sign by GiNaC's hash order, (−a)/(−b) in one process and a/b in another.
GiNaC::ex canonical_numer_denom(const GiNaC::ex& e);

/// A product with the powers of sums that differ only in sign merged: (−D)²·√D is D^(5/2).
/// GiNaC gives a sum to an integer power the sign its hash order picks and leaves the
/// base of a root as it is, so it merges the two in some processes and not in others.
/// The root's base keeps its sign; integer powers take it, with (−1)^n. Recurses into
/// sums, powers and functions.
GiNaC::ex merge_signed_powers(const GiNaC::ex& e);

/// canonical_keys().key(e), for one-off use.
std::string canonical_key(const GiNaC::ex& e);

/// Whether `a` comes before `b` by canonical_key (a strict weak order).
bool canonical_less(const GiNaC::ex& a, const GiNaC::ex& b);

} // namespace lagrange
