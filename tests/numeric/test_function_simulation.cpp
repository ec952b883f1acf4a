// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_function_simulation.cpp
 *  Scenes with atan, tanh, cosh and abs simulated end to end, each against a reference
 *  independent of the engine's derivation: a chain hanging from a bead on a wire y = f(x)
 *  by Newton's equations of its point masses written out here and integrated by RK4 in long
 *  double; a bead on y = cosh x − 1 against its period by quadrature of the energy integral;
 *  a particle in the potential k|x| against the closed-form motion. */
#include "engine/analysis.h"
#include "numeric/simulation.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <string>

using lagrange_test::load;

namespace {

lagrange::simulation_result run(const lagrange::model& scene)
{
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::simulation});
    REQUIRE(a.simulation);
    return *a.simulation;
}

using state = std::array<long double, 6>; // q1 q2 q3 and their rates

/// The wire y = f(x) with f′ and f″.
struct wire {
    std::function<long double(long double)> f, d1, d2;
};

/// q̈ of three equal masses (m = 1, g = 9.81): A = (q1, f(q1)) on the wire, B = A + (sin q2,
/// −cos q2), C = B + (sin q3, −cos q3), from Newton: Σ J_iᵀ(J_i q̈ + h_i) = Σ J_iᵀ(0, −g),
/// J_i the Jacobian of point i's position and h_i its acceleration at q̈ = 0.
std::array<long double, 3> accelerations(const wire& w, const state& x)
{
    const long double g = 9.81L, d1 = w.d1(x[0]), d2 = w.d2(x[0]);
    const long double c2 = cosl(x[1]), s2 = sinl(x[1]), c3 = cosl(x[2]), s3 = sinl(x[2]);
    const long double v1 = x[3], v2 = x[4], v3 = x[5];
    // rows: x and y of each point; columns: q1, q2, q3
    const long double J[3][2][3] = {{{1, 0, 0}, {d1, 0, 0}},
                                    {{1, c2, 0}, {d1, s2, 0}},
                                    {{1, c2, c3}, {d1, s2, s3}}};
    const long double h[3][2] = {{0, d2 * v1 * v1},
                                 {-s2 * v2 * v2, d2 * v1 * v1 + c2 * v2 * v2},
                                 {-s2 * v2 * v2 - s3 * v3 * v3, d2 * v1 * v1 + c2 * v2 * v2 + c3 * v3 * v3}};
    long double M[3][4] = {};
    for (int p = 0; p < 3; ++p)
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j)
                M[i][j] += J[p][0][i] * J[p][0][j] + J[p][1][i] * J[p][1][j];
            M[i][3] += J[p][0][i] * (0 - h[p][0]) + J[p][1][i] * (-g - h[p][1]);
        }
    for (int k = 0; k < 3; ++k) // Gaussian elimination: M is positive definite
        for (int i = k + 1; i < 3; ++i)
            for (int j = 3; j >= k; --j)
                M[i][j] -= M[i][k] / M[k][k] * M[k][j];
    std::array<long double, 3> a{};
    for (int i = 2; i >= 0; --i) {
        a[i] = M[i][3];
        for (int j = i + 1; j < 3; ++j)
            a[i] -= M[i][j] * a[j];
        a[i] /= M[i][i];
    }
    return a;
}

state rk4(const wire& w, state x, long double until, int steps)
{
    auto f = [&](const state& y) {
        const std::array<long double, 3> a = accelerations(w, y);
        return state{y[3], y[4], y[5], a[0], a[1], a[2]};
    };
    const long double h = until / steps;
    for (int s = 0; s < steps; ++s) {
        state k1 = f(x), y = x;
        for (int i = 0; i < 6; ++i)
            y[i] = x[i] + h / 2 * k1[i];
        state k2 = f(y);
        for (int i = 0; i < 6; ++i)
            y[i] = x[i] + h / 2 * k2[i];
        state k3 = f(y);
        for (int i = 0; i < 6; ++i)
            y[i] = x[i] + h * k3[i];
        state k4 = f(y);
        for (int i = 0; i < 6; ++i)
            x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
    return x;
}

} // namespace

TEST_CASE("simulate: a chain hanging from a bead on a wire y = atan x, and y = tanh x", "[simulation][functions]")
{
    // The scene that once stopped with "cannot evaluate atan(q1) numerically"; the same with tanh.
    const std::vector<std::pair<std::string, wire>> wires = {
        {"atan", {[](long double x) { return atanl(x); }, [](long double x) { return 1 / (1 + x * x); },
                  [](long double x) { return -2 * x / ((1 + x * x) * (1 + x * x)); }}},
        {"tanh", {[](long double x) { return tanhl(x); },
                  [](long double x) { return 1 / (coshl(x) * coshl(x)); },
                  [](long double x) { return -2 * tanhl(x) / (coshl(x) * coshl(x)); }}}};
    for (const auto& [name, w] : wires) {
        INFO(name);
        const std::string f = name + "(q1)";
        lagrange::model scene =
            load("parameters m g\ncoordinates q1 q2 q3\npoint A mass m at (q1, " + f + ")\n"
                 "point B mass m at (q1 + sin(q2), " + f + " - cos(q2))\n"
                 "point C mass m at (q1 + sin(q2) + sin(q3), " + f + " - cos(q2) - cos(q3))\n"
                 "gravity g along (0, -1)\nvalues m = 1, g = 9.81\ninitial q1 = 0.3, q2 = 0.2\n"
                 "simulate until 1 tolerance 1e-10\n");
        const lagrange::simulation_result s = run(scene);
        REQUIRE(s.run.invariant_drift.size() == 1);
        CHECK(s.run.invariant_drift[0].second < 1e-9); // the energy
        const state reference = rk4(w, {0.3L, 0.2L, 0, 0, 0, 0}, 1, 20000);
        REQUIRE(s.run.final_state.size() == 6);
        for (std::size_t k = 0; k < 6; ++k) {
            INFO("state " << k << ": " << s.run.final_state[k] << " against " << static_cast<double>(reference[k]));
            CHECK(std::abs(s.run.final_state[k] - static_cast<double>(reference[k])) <= 1e-7);
        }
    }
}

TEST_CASE("simulate: a bead on y = cosh x − 1 swings with the period of its energy integral", "[simulation][functions]")
{
    // T = ½ m (1 + sinh² x) ẋ², V = m g (cosh x − 1), from rest at x0: the period is
    // 4 ∫₀^x0 √((1 + sinh² x) / (2 g (cosh x0 − cosh x))) dx; with x = x0 sin φ the integrand is
    // smooth on [0, π/2], and Simpson's rule in long double converges to far below the test's tolerance.
    const long double x0 = 1.2L, g = 9.81L;
    auto integrand = [&](long double phi) {
        const long double x = x0 * sinl(phi), s = sinhl(x);
        const long double gap = 2 * sinhl((x0 + x) / 2) * sinhl((x0 - x) / 2); // cosh x0 − cosh x
        // dx = x0 cos φ dφ, and cos φ / √gap stays finite at φ = π/2
        return x0 * cosl(phi) * sqrtl((1 + s * s) / (2 * g * gap));
    };
    const int n = 20000;
    const long double h = (M_PI / 2) / n;
    long double sum = 0;
    for (int k = 0; k <= n; ++k) {
        const long double phi = k * h;
        const long double weight = k == 0 || k == n ? 1 : (k % 2 ? 4 : 2);
        // at φ = π/2 the integrand's limit: √(x0 (1 + sinh² x0) / (g sinh x0))
        sum += weight * (k == n ? sqrtl(x0 / (g * sinhl(x0)) * (1 + sinhl(x0) * sinhl(x0))) : integrand(phi));
    }
    const double period = static_cast<double>(4 * sum * h / 3);
    lagrange::model scene = load("parameters m g\ncoordinates x\npoint P mass m at (x, cosh(x) - 1)\n"
                                 "gravity g along (0, -1)\nvalues m = 1, g = 9.81\ninitial x = 1.2\n"
                                 "simulate until " + std::to_string(1.5 * period) + " tolerance 1e-10\n");
    const lagrange::simulation_result s = run(scene);
    REQUIRE(s.run.invariant_drift.size() == 1);
    CHECK(s.run.invariant_drift[0].second < 1e-9);
    // at 1.5 periods: at the other end, at rest
    REQUIRE(s.run.final_state.size() == 2);
    INFO("period " << period << ", final state " << s.run.final_state[0] << ", " << s.run.final_state[1]);
    CHECK(std::abs(s.run.final_state[0] + 1.2) <= 1e-6);
    CHECK(std::abs(s.run.final_state[1]) <= 5e-6);
}

TEST_CASE("simulate: a particle in the potential k|x| against its closed-form motion", "[simulation][functions]")
{
    // From rest at x0 = 1 with m = 1, k = 2: ẍ = −k sign x, x = 1 − t² until t1 = 1, then the same
    // parabolas mirrored: period 4 t1. The force jumps at x = 0, where the step control must cross.
    lagrange::model scene = load("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = k*abs(x)\n"
                                 "values m = 1, k = 2\ninitial x = 1\nsimulate until 5.5 tolerance 1e-10\n");
    const lagrange::simulation_result s = run(scene);
    REQUIRE(s.run.invariant_drift.size() == 1);
    CHECK(s.run.invariant_drift[0].second < 1e-8);
    REQUIRE(s.run.final_state.size() == 2);
    // t = 5.5: a period and 1.5, moving left past x = 0, the kink
    auto exact = [](double t) {
        const double r = std::fmod(t, 4.0);
        if (r <= 1)
            return std::array<double, 2>{1 - r * r, -2 * r};
        if (r <= 3)
            return std::array<double, 2>{-1 + (r - 2) * (r - 2), 2 * (r - 2)};
        return std::array<double, 2>{1 - (4 - r) * (4 - r), 2 * (4 - r)};
    };
    const std::array<double, 2> expected = exact(5.5);
    INFO("final " << s.run.final_state[0] << ", " << s.run.final_state[1] << " against " << expected[0] << ", "
                  << expected[1]);
    CHECK(std::abs(s.run.final_state[0] - expected[0]) <= 1e-6);
    CHECK(std::abs(s.run.final_state[1] - expected[1]) <= 1e-6);
    for (std::size_t k = 0; k < s.run.times.size(); ++k)
        CHECK(std::abs(s.run.states[k][0] - exact(s.run.times[k])[0]) <= 1e-6);
}
