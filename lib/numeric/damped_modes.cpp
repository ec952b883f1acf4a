// SPDX-License-Identifier: GPL-2.0-or-later
/** @file damped_modes.cpp
 *  The damped quadratic eigenproblem at one point; the linearization's matrices at a
 *  `values` point. */
#include "numeric/damped_modes.h"

#include "core/errors.h"
#include "program/expression_program.h"
#include "numeric/quadratic_modes.h"

#include <algorithm>
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

namespace {

/// x scaled so that its first component of largest modulus (to a relative 10⁻⁸, so that
/// rounding does not pick between equal components) is exactly 1.
Eigen::VectorXcd unit_largest(Eigen::VectorXcd x)
{
    const double largest = x.cwiseAbs().maxCoeff();
    if (largest == 0)
        return x;
    for (Eigen::Index k = 0; k < x.size(); ++k)
        if (std::abs(x(k)) >= (1 - 1e-8) * largest) {
            const std::complex<double> pivot = x(k);
            x /= pivot;
            x(k) = 1;
            break;
        }
    return x;
}

/// ‖(s²M + sD + K)x‖ / ((|s|²‖M‖ + |s|‖D‖ + ‖K‖)‖x‖), Frobenius norms.
double pencil_backward_error(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& velocity_matrix,
                             const Eigen::MatrixXd& stiffness, std::complex<double> s, const Eigen::VectorXcd& x)
{
    using complex = std::complex<double>;
    const Eigen::VectorXcd residual = (s * s) * (mass.cast<complex>() * x) +
                                      s * (velocity_matrix.cast<complex>() * x) + stiffness.cast<complex>() * x;
    const double scale =
        (std::norm(s) * mass.norm() + std::abs(s) * velocity_matrix.norm() + stiffness.norm()) * x.norm();
    if (scale == 0)
        return residual.norm() == 0 ? 0 : std::numeric_limits<double>::infinity();
    return residual.norm() / scale;
}

/// Caughey–O'Kelly at one point: ‖C M⁻¹K − K M⁻¹C‖ within rounding of ‖C‖‖M⁻¹‖‖K‖.
bool proportional_at(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& damping, const Eigen::MatrixXd& stiffness)
{
    const Eigen::MatrixXd inverse_mass = mass.inverse();
    if (!inverse_mass.allFinite())
        return false;
    const Eigen::MatrixXd commutator = damping * inverse_mass * stiffness - stiffness * inverse_mass * damping;
    const double scale = damping.norm() * inverse_mass.norm() * stiffness.norm();
    const double rounding = 1e3 * static_cast<double>(mass.rows()) * std::numeric_limits<double>::epsilon();
    return commutator.norm() <= rounding * scale;
}

/// The damped modes of one point into `entry`: each vector of `q` scaled by unit_largest;
/// with proportional damping made real where its real part is as good an eigenvector (a
/// multiple eigenvalue may have a genuinely complex vector in its eigenspace, kept as is).
void set_damped_modes(numeric_modes& entry, const quadratic_modes& q, const Eigen::MatrixXd& mass,
                      const Eigen::MatrixXd& velocity_matrix, const Eigen::MatrixXd& stiffness, bool proportional)
{
    const double rounding = 1e3 * std::numeric_limits<double>::epsilon();
    entry.proportional_damping = proportional;
    entry.damped_modes.resize(q.vectors.rows(), q.vectors.cols());
    entry.damped_mode_backward_error.clear();
    for (Eigen::Index k = 0; k < q.vectors.cols(); ++k) {
        const std::complex<double> s = q.eigenvalues[static_cast<std::size_t>(k)];
        Eigen::VectorXcd x = unit_largest(q.vectors.col(k));
        double eta = pencil_backward_error(mass, velocity_matrix, stiffness, s, x);
        if (proportional) {
            const Eigen::VectorXcd real_part = x.real().cast<std::complex<double>>();
            const double real_eta = pencil_backward_error(mass, velocity_matrix, stiffness, s, real_part);
            if (real_eta <= std::max(8 * eta, rounding)) {
                x = real_part;
                eta = real_eta;
            }
        }
        entry.damped_modes.col(k) = x;
        entry.damped_mode_backward_error.push_back(eta);
    }
}

} // namespace

void add_damped_eigenvalues(numeric_modes& entry, const Eigen::MatrixXd& kinetic, const Eigen::MatrixXd& potential,
                            const Eigen::MatrixXd& damping, const Eigen::MatrixXd& gyroscopic)
{
    const quadratic_modes q = solve_quadratic_modes(kinetic, damping - gyroscopic, potential);
    entry.damped = true;
    entry.eigenvalues = q.eigenvalues;
    entry.eigenvalue_error = q.error;
    entry.damping_ratio.clear();
    const bool proportional = gyroscopic.isZero(0) && proportional_at(kinetic, damping, potential);
    set_damped_modes(entry, q, kinetic, damping - gyroscopic, potential, proportional);
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

} // namespace lagrange
