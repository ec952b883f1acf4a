// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_angle_sums.cpp
 *  expand_angle_sums: the addition theorems, checked by value and for their shape. */
#include "program/angle_sums.h"

#include <catch2/catch.hpp>

using Catch::Matchers::WithinAbs;
using lagrange::expand_angle_sums;

TEST_CASE("angle_sums: sines and cosines of sums become those of single angles", "[angle_sums]")
{
    GiNaC::realsymbol a("a"), b("b"), c("c"), v("v");
    const GiNaC::ex e = 3 * GiNaC::cos(a - b) * v * v + GiNaC::sin(a + 2 * b - c) - GiNaC::sin(c) +
                        GiNaC::cos(GiNaC::sin(a + b));
    const GiNaC::ex expanded = expand_angle_sums(e);
    // No sine or cosine of a sum is left, at any depth.
    bool sum_argument = false;
    for (auto i = expanded.preorder_begin(); i != expanded.preorder_end(); ++i)
        if ((is_ex_the_function(*i, GiNaC::sin) || is_ex_the_function(*i, GiNaC::cos)) &&
            GiNaC::is_a<GiNaC::add>(i->op(0)))
            sum_argument = true;
    CHECK_FALSE(sum_argument);
    // The same values, at points chosen apart from the expression.
    const double points[][4] = {{0.3, -1.2, 2.5, 0.7}, {-2.9, 0.4, 1.1, -1.5}, {1.7, 1.6, -0.2, 3.0}};
    for (const auto& p : points) {
        const GiNaC::lst at{a == p[0], b == p[1], c == p[2], v == p[3]};
        const double by_theorem = GiNaC::ex_to<GiNaC::numeric>(expanded.subs(at).evalf()).to_double();
        const double direct = 3 * std::cos(p[0] - p[1]) * p[3] * p[3] + std::sin(p[0] + 2 * p[1] - p[2]) -
                              std::sin(p[2]) + std::cos(std::sin(p[0] + p[1]));
        CHECK_THAT(by_theorem, WithinAbs(direct, 1e-13));
    }
}
