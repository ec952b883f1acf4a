// SPDX-License-Identifier: GPL-2.0-or-later
/** @file pythagorean.cpp
 *  sin² a + cos² a = 1 for parameter angles, applied sum by sum where it shortens. */
#include "algebra/pythagorean.h"

#include "algebra/expression.h"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::numeric;

/// True if `a` holds a symbol and every symbol in it is declared positive (th0, 2·th0,
/// th0 − th1): an angle of parameters alone, which the canonical form keeps as an offset.
bool parameter_angle(const ex& a)
{
    bool any = false;
    bool all = true;
    std::vector<ex> stack{a};
    while (!stack.empty()) {
        const ex e = stack.back();
        stack.pop_back();
        if (ex_kind_of(e) == ex_kind::symbol) {
            any = true;
            all = all && e.info(GiNaC::info_flags::positive);
        }
        for (std::size_t i = 0; i < e.nops(); ++i)
            stack.push_back(e.op(i));
    }
    return any && all;
}

/// The parameter angles of the sines and cosines in `e`, ordered by their printed form
/// (never by GiNaC's hash order, which changes from process to process).
std::vector<ex> parameter_angles(const ex& e)
{
    std::map<std::string, ex> found;
    std::vector<ex> stack{e};
    while (!stack.empty()) {
        const ex x = stack.back();
        stack.pop_back();
        if (is_sin_or_cos(x) && parameter_angle(x.op(0))) {
            std::ostringstream text;
            text << x.op(0);
            found.emplace(text.str(), x.op(0));
        }
        for (std::size_t i = 0; i < x.nops(); ++i)
            stack.push_back(x.op(i));
    }
    std::vector<ex> angles;
    for (const auto& [text, angle] : found)
        angles.push_back(angle);
    return angles;
}

/// (power of sin a, power of cos a) → coefficient.
using trig_polynomial = std::map<std::pair<int, int>, numeric>;

/// `p` modulo s² + c² − 1, of degree ≤ 1 in s (`sine`) or in c: sⁱ = s^(i mod 2)·(1 − c²)^(i div 2).
trig_polynomial reduced(const trig_polynomial& p, bool sine)
{
    trig_polynomial out;
    for (const auto& [powers, coefficient] : p) {
        const int high = sine ? powers.first : powers.second;
        const int half = high / 2;
        numeric binomial = 1; // C(half, k)
        for (int k = 0; k <= half; ++k) {
            const std::pair<int, int> target =
                sine ? std::pair{high % 2, powers.second + 2 * k} : std::pair{powers.first + 2 * k, high % 2};
            out[target] += coefficient * binomial * (k % 2 ? -1 : 1);
            binomial = binomial * (half - k) / (k + 1);
        }
    }
    for (auto it = out.begin(); it != out.end();)
        it = it->second.is_zero() ? out.erase(it) : std::next(it);
    return out;
}

/// The sin a or cos a of `factor` (or of its positive integer power): (is sine, exponent).
std::optional<std::pair<bool, int>> trig_power_of(const ex& factor, const ex& angle)
{
    ex base = factor;
    int exponent = 1;
    if (ex_kind_of(factor) == ex_kind::power) {
        if (!factor.op(1).info(GiNaC::info_flags::posint))
            return std::nullopt;
        base = factor.op(0);
        exponent = GiNaC::ex_to<numeric>(factor.op(1)).to_int();
    }
    if (!is_sin_or_cos(base) || !base.op(0).is_equal(angle))
        return std::nullopt;
    return std::pair{GiNaC::is_the_function<GiNaC::sin_SERIAL>(base), exponent};
}

/// The sum `sum` with the terms that share all factors but the powers of sin a and cos a
/// reduced, group by group, where that leaves fewer terms.
ex reduce_sum(const ex& sum, const ex& angle)
{
    std::map<ex, trig_polynomial, GiNaC::ex_is_less> groups;
    for (const ex& term : terms_of(sum)) {
        numeric coefficient = 1;
        std::pair<int, int> powers{0, 0};
        GiNaC::exvector rest;
        for (const ex& factor : factors_of(term)) {
            if (ex_kind_of(factor) == ex_kind::number)
                coefficient = coefficient * GiNaC::ex_to<numeric>(factor);
            else if (std::optional<std::pair<bool, int>> trig = trig_power_of(factor, angle))
                (trig->first ? powers.first : powers.second) += trig->second;
            else
                rest.push_back(factor);
        }
        groups[product_of(rest)][powers] += coefficient;
    }
    bool changed = false;
    GiNaC::exvector terms;
    for (auto& [rest, polynomial] : groups) {
        for (auto it = polynomial.begin(); it != polynomial.end();)
            it = it->second.is_zero() ? polynomial.erase(it) : std::next(it);
        const std::size_t before = polynomial.size();
        for (bool sine : {true, false}) {
            trig_polynomial candidate = reduced(polynomial, sine);
            if (candidate.size() < polynomial.size()) {
                polynomial = std::move(candidate);
            }
        }
        changed = changed || polynomial.size() < before;
        for (const auto& [powers, coefficient] : polynomial)
            terms.push_back(coefficient * rest * GiNaC::pow(GiNaC::sin(angle), powers.first) *
                            GiNaC::pow(GiNaC::cos(angle), powers.second));
    }
    return changed ? sum_of(terms) : sum;
}

ex reduce_everywhere(const ex& e, const std::vector<ex>& angles)
{
    if (e.nops() == 0)
        return e;
    map_each recurse([&](const ex& x) { return reduce_everywhere(x, angles); });
    ex mapped = e.map(recurse);
    for (const ex& angle : angles)
        if (ex_kind_of(mapped) == ex_kind::sum)
            mapped = reduce_sum(mapped, angle);
    return mapped;
}

} // namespace

GiNaC::ex pythagorean(const GiNaC::ex& e)
{
    const std::vector<ex> angles = parameter_angles(e);
    return angles.empty() ? e : reduce_everywhere(e, angles);
}

} // namespace lagrange
