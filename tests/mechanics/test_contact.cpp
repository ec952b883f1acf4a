// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_contact.cpp
 *  The ground's force on a rolling wheel (`contact`), for SymPy's rolling disc of
 *  test_aux_dep (test_kane2.py): its centre at (x, y, z) with the height a coordinate, as
 *  SymPy's dependent q3, so that `rolls` holds it with the constraint D_contact. Checked
 *  against SymPy's own auxiliary-speed solution at random states (sympy_aux_dep.py, run when
 *  python3-sympy is present: tag python_sympy), against Newton's law for the centre,
 *  F = m (ẍ, ÿ, z̈) − m g ẑ, and at upright straight rolling, F = (0, 0, −m g); and the
 *  refusals. */
#include "engine/analysis.h"
#include "helpers/cli_runner.h"
#include "helpers/expressions.h"
#include "helpers/scene_helpers.h"
#include "helpers/tools.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::symbol_of;

namespace {

/// SymPy's disc: yaw q1, lean q2, spin q3 (z down, as SymPy's A.z), inertia I across the
/// axis and J about it, with the values sympy_aux_dep.py uses.
const char* disc_scene = "parameters m g r I J\ncoordinates q1 q2 q3 x y z\n"
                         "body D inertia (I, J, I) mass m at (x, y, z) orientation rotations(z q1, x q2, y q3)\n"
                         "gravity g along (0, 0, 1)\nrolls D on ground radius r axis y\n"
                         "values m = 13/10, g = 981/100, r = 2/5, I = 7/100, J = 11/100\nwant contact\n";

GiNaC::exmap parameter_values(const model& scene) { return value_map(scene, scene.values.at(0)); }

/// The state (q then q̇, scene order) as a substitution.
GiNaC::exmap state_map(const model& scene, const std::vector<double>& state)
{
    GiNaC::exmap at;
    const std::size_t n = scene.coordinates.size();
    for (std::size_t i = 0; i < n; ++i) {
        at[scene.coordinates[i].position] = state[i];
        at[scene.coordinates[i].velocity] = state[n + i];
    }
    return at;
}

double value_at(const GiNaC::ex& e, const GiNaC::exmap& parameters, const GiNaC::exmap& state)
{
    return lagrange_test::value_at(e.subs(parameters), state);
}

} // namespace

TEST_CASE("contact: the rolling disc's contact force equals SymPy's test_aux_dep", "[contact][python_sympy]")
{
    const std::string rows = lagrange_test::run_shell("/usr/bin/python3 " + std::string(LAGRANGE_SOURCE_DIR) +
                                                      "/tests/mechanics/sympy_aux_dep.py");
    model scene = load(disc_scene);
    const auto start = std::chrono::steady_clock::now();
    analysis result = analyze(scene, {product::contact});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 5 * lagrange_test::time_scale());
    REQUIRE(result.contact);
    REQUIRE(result.contact->contacts.size() == 1);
    const contact_force& contact = result.contact->contacts[0];
    const GiNaC::exmap parameters = parameter_values(scene);
    std::istringstream in(rows);
    std::size_t states = 0;
    for (std::vector<double> row(15); in >> row[0];) {
        for (std::size_t k = 1; k < row.size(); ++k)
            REQUIRE(in >> row[k]);
        const GiNaC::exmap at = state_map(scene, std::vector<double>(row.begin(), row.begin() + 12));
        for (unsigned i = 0; i < 3; ++i) {
            INFO("state " << states << ", component " << i);
            CHECK_THAT(value_at(contact.force[i], parameters, at), Catch::WithinAbs(row[12 + i], 1e-9));
        }
        ++states;
    }
    CHECK(states == 6);
}

TEST_CASE("contact: the rolling disc's contact force is Newton's law for its centre", "[contact]")
{
    model scene = load(disc_scene);
    analysis result = analyze(scene, {product::contact});
    REQUIRE(result.contact);
    const contact_force& contact = result.contact->contacts.at(0);
    REQUIRE(result.multipliers);
    const std::vector<GiNaC::ex>& accelerations = result.multipliers->accelerations;
    const GiNaC::exmap parameters = parameter_values(scene);
    const double m = 1.3, g = 9.81, r = 0.4;
    std::mt19937 random(31);
    std::uniform_real_distribution<double> angle(-1, 1), rate(-2, 2);
    for (int trial = 0; trial < 5; ++trial) {
        const double yaw = 3 * angle(random), lean = angle(random), spin = 3 * angle(random);
        const double yaw_rate = rate(random), lean_rate = rate(random), spin_rate = rate(random);
        // the centre's velocity that rolling allows: ż from z = −r cos(lean), ẋ and ẏ from
        // the contact point at rest, v_c = −ω × (p − c)
        std::vector<double> state{yaw, lean, spin, 0.1, -0.2, -r * std::cos(lean), yaw_rate, lean_rate, spin_rate};
        const double sy = std::sin(yaw), cy = std::cos(yaw), sl = std::sin(lean), cl = std::cos(lean);
        // ω = q1' ẑ + q2' A.x + q3' B.y; the contact point p − c = r (sy sl, −cy sl, cl) below the centre
        const double wx = lean_rate * cy - spin_rate * sy * cl, wy = lean_rate * sy + spin_rate * cy * cl,
                     wz = yaw_rate + spin_rate * sl;
        const double bx = r * sy * sl, by = -r * cy * sl, bz = r * cl;
        state.push_back(-(wy * bz - wz * by));
        state.push_back(-(wz * bx - wx * bz));
        state.push_back(-(wx * by - wy * bx));
        const GiNaC::exmap at = state_map(scene, state);
        for (double constraint : {value_at(scene.constraints[0].function, parameters, at),
                                  value_at(scene.constraints[1].function, parameters, at),
                                  value_at(scene.constraints[2].function, parameters, at)})
            REQUIRE(std::abs(constraint) < 1e-12);
        INFO("trial " << trial);
        CHECK_THAT(value_at(contact.force[0], parameters, at),
                   Catch::WithinAbs(m * value_at(accelerations[3], parameters, at), 1e-9));
        CHECK_THAT(value_at(contact.force[1], parameters, at),
                   Catch::WithinAbs(m * value_at(accelerations[4], parameters, at), 1e-9));
        CHECK_THAT(value_at(contact.force[2], parameters, at),
                   Catch::WithinAbs(m * value_at(accelerations[5], parameters, at) - m * g, 1e-9));
    }
    // Upright, rolling straight at any rate: the ground carries the weight, nothing else.
    const std::vector<double> upright{0.3, 0, 1, 0, 0, -r, 0, 0, 2.5,
                                      -r * 2.5 * std::cos(0.3), -r * 2.5 * std::sin(0.3), 0};
    const GiNaC::exmap at = state_map(scene, upright);
    CHECK_THAT(value_at(contact.force[0], parameters, at), Catch::WithinAbs(0, 1e-12));
    CHECK_THAT(value_at(contact.force[1], parameters, at), Catch::WithinAbs(0, 1e-12));
    CHECK_THAT(value_at(contact.force[2], parameters, at), Catch::WithinRel(-m * g, 1e-12));
}

TEST_CASE("contact: a height held by the coordinates, and no rolling wheel, are refused", "[contact]")
{
    // The centre r cos(q2) above the ground: the normal force is no multiplier.
    model built_in = load("parameters m g r\ncoordinates q1 q2 q3 x y\n"
                          "body D disk(r) mass m axis y at (x + r*sin(q2)*sin(q1), y - r*sin(q2)*cos(q1), "
                          "r*cos(q2)) orientation rotations(z q1, x q2, y q3)\ngravity g along (0, 0, -1)\n"
                          "rolls D on ground\n");
    REQUIRE(built_in.contacts.size() == 1);
    CHECK(built_in.contacts[0].normal_by_construction);
    CHECK_THROWS_AS(analyze(built_in, {product::contact}), computation_error);
    CHECK_THROWS_WITH(analyze(built_in, {product::contact}),
                      Catch::Matchers::Contains("height of D above the ground holds by its coordinates"));
    // Constrained or not, a scene without a `rolls` line has no contact to give.
    for (const char* constraint : {"constraint c: x = y\n", ""}) {
        model unrolled = load(std::string("parameters m g\ncoordinates x y\npoint P mass m at (x, y)\n"
                                          "gravity g along (0, -1)\n") + constraint);
        CHECK_THROWS_AS(analyze(unrolled, {product::contact}), computation_error);
        CHECK_THROWS_WITH(analyze(unrolled, {product::contact}),
                          Catch::Matchers::Contains("`contact` needs a wheel rolling on the ground"));
    }
}
