// SPDX-License-Identifier: GPL-2.0-or-later
/** @file sorted_terms.cpp
 *  The sorted-term core (see sorted_terms.h). */
#include "algebra/sorted_terms.h"

#include "algebra/canonical_order.h"

#include <algorithm>
#include <sstream>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::is_a;
using GiNaC::numeric;

void split_into(const ex& e, term_factors& parts)
{
    if (is_a<numeric>(e)) {
        parts.coefficient *= GiNaC::ex_to<numeric>(e);
    } else if (is_a<GiNaC::mul>(e)) {
        for (const ex& factor : e)
            split_into(factor, parts);
    } else {
        parts.factors.push_back(e);
    }
}

} // namespace

term_factors split_term(const ex& term)
{
    term_factors parts;
    split_into(term, parts);
    return parts;
}

numeric exponent_in(const ex& e, const ex& s)
{
    if (e.is_equal(s))
        return 1;
    if (is_a<GiNaC::power>(e)) {
        if (!is_a<numeric>(e.op(1)) || !GiNaC::ex_to<numeric>(e.op(1)).is_real())
            return 0;
        return exponent_in(e.op(0), s) * GiNaC::ex_to<numeric>(e.op(1));
    }
    if (is_a<GiNaC::mul>(e)) {
        numeric total = 0;
        for (const ex& factor : e)
            total += exponent_in(factor, s);
        return total;
    }
    if (is_a<GiNaC::add>(e)) {
        numeric highest = 0;
        bool first = true;
        for (const ex& term : e) {
            numeric k = exponent_in(term, s);
            if (first || k > highest)
                highest = k;
            first = false;
        }
        return highest;
    }
    return 0;
}

term_degrees degrees_of(const ex& term, const term_order& order)
{
    term_degrees d;
    for (const auto& group : order.groups) {
        numeric degree = 0;
        for (const ex& s : group) {
            d.exponents.push_back(exponent_in(term, s));
            degree += d.exponents.back();
        }
        d.degrees.push_back(degree);
    }
    return d;
}

int compare_degrees(const term_degrees& a, const term_degrees& b)
{
    for (std::size_t g = 0; g < a.degrees.size(); ++g)
        if (a.degrees[g] != b.degrees[g])
            return a.degrees[g] > b.degrees[g] ? -1 : 1;
    for (std::size_t k = 0; k < a.exponents.size(); ++k)
        if (a.exponents[k] != b.exponents[k])
            return a.exponents[k] > b.exponents[k] ? -1 : 1;
    return 0;
}

std::vector<std::string> sorted_operands(const ex& e, const std::function<std::string(const ex&)>& text)
{
    std::vector<std::string> parts;
    parts.reserve(e.nops());
    for (const ex& operand : e)
        parts.push_back(text(operand));
    std::sort(parts.begin(), parts.end());
    return parts;
}

std::string message_text(const ex& e)
{
    auto wrapped = [](const ex& x) {
        std::string text = message_text(x);
        return is_a<GiNaC::add>(x) || is_a<GiNaC::mul>(x) ? "(" + text + ")" : text;
    };
    if (is_a<GiNaC::mul>(e) && e.op(e.nops() - 1).is_equal(-1)) { // −x, not -1*x
        ex positive = -e;
        return "-" + (is_a<GiNaC::add>(positive) ? "(" + message_text(positive) + ")" : message_text(positive));
    }
    if (is_a<GiNaC::add>(e) || is_a<GiNaC::mul>(e)) {
        const bool sum = is_a<GiNaC::add>(e);
        std::vector<std::string> parts =
            sum ? sorted_operands(e, [](const ex& x) { return message_text(x); }) : sorted_operands(e, wrapped);
        std::string out;
        if (!sum && parts.size() > 1 && parts.front() == "-1") { // -E*q0, not -1*E*q0
            parts.erase(parts.begin());
            out = "-";
        }
        for (const std::string& part : parts)
            out += (out.empty() || out == "-" ? "" : (sum ? (part.rfind('-', 0) == 0 ? "" : "+") : "*")) + part;
        return out;
    }
    if (is_a<GiNaC::power>(e))
        return wrapped(e.op(0)) + "^" + wrapped(e.op(1));
    if (is_a<GiNaC::function>(e)) {
        std::string out = GiNaC::ex_to<GiNaC::function>(e).get_name() + "(";
        for (std::size_t i = 0; i < e.nops(); ++i)
            out += (i ? "," : "") + message_text(e.op(i));
        return out + ")";
    }
    std::ostringstream out;
    out << e;
    return out.str();
}

GiNaC::exvector sorted_factors(const ex& product)
{
    // By keys that do not depend on the sign factor() gave each factor ((x − a) or (a − x)),
    // a choice GiNaC makes by its hash order.
    canonical_keys keys;
    std::vector<std::pair<std::string, ex>> keyed;
    for (const ex& f : is_a<GiNaC::mul>(product) ? GiNaC::exvector(product.begin(), product.end())
                                                 : GiNaC::exvector{product})
        keyed.emplace_back(keys.factor(f).key, f);
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    GiNaC::exvector factors;
    for (const auto& [key, f] : keyed)
        factors.push_back(f);
    return factors;
}

} // namespace lagrange
