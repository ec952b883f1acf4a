// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_asymptotic.cpp
 *  The asymptotic frequencies against the exact ones near the limit: the eigenvalues of
 *  the pencil (V, T) at the parameter values (Eigen's generalized self-adjoint solver),
 *  with the limit's variable at two values ever closer to 0 (or ∞). The leading terms
 *  must approach them: relative differences small at the closer value and not larger
 *  than at the farther one. */
#include "verify/verify.h"

#include "core/errors.h"
#include "numeric/values.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>

namespace lagrange {

namespace {

using GiNaC::ex;

/// The parameters at the `values` line (else 1) with the limit's variable at `x`: a
/// parameter directly, or a ratio p/q through p = x·q (or q = p/x). Nothing if the ratio
/// is not a quotient of two parameters.
std::optional<GiNaC::exmap> point_at(const model& scene, double x)
{
    GiNaC::exmap given;
    if (!scene.values.empty())
        given = value_map(scene, scene.values.front());
    GiNaC::exmap at;
    for (const parameter& p : scene.parameters) {
        std::optional<double> v;
        if (auto found = given.find(p.symbol); found != given.end())
            v = real_at(found->second, {});
        at[p.symbol] = GiNaC::numeric(v && *v > 0 ? *v : 1.0);
    }
    const std::string& name = scene.limit->variable;
    for (const parameter& p : scene.parameters)
        if (p.name == name) {
            at[p.symbol] = GiNaC::numeric(x);
            return at;
        }
    if (!scene.ratio || scene.ratio->name != name)
        return std::nullopt;
    const ex top = scene.ratio->definition.numer(), bottom = scene.ratio->definition.denom();
    at[scene.ratio->symbol] = GiNaC::numeric(x);
    if (GiNaC::is_a<GiNaC::symbol>(top) && at.count(top) && !bottom.has(top)) {
        std::optional<double> b = real_at(bottom, at);
        if (!b)
            return std::nullopt;
        at[top] = GiNaC::numeric(x * *b);
        return at;
    }
    if (GiNaC::is_a<GiNaC::symbol>(bottom) && at.count(bottom) && !top.has(bottom)) {
        std::optional<double> t = real_at(top, at);
        if (!t)
            return std::nullopt;
        at[bottom] = GiNaC::numeric(*t / x);
        return at;
    }
    return std::nullopt;
}

/// Largest relative difference between the asymptotic ω² and the pencil's eigenvalues, both
/// in ascending order, at the limit's variable x; nothing if either cannot be evaluated.
std::optional<double> difference_at(const model& scene, const linearization_result& linear,
                                    const asymptotic_result& limit, double x)
{
    std::optional<GiNaC::exmap> at = point_at(scene, x);
    if (!at)
        return std::nullopt;
    const unsigned n = linear.kinetic.rows();
    Eigen::MatrixXd t(n, n), v(n, n);
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) {
            std::optional<double> a = real_at(linear.kinetic(i, j), *at), b = real_at(linear.potential(i, j), *at);
            if (!a || !b)
                return std::nullopt;
            t(i, j) = *a;
            v(i, j) = *b;
        }
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(v, t, Eigen::EigenvaluesOnly);
    if (solver.info() != Eigen::Success || limit.frequencies.size() != n)
        return std::nullopt;
    std::vector<double> asymptotic;
    for (const ex& w : limit.frequencies) {
        std::optional<double> value = real_at(w, *at);
        if (!value)
            return std::nullopt;
        asymptotic.push_back(*value);
    }
    std::sort(asymptotic.begin(), asymptotic.end());
    const Eigen::VectorXd exact = solver.eigenvalues(); // ascending
    const double scale = exact.cwiseAbs().maxCoeff();
    double worst = 0;
    for (unsigned k = 0; k < n; ++k) {
        // A frequency that vanishes in the limit is compared on the scale of the others.
        const double size = std::max(std::abs(exact(k)), 1e-12 * scale);
        worst = std::max(worst, std::abs(asymptotic[k] - exact(k)) / size);
    }
    return worst;
}

} // namespace

verification_entry verify_asymptotic(const model& scene, const linearization_result& linear,
                                     const asymptotic_result& limit)
{
    if (!scene.limit)
        return {"asymptotic", "not checked: no limit", false};
    const bool infinity = scene.limit->to_infinity;
    const double far = infinity ? 1e4 : 1e-4, near = infinity ? 1e8 : 1e-8;
    std::optional<double> at_far = difference_at(scene, linear, limit, far);
    std::optional<double> at_near = difference_at(scene, linear, limit, near);
    if (!at_far || !at_near)
        return {"asymptotic",
                "not checked: the frequencies or the pencil have no numeric value near the limit "
                "(a limit variable that is neither a parameter nor a ratio of two)",
                false};
    const std::string where = scene.limit->variable + " = " + message_number(near);
    // Leading order: at least the square root of the variable's distance from the limit
    // (the smallest correction a series in √x can leave), and no worse than farther away.
    const double allowed = 10 * std::sqrt(infinity ? 1 / near : near);
    if (*at_near > allowed || *at_near > *at_far + 1e-9)
        throw computation_error("verification failed: asymptotic: the limit's ω² differ from the eigenvalues of "
                                "(V, T) by " + message_number(*at_near) + " (relative) at " + where +
                                ", and by " + message_number(*at_far) + " at " + scene.limit->variable + " = " +
                                message_number(far));
    return {"asymptotic", "ω² against the eigenvalues of (V, T) at " + scene.limit->variable + " = " +
                              message_number(far) + " and " + message_number(near) +
                              ": relative differences within " + message_number(allowed) + " and shrinking"};
}

} // namespace lagrange
