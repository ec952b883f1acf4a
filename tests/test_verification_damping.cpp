/** @file test_verification_damping.cpp
 *  The damping checks of the self-verification: correct damping matrices (dampers between
 *  moving points in 2-D, a Rayleigh line, a velocity-dependent force) and polynomials
 *  pass; a damping matrix or damped polynomial made wrong on purpose is caught, naming it. */
#include "engine/analysis.h"
#include "numeric/verification.h"
#include "scene_helpers.h"

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
