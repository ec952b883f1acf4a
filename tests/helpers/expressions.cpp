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

void check_matrix(const GiNaC::matrix& got, const std::vector<std::vector<GiNaC::ex>>& expected)
{
    REQUIRE(got.rows() == expected.size());
    for (unsigned i = 0; i < got.rows(); ++i) {
        REQUIRE(got.cols() == expected[i].size());
        for (unsigned j = 0; j < got.cols(); ++j) {
            INFO("entry (" << i << ", " << j << "): " << got(i, j) << " against " << expected[i][j]);
            CHECK(same(got(i, j), expected[i][j]));
        }
    }
}

} // namespace lagrange_test
