/** @file test_analysis.cpp
 *  The stage planner: only the stages a product needs run, in order, once. */
#include "engine/analysis.h"
#include "scene_helpers.h"

#include <catch2/catch.hpp>

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
    analysis a = analyze(scene, {product::equations});
    CHECK(stage_names(a) == std::vector<std::string>{"lagrangian", "equations"});
    REQUIRE(a.equations);
    CHECK(a.equations->size() == 1);
    for (const stage_time& s : a.stages)
        CHECK(s.seconds >= 0);
}

TEST_CASE("analysis: without --want, the scene's want line decides, else every available product", "[analysis]")
{
    model plain = load(oscillator);
    CHECK(analyze(plain).wanted == available_products());
    model asking = load(oscillator + "want equations\n");
    CHECK(analyze(asking).wanted == std::set<product>{product::equations});
}

TEST_CASE("analysis: a product this version does not compute is a computation error", "[analysis]")
{
    model scene = load(oscillator + "want modes\n");
    REQUIRE_THROWS_MATCHES(analyze(scene), computation_error,
                           Catch::Matchers::Message("`modes` is not computed by this version of lagrange yet"));
    CHECK_THROWS_AS(analyze(load(oscillator), {product::inertia}), computation_error);
}
