// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gyroscopic_modes.cpp
 *  The quadratic eigenproblem of a gyroscopic linearization at one point. */
#include "numeric/gyroscopic_modes.h"

#include "numeric/quadratic_modes.h"

#include <cmath>

namespace lagrange {

numeric_modes gyroscopic_modes_at(const Eigen::MatrixXd& kinetic, const Eigen::MatrixXd& potential,
                                  const Eigen::MatrixXd& gyroscopic)
{
    const std::size_t n = static_cast<std::size_t>(kinetic.rows());
    const quadratic_modes q = solve_quadratic_modes(kinetic, -gyroscopic, potential);
    numeric_modes modes;
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
        // a real pair ±γ grows at γ; a complex s = γ + iω (a Krein collision) at Re s
        const double growth = s.imag() == 0 ? std::abs(s.real()) : s.real();
        modes.growth_rate.push_back(growth > q.error[k] ? growth : 0.0);
        modes.complex_modes.col(static_cast<Eigen::Index>(k - n)) = q.vectors.col(static_cast<Eigen::Index>(k));
    }
    modes.stability = unstable ? "unstable" : zero ? "marginal" : "stable";
    return modes;
}

} // namespace lagrange
