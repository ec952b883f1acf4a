// SPDX-License-Identifier: GPL-2.0-or-later
/** @file chain_scene.h
 *  The planar chain of pendulums as scene text, for the tests (through scene_helpers.h)
 *  and the benchmarks (bench/chain_equations.cpp), without Catch2. */
#pragma once

#include <string>

namespace lagrange_test {

/// A planar chain of `links` point masses on rods under gravity, absolute angles q1 … qN:
/// parameters g, m1 l1 … (no values).
inline std::string chain_scene(int links)
{
    std::string parameters = "parameters g", coordinates = "coordinates", points, x, y;
    for (int k = 1; k <= links; ++k) {
        const std::string i = std::to_string(k);
        parameters += " m" + i + " l" + i;
        coordinates += " q" + i;
        x += (k > 1 ? " + " : "") + ("l" + i + "*sin(q" + i + ")");
        y += " - l" + i + "*cos(q" + i + ")";
        points += "point P" + i + " mass m" + i + " at (" + x + "," + y + ")\n";
    }
    return parameters + "\n" + coordinates + "\n" + points + "gravity g along (0, -1)\n";
}

} // namespace lagrange_test
