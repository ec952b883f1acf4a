// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_trust_equilibria.cpp
 *  Issue 32: equilibria of an easy polynomial system that were "not found". The
 *  Hénon–Heiles potential V = (x² + y²)/2 + x²y − y³/3 has four: the stable origin and
 *  three saddles at the corners of its triangle, (0, 1) and (±√3/2, −1/2). */
#include "engine/analysis.h"
#include "helpers/cli_runner.h"
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

TEST_CASE("trust: Størmer's effective potential has a curve of equilibria, not a refusal",
          "[trust][equilibrium]")
{
    // V = ½ f², f = C/ρ − ρ/r³: V = 0 on the curve C r³ = ρ², i.e. ρ = cos³λ / C,
    // z = cos²λ sin λ / C in the latitude λ; across it ∂²V = (∂f)², C⁶ along ρ at (1/C, 0).
    // Beside it ∇f = 0 at z = 0, ρ = 2/C, a saddle of V.
    const model scene = lagrange_test::load(R"(
parameters C
coordinates rho z
T = 1/2*rho'^2 + 1/2*z'^2
V = 1/2*(C/rho - rho/(rho^2 + z^2)^(3/2))^2
values C = 0.7
)");
    analysis a = analyze(scene, {product::equilibrium, product::numeric});
    REQUIRE(a.equilibria);
    REQUIRE(a.equilibria->family);
    const equilibrium_family& family = *a.equilibria->family;
    CHECK(family.dimension == 1);
    CHECK(family.across == 1);
    CHECK(lagrange_test::value_at(family.potential, {}) == 0);
    const double c = 0.7;
    const GiNaC::ex rho = lagrange_test::symbol_of(scene, "rho"), z = lagrange_test::symbol_of(scene, "z"),
                    C = lagrange_test::symbol_of(scene, "C");
    for (double latitude : {-1.2, -0.5, 0.0, 0.3, 1.0, 1.4}) {
        INFO("latitude " << latitude);
        const double r = std::pow(std::cos(latitude), 2) / c;
        const double on = lagrange_test::value_at(
            family.relation, {{C, c}, {rho, r * std::cos(latitude)}, {z, r * std::sin(latitude)}});
        const double off = lagrange_test::value_at(
            family.relation, {{C, c}, {rho, 1.1 * r * std::cos(latitude)}, {z, 1.1 * r * std::sin(latitude)}});
        CHECK(std::abs(on) <= 1e-13 * std::abs(off));
        CHECK(off != 0);
    }
    // the points: (1/C, 0) on the curve (a zero mode along it), the saddle (2/C, 0) off it
    REQUIRE(a.equilibria->points.size() == 2);
    const GiNaC::exmap at{{C, c}};
    const equilibrium_point& on_curve = a.equilibria->points.at(a.equilibria->chosen);
    CHECK(lagrange_test::value_at(on_curve.position[0], at) == Approx(1 / c).epsilon(1e-15));
    CHECK(lagrange_test::value_at(on_curve.position[1], at) == 0);
    CHECK(on_curve.kind == stability::marginal);
    const equilibrium_point& saddle = a.equilibria->points.at(1 - a.equilibria->chosen);
    CHECK(lagrange_test::value_at(saddle.position[0], at) == Approx(2 / c).epsilon(1e-15));
    CHECK(lagrange_test::value_at(saddle.position[1], at) == 0);
    CHECK(saddle.kind == stability::unstable);
    REQUIRE(a.numeric);
    REQUIRE(a.numeric->size() == 1);
    const std::vector<double>& omega = a.numeric->front().omega;
    REQUIRE(omega.size() == 2);
    CHECK(std::abs(omega[0]) <= 1e-12);
    CHECK(omega[1] == Approx(std::pow(c, 3)).epsilon(1e-12));
}

TEST_CASE("trust: Størmer's curve in his variables is C r = cos² λ", "[trust][equilibrium]")
{
    const model scene = lagrange_test::load(lagrange_test::read_file(std::string(LAGRANGE_SOURCE_DIR) +
                                                                     "/tests/scenes/stormer.lag"));
    analysis a = analyze(scene, {product::equilibrium});
    REQUIRE(a.equilibria);
    REQUIRE(a.equilibria->family);
    CHECK(a.equilibria->family->across == 1);
    const GiNaC::ex r = lagrange_test::symbol_of(scene, "r"), lat = lagrange_test::symbol_of(scene, "lat"),
                    C = lagrange_test::symbol_of(scene, "C");
    const double c = 0.7;
    for (double latitude : {-1.0, 0.0, 0.4, 1.3}) {
        INFO("latitude " << latitude << ", relation " << a.equilibria->family->relation);
        const double on_curve = std::pow(std::cos(latitude), 2) / c;
        const double on = lagrange_test::value_at(a.equilibria->family->relation, {{C, c}, {r, on_curve}, {lat, latitude}});
        const double off =
            lagrange_test::value_at(a.equilibria->family->relation, {{C, c}, {r, 1.2 * on_curve}, {lat, latitude}});
        CHECK(std::abs(on) <= 1e-13 * std::abs(off));
        CHECK(off != 0);
    }
}
