// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_parameter_angles.cpp
 *  Sines and cosines of a parameter angle (th0, a positive parameter that the canonical
 *  form keeps as an offset): sin² th0 + cos² th0 is 1 wherever it stands, and nothing is
 *  rewritten that holds only for some values of th0 (acos(cos th0) = th0 only on [0, π]).
 *  Each identity is checked by value at th0 = 5 and −2, where the unsound rewrites differ. */
#include "algebra/pythagorean.h"
#include "algebra/simplify.h"
#include "engine/analysis.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

namespace {

using GiNaC::ex;

/// `e` at th0 = `value` (and the other symbols at `others`) as a double.
double at(const ex& e, const GiNaC::symbol& th0, double value, const GiNaC::exmap& others = {})
{
    GiNaC::exmap values = others;
    values[th0] = value;
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(values))).to_double();
}

} // namespace

TEST_CASE("parameter angles: sin² + cos² of a parameter is 1, proved, never guessed", "[algebra][pythagorean]")
{
    const GiNaC::possymbol th0("th0"), m("m"), k("k");
    const GiNaC::realsymbol x("x"), xd("x_dot");
    lagrange::simplifier simplify{GiNaC::lst{x}, GiNaC::lst{xd}, {}};
    const ex s = GiNaC::sin(th0), c = GiNaC::cos(th0);

    // The clutter the issue found in T: gone, in the canonical and the shown form.
    const ex kinetic = ex(1) / 2 * m * (GiNaC::pow(s, 2) + GiNaC::pow(c, 2)) * GiNaC::pow(xd, 2);
    CHECK(simplify(kinetic).is_equal(ex(1) / 2 * m * GiNaC::pow(xd, 2)));
    CHECK(simplify.canonical(kinetic - ex(1) / 2 * m * GiNaC::pow(xd, 2)).is_zero());
    // A residual that vanishes only through the identity is zero.
    CHECK(simplify.canonical(k * x * (GiNaC::pow(s, 4) - GiNaC::pow(c, 4) + 1 - 2 * GiNaC::pow(s, 2))).is_zero());
    // Shorter where it is shorter, the same value always.
    const ex v = 2 * k - 2 * k * GiNaC::pow(c, 2);
    const ex shown = simplify(v * GiNaC::pow(x, 2));
    CHECK(shown.is_equal(2 * k * GiNaC::pow(s, 2) * GiNaC::pow(x, 2)));
    for (double value : {5.0, -2.0, 0.3})
        CHECK(at(shown, th0, value, {{k, 1.5}, {x, 0.7}}) ==
              Approx(at(v * GiNaC::pow(x, 2), th0, value, {{k, 1.5}, {x, 0.7}})).epsilon(1e-14));
    // Different coefficients are not the identity: m sin² + k cos² stays.
    const ex mixed = m * GiNaC::pow(s, 2) + k * GiNaC::pow(c, 2);
    CHECK(lagrange::pythagorean(mixed).is_equal(mixed));
    // A root of 1 − cos² th0 is |sin th0|, not sin th0: at th0 = 5, sin th0 < 0.
    const ex root = GiNaC::sqrt(1 - GiNaC::pow(c, 2));
    CHECK(at(simplify(root), th0, 5) == Approx(std::abs(std::sin(5.0))).epsilon(1e-14));
    CHECK(at(simplify(root), th0, 5) > 0);
}

TEST_CASE("parameter angles: acos(cos th0) is kept, it is th0 only from 0 to π", "[algebra][pythagorean]")
{
    const GiNaC::possymbol th0("th0");
    const GiNaC::realsymbol x("x"), xd("x_dot");
    lagrange::simplifier simplify{GiNaC::lst{x}, GiNaC::lst{xd}, {}};
    for (const ex& e : {GiNaC::acos(GiNaC::cos(th0)), GiNaC::asin(GiNaC::sin(th0)), GiNaC::atan(GiNaC::tan(th0))}) {
        const ex simplified = simplify(e);
        INFO(e << " -> " << simplified);
        CHECK_FALSE(simplified.is_equal(th0));
        for (double value : {5.0, 2.0, 0.5})
            CHECK(at(simplified, th0, value) == Approx(at(e, th0, value)).epsilon(1e-14));
    }
    // 2π − 5: the value at th0 = 5, not 5.
    CHECK(at(simplify(GiNaC::acos(GiNaC::cos(th0))), th0, 5) == Approx(2 * M_PI - 5).epsilon(1e-14));
}

TEST_CASE("parameter angles: an equilibrium at acos(cos th0) is where the scene puts it", "[algebra][pythagorean]")
{
    // V = k (cos θ − cos th0)²: the stable equilibrium is at cos θ = cos th0; at th0 = 5 that
    // is θ = 2π − 5 = 1.283, which the engine must give (θ = th0 would be off the branch of
    // acos). T's coefficient sin² th0 + cos² th0 is 1.
    lagrange::model scene = lagrange_test::load(R"(parameters m k th0
coordinates theta
T = 1/2*m*(sin(th0)^2 + cos(th0)^2)*theta'^2
V = k*(cos(theta) - cos(th0))^2
values m = 1, k = 1, th0 = 5
want equilibrium, linearization, numeric
)");
    lagrange::analysis result = lagrange::analyze(scene);
    REQUIRE(result.equilibria);
    REQUIRE(result.linearization);
    const GiNaC::ex theta = result.equilibria->points.at(result.equilibria->chosen).position.at(0);
    const GiNaC::possymbol th0 = GiNaC::ex_to<GiNaC::possymbol>(lagrange_test::symbol_of(scene, "th0"));
    INFO("θ = " << theta);
    CHECK(at(theta, th0, 5) == Approx(2 * M_PI - 5).epsilon(1e-14));
    std::ostringstream kinetic;
    kinetic << result.lagrangian->kinetic;
    CHECK(kinetic.str().find("th0") == std::string::npos);
    // ω² = 2 k sin² th0 / m at th0 = 5.
    REQUIRE(result.numeric);
    REQUIRE_FALSE(result.numeric->empty());
    CHECK(result.numeric->front().omega.at(0) == Approx(std::sqrt(2) * std::abs(std::sin(5.0))).epsilon(1e-12));
}
