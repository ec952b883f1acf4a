// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_equilibrium.cpp
 *  Equilibria the solver used to miss (rational potentials, spring lengths √(r²), an
 *  equilibrium given through a parameter, long chains), "no equilibrium at all", and
 *  stability decided at the `values` points, each against a textbook closed form. */
#include "helpers/cli_runner.h"
#include "mechanics/equilibrium.h"
#include "mechanics/lagrangian.h"
#include "mechanics/linearization.h"
#include "mechanics/modes.h"
#include "scene/lower.h"
#include "helpers/scene_helpers.h"
#include "helpers/expressions.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::symbol_of;
using Catch::Matchers::WithinRel;

using lagrange_test::same;
using lagrange_test::value_at;

namespace {

struct solved {
    model scene;
    lagrangian_result lagrangian;
    equilibria_result equilibria;
    linearization_result linear;
    modes_result modes;
};

/// The equilibria of a scene and the closed-form modes about the chosen one.
solved solve(const std::string& text)
{
    solved a{load(text), {}, {}, {}, {}};
    simplifier simplify = make_simplifier(a.scene);
    a.lagrangian = derive_lagrangian(a.scene, simplify);
    a.equilibria = find_equilibria(a.scene, a.lagrangian, simplify);
    a.linear = linearize(a.scene, a.lagrangian, a.equilibria.points.at(a.equilibria.chosen).position, simplify);
    a.modes = symbolic_modes(a.scene, a.linear, characteristic_polynomial(a.scene, a.linear));
    return a;
}

} // namespace

TEST_CASE("equilibrium: Atwood's machine has none, and says so", "[equilibrium]")
{
    model scene = load(R"(parameters m1 m2 g
coordinates x
T = 1/2*(m1 + m2)*x'^2
V = -m1*g*x + m2*g*x
)");
    simplifier simplify = make_simplifier(scene);
    lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
    try {
        find_equilibria(scene, lagrangian, simplify);
        FAIL("no error");
    } catch (const computation_error& e) {
        std::string message = e.what();
        INFO(message);
        CHECK(message.rfind("no equilibrium: ∂U/∂x = ", 0) == 0);
        CHECK(message.find("≠ 0") != std::string::npos);
        CHECK(message.find("could not be solved") == std::string::npos);
    }
}

TEST_CASE("equilibrium: a rational potential with a parameter in the denominator", "[equilibrium]")
{
    // V = ((y1−b)² + (y2−b)² + y3² + (y1−b)(y2−b))/a: the minimum at (b, b, 0); with unit
    // masses ω² are the eigenvalues of the Hessian [[2,1,0],[1,2,0],[0,0,2]]/a: 1/a, 2/a, 3/a.
    solved a = solve(R"(parameters a b
coordinates y1 y2 y3
T = 1/2*(y1'^2 + y2'^2 + y3'^2)
V = ((y1 - b)^2 + (y2 - b)^2 + y3^2 + (y1 - b)*(y2 - b))/a
)");
    GiNaC::ex pa = symbol_of(a.scene, "a"), b = symbol_of(a.scene, "b");
    REQUIRE(a.equilibria.points.size() == 1);
    const equilibrium_point& point = a.equilibria.points[0];
    CHECK(same(point.position[0], b));
    CHECK(same(point.position[1], b));
    CHECK(same(point.position[2], 0));
    CHECK(point.kind == stability::stable);
    REQUIRE(a.modes.frequencies.size() == 3);
    CHECK(same(a.modes.frequencies[0], 1 / pa));
    CHECK(same(a.modes.frequencies[1], 2 / pa));
    CHECK(same(a.modes.frequencies[2], 3 / pa));
}

TEST_CASE("equilibrium: the issue's V = (y1² + y2² + y3² + y1 y2)/a", "[equilibrium]")
{
    solved a = solve(R"(parameters a
coordinates y1 y2 y3
T = 1/2*(y1'^2 + y2'^2 + y3'^2)
V = (y1^2 + y2^2 + y3^2 + y1*y2)/a
)");
    REQUIRE(a.equilibria.points.size() == 1);
    for (const GiNaC::ex& x : a.equilibria.points[0].position)
        CHECK(same(x, 0));
    CHECK(a.equilibria.points[0].kind == stability::stable);
}

TEST_CASE("equilibrium: normal coordinates are written in the displacement q − q0", "[equilibrium]")
{
    solved a = solve(R"(parameters a b
coordinates y1 y2 y3
T = 1/2*(y1'^2 + y2'^2 + y3'^2)
V = ((y1 - b)^2 + (y2 - b)^2 + y3^2 + (y1 - b)*(y2 - b))/a
)");
    REQUIRE(a.modes.normal_coordinates.size() == 3);
    GiNaC::exmap at_equilibrium;
    for (std::size_t i = 0; i < 3; ++i)
        at_equilibrium[a.scene.coordinates[i].position] = a.equilibria.points[0].position[i];
    // with T = 1 the normal coordinates are the unit eigenvectors of the Hessian applied to
    // q − q0: (y1 − y2)/√2, y3 and (y1 + y2 − 2b)/√2 up to sign; each vanishes at q0.
    GiNaC::ex y1 = symbol_of(a.scene, "y1"), y2 = symbol_of(a.scene, "y2"), y3 = symbol_of(a.scene, "y3"),
              b = symbol_of(a.scene, "b");
    std::vector<GiNaC::ex> expected{(y1 - y2) / GiNaC::sqrt(GiNaC::ex(2)), y3,
                                   (y1 + y2 - 2 * b) / GiNaC::sqrt(GiNaC::ex(2))};
    for (std::size_t k = 0; k < 3; ++k) {
        INFO(a.modes.normal_coordinates[k]);
        CHECK(same(a.modes.normal_coordinates[k].subs(at_equilibrium), 0));
        CHECK((same(a.modes.normal_coordinates[k], expected[k]) || same(a.modes.normal_coordinates[k], -expected[k])));
    }
}

TEST_CASE("equilibrium: the elastic pendulum hangs at r = a + m g/k without an equilibrium line", "[equilibrium]")
{
    solved a = solve(R"(parameters m k a g
coordinates r theta
point bob mass m at (r*sin(theta), -r*cos(theta))
spring k between bob and (0, 0) rest a
gravity g along (0, -1)
)");
    GiNaC::ex m = symbol_of(a.scene, "m"), k = symbol_of(a.scene, "k"), pa = symbol_of(a.scene, "a"),
              g = symbol_of(a.scene, "g");
    const equilibrium_point& chosen = a.equilibria.points.at(a.equilibria.chosen);
    GiNaC::ex r0 = pa + m * g / k;
    CHECK(same(chosen.position[0], r0));
    CHECK(same(chosen.position[1], 0));
    CHECK(chosen.kind == stability::stable);
    // every equilibrium listed is on the branch r > 0
    for (const equilibrium_point& p : a.equilibria.points)
        CHECK(value_at(p.position[0], {{m, 1}, {k, 1}, {pa, 1}, {g, 5}}) > 0);
    // textbook: the spring mode k/m and the swing g/r0
    REQUIRE(a.modes.frequencies.size() == 2);
    bool spring = false, swing = false;
    for (const GiNaC::ex& w2 : a.modes.frequencies) {
        spring = spring || same(w2, k / m);
        swing = swing || same(w2, g / r0);
    }
    CHECK((spring && swing));
}

TEST_CASE("equilibrium: a conical orbit given through the parameter th0", "[equilibrium]")
{
    // Spherical pendulum reduced by its angular momentum p: U = p²/(2 m l² sin²θ) − m g l cos θ.
    // With p² = m² g l³ sin³θ0 tanθ0 the point θ0 is a circular orbit, and small
    // oscillations about it have ω² = g (1 + 3 cos²θ0)/(l cos θ0) (textbook).
    const std::string text = R"(parameters m g l th0
coordinates theta
let p2 = m^2*g*l^3*sin(th0)^3*tan(th0)
T = 1/2*m*l^2*theta'^2
V = p2/(2*m*l^2*sin(theta)^2) - m*g*l*cos(theta)
equilibrium theta = th0
values m = 1, g = 9.81, l = 2, th0 = 0.7
)";
    solved a = solve(text);
    GiNaC::ex g = symbol_of(a.scene, "g"), l = symbol_of(a.scene, "l"), m = symbol_of(a.scene, "m"),
              th0 = symbol_of(a.scene, "th0");
    REQUIRE(a.equilibria.given);
    CHECK(a.equilibria.points[0].kind == stability::stable); // decided at the values
    REQUIRE(a.modes.frequencies.size() == 1);
    for (double angle : {0.3, 0.7, 1.2}) {
        GiNaC::exmap point{{m, 1.5}, {g, 9.81}, {l, 2}, {th0, angle}};
        double expected = 9.81 * (1 + 3 * std::cos(angle) * std::cos(angle)) / (2 * std::cos(angle));
        CHECK_THAT(value_at(a.modes.frequencies[0], point), WithinRel(expected, 1e-12));
    }
}

TEST_CASE("equilibrium: a point that is not one is still rejected through a parameter", "[equilibrium]")
{
    model scene = load(R"(parameters m g l th0
coordinates theta
let p2 = m^2*g*l^3*sin(th0)^3*tan(th0)
T = 1/2*m*l^2*theta'^2
V = 2*p2/(2*m*l^2*sin(theta)^2) - m*g*l*cos(theta)
equilibrium theta = th0
)");
    simplifier simplify = make_simplifier(scene);
    lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
    REQUIRE_THROWS_WITH(find_equilibria(scene, lagrangian, simplify), Catch::Contains("not one"));
}

TEST_CASE("equilibrium: stability decided at the values, and the stable point chosen", "[equilibrium]")
{
    // bead on a hoop spinning at w: V'' = m g R − m R² w² at the bottom; above w² = g/R
    // the side cos q0 = g/(R w²) is the stable one, with ω² = w² − g²/(R² w²).
    const std::string hoop = R"(parameters m g R w
coordinates q
T = 1/2*m*R^2*q'^2
V = m*g*R*(1 - cos(q)) - 1/2*m*R^2*w^2*sin(q)^2
)";
    SECTION("slow: the bottom")
    {
        solved a = solve(hoop + "values m = 1, g = 9.81, R = 1, w = 2\n");
        const equilibrium_point& chosen = a.equilibria.points.at(a.equilibria.chosen);
        CHECK(same(chosen.position[0], 0));
        CHECK(chosen.kind == stability::stable);
        // cos q0 = g/(R w²) > 1: no side equilibrium at these values, so nothing is claimed of it
        for (const equilibrium_point& p : a.equilibria.points)
            if (!same(p.position[0], 0) && !same(p.position[0], GiNaC::Pi))
                CHECK(p.kind == stability::unknown);
    }
    SECTION("fast: the side")
    {
        solved a = solve(hoop + "values m = 1, g = 9.81, R = 1, w = 4\n");
        GiNaC::ex g = symbol_of(a.scene, "g"), R = symbol_of(a.scene, "R"), w = symbol_of(a.scene, "w");
        const equilibrium_point& chosen = a.equilibria.points.at(a.equilibria.chosen);
        CHECK(same(chosen.position[0], GiNaC::acos(g / (R * w * w))));
        CHECK(chosen.kind == stability::stable);
        for (const equilibrium_point& p : a.equilibria.points)
            if (same(p.position[0], 0))
                CHECK(p.kind == stability::unstable);
        REQUIRE(a.modes.frequencies.size() == 1);
        CHECK(same(a.modes.frequencies[0], w * w - g * g / (R * R * w * w)));
    }
    SECTION("values on both sides: undecided")
    {
        solved a = solve(hoop + "values m = 1, g = 9.81, R = 1, w = 2\nvalues m = 1, g = 9.81, R = 1, w = 4\n");
        for (const equilibrium_point& p : a.equilibria.points)
            if (same(p.position[0], 0))
                CHECK(p.kind == stability::unknown);
    }
}

TEST_CASE("equilibrium: the 12-link chain's stable equilibrium without 2^12 combinations", "[equilibrium]")
{
    // absolute angles: ∂V/∂q_i = g l_i sin q_i Σ_{k≥i} m_k, so the chain hangs straight down
    model scene = load(lagrange_test::chain_scene(12));
    simplifier simplify = make_simplifier(scene);
    lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
    equilibria_result equilibria = find_equilibria(scene, lagrangian, simplify);
    REQUIRE(equilibria.points.size() == 1);
    for (const GiNaC::ex& angle : equilibria.points[0].position)
        CHECK(angle.is_zero());
    CHECK(equilibria.points[0].kind == stability::stable);
}

TEST_CASE("equilibrium: a chain in relative angles hangs at 0 without listing combinations", "[equilibrium]")
{
    // six links of length l and mass m, each angle measured from the link above
    std::string coordinates = "coordinates", points, x, y, angle;
    for (int k = 1; k <= 6; ++k) {
        std::string i = std::to_string(k);
        coordinates += " q" + i;
        angle += (k > 1 ? " + q" : "q") + i;
        x += " + l*sin(" + angle + ")";
        y += " - l*cos(" + angle + ")";
        points += "point P" + i + " mass m at (" + x + ", " + y + ")\n";
    }
    model scene = load("parameters m l g\n" + coordinates + "\n" + points + "gravity g along (0, -1)\n");
    simplifier simplify = make_simplifier(scene);
    lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
    equilibria_result equilibria = find_equilibria(scene, lagrangian, simplify);
    REQUIRE(equilibria.points.size() == 1);
    for (const GiNaC::ex& a : equilibria.points[0].position)
        CHECK(a.is_zero());
    CHECK(equilibria.points[0].kind == stability::stable);
}

TEST_CASE("equilibrium: the command line says no equilibrium with exit 1, senseless values with exit 2",
          "[equilibrium][cli]")
{
    const std::string scenes = std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/";
    lagrange_test::cli_result none = lagrange_test::run_cli(scenes + "atwood.lag --want equilibrium");
    CHECK(none.exit_code == 1);
    CHECK(none.err.find("no equilibrium: ∂U/∂x = -g*m1+g*m2 ≠ 0") != std::string::npos);
    // the default run leaves out the small oscillations with that note
    lagrange_test::cli_result by_default = lagrange_test::run_cli(scenes + "atwood.lag");
    CHECK(by_default.exit_code == 0);
    CHECK(by_default.out.find("no equilibrium") != std::string::npos);
    lagrange_test::cli_result bad = lagrange_test::run_cli("- --values m=-2",
                                                           "parameters m g\ncoordinates x\n"
                                                           "point P mass m at (x, 0)\ngravity g along (0, -1)\n");
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("--values:1:3: error: these values make the mass of point `P` negative") != std::string::npos);
}
