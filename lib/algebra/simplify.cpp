// SPDX-License-Identifier: GPL-2.0-or-later
/** @file simplify.cpp
 *  The compact grouping by velocities and accelerations (each coefficient factored),
 *  and the simplifier that chains the canonical form (trig_canonical.cpp), the
 *  rewrite rules and that grouping. */
#include "algebra/simplify.h"

#include "algebra/expression.h"
#include "algebra/factor.h"
#include "algebra/harmonic.h"
#include "algebra/canonical_order.h"
#include "algebra/pythagorean.h"

#include <cln/integer.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::exmap;
using GiNaC::exvector;
using GiNaC::numeric;

/// Largest number of terms for which a coefficient is handed to GiNaC's factor().
constexpr size_t factor_term_limit = 12;

/// A monomial as base -> exponent (numeric coefficient dropped).
using monomial_exponents = std::map<ex, numeric, GiNaC::ex_is_less>;

monomial_exponents exponents_of(const ex& term)
{
    monomial_exponents exponents;
    for (const ex& factor : factors_of(term)) {
        if (ex_kind_of(factor) == ex_kind::number)
            continue;
        if (ex_kind_of(factor) == ex_kind::power && ex_kind_of(factor.op(1)) == ex_kind::number)
            exponents[factor.op(0)] += GiNaC::ex_to<numeric>(factor.op(1));
        else
            exponents[factor] += 1;
    }
    return exponents;
}

numeric coefficient_of(const ex& term)
{
    numeric c = 1;
    for (const ex& factor : factors_of(term))
        if (ex_kind_of(factor) == ex_kind::number)
            c *= GiNaC::ex_to<numeric>(factor);
    return c;
}

/// True if every term is a number times at most one non-numeric factor of degree 1.
bool is_linear(const exvector& terms)
{
    for (const ex& term : terms) {
        const monomial_exponents exponents = exponents_of(term);
        if (exponents.size() > 1 || (exponents.size() == 1 && !exponents.begin()->second.is_equal(1)))
            return false;
    }
    return true;
}

/// GiNaC's factor() with the non-polynomial parts (cos(theta - phi), sqrt(M), ...)
/// replaced by temporary symbols, which factor() would otherwise refuse to look into.
ex factor_polynomial(const ex& p)
{
    exmap replacements;
    const ex rational = p.to_rational(replacements);
    const ex parts = rational.numer_denom();
    const ex factored = factor_if_quick(parts.op(0)) / factor_if_quick(parts.op(1));
    return factored.subs(replacements, GiNaC::subs_options::no_pattern);
}

/// The factors of a compact form of the expanded sum `c`: its numeric and monomial
/// content, then the remaining sum, factored if it is small and not linear.
exvector compact_factors(const ex& c)
{
    const exvector terms = terms_of(c);
    if (terms.size() <= 1)
        return {c};
    if (has_compound_denominator(c))
        return {factor_polynomial(c)};

    numeric numerator_gcd = 0;
    numeric denominator_lcm = 1;
    bool all_negative = true;
    monomial_exponents common;
    for (size_t i = 0; i < terms.size(); ++i) {
        const numeric coefficient = coefficient_of(terms[i]);
        numerator_gcd = GiNaC::gcd(numerator_gcd, coefficient.numer());
        denominator_lcm = GiNaC::lcm(denominator_lcm, coefficient.denom());
        all_negative = all_negative && coefficient.is_negative();
        const monomial_exponents exponents = exponents_of(terms[i]);
        if (i == 0) {
            common = exponents;
            continue;
        }
        for (auto it = common.begin(); it != common.end();) {
            auto found = exponents.find(it->first);
            if (found == exponents.end() || !found->second.is_rational() || !it->second.is_rational()) {
                it = common.erase(it);
                continue;
            }
            if (found->second < it->second)
                it->second = found->second;
            ++it;
        }
    }
    numeric content = numerator_gcd / denominator_lcm;
    if (all_negative)
        content = -content;
    exvector content_factors;
    for (const auto& [base, exponent] : common)
        if (!exponent.is_zero())
            content_factors.push_back(GiNaC::pow(base, exponent));
    const ex content_monomial = product_of(content_factors);

    exvector cofactor_terms;
    cofactor_terms.reserve(terms.size());
    for (const ex& term : terms)
        cofactor_terms.push_back((term / content_monomial) * content.inverse());
    ex cofactor = sum_of(cofactor_terms);
    if (cofactor_terms.size() <= factor_term_limit && !is_linear(cofactor_terms))
        cofactor = factor_polynomial(cofactor);

    exvector result = content_factors;
    if (!content.is_equal(numeric(1)))
        result.push_back(content);
    for (const ex& factor : factors_of(cofactor))
        result.push_back(factor);
    return result;
}

struct key_hash {
    size_t operator()(const std::vector<std::int32_t>& key) const
    {
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (std::int32_t x : key) {
            h ^= static_cast<std::uint32_t>(x);
            h *= 0xff51afd7ed558ccdULL;
            h ^= h >> 32;
        }
        return static_cast<size_t>(h);
    }
};

/// The terms of one group of collect_compact over a harmonic polynomial: indices of
/// the polynomial's terms that share their monomial in the variables and harmonics.
struct harmonic_group {
    std::vector<size_t> terms;
};

/// compact_factors for a coefficient given as terms of a harmonic polynomial whose
/// exponents count only for the symbols not in `variable`: the same factors, with
/// the content taken out without building the expanded coefficient first.
exvector compact_factors(const harmonic_polynomial& p, const std::vector<size_t>& terms,
                         const std::vector<bool>& variable)
{
    const harmonic_space& space = p.space();
    const size_t symbols = p.symbol_count();
    auto term_ex = [&](size_t i, const cln::cl_RA& divisor, const std::vector<std::int32_t>& subtracted) {
        const harmonic_term t = p.term(i);
        exvector factors;
        const cln::cl_RA c = *t.coefficient / divisor;
        if (!cln::equal(c, cln::cl_RA(1)))
            factors.push_back(harmonic_space::number(c));
        for (size_t s = 0; s < symbols; ++s) {
            if (variable[s])
                continue;
            const std::int32_t e = t.exponents[s] - subtracted[s];
            if (e != 0)
                factors.push_back(space.power(s, e));
        }
        return product_of(factors);
    };
    const std::vector<std::int32_t> none(symbols, 0);
    if (terms.size() == 1)
        return {term_ex(terms.front(), 1, none)};

    cln::cl_I numerator_gcd = 0;
    cln::cl_I denominator_lcm = 1;
    bool all_negative = true;
    std::vector<std::int32_t> common(symbols, 0);
    std::vector<bool> in_all(symbols, true);
    for (size_t k = 0; k < terms.size(); ++k) {
        const harmonic_term t = p.term(terms[k]);
        numerator_gcd = cln::gcd(numerator_gcd, cln::numerator(*t.coefficient));
        denominator_lcm = cln::lcm(denominator_lcm, cln::denominator(*t.coefficient));
        all_negative = all_negative && cln::minusp(*t.coefficient);
        for (size_t s = 0; s < symbols; ++s) {
            if (variable[s] || !in_all[s])
                continue;
            const std::int32_t e = t.exponents[s];
            if (e == 0) {
                in_all[s] = false;
                common[s] = 0;
            } else if (k == 0 || e < common[s]) {
                common[s] = e;
            }
        }
    }
    cln::cl_RA content = numerator_gcd / denominator_lcm;
    if (all_negative)
        content = -content;
    exvector content_factors;
    for (size_t s = 0; s < symbols; ++s)
        if (!variable[s] && in_all[s] && common[s] != 0)
            content_factors.push_back(space.power(s, common[s]));
        else
            common[s] = 0;

    exvector cofactor_terms;
    cofactor_terms.reserve(terms.size());
    bool linear = true;
    for (size_t i : terms) {
        cofactor_terms.push_back(term_ex(i, content, common));
        const harmonic_term t = p.term(i);
        int degree_symbols = 0;
        for (size_t s = 0; s < symbols && linear; ++s) {
            if (variable[s])
                continue;
            const std::int32_t e = t.exponents[s] - common[s];
            if (e != 0 && (e != 1 || ++degree_symbols > 1))
                linear = false;
        }
    }
    ex cofactor = sum_of(cofactor_terms);
    if (cofactor_terms.size() <= factor_term_limit && !linear)
        cofactor = factor_polynomial(cofactor);

    exvector result = content_factors;
    if (!cln::equal(content, cln::cl_RA(1)))
        result.push_back(harmonic_space::number(content));
    for (const ex& factor : factors_of(cofactor))
        result.push_back(factor);
    return result;
}

/// collect_compact over a harmonic polynomial;
/// nullopt if a variable is not a symbol (then only the general path applies).
std::optional<ex> collect_compact_harmonic(const harmonic_polynomial& p, const GiNaC::lst& variables,
                                           const GiNaC::lst& angles)
{
    const harmonic_space& space = p.space();
    const size_t symbols = p.symbol_count();
    std::vector<bool> variable(symbols, false);
    for (const ex& v : variables) {
        if (ex_kind_of(v) != ex_kind::symbol)
            return std::nullopt;
        if (auto index = space.index_of(v); index && *index < symbols)
            variable[*index] = true;
    }
    // A harmonic is an angle function for collect_compact if one of `angles` is in its argument.
    std::vector<bool> listed_angle(space.angle_count(), false);
    for (const ex& q : angles)
        if (auto index = space.index_of(q); index && *index < space.angle_count())
            listed_angle[*index] = true;
    auto is_angle_function = [&](const harmonic_term& t) {
        if (t.kind == wave::none)
            return false;
        for (size_t i = 0; i < space.angle_count(); ++i)
            if (t.frequency[i] != 0 && listed_angle[i])
                return true;
        return false;
    };

    // Groups keyed by the monomial: harmonic (if an angle function) and variable exponents.
    std::unordered_map<std::vector<std::int32_t>, size_t, key_hash> index;
    std::vector<std::vector<std::int32_t>> keys;
    std::vector<harmonic_group> groups;
    std::vector<bool> harmonic_in_monomial;
    std::vector<std::int32_t> key;
    for (size_t i = 0; i < p.size(); ++i) {
        const harmonic_term t = p.term(i);
        const bool angle_function = is_angle_function(t);
        if (t.kind != wave::none && !angle_function)
            return std::nullopt; // a harmonic in a coefficient: only the general path handles it
        key.assign(1, angle_function ? static_cast<std::int32_t>(t.kind) : 0);
        for (size_t a = 0; a < space.angle_count(); ++a)
            key.push_back(angle_function ? t.frequency[a] : 0);
        for (size_t s = 0; s < symbols; ++s)
            key.push_back(variable[s] ? t.exponents[s] : 0);
        auto [it, inserted] = index.emplace(key, groups.size());
        if (inserted) {
            groups.emplace_back();
            keys.push_back(key);
            harmonic_in_monomial.push_back(angle_function);
        }
        groups[it->second].terms.push_back(i);
    }
    exvector result;
    result.reserve(groups.size());
    for (size_t g = 0; g < groups.size(); ++g) {
        exvector factors = compact_factors(p, groups[g].terms, variable);
        exvector monomial;
        const harmonic_term t = p.term(groups[g].terms.front());
        for (size_t s = 0; s < symbols; ++s)
            if (variable[s] && t.exponents[s] != 0)
                monomial.push_back(space.power(s, t.exponents[s]));
        if (harmonic_in_monomial[g])
            monomial.push_back(space.wave_function(t.kind, t.frequency));
        factors.push_back(product_of(monomial));
        result.push_back(product_of(factors));
    }
    return sum_of(result);
}

} // namespace

GiNaC::ex collect_compact(const GiNaC::ex& e, const GiNaC::lst& variables, const GiNaC::lst& angles)
{
    const std::set<ex, GiNaC::ex_is_less> variable_set(variables.begin(), variables.end());
    auto is_angle_function = [&](const ex& f) {
        if (ex_kind_of(f) != ex_kind::function)
            return false;
        for (const ex& angle : angles)
            if (f.has(angle))
                return true;
        return false;
    };
    auto is_variable_power = [&](const ex& f) {
        if (variable_set.count(f) != 0 || is_angle_function(f))
            return true;
        return (ex_kind_of(f) == ex_kind::power) &&
               (variable_set.count(f.op(0)) != 0 || is_angle_function(f.op(0))) &&
               f.op(1).info(GiNaC::info_flags::integer);
    };
    std::map<ex, exvector, GiNaC::ex_is_less> by_monomial;
    for (const ex& term : terms_of(e.expand())) {
        exvector monomial;
        exvector coefficient;
        for (const ex& factor : factors_of(term))
            (is_variable_power(factor) ? monomial : coefficient).push_back(factor);
        by_monomial[product_of(monomial)].push_back(product_of(coefficient));
    }
    exvector result;
    for (const auto& [monomial, coefficient_terms] : by_monomial) {
        const ex coefficient = sum_of(coefficient_terms);
        if (coefficient.is_zero())
            continue;
        exvector factors = compact_factors(coefficient);
        factors.push_back(monomial);
        result.push_back(product_of(factors));
    }
    return sum_of(result);
}

GiNaC::ex collect_compact(const harmonic_polynomial& p, const GiNaC::lst& variables, const GiNaC::lst& angles)
{
    if (std::optional<ex> grouped = collect_compact_harmonic(p, variables, angles))
        return *grouped;
    return collect_compact(to_ex(p), variables, angles);
}

namespace {

/// The bases of odd half-integer powers in e (the ρ² + z² of (ρ² + z²)^(3/2) and of its
/// square root), in canonical order.
exvector half_power_bases(const ex& e)
{
    exvector bases;
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i) {
        if (!GiNaC::is_a<GiNaC::power>(*i))
            continue;
        const ex k = i->op(1);
        if (!k.info(GiNaC::info_flags::rational) || k.info(GiNaC::info_flags::integer) ||
            !(2 * k).info(GiNaC::info_flags::integer) || i->op(0).info(GiNaC::info_flags::numeric))
            continue;
        if (std::none_of(bases.begin(), bases.end(), [&](const ex& b) { return b.is_equal(i->op(0)); }))
            bases.push_back(i->op(0));
    }
    std::sort(bases.begin(), bases.end(), canonical_less);
    return bases;
}

/// f(e) with each half power b^(k/2) written as s^k of one symbol s = √b while f runs.
/// GiNaC's normal() takes b^(3/2) and b^(1/2) as unrelated atoms and, by hash order, keeps
/// one form or the other, so the result changed from run to run; through s it is one.
template <typename F>
ex through_square_roots(const ex& e, F f)
{
    const exvector bases = half_power_bases(e);
    if (bases.empty())
        return f(e);
    ex x = e;
    GiNaC::exmap back;
    for (std::size_t k = 0; k < bases.size(); ++k) {
        const GiNaC::realsymbol root("sqrt_" + std::to_string(k));
        x = x.subs(GiNaC::pow(bases[k], GiNaC::wild(0)) == GiNaC::pow(root, 2 * GiNaC::wild(0)));
        back[root] = GiNaC::sqrt(bases[k]);
    }
    return f(x).subs(back);
}

} // namespace

// Sines of parameter angles (th0) are atoms of the canonical form: sin² th0 + cos² th0 = 1
// is applied after it, where it shortens a sum, and again after the grouping, which can
// gather such a sum into one coefficient.
GiNaC::ex simplifier::canonical(const GiNaC::ex& e) const
{
    return through_square_roots(e, [&](const ex& x) { return pythagorean(trig_canonical(x, angles)); });
}

GiNaC::ex simplifier::compact(const GiNaC::ex& canonical_form) const
{
    return through_square_roots(canonical_form, [&](const ex& x) {
        return pythagorean(collect_compact(rewrite(x, rules), variables, angles));
    });
}

GiNaC::ex simplifier::compact(const harmonic_polynomial& canonical_form) const
{
    rewrite_screen screen(rules);
    return compact_harmonic(canonical_form, screen);
}

std::vector<GiNaC::ex> simplifier::compact(const std::vector<harmonic_polynomial>& canonical_forms) const
{
    rewrite_screen screen(rules);
    std::vector<GiNaC::ex> compact_forms;
    compact_forms.reserve(canonical_forms.size());
    for (const harmonic_polynomial& p : canonical_forms)
        compact_forms.push_back(compact_harmonic(p, screen));
    return compact_forms;
}

GiNaC::ex simplifier::compact_harmonic(const harmonic_polynomial& canonical_form, rewrite_screen& screen) const
{
    // The rewrite changes nothing if no rule can fire at any node: then group the
    // polynomial directly, without building its expanded expression.
    const harmonic_space& space = canonical_form.space();
    std::unordered_map<const GiNaC::basic*, size_t> index;
    exvector atoms;
    std::vector<std::vector<size_t>> term_atoms(canonical_form.size());
    auto note = [&](const ex& atom, std::vector<size_t>& term) {
        auto [it, inserted] = index.emplace(&GiNaC::ex_to<GiNaC::basic>(atom), atoms.size());
        if (inserted)
            atoms.push_back(atom);
        term.push_back(it->second);
    };
    for (size_t i = 0; i < canonical_form.size(); ++i) {
        const harmonic_term t = canonical_form.term(i);
        for (size_t s = 0; s < canonical_form.symbol_count(); ++s)
            if (t.exponents[s] != 0)
                note(space.power(s, t.exponents[s]), term_atoms[i]);
        if (t.kind != wave::none)
            note(space.wave_function(t.kind, t.frequency), term_atoms[i]);
    }
    if (!screen.may_fire(atoms, term_atoms))
        if (std::optional<ex> grouped = collect_compact_harmonic(canonical_form, variables, angles))
            return pythagorean(*grouped);
    return compact(to_ex(canonical_form));
}

GiNaC::ex simplifier::operator()(const GiNaC::ex& e) const { return compact(canonical(e)); }

} // namespace lagrange
