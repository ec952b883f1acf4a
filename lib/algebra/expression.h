// SPDX-License-Identifier: GPL-2.0-or-later
/** @file expression.h
 *  Small expression helpers shared by the algebra: what an expression is at its top
 *  node, its terms and factors, a sum or product of many operands built in one
 *  allocation, and a map over the operands by a callable. */
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <utility>

namespace lagrange {

/// What an expression is at its top node. GiNaC's is_a<> is a dynamic_cast, and
/// with libstdc++ every failed one compares type names as strings; the matcher and
/// the canonical form ask this very often, so they use ex_kind_of instead.
enum class ex_kind { number, symbol, constant, sum, product, power, function, wildcard, other };

ex_kind ex_kind_of(const GiNaC::ex& e);

/// The terms of a sum (a non-sum is a one-term sum; zero has no terms).
GiNaC::exvector terms_of(const GiNaC::ex& e);

/// The factors of a product (a non-product is a one-factor product).
GiNaC::exvector factors_of(const GiNaC::ex& e);

/// True if a sum of products has a negative power of something other than a symbol
/// (a denominator that only normal() can combine).
bool has_compound_denominator(const GiNaC::ex& e);

/// True if `e` contains a symbol (a parameter, coordinate or any other); π is a constant.
bool has_symbol(const GiNaC::ex& e);

/// True if `e` is a sine or a cosine.
bool is_sin_or_cos(const GiNaC::ex& e);

/// True if `e` contains a sine, cosine or tangent.
bool has_trigonometric(const GiNaC::ex& e);

/// True if `q` appears in the argument of a sine or cosine in `e`.
bool inside_trigonometric(const GiNaC::ex& e, const GiNaC::ex& q);

/// True if `q` appears in the argument of any function in `e` (a sine, exp, abs, …).
bool inside_function(const GiNaC::ex& e, const GiNaC::ex& q);

/// The sum of `terms` (0 if none, the term itself if one).
inline GiNaC::ex sum_of(const GiNaC::exvector& terms)
{
    if (terms.empty())
        return 0;
    if (terms.size() == 1)
        return terms.front();
    return GiNaC::dynallocate<GiNaC::add>(terms);
}

/// The product of `factors` (1 if none, the factor itself if one).
inline GiNaC::ex product_of(const GiNaC::exvector& factors)
{
    if (factors.empty())
        return 1;
    if (factors.size() == 1)
        return factors.front();
    return GiNaC::dynallocate<GiNaC::mul>(factors);
}

/// A map_function that applies a callable to every operand.
struct map_each : GiNaC::map_function {
    explicit map_each(std::function<GiNaC::ex(const GiNaC::ex&)> f) : apply(std::move(f)) {}
    GiNaC::ex operator()(const GiNaC::ex& e) override { return apply(e); }
    std::function<GiNaC::ex(const GiNaC::ex&)> apply;
};

} // namespace lagrange
