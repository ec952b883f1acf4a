// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_lower_rolling.cpp
 *  `rolls W on ground`: the constraints it derives from a wheel's pose (a coin leaning
 *  on the plane: contact height r cos q2 above the ground for a centre at height h, and
 *  the velocity of its material contact point), and its errors. */
#include "scene/lower.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>
#include <string>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::require_error;

namespace {

/// A disc of radius r whose centre is at (x, y, h), yawed by q1, leaning by q2 and turning
/// by q3 about its axis y.
const std::string coin = "parameters m g r\ncoordinates x y h q1 q2 q3\n"
                         "body D disk(r) mass m axis y at (x, y, h) orientation rotations(z q1, x q2, y q3)\n"
                         "gravity g along (0, 0, -1)\n";

double at(const GiNaC::ex& e, const GiNaC::exmap& point)
{
    return GiNaC::ex_to<GiNaC::numeric>(e.subs(point).evalf()).to_double();
}

} // namespace

TEST_CASE("rolls: a coin's contact height and no-slip constraints", "[lower][rolls]")
{
    const model scene = load(coin + "rolls D on ground\n");
    REQUIRE(scene.constraints.size() == 3);
    CHECK(scene.constraints[0].name == "D_contact");
    CHECK(scene.constraints[0].constraint_kind == constraint::kind::holonomic);
    CHECK(scene.constraints[1].name == "D_roll_x");
    CHECK(scene.constraints[2].name == "D_roll_y");
    CHECK(scene.constraints[1].constraint_kind == constraint::kind::pfaffian);
    CHECK(scene.constraints[1].multiplier.get_name() == "lambda_D_roll_x");
    // At random states: the contact is h − r cos q2 above the ground, and the contact point's
    // velocity is the centre's plus ω × (p − c), with p − c = r (−sin q2 sin q1, sin q2 cos q1,
    // −cos q2) and ω = q̇1 e_z + q̇2 (cos q1, sin q1, 0) + q̇3 (the disc's axis).
    std::mt19937 random(7);
    std::uniform_real_distribution<double> small(-0.6, 0.6);
    for (int trial = 0; trial < 5; ++trial) {
        GiNaC::exmap point;
        std::map<std::string, double> q;
        for (const coordinate& c : scene.coordinates) {
            q[c.name] = small(random);
            q[c.name + "'"] = small(random);
            point[c.position] = q[c.name];
            point[c.velocity] = q[c.name + "'"];
        }
        const double r = 0.7;
        point[lagrange_test::symbol_of(scene, "r")] = r;
        const double q1 = q["q1"], q2 = q["q2"];
        CHECK(at(scene.constraints[0].function, point) == Approx(q["h"] - r * std::cos(q2)).margin(1e-12));
        const double axis[3] = {-std::cos(q2) * std::sin(q1), std::cos(q2) * std::cos(q1), std::sin(q2)};
        const double omega[3] = {q["q2'"] * std::cos(q1) + q["q3'"] * axis[0],
                                 q["q2'"] * std::sin(q1) + q["q3'"] * axis[1], q["q1'"] + q["q3'"] * axis[2]};
        const double offset[3] = {-r * std::sin(q2) * std::sin(q1), r * std::sin(q2) * std::cos(q1), -r * std::cos(q2)};
        const double slip_x = q["x'"] + omega[1] * offset[2] - omega[2] * offset[1];
        const double slip_y = q["y'"] + omega[2] * offset[0] - omega[0] * offset[2];
        CHECK(at(scene.constraints[1].function, point) == Approx(slip_x).margin(1e-12));
        CHECK(at(scene.constraints[2].function, point) == Approx(slip_y).margin(1e-12));
    }
}

TEST_CASE("rolls: an inertia body rolls with its rim's radius and axis", "[lower][rolls]")
{
    const model scene = load("parameters m g r I J\ncoordinates x y h q1 q2 q3\n"
                             "body W inertia (I, J, I) mass m at (x, y, h) orientation rotations(z q1, x q2, y q3)\n"
                             "gravity g along (0, 0, -1)\nrolls W on ground radius r axis y\n");
    REQUIRE(scene.constraints.size() == 3);
    CHECK(scene.constraints[2].name == "W_roll_y");
}

TEST_CASE("rolls: errors", "[lower][rolls]")
{
    require_error(coin + "rolls E on ground\n", 5, 7, "unknown body `E`");
    require_error(coin + "rolls D on floor\n", 5, 12, "`ground`");
    require_error(coin + "rolls D on ground\nrolls D on ground\n", 6, 7, "already rolls");
    require_error(coin + "rolls D on ground axis z\n", 5, 24, "its own axis `y`");
    require_error(coin + "rolls D on ground radius -1 axis y\n", 5, 1, "must be positive");
    require_error("parameters m g r I\ncoordinates x q\n"
                  "body W inertia (I, I, I) mass m at (x, 0, r) orientation rotations(y q)\n"
                  "gravity g along (0, 0, -1)\nrolls W on ground\n",
                  5, 7, "not a `disk` or `ring`");
    require_error("parameters m g r\ncoordinates x\nbody D disk(r) mass m at (x, 0, r)\n"
                  "gravity g along (0, 0, -1)\nrolls D on ground\n",
                  5, 7, "has no orientation");
    require_error("parameters m r\ncoordinates x q\n"
                  "body D disk(r) mass m axis y at (x, 0, r) orientation rotations(y q)\nrolls D on ground\n",
                  4, 1, "needs three-dimensional gravity");
    require_error(coin + "constraint D_roll_x: x = 0\nrolls D on ground\n", 6, 7, "already declared");
    require_error("parameters m g r a\ncoordinates x y h q1 q2 q3\n"
                  "body D disk(r) mass m axis y at (x, y, h) orientation rotations(z q1, x q2, y q3)\n"
                  "gravity g along (0, a, -1)\nrolls D on ground\n",
                  5, 1, "direction of gravity in numbers");
}
