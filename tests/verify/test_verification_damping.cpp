// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_verification_damping.cpp
 *  The damping checks of the self-verification: correct damping matrices (dampers between
 *  moving points in 2-D, a Rayleigh line, a velocity-dependent force) and polynomials
 *  pass; a damping matrix or damped polynomial made wrong on purpose is caught, naming it. */
#include "engine/analysis.h"
#include "verify/verify.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <string>

using namespace lagrange;
using lagrange_test::load;

namespace {

/// A double pendulum with a damper between the bobs (2-D, non-proportional), a Rayleigh
/// line on the upper joint and a velocity-dependent force on the lower angle.
const std::string damped_double_pendulum = R"(parameters m1 m2 l g b c d
coordinates theta phi
point P mass m1 at (l*sin(theta), -l*cos(theta))
point Q mass m2 at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))
gravity g along (0, -1)
damper b between P and (l, -2*l)
dissipation F = 1/2*c*theta'^2
force phi = -d*phi'*(1 + phi^2)
equilibrium theta = 0, phi = 0
)";

void require_caught(const model& scene, const linearization_result& linear, const damping_result& damping,
                    const std::string& what)
{
    try {
        verify_damping(scene, linear, damping);
        FAIL("the wrong " << what << " passed verification");
    } catch (const computation_error& e) {
        INFO(e.what());
        CHECK(std::string(e.what()).find("verification failed: " + what) != std::string::npos);
    }
}

} // namespace

TEST_CASE("verification: the damping matrix and damped polynomial of a damped double pendulum pass",
          "[verification][damping]")
{
    model scene = load(damped_double_pendulum);
    analysis a = analyze(scene, {product::damping});
    REQUIRE(a.damping);
    REQUIRE(a.verification);
    bool damping = false, polynomial = false;
    for (const verification_entry& e : a.verification->entries) {
        INFO(e.item << ": " << e.how);
        CHECK(e.checked);
        damping = damping || e.item == "damping";
        polynomial = polynomial || e.item == "damped_characteristic";
    }
    CHECK(damping);
    CHECK(polynomial);
    CHECK_FALSE(a.damping->proportional);
}

TEST_CASE("verification catches a wrong damping matrix and a wrong damped polynomial", "[verification][damping]")
{
    model scene = load(damped_double_pendulum);
    analysis a = analyze(scene, {product::damping});
    REQUIRE(a.damping);
    const GiNaC::ex b = lagrange_test::symbol_of(scene, "b");
    {
        damping_result wrong = *a.damping;
        wrong.damping(0, 1) = wrong.damping(0, 1) + b / 7;
        wrong.damping(1, 0) = wrong.damping(0, 1);
        require_caught(scene, *a.linearization, wrong, "the damping matrix");
    }
    {
        damping_result wrong = *a.damping;
        wrong.polynomial = wrong.polynomial + b * wrong.s;
        require_caught(scene, *a.linearization, wrong, "the damped characteristic polynomial");
    }
}

TEST_CASE("verification catches a wrong state-space matrix and a wrong transfer function", "[verification][transfer]")
{
    model scene = load(R"(parameters mc mp l g c
coordinates x theta
input F
point C mass mc at (x, 0)
point B mass mp at (x + l*sin(theta), l*cos(theta))
gravity g along (0, -1)
damper c between C and (0, 0)
force on C (F, 0)
equilibrium x = 0, theta = 0
)");
    analysis a = analyze(scene, {product::transfer, product::state_space});
    REQUIRE(a.state_space);
    REQUIRE(a.transfer);
    REQUIRE(a.verification);
    int checked = 0;
    for (const verification_entry& e : a.verification->entries)
        if (e.item == "state_space" || e.item == "transfer") {
            INFO(e.item << ": " << e.how);
            CHECK(e.checked);
            ++checked;
        }
    CHECK(checked == 2);
    const GiNaC::ex c = lagrange_test::symbol_of(scene, "c");
    auto caught = [&](const state_space_result& system, const transfer_result& transfer, const std::string& what) {
        try {
            verify_linear_system(scene, *a.linearization, system, &transfer);
            FAIL("the wrong " << what << " passed verification");
        } catch (const computation_error& e) {
            INFO(e.what());
            CHECK(std::string(e.what()).find("verification failed: " + what) != std::string::npos);
        }
    };
    {
        state_space_result wrong = *a.state_space;
        wrong.a(2, 2) = wrong.a(2, 2) + c; // the damper's sign flipped
        caught(wrong, *a.transfer, "the state space");
    }
    {
        state_space_result wrong = *a.state_space;
        wrong.b(3, 0) = -wrong.b(3, 0);
        caught(wrong, *a.transfer, "the state space");
    }
    {
        transfer_result wrong = *a.transfer;
        wrong.entries[1].numerator = -wrong.entries[1].numerator;
        caught(*a.state_space, wrong, "the transfer function");
    }
}
