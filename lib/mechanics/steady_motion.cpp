// SPDX-License-Identifier: GPL-2.0-or-later
/** @file steady_motion.cpp
 *  Steady motions on the reduced system. */
#include "mechanics/steady_motion.h"

#include "core/number_text.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"
#include "algebra/exact_matrix.h"
#include "algebra/expression.h"
#include "algebra/sorted_terms.h"
#include "algebra/sign.h"
#include "mechanics/equilibrium.h"
#include "mechanics/gyroscopic.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <utility>
#include <string>

namespace lagrange {

namespace {

using GiNaC::ex;

bool contains(const std::vector<std::size_t>& list, std::size_t i)
{
    return std::find(list.begin(), list.end(), i) != list.end();
}

bool contains_symbol(const std::vector<GiNaC::realsymbol>& list, const GiNaC::ex& e)
{
    for (const GiNaC::realsymbol& s : list)
        if (e.is_equal(s))
            return true;
    return false;
}

/// e with every floating-point number written as the exact decimal it prints as (0.5 as
/// 1/2), so that a steady motion given in decimals is studied exactly.
ex exact_decimals(const ex& e)
{
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric& x = GiNaC::ex_to<GiNaC::numeric>(e);
        if (x.is_rational() || !x.is_real())
            return e;
        const std::string digits = shortest(x.to_double());
        const std::size_t exponent_at = digits.find_first_of("eE");
        std::string mantissa = digits.substr(0, exponent_at);
        long exponent = exponent_at == std::string::npos ? 0 : std::stol(digits.substr(exponent_at + 1));
        const std::size_t point = mantissa.find('.');
        if (point != std::string::npos) {
            exponent -= static_cast<long>(mantissa.size() - point - 1);
            mantissa.erase(point, 1);
        }
        return GiNaC::numeric(mantissa.c_str()) * GiNaC::pow(GiNaC::numeric(10), exponent);
    }
    map_each recurse([](const ex& x) { return exact_decimals(x); });
    return e.nops() == 0 ? e : e.map(recurse);
}

/// The verdict of steady_motion_result from the signs of the reduced V's leading minors.
void judge_stability(steady_motion_result& result)
{
    const std::vector<ex> minors = leading_minors(result.linear.potential);
    bool positive = true;
    for (const ex& minor : minors) {
        const std::optional<int> sign = sign_of(minor);
        positive = positive && sign && *sign > 0;
    }
    if (positive) {
        result.verdict = stability::stable;
        result.stability_reason = result.linear.has_gyroscopic()
                                      ? "the reduced V is positive definite (Kelvin–Tait: G does not change it)"
                                      : "the reduced V is positive definite (Routh)";
        return;
    }
    const std::optional<int> determinant = minors.empty() ? std::nullopt : sign_of(minors.back());
    if (determinant && *determinant < 0) {
        result.verdict = stability::unstable;
        result.stability_reason = "det of the reduced V is negative: an odd number of negative stiffnesses, which no "
                                  "gyroscopic term stabilizes (Kelvin–Tait–Chetaev)";
        return;
    }
    if (!result.linear.has_gyroscopic() && result.modes.closed_form)
        for (const ex& f : result.modes.frequencies)
            if (std::optional<int> sign = sign_of(f); sign && *sign < 0) {
                result.verdict = stability::unstable;
                result.stability_reason = "an ω² is negative";
                return;
            }
    result.verdict = stability::unknown;
    result.stability_reason = "the signs of the reduced V are not decided for every value of the parameters";
}

} // namespace

steady_motion_result steady_motion(const model& scene, const lagrangian_result& lagrangian,
                                   const reduced_result& reduced, const simplifier& simplify)
{
    const steady_motion_request& request = *scene.steady;
    const auto& coords = scene.coordinates;
    steady_motion_result result;
    result.kept = reduced.kept;
    result.cyclic = reduced.cyclic;
    for (std::size_t i = 0; i < coords.size(); ++i) {
        if (request.rates[i] && !contains(reduced.cyclic, i))
            throw computation_error("the steady motion gives a rate for `" + coords[i].name +
                                    "`, but L depends on " + coords[i].name +
                                    ", so it is not cyclic and cannot turn at a steady rate");
        if (!request.positions[i] && !contains(reduced.cyclic, i))
            throw computation_error("the steady motion does not give coordinate `" + coords[i].name +
                                    "`, which is not cyclic");
    }
    // The rates: given, or a symbol to solve for.
    GiNaC::exmap rate_map;
    std::vector<ex> candidates;
    for (std::size_t c : reduced.cyclic) {
        if (request.rates[c]) {
            result.rates.push_back(exact_decimals(*request.rates[c]));
            result.rate_given.push_back(true);
        } else {
            GiNaC::realsymbol unknown(coords[c].name + "_dot");
            result.unknown_rates.push_back(unknown);
            result.rates.push_back(unknown);
            result.rate_given.push_back(false);
            candidates.push_back(unknown);
        }
        rate_map[coords[c].velocity] = result.rates.back();
    }
    for (std::size_t k = 0; k < reduced.cyclic.size(); ++k)
        if (result.rate_given[k] && GiNaC::is_a<GiNaC::symbol>(result.rates[k]))
            candidates.push_back(result.rates[k]);
    std::vector<ex> at(coords.size(), 0);
    for (std::size_t a : reduced.kept) {
        at[a] = exact_decimals(*request.positions[a]);
        result.position.push_back(at[a]);
    }
    auto at_point = [&](const ex& e) { return evaluate_at(e.subs(rate_map), scene, at); };

    // The condition ∂L/∂a = 0 (equivalently ∂U_eff/∂a = 0 at the momenta of the motion).
    const ex& l = lagrangian.lagrangian_canonical;
    std::vector<std::pair<std::size_t, ex>> failing;
    for (std::size_t a : reduced.kept) {
        budget_check();
        const ex condition = tidy_trigonometric(at_point(differentiate(l, coords[a].position)));
        if (!vanishes(condition))
            failing.push_back({a, condition});
    }
    GiNaC::exmap solution;
    if (failing.size() > 1)
        throw computation_error("the point is not a steady motion: ∂L/∂" + coords[failing[0].first].name + " = " +
                                message_text(failing[0].second) + " and ∂L/∂" + coords[failing[1].first].name +
                                " = " + message_text(failing[1].second) + " there, not 0");
    if (failing.size() == 1) {
        const ex p = failing[0].second.normal().numer().expand();
        // The unknown solved for: a rate left out; else a parameter the motion's own values
        // do not hold, in which the condition is linear (g = l Ω² cos θ0 for the conical
        // pendulum, so that the results read in the motion's data); else a rate named by a
        // parameter. The relation is shown solved for a rate where it can be.
        auto solve = [&](const ex& u, bool linear_only) -> std::optional<std::pair<ex, ex>> {
            if (!p.is_polynomial(u))
                return std::nullopt;
            const int degree = p.degree(u);
            const ex c0 = p.coeff(u, 0), c1 = p.coeff(u, 1), c2 = p.coeff(u, 2);
            if (degree == 1 && !(linear_only && c0.is_zero()))
                return std::make_pair(u, tidy_trigonometric(-c0 / c1));
            if (!linear_only && degree == 2 && c1.is_zero())
                return std::make_pair(GiNaC::pow(u, 2), tidy_trigonometric(-c0 / c2));
            return std::nullopt;
        };
        auto use = [&](const ex& u, const std::pair<ex, ex>& solved) {
            solution[u] = solved.first.is_equal(u) ? solved.second : GiNaC::sqrt(solved.second);
        };
        for (const ex& u : candidates) {
            if (contains_symbol(result.unknown_rates, u)) {
                if (auto solved = solve(u, false)) {
                    result.relation = solved;
                    use(u, *solved);
                    break;
                }
            }
        }
        if (!result.relation) {
            for (const parameter& q : scene.parameters) {
                bool held = false;
                for (const ex& v : result.position)
                    held = held || v.has(q.symbol);
                for (const ex& v : result.rates)
                    held = held || v.has(q.symbol);
                if (held)
                    continue;
                if (auto solved = solve(q.symbol, true)) {
                    use(q.symbol, *solved);
                    result.relation = solved;
                    for (const ex& u : candidates)
                        if (auto shown = solve(u, false)) {
                            result.relation = shown;
                            break;
                        }
                    break;
                }
            }
        }
        if (!result.relation) {
            for (const ex& u : candidates)
                if (auto solved = solve(u, false)) {
                    result.relation = solved;
                    use(u, *solved);
                    break;
                }
        }
        if (!result.relation)
            throw computation_error("the point is not a steady motion: ∂L/∂" + coords[failing[0].first].name +
                                    " = " + message_text(failing[0].second) +
                                    " there, not 0, and that cannot be solved for a rate or a parameter");
    }
    result.solution = solution;
    // Shown in the shortest of three exact forms: tidied (sin² = 1 − cos², factored), and
    // the simplifier's compact form of that or of the expression itself where no sine or
    // cosine is left in a denominator (sin(th0)², not −(cos(th0) + 1)·(cos(th0) − 1)).
    auto apply = [&](const ex& e) {
        const ex raw = e.subs(solution);
        const ex tidied = tidy_trigonometric(raw);
        ex best = tidied;
        std::size_t shortest = message_text(tidied).size();
        for (const ex& form : {tidied, raw}) {
            if (has_trigonometric(form.denom()))
                continue;
            const ex candidate = simplify(form);
            const std::size_t length = message_text(candidate).size();
            if (length < shortest) {
                best = candidate;
                shortest = length;
            }
        }
        return best;
    };
    for (std::size_t k = 0; k < result.rates.size(); ++k)
        if (!result.rate_given[k])
            result.rates[k] = apply(result.rates[k]);

    // The momenta of the motion, and the reduced system linearized at fixed momenta.
    GiNaC::exmap momenta_map;
    for (std::size_t k = 0; k < reduced.cyclic.size(); ++k) {
        const ex momentum = at_point(differentiate(l, coords[reduced.cyclic[k]].velocity));
        momenta_map[reduced.momenta[k]] = momentum;
        result.momenta.push_back(apply(momentum));
    }
    const std::size_t m = reduced.kept.size();
    result.linear.at = result.position;
    result.linear.kinetic = GiNaC::matrix(m, m);
    result.linear.potential = GiNaC::matrix(m, m);
    result.linear.gyroscopic = GiNaC::matrix(m, m);
    std::vector<ex> beta;
    for (std::size_t i = 0; i < m; ++i)
        beta.push_back(differentiate(reduced.linear_raw, coords[reduced.kept[i]].velocity));
    for (std::size_t i = 0; i < m; ++i) {
        const coordinate& ai = coords[reduced.kept[i]];
        const ex first = differentiate(reduced.potential_raw, ai.position);
        for (std::size_t j = 0; j < m; ++j) {
            budget_check();
            const coordinate& aj = coords[reduced.kept[j]];
            const unsigned r = static_cast<unsigned>(i), s = static_cast<unsigned>(j);
            result.linear.kinetic(r, s) =
                apply(at_point(differentiate(differentiate(reduced.quadratic_raw, ai.velocity), aj.velocity)));
            result.linear.potential(r, s) =
                apply(at_point(differentiate(first, aj.position).subs(momenta_map)));
            result.linear.gyroscopic(r, s) = apply(at_point(
                (differentiate(beta[j], ai.position) - differentiate(beta[i], aj.position)).subs(momenta_map)));
        }
    }
    model reduced_scene = scene;
    reduced_scene.coordinates.clear();
    for (std::size_t a : reduced.kept)
        reduced_scene.coordinates.push_back(coords[a]);
    reduced_scene.steady.reset();
    result.characteristic = characteristic_polynomial(reduced_scene, result.linear);
    // The frequencies about the steady motion are its product; mode vectors would go unused.
    result.modes = result.linear.has_gyroscopic()
                       ? gyroscopic_modes(reduced_scene, result.linear, result.characteristic)
                       : symbolic_modes(reduced_scene, result.linear, result.characteristic, false);
    for (GiNaC::ex& f : result.modes.frequencies)
        f = apply(f);
    judge_stability(result);
    return result;
}

} // namespace lagrange
