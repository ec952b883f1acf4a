// SPDX-License-Identifier: GPL-2.0-or-later
/** @file poinsot.cpp
 *  Poinsot's construction in space (see poinsot.h). */
#include "numeric/poinsot.h"

#include "numeric/ode.h"
#include "core/errors.h"
#include "core/number_text.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace lagrange {

poinsot_motion compute_poinsot(const euler_result& body, const poinsot_settings& settings)
{
    if (!body.torque_free || !body.poinsot)
        throw computation_error("Poinsot's construction of body `" + body.body +
                                "` needs a torque-free body with numbers for its moments and a nonzero initial ω");
    if (!(settings.step >= 0) || !std::isfinite(settings.step))
        throw std::invalid_argument("the time between frames must be positive (or 0: a 600th of the run)");
    const auto& p = *body.poinsot;
    poinsot_motion out;
    out.body = body.body;
    out.moments = p.moments;
    out.period = p.period;
    const Eigen::Vector3d inertia(p.moments[0], p.moments[1], p.moments[2]);
    const Eigen::Vector3d w0(p.initial[0], p.initial[1], p.initial[2]);
    const Eigen::Vector3d l0 = inertia.cwiseProduct(w0);
    out.energy = 0.5 * w0.dot(l0);
    out.momentum = l0.norm();
    if (!(out.energy > 0))
        throw computation_error("Poinsot's construction of body `" + body.body + "` needs a nonzero initial ω");
    for (int k = 0; k < 3; ++k)
        out.semi_axes[static_cast<std::size_t>(k)] = 1 / std::sqrt(inertia[k]);
    const double scale = std::sqrt(2 * out.energy); // ρ = ω/√(2T)
    out.plane_distance = scale / out.momentum;
    for (const auto& w : p.polhode)
        out.polhode.push_back({w[0] / scale, w[1] / scale, w[2] / scale});
    if (!out.polhode.empty())
        out.polhode.push_back(out.polhode.front());

    // x = (ω1, ω2, ω3, q_w, q_x, q_y, q_z): Euler's equations and q̇ = ½ q ⊗ (0, ω).
    ode_system system;
    system.dimension = 7;
    system.rhs = [inertia](double, const double* x, double* dxdt) {
        const double I1 = inertia[0], I2 = inertia[1], I3 = inertia[2];
        dxdt[0] = (I2 - I3) * x[1] * x[2] / I1;
        dxdt[1] = (I3 - I1) * x[2] * x[0] / I2;
        dxdt[2] = (I1 - I2) * x[0] * x[1] / I3;
        const double qw = x[3], qx = x[4], qy = x[5], qz = x[6];
        dxdt[3] = 0.5 * (-qx * x[0] - qy * x[1] - qz * x[2]);
        dxdt[4] = 0.5 * (qw * x[0] + qy * x[2] - qz * x[1]);
        dxdt[5] = 0.5 * (qw * x[1] + qz * x[0] - qx * x[2]);
        dxdt[6] = 0.5 * (qw * x[2] + qx * x[1] - qy * x[0]);
    };
    // The space axes: L along −z at t = 0.
    const Eigen::Quaterniond start = Eigen::Quaterniond::FromTwoVectors(l0, -Eigen::Vector3d::UnitZ());
    const std::vector<double> x0{w0[0], w0[1], w0[2], start.w(), start.x(), start.y(), start.z()};
    double until = settings.until;
    if (!(until > 0))
        until = p.period > 0 ? 3 * p.period : 10;
    const double step = settings.step > 0 ? settings.step : until / 600;
    if (!std::isfinite(until) || !(until / step < 1e7))
        throw computation_error("Poinsot's construction of body `" + body.body + "` over " + shortest(until) +
                                " time units every " + shortest(step) + " would have more than 10 million frames");
    integration_options options;
    options.until = until;
    options.tolerance = settings.tolerance;
    const std::size_t count = static_cast<std::size_t>(std::floor(until / step + 1e-9)) + 1;
    for (std::size_t f = 0; f < count; ++f)
        options.times.push_back(std::min(until, static_cast<double>(f) * step));
    if (options.times.back() < until)
        options.times.push_back(until);
    const trajectory run = integrate(system, ode_method::dop853, x0, options);
    out.method = run.method;
    out.steps = run.steps;
    out.times = run.times;
    for (const std::vector<double>& x : run.states) {
        const Eigen::Vector3d w(x[0], x[1], x[2]);
        const Eigen::Matrix3d R = Eigen::Quaterniond(x[3], x[4], x[5], x[6]).normalized().toRotationMatrix();
        const Eigen::Vector3d rho = R * w / scale;
        out.omega.push_back({w[0], w[1], w[2]});
        std::array<double, 9> rows{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                rows[static_cast<std::size_t>(3 * i + j)] = R(i, j);
        out.rotation.push_back(rows);
        out.contact.push_back({rho[0], rho[1], rho[2]});
    }
    return out;
}

} // namespace lagrange
