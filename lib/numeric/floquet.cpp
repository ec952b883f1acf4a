// SPDX-License-Identifier: GPL-2.0-or-later
/** @file floquet.cpp
 *  The monodromy matrix over one period of the drive and its eigenvalues, the Floquet
 *  multipliers, about each point that solves the equations at every t. */
#include "numeric/floquet.h"

#include "algebra/budget.h"
#include "numeric/compiled_modes.h"
#include "program/expression_program.h"
#include "numeric/ode.h"
#include "numeric/values.h"

#include "core/errors.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <string>

namespace lagrange {

namespace {

using GiNaC::ex;

/// Largest denominator tried when a ratio of two frequencies is known only as a float.
constexpr long largest_ratio_denominator = 64;

/// The denominator of `ratio` as a fraction, if it is one (exactly, or within 1e-9
/// relative for a floating value with a denominator up to largest_ratio_denominator).
std::optional<long> ratio_denominator(const ex& ratio)
{
    if (GiNaC::is_a<GiNaC::numeric>(ratio) && GiNaC::ex_to<GiNaC::numeric>(ratio).is_rational())
        return GiNaC::ex_to<GiNaC::numeric>(ratio).denom().to_long();
    const ex value = ratio.evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
        return std::nullopt;
    const double r = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
    for (long q = 1; q <= largest_ratio_denominator; ++q) {
        const double scaled = r * static_cast<double>(q);
        if (std::abs(scaled - std::round(scaled)) <= 1e-9 * std::max(1.0, std::abs(scaled)))
            return q;
    }
    return std::nullopt;
}

std::string line_of(const value_point& point) { return std::to_string(point.where.line); }

} // namespace

std::optional<long> frequency_ratio_denominator(const ex& ratio) { return ratio_denominator(ratio); }

std::vector<ex> drive_frequencies(const model& scene, const equations_of_motion& equations,
                                  const periodic_linearization& linear)
{
    std::vector<ex> frequencies;
    for (const GiNaC::matrix* m : {&linear.mass, &linear.stiffness, &linear.velocity})
        for (unsigned i = 0; i < m->rows(); ++i)
            for (unsigned j = 0; j < m->cols(); ++j)
                for (const ex& omega : time_frequencies((*m)(i, j), scene.time)) {
                    bool known = false;
                    for (const ex& f : frequencies)
                        known = known || (f - omega).normal().is_zero() || (f + omega).normal().is_zero();
                    if (!known)
                        frequencies.push_back(omega);
                }
    if (frequencies.empty()) // the linearization is constant: the period of L
        frequencies = time_frequencies(equations.lagrangian, scene.time);
    return frequencies;
}

double common_period(const std::vector<ex>& frequencies, const GiNaC::exmap& values)
{
    if (frequencies.empty())
        throw computation_error("L does not depend on t, so it has no period");
    const ex first = frequencies.front().subs(values).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(first) || !GiNaC::ex_to<GiNaC::numeric>(first).is_real() ||
        GiNaC::ex_to<GiNaC::numeric>(first).is_zero())
        throw computation_error("the frequency of the drive has no nonzero value at these values");
    long denominators = 1;
    for (std::size_t j = 1; j < frequencies.size(); ++j) {
        const ex ratio = (frequencies[j] / frequencies.front()).subs(values).normal();
        const std::optional<long> q = ratio_denominator(ratio);
        if (!q)
            throw computation_error("L is not periodic in t: its frequencies are incommensurate at these values");
        denominators = std::lcm(denominators, *q);
    }
    const double base = std::abs(GiNaC::ex_to<GiNaC::numeric>(first).to_double()) / static_cast<double>(denominators);
    return 2 * M_PI / base;
}

std::vector<double> monodromy(std::size_t dimension, const std::function<void(double t, double* a)>& rate,
                              double period)
{
    const std::size_t d = dimension;
    ode_system system;
    system.dimension = d * d;
    std::vector<double> a(d * d);
    std::size_t calls = 0;
    system.rhs = [&, d](double t, const double* x, double* dxdt) {
        // The integration is the stage's own loop: it ends at the stage's time budget.
        if (++calls % 256 == 0)
            budget_check();
        rate(t, a.data());
        // Φ' = A Φ, both row-major.
        for (std::size_t i = 0; i < d; ++i)
            for (std::size_t j = 0; j < d; ++j) {
                double sum = 0;
                for (std::size_t k = 0; k < d; ++k)
                    sum += a[i * d + k] * x[k * d + j];
                dxdt[i * d + j] = sum;
            }
    };
    std::vector<double> identity(d * d, 0.0);
    for (std::size_t i = 0; i < d; ++i)
        identity[i * d + i] = 1;
    integration_options options;
    options.start = 0;
    options.until = period;
    options.tolerance = 1e-12;
    options.keep_states = false;
    options.outputs = false;
    return integrate(system, ode_method::dop853, identity, options).final_state;
}

std::vector<floquet_point> floquet_multipliers(const model& scene, const equations_of_motion& equations,
                                               const time_dependence_result& time)
{
    if (scene.values.empty())
        throw computation_error("`floquet` needs a `values` line or --values");
    const std::size_t n = scene.coordinates.size();
    const auto size = static_cast<Eigen::Index>(n);
    std::vector<floquet_point> results;
    for (const std::vector<ex>& point : time.points) {
        const periodic_linearization linear = linearize_about(scene, equations, point);
        std::vector<ex> entries;
        for (const GiNaC::matrix* m : {&linear.mass, &linear.stiffness, &linear.velocity})
            for (unsigned i = 0; i < m->rows(); ++i)
                for (unsigned j = 0; j < m->cols(); ++j)
                    entries.push_back((*m)(i, j));
        const std::vector<ex> frequencies = drive_frequencies(scene, equations, linear);
        for (const value_point& values : scene.values) {
            const GiNaC::exmap value_of = value_map(scene, values);
            std::vector<ex> numeric_entries;
            for (const ex& e : entries)
                numeric_entries.push_back(e.subs(value_of));
            for (const parameter& p : scene.parameters)
                for (const ex& e : numeric_entries)
                    if (e.has(p.symbol))
                        throw computation_error("no value for parameter `" + p.name + "` at the values on line " +
                                                line_of(values));
            for (const ex& f : frequencies)
                for (const parameter& p : scene.parameters)
                    if (f.subs(value_of).has(p.symbol))
                        throw computation_error("no value for parameter `" + p.name + "` at the values on line " +
                                                line_of(values));
            floquet_point result;
            result.point = point;
            for (const auto& [name, value] : values.values) {
                const ex number = value.evalf();
                if (GiNaC::is_a<GiNaC::numeric>(number) && GiNaC::ex_to<GiNaC::numeric>(number).is_real())
                    result.values.emplace_back(name, GiNaC::ex_to<GiNaC::numeric>(number).to_double());
            }
            result.period = common_period(frequencies, value_of);

            const expression_program program(numeric_entries, {scene.time});
            std::vector<double> scratch, out(numeric_entries.size());
            Eigen::MatrixXd mass(size, size), stiffness(size, size), velocity(size, size);
            auto rate = [&](double t, double* a) {
                program.run(&t, scratch, out.data());
                for (Eigen::Index i = 0; i < size; ++i)
                    for (Eigen::Index j = 0; j < size; ++j) {
                        const auto k = static_cast<std::size_t>(i * size + j);
                        mass(i, j) = out[k];
                        stiffness(i, j) = out[n * n + k];
                        velocity(i, j) = out[2 * n * n + k];
                    }
                const Eigen::FullPivLU<Eigen::MatrixXd> lu(mass);
                if (!lu.isInvertible() || !mass.allFinite())
                    throw computation_error("the mass matrix is singular at t = " + message_number(t) +
                                            " at the values on line " + line_of(values));
                if (!stiffness.allFinite() || !velocity.allFinite())
                    throw computation_error("the linearized equations are not finite at t = " + message_number(t) +
                                            " at the values on line " + line_of(values));
                const Eigen::MatrixXd k_part = lu.solve(stiffness), c_part = lu.solve(velocity);
                const std::size_t d = 2 * n;
                std::fill(a, a + d * d, 0.0);
                for (std::size_t i = 0; i < n; ++i) {
                    a[i * d + n + i] = 1;
                    for (std::size_t j = 0; j < n; ++j) {
                        a[(n + i) * d + j] = k_part(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
                        a[(n + i) * d + n + j] = c_part(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
                    }
                }
            };
            const std::vector<double> phi = monodromy(2 * n, rate, result.period);
            Eigen::MatrixXd matrix(2 * size, 2 * size);
            for (Eigen::Index i = 0; i < 2 * size; ++i)
                for (Eigen::Index j = 0; j < 2 * size; ++j)
                    matrix(i, j) = phi[static_cast<std::size_t>(i * 2 * size + j)];
            if (!matrix.allFinite())
                throw computation_error("the monodromy matrix is not finite at the values on line " + line_of(values));
            const Eigen::EigenSolver<Eigen::MatrixXd> solver(matrix, false);
            if (solver.info() != Eigen::Success)
                throw computation_error("the Floquet multipliers could not be computed at the values on line " +
                                        line_of(values));
            for (Eigen::Index k = 0; k < solver.eigenvalues().size(); ++k)
                result.multipliers.push_back(solver.eigenvalues()(k));
            std::sort(result.multipliers.begin(), result.multipliers.end(),
                      [](const std::complex<double>& a, const std::complex<double>& b) {
                          if (std::abs(a) != std::abs(b))
                              return std::abs(a) > std::abs(b);
                          return a.imag() > b.imag();
                      });
            result.stable = true;
            for (const std::complex<double>& mu : result.multipliers)
                result.stable = result.stable && std::abs(mu) <= 1 + floquet_tolerance;
            results.push_back(std::move(result));
        }
    }
    return results;
}

} // namespace lagrange
