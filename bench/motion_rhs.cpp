// SPDX-License-Identifier: GPL-2.0-or-later
/** @file motion_rhs.cpp
 *  Benchmark: one right-hand side of the double pendulum's first-order system
 *  (M(q) q̈ = f solved per call), compiled from the scene by compiled_motion,
 *  against a hand-written C++ right-hand side of the same equations, in the same run.
 *  Also checks that both agree. Usage: motion_rhs [calls] */
#include "engine/analysis.h"
#include "numeric/compiled_motion.h"
#include "scene/lower.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using clock_type = std::chrono::steady_clock;

constexpr double M = 1, m = 0.01, l = 1, g = 9.81;

/// The double pendulum's equations written by hand (the closed form of q̈); not
/// inlined, as an integrator calls its right-hand side through a function.
__attribute__((noinline)) void hand_written(const double* x, double* dxdt)
{
    double th = x[0], ph = x[1], thd = x[2], phd = x[3];
    double d = th - ph, c = std::cos(d), s = std::sin(d);
    // (M+m) l θ̈ + m l c φ̈ = −m l s φ̇² − (M+m) g sin θ;  l c θ̈ + l φ̈ = l s θ̇² − g sin φ
    double a11 = (M + m) * l, a12 = m * l * c, a21 = l * c, a22 = l;
    double b1 = -m * l * s * phd * phd - (M + m) * g * std::sin(th);
    double b2 = l * s * thd * thd - g * std::sin(ph);
    double det = a11 * a22 - a12 * a21;
    dxdt[0] = thd;
    dxdt[1] = phd;
    dxdt[2] = (b1 * a22 - a12 * b2) / det;
    dxdt[3] = (a11 * b2 - a21 * b1) / det;
}

template <class F>
double nanoseconds_per_call(F&& f, long calls)
{
    double best = 1e300;
    for (int run = 0; run < 5; ++run) {
        auto start = clock_type::now();
        f(calls);
        std::chrono::duration<double> elapsed = clock_type::now() - start;
        best = std::min(best, elapsed.count() * 1e9 / static_cast<double>(calls));
    }
    return best;
}

} // namespace

int main(int argc, char** argv)
{
    long calls = argc > 1 ? std::atol(argv[1]) : 2'000'000;
    std::string scene_text = "parameters M m l g\ncoordinates theta phi\n"
                             "point upper mass M at (l*sin(theta), -l*cos(theta))\n"
                             "point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))\n"
                             "gravity g along (0, -1)\nvalues M = 1, m = 0.01, l = 1, g = 9.81\n";
    lagrange::model scene = lagrange::load_model(lagrange::source_text("bench.lag", scene_text));
    lagrange::analysis result = lagrange::analyze(scene, {lagrange::product::equations});
    lagrange::compiled_motion motion(scene, *result.equations, lagrange::first_value_point(scene));

    std::vector<double> x{0.3, -0.2, 0.1, 0.4}, out(4), reference(4);
    motion.rhs(0, x.data(), out.data());
    hand_written(x.data(), reference.data());
    double difference = 0;
    for (int i = 0; i < 4; ++i)
        difference = std::max(difference, std::abs(out[i] - reference[i]));

    volatile double sink = 0;
    // Every timed loop varies the inputs on each call (nothing can be hoisted out of it)
    // and keeps one output of `evaluate`.
    auto timed = [&](auto evaluate, long count) {
        return nanoseconds_per_call(
            [&](long n) {
                for (long k = 0; k < n; ++k) {
                    x[0] = 1e-9 * static_cast<double>(k & 1023);
                    x[1] = -0.2 + 1e-9 * static_cast<double>(k & 511);
                    sink = sink + evaluate();
                }
            },
            count);
    };
    auto right_hand_side = [&] {
        motion.rhs(0, x.data(), out.data());
        return out[2];
    };
    double hand = timed(
        [&] {
            hand_written(x.data(), out.data());
            return out[2];
        },
        calls);
    double compiled = timed(right_hand_side, calls);
    auto compile_start = clock_type::now();
    bool native = motion.compile_native();
    std::chrono::duration<double> compile_time = clock_type::now() - compile_start;
    double compiled_native = timed(right_hand_side, calls);
    motion.rhs(0, x.data(), out.data());
    hand_written(x.data(), reference.data());
    for (int i = 0; i < 4; ++i)
        difference = std::max(difference, std::abs(out[i] - reference[i]));
    std::vector<double> jac(16);
    double jacobian = timed(
        [&] {
            motion.jacobian(0, x.data(), jac.data());
            return jac[9];
        },
        calls / 4);
    std::printf("double pendulum right-hand side (best of 5 runs of %ld calls)\n", calls);
    std::printf("  hand-written C++          %8.1f ns\n", hand);
    std::printf("  compiled_motion (interp.) %8.1f ns   ratio %.2f   (%zu instructions)\n", compiled,
                compiled / hand, motion.instructions());
    std::printf("  compiled_motion (native)  %8.1f ns   ratio %.2f   (%s; cc took %.2f s)\n", compiled_native,
                compiled_native / hand, native ? "compiled" : "NO COMPILER: interpreter", compile_time.count());
    std::printf("  compiled_motion Jacobian  %8.1f ns   (native)\n", jacobian);
    std::printf("  max |difference| of q''   %8.2e\n", difference);
    return difference < 1e-12 ? 0 : 1;
}
