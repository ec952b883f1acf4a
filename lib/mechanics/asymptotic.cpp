// SPDX-License-Identifier: GPL-2.0-or-later
/** @file asymptotic.cpp
 *  The closed-form modes in the scene's `limit`: Laurent series in ε with the
 *  variable as ε² (→ 0) or 1/ε² (→ ∞), the leading terms of the frequencies
 *  (with corrections until they differ), of the modes and normal coordinates,
 *  and the beats of frequencies equal to leading order. */
#include "mechanics/asymptotic.h"

#include "algebra/budget.h"
#include "algebra/sign.h"
#include "algebra/surd.h"
#include "core/errors.h"

#include <algorithm>
#include <functional>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::exvector;
using GiNaC::is_a;

/// Terms of the Laurent series of e in eps at 0, lowest order first (at most `count`).
std::vector<std::pair<int, ex>> series_terms(const ex& e, const GiNaC::symbol& eps, int count)
{
    std::vector<std::pair<int, ex>> terms;
    for (int order = count; order <= 4 * count && static_cast<int>(terms.size()) < count; order += count) {
        terms.clear();
        ex polynomial = GiNaC::series_to_poly(e.series(eps == 0, order));
        polynomial = polynomial.expand();
        for (int k = polynomial.ldegree(eps); k <= polynomial.degree(eps); ++k) {
            ex c = polynomial.coeff(eps, k);
            if (!vanishes(c))
                terms.emplace_back(k, tidy(c));
        }
    }
    if (static_cast<int>(terms.size()) > count)
        terms.resize(count);
    return terms;
}

} // namespace

asymptotic_result asymptotic_limit(const model& scene, const modes_result& modes)
{
    asymptotic_result result;
    if (!scene.limit)
        return result;
    const limit_request& limit = *scene.limit;
    result.label = limit.variable + (limit.to_infinity ? " -> oo" : " -> 0");
    ex variable;
    const std::vector<ex>* frequencies = nullptr;
    const std::vector<std::vector<ex>>* mode_vectors = nullptr;
    const std::vector<ex>* normal_coordinates = nullptr;
    if (scene.ratio && scene.ratio->name == limit.variable && !modes.frequencies_in_ratio.empty()) {
        variable = scene.ratio->symbol;
        frequencies = &modes.frequencies_in_ratio;
        mode_vectors = &modes.modes_in_ratio;
        normal_coordinates = &modes.normal_coordinates_in_ratio;
    } else {
        for (const parameter& p : scene.parameters)
            if (p.name == limit.variable)
                variable = p.symbol;
        frequencies = &modes.frequencies;
        mode_vectors = &modes.modes;
        normal_coordinates = &modes.normal_coordinates;
    }
    if (variable.is_zero() || frequencies->empty())
        return result;
    // x = ε² (x -> 0) or x = 1/ε² (x -> ∞): the square roots of x become powers of ε.
    GiNaC::possymbol eps("epsilon");
    ex replacement = limit.to_infinity ? 1 / (eps * eps) : eps * eps;
    ex back = limit.to_infinity ? 1 / GiNaC::sqrt(variable) : GiNaC::sqrt(variable);
    auto in_eps = [&](const ex& e) { return simplify_square_roots(e.subs(variable == replacement)); };
    auto sum_of = [&](const std::vector<std::pair<int, ex>>& terms, std::size_t count) {
        ex sum = 0;
        for (std::size_t t = 0; t < count && t < terms.size(); ++t)
            sum += terms[t].second * GiNaC::pow(back, terms[t].first);
        return sum;
    };
    // The leading term c εᵏ of a product or power is the product or power of the
    // leading terms: this keeps the series away from √ of a sum that vanishes at ε = 0.
    std::function<ex(const ex&)> leading_in_eps = [&](const ex& e) -> ex {
        try {
            std::vector<std::pair<int, ex>> terms = series_terms(e, eps, 1);
            if (terms.empty())
                return 0;
            return terms[0].second * GiNaC::pow(eps, terms[0].first);
        } catch (const budget_exceeded&) {
            throw; // out of budget: the stage stops, no fallback
        } catch (const std::exception&) {
        }
        if (is_a<GiNaC::mul>(e)) {
            ex product = 1;
            for (const ex& factor : e)
                product *= leading_in_eps(factor);
            return product;
        }
        if (is_a<GiNaC::power>(e) && is_a<GiNaC::numeric>(e.op(1)))
            return simplify_square_roots(GiNaC::pow(leading_in_eps(e.op(0)), e.op(1)));
        throw computation_error("no series");
    };
    auto leading = [&](const ex& e) -> ex {
        try {
            return tidy(leading_in_eps(in_eps(e)).subs(eps == back));
        } catch (const budget_exceeded&) {
            throw; // out of budget: the stage stops, no fallback
        } catch (const std::exception&) {
            return e;
        }
    };
    // Frequencies: the leading term of each, and further terms until they differ.
    std::vector<std::vector<std::pair<int, ex>>> terms;
    bool expanded = true;
    for (const ex& f : *frequencies) {
        try {
            terms.push_back(series_terms(in_eps(f), eps, 4));
        } catch (const budget_exceeded&) {
            throw; // out of budget: the stage stops, no fallback
        } catch (const std::exception&) {
            expanded = false;
            break;
        }
    }
    if (expanded) {
        std::vector<std::size_t> kept(terms.size(), 1);
        for (int round = 0; round < 3; ++round) {
            bool changed = false;
            for (std::size_t i = 0; i < terms.size(); ++i)
                for (std::size_t j = i + 1; j < terms.size(); ++j)
                    if (vanishes(sum_of(terms[i], kept[i]) - sum_of(terms[j], kept[j]))) {
                        kept[i] = std::min(kept[i] + 1, terms[i].size());
                        kept[j] = std::min(kept[j] + 1, terms[j].size());
                        changed = true;
                    }
            if (!changed)
                break;
        }
        for (std::size_t i = 0; i < terms.size(); ++i) {
            if (terms[i].empty()) {
                // ω² = 0 identically: a zero mode (a free translation) stays 0
                result.frequencies.push_back(0);
                result.frequency_series.push_back({ex(0)});
                continue;
            }
            // c0·εᵏ⁰ (1 + (c1/c0) εᵏ¹⁻ᵏ⁰ + …): the leading term outside, corrections in order
            ex correction = 1;
            for (std::size_t t = 1; t < kept[i] && t < terms[i].size(); ++t)
                correction += tidy(terms[i][t].second / terms[i][0].second) *
                              GiNaC::pow(back, terms[i][t].first - terms[i][0].first);
            result.frequencies.push_back(terms[i][0].second * GiNaC::pow(back, terms[i][0].first) * correction);
            std::vector<ex> series{terms[i][0].second * GiNaC::pow(back, terms[i][0].first), 1};
            for (std::size_t t = 1; t < kept[i] && t < terms[i].size(); ++t)
                series.push_back(tidy(terms[i][t].second / terms[i][0].second) *
                                 GiNaC::pow(back, terms[i][t].first - terms[i][0].first));
            result.frequency_series.push_back(series);
        }
        // Frequencies equal to leading order beat: ω_j − ω_i and the period 2π/(ω_j − ω_i).
        for (std::size_t i = 0; i < terms.size(); ++i)
            for (std::size_t j = i + 1; j < terms.size(); ++j) {
                if (terms[i].empty() || terms[j].empty() || terms[i][0].first != terms[j][0].first ||
                    !vanishes(terms[i][0].second - terms[j][0].second))
                    continue;
                try {
                    ex difference = leading_in_eps(in_eps(GiNaC::sqrt((*frequencies)[j]) -
                                                          GiNaC::sqrt((*frequencies)[i])));
                    if (difference.is_zero())
                        continue;
                    difference = tidy(difference.subs(eps == back));
                    result.beats.push_back({i, j, difference, tidy(2 * GiNaC::Pi / difference)});
                } catch (const budget_exceeded&) {
                    throw; // out of budget: the stage stops, no fallback
                } catch (const std::exception&) {
                }
            }
    } else {
        result.frequencies = *frequencies;
    }
    for (const std::vector<ex>& mode : *mode_vectors) {
        std::vector<ex> limit_mode;
        for (const ex& component : mode)
            limit_mode.push_back(leading(component));
        result.modes.push_back(limit_mode);
    }
    for (const ex& zeta : *normal_coordinates) {
        // ζ = (Σ w_j q_j) · scale: the leading terms of each w_j times that of the scale
        ex combination = 0, scale = 1;
        for (const ex& factor : is_a<GiNaC::mul>(zeta) ? exvector(zeta.begin(), zeta.end()) : exvector{zeta}) {
            bool has_coordinate = false;
            for (const coordinate& c : scene.coordinates)
                has_coordinate = has_coordinate || factor.has(c.position);
            (has_coordinate ? combination : scale) = has_coordinate ? combination + factor : scale * factor;
        }
        // written as prefactor·(q_p + Σ r_j q_j) with p the first coordinate present
        ex leading_scale = leading(scale);
        std::vector<ex> coefficients;
        for (const coordinate& c : scene.coordinates)
            coefficients.push_back(leading(combination.expand().coeff(c.position, 1)));
        std::size_t pivot = 0;
        while (pivot + 1 < coefficients.size() && vanishes(coefficients[pivot]))
            ++pivot;
        if (vanishes(coefficients[pivot])) {
            result.normal_coordinates.push_back(leading(zeta));
            continue;
        }
        ex sum = 0;
        for (std::size_t j = 0; j < coefficients.size(); ++j)
            sum += tidy(coefficients[j] / coefficients[pivot]) *
                   (j < modes.displacements.size() ? modes.displacements[j] : ex(scene.coordinates[j].position));
        result.normal_coordinates.push_back(tidy(coefficients[pivot] * leading_scale) * sum);
    }
    return result;
}

} // namespace lagrange
