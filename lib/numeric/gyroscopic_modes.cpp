// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gyroscopic_modes.cpp
 *  T, V and G compiled into one straight-line program, evaluated per `values` point,
 *  and the quadratic eigenproblem solved there. */
#include "numeric/gyroscopic_modes.h"

#include "core/errors.h"
#include "numeric/expression_program.h"
#include "numeric/quadratic_modes.h"

#include <cmath>
#include <string>

namespace lagrange {

std::vector<numeric_modes> numeric_gyroscopic_modes(const model& scene, const linearization_result& linear)
{
    const std::size_t n = linear.kinetic.rows();
    std::vector<GiNaC::ex> outputs, symbols;
    for (const GiNaC::matrix* m : {&linear.kinetic, &linear.potential, &linear.gyroscopic})
        for (unsigned i = 0; i < n; ++i)
            for (unsigned j = 0; j < n; ++j)
                outputs.push_back((*m)(i, j));
    for (const parameter& p : scene.parameters)
        symbols.push_back(p.symbol);
    std::vector<bool> used(scene.parameters.size(), false);
    for (std::size_t k = 0; k < scene.parameters.size(); ++k)
        for (const GiNaC::ex& e : outputs)
            used[k] = used[k] || e.has(scene.parameters[k].symbol);
    for (const GiNaC::ex& e : outputs) {
        GiNaC::ex rest = e;
        for (const GiNaC::ex& s : symbols)
            rest = rest.subs(s == 1);
        if (!GiNaC::is_a<GiNaC::numeric>(rest.evalf()))
            throw computation_error("the linearization holds a symbol that is not a parameter");
    }
    const expression_program program(outputs, symbols);
    std::vector<numeric_modes> results;
    std::vector<double> scratch, out(outputs.size());
    for (const value_point& point : scene.values) {
        const std::string where = " at the values on line " + std::to_string(point.where.line);
        std::vector<double> values(scene.parameters.size(), std::nan(""));
        std::vector<bool> given(scene.parameters.size(), false);
        read_value_point(scene, point, values, given);
        for (std::size_t k = 0; k < scene.parameters.size(); ++k)
            if (used[k] && !given[k])
                throw computation_error("no value for parameter `" + scene.parameters[k].name + "`" + where);
        program.run(values.data(), scratch, out.data());
        Eigen::MatrixXd kinetic(n, n), potential(n, n), gyroscopic(n, n);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                kinetic(i, j) = out[i * n + j];
                potential(i, j) = out[n * n + i * n + j];
                gyroscopic(i, j) = out[2 * n * n + i * n + j];
            }
        if (!kinetic.allFinite() || !potential.allFinite() || !gyroscopic.allFinite())
            throw computation_error("the linearization is not finite" + where);
        quadratic_modes q;
        try {
            q = solve_quadratic_modes(kinetic, -gyroscopic, potential);
        } catch (const computation_error& error) {
            throw computation_error(std::string(error.what()) + where);
        }
        numeric_modes modes;
        for (std::size_t k = 0; k < scene.parameters.size(); ++k)
            if (given[k])
                modes.values.push_back({scene.parameters[k].name, values[k]});
        modes.method = "quadratic eigenproblem (Eigen, first-order system)";
        modes.eigenvalues = q.eigenvalues;
        modes.complex_modes.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
        bool unstable = false, zero = false;
        for (std::size_t k = 0; k < 2 * n; ++k) {
            const std::complex<double> s = q.eigenvalues[k];
            unstable = unstable || std::abs(s.real()) > q.error[k];
            zero = zero || std::abs(s) <= q.error[k];
        }
        for (std::size_t k = n; k < 2 * n; ++k) {
            const std::complex<double> s = q.eigenvalues[k];
            double omega = s.imag() == 0 ? -std::abs(s.real()) : s.imag();
            if (omega == 0)
                omega = 0; // no −0 in the output
            modes.omega.push_back(omega);
            modes.omega_squared.push_back(std::copysign(omega * omega, omega));
            modes.error.push_back(std::abs(s) > q.error[k] ? q.error[k] / std::abs(s) : q.error[k]);
            modes.complex_modes.col(static_cast<Eigen::Index>(k - n)) = q.vectors.col(static_cast<Eigen::Index>(k));
        }
        modes.stability = unstable ? "unstable" : zero ? "marginal" : "stable";
        results.push_back(std::move(modes));
    }
    return results;
}

} // namespace lagrange
