// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_parser.cpp
 *  The parser: every statement, nesting limits, and its error paths. */
#include "helpers/scene_helpers.h"
#include "scene/parser.h"

#include <catch2/catch.hpp>

using namespace lagrange;
using namespace lagrange_test;

TEST_CASE("parser: error paths", "[parser]")
{
    require_error("parameters\n", 1, 11, "expected a name after `parameters`");
    require_error("frobnicate x\n", 1, 1, "unknown statement `frobnicate`");
    require_error("42\n", 1, 1, "expected a statement");
    require_error(header + "T = (m*q'\n", 3, 10, "expected `)`");
    require_error(header + "T = m*\n", 3, 7, "expected an expression");
    require_error(header + "point P mass m to (l, 0)\n", 3, 16, "expected `at`");
    require_error(header + "point P mass m at (l)\n", 3, 21, "a vector has 2 or 3 components");
    require_error(header + "point P mass m at (l, 0, 0, 0)\n", 3, 27, "a vector has 2 or 3 components");
    require_error(header + "T = m*(q+1)'\n", 3, 12, "follows a coordinate's name only");
    require_error(header + "limit m -> 1\n", 3, 12, "expected `0` or `oo`");
    require_error(header + "simulate until 1 step 0.1 step 0.2\n", 3, 27, "given twice");
    require_error(header + "simulate 10\n", 3, 10, "expected `until`");
    require_error(header + "spring k between (0,0) or (1,1)\n", 3, 24, "expected `and`");
    require_error(header + "T = m q\n", 3, 7, "expected the end of the statement");
    require_error(header + "want equations modes\n", 3, 16, "expected the end of the statement");
    require_error(header + "body B disk(l) mass m spin (0,0,1)\n", 3, 23, "expected `axis`");
}

TEST_CASE("parser: a function name followed by its argument asks for parentheses", "[parser]")
{
    require_error(header + "point P mass m at (l*sin q, -l*cos(q))\n", 3, 26, "write `sin(q)`");
    require_error(header + "V = -m*g*l*cos q\n", 3, 16, "a function's argument goes in parentheses: write `cos(q)`");
    require_error(header + "V = exp 2\n", 3, 9, "write `exp(2)`");
    // A name that is no function keeps the general message.
    require_error(header + "T = m q\n", 3, 7, "expected the end of the statement, found `q`");
}

TEST_CASE("parser: nesting deeper than the limit is an error, not a crash", "[parser]")
{
    std::string deep = std::string(10000, '(') + "q" + std::string(10000, ')');
    require_error(header + "V = " + deep + "\n", 3, 5 + max_expression_depth, "nested more than");
    std::string minus(10000, '-');
    require_error(header + "V = " + minus + "q\n", 3, 5 + max_expression_depth, "nested more than");
}

TEST_CASE("parser: every statement of the language parses", "[parser]")
{
    std::string text = R"(scene "all"
parameters M m l g k a
coordinates x y
let r = sqrt(x^2 + y^2)
point P mass m at (x, y)
point Q mass M at (x + l, y, 0)
gravity g along (0, -1)
spring k between P and Q rest a
spring k between (0, 0) and P
equilibrium x = 0, y = 0
values M = 1, m = 1/2, l = 1, g = 9.81, k = 1e3, a = 0.5
initial x = 0.1, x' = 0, y' = 2
simulate until 10 step 0.01 method rk45 tolerance 1e-9
want equations
)";
    model scene = load(text);
    CHECK(scene.title == "all");
    CHECK(scene.points.size() == 2);
    CHECK(scene.springs.size() == 2);
    CHECK(scene.values.size() == 1);
    REQUIRE(scene.simulation);
    CHECK(scene.simulation->method == "rk45");
    CHECK(scene.wanted == std::set<product>{product::equations});
    REQUIRE(scene.initial);
    CHECK(scene.initial->velocities.count("y"));
}

TEST_CASE("parser: rigid-body statements parse and lower", "[parser]")
{
    CHECK(load(header + "body B disk(l) mass m axis z at (0, 0, l)\n").bodies.size() == 1);
    CHECK(load(header + "body B region ball(l) density 1 + x^2\n").bodies.size() == 1);
    CHECK(load(header + "body B inertia (1, 2, 3) mass m orientation zxz(q, q, q)\n").bodies.size() == 1);
    model free = load(header + "body B inertia (1, 2, 3) mass m\nomega B (w1, w2, w3)\ntorque B (0, 0, 1)\n");
    REQUIRE(free.bodies.size() == 1);
    CHECK(free.bodies[0].omega.has_value());
}
