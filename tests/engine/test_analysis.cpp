// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_analysis.cpp
 *  The stage planner: only the stages a product needs run, in order, once. */
#include "engine/analysis.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>

using namespace lagrange;
using namespace lagrange_test;

namespace {

std::vector<std::string> stage_names(const analysis& a)
{
    std::vector<std::string> names;
    for (const stage_time& s : a.stages)
        names.push_back(s.stage);
    return names;
}

const std::string oscillator = "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n";

} // namespace

TEST_CASE("analysis: equations run the lagrangian stage, then the equations", "[analysis]")
{
    model scene = load(oscillator);
    const auto start = std::chrono::steady_clock::now();
    analysis a = analyze(scene, {product::equations});
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(stage_names(a) == std::vector<std::string>{"lagrangian", "equations", "verification"});
    REQUIRE(a.equations);
    REQUIRE(a.equations->residuals);
    CHECK(a.equations->residuals->size() == 1);
    // Each stage's time is its share of the run: together no more than the whole call.
    double total = 0;
    for (const stage_time& s : a.stages) {
        INFO(s.stage << ": " << s.seconds << " s of " << elapsed << " s");
        CHECK(std::isfinite(s.seconds));
        CHECK(s.seconds >= 0);
        total += s.seconds;
    }
    CHECK(total <= elapsed);
    CHECK(total > 0);
}

TEST_CASE("analysis: without --want, the scene's want line decides, else what the scene supports", "[analysis]")
{
    model plain = load(oscillator);
    std::set<product> small_oscillations = {product::equations,      product::equilibrium, product::linearization,
                                            product::characteristic, product::frequencies, product::modes,
                                            product::normal_coordinates};
    CHECK(analyze(plain).wanted == small_oscillations);
    model with_values = load(oscillator + "values m = 1, k = 4\n");
    analysis numeric = analyze(with_values);
    CHECK(numeric.wanted.count(product::numeric));
    REQUIRE(numeric.numeric);
    CHECK(numeric.numeric->at(0).omega.at(0) == Approx(2.0).epsilon(1e-15));
    model asking = load(oscillator + "want equations\n");
    CHECK(analyze(asking).wanted == std::set<product>{product::equations});
}

TEST_CASE("analysis: inertia and euler without a rigid body are computation errors", "[analysis]")
{
    model scene = load(oscillator + "want inertia\n");
    REQUIRE_THROWS_MATCHES(analyze(scene), computation_error,
                           Catch::Matchers::Message("`inertia` and `euler` need a rigid body (`body B disk(R) mass M`)"));
    CHECK_THROWS_AS(analyze(load(oscillator), {product::euler}), computation_error);
}

TEST_CASE("analysis: only the stages a product needs run", "[analysis]")
{
    model scene = load(oscillator + "values m = 1, k = 4\n");
    CHECK(stage_names(analyze(scene, {product::characteristic})) ==
          std::vector<std::string>{"lagrangian", "equilibrium", "linearization", "characteristic", "verification"});
    CHECK(stage_names(analyze(scene, {product::numeric})) ==
          std::vector<std::string>{"lagrangian", "equilibrium", "linearization", "numeric", "verification"});
}

TEST_CASE("analysis: a wanted product that cannot be done is an error, by default a note", "[analysis]")
{
    const std::string no_values = oscillator + "want numeric\n";
    REQUIRE_THROWS_AS(analyze(load(no_values)), computation_error);
    const std::string free_coordinate = "parameters m k\ncoordinates x y\nT = 1/2*m*x'^2\nV = 1/2*k*x^2 + k*y^2\n";
    analysis by_default = analyze(load(free_coordinate));
    CHECK(by_default.equations);
    REQUIRE(by_default.notes.size() == 1);
    CHECK(by_default.notes[0].find("no kinetic energy") != std::string::npos);
    CHECK_THROWS_AS(analyze(load(free_coordinate), {product::modes}), computation_error);
}
