// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_response.cpp
 *  The frequency response H(iω): the damped oscillator's magnitude peak at
 *  ω_r = √(ω₀² − 2γ²) with |H| = 1/(2mγ√(ω₀² − γ²)) there, its magnitude and phase at every
 *  frequency against |1/(k − mω² + ibω)|, and an unknown input or coordinate. */
#include "engine/analysis.h"
#include "numeric/linear_response.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

using namespace lagrange;
using lagrange_test::load;

namespace {

const char* oscillator = R"(parameters m k b
coordinates x
input u
point P mass m at (x, 0)
spring k between P and (0, 0)
damper b between P and (0, 0)
force on P (u, 0)
values m = 2, k = 8, b = 0.6
)";

} // namespace

TEST_CASE("response: the damped oscillator peaks at ω_r = √(ω₀² − 2γ²)", "[response]")
{
    model scene = load(oscillator);
    analysis a = analyze(scene, {product::state_space});
    REQUIRE(a.state_space);
    response_settings settings;
    settings.from = 0.1;
    settings.to = 20;
    settings.points = 301;
    frequency_response r = frequency_response_of(scene, *a.linearization, *a.state_space, "u", "x", settings);
    const double m = 2, k = 8, b = 0.6;
    const double gamma = b / (2 * m), omega0_squared = k / m;
    const double resonance = std::sqrt(omega0_squared - 2 * gamma * gamma);
    CHECK_THAT(r.peak_omega, Catch::WithinRel(resonance, 1e-7));
    CHECK_THAT(r.peak_magnitude,
               Catch::WithinRel(1 / (2 * m * gamma * std::sqrt(omega0_squared - gamma * gamma)), 1e-12));
    REQUIRE(r.omega.size() == 301);
    CHECK_THAT(r.omega.front(), Catch::WithinRel(0.1, 1e-15));
    CHECK_THAT(r.omega.back(), Catch::WithinRel(20.0, 1e-13));
    for (std::size_t j = 0; j < r.omega.size(); ++j) {
        const double w = r.omega[j];
        const std::complex<double> h = 1.0 / std::complex<double>(k - m * w * w, b * w);
        CHECK_THAT(r.magnitude[j], Catch::WithinRel(std::abs(h), 1e-13));
        CHECK_THAT(r.phase_degrees[j], Catch::WithinAbs(std::arg(h) * 180 / M_PI, 1e-10));
        CHECK_THAT(r.magnitude_db[j], Catch::WithinAbs(20 * std::log10(std::abs(h)), 1e-12));
    }
    // The phase falls from 0 through −90° at ω₀ towards −180°.
    CHECK(r.phase_degrees.front() > -5);
    CHECK(r.phase_degrees.back() < -175);
}

TEST_CASE("response: the default range spans a decade either side of the eigenvalues", "[response]")
{
    model scene = load(oscillator);
    analysis a = analyze(scene, {product::state_space});
    frequency_response r = frequency_response_of(scene, *a.linearization, *a.state_space, "u", "x", {});
    CHECK_THAT(r.omega.front(), Catch::WithinRel(0.2, 1e-12)); // |s| = ω₀ = 2
    CHECK_THAT(r.omega.back(), Catch::WithinRel(20.0, 1e-12));
}

TEST_CASE("response: an unknown input or coordinate is an error", "[response]")
{
    model scene = load(oscillator);
    analysis a = analyze(scene, {product::state_space});
    CHECK_THROWS_WITH(frequency_response_of(scene, *a.linearization, *a.state_space, "v", "x", {}),
                      Catch::Contains("no input `v`"));
    CHECK_THROWS_WITH(frequency_response_of(scene, *a.linearization, *a.state_space, "u", "y", {}),
                      Catch::Contains("no coordinate `y`"));
}
