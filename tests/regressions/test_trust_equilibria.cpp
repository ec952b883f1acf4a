// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_trust_equilibria.cpp
 *  Issue 32: equilibria of an easy polynomial system that were "not found". The
 *  Hénon–Heiles potential V = (x² + y²)/2 + x²y − y³/3 has four: the stable origin and
 *  three saddles at the corners of its triangle, (0, 1) and (±√3/2, −1/2). */
#include "engine/analysis.h"
#include "helpers/expressions.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace lagrange;

TEST_CASE("trust: the Hénon–Heiles equilibria are found in closed form", "[trust][equilibrium]")
{
    const model scene = lagrange_test::load(R"(
parameters m
coordinates x y
T = m*(x'^2 + y'^2)/2
V = (x^2 + y^2)/2 + x^2*y - y^3/3
)");
    analysis a = analyze(scene, {product::equilibrium});
    REQUIRE(a.equilibria);
    std::vector<std::pair<double, double>> found;
    int stable = 0;
    for (const equilibrium_point& p : a.equilibria->points) {
        REQUIRE(p.position.size() == 2);
        found.emplace_back(lagrange_test::value_at(p.position[0], {}), lagrange_test::value_at(p.position[1], {}));
        stable += p.kind == stability::stable;
    }
    std::sort(found.begin(), found.end());
    const double h = std::sqrt(3.0) / 2;
    const std::vector<std::pair<double, double>> expected{{-h, -0.5}, {0, 0}, {0, 1}, {h, -0.5}};
    REQUIRE(found.size() == expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        CHECK(found[k].first == Approx(expected[k].first).margin(1e-15));
        CHECK(found[k].second == Approx(expected[k].second).margin(1e-15));
    }
    CHECK(stable == 1);
}
