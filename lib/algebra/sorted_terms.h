// SPDX-License-Identifier: GPL-2.0-or-later
/** @file sorted_terms.h
 *  The sorted-term core that every printed expression goes through: a term split into
 *  its numeric coefficient and its other factors, the degrees that order the terms of a
 *  sum, and operands sorted by their printed form. GiNaC's own order of terms changes
 *  from run to run; text built on these keys does not. The printers of lib/output
 *  (print.h) and the expressions in error messages (message_text) both use it. */
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

namespace lagrange {

/// How to order the terms of a sum: groups of symbols in priority order. Terms
/// are sorted by their total degree in the first group (descending), then by their
/// exponent vector in that group (lexicographic, descending), then the next group,
/// and finally by their printed form. Example: {{theta_ddot, phi_ddot},
/// {theta_dot, phi_dot}} puts accelerations first, then velocities, then the rest.
struct term_order {
    std::vector<std::vector<GiNaC::ex>> groups;
};

/// A term as its numeric coefficient times its other factors.
struct term_factors {
    GiNaC::numeric coefficient = 1;
    GiNaC::exvector factors; ///< nested products flattened, in GiNaC's order
};

/// Splits `term` (a product, a number, or anything else as one factor).
term_factors split_term(const GiNaC::ex& term);

/// The exponent of `s` in a term: 2 in x*s^2, -1 in x/s, the highest in a sum factor.
GiNaC::numeric exponent_in(const GiNaC::ex& term, const GiNaC::ex& s);

/// Where a term stands by a term order: its exponent of each group symbol (groups
/// concatenated) and its total degree in each group.
struct term_degrees {
    std::vector<GiNaC::numeric> exponents;
    std::vector<GiNaC::numeric> degrees;
};

term_degrees degrees_of(const GiNaC::ex& term, const term_order& order);

/// Compares terms by the order's groups: total degree, then exponents, both
/// descending. Negative if `a` comes first, 0 if the order does not tell them apart.
int compare_degrees(const term_degrees& a, const term_degrees& b);

/// The operands of `e` (terms of a sum, factors of a product, …) as `text` prints
/// them, sorted by that text.
std::vector<std::string> sorted_operands(const GiNaC::ex& e, const std::function<std::string(const GiNaC::ex&)>& text);

/// The factors of a product (a non-product is one factor) sorted by their canonical key
/// (canonical_order.h), whatever sign each factor has:
/// an order of, say, a factored polynomial's factors that GiNaC's hash order does not move.
GiNaC::exvector sorted_factors(const GiNaC::ex& product);

/// e as text for messages, the same whatever GiNaC's internal term order: the
/// operands of sums and products printed recursively and sorted ("-E*q0",
/// "cos(x)*m+g"). The full printer (output/print.h) orders by a term order as well.
std::string message_text(const GiNaC::ex& e);

} // namespace lagrange
