// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_lower_operating_point.cpp
 *  The statements `linearize about` and `independent`: what they lower to, and their errors
 *  at the offending name. */
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::require_error;

namespace {

const std::string pendulum = "parameters m L g\ncoordinates q1 q2\ninput u\n";

} // namespace

TEST_CASE("lower: linearize about names positions, velocities and inputs", "[lower]")
{
    model scene = load(pendulum + "linearize about q1 = L, q2' = 1/2, u = g\nindependent q2, q1'\n");
    REQUIRE(scene.operating_point);
    CHECK(scene.operating_point->positions[0]);
    CHECK_FALSE(scene.operating_point->positions[1]);
    CHECK_FALSE(scene.operating_point->velocities[0]);
    CHECK(scene.operating_point->velocities[1]->is_equal(GiNaC::numeric(1, 2)));
    CHECK(scene.operating_point->inputs[0].is_equal(scene.parameters[2].symbol));
    CHECK(scene.operating_point->position_where[0].column == 22);
    REQUIRE(scene.independent);
    CHECK(scene.independent->coordinates == std::vector<std::size_t>{1});
    CHECK(scene.independent->speeds == std::vector<std::size_t>{0});
}

TEST_CASE("lower: errors of linearize about and independent", "[lower]")
{
    require_error(pendulum + "linearize about q1 = 1, q1 = 2\n", 4, 25, "`q1` is given twice");
    require_error(pendulum + "linearize about m = 1\n", 4, 17, "is not a coordinate or an input");
    require_error(pendulum + "linearize about q1 = q2\n", 4, 22, "coordinate `q2` cannot appear");
    require_error(pendulum + "linearize q1 = 0\n", 4, 11, "`about`");
    require_error(pendulum + "linearize about q1 = 0\nlinearize about q2 = 0\n", 5, 1, "given twice");
    require_error(pendulum + "independent q1, q1\n", 4, 17, "`q1` is given twice");
    require_error(pendulum + "independent g\n", 4, 13, "`g` is not a coordinate");
    require_error(pendulum + "independent q1\nindependent q2\n", 5, 1, "given twice");
}
