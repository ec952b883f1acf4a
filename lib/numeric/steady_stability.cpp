// SPDX-License-Identifier: GPL-2.0-or-later
/** @file steady_stability.cpp
 *  Eigenvalues of a steady motion's reduced system at the `values` points. */
#include "numeric/steady_stability.h"

#include "core/errors.h"
#include "numeric/damped_modes.h"
#include "numeric/values.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>

namespace lagrange {

std::vector<steady_motion_result::at_point> steady_stability_at_values(const model& scene,
                                                                       const steady_motion_result& motion)
{
    std::vector<steady_motion_result::at_point> result;
    for (const value_point& point : scene.values) {
        std::vector<Eigen::MatrixXd> at;
        try {
            at = matrices_at(scene, {&motion.linear.kinetic, &motion.linear.potential, &motion.linear.gyroscopic},
                             point);
        } catch (const computation_error&) {
            continue; // a parameter without a value here, or an entry that is not finite
        }
        const Eigen::Index n = at[0].rows();
        Eigen::FullPivLU<Eigen::MatrixXd> kinetic(at[0]);
        if (!kinetic.isInvertible())
            continue;
        Eigen::MatrixXd first_order = Eigen::MatrixXd::Zero(2 * n, 2 * n);
        first_order.topRightCorner(n, n) = Eigen::MatrixXd::Identity(n, n);
        first_order.bottomLeftCorner(n, n) = -kinetic.solve(at[1]);
        first_order.bottomRightCorner(n, n) = kinetic.solve(at[2]);
        Eigen::EigenSolver<Eigen::MatrixXd> eigen(first_order, false);
        if (eigen.info() != Eigen::Success)
            continue;
        steady_motion_result::at_point entry;
        for (const auto& [name, value] : point.values)
            for (const parameter& p : scene.parameters)
                if (p.name == name) {
                    const GiNaC::ex number = value.evalf();
                    if (GiNaC::is_a<GiNaC::numeric>(number))
                        entry.values.push_back({name, GiNaC::ex_to<GiNaC::numeric>(number).to_double()});
                }
        double largest = 0, growth = -HUGE_VAL;
        for (Eigen::Index k = 0; k < eigen.eigenvalues().size(); ++k) {
            entry.eigenvalues.push_back(eigen.eigenvalues()(k));
            largest = std::max(largest, std::abs(entry.eigenvalues.back()));
            growth = std::max(growth, entry.eigenvalues.back().real());
        }
        std::sort(entry.eigenvalues.begin(), entry.eigenvalues.end(),
                  [](const std::complex<double>& x, const std::complex<double>& y) {
                      return x.imag() != y.imag() ? x.imag() < y.imag() : x.real() < y.real();
                  });
        const double tolerance = 1e-9 * (1 + largest);
        bool distinct = true;
        for (std::size_t k = 1; k < entry.eigenvalues.size(); ++k)
            distinct = distinct && std::abs(entry.eigenvalues[k] - entry.eigenvalues[k - 1]) > 1e3 * tolerance;
        entry.verdict = growth > tolerance ? stability::unstable : distinct ? stability::stable : stability::marginal;
        result.push_back(entry);
    }
    return result;
}

} // namespace lagrange
