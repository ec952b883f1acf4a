// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_mass_matrix.cpp
 *  solve_mass_matrix and the message of a failed solve: a singular configuration, or an
 *  overflow (the message once read "not positive definite at t = -nan"). */
#include "numeric/mass_matrix.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace lagrange;

TEST_CASE("mass matrix: a failed solve says singular, or overflow when the state is not finite", "[mass_matrix]")
{
    const double finite[4] = {0.1, 0.2, 1.0, -1.0};
    CHECK(singular_mass_matrix_message(1.5, finite, 4) ==
          "the mass matrix is not positive definite at t = 1.5 (a singular configuration of the coordinates)");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double overflowed[4] = {0.1, HUGE_VAL, 1.0, nan};
    CHECK(singular_mass_matrix_message(2.0, overflowed, 4) ==
          "the motion overflowed: the state is no longer finite at t = 2 (the initial values or parameters may be "
          "too large)");
    CHECK(singular_mass_matrix_message(-nan, finite, 4) ==
          "the motion overflowed: the state is no longer finite (the initial values or parameters may be too large)");
}
