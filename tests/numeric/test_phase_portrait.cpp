// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_phase_portrait.cpp
 *  Phase portraits (numeric/phase_portrait.h): the pendulum's energy grid, its minimum and
 *  its separatrix through the upright position; a non-periodic well; the coordinate option. */
#include "engine/analysis.h"
#include "numeric/phase_portrait.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lagrange_test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

lagrange::phase_portrait portrait_of(const std::string& text, const std::string& coordinate = "")
{
    lagrange::model scene = load(text);
    lagrange::analysis result =
        lagrange::analyze(scene, {lagrange::product::equations, lagrange::product::equilibrium});
    lagrange::phase_settings settings;
    settings.grid = 101;
    if (!coordinate.empty())
        settings.coordinate = lagrange::phase_coordinate(coordinate, scene);
    return lagrange::compute_phase_portrait(scene, *result.equations,
                                            result.equilibria ? &*result.equilibria : nullptr, settings);
}

} // namespace

TEST_CASE("phase portrait: the pendulum's levels, minimum and separatrix through the upright position", "[phase]")
{
    const double m = 2, l = 1.5, g = 9.81;
    const lagrange::phase_portrait p = portrait_of("parameters m l g\ncoordinates theta\n"
                                                   "point P mass m at (l*sin(theta), -l*cos(theta))\n"
                                                   "gravity g along (0, -1)\nvalues m = 2, l = 1.5, g = 9.81\n");
    CHECK_THAT(p.q_low, WithinAbs(-M_PI, 1e-12));
    CHECK_THAT(p.q_high, WithinAbs(M_PI, 1e-12));
    CHECK_THAT(p.minimum, WithinRel(-m * g * l, 1e-12));
    REQUIRE(p.separatrices.size() == 1);
    CHECK_THAT(p.separatrices[0], WithinRel(m * g * l, 1e-12));
    REQUIRE(p.unstable.size() == 1);
    CHECK_THAT(std::abs(p.unstable[0]), WithinRel(M_PI, 1e-12));
    REQUIRE(p.stable.size() == 1);
    CHECK_THAT(p.stable[0], WithinAbs(0, 1e-12));
    CHECK(p.levels.size() == 12);
    // Levels below and above the separatrix: librations and rotations.
    CHECK(p.levels.front() < p.separatrices[0]);
    CHECK(p.levels.back() > p.separatrices[0]);
    // The grid is h = ½ m l² q̇² − m g l cos q, and the rotations at the top level fit in it.
    double worst = 0;
    for (std::size_t r = 0; r < p.grid; r += 7)
        for (std::size_t i = 0; i < p.grid; i += 5) {
            const double q = p.q(i), v = p.v(r);
            worst = std::max(worst, std::abs(p.energy[r * p.grid + i] - (m * l * l * v * v / 2 - m * g * l * std::cos(q))));
        }
    CHECK(worst <= 1e-12 * m * g * l);
    const double top = p.levels.back();
    CHECK(p.v_high >= std::sqrt(2 * (top + m * g * l) / (m * l * l)));
}

TEST_CASE("phase portrait: a quartic double well has its separatrix at the hump, and --coordinate names a coordinate",
          "[phase]")
{
    // V = (x² − 1)²: stable at x = ±1 (V = 0), unstable at 0 (V = 1): the figure-eight separatrix.
    const std::string well = "coordinates x y\nT = 1/2*x'^2 + 1/2*y'^2\nV = (x^2 - 1)^2 + y^2\n";
    const lagrange::phase_portrait p = portrait_of(well, "x");
    REQUIRE(p.separatrices.size() == 1);
    CHECK_THAT(p.separatrices[0], WithinRel(1.0, 1e-12));
    CHECK_THAT(p.minimum, WithinAbs(0, 1e-12));
    REQUIRE(p.unstable.size() == 1);
    CHECK_THAT(p.unstable[0], WithinAbs(0, 1e-12));
    CHECK(p.stable.size() == 2);
    CHECK(p.q_low < -1);
    CHECK(p.q_high > 1);
    // y's slice through the well at x = ±1 is a plain oscillator: no separatrix.
    CHECK(portrait_of(well, "y").separatrices.empty());
    try {
        portrait_of(well, "z");
        FAIL("no error");
    } catch (const lagrange::scene_error& e) {
        CHECK(e.where().file == "--coordinate");
        CHECK(std::string(e.what()).find("`z` is not a coordinate of the scene (its coordinates: x, y)") !=
              std::string::npos);
    }
}
