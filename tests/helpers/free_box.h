// SPDX-License-Identifier: GPL-2.0-or-later
/** @file free_box.h
 *  The free asymmetric body of the tests: a box with edges a, b, c along x, y, z,
 *  whose principal moments are I1 = M(b² + c²)/12, I2 = M(a² + c²)/12, I3 = M(a² + b²)/12. */
#pragma once

#include <array>
#include <string>

namespace lagrange_test {

inline const std::string free_box_scene = "parameters M a b c\nbody X box(a, b, c) mass M\nomega X (w1, w2, w3)\n"
                                          "values M = 1, a = 1, b = 2, c = 3\ninitial w1 = 0.2, w2 = 1, w3 = 0.3\n";
inline constexpr std::array<double, 3> free_box_moments{13.0 / 12, 10.0 / 12, 5.0 / 12};
inline constexpr std::array<double, 3> free_box_omega0{0.2, 1, 0.3};

} // namespace lagrange_test
