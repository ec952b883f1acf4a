/** @file factor.cpp
 *  GiNaC's factor() where it is quick (see factor.h). */
#include "algebra/factor.h"

#include "algebra/budget.h"

#include <cstdlib>

namespace lagrange {

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
    return GiNaC::factor(e);
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
