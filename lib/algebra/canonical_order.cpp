// SPDX-License-Identifier: GPL-2.0-or-later
/** @file canonical_order.cpp
 *  Keys and signs independent of GiNaC's hash order (canonical_order.h). */
#include "algebra/canonical_order.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::is_a;

std::string number_text(const GiNaC::numeric& n)
{
    std::ostringstream text;
    text << n;
    return text.str();
}

bool negative_number(const GiNaC::numeric& c)
{
    const GiNaC::numeric re = c.real();
    return re.is_zero() ? c.imag().is_negative() : re.is_negative();
}

std::string joined(const char* head, std::vector<std::string> keys, bool sorted)
{
    if (sorted)
        std::sort(keys.begin(), keys.end());
    std::string key = std::string(head) + "(";
    for (const std::string& k : keys)
        key += k + ",";
    return key + ")";
}

bool odd_integer(const ex& e)
{
    return is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_odd();
}

} // namespace

canonical_term canonical_keys::term(const ex& e)
{
    if (is_a<GiNaC::numeric>(e))
        return {GiNaC::ex_to<GiNaC::numeric>(e), "1"};
    auto found = terms_.find(e);
    if (found != terms_.end())
        return found->second;
    canonical_term result{1, ""};
    if (is_a<GiNaC::mul>(e)) {
        std::vector<std::string> keys;
        for (const ex& f : e) {
            if (is_a<GiNaC::numeric>(f)) {
                result.coefficient *= GiNaC::ex_to<GiNaC::numeric>(f);
                continue;
            }
            canonical_factor c = factor(f);
            if (c.negative)
                result.coefficient = -result.coefficient;
            keys.push_back(c.key);
        }
        result.rest = keys.size() == 1 ? keys.front() : joined("mul", keys, true);
    } else {
        canonical_factor c = factor(e);
        result.coefficient = c.negative ? -1 : 1;
        result.rest = c.key;
    }
    terms_.emplace(e, result);
    return result;
}

canonical_factor canonical_keys::sum(const ex& e)
{
    std::vector<canonical_term> parts;
    for (const ex& t : e)
        parts.push_back(term(t));
    std::size_t lead = 0;
    for (std::size_t k = 1; k < parts.size(); ++k)
        if (parts[k].rest < parts[lead].rest)
            lead = k;
    const bool negative = !parts.empty() && negative_number(parts[lead].coefficient);
    std::vector<std::string> keys;
    for (const canonical_term& p : parts)
        keys.push_back(p.rest + "*" + number_text(negative ? -p.coefficient : p.coefficient));
    return {negative, joined("add", keys, true)};
}

canonical_factor canonical_keys::factor(const ex& e)
{
    auto found = factors_.find(e);
    if (found != factors_.end())
        return found->second;
    canonical_factor result;
    if (is_a<GiNaC::add>(e)) {
        result = sum(e);
    } else if (is_a<GiNaC::power>(e) && is_a<GiNaC::add>(e.op(0)) && e.op(1).info(GiNaC::info_flags::integer)) {
        canonical_factor base = sum(e.op(0));
        result = {base.negative && odd_integer(e.op(1)), joined("power", {base.key, key(e.op(1))}, false)};
    } else if (is_a<GiNaC::symbol>(e)) {
        result.key = "s" + GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    } else if (is_a<GiNaC::numeric>(e)) {
        result.key = "n" + number_text(GiNaC::ex_to<GiNaC::numeric>(e));
    } else if (is_a<GiNaC::constant>(e)) {
        std::ostringstream text;
        text << e;
        result.key = "c" + text.str();
    } else {
        std::vector<std::string> keys;
        for (const ex& operand : e)
            keys.push_back(key(operand));
        const std::string head = is_a<GiNaC::function>(e) ? GiNaC::ex_to<GiNaC::function>(e).get_name()
                                                          : GiNaC::ex_to<GiNaC::basic>(e).class_name();
        result.key = joined(head.c_str(), keys, false);
    }
    factors_.emplace(e, result);
    return result;
}

std::string canonical_keys::key(const ex& e, bool negated)
{
    if (is_a<GiNaC::add>(e)) {
        std::vector<std::string> keys;
        for (const ex& t : e) {
            canonical_term p = term(t);
            keys.push_back(p.rest + "*" + number_text(negated ? -p.coefficient : p.coefficient));
        }
        return joined("add", keys, true);
    }
    canonical_term p = term(e);
    return p.rest + "*" + number_text(negated ? -p.coefficient : p.coefficient);
}

bool canonically_negative(const ex& e)
{
    canonical_keys keys;
    return is_a<GiNaC::add>(e) ? keys.sum(e).negative : negative_number(keys.term(e).coefficient);
}

ex canonical_numer_denom(const ex& e)
{
    const ex fraction = e.normal().numer_denom();
    if (!canonically_negative(fraction.op(1)))
        return fraction;
    return GiNaC::lst{(-fraction.op(0)).expand(), (-fraction.op(1)).expand()};
}

ex merge_signed_powers(const ex& e)
{
    if (is_a<GiNaC::add>(e) || is_a<GiNaC::function>(e) || is_a<GiNaC::power>(e)) {
        struct recurse : GiNaC::map_function {
            ex operator()(const ex& x) override { return merge_signed_powers(x); }
        } each;
        return e.map(each);
    }
    if (!is_a<GiNaC::mul>(e))
        return e;
    canonical_keys keys;
    struct power_of_sum {
        ex base, exponent;
        std::string key;
    };
    std::vector<power_of_sum> powers;
    GiNaC::exvector others;
    for (const ex& f : e) {
        const ex g = merge_signed_powers(f);
        const bool power = is_a<GiNaC::power>(g) && is_a<GiNaC::add>(g.op(0)) && is_a<GiNaC::numeric>(g.op(1));
        if (power || is_a<GiNaC::add>(g)) {
            const ex base = power ? g.op(0) : g, exponent = power ? g.op(1) : ex(1);
            powers.push_back({base, exponent, keys.sum(base).key});
        } else {
            others.push_back(g);
        }
    }
    ex result = GiNaC::mul(others);
    std::vector<bool> done(powers.size(), false);
    for (std::size_t i = 0; i < powers.size(); ++i) {
        if (done[i])
            continue;
        // The group of powers of ±base; the base that a root (a non-integer exponent) has.
        std::vector<std::size_t> group;
        ex base = powers[i].base;
        for (std::size_t j = i; j < powers.size(); ++j)
            if (!done[j] && powers[j].key == powers[i].key) {
                group.push_back(j);
                done[j] = true;
                if (!powers[j].exponent.info(GiNaC::info_flags::integer))
                    base = powers[j].base;
            }
        ex exponent = 0, sign = 1;
        bool mergeable = true;
        for (std::size_t j : group) {
            const bool same = (powers[j].base - base).expand().is_zero();
            if (!same && !powers[j].exponent.info(GiNaC::info_flags::integer))
                mergeable = false; // roots of both signs: leave them
            exponent += powers[j].exponent;
            if (!same && GiNaC::ex_to<GiNaC::numeric>(powers[j].exponent).is_odd())
                sign = -sign;
        }
        if (!mergeable || group.size() == 1) {
            for (std::size_t j : group)
                result *= GiNaC::pow(powers[j].base, powers[j].exponent);
            continue;
        }
        result *= sign * GiNaC::pow(base, exponent);
    }
    return result;
}

std::string canonical_key(const ex& e)
{
    canonical_keys keys;
    return keys.key(e);
}

bool canonical_less(const ex& a, const ex& b)
{
    canonical_keys keys;
    return keys.key(a) < keys.key(b);
}

} // namespace lagrange
