// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_critical.cpp
 *  Critical parameters: the reduced Whipple bicycle (examples/bicycle_reduced.lag) against
 *  the benchmark of Meijaard, Papadopoulos, Ruina and Schwab, Proc. R. Soc. A 463 (2007)
 *  1955–1982: the lean/steer eigenvalues at v = 0, 1, …, 10 m/s of its Table 2 (as
 *  transcribed in D. L. Peterson's whipple test, and for v = 0, 4, 5, 10 in the
 *  `pathfinder` package's test_whipple.py) and the weave and capsize speeds of its §5;
 *  a range with no crossing; a damped oscillator whose stiffness k − a changes sign at
 *  a = k. */
#include "engine/analysis.h"
#include "numeric/critical.h"
#include "helpers/bicycle_benchmark.h"
#include "helpers/cli_runner.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <complex>
#include <map>
#include <vector>

using namespace lagrange;
using lagrange_test::load;

namespace {

using complex = std::complex<double>;

using lagrange_test::check_table_2;

model bicycle()
{
    return load_model(source_text("bicycle_reduced.lag",
                                  lagrange_test::read_file(std::string(LAGRANGE_SOURCE_DIR) +
                                                           "/examples/bicycle_reduced.lag")));
}

} // namespace

TEST_CASE("critical: the reduced bicycle's eigenvalues match Meijaard's Table 2", "[critical]")
{
    const model scene = bicycle();
    const analysis result = analyze(scene, {product::critical});
    REQUIRE(result.critical);
    check_table_2(*result.critical);
}

TEST_CASE("critical: the reduced bicycle's weave and capsize speeds to 1e-10", "[critical]")
{
    const model scene = bicycle();
    const analysis result = analyze(scene, {product::critical});
    REQUIRE(result.critical);
    const std::vector<critical_crossing>& crossings = result.critical->crossings;
    REQUIRE(crossings.size() == 2);
    // Meijaard et al. (2007), §5: v_w = 4.292382536341, v_c = 6.024262015388 (m/s)
    CHECK(std::abs(crossings[0].value - 4.292382536341) <= 1e-10);
    CHECK(std::abs(crossings[1].value - 6.024262015388) <= 1e-10);
    CHECK(crossings[0].tolerance <= 1e-12);
    CHECK(crossings[1].tolerance <= 1e-12);
    // the weave pair crosses at ±iω (the paper's 3.43503384866144 rad/s), capsize through 0
    CHECK(std::abs(crossings[0].eigenvalue.imag() - 3.43503384866144) <= 1e-9);
    CHECK(std::abs(crossings[1].eigenvalue) <= 1e-9);
    CHECK(crossings[0].unstable_before == 2);
    CHECK(crossings[0].unstable_after == 0);
    CHECK(crossings[1].unstable_before == 0);
    CHECK(crossings[1].unstable_after == 1);
}

TEST_CASE("critical: a range with no crossing has none", "[critical]")
{
    std::string text = lagrange_test::read_file(std::string(LAGRANGE_SOURCE_DIR) + "/examples/bicycle_reduced.lag");
    const std::string line = "critical v from 0 to 10";
    text.replace(text.find(line), line.size(), "critical v from 7 to 10");
    const analysis result = analyze(load(text), {product::critical});
    REQUIRE(result.critical);
    CHECK(result.critical->crossings.empty());
}

TEST_CASE("critical: a damped stiffness through zero crosses where it vanishes", "[critical]")
{
    // m x'' + b x' + (k − a) x = 0 with a force a·x − b·x': one real s through 0 at a = k
    const model scene = load(R"(parameters m k a b
coordinates x
T = 1/2*m*x'^2
V = 1/2*k*x^2
force x = a*x - b*x'
equilibrium x = 0
values m = 2, k = 3, b = 0.5
critical a from 1 to 5
)");
    const analysis result = analyze(scene, {product::critical});
    REQUIRE(result.critical);
    REQUIRE(result.critical->crossings.size() == 1);
    CHECK(std::abs(result.critical->crossings[0].value - 3) <= 1e-10);
    CHECK(result.critical->crossings[0].unstable_before == 0);
    CHECK(result.critical->crossings[0].unstable_after == 1);
}

TEST_CASE("critical: errors", "[critical]")
{
    lagrange_test::require_error("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\ncritical w from 0 to 1\n", 4, 10,
                                 "is not a parameter");
    lagrange_test::require_error("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\ncritical k from 2 to 1\n", 4, 22,
                                 "above its start");
    lagrange_test::require_error("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\ncritical k from -1 to 1\n", 4, 17,
                                 "≥ 0");
    // no `values` for the other parameter
    const model scene = load("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\nequilibrium x = 0\n"
                             "critical k from 1 to 2\n");
    REQUIRE_THROWS_WITH(analyze(scene, {product::critical}), Catch::Contains("needs a value of parameter `m`"));
}
