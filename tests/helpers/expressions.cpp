// SPDX-License-Identifier: GPL-2.0-or-later
/** @file expressions.cpp
 *  Comparing and evaluating expressions in tests. */
#include "helpers/expressions.h"

#include <catch2/catch.hpp>

namespace lagrange_test {

bool same(const GiNaC::ex& a, const GiNaC::ex& b)
{
    const GiNaC::ex difference = (a - b).expand();
    return difference.is_zero() || difference.normal().is_zero();
}

double value_at(const GiNaC::ex& e, const GiNaC::exmap& point)
{
    const GiNaC::ex v = GiNaC::evalf(e.subs(point));
    INFO("expression " << e << " at the point: " << v);
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(v));
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
    REQUIRE(n.is_real());
    return n.to_double();
}

} // namespace lagrange_test
