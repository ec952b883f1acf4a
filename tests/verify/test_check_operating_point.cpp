// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_check_operating_point.cpp
 *  The finite-difference check of a linearization about an operating point: it passes on
 *  the rolling disc and the Cartesian pendulum, and it fails on an A, a B or a residual
 *  changed by a little. */
#include "engine/analysis.h"
#include "helpers/scene_helpers.h"
#include "verify/check_operating_point.h"

#include <catch2/catch.hpp>

using namespace lagrange;
using lagrange_test::load;

namespace {

const char* driven_pendulum = "parameters m L g\ncoordinates q1 q2\ninput u\npoint P mass m at (q1, q2)\n"
                              "force on P (m*g, u)\nconstraint rod: q1^2 + q2^2 = L^2\n"
                              "linearize about q1 = 3*L/5, q2 = 4*L/5, q1' = -4/5, q2' = 3/5, u = 1\n"
                              "want state_space\n";

} // namespace

TEST_CASE("check operating point: passes where right, fails on a changed entry", "[verification]")
{
    model scene = load(driven_pendulum);
    analysis result = analyze(scene, {product::state_space});
    REQUIRE(result.operating);
    verification_entry entry = verify_operating_point(scene, *result.equations, *result.operating);
    CHECK(entry.checked);
    CHECK(entry.item == "state_space");
    operating_linearization changed = *result.operating;
    changed.a(1, 0) = changed.a(1, 0) + GiNaC::numeric(1, 1000);
    CHECK_THROWS_WITH(verify_operating_point(scene, *result.equations, changed),
                      Catch::Contains("verification failed") && Catch::Contains("A(2, 1)"));
    changed = *result.operating;
    changed.b(1, 0) = changed.b(1, 0) * GiNaC::numeric(1001, 1000);
    CHECK_THROWS_WITH(verify_operating_point(scene, *result.equations, changed), Catch::Contains("B(2, 1)"));
    changed = *result.operating;
    changed.residual[1] = changed.residual[1] + GiNaC::numeric(1, 1000);
    CHECK_THROWS_WITH(verify_operating_point(scene, *result.equations, changed), Catch::Contains("residual"));
}
