// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_ode.cpp
 *  The integrators on systems with exact solutions: each method within its tolerance,
 *  invariant drift, limits and messages. */
#include "numeric/ode.h"
#include "helpers/ode_helpers.h"
#include "scene/source.h"

#include <catch2/catch.hpp>

#include <cmath>

using Catch::Matchers::WithinAbs;

namespace {

/// x'' = −ω² x, x(0) = 1, x'(0) = 0: exact x = cos ωt; energy ½(v² + ω²x²).
lagrange::ode_system harmonic(double omega)
{
    lagrange::ode_system s;
    s.dimension = 2;
    s.rhs = [omega](double, const double* x, double* f) {
        f[0] = x[1];
        f[1] = -omega * omega * x[0];
    };
    s.jacobian = [omega](double, const double*, double* j) {
        j[0] = 0, j[1] = 1, j[2] = -omega * omega, j[3] = 0;
    };
    s.invariants.push_back({"energy", [omega](const double* x) { return 0.5 * (x[1] * x[1] + omega * omega * x[0] * x[0]); }, 0});
    s.exact = [omega](double t, double* x) {
        x[0] = std::cos(omega * t);
        x[1] = -omega * std::sin(omega * t);
    };
    return s;
}

} // namespace

TEST_CASE("integrate: every method on the harmonic oscillator, error within its tolerance", "[ode]")
{
    lagrange::ode_system s = harmonic(2.0);
    for (lagrange::ode_method method : lagrange::all_ode_methods()) {
        for (double tolerance : {1e-5, 1e-8}) {
            lagrange::integration_options options;
            options.until = 10;
            options.tolerance = tolerance;
            options.frequency = 2.0;
            lagrange::trajectory run = lagrange::integrate(s, method, {1.0, 0.0}, options);
            INFO(lagrange::to_string(method) << " at " << tolerance << ": error " << *run.exact_error);
            REQUIRE(run.exact_error);
            // The tolerance is a target for the global relative error (over three periods here).
            CHECK(*run.exact_error <= tolerance);
            CHECK(*run.exact_error > 0);
            CHECK(run.steps > 0);
            CHECK(run.times.size() == 1001);
            CHECK_THAT(run.times.back(), WithinAbs(10, 0));
        }
    }
}

TEST_CASE("integrate: without output times the dense-output methods take the same steps", "[ode]")
{
    // What the work-precision benchmark relies on: the run it times (no outputs) and the one
    // it measures the error of (1001 interpolated outputs) are the same integration.
    lagrange::ode_system s = lagrange_test::pendulum_system();
    for (lagrange::ode_method method :
         {lagrange::ode_method::dopri5, lagrange::ode_method::dop853, lagrange::ode_method::bulirsch_stoer}) {
        for (double tolerance : {1e-4, 1e-9}) {
            lagrange::integration_options options;
            options.until = 20;
            options.tolerance = tolerance;
            lagrange::trajectory with = lagrange::integrate(s, method, {1.5, 0.0}, options);
            options.outputs = false;
            options.keep_states = false;
            lagrange::trajectory without = lagrange::integrate(s, method, {1.5, 0.0}, options);
            INFO(lagrange::to_string(method) << " at " << tolerance);
            CHECK(without.steps == with.steps);
            if (method == lagrange::ode_method::dop853) {
                // DOP853's interpolant needs three more stages in each step with an output time.
                CHECK(with.evaluations > without.evaluations);
                CHECK(with.evaluations - without.evaluations <= 3 * with.steps);
                CHECK((with.evaluations - without.evaluations) % 3 == 0);
            } else {
                CHECK(without.evaluations == with.evaluations);
            }
            CHECK(without.times.size() == without.steps + 1); // the start and each step's end
            CHECK(with.times.size() == 1001);
            CHECK_THAT(without.times.back(), WithinAbs(20, 1e-12));
            REQUIRE(without.final_state.size() == 2);
            // The last step's end against the interpolant there: dopri5's and DOP853's
            // interpolants are the step's end to rounding; Bulirsch–Stoer's is a fitted
            // polynomial, accurate to the tolerance (measured: 2e-9 at 1e-4).
            double close = method == lagrange::ode_method::bulirsch_stoer ? tolerance / 100 : 1e-12;
            for (int i = 0; i < 2; ++i)
                CHECK_THAT(without.final_state[i], WithinAbs(with.final_state[i], close));
        }
    }
}

TEST_CASE("integrate: rkf78 without output times takes its own steps, and explicit output times", "[ode]")
{
    // rkf78 has no interpolant: with 1000 output times it ends a step at each; without, its
    // steps are as long as the (tightened) tolerance allows, and its error at their ends
    // stays within the tolerance (harmonic oscillator over 3 periods, exact solution).
    lagrange::ode_system s = harmonic(2.0);
    lagrange::integration_options options;
    options.until = 10;
    options.tolerance = 1e-10;
    lagrange::trajectory with = lagrange::integrate(s, lagrange::ode_method::rkf78, {1.0, 0.0}, options);
    options.outputs = false;
    lagrange::trajectory without = lagrange::integrate(s, lagrange::ode_method::rkf78, {1.0, 0.0}, options);
    CHECK(with.steps >= 1000);
    CHECK(without.steps < with.steps / 5);
    CHECK(without.times.size() == without.steps + 1);
    CHECK_THAT(without.times.back(), WithinAbs(10, 1e-12));
    REQUIRE(without.exact_error);
    CHECK(*without.exact_error <= 1e-10);
    CHECK(*with.exact_error <= 1e-10);
    // explicit output times: the states at exactly those, and a bad list is refused
    lagrange::integration_options at;
    at.until = 2;
    at.tolerance = 1e-12;
    at.times = {0, 0.25, 1.0, 1.5, 2};
    lagrange::trajectory some = lagrange::integrate(s, lagrange::ode_method::dopri5, {1.0, 0.0}, at);
    REQUIRE(some.times.size() == 5);
    for (std::size_t k = 0; k < 5; ++k) {
        CHECK(some.times[k] == at.times[k]);
        CHECK_THAT(some.states[k][0], WithinAbs(std::cos(2 * at.times[k]), 1e-10));
    }
    at.times = {0, 1.5, 1.0, 2};
    CHECK_THROWS_AS(lagrange::integrate(s, lagrange::ode_method::dopri5, {1.0, 0.0}, at), std::invalid_argument);
    CHECK(lagrange::steps_to_outputs(lagrange::ode_method::rkf78));
    CHECK_FALSE(lagrange::steps_to_outputs(lagrange::ode_method::dopri5));
    CHECK_FALSE(lagrange::steps_to_outputs(lagrange::ode_method::dop853));
    CHECK_FALSE(lagrange::steps_to_outputs(lagrange::ode_method::bulirsch_stoer));
}

TEST_CASE("integrate: implicit midpoint keeps the energy of a nonlinear pendulum over a long run", "[ode]")
{
    lagrange::ode_system s = lagrange_test::pendulum_system();
    lagrange::integration_options options;
    options.until = 2000;
    options.fixed_step = 0.05;
    options.output_step = 1;
    lagrange::trajectory midpoint = lagrange::integrate(s, lagrange::ode_method::implicit_midpoint, {2.0, 0.0}, options);
    REQUIRE(midpoint.invariant_drift.size() == 1);
    // Symplectic: the energy error stays O(h²) and bounded, with no secular growth.
    CHECK(midpoint.invariant_drift[0].second < 2e-3);
    options.until = 200;
    lagrange::trajectory shorter = lagrange::integrate(s, lagrange::ode_method::implicit_midpoint, {2.0, 0.0}, options);
    CHECK(midpoint.invariant_drift[0].second < 1.5 * shorter.invariant_drift[0].second);
    // An explicit method at a loose tolerance drifts without bound instead.
    options.until = 2000;
    options.tolerance = 1e-4;
    lagrange::trajectory dopri = lagrange::integrate(s, lagrange::ode_method::dopri5, {2.0, 0.0}, options);
    CHECK(dopri.invariant_drift[0].second > midpoint.invariant_drift[0].second);
    options.tolerance = 1e-11;
    lagrange::trajectory tight = lagrange::integrate(s, lagrange::ode_method::rkf78, {2.0, 0.0}, options);
    CHECK(tight.invariant_drift[0].second < 1e-7);
}

TEST_CASE("integrate: BDF on a stiff linear system against its exact solution", "[ode]")
{
    // x' = −1e6 (x − cos t) − sin t: exact x = cos t for x(0) = 1 (stiffness 1e6).
    lagrange::ode_system s;
    s.dimension = 1;
    s.rhs = [](double t, const double* x, double* f) { f[0] = -1e6 * (x[0] - std::cos(t)) - std::sin(t); };
    s.jacobian = [](double, const double*, double* j) { j[0] = -1e6; };
    s.exact = [](double t, double* x) { x[0] = std::cos(t); };
    lagrange::integration_options options;
    options.until = 10;
    options.tolerance = 1e-8;
    lagrange::trajectory bdf = lagrange::integrate(s, lagrange::ode_method::bdf, {1.0}, options);
    CHECK(*bdf.exact_error < 1e-6);
    CHECK(bdf.steps < 20000);
    CHECK(bdf.jacobians > 0);
}

TEST_CASE("integrate: runaway solutions and limits stop with a message", "[ode][errors]")
{
    // x' = x², x(0) = 1 blows up at t = 1.
    lagrange::ode_system s;
    s.dimension = 1;
    s.rhs = [](double, const double* x, double* f) { f[0] = x[0] * x[0]; };
    s.jacobian = [](double, const double* x, double* j) { j[0] = 2 * x[0]; };
    lagrange::integration_options options;
    options.until = 2;
    options.max_seconds = 5;
    for (lagrange::ode_method method : lagrange::all_ode_methods()) {
        INFO(lagrange::to_string(method));
        CHECK_THROWS_AS(lagrange::integrate(s, method, {1.0}, options), lagrange::computation_error);
    }
    // A step limit is a message, not a hang.
    lagrange::ode_system stiff = harmonic(1e6);
    options.until = 100;
    options.max_steps = 1000;
    CHECK_THROWS_WITH(lagrange::integrate(stiff, lagrange::ode_method::dopri5, {1.0, 0.0}, options),
                      Catch::Contains("step limit") || Catch::Contains("made no progress"));
    lagrange::ode_system no_jacobian = lagrange_test::pendulum_system();
    no_jacobian.jacobian = nullptr;
    CHECK_THROWS_AS(lagrange::integrate(no_jacobian, lagrange::ode_method::bdf, {1.0, 0.0}, {}), std::invalid_argument);
}
