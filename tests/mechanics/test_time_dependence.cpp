// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_time_dependence.cpp
 *  Explicit time: L free of t once its sines and cosines are canonical (a hoop turned
 *  at a fixed rate), the points that solve the equations at every t (a vertically
 *  driven pendulum, the Mathieu equation), and the refusal when none does (a
 *  horizontally driven pendulum). */
#include "engine/analysis.h"
#include "mechanics/time_dependence.h"
#include "helpers/cli_runner.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace lagrange;
using namespace lagrange_test;

namespace {

const std::string hoop = "parameters m g R w\ncoordinates q\n"
                         "point bead mass m at (R*sin(q)*cos(w*t), R*sin(q)*sin(w*t), -R*cos(q))\n"
                         "gravity g along (0, 0, -1)\n";

const std::string vertical_drive = "parameters m g l a gamma\ncoordinates phi\n"
                                   "point bob mass m at (l*sin(phi), a*cos(gamma*t) - l*cos(phi))\n"
                                   "gravity g along (0, -1)\n";

const std::string horizontal_drive = "parameters m g l a gamma\ncoordinates phi\n"
                                     "point bob mass m at (a*cos(gamma*t) + l*sin(phi), -l*cos(phi))\n"
                                     "gravity g along (0, -1)\n";

const std::string no_equilibrium = "no equilibrium: L depends on t and no point solves the equations at all t";

} // namespace

TEST_CASE("time dependence: the hoop written with cos(w t) has an L free of t", "[time_dependence]")
{
    const model scene = load(hoop + "values m = 1, g = 9.81, R = 1, w = 2\n");
    CHECK(mentions_time(scene));
    const analysis a = analyze(scene, {product::equilibrium});
    REQUIRE(a.lagrangian);
    CHECK_FALSE(a.lagrangian->lagrangian_canonical.has(scene.time));
    REQUIRE(a.time);
    CHECK_FALSE(a.time->depends_on_time);
    // The reference: ½ m R² (q̇² + w² sin² q) + m g R cos q.
    const GiNaC::ex m = symbol_of(scene, "m"), g = symbol_of(scene, "g"), R = symbol_of(scene, "R"),
                    w = symbol_of(scene, "w"), q = symbol_of(scene, "q"), q_dot = symbol_of(scene, "q_dot");
    const GiNaC::ex reference = GiNaC::numeric(1, 2) * m * R * R * (q_dot * q_dot + w * w * GiNaC::pow(GiNaC::sin(q), 2)) +
                                m * g * R * GiNaC::cos(q);
    CHECK(trig_equal(a.lagrangian->lagrangian_canonical, reference, GiNaC::lst{q}));
    // Past the critical rate w² = g/R the bottom is no longer the stable equilibrium.
    REQUIRE(a.equilibria);
    CHECK(a.equilibria->points.size() >= 2);
}

TEST_CASE("time dependence: a scene without t has no time stage", "[time_dependence]")
{
    const model scene = load("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n");
    CHECK_FALSE(mentions_time(scene));
    const analysis a = analyze(scene, {product::equilibrium});
    CHECK_FALSE(a.time);
    for (const stage_time& s : a.stages)
        CHECK(s.stage != "time");
}

TEST_CASE("time dependence: a vertically driven pendulum is at rest at phi = 0 and pi at every t", "[time_dependence]")
{
    const model scene = load(vertical_drive);
    const analysis a = analyze(scene, {product::equations});
    const simplifier simplify = make_simplifier(scene);
    const time_dependence_result time = analyze_time_dependence(scene, *a.lagrangian, *a.equations, simplify);
    CHECK(time.depends_on_time);
    REQUIRE(time.points.size() == 2);
    CHECK(time.points[0][0].is_zero());
    CHECK(time.points[1][0].is_equal(GiNaC::Pi));
    // The equilibrium stage does not linearize a time-dependent L.
    REQUIRE_THROWS_WITH(analyze(scene, {product::equilibrium}), Catch::Contains("L depends on t"));
}

TEST_CASE("time dependence: a horizontally driven pendulum has no equilibrium", "[time_dependence]")
{
    const model scene = load(horizontal_drive);
    REQUIRE_THROWS_WITH(analyze(scene, {product::equilibrium}), Catch::Contains(no_equilibrium));
    REQUIRE_THROWS_WITH(analyze(scene, {product::numeric}), Catch::Contains(no_equilibrium));
    // The same as a user sees it: exit 1 with the message, nothing linearized.
    const std::string path =
        temporary_file("horizontal.lag", horizontal_drive + "values m = 1, g = 9.81, l = 1, a = 0.1, gamma = 5\n");
    for (const char* format : {"text", "json"}) {
        const cli_result run = run_cli(path + " --format " + format, "", 60);
        CHECK(run.exit_code == 1);
        CHECK(run.err.find(no_equilibrium) != std::string::npos);
        CHECK(run.out.find("ω") == std::string::npos);
    }
}

TEST_CASE("time dependence: an equilibrium line is checked at every t", "[time_dependence]")
{
    const model upright = load(vertical_drive + "equilibrium phi = pi\n");
    const analysis a = analyze(upright, {product::equations});
    const time_dependence_result time =
        analyze_time_dependence(upright, *a.lagrangian, *a.equations, make_simplifier(upright));
    CHECK(time.given);
    REQUIRE(time.points.size() == 1);
    CHECK(time.points[0][0].is_equal(GiNaC::Pi));
    const model wrong = load(vertical_drive + "equilibrium phi = pi/2\nvalues m = 1, g = 1, l = 1, a = 1, gamma = 1\n");
    REQUIRE_THROWS_WITH(analyze(wrong, {product::floquet}), Catch::Contains("does not solve the equations at every t"));
}

TEST_CASE("time dependence: frequencies of the drive, and t outside a sine refused", "[time_dependence]")
{
    const GiNaC::realsymbol t("t"), x("x");
    const GiNaC::possymbol w("w");
    const std::vector<GiNaC::ex> found =
        time_frequencies(x * GiNaC::cos(2 * w * t) + GiNaC::sin(w * t) * GiNaC::sin(3 * w * t + 1), t);
    REQUIRE(found.size() == 3);
    for (const GiNaC::ex& omega : {GiNaC::ex(w), 2 * w, 3 * w})
        CHECK(std::count_if(found.begin(), found.end(), [&](const GiNaC::ex& f) { return (f - omega).is_zero(); }) == 1);
    CHECK(time_frequencies(x * x, t).empty());
    REQUIRE_THROWS_AS(time_frequencies(t * GiNaC::cos(w * t), t), computation_error);
    REQUIRE_THROWS_WITH(time_frequencies(GiNaC::sin(w * t * t), t), Catch::Contains("not linear in t"));
}
