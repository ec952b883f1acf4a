// SPDX-License-Identifier: GPL-2.0-or-later
/** @file surd.cpp
 *  Exact square roots and quadratic surds (see surd.h). */
#include "algebra/surd.h"

#include "algebra/budget.h"
#include "algebra/canonical_order.h"
#include "algebra/expression.h"
#include "algebra/factor.h"
#include "algebra/sign.h"

#include <sstream>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::exvector;
using GiNaC::is_a;

/// A positive rational r as a² b with b free of squares (trial division up to a bound).
std::pair<GiNaC::numeric, GiNaC::numeric> split_square(const GiNaC::numeric& r)
{
    auto split_integer = [](GiNaC::numeric n) {
        GiNaC::numeric outside = 1;
        for (long d = 2; d <= 10000 && GiNaC::numeric(d * d) <= n; ++d)
            while (GiNaC::mod(n, GiNaC::numeric(d * d)).is_zero()) {
                n = n / (d * d);
                outside *= d;
            }
        return std::make_pair(outside, n);
    };
    auto [numerator_out, numerator_in] = split_integer(r.numer());
    auto [denominator_out, denominator_in] = split_integer(r.denom());
    // √(a/b) = √(a b)/b
    return {numerator_out / (denominator_out * denominator_in), numerator_in * denominator_in};
}

/// The length of e as GiNaC prints it (the same for equal expressions whatever
/// the term order, so a deterministic measure of size).
std::size_t printed_length(const ex& e)
{
    std::ostringstream out;
    out << e;
    return out.str().size();
}

} // namespace

std::pair<ex, ex> square_root_parts_of_product(const ex& product)
{
    exvector given;
    if (is_a<GiNaC::mul>(product))
        given.assign(product.begin(), product.end());
    else
        given.push_back(product);
    // A sum's integer content on its own, 4·(a² − a·b + b²) whether factor() kept the 4
    // apart or GiNaC multiplied it in (which it does for a number times one sum), so
    // that its square leaves the root the same way in every process.
    // And each sum with its canonical sign, the −1s with the numbers: −4·(a·b − a² − b²)
    // and 4·(a² − a·b + b²) are one product.
    exvector factors;
    GiNaC::numeric coefficient = 1;
    for (const ex& factor : given) {
        if (is_a<GiNaC::numeric>(factor) && ex_to<GiNaC::numeric>(factor).is_rational()) {
            coefficient *= ex_to<GiNaC::numeric>(factor);
            continue;
        }
        const bool power = is_a<GiNaC::power>(factor) && factor.op(1).info(GiNaC::info_flags::posint);
        ex base = power ? factor.op(0) : factor;
        const ex exponent = power ? factor.op(1) : ex(1);
        if (is_a<GiNaC::add>(base) && base.info(GiNaC::info_flags::rational_polynomial)) {
            if (canonically_negative(base)) {
                base = (-base).expand();
                if (ex_to<GiNaC::numeric>(exponent).is_odd())
                    coefficient = -coefficient;
            }
            const GiNaC::numeric content = base.integer_content();
            if (content.is_positive() && !content.is_equal(1)) {
                coefficient *= ex_to<GiNaC::numeric>(GiNaC::pow(content, exponent));
                base = (base / content).expand();
            }
            factors.push_back(GiNaC::pow(base, exponent));
            continue;
        }
        factors.push_back(factor);
    }
    if (!coefficient.is_equal(1))
        factors.insert(factors.begin(), coefficient);
    ex outside = 1, inside = 1;
    for (const ex& factor : factors) {
        ex base = factor;
        long exponent = 1;
        if (is_a<GiNaC::power>(factor) && is_a<GiNaC::numeric>(factor.op(1)) &&
            ex_to<GiNaC::numeric>(factor.op(1)).is_pos_integer()) {
            base = factor.op(0);
            exponent = ex_to<GiNaC::numeric>(factor.op(1)).to_long();
        }
        if (is_a<GiNaC::numeric>(base) && ex_to<GiNaC::numeric>(base).is_rational() &&
            ex_to<GiNaC::numeric>(base).is_positive()) {
            auto [out, in] = split_square(GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(base, exponent)));
            outside *= out;
            inside *= in;
            continue;
        }
        std::optional<int> sign = sign_of(base);
        if (exponent >= 2 && sign && *sign != 0) {
            outside *= GiNaC::pow(*sign * base, exponent / 2);
            exponent %= 2;
        }
        inside *= GiNaC::pow(base, exponent);
    }
    return {outside, inside};
}

std::pair<ex, ex> square_root_parts(const ex& e)
{
    try {
        ex fraction = canonical_numer_denom(e);
        auto [numerator_out, numerator_in] = square_root_parts_of_product(factor_if_quick(fraction.op(0)));
        auto [denominator_out, denominator_in] = square_root_parts_of_product(factor_if_quick(fraction.op(1)));
        // √(a/b) = √(a b)/b
        return {numerator_out / (denominator_out * denominator_in), numerator_in * denominator_in};
    } catch (const budget_exceeded&) {
        throw; // out of budget: the stage stops, no fallback
    } catch (const std::exception&) {
        return {1, e};
    }
}

ex square_root(const ex& e)
{
    auto [outside, inside] = square_root_parts(e);
    return outside * GiNaC::sqrt(inside);
}

ex simplify_square_roots(const ex& e)
{
    if (is_a<GiNaC::power>(e) && is_a<GiNaC::numeric>(e.op(1))) {
        const GiNaC::numeric& k = ex_to<GiNaC::numeric>(e.op(1));
        ex base = simplify_square_roots(e.op(0));
        if (k.denom() == 2)
            return GiNaC::pow(square_root(base), k.numer());
        return GiNaC::pow(base, e.op(1));
    }
    if (e.nops() == 0)
        return e;
    map_each recurse([](const ex& x) { return simplify_square_roots(x); });
    return e.map(recurse);
}

ex simplify_with(const ex& e, const surd& r)
{
    if (!e.has(r.symbol))
        return tidy(e);
    const ex& s = r.symbol;
    try {
        auto reduce = [&](const ex& p) {
            ex expanded = p.expand();
            ex even = 0, odd = 0;
            for (int k = expanded.ldegree(s); k <= expanded.degree(s); ++k) {
                ex part = expanded.coeff(s, k) * GiNaC::pow(r.radicand, k / 2);
                (k % 2 == 0 ? even : odd) += part;
            }
            return std::make_pair(even.expand(), odd.expand());
        };
        budget_check();
        ex fraction = e.normal().numer_denom();
        budget_check();
        auto [numerator_0, numerator_1] = reduce(fraction.op(0));
        auto [denominator_0, denominator_1] = reduce(fraction.op(1));
        if (!denominator_1.is_zero()) {
            // multiply by the conjugate of the denominator
            ex n0 = numerator_0 * denominator_0 - numerator_1 * denominator_1 * r.radicand;
            ex n1 = numerator_1 * denominator_0 - numerator_0 * denominator_1;
            numerator_0 = n0.expand();
            numerator_1 = n1.expand();
            denominator_0 = (denominator_0 * denominator_0 - denominator_1 * denominator_1 * r.radicand).expand();
        }
        return tidy(numerator_0 / denominator_0) + tidy(numerator_1 / denominator_0) * s;
    } catch (const budget_exceeded&) {
        throw; // out of budget: the stage stops, no fallback
    } catch (const std::exception&) {
        return tidy(e);
    }
}

std::optional<int> sign_with(const ex& e, const surd& r)
{
    if (!e.has(r.symbol))
        return sign_of(e);
    ex expanded = simplify_with(e, r).expand();
    if (expanded.degree(r.symbol) > 1 || expanded.ldegree(r.symbol) < 0)
        return std::nullopt;
    ex c0 = expanded.coeff(r.symbol, 0), c1 = expanded.coeff(r.symbol, 1);
    std::optional<int> s0 = sign_of(c0), s1 = sign_of(c1);
    if (!s0 || !s1)
        return std::nullopt;
    if (*s0 == 0 || *s1 == 0 || *s0 == *s1)
        return *s0 != 0 ? *s0 : *s1;
    std::optional<int> larger = sign_of(c0 * c0 - c1 * c1 * r.radicand);
    if (!larger || *larger == 0)
        return std::nullopt;
    return *larger > 0 ? *s0 : *s1;
}

ex fold_surd(const ex& e, const surd& r)
{
    ex restored = r.restore(e);
    ex expanded = e.expand();
    if (!e.has(r.symbol) || expanded.degree(r.symbol) != 1 || !expanded.coeff(r.symbol, 0).is_zero())
        return restored;
    ex c1 = expanded.coeff(r.symbol, 1);
    std::optional<int> sign = sign_of(c1);
    if (!sign || *sign == 0)
        return restored;
    ex folded = *sign * GiNaC::sqrt(tidy(c1 * c1 * r.radicand));
    return printed_length(folded) < printed_length(restored) ? folded : restored;
}

} // namespace lagrange
