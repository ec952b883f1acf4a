// SPDX-License-Identifier: GPL-2.0-or-later
/** @file match.h
 *  The matcher's pieces that the rewriter (rules.cpp) also uses: a match that tells
 *  which terms of a sum it used, and the small structural helpers of both. Internal
 *  to the algebra (not installed); match() and rewrite() in rules.h are the API. */
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <vector>

namespace lagrange {

/// match(), except that `bindings` may be partly filled when it fails (a rule starts
/// from none). For a sum pattern against a sum, `used_terms` receives the indices of
/// the terms of `e` that the pattern took; the others stay beside the replacement.
bool match_terms(const GiNaC::ex& e, const GiNaC::ex& pattern, GiNaC::exmap& bindings,
                 std::vector<std::size_t>& used_terms);

/// True if `p` contains a wildcard.
bool has_wildcard(const GiNaC::ex& p);

/// A product split into its numeric coefficient and its other factors.
struct product_parts {
    GiNaC::numeric coefficient = 1;
    GiNaC::exvector factors;
};

product_parts split_product(const GiNaC::ex& e);

/// The gcd of the numeric coefficients of `e` (1 where it is not a polynomial).
GiNaC::numeric coefficient_content(const GiNaC::ex& e);

} // namespace lagrange
