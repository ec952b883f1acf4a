// SPDX-License-Identifier: GPL-2.0-or-later
/** @file euler.cpp
 *  Euler's equations, torque-free motion (symmetric and elliptic), Poinsot. */
#include "bodies/euler.h"

#include "algebra/budget.h"
#include "algebra/factor.h"
#include "algebra/sign.h"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include <algorithm>
#include <cmath>

namespace lagrange {

std::array<double, 3> euler_result::elliptic_solution::evaluate(double t) const
{
    double cn = 0, dn = 0;
    double sn = boost::math::jacobi_elliptic(modulus, rate * t + phase, &cn, &dn);
    std::array<double, 3> w{};
    w[roles[0]] = amplitudes[0] * cn;
    w[roles[1]] = amplitudes[1] * sn;
    w[roles[2]] = amplitudes[2] * dn;
    return w;
}

namespace {

/// The asymmetric torque-free solution in Jacobi elliptic functions (Landau & Lifshitz §37),
/// for moments I and initial ω; nothing for a degenerate case (an axis rotation, the separatrix).
std::optional<euler_result::elliptic_solution> elliptic_motion(const std::array<double, 3>& I,
                                                               const std::array<double, 3>& w0)
{
    euler_result::elliptic_solution s;
    s.moments = I;
    s.initial = w0;
    double two_t = 0, l2 = 0;
    for (int i = 0; i < 3; ++i) {
        two_t += I[i] * w0[i] * w0[i];
        l2 += I[i] * I[i] * w0[i] * w0[i];
    }
    s.energy = two_t / 2;
    s.momentum_squared = l2;
    std::array<std::size_t, 3> order = {0, 1, 2};
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return I[a] < I[b]; });
    const std::size_t a = order[0], b = order[1], c = order[2];
    const double Ia = I[a], Ib = I[b], Ic = I[c];
    const double scale = std::max({std::abs(two_t * Ic), std::abs(l2), 1e-300});
    if (Ib - Ia <= 1e-12 * Ic || Ic - Ib <= 1e-12 * Ic)
        return std::nullopt;
    const double above = l2 - two_t * Ia, below = two_t * Ic - l2;
    if (above <= 1e-13 * scale || below <= 1e-13 * scale || std::abs(l2 - two_t * Ib) <= 1e-12 * scale)
        return std::nullopt;
    double k2 = 0;
    if (l2 > two_t * Ib) { // ω about the axis of the largest moment keeps its sign: dn there
        s.roles = {a, b, c};
        s.amplitudes = {std::sqrt(below / (Ia * (Ic - Ia))), std::sqrt(below / (Ib * (Ic - Ib))),
                        std::sqrt(above / (Ic * (Ic - Ia)))};
        s.rate = std::sqrt((Ic - Ib) * above / (Ia * Ib * Ic));
        k2 = (Ib - Ia) * below / ((Ic - Ib) * above);
    } else { // about the axis of the smallest moment
        s.roles = {c, b, a};
        s.amplitudes = {std::sqrt(above / (Ic * (Ic - Ia))), std::sqrt(above / (Ib * (Ib - Ia))),
                        std::sqrt(below / (Ia * (Ic - Ia)))};
        s.rate = std::sqrt((Ib - Ia) * below / (Ia * Ib * Ic));
        k2 = (Ic - Ib) * above / ((Ib - Ia) * below);
    }
    if (!(k2 > 0 && k2 < 1))
        return std::nullopt;
    s.modulus = std::sqrt(k2);
    // Parity: with amplitudes positive the triple solves Euler's equations when the cn
    // equation I_p ω̇_p = (I_{p+1} − I_{p+2}) ω_{p+1} ω_{p+2} holds in sign; else flip sn.
    const std::size_t p = s.roles[0];
    const double lhs = -I[p] * s.amplitudes[0] * s.rate;
    const double rhs = (I[(p + 1) % 3] - I[(p + 2) % 3]) * s.amplitudes[1] * s.amplitudes[2];
    if ((lhs > 0) != (rhs > 0))
        s.amplitudes[1] = -s.amplitudes[1];
    // Flipping two components is a symmetry of the equations: match the sign of the dn component.
    if ((w0[s.roles[2]] < 0) != (s.amplitudes[2] < 0)) {
        s.amplitudes[2] = -s.amplitudes[2];
        s.amplitudes[0] = -s.amplitudes[0];
    }
    const double amplitude_angle = std::atan2(w0[s.roles[1]] / s.amplitudes[1], w0[s.roles[0]] / s.amplitudes[0]);
    s.phase = boost::math::ellint_1(s.modulus, amplitude_angle);
    s.period = 4 * boost::math::ellint_1(s.modulus) / s.rate;
    return s;
}

} // namespace

euler_result derive_euler(const rigid_body& body, const inertia_result& inertia,
                          const std::optional<initial_state>& initial, const GiNaC::exmap& values)
{
    if (!body.omega)
        throw std::invalid_argument("body `" + body.name + "` has no `omega`");
    euler_result result;
    result.body = body.name;
    result.omega.assign(body.omega->begin(), body.omega->end());
    result.rates.assign(body.omega_rates.begin(), body.omega_rates.end());
    const std::vector<GiNaC::ex>& w = result.omega;
    const std::vector<GiNaC::ex>& dw = result.rates;
    for (const GiNaC::ex& n : body.torque)
        result.torque_free = result.torque_free && n.is_zero();

    // dL/dt|space = dL/dt|body + ω × L = N with L = I ω and I constant in the body frame.
    auto euler_equations = [&](const GiNaC::matrix& tensor) {
        GiNaC::matrix omega{{w[0]}, {w[1]}, {w[2]}}, rates{{dw[0]}, {dw[1]}, {dw[2]}};
        GiNaC::matrix l = tensor.mul(omega), l_rate = tensor.mul(rates);
        std::vector<GiNaC::ex> equations;
        for (unsigned i = 0; i < 3; ++i) {
            const unsigned j = (i + 1) % 3, k = (i + 2) % 3;
            GiNaC::ex cross = w[j] * l(k, 0) - w[k] * l(j, 0);
            equations.push_back((l_rate(i, 0) + cross - body.torque[i]).expand());
        }
        return equations;
    };
    // A thin body (a zero principal moment, det I = 0) has no equation for its spin about
    // that axis: Euler's equations would print 0 = 0 and a "solution" nothing determines.
    const GiNaC::ex determinant = inertia.tensor.determinant();
    budget_check_terms(determinant, "the determinant of the inertia tensor");
    if (determinant.expand().is_zero())
        throw computation_error("body `" + body.name + "` has a zero principal moment of inertia (a thin body): "
                                "Euler's equations do not determine its spin about that axis; give its "
                                "orientation by coordinates (`orientation`) instead of `omega`");
    result.equations = euler_equations(inertia.tensor);
    if (inertia.diagonal) {
        result.moments = inertia.principal;
    } else if (inertia.principal.size() == 3) {
        result.moments = inertia.principal;
        result.principal_equations = euler_equations(diagonal_tensor(inertia.principal));
    }
    if (result.moments.size() != 3)
        return result;
    const std::vector<GiNaC::ex>& I = result.moments;
    result.kinetic_energy = 0;
    result.angular_momentum_squared = 0;
    for (int i = 0; i < 3; ++i) {
        result.kinetic_energy += GiNaC::numeric(1, 2) * I[i] * w[i] * w[i];
        result.angular_momentum_squared += I[i] * I[i] * w[i] * w[i];
    }
    // Stability of steady rotation about axis i: small deviations obey
    // δω̈_j = (I_i − I_j)(I_k − I_i) ω_i² / (I_j I_k) δω_j, so rotation is stable when
    // (I_i − I_j)(I_i − I_k) > 0 (largest or smallest moment), unstable when < 0.
    for (int i = 0; i < 3; ++i) {
        std::optional<int> sign = sign_at((I[i] - I[(i + 1) % 3]) * (I[i] - I[(i + 2) % 3]), values);
        result.stability.push_back(!sign ? "unknown" : *sign > 0 ? "stable" : *sign < 0 ? "unstable" : "marginal");
    }
    if (!result.torque_free)
        return result;

    std::vector<GiNaC::ex> start;
    bool numbers = initial.has_value();
    for (const GiNaC::ex& wi : w) {
        const std::string name = GiNaC::ex_to<GiNaC::symbol>(wi).get_name();
        if (initial) {
            auto found = initial->others.find(name);
            start.push_back(found == initial->others.end() ? GiNaC::ex(0) : found->second);
        } else {
            start.push_back(GiNaC::realsymbol(name + "_0"));
        }
    }
    // Symmetric body: two equal moments.
    std::optional<std::size_t> axis;
    for (std::size_t a = 0; a < 3 && !axis; ++a)
        if (normal_with_pi(I[(a + 1) % 3] - I[(a + 2) % 3]).is_zero())
            axis = a;
    if (axis) {
        euler_result::symmetric_solution s;
        const std::size_t a = *axis, b = (a + 1) % 3, c = (a + 2) % 3;
        s.axis = a;
        const GiNaC::ex transverse = I[b];
        s.precession = normal_with_pi((I[a] - transverse) * start[a] / transverse);
        s.constants = start;
        GiNaC::realsymbol t("t");
        s.time = t;
        s.omega.resize(3);
        // ω̇_b = −Ω ω_c, ω̇_c = Ω ω_b: a rotation of (ω_b, ω_c) at the rate Ω.
        s.omega[a] = start[a];
        s.omega[b] = start[b] * GiNaC::cos(s.precession * t) - start[c] * GiNaC::sin(s.precession * t);
        s.omega[c] = start[c] * GiNaC::cos(s.precession * t) + start[b] * GiNaC::sin(s.precession * t);
        result.symmetric = s;
    }
    if (!numbers)
        return result;
    std::array<double, 3> moments{}, w0{};
    for (int i = 0; i < 3; ++i) {
        std::optional<double> m = number_at(I[i], values), v = number_at(start[i], values);
        if (!m || !v || *m <= 0)
            return result;
        moments[i] = *m;
        w0[i] = *v;
    }
    euler_result::poinsot_construction poinsot;
    double two_t = 0, l2 = 0;
    for (int i = 0; i < 3; ++i) {
        two_t += moments[i] * w0[i] * w0[i];
        l2 += moments[i] * moments[i] * w0[i] * w0[i];
    }
    if (two_t <= 0)
        return result;
    for (int i = 0; i < 3; ++i)
        poinsot.ellipsoid_axes[i] = std::sqrt(two_t / moments[i]);
    poinsot.plane_distance = two_t / std::sqrt(l2);
    poinsot.moments = moments;
    poinsot.initial = w0;
    constexpr int polhode_points = 64;
    if (!axis) {
        result.elliptic = elliptic_motion(moments, w0);
        if (result.elliptic)
            poinsot.period = result.elliptic->period;
        if (result.elliptic)
            for (int n = 0; n < polhode_points; ++n)
                poinsot.polhode.push_back(result.elliptic->evaluate(result.elliptic->period * n / polhode_points));
    } else {
        const std::size_t a = *axis, b = (a + 1) % 3, c = (a + 2) % 3;
        const double omega_p = (moments[a] - moments[b]) * w0[a] / moments[b];
        const double period = omega_p != 0 ? 2 * M_PI / std::abs(omega_p) : 0;
        poinsot.period = period;
        for (int n = 0; n < polhode_points && period > 0; ++n) {
            const double angle = omega_p * period * n / polhode_points;
            std::array<double, 3> p{};
            p[a] = w0[a];
            p[b] = w0[b] * std::cos(angle) - w0[c] * std::sin(angle);
            p[c] = w0[c] * std::cos(angle) + w0[b] * std::sin(angle);
            poinsot.polhode.push_back(p);
        }
    }
    result.poinsot = poinsot;
    return result;
}

} // namespace lagrange
