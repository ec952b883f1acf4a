// SPDX-License-Identifier: GPL-2.0-or-later
/** @file factor.cpp
 *  GiNaC's factor() where it is quick, FLINT's for the large sparse polynomials of
 *  characteristic polynomials (see factor.h). */
#include "algebra/factor.h"

#include "algebra/budget.h"
#include "algebra/integer_polynomial.h"

#include <optional>
#include <vector>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::is_a;

/// Whether GiNaC's factor() is left to do a polynomial: few terms or few symbols, where
/// it is quick (its forms are those every example prints).
bool small_for_factor(const ex& expanded)
{
    if (!is_a<GiNaC::add>(expanded) || expanded.nops() <= 4)
        return true;
    GiNaC::exset symbols;
    for (GiNaC::const_preorder_iterator i = expanded.preorder_begin(); i != expanded.preorder_end(); ++i)
        if (is_a<GiNaC::symbol>(*i) && symbols.insert(*i).second && symbols.size() > 3)
            return false;
    return true;
}

/// One factor of an explicit product.
ex factor_one(const ex& f)
{
    if (!f.info(GiNaC::info_flags::rational_polynomial))
        return GiNaC::factor(f);
    const ex expanded = f.expand();
    if (small_for_factor(expanded))
        return GiNaC::factor(f);
    budget_check();
    if (std::optional<ex> factored = polynomial_factor(expanded))
        return *factored;
    return GiNaC::factor(f);
}

/// A factor that GiNaC's factor() wrote nested, ((2·M + m)·l² + m), collected in a main
/// variable it picks by its hash order (the first in an exset), as the plain sum
/// 2·M·l² + l²·m + m, which the printers order themselves: the same in every process.
ex flat(const ex& f)
{
    if (is_a<GiNaC::add>(f)) {
        for (const ex& term : f)
            if (term.info(GiNaC::info_flags::polynomial) && !term.is_equal(term.expand()))
                return f.expand();
        return f;
    }
    if (is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint))
        return GiNaC::pow(flat(f.op(0)), f.op(1));
    if (is_a<GiNaC::mul>(f)) {
        GiNaC::exvector factors;
        for (const ex& g : f)
            factors.push_back(flat(g));
        return GiNaC::mul(factors);
    }
    return f;
}

} // namespace

bool too_large_to_factor(const GiNaC::ex& e)
{
    if (GiNaC::is_a<GiNaC::power>(e)) {
        const GiNaC::ex& exponent = e.op(1);
        if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(exponent);
            if (n.is_integer() && GiNaC::abs(n) > factor_max_degree)
                return true;
        }
    }
    for (const GiNaC::ex& operand : e)
        if (too_large_to_factor(operand))
            return true;
    return false;
}

GiNaC::ex factor_if_quick(const GiNaC::ex& e)
{
    budget_check();
    if (too_large_to_factor(e))
        return e;
    if (!e.info(GiNaC::info_flags::rational_polynomial))
        return flat(GiNaC::factor(e));
    // each explicit factor on its own, as GiNaC's factor() does
    const GiNaC::exvector factors = is_a<GiNaC::mul>(e) ? GiNaC::exvector(e.begin(), e.end()) : GiNaC::exvector{e};
    ex result = 1;
    for (const ex& f : factors) {
        if (is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint))
            result *= GiNaC::pow(factor_one(f.op(0)), f.op(1));
        else
            result *= factor_one(f);
    }
    return flat(result);
}

GiNaC::ex polynomial_content(const std::vector<GiNaC::ex>& polynomials)
{
    std::vector<ex> nonzero;
    for (const ex& p : polynomials)
        if (!p.is_zero())
            nonzero.push_back(p.expand());
    if (nonzero.empty())
        return 0;
    bool integral = true;
    for (const ex& p : nonzero)
        integral = integral && p.info(GiNaC::info_flags::rational_polynomial) &&
                   p.integer_content().is_integer();
    if (integral)
        if (std::optional<ex> gcd = polynomial_gcd(nonzero))
            return *gcd;
    ex content = nonzero.front();
    for (std::size_t k = 1; k < nonzero.size(); ++k)
        content = GiNaC::gcd(content, nonzero[k]);
    return content;
}

namespace {

GiNaC::ex with_pi_as_symbol(const GiNaC::ex& e, GiNaC::ex (*f)(const GiNaC::ex&))
{
    static const GiNaC::possymbol pi("Pi");
    return f(e.subs(GiNaC::Pi == pi)).subs(pi == GiNaC::Pi);
}

GiNaC::ex normal_of(const GiNaC::ex& e) { return e.normal(); }
GiNaC::ex factor_of(const GiNaC::ex& e) { return factor_if_quick(e.normal()); }

} // namespace

GiNaC::ex normal_with_pi(const GiNaC::ex& e) { return with_pi_as_symbol(e, normal_of); }
GiNaC::ex factor_with_pi(const GiNaC::ex& e) { return with_pi_as_symbol(e, factor_of); }

} // namespace lagrange
