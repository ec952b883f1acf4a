// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_forced_simulation.cpp
 *  Simulations with dissipation, forces and inputs: the damped oscillator against its
 *  closed form, the steady state of a driven damped oscillator against its amplitude and
 *  phase (closed form, and from `transfer` at s = iw), a pendulum with a driving torque against a long-double Runge–Kutta reference at a
 *  tiny step, the energy balance, the automatic choice on a stiff damper, and an input
 *  without a value. */
#include "engine/analysis.h"
#include "numeric/compiled_motion.h"
#include "numeric/simulation.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using lagrange_test::load;
using lagrange_test::symbol_of;

namespace {

lagrange::simulation_result run(const lagrange::model& scene, lagrange::simulation_settings settings = {})
{
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::simulation}, settings);
    REQUIRE(a.simulation);
    return *a.simulation;
}

double drift_named(const lagrange::simulation_result& s, const std::string& name)
{
    for (const auto& [n, drift] : s.run.invariant_drift)
        if (n == name)
            return drift;
    FAIL("no invariant " << name);
    return 0;
}

} // namespace

TEST_CASE("forced simulation: the damped oscillator follows its closed form, with its energy balance",
          "[simulation][forces]")
{
    // m x'' + b x' + k x = 0, m = 1, k = 4, b = 0.4: γ = 0.2, ω_d = √(4 − 0.04).
    lagrange::model scene = load(R"(parameters m k b
coordinates x
point P mass m at (x, 0)
spring k between P and (0, 0)
damper b between P and (0, 0)
values m = 1, k = 4, b = 0.4
initial x = 1, x' = 0
simulate until 20 tolerance 1e-10
)");
    lagrange::simulation_result s = run(scene);
    const double gamma = 0.2, wd = std::sqrt(4 - gamma * gamma);
    double worst = 0;
    for (std::size_t k = 0; k < s.run.times.size(); ++k) {
        double t = s.run.times[k];
        double exact = std::exp(-gamma * t) * (std::cos(wd * t) + gamma / wd * std::sin(wd * t));
        worst = std::max(worst, std::abs(s.run.states[k][0] - exact));
    }
    CHECK(worst < 1e-8);
    CHECK(drift_named(s, "energy_balance") < 1e-8);
    for (const auto& [name, drift] : s.run.invariant_drift)
        CHECK(name != "energy");
    // The balance is not trivially small: the energy itself falls by orders of magnitude.
    CHECK(std::abs(s.run.final_state[2]) > 0.5);
    // Decaying, the linearized motion still has the frequency |s| = ω0 = 2.
    REQUIRE(s.frequencies.size() == 1);
    CHECK_THAT(s.frequencies[0], WithinRel(2.0, 1e-9));
}

TEST_CASE("forced simulation: a driven damped oscillator settles to the steady-state amplitude and phase",
          "[simulation][forces]")
{
    // m x'' + b x' + k x = F0 cos(w t): x → A cos(w t − δ), A = F0/√((k − m w²)² + (b w)²),
    // tan δ = b w/(k − m w²).
    lagrange::model scene = load(R"(parameters m k b F0 w
coordinates x
input u
point P mass m at (x, 0)
spring k between P and (0, 0)
dissipation F = 1/2*b*x'^2
force x = u
values m = 1, k = 4, b = 0.8, F0 = 1.5, w = 1.7, u = F0*cos(w*t)
simulate until 60 tolerance 1e-10
)");
    lagrange::simulation_result s = run(scene);
    const double m = 1, k = 4, b = 0.8, F0 = 1.5, w = 1.7;
    const double amplitude = F0 / std::hypot(k - m * w * w, b * w), phase = std::atan2(b * w, k - m * w * w);

    // The same steady state from `transfer`: x → F0 |H(iw)| cos(w t + arg H(iw)).
    lagrange::analysis linear = lagrange::analyze(scene, {lagrange::product::transfer});
    REQUIRE(linear.transfer);
    REQUIRE(linear.transfer->entries.size() == 1);
    const GiNaC::exmap at{{symbol_of(scene, "m"), 1}, {symbol_of(scene, "k"), 4},
                          {symbol_of(scene, "b"), GiNaC::numeric(4, 5)}};
    const GiNaC::ex h = GiNaC::evalf(
        linear.transfer->entries[0].function().subs(at).subs(linear.transfer->s == GiNaC::I * GiNaC::numeric(17, 10)));
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(h));
    const std::complex<double> response(GiNaC::real(GiNaC::ex_to<GiNaC::numeric>(h)).to_double(),
                                        GiNaC::imag(GiNaC::ex_to<GiNaC::numeric>(h)).to_double());
    CHECK_THAT(F0 * std::abs(response), WithinRel(amplitude, 1e-12));
    CHECK_THAT(-std::arg(response), WithinAbs(phase, 1e-12));

    double worst = 0, worst_transfer = 0;
    for (std::size_t i = 0; i < s.run.times.size(); ++i) {
        double t = s.run.times[i];
        if (t < 40) // the transient decays like e^{−0.4 t}: below 1e-7 here
            continue;
        worst = std::max(worst, std::abs(s.run.states[i][0] - amplitude * std::cos(w * t - phase)));
        worst_transfer = std::max(worst_transfer, std::abs(s.run.states[i][0] - F0 * std::abs(response) *
                                                                                   std::cos(w * t + std::arg(response))));
    }
    CHECK(worst < 1e-6);
    CHECK(worst_transfer < 1e-6);
    CHECK(drift_named(s, "energy_balance") < 1e-8);
}

TEST_CASE("forced simulation: a pendulum with a driving torque against a high-precision reference",
          "[simulation][forces]")
{
    lagrange::model scene = load(R"(parameters m l g tau0 w
coordinates theta
point P mass m at (l*sin(theta), -l*cos(theta))
gravity g along (0, -1)
force theta = tau0*cos(w*t)
values m = 0.5, l = 1.2, g = 9.81, tau0 = 2.5, w = 2.2
initial theta = 0.3, theta' = -0.4
simulate until 10 step 0.5 tolerance 1e-11
)");
    lagrange::simulation_result s = run(scene);
    // Reference: θ'' = −(g/l) sin θ + τ0 cos(w t)/(m l²) by classical Runge–Kutta in long
    // double at a step of 1e-4 (error about h⁴ ≈ 1e-16 of the motion).
    const long double m = 0.5L, l = 1.2L, g = 9.81L, tau0 = 2.5L, w = 2.2L;
    auto accel = [&](long double t, long double th) {
        return -(g / l) * std::sin(th) + tau0 * std::cos(w * t) / (m * l * l);
    };
    long double th = 0.3L, om = -0.4L, t = 0;
    const long double h = 1e-4L;
    std::size_t next = 0;
    double worst = 0;
    for (long step = 0; step <= 100000; ++step) {
        t = static_cast<long double>(step) * h;
        if (next < s.run.times.size() && std::abs(static_cast<long double>(s.run.times[next]) - t) < h / 2) {
            worst = std::max(worst, static_cast<double>(std::abs(s.run.states[next][0] - th)));
            worst = std::max(worst, static_cast<double>(std::abs(s.run.states[next][1] - om)));
            ++next;
        }
        long double k1x = om, k1v = accel(t, th);
        long double k2x = om + h / 2 * k1v, k2v = accel(t + h / 2, th + h / 2 * k1x);
        long double k3x = om + h / 2 * k2v, k3v = accel(t + h / 2, th + h / 2 * k2x);
        long double k4x = om + h * k3v, k4v = accel(t + h, th + h * k3x);
        th += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        om += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    }
    CHECK(next == s.run.times.size());
    CHECK(worst < 1e-9);
    CHECK(drift_named(s, "energy_balance") < 1e-9);
}

TEST_CASE("forced simulation: a stiff damper makes `auto` choose BDF", "[simulation][forces][stiff]")
{
    // m x'' + b x' + k x = 0 with b²/(m k) = 1e6: decay rates b/m and k/b, a factor 1e6 apart.
    lagrange::model scene = load(R"(parameters m k b
coordinates x
point P mass m at (x, 0)
spring k between P and (0, 0)
damper b between P and (0, 0)
values m = 1, k = 1, b = 1000
initial x = 1
simulate until 5
)");
    lagrange::simulation_result s = run(scene);
    CHECK(s.method == "bdf");
    REQUIRE(s.frequencies.size() == 2);
    CHECK(s.stiffness > 1e5);
    // Overdamped: x = (s2 e^{s1 t} − s1 e^{s2 t})/(s2 − s1), s = (−b ± √(b² − 4k))/2.
    const double root = std::sqrt(1000.0 * 1000.0 - 4), s1 = -2 / (1000 + root), s2 = (-1000 - root) / 2;
    const double exact = (s2 * std::exp(s1 * 5) - s1 * std::exp(s2 * 5)) / (s2 - s1);
    CHECK_THAT(s.run.final_state[0], WithinRel(exact, 1e-7));
}

TEST_CASE("forced simulation: an input without a value is an error at its declaration", "[simulation][forces][errors]")
{
    lagrange::model scene = load("parameters m\ncoordinates x\ninput u\nT = 1/2*m*x'^2\nforce x = u\n"
                                 "values m = 1\nsimulate until 1\n");
    try {
        run(scene);
        FAIL("no error");
    } catch (const lagrange::scene_error& e) {
        CHECK(e.where().line == 3);
        CHECK(e.where().column == 7);
        CHECK(std::string(e.what()).find("input `u` has no value") != std::string::npos);
        CHECK(e.has_line_text());
        CHECK(e.line_text() == "input u");
    }
}

TEST_CASE("forced simulation: the Jacobian with the work row against central differences",
          "[simulation][forces][jacobian]")
{
    // A damped, driven pendulum: the state is (θ, θ̇, W), and nothing depends on W.
    lagrange::model scene = load(R"(parameters m l g b A w
coordinates theta
point P mass m at (l*sin(theta), -l*cos(theta))
gravity g along (0, -1)
dissipation F = 1/2*b*theta'^2
force theta = A*cos(w*t)
values m = 1.3, l = 0.8, g = 9.81, b = 0.4, A = 0.7, w = 2.1
)");
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
    lagrange::compiled_motion motion(scene, *a.equations, lagrange::first_value_point(scene));
    REQUIRE(motion.accumulates_work());
    const std::size_t d = motion.dimension();
    REQUIRE(d == 3);
    const double t = 0.37;
    std::vector<double> x{0.6, -1.4, 0.25}, j(d * d, -1.0);
    motion.jacobian(t, x.data(), j.data());
    for (std::size_t k = 0; k < d; ++k) {
        std::vector<double> up = x, down = x, fu(d), fd(d);
        const double h = 1e-6;
        up[k] += h;
        down[k] -= h;
        motion.rhs(t, up.data(), fu.data());
        motion.rhs(t, down.data(), fd.data());
        for (std::size_t i = 0; i < d; ++i)
            CHECK_THAT(j[i * d + k], WithinAbs((fu[i] - fd[i]) / (2 * h), 1e-7 * (1 + std::abs(j[i * d + k]))));
    }
}
