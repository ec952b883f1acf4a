// SPDX-License-Identifier: GPL-2.0-or-later
/** @file calculus.cpp
 *  Partial and total time derivatives over a model's symbols. */
#include "algebra/calculus.h"

#include <map>

namespace lagrange {

GiNaC::ex differentiate(const GiNaC::ex& e, const GiNaC::symbol& variable)
{
    // Written by hand because GiNaC's diff applies the sum and product rules to
    // every operand, also those free of the variable, and builds the zeros that
    // then have to be collected again (docs/benchmarks.md has the measurement).
    if (!e.has(variable))
        return 0;
    if (GiNaC::is_a<GiNaC::add>(e)) {
        GiNaC::exvector terms;
        for (const GiNaC::ex& term : e)
            if (term.has(variable))
                terms.push_back(differentiate(term, variable));
        return GiNaC::add(terms);
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        GiNaC::exvector terms;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (!e.op(i).has(variable))
                continue;
            GiNaC::exvector factors;
            factors.reserve(e.nops());
            for (std::size_t j = 0; j < e.nops(); ++j)
                factors.push_back(i == j ? differentiate(e.op(j), variable) : e.op(j));
            terms.push_back(GiNaC::mul(factors));
        }
        return GiNaC::add(terms);
    }
    return e.diff(variable);
}

namespace {

/// The total time derivative by structural recursion, one pass over the expression:
/// q -> q', q' -> q'', t -> 1, parameters -> 0, and the chain rule.
class time_differentiator {
public:
    explicit time_differentiator(const model& scene) : time_(scene.time)
    {
        for (const coordinate& c : scene.coordinates) {
            rates_[c.position] = c.velocity;
            rates_[c.velocity] = c.acceleration;
        }
    }

    GiNaC::ex operator()(const GiNaC::ex& e) const
    {
        if (GiNaC::is_a<GiNaC::symbol>(e)) {
            if (e.is_equal(time_))
                return 1;
            auto rate = rates_.find(e);
            return rate == rates_.end() ? GiNaC::ex(0) : rate->second;
        }
        if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e))
            return 0;
        if (GiNaC::is_a<GiNaC::add>(e)) {
            GiNaC::exvector terms;
            terms.reserve(e.nops());
            for (const GiNaC::ex& term : e)
                terms.push_back((*this)(term));
            return GiNaC::add(terms);
        }
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            GiNaC::exvector terms;
            for (std::size_t i = 0; i < e.nops(); ++i) {
                GiNaC::ex rate = (*this)(e.op(i));
                if (rate.is_zero())
                    continue;
                GiNaC::exvector factors;
                factors.reserve(e.nops());
                for (std::size_t j = 0; j < e.nops(); ++j)
                    factors.push_back(i == j ? rate : e.op(j));
                terms.push_back(GiNaC::mul(factors));
            }
            return GiNaC::add(terms);
        }
        if (GiNaC::is_a<GiNaC::power>(e)) {
            const GiNaC::ex& base = e.op(0);
            const GiNaC::ex& exponent = e.op(1);
            GiNaC::ex base_rate = (*this)(base);
            if (GiNaC::is_a<GiNaC::numeric>(exponent))
                return base_rate.is_zero() ? GiNaC::ex(0) : exponent * GiNaC::pow(base, exponent - 1) * base_rate;
            return e * ((*this)(exponent) * GiNaC::log(base) + exponent * base_rate / base);
        }
        // Functions and anything else: the chain rule over the symbols inside.
        GiNaC::ex result = 0;
        if (e.has(time_))
            result += e.diff(GiNaC::ex_to<GiNaC::symbol>(time_));
        for (const auto& [symbol, rate] : rates_)
            if (e.has(symbol))
                result += e.diff(GiNaC::ex_to<GiNaC::symbol>(symbol)) * rate;
        return result;
    }

private:
    GiNaC::ex time_;
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> rates_;
};

} // namespace

GiNaC::ex time_derivative(const GiNaC::ex& e, const model& scene) { return time_differentiator(scene)(e); }

} // namespace lagrange
