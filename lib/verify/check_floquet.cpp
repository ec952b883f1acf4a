// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_floquet.cpp
 *  The Floquet multipliers against the flow of the full (nonlinear) equations: the
 *  monodromy matrix by central differences of solutions that start beside the point,
 *  integrated over one period with the compiled M q̈ = f (checked against L by the
 *  `equations` entry), shares nothing with the symbolic linearization about the point
 *  that the multipliers come from. Compared through the characteristic polynomial of
 *  the monodromy, whose coefficients depend smoothly on its entries where the
 *  multipliers themselves may not (a double multiplier at ±1). */
#include "verify/verify.h"

#include "core/errors.h"
#include "numeric/compiled_motion.h"
#include "numeric/values.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>

namespace lagrange {

namespace {

using GiNaC::ex;

/// The coefficients of ∏ (x − μ), highest degree first (real up to rounding).
std::vector<std::complex<double>> polynomial_of(const std::vector<std::complex<double>>& roots)
{
    std::vector<std::complex<double>> c = {1.0};
    for (const std::complex<double>& mu : roots) {
        c.push_back(0.0);
        for (std::size_t k = c.size() - 1; k > 0; --k)
            c[k] -= mu * c[k - 1];
    }
    return c;
}

const value_point* values_of(const model& scene, const floquet_point& result)
{
    for (const value_point& v : scene.values) {
        if (v.values.size() != result.values.size())
            continue;
        bool same = true;
        for (std::size_t k = 0; k < v.values.size() && same; ++k) {
            const ex number = v.values[k].second.evalf();
            same = v.values[k].first == result.values[k].first && GiNaC::is_a<GiNaC::numeric>(number) &&
                   GiNaC::ex_to<GiNaC::numeric>(number).to_double() == result.values[k].second;
        }
        if (same)
            return &v;
    }
    return nullptr;
}

} // namespace

verification_entry verify_floquet(const model& scene, const equations_of_motion& equations,
                                  const std::vector<floquet_point>& points)
{
    const std::size_t n = scene.coordinates.size(), d = 2 * n;
    for (const floquet_point& result : points) {
        const value_point* values = values_of(scene, result);
        if (!values)
            return {"floquet", "not checked: its values point was not found", false};
        std::map<std::string, ex> by_name;
        for (const auto& [name, value] : values->values)
            by_name[name] = value;
        const compiled_motion motion(scene, equations, by_name);
        const GiNaC::exmap value_of = value_map(scene, *values);
        std::vector<double> start(motion.dimension(), 0.0);
        for (std::size_t j = 0; j < n; ++j) {
            const ex x = result.point[j].subs(value_of).evalf();
            if (!GiNaC::is_a<GiNaC::numeric>(x))
                return {"floquet", "not checked: the point has no numeric value", false};
            start[j] = GiNaC::ex_to<GiNaC::numeric>(x).to_double();
        }
        integration_options options;
        options.until = result.period;
        options.tolerance = 1e-13;
        options.keep_states = false;
        options.outputs = false;
        const ode_system system = motion.system();
        Eigen::MatrixXd phi(static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(d));
        for (std::size_t j = 0; j < d; ++j) {
            const double h = 1e-5 * std::max(1.0, std::abs(start[j]));
            std::vector<double> plus = start, minus = start;
            plus[j] += h;
            minus[j] -= h;
            const std::vector<double> a = integrate(system, ode_method::dop853, plus, options).final_state;
            const std::vector<double> b = integrate(system, ode_method::dop853, minus, options).final_state;
            for (std::size_t i = 0; i < d; ++i)
                phi(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = (a[i] - b[i]) / (2 * h);
        }
        const Eigen::EigenSolver<Eigen::MatrixXd> solver(phi, false);
        if (!phi.allFinite() || solver.info() != Eigen::Success)
            return {"floquet", "not checked: the flow's monodromy matrix has no eigenvalues", false};
        std::vector<std::complex<double>> reference;
        for (Eigen::Index k = 0; k < solver.eigenvalues().size(); ++k)
            reference.push_back(solver.eigenvalues()(k));
        const std::vector<std::complex<double>> expected = polynomial_of(reference),
                                                got = polynomial_of(result.multipliers);
        double scale = 1;
        for (const std::complex<double>& mu : reference)
            scale = std::max(scale, std::pow(std::abs(mu), static_cast<double>(d)));
        for (std::size_t k = 0; k < expected.size() && k < got.size(); ++k)
            if (got.size() != expected.size() || std::abs(got[k] - expected[k]) > 1e-5 * scale) {
                std::string where;
                for (const auto& [name, value] : result.values)
                    where += (where.empty() ? "" : ", ") + name + " = " + message_number(value);
                throw computation_error("verification failed: floquet: the multipliers at " + where +
                                        " do not match the monodromy of the equations' own flow (coefficient " +
                                        std::to_string(k) + " of its characteristic polynomial is " +
                                        message_number(got[k].real()) + ", but " +
                                        message_number(expected[k].real()) + " by the independent check)");
            }
    }
    return {"floquet", "the multipliers' characteristic polynomial against the monodromy of the nonlinear "
                       "equations by central differences of their solutions over one period (DOP853, 1e-13)"};
}

} // namespace lagrange
