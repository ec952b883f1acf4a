// SPDX-License-Identifier: GPL-2.0-or-later
/** @file sign.cpp
 *  Zero tests, signs and tidy forms of expressions in positive parameters (see sign.h). */
#include "algebra/sign.h"

#include "algebra/budget.h"
#include "algebra/canonical_order.h"
#include "algebra/expression.h"
#include "algebra/factor.h"
#include "algebra/pythagorean.h"

#include <cmath>
#include <map>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;

/// The sign of a constant expression (π, √2, cos(1), 1 − √14) by its value, when that
/// stands clear of the rounding of its terms' values; nothing otherwise or with a symbol.
std::optional<int> constant_sign(const ex& e)
{
    if (has_symbol(e))
        return std::nullopt;
    const ex value = e.evalf();
    if (!is_a<GiNaC::numeric>(value) || !ex_to<GiNaC::numeric>(value).is_real() || value.is_zero())
        return std::nullopt;
    double magnitude = 0;
    for (const ex& term : is_a<GiNaC::add>(e) ? GiNaC::exvector(e.begin(), e.end()) : GiNaC::exvector{e}) {
        const ex v = GiNaC::abs(term.evalf()).evalf();
        if (!is_a<GiNaC::numeric>(v))
            return std::nullopt;
        magnitude += ex_to<GiNaC::numeric>(v).to_double();
    }
    const GiNaC::numeric& n = ex_to<GiNaC::numeric>(value);
    if (std::abs(n.to_double()) <= 1e-12 * magnitude)
        return std::nullopt;
    return n.is_positive() ? 1 : -1;
}

std::optional<int> sign_by_structure(const ex& e);

/// The sign of a sum whose terms, grouped by their symbolic part (k/m in −k/m + √14·k/m),
/// have constant coefficients that all give the same sign; nothing otherwise.
std::optional<int> sign_by_grouping(const ex& sum)
{
    std::map<ex, ex, GiNaC::ex_is_less> groups; // symbolic part -> its constant coefficient
    for (const ex& term : sum) {
        ex constant = 1, rest = 1;
        for (const ex& factor : factors_of(term))
            (has_symbol(factor) ? rest : constant) *= factor;
        groups[rest] += constant;
    }
    if (groups.size() == sum.nops())
        return std::nullopt; // nothing grouped: the terms' signs already disagree
    int sign = 0;
    for (const auto& [rest, constant] : groups) {
        std::optional<int> part = sign_by_structure(rest);
        std::optional<int> coefficient = constant_sign(constant);
        if (!part || *part == 0 || !coefficient)
            return std::nullopt;
        if (sign != 0 && *part * *coefficient != sign)
            return std::nullopt;
        sign = *part * *coefficient;
    }
    return sign;
}

/// The sign of a product, power or sum of terms of known sign; nothing if unknown.
std::optional<int> sign_by_structure(const ex& e)
{
    if (is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric& n = ex_to<GiNaC::numeric>(e);
        if (!n.is_real())
            return std::nullopt;
        return n.is_zero() ? 0 : (n.is_positive() ? 1 : -1);
    }
    if (is_a<GiNaC::symbol>(e))
        return e.info(GiNaC::info_flags::positive) ? std::optional<int>(1) : std::nullopt;
    if (is_a<GiNaC::mul>(e)) {
        int sign = 1;
        for (const ex& factor : e) {
            std::optional<int> s = sign_by_structure(factor);
            if (!s)
                return std::nullopt;
            sign *= *s;
        }
        return sign;
    }
    if (is_a<GiNaC::power>(e)) {
        const ex& exponent = e.op(1);
        if (!is_a<GiNaC::numeric>(exponent))
            return std::nullopt;
        std::optional<int> base = sign_by_structure(e.op(0));
        const GiNaC::numeric& k = ex_to<GiNaC::numeric>(exponent);
        if (k.is_even())
            return base ? std::optional<int>(*base == 0 ? 0 : 1) : std::nullopt;
        if (!base)
            return std::nullopt;
        if (k.is_integer())
            return *base;
        return *base > 0 ? std::optional<int>(1) : std::nullopt;
    }
    if (is_a<GiNaC::add>(e)) {
        bool all_nonnegative = true, all_nonpositive = true, any_nonzero = false;
        for (const ex& term : e) {
            std::optional<int> s = sign_by_structure(term);
            if (!s)
                return std::nullopt;
            all_nonnegative = all_nonnegative && *s >= 0;
            all_nonpositive = all_nonpositive && *s <= 0;
            any_nonzero = any_nonzero || *s != 0;
        }
        if (!any_nonzero)
            return 0;
        if (all_nonnegative)
            return 1;
        if (all_nonpositive)
            return -1;
        // terms of both signs: 1 − √14, or −k/m + √14·k/m
        return has_symbol(e) ? sign_by_grouping(e) : constant_sign(e);
    }
    if (e.info(GiNaC::info_flags::positive))
        return 1;
    return constant_sign(e);
}

} // namespace

bool vanishes(const ex& e)
{
    if (e.is_zero())
        return true;
    ex expanded = e.expand();
    if (expanded.is_zero() || pythagorean(expanded).is_zero())
        return true;
    const ex fraction = expanded.normal();
    return fraction.is_zero() || pythagorean(fraction.numer().expand()).is_zero();
}

bool is_zero_matrix(const GiNaC::matrix& m)
{
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j)
            if (!vanishes(m(i, j)))
                return false;
    return true;
}

ex tidy(const ex& e)
{
    try {
        budget_check(); // GiNaC's normal and factor can take long: a checkpoint before each
        ex fraction = canonical_numer_denom(e);
        budget_check();
        // sin² th0 + cos² th0 = 1 first (algebra/pythagorean.h): factors then see the shorter form
        ex numerator = factor_if_quick(pythagorean(fraction.op(0)));
        budget_check();
        return numerator / factor_if_quick(pythagorean(fraction.op(1)));
    } catch (const budget_exceeded&) {
        throw; // out of budget: the stage stops, no fallback
    } catch (const std::exception&) {
        return e;
    }
}

std::optional<int> sign_of(const ex& e)
{
    if (vanishes(e))
        return 0;
    if (std::optional<int> s = sign_by_structure(e))
        return s;
    ex fraction = e.normal().numer_denom();
    std::optional<int> denominator = sign_by_structure(fraction.op(1));
    if (!denominator) {
        try {
            denominator = sign_by_structure(factor_if_quick(fraction.op(1)));
        } catch (const budget_exceeded&) {
            throw; // out of budget: the stage stops, no fallback
        } catch (const std::exception&) {
        }
    }
    if (!denominator || *denominator == 0)
        return std::nullopt;
    std::optional<int> numerator = sign_by_structure(fraction.op(0));
    if (!numerator)
        numerator = sign_by_structure(fraction.op(0).expand());
    if (!numerator) {
        try {
            numerator = sign_by_structure(factor_if_quick(fraction.op(0)));
        } catch (const budget_exceeded&) {
            throw; // out of budget: the stage stops, no fallback
        } catch (const std::exception&) {
        }
    }
    if (!numerator)
        return std::nullopt;
    return *numerator * *denominator;
}

std::optional<double> number_at(const GiNaC::ex& e, const GiNaC::exmap& values)
{
    GiNaC::ex n = e.subs(values).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_real())
        return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(n).to_double();
}

std::optional<int> sign_at(const GiNaC::ex& e, const GiNaC::exmap& values)
{
    GiNaC::ex n = factor_with_pi(e);
    if (n.is_zero())
        return 0;
    if (n.info(GiNaC::info_flags::positive))
        return 1;
    if ((-n).info(GiNaC::info_flags::positive))
        return -1;
    // At numbers, e itself and not its factored form: GiNaC's factor() may rewrite a
    // square root √X as ±i·√(−X) on the wrong branch, with a sign that follows the term
    // order (so the memory layout); the stability of a free body's rotation came out wrong.
    if (std::optional<double> x = number_at(e, values)) {
        if (std::abs(*x) < 1e-14 * (1 + std::abs(*x)))
            return 0;
        return *x > 0 ? 1 : -1;
    }
    return std::nullopt;
}

} // namespace lagrange
