// SPDX-License-Identifier: GPL-2.0-or-later
/** @file large_systems.cpp
 *  Benchmark: the planar N-link chain (tests/helpers/chain_scene.h) at the sizes where the
 *  compiled equations meet their limits. Per N: the time to derive and build the programs,
 *  the first-run C compile of the right-hand side (no cache; what `simulate` waits for with an
 *  explicit method), and the nanoseconds of one q̈(q, q̇) through
 *  compiled_motion::rhs (native), beside a hand-written O(N) recursion for the same chain
 *  (the rod tensions solved along the chain, a tridiagonal system), measured in the same run
 *  on the same states, with their largest relative difference.
 *    large_systems N [calls [FORM]]   one table row; FORM: automatic, expanded, single_angles
 *                                     or recursive
 *                                     (lagrange::motion_form)
 *    large_systems --scene N          the chain with values, an initial state and `simulate`
 *  bench/large_systems.sh runs it for N = 2 … 50 beside the whole `simulate` command. */
#include "helpers/chain_recursion.h"
#include "helpers/chain_scene.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/lagrangian.h"
#include "numeric/compiled_motion.h"
#include "scene/lower.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point start)
{
    return std::chrono::duration<double>(clock_type::now() - start).count();
}

/// The chain's parameter values: link k has mass 1 + k/10 and length 1 − k/100.
double mass(int k) { return 1 + 0.1 * k; }
double length(int k) { return 1 - 0.01 * k; }
constexpr double gravity = 9.81;

std::string scene_with_values(int links)
{
    std::string values = "values g = 9.81", initial = "initial";
    char number[64];
    for (int k = 1; k <= links; ++k) {
        std::snprintf(number, sizeof number, ", m%d = %g, l%d = %g", k, mass(k), k, length(k));
        values += number;
        std::snprintf(number, sizeof number, "%s q%d = %g", k > 1 ? "," : "", k, 0.3 * (k % 2 ? -1 : 1) / k);
        initial += number;
    }
    return lagrange_test::chain_scene(links) + values + "\n" + initial + "\nsimulate until 5\n";
}

/// The best of 7 runs of `calls` calls of each of `a` and `b`, their runs taken in turn, so
/// that both see the same load of a busy machine.
template <class A, class B>
std::pair<double, double> nanoseconds_per_call(A&& a, B&& b, long calls)
{
    double best_a = 1e300, best_b = 1e300;
    for (int run = 0; run < 7; ++run) {
        auto start = clock_type::now();
        a(calls);
        best_a = std::min(best_a, seconds_since(start) * 1e9 / static_cast<double>(calls));
        start = clock_type::now();
        b(calls);
        best_b = std::min(best_b, seconds_since(start) * 1e9 / static_cast<double>(calls));
    }
    return {best_a, best_b};
}

} // namespace

int main(int argc, char** argv)
{
    if (argc == 3 && std::string(argv[1]) == "--scene") {
        std::fputs(scene_with_values(std::atoi(argv[2])).c_str(), stdout);
        return 0;
    }
    if (argc < 2) {
        std::fprintf(stderr, "usage: large_systems N [calls] | --scene N\n");
        return 2;
    }
    const int n = std::atoi(argv[1]);
    const long calls = argc > 2 && std::atol(argv[2]) > 0 ? std::atol(argv[2]) : std::max(2000L, 4'000'000L / (n * n));
    const std::string form_name = argc > 3 ? argv[3] : "automatic";
    const lagrange::motion_form form = form_name == "expanded"        ? lagrange::motion_form::expanded
                                       : form_name == "single_angles" ? lagrange::motion_form::single_angles
                                       : form_name == "recursive"     ? lagrange::motion_form::recursive
                                                                      : lagrange::motion_form::automatic;
    setenv("LAGRANGE_CACHE", "0", 1); // the first run's compile, every time

    auto start = clock_type::now();
    lagrange::model scene = lagrange::load_model(lagrange::source_text("chain.lag", scene_with_values(n)));
    // What `simulate` derives: M and f, not the printed equations (refused beyond 1000 terms).
    const lagrange::simplifier simplify = lagrange::make_simplifier(scene);
    const lagrange::equations_of_motion equations =
        lagrange::derive_equations_of_motion(scene, lagrange::derive_lagrangian(scene, simplify), simplify, false);
    lagrange::compiled_motion motion(scene, equations, lagrange::first_value_point(scene), form);
    const double derive_seconds = seconds_since(start);
    start = clock_type::now();
    std::string why;
    const bool native = motion.compile_native_rhs(lagrange::native_limits{600}, &why);
    const double compile_seconds = seconds_since(start);

    // Random states (seeded), the same for both right-hand sides.
    const std::size_t d = 2 * static_cast<std::size_t>(n);
    constexpr int states = 64;
    std::mt19937_64 random(39);
    std::uniform_real_distribution<double> angle(-1.5, 1.5), rate(-2, 2);
    std::vector<double> x(states * d);
    for (int j = 0; j < states; ++j)
        for (std::size_t i = 0; i < d; ++i)
            x[j * d + i] = i < d / 2 ? angle(random) : rate(random);
    std::vector<double> masses, lengths;
    for (int k = 1; k <= n; ++k) {
        masses.push_back(mass(k));
        lengths.push_back(length(k));
    }
    const lagrange_test::tension_chain hand(masses, lengths, gravity);
    std::vector<double> ours(d), theirs(d);
    double difference = 0;
    for (int j = 0; j < states; ++j) {
        motion.rhs(0, &x[j * d], ours.data());
        hand(&x[j * d], theirs.data());
        double size = 0, gap = 0;
        for (std::size_t i = 0; i < d; ++i) {
            size = std::max(size, std::abs(theirs[i]));
            gap = std::max(gap, std::abs(ours[i] - theirs[i]));
        }
        difference = std::max(difference, gap / size);
    }
    volatile double sink = 0;
    auto timed = [&](auto evaluate) {
        return [&, evaluate](long count) {
            for (long k = 0; k < count; ++k) {
                evaluate(&x[(k % states) * d], ours.data());
                sink = sink + ours[d - 1];
            }
        };
    };
    const auto [hand_ns, ours_ns] =
        nanoseconds_per_call(timed([&](const double* state, double* out) { hand(state, out); }),
                             timed([&](const double* state, double* out) { motion.rhs(0, state, out); }), calls);
    std::printf("%d %.4f %.3f %s %.1f %.1f %.2f %.1e %zu %s\n", n, derive_seconds, compile_seconds,
                native ? "native" : "interpreted", ours_ns, hand_ns, ours_ns / hand_ns, difference,
                motion.instructions(),
                motion.recursive() ? "recursive" : motion.single_angles() ? "single_angles" : "expanded");
    if (!native)
        std::fprintf(stderr, "N = %d: %s\n", n, why.c_str());
    return difference < 1e-9 ? 0 : 1;
}
