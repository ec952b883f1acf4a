// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_elimination.cpp
 *  Constraints eliminated explicitly (`eliminated`): the reduced equations against
 *  textbook closed forms (Atwood's machine, the ladder, a bead on a parabolic wire) and
 *  against the multiplier form at random states on the constraint manifold; the offer in
 *  the output; and constraints that cannot be eliminated. */
#include "helpers/cli_runner.h"
#include "engine/analysis.h"
#include "helpers/scene_helpers.h"
#include "helpers/expressions.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <random>
#include <string>

using namespace lagrange;
using namespace lagrange_test;

namespace {

const std::string atwood = R"(parameters m1 m2 g l
coordinates y1 y2
point P1 mass m1 at (0, y1)
point P2 mass m2 at (1, y2)
gravity g along (0, -1)
constraint string: y1 + y2 = -l
)";

const std::string ladder = R"(parameters m l g
coordinates x y theta
T = 1/2*m*(x'^2 + y'^2) + 1/2*(m*l^2/12)*theta'^2
V = m*g*y
constraint wall: x = l/2*sin(theta)
constraint floor: y = l/2*cos(theta)
)";

const std::string bead = R"(parameters m g a k
coordinates x y
point P mass m at (x, y)
gravity g along (0, -1)
dissipation F = 1/2*k*(x'^2 + y'^2)
constraint wire: y = a*x^2
)";

/// The reduced equation of coordinate `q`, solved for its acceleration.
GiNaC::ex acceleration_from(const GiNaC::ex& equation, const GiNaC::ex& acceleration)
{
    const GiNaC::ex e = equation.expand();
    return (-e.coeff(acceleration, 0) / e.coeff(acceleration, 1)).normal();
}

} // namespace

TEST_CASE("elimination: Atwood's machine and the ladder against their closed forms", "[elimination][constraints]")
{
    {
        model scene = load(atwood);
        analysis a = analyze(scene, {product::eliminated});
        REQUIRE(a.elimination);
        REQUIRE(a.elimination->complete);
        REQUIRE(a.elimination->eliminated.size() == 1);
        CHECK(scene.coordinates[a.elimination->eliminated[0].coordinate].name == "y2");
        CHECK(same(a.elimination->eliminated[0].value, -symbol_of(scene, "l") - symbol_of(scene, "y1")));
        REQUIRE(a.elimination->equations.size() == 1);
        // ÿ1 = (m2 − m1) g/(m1 + m2): the heavier side falls.
        const GiNaC::ex m1 = symbol_of(scene, "m1"), m2 = symbol_of(scene, "m2"), g = symbol_of(scene, "g");
        CHECK(same(acceleration_from(a.elimination->equations[0], symbol_of(scene, "y1_ddot")),
                   (m2 - m1) * g / (m1 + m2)));
    }
    {
        model scene = load(ladder);
        analysis a = analyze(scene, {product::eliminated});
        REQUIRE(a.elimination);
        REQUIRE(a.elimination->complete);
        REQUIRE(a.elimination->kept.size() == 1);
        CHECK(scene.coordinates[a.elimination->kept[0]].name == "theta");
        // I_top θ̈ = m g (l/2) sin θ with I_top = m l²/3: θ̈ = (3 g/2 l) sin θ.
        const GiNaC::ex g = symbol_of(scene, "g"), l = symbol_of(scene, "l"), theta = symbol_of(scene, "theta");
        CHECK(same(acceleration_from(a.elimination->equations[0], symbol_of(scene, "theta_ddot")),
                   3 * g / (2 * l) * GiNaC::sin(theta)));
    }
}

TEST_CASE("elimination: a damped bead on a parabolic wire agrees with the multiplier form", "[elimination][constraints]")
{
    model scene = load(bead);
    analysis a = analyze(scene, {product::eliminated, product::multipliers});
    REQUIRE(a.elimination);
    REQUIRE(a.elimination->complete);
    REQUIRE(a.multipliers);
    const GiNaC::ex m = symbol_of(scene, "m"), g = symbol_of(scene, "g"), alpha = symbol_of(scene, "a"),
                    k = symbol_of(scene, "k"), x = symbol_of(scene, "x"), v = symbol_of(scene, "x_dot");
    const GiNaC::ex reduced = acceleration_from(a.elimination->equations[0], symbol_of(scene, "x_ddot"));
    // By hand: L = ½ m (1 + 4a²x²) ẋ² − m g a x², F = ½ k (1 + 4a²x²) ẋ².
    const GiNaC::ex by_hand = -(4 * m * alpha * alpha * x * v * v + 2 * m * g * alpha * x +
                                k * (1 + 4 * alpha * alpha * x * x) * v) /
                              (m * (1 + 4 * alpha * alpha * x * x));
    CHECK(same(reduced, by_hand));

    // The multiplier form's ẍ at random states on the manifold (y = a x², ẏ = 2 a x ẋ).
    std::mt19937 random(5);
    std::uniform_real_distribution<double> uniform(-2, 2), positive(0.5, 2);
    const GiNaC::ex y = symbol_of(scene, "y"), w = symbol_of(scene, "y_dot");
    for (int trial = 0; trial < 5; ++trial) {
        const GiNaC::numeric X(uniform(random)), V(uniform(random)), A(positive(random)), G(positive(random)),
            M(positive(random)), K(positive(random));
        GiNaC::exmap at = {{x, X}, {v, V}, {alpha, A}, {g, G}, {m, M}, {k, K}, {y, A * X * X}, {w, 2 * A * X * V}};
        const double from_multipliers = GiNaC::ex_to<GiNaC::numeric>(a.multipliers->accelerations[0].subs(at).evalf()).to_double();
        const double from_reduced = GiNaC::ex_to<GiNaC::numeric>(reduced.subs(at).evalf()).to_double();
        CHECK(std::abs(from_multipliers - from_reduced) <= 1e-12 * (1 + std::abs(from_reduced)));
    }
}

TEST_CASE("elimination: offered in the output, refused where it cannot be done", "[elimination][constraints][cli]")
{
    const std::string file = temporary_file("atwood_elimination.lag", atwood + "want equations, eliminated\n");
    cli_result text = run_cli(file);
    REQUIRE(text.exit_code == 0);
    CHECK(text.out.find("string can be eliminated: y2 = -l - y1") != std::string::npos);
    CHECK(text.out.find("Equations with the constraints eliminated") != std::string::npos);
    cli_result json = run_cli(file + " --format json");
    REQUIRE(json.exit_code == 0);
    const nlohmann::json doc = nlohmann::json::parse(json.out);
    CHECK(doc["constraints"]["string"]["eliminates"]["coordinate"] == "y2");
    REQUIRE(doc.contains("eliminated"));
    CHECK(doc["eliminated"].contains("y1"));

    // A pendulum in Cartesian coordinates: no coordinate appears linearly.
    const std::string cartesian = "parameters m g l\ncoordinates x y\npoint P mass m at (x, y)\n"
                                  "gravity g along (0, -1)\nconstraint rod: x^2 + y^2 = l^2\n";
    model scene = load(cartesian);
    CHECK_THROWS_AS(analyze(scene, {product::eliminated}), computation_error);
    analysis by_default = analyze(scene);
    REQUIRE(by_default.elimination);
    CHECK(by_default.elimination->eliminated.empty());
    CHECK(by_default.elimination->equations.empty());
    cli_result refused = run_cli(temporary_file("cartesian_elimination.lag", cartesian + "want eliminated\n"));
    CHECK(refused.exit_code == 1);
    CHECK(refused.err.find("cannot all be eliminated") != std::string::npos);
}

TEST_CASE("elimination: a constraint with a coordinate under a square root is not linear in it",
          "[elimination][constraints]")
{
    // a wheel's contact height r·√(1 − (k·a)²) (`rolls`): h can be eliminated, q2 cannot,
    // and asking GiNaC for the degree in q2 must not throw
    const model scene = load("parameters m g r\ncoordinates h q1 q2\n"
                             "body D disk(r) mass m axis y at (0, 0, h) orientation rotations(z q1, x q2)\n"
                             "gravity g along (0, 0, -1)\n"
                             "constraint c: h = r*sqrt(1 - sin(q2)^2/2 + sin(q1)*cos(q2)/3)\n");
    const analysis a = analyze(scene, {product::equations});
    REQUIRE(a.elimination);
    REQUIRE(a.elimination->eliminated.size() == 1);
    CHECK(scene.coordinates[a.elimination->eliminated[0].coordinate].name == "h");
}
