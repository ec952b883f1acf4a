// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_compiled_motion.cpp
 *  The forms of the compiled right-hand side (motion_form): the single-angle form against
 *  the expanded one and both against the chain's O(N) recursion by hand, at random states. */
#include "engine/analysis.h"
#include "numeric/compiled_motion.h"
#include "helpers/chain_recursion.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using lagrange_test::load;

namespace {

/// max_i |a_i − b_i| / max_i |b_i|
double relative_difference(const std::vector<double>& a, const std::vector<double>& b)
{
    double gap = 0, size = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        gap = std::max(gap, std::abs(a[i] - b[i]));
        size = std::max(size, std::abs(b[i]));
    }
    return gap / size;
}

} // namespace

TEST_CASE("compiled_motion: single angles agree with the expanded form and the hand recursion", "[compiled_motion]")
{
    for (int links : {2, 5, 8}) {
        INFO(links << " links");
        std::vector<double> masses, lengths;
        std::string values = "values g = 9.81";
        for (int k = 1; k <= links; ++k) {
            masses.push_back(0.5 + 0.25 * k);
            lengths.push_back(1.5 - 0.125 * k);
            values += ", m" + std::to_string(k) + " = " + std::to_string(masses.back()) + ", l" + std::to_string(k) +
                      " = " + std::to_string(lengths.back());
        }
        lagrange::model scene = load(lagrange_test::chain_scene(links) + values + "\n");
        lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
        const auto point = lagrange::first_value_point(scene);
        lagrange::compiled_motion expanded(scene, *a.equations, point, lagrange::motion_form::expanded);
        lagrange::compiled_motion single(scene, *a.equations, point, lagrange::motion_form::single_angles);
        lagrange::compiled_motion automatic(scene, *a.equations, point);
        CHECK_FALSE(expanded.single_angles());
        CHECK(single.single_angles());
        CHECK(automatic.single_angles() == (static_cast<std::size_t>(links) >= lagrange::single_angles_coordinates));
        const lagrange_test::tension_chain hand(masses, lengths, 9.81);
        const std::size_t d = 2 * static_cast<std::size_t>(links);
        std::mt19937_64 random(39);
        std::uniform_real_distribution<double> angle(-3, 3), rate(-2, 2);
        for (int state = 0; state < 20; ++state) {
            std::vector<double> x(d), by_expanded(d), by_single(d), by_hand(d);
            for (std::size_t i = 0; i < d; ++i)
                x[i] = i < d / 2 ? angle(random) : rate(random);
            expanded.rhs(0, x.data(), by_expanded.data());
            single.rhs(0, x.data(), by_single.data());
            hand(x.data(), by_hand.data());
            CHECK(relative_difference(by_single, by_expanded) < 1e-13);
            CHECK(relative_difference(by_expanded, by_hand) < 1e-12);
        }
    }
}

TEST_CASE("compiled_motion: native code in parts gives the numbers of one function", "[compiled_motion][cc]")
{
    // An 8-link chain's right-hand side (about 500 statements) in parts of 40, in two
    // translation units compiled side by side, against the same program as one function
    // (the same operations in the same order: equal to the bit) and the hand recursion.
    const int links = 8;
    std::vector<double> masses, lengths;
    std::string values = "values g = 9.81";
    for (int k = 1; k <= links; ++k) {
        masses.push_back(1 + 0.1 * k);
        lengths.push_back(1 - 0.01 * k);
        values += ", m" + std::to_string(k) + " = " + std::to_string(masses.back()) + ", l" + std::to_string(k) +
                  " = " + std::to_string(lengths.back());
    }
    lagrange::model scene = load(lagrange_test::chain_scene(links) + values + "\n");
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
    const auto point = lagrange::first_value_point(scene);
    lagrange::compiled_motion in_parts(scene, *a.equations, point), whole(scene, *a.equations, point);
    REQUIRE(in_parts.instructions() > 3 * 40);
    lagrange::native_limits parts_limits, whole_limits;
    parts_limits.part_statements = 40;
    whole_limits.part_statements = 0;
    std::string why;
    REQUIRE(in_parts.compile_native_rhs(parts_limits, &why));
    REQUIRE(whole.compile_native_rhs(whole_limits, &why));
    const lagrange_test::tension_chain hand(masses, lengths, 9.81);
    const std::size_t d = 2 * static_cast<std::size_t>(links);
    std::mt19937_64 random(40);
    std::uniform_real_distribution<double> angle(-3, 3), rate(-2, 2);
    for (int state = 0; state < 50; ++state) {
        std::vector<double> x(d), by_parts(d), by_whole(d), by_hand(d);
        for (std::size_t i = 0; i < d; ++i)
            x[i] = i < d / 2 ? angle(random) : rate(random);
        in_parts.rhs(0, x.data(), by_parts.data());
        whole.rhs(0, x.data(), by_whole.data());
        hand(x.data(), by_hand.data());
        CHECK(by_parts == by_whole);
        CHECK(relative_difference(by_parts, by_hand) < 1e-12);
    }
}
