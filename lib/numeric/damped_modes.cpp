/** @file damped_modes.cpp
 *  M, K, C and G compiled into one straight-line program, evaluated per `values` point,
 *  and the damped quadratic eigenproblem solved there. */
#include "numeric/damped_modes.h"

#include "core/errors.h"
#include "numeric/expression_program.h"
#include "numeric/quadratic_modes.h"

#include <cmath>
#include <limits>
#include <string>

namespace lagrange {

double damping_ratio(std::complex<double> s)
{
    const double modulus = std::abs(s);
    if (modulus == 0)
        return std::numeric_limits<double>::quiet_NaN();
    const double ratio = -s.real() / modulus;
    return ratio == 0 ? 0 : ratio; // no −0 in the output
}

std::vector<Eigen::MatrixXd> matrices_at(const model& scene, const std::vector<const GiNaC::matrix*>& matrices,
                                         const value_point& point)
{
    std::vector<GiNaC::ex> outputs, symbols;
    for (const GiNaC::matrix* m : matrices)
        for (unsigned i = 0; i < m->rows(); ++i)
            for (unsigned j = 0; j < m->cols(); ++j)
                outputs.push_back((*m)(i, j));
    for (const parameter& p : scene.parameters)
        symbols.push_back(p.symbol);
    for (const GiNaC::ex& e : outputs) {
        GiNaC::ex rest = e;
        for (const GiNaC::ex& s : symbols)
            rest = rest.subs(s == 1);
        if (!GiNaC::is_a<GiNaC::numeric>(rest.evalf()))
            throw computation_error("the linearization holds a symbol that is not a parameter");
    }
    const std::string where = " at the values on line " + std::to_string(point.where.line);
    std::vector<double> values(scene.parameters.size(), std::nan(""));
    std::vector<bool> given(scene.parameters.size(), false);
    read_value_point(scene, point, values, given);
    for (std::size_t k = 0; k < scene.parameters.size(); ++k)
        if (!given[k])
            for (const GiNaC::ex& e : outputs)
                if (e.has(scene.parameters[k].symbol))
                    throw computation_error("no value for parameter `" + scene.parameters[k].name + "`" + where);
    const expression_program program(outputs, symbols);
    std::vector<double> scratch, out(outputs.size());
    program.run(values.data(), scratch, out.data());
    std::vector<Eigen::MatrixXd> result;
    std::size_t next = 0;
    for (const GiNaC::matrix* m : matrices) {
        Eigen::MatrixXd value(m->rows(), m->cols());
        for (unsigned i = 0; i < m->rows(); ++i)
            for (unsigned j = 0; j < m->cols(); ++j)
                value(i, j) = out[next++];
        if (!value.allFinite())
            throw computation_error("the linearization is not finite" + where);
        result.push_back(std::move(value));
    }
    return result;
}

void add_damped_eigenvalues(const model& scene, const linearization_result& linear, const GiNaC::matrix& damping,
                            std::vector<numeric_modes>& entries)
{
    if (entries.size() != scene.values.size())
        throw std::invalid_argument("add_damped_eigenvalues: one numeric entry per values point");
    for (std::size_t p = 0; p < scene.values.size(); ++p) {
        const value_point& point = scene.values[p];
        std::vector<Eigen::MatrixXd> at =
            matrices_at(scene, {&linear.kinetic, &linear.potential, &damping, &linear.gyroscopic}, point);
        quadratic_modes q;
        try {
            q = solve_quadratic_modes(at[0], at[2] - at[3], at[1]);
        } catch (const computation_error& error) {
            throw computation_error(std::string(error.what()) + " at the values on line " +
                                    std::to_string(point.where.line));
        }
        numeric_modes& entry = entries[p];
        entry.damped = true;
        entry.eigenvalues = q.eigenvalues;
        entry.eigenvalue_error = q.error;
        entry.damping_ratio.clear();
        bool unstable = false, marginal = false;
        for (std::size_t k = 0; k < q.eigenvalues.size(); ++k) {
            const std::complex<double> s = q.eigenvalues[k];
            entry.damping_ratio.push_back(damping_ratio(s));
            unstable = unstable || s.real() > q.error[k];
            marginal = marginal || s.real() >= -q.error[k];
        }
        // Stable: every s decays beyond its error; marginal: some s has a real part that
        // cannot be told from 0 (a free coordinate, an undamped mode).
        entry.stability = unstable ? "unstable" : marginal ? "marginal" : "stable";
    }
}

} // namespace lagrange
