/** @file expression.h
 *  Small expression helpers shared by the algebra: a sum or product of many
 *  operands built in one allocation, and a map over the operands by a callable. */
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <utility>

namespace lagrange {

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
