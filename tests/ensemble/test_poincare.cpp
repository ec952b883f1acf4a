// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_poincare.cpp
 *  Poincaré sections (ensemble/poincare.h, output/poincare_output.h): the points of an
 *  integrable system on their known ellipses, Hénon–Heiles' points on the energy surface,
 *  the same bytes on 1 and 2 threads, and the section option's errors. */
#include "engine/analysis.h"
#include "ensemble/poincare.h"
#include "output/poincare_output.h"
#include "helpers/cli_runner.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace lagrange_test;

namespace {

const std::string scenes = std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/";

lagrange::poincare_result section_of(const lagrange::model& scene, const std::string& text,
                                     const lagrange::poincare_settings& settings)
{
    lagrange::analysis result =
        lagrange::analyze(scene, {lagrange::product::equations, lagrange::product::equilibrium});
    return lagrange::compute_poincare(scene, *result.equations, result.equilibria ? &*result.equilibria : nullptr,
                                      lagrange::parse_poincare_section(text, scene), settings);
}

} // namespace

TEST_CASE("poincare: the section of two uncoupled oscillators lies on each orbit's ellipse", "[ensemble][poincare]")
{
    // Each oscillator keeps its energy, so orbit k's points (y, y') lie on
    // (1/2) y'^2 + (1/2) k2 y^2 = E_y(k), and x = 0, x' = sqrt(2 (E - E_y)) > 0 there.
    lagrange::model scene = load(read_file(scenes + "two_oscillators.lag"));
    lagrange::poincare_settings settings;
    settings.energy = 1;
    settings.orbits = 12;
    settings.crossings = 30;
    settings.tolerance = 1e-10;
    settings.threads = 2;
    const lagrange::poincare_result result = section_of(scene, "x = 0, x' > 0", settings);
    REQUIRE(result.no_crossings.empty());
    REQUIRE(result.has_minimum);
    CHECK(result.minimum == 0);
    CHECK(result.crossings() == 12 * 30);
    double worst = 0;
    for (const lagrange::poincare_orbit& orbit : result.orbits) {
        REQUIRE(orbit.failure.empty());
        const double* start = orbit.points.data();
        const double ellipse = start[4] * start[4] / 2 + start[2] * start[2]; // k2 = 2
        for (std::size_t p = 0; p < orbit.points.size(); p += 5) {
            const double* c = orbit.points.data() + p;
            const double t = c[0], x = c[1], y = c[2], x_dot = c[3], y_dot = c[4];
            INFO("crossing at t = " << t);
            CHECK(std::abs(x) <= 1e-12);
            CHECK(x_dot > 0);
            worst = std::max(worst, std::abs(y_dot * y_dot / 2 + y * y - ellipse));
            // x = sin(t)·A crosses 0 upwards at t = 2πk (k1 = 1).
            const double turns = t / (2 * M_PI);
            CHECK(std::abs(turns - std::round(turns)) <= 1e-8);
        }
    }
    // On its ellipse to the tolerance (energies of order 1).
    CHECK(worst <= 1e-9);
    CHECK(result.worst_energy_error <= 1e-9);
}

TEST_CASE("poincare: Hénon–Heiles at E = 1/12 conserves the energy at every crossing, on any number of threads",
          "[ensemble][poincare]")
{
    lagrange::model scene = load(read_file(scenes + "henon_heiles.lag"));
    lagrange::poincare_settings settings;
    settings.energy = 1.0 / 12;
    settings.orbits = 16;
    settings.crossings = 60;
    settings.seed = 7;
    settings.tolerance = 1e-10;
    settings.threads = 1;
    const lagrange::poincare_result one = section_of(scene, "x = 0, x' > 0", settings);
    settings.threads = 2;
    const lagrange::poincare_result two = section_of(scene, "x = 0, x' > 0", settings);
    REQUIRE(one.crossings() == 16 * 60);
    REQUIRE(one.failures() == 0);
    double worst = 0;
    for (const lagrange::poincare_orbit& orbit : one.orbits)
        for (std::size_t p = 0; p < orbit.points.size(); p += 5) {
            const double x = orbit.points[p + 1], y = orbit.points[p + 2];
            const double u = orbit.points[p + 3], v = orbit.points[p + 4];
            CHECK(std::abs(x) <= 1e-12);
            CHECK(u > 0);
            // H = (u² + v²)/2 + (x² + y²)/2 + x² y − y³/3, written out independently of the engine.
            const double h = (u * u + v * v) / 2 + (x * x + y * y) / 2 + x * x * y - y * y * y / 3;
            worst = std::max(worst, std::abs(h - settings.energy) / settings.energy);
        }
    // The tolerance bounds the error of a span of a few periods; over 60 crossings (about 400
    // time units, 60 periods) the energy drifts past it, by 2.7 times at tolerance 1e-9.
    CHECK(worst <= 10 * settings.tolerance);
    CHECK(worst > 0); // measured, not assumed
    std::ostringstream a, b;
    lagrange::write_poincare_csv(a, one);
    lagrange::write_poincare_csv(b, two);
    CHECK(a.str() == b.str());
    CHECK(two.threads == 2);
    // Another seed starts other orbits.
    settings.seed = 8;
    std::ostringstream c;
    lagrange::write_poincare_csv(c, section_of(scene, "x = 0, x' > 0", settings));
    CHECK(c.str() != a.str());
}

TEST_CASE("poincare: a section the energy does not reach has no crossings, and an energy below the minimum is refused",
          "[ensemble][poincare]")
{
    lagrange::model scene = load(read_file(scenes + "two_oscillators.lag"));
    lagrange::poincare_settings settings;
    settings.energy = 1;
    settings.orbits = 4;
    // ½ x² = 2 > 1 on the section x = 2.
    const lagrange::poincare_result far = section_of(scene, "x = 2", settings);
    CHECK(far.crossings() == 0);
    CHECK_THAT(far.no_crossings, Catch::Contains("outside the energy surface"));
    settings.energy = -0.5;
    CHECK_THROWS_AS(section_of(scene, "x = 0", settings), lagrange::poincare_request_error);
    CHECK_THROWS_WITH(section_of(scene, "x = 0", settings), Catch::Contains("below the minimum of the energy, 0"));
}

TEST_CASE("poincare: a bad --section is an error located in the option", "[ensemble][poincare]")
{
    lagrange::model scene = load(read_file(scenes + "henon_heiles.lag"));
    auto require_error = [&](const std::string& text, int column, const std::string& fragment) {
        require_option_error("--section", text, [&] { lagrange::parse_poincare_section(text, scene); }, column, fragment);
    };
    require_error("psi = 0, psi' > 0", 1, "`psi` is not a coordinate");
    require_error("x = 0, z' > 0", 8, "`z` is not a coordinate");
    require_error("x = 0, y' > 0", 8, "that of the section's coordinate");
    require_error("x = a", 5, "not a number");
    require_error("x 0", 3, "expected `=`");
    require_error("x = 0, x' >= 0", 12, "expected `0`");
    require_error("x = 0, x > 0", 8, "expected the direction");
    const lagrange::poincare_section s = lagrange::parse_poincare_section("y = -0.25, y_dot < 0", scene);
    CHECK(s.coordinate == 1);
    CHECK(s.level == -0.25);
    CHECK(s.direction == -1);
    CHECK(lagrange::parse_poincare_section(" x=0.5 ", scene).direction == 0);
}

TEST_CASE("poincare: three uncoupled oscillators keep each free oscillator on its ellipse on any number of threads",
          "[ensemble][poincare]")
{
    // The section x = 0, x' > 0 of three coordinates has four dimensions (y, z, y', z'); each
    // oscillator keeps its energy, so orbit k's points lie on (1/2) y'^2 + y^2 = E_y(k) and
    // (1/2) z'^2 + (3/2) z^2 = E_z(k) (k2 = 2, k3 = 3), at the times 2πk (k1 = 1).
    lagrange::model scene = load(read_file(scenes + "three_oscillators.lag"));
    lagrange::poincare_settings settings;
    settings.energy = 1;
    settings.orbits = 10;
    settings.crossings = 25;
    settings.tolerance = 1e-10;
    settings.threads = 1;
    const lagrange::poincare_result one = section_of(scene, "x = 0, x' > 0", settings);
    REQUIRE(one.no_crossings.empty());
    REQUIRE(one.width() == 7);
    REQUIRE(one.crossings() == 10 * 25);
    CHECK(one.minimum == 0);
    double worst_y = 0, worst_z = 0, worst_h = 0;
    for (const lagrange::poincare_orbit& orbit : one.orbits) {
        REQUIRE(orbit.failure.empty());
        const double* s = orbit.points.data();
        const double e_y = s[5] * s[5] / 2 + s[2] * s[2], e_z = s[6] * s[6] / 2 + 1.5 * s[3] * s[3];
        for (std::size_t p = 0; p < orbit.points.size(); p += 7) {
            const double* c = orbit.points.data() + p;
            const double t = c[0], x = c[1], y = c[2], z = c[3], u = c[4], v = c[5], w = c[6];
            INFO("crossing at t = " << t);
            CHECK(std::abs(x) <= 1e-12);
            CHECK(u > 0);
            worst_y = std::max(worst_y, std::abs(v * v / 2 + y * y - e_y));
            worst_z = std::max(worst_z, std::abs(w * w / 2 + 1.5 * z * z - e_z));
            // H written out: (u² + v² + w²)/2 + x²/2 + y² + 3 z²/2.
            worst_h = std::max(worst_h, std::abs((u * u + v * v + w * w) / 2 + x * x / 2 + y * y + 1.5 * z * z - 1));
            const double turns = t / (2 * M_PI);
            CHECK(std::abs(turns - std::round(turns)) <= 1e-8);
        }
    }
    CHECK(worst_y <= 1e-9);
    CHECK(worst_z <= 1e-9);
    CHECK(worst_h <= 1e-9);
    CHECK(one.worst_energy_error <= 1e-9);
    settings.threads = 2;
    const lagrange::poincare_result two = section_of(scene, "x = 0, x' > 0", settings);
    CHECK(two.threads == 2);
    std::ostringstream a, b;
    lagrange::write_poincare_csv(a, one);
    lagrange::write_poincare_csv(b, two);
    CHECK(a.str().rfind("orbit,t,x,y,z,x_dot,y_dot,z_dot\n", 0) == 0);
    CHECK(a.str() == b.str());
}

TEST_CASE("poincare: the starts of three oscillators fill the section's energy ellipsoid uniformly",
          "[ensemble][poincare]")
{
    // On x = 0 the free part (y, z, y', z') may take any point of the solid ellipsoid
    // y² + (3/2) z² + (1/2)(y'² + z'²) ≤ E (x' > 0 takes the rest). Drawn uniformly in it, the
    // normalized radius r (r² that sum over E) of a 4-ball has P(r ≤ s) = s⁴: a box too small
    // for the ellipsoid, or starts not uniform, would change it.
    lagrange::model scene = load(read_file(scenes + "three_oscillators.lag"));
    for (const std::string section : {"x = 0, x' > 0", "x = 0"}) {
        INFO("--section " << section);
        lagrange::poincare_settings settings;
        settings.energy = 2;
        settings.orbits = 800;
        settings.crossings = 1; // the starts only
        const lagrange::poincare_result result = section_of(scene, section, settings);
        REQUIRE(result.crossings() == 800);
        std::vector<double> radii;
        double largest[4] = {0, 0, 0, 0};
        for (const lagrange::poincare_orbit& orbit : result.orbits) {
            const double *c = orbit.points.data(), y = c[2], z = c[3], u = c[4], v = c[5], w = c[6];
            CHECK(std::abs((u * u + v * v + w * w) / 2 + y * y + 1.5 * z * z - 2) <= 1e-12);
            CHECK(u >= 0);
            radii.push_back(std::sqrt((y * y + 1.5 * z * z + (v * v + w * w) / 2) / 2));
            largest[0] = std::max(largest[0], std::abs(y) / std::sqrt(2.0));       // |y| ≤ √E
            largest[1] = std::max(largest[1], std::abs(z) / std::sqrt(2 / 1.5));   // |z| ≤ √(E/1.5)
            largest[2] = std::max(largest[2], std::abs(v) / 2);                  // |y'| ≤ √(2E)
            largest[3] = std::max(largest[3], std::abs(w) / 2);
        }
        for (double s : {0.5, 0.7, 0.8, 0.9, 0.95}) {
            const double below = static_cast<double>(std::count_if(radii.begin(), radii.end(), [&](double r) {
                                     return r <= s;
                                 })) / static_cast<double>(radii.size());
            INFO("P(r <= " << s << ") = " << below << ", expected " << std::pow(s, 4));
            // 800 draws: the standard deviation is at most 0.018; 4 of them.
            CHECK(std::abs(below - std::pow(s, 4)) <= 0.07);
        }
        // The starts reach out to the ellipsoid's extremes in every direction (to within a fifth:
        // a box that cut them would stop short).
        for (double reach : largest) {
            CHECK(reach > 0.8);
            CHECK(reach <= 1 + 1e-12);
        }
    }
}

TEST_CASE("poincare: --axes picks two of the section's quantities and a scene of one coordinate is refused",
          "[ensemble][poincare]")
{
    lagrange::model scene = load(read_file(scenes + "three_oscillators.lag"));
    const lagrange::poincare_section section = lagrange::parse_poincare_section("y = 0, y' > 0", scene);
    lagrange::poincare_axes axes = lagrange::default_poincare_axes(scene, section);
    CHECK(axes.horizontal == 1); // x
    CHECK(axes.vertical == 4);   // x'
    axes = lagrange::parse_poincare_axes("z, x_dot", scene, section);
    CHECK(axes.horizontal == 3);
    CHECK(axes.vertical == 4);
    axes = lagrange::parse_poincare_axes(" x , z'", scene, section);
    CHECK(axes.horizontal == 1);
    CHECK(axes.vertical == 6);
    auto require_error = [&](const std::string& text, int column, const std::string& fragment) {
        require_option_error("--axes", text, [&] { lagrange::parse_poincare_axes(text, scene, section); }, column, fragment);
    };
    require_error("x, w'", 4, "`w` is not a coordinate");
    require_error("y, z", 1, "the section's coordinate");
    require_error("x z", 3, "expected `,`");
    require_error("x, z, y'", 5, "expected the end");
    require_error("", 1, "give the axes");

    lagrange::model pendulum = load("scene \"One oscillator\"\ncoordinates x\nT = 1/2*x'^2\nV = 1/2*x^2\n");
    lagrange::poincare_settings settings;
    settings.energy = 1;
    CHECK_THROWS_WITH(section_of(pendulum, pendulum.coordinates[0].name + " = 0", settings),
                      Catch::Contains("two or more degrees of freedom, and the scene has 1 coordinate"));
}
