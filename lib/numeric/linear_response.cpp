// SPDX-License-Identifier: GPL-2.0-or-later
/** @file linear_response.cpp
 *  State-space matrices at numbers and the frequency response by complex LU. */
#include "numeric/linear_response.h"

#include "core/number_text.h"

#include "core/errors.h"
#include "numeric/compiled_modes.h"
#include "numeric/damped_modes.h"
#include "numeric/quadratic_modes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lagrange {

namespace {

using complex = std::complex<double>;

/// The parameters a `values` line gives, in scene order.
std::vector<std::pair<std::string, double>> given_values(const model& scene, const value_point& point)
{
    std::vector<double> values(scene.parameters.size(), std::nan(""));
    std::vector<bool> given(scene.parameters.size(), false);
    read_value_point(scene, point, values, given);
    std::vector<std::pair<std::string, double>> result;
    for (std::size_t k = 0; k < scene.parameters.size(); ++k)
        if (given[k])
            result.push_back({scene.parameters[k].name, values[k]});
    return result;
}

std::size_t index_of_input(const model& scene, const std::string& name)
{
    for (std::size_t k = 0; k < scene.inputs.size(); ++k)
        if (scene.inputs[k].name == name)
            return k;
    std::string known;
    for (const input_signal& u : scene.inputs)
        known += (known.empty() ? "" : ", ") + ("`" + u.name + "`");
    throw computation_error("the scene has no input `" + name + "`" +
                            (known.empty() ? std::string(" (it declares none)") : " (its inputs: " + known + ")"));
}

std::size_t index_of_coordinate(const model& scene, const std::string& name)
{
    for (std::size_t k = 0; k < scene.coordinates.size(); ++k)
        if (scene.coordinates[k].name == name)
            return k;
    throw computation_error("the scene has no coordinate `" + name + "`");
}

/// H(iω) of one input to one coordinate from the numeric matrices.
complex gain_at(double omega, const Eigen::MatrixXd& mass, const Eigen::MatrixXd& velocity,
                const Eigen::MatrixXd& stiffness, const Eigen::VectorXd& forcing, std::size_t output)
{
    const complex i_omega(0, omega);
    Eigen::MatrixXcd pencil = stiffness.cast<complex>() + i_omega * velocity.cast<complex>() +
                              (i_omega * i_omega) * mass.cast<complex>();
    Eigen::FullPivLU<Eigen::MatrixXcd> lu(pencil);
    if (!lu.isInvertible())
        throw computation_error("the linearized system is singular at ω = " + fixed(omega, 6) +
                                " (an undamped resonance): no frequency response there");
    Eigen::VectorXcd x = lu.solve(forcing.cast<complex>());
    return x(static_cast<Eigen::Index>(output));
}

} // namespace

std::vector<state_space_point> state_space_at_values(const model& scene, const state_space_result& system)
{
    std::vector<state_space_point> result;
    for (const value_point& point : scene.values) {
        std::vector<Eigen::MatrixXd> at;
        try {
            at = matrices_at(scene, {&system.a, &system.b}, point);
        } catch (const computation_error& error) {
            if (std::string(error.what()).find("no value for parameter") == std::string::npos)
                throw;
            continue;
        }
        result.push_back({given_values(scene, point), at[0], at[1], {}});
        if (at[0].rows() > 0) {
            Eigen::EigenSolver<Eigen::MatrixXd> eigen(at[0], false);
            if (eigen.info() != Eigen::Success)
                throw computation_error("the eigenvalues of A did not converge at a `values` point");
            for (Eigen::Index k = 0; k < eigen.eigenvalues().size(); ++k)
                result.back().eigenvalues.push_back(eigen.eigenvalues()(k));
            std::sort(result.back().eigenvalues.begin(), result.back().eigenvalues.end(),
                      [](const complex& x, const complex& y) {
                          return x.imag() != y.imag() ? x.imag() < y.imag() : x.real() < y.real();
                      });
            double largest = 0, growth = -HUGE_VAL;
            for (const complex& z : result.back().eigenvalues) {
                largest = std::max(largest, std::abs(z));
                growth = std::max(growth, z.real());
            }
            const double tolerance = 1e-9 * (1 + largest);
            result.back().stability = growth > tolerance ? "unstable" : growth < -tolerance ? "stable" : "marginal";
        }
    }
    return result;
}

frequency_response frequency_response_of(const model& scene, const linearization_result& linear,
                                         const state_space_result& system, const std::string& input,
                                         const std::string& output, const response_settings& settings,
                                         const value_point* point)
{
    const std::size_t u = index_of_input(scene, input);
    const std::size_t q = index_of_coordinate(scene, output);
    value_point merged;
    if (!point) {
        if (scene.values.empty())
            throw computation_error("a frequency response needs numbers: give a `values` line or --values");
        // Every `values` line overlaid in order: later ones (and --values) override earlier ones.
        for (const value_point& line : scene.values) {
            for (const auto& given : line.values) {
                auto same = std::find_if(merged.values.begin(), merged.values.end(),
                                         [&](const auto& entry) { return entry.first == given.first; });
                if (same == merged.values.end())
                    merged.values.push_back(given);
                else
                    same->second = given.second;
            }
            merged.where = line.where;
        }
        point = &merged;
    }
    std::vector<Eigen::MatrixXd> at = matrices_at(
        scene, {&linear.kinetic, &linear.potential, &system.damping, &linear.gyroscopic, &system.input_matrix},
        *point);
    const Eigen::MatrixXd& mass = at[0];
    const Eigen::MatrixXd& stiffness = at[1];
    const Eigen::MatrixXd velocity = at[2] - at[3];
    const Eigen::VectorXd forcing = at[4].col(static_cast<Eigen::Index>(u));

    frequency_response result;
    result.input = input;
    result.output = output;
    result.values = given_values(scene, *point);
    double from = settings.from, to = settings.to;
    if (from <= 0 || to <= 0) {
        // A decade either side of the system's nonzero eigenvalues' moduli.
        const quadratic_modes modes = solve_quadratic_modes(mass, velocity, stiffness);
        double low = std::numeric_limits<double>::infinity(), high = 0;
        for (std::size_t k = 0; k < modes.eigenvalues.size(); ++k) {
            const double r = std::abs(modes.eigenvalues[k]);
            if (r > modes.error[k]) {
                low = std::min(low, r);
                high = std::max(high, r);
            }
        }
        if (high == 0)
            low = high = 1;
        if (from <= 0)
            from = low / 10;
        if (to <= 0)
            to = high * 10;
    }
    if (!(from > 0) || !(to > from) || settings.points < 2)
        throw computation_error("the frequency range needs 0 < from < to and at least 2 points");
    for (std::size_t k = 0; k < settings.points; ++k) {
        const double f = static_cast<double>(k) / static_cast<double>(settings.points - 1);
        const double omega = settings.logarithmic ? from * std::pow(to / from, f) : from + (to - from) * f;
        const complex h = gain_at(omega, mass, velocity, stiffness, forcing, q);
        result.omega.push_back(omega);
        result.gain.push_back(h);
        result.magnitude.push_back(std::abs(h));
        result.magnitude_db.push_back(20 * std::log10(std::abs(h)));
        double phase = std::arg(h) * 180 / M_PI;
        if (!result.phase_degrees.empty()) {
            const double previous = result.phase_degrees.back();
            phase += 360 * std::round((previous - phase) / 360);
        }
        result.phase_degrees.push_back(phase);
    }
    // The peak: the grid's largest |H|, refined between its neighbours.
    const auto largest = std::max_element(result.magnitude.begin(), result.magnitude.end());
    const std::size_t k = static_cast<std::size_t>(largest - result.magnitude.begin());
    if (k == 0 || k + 1 == result.magnitude.size()) {
        result.peak_omega = result.peak_magnitude = std::numeric_limits<double>::quiet_NaN();
        return result;
    }
    double a = result.omega[k - 1], b = result.omega[k + 1];
    const double golden = (std::sqrt(5.0) - 1) / 2;
    auto magnitude = [&](double w) { return std::abs(gain_at(w, mass, velocity, stiffness, forcing, q)); };
    double c = b - golden * (b - a), d = a + golden * (b - a);
    double fc = magnitude(c), fd = magnitude(d);
    for (int iteration = 0; iteration < 200 && b - a > 1e-15 * b; ++iteration) {
        if (fc > fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - golden * (b - a);
            fc = magnitude(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + golden * (b - a);
            fd = magnitude(d);
        }
    }
    result.peak_omega = (a + b) / 2;
    result.peak_magnitude = magnitude(result.peak_omega);
    return result;
}

} // namespace lagrange
