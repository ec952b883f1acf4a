// SPDX-License-Identifier: GPL-2.0-or-later
/** @file angle_sums.cpp
 *  The addition theorems applied to sines and cosines of sums (expand_angle_sums). */
#include "program/angle_sums.h"

#include "algebra/canonical_order.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

namespace {

/// sin and cos of one term, through −term where its coefficient is negative (GiNaC keeps
/// sin(−q) as written), so that q and −q share one sine and cosine.
std::pair<GiNaC::ex, GiNaC::ex> sine_cosine(const GiNaC::ex& term)
{
    const GiNaC::ex coefficient = GiNaC::is_a<GiNaC::mul>(term) ? term.op(term.nops() - 1) : term;
    if (GiNaC::is_a<GiNaC::numeric>(coefficient) && GiNaC::ex_to<GiNaC::numeric>(coefficient).is_negative())
        return {-GiNaC::sin(-term), GiNaC::cos(-term)};
    return {GiNaC::sin(term), GiNaC::cos(term)};
}

/// sin and cos of a sum of `terms` (sorted), from index `first` on.
std::pair<GiNaC::ex, GiNaC::ex> sine_cosine(const std::vector<GiNaC::ex>& terms, std::size_t first)
{
    if (first + 1 == terms.size())
        return sine_cosine(terms[first]);
    const auto [sine_rest, cosine_rest] = sine_cosine(terms, first + 1);
    const auto [sine, cosine] = sine_cosine(terms[first]);
    return {sine * cosine_rest + cosine * sine_rest, cosine * cosine_rest - sine * sine_rest};
}

struct expand_map : GiNaC::map_function {
    canonical_keys keys;
    GiNaC::ex operator()(const GiNaC::ex& e) override
    {
        const bool sine = is_ex_the_function(e, GiNaC::sin), cosine = is_ex_the_function(e, GiNaC::cos);
        if (!sine && !cosine)
            return e.map(*this);
        const GiNaC::ex argument = (*this)(e.op(0));
        if (!GiNaC::is_a<GiNaC::add>(argument))
            return sine ? GiNaC::sin(argument) : GiNaC::cos(argument);
        std::vector<std::pair<std::string, GiNaC::ex>> keyed;
        for (const GiNaC::ex& t : argument)
            keyed.emplace_back(keys.key(t), t);
        std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<GiNaC::ex> terms;
        for (const auto& [key, t] : keyed)
            terms.push_back(t);
        const auto [s, c] = sine_cosine(terms, 0);
        return sine ? s : c;
    }
};

} // namespace

GiNaC::ex expand_angle_sums(const GiNaC::ex& e)
{
    expand_map expand;
    return expand(e);
}

} // namespace lagrange
