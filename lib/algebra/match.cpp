// SPDX-License-Identifier: GPL-2.0-or-later
/** @file match.cpp
 *  A pattern matcher for rewrite rules that does not depend on GiNaC's term order:
 *  sums match any k of their terms, products match their factors in any order, and
 *  a wildcard factor takes the rest of a product (numeric coefficient included). */
#include "algebra/match.h"

#include "algebra/expression.h"
#include "algebra/rules.h"

#include <algorithm>
#include <typeinfo>
#include <unordered_map>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::exmap;
using GiNaC::exvector;
using GiNaC::numeric;

/// How many elementary match attempts one top-level match may spend: the search over
/// assignments of pattern terms to target terms is exponential in the worst case.
constexpr long match_budget = 200000;

/// State of one top-level match: the remaining budget of attempts.
struct match_context {
    long budget = match_budget;
    bool in_argument = false; ///< matching inside a function's argument
};

bool is_leaf(const ex& e)
{
    const ex_kind kind = ex_kind_of(e);
    return kind == ex_kind::symbol || kind == ex_kind::number || kind == ex_kind::constant;
}

/// Equality by meaning: structurally equal, or the difference expands to zero.
bool same_value(const ex& a, const ex& b)
{
    if (a.is_equal(b))
        return true;
    if (is_leaf(a) && is_leaf(b))
        return false;
    return (a - b).expand().is_zero();
}

/// `e` expanded; a product of factors without sums is returned as it is.
ex expanded(const ex& e)
{
    if (ex_kind_of(e) == ex_kind::product) {
        for (size_t i = 0; i < e.nops(); ++i) {
            const ex& f = e.op(i);
            const ex_kind kind = ex_kind_of(f);
            if (kind == ex_kind::sum || kind == ex_kind::product ||
                (kind == ex_kind::power && ex_kind_of(f.op(0)) == ex_kind::sum))
                return e.expand();
        }
        return e;
    }
    const ex_kind kind = ex_kind_of(e);
    if (kind == ex_kind::symbol || kind == ex_kind::number || kind == ex_kind::function)
        return e;
    return e.expand();
}

/// True if `p` contains a wildcard that `bindings` does not bind.
bool has_unbound_wildcard(const ex& p, const exmap& bindings)
{
    if (ex_kind_of(p) == ex_kind::wildcard)
        return bindings.find(p) == bindings.end();
    for (size_t i = 0; i < p.nops(); ++i)
        if (has_unbound_wildcard(p.op(i), bindings))
            return true;
    return false;
}

bool match_node(const ex& e, const ex& pattern, exmap& bindings, match_context& context);

/// Matcher of a sum pattern against the terms of a target sum. In `partial` mode the
/// pattern's terms match distinct terms of the target and the others stay; otherwise
/// every target term must be used, and one unbound bare wildcard term, if the pattern
/// has one, takes the terms left over.
class sum_matcher {
public:
    sum_matcher(const ex& target, const ex& pattern, bool partial, match_context& context)
        : targets_(terms_of(target)), patterns_(terms_of(pattern)), partial_(partial),
          context_(context), target_used_(targets_.size(), false),
          pattern_done_(patterns_.size(), false)
    {
    }

    bool run(exmap& bindings) { return step(bindings); }

    /// Indices of the target terms that the pattern used (valid after a successful run).
    std::vector<size_t> used_terms() const
    {
        std::vector<size_t> used;
        for (size_t i = 0; i < target_used_.size(); ++i)
            if (target_used_[i])
                used.push_back(i);
        return used;
    }

private:
    /// The pattern term to match next: a fully bound one (cheapest), else one with
    /// structure, else a bare wildcard. Returns patterns_.size() when all are done.
    size_t next_pattern(const exmap& bindings) const
    {
        size_t structured = patterns_.size();
        size_t bare = patterns_.size();
        for (size_t j = 0; j < patterns_.size(); ++j) {
            if (pattern_done_[j])
                continue;
            if (!has_unbound_wildcard(patterns_[j], bindings))
                return j;
            if (ex_kind_of(patterns_[j]) == ex_kind::wildcard) {
                if (bare == patterns_.size())
                    bare = j;
            } else if (structured == patterns_.size()) {
                structured = j;
            }
        }
        return structured != patterns_.size() ? structured : bare;
    }

    size_t unused_count() const
    {
        return static_cast<size_t>(std::count(target_used_.begin(), target_used_.end(), false));
    }

    /// Finds a target term that is structurally equal to the expanded `part`.
    bool find_unused(const ex& part, size_t& index)
    {
        if (expanded_targets_.empty()) {
            for (size_t i = 0; i < targets_.size(); ++i) {
                expanded_targets_.push_back(expanded(targets_[i]));
                by_hash_.emplace(expanded_targets_.back().gethash(), i);
                if (!expanded_targets_.back().is_equal(targets_[i]))
                    unexpanded_targets_.push_back(i);
            }
        }
        auto range = by_hash_.equal_range(part.gethash());
        for (auto it = range.first; it != range.second; ++it)
            if (!target_used_[it->second] && expanded_targets_[it->second].is_equal(part)) {
                index = it->second;
                return true;
            }
        return false;
    }

    bool finish() const { return partial_ || unused_count() == 0; }

    bool step(exmap& bindings)
    {
        const size_t j = next_pattern(bindings);
        if (j == patterns_.size())
            return finish();
        if (--context_.budget < 0)
            return false;
        const ex& p = patterns_[j];
        pattern_done_[j] = true;
        bool found = false;
        if (!has_unbound_wildcard(p, bindings))
            found = step_bound(p, bindings);
        else if (ex_kind_of(p) == ex_kind::wildcard && !partial_ && last_pattern(j))
            found = step_absorb(p, bindings);
        else
            found = step_search(p, bindings);
        if (!found)
            pattern_done_[j] = false;
        return found;
    }

    bool last_pattern(size_t j) const
    {
        for (size_t k = 0; k < patterns_.size(); ++k)
            if (k != j && !pattern_done_[k])
                return false;
        return true;
    }

    /// A pattern term without unbound wildcards: its value (a sum, possibly) must be
    /// found term by term among the unused target terms, or be equal by meaning to one
    /// unused target term that is not in expanded form.
    bool step_bound(const ex& p, exmap& bindings)
    {
        const ex value = expanded(ex_kind_of(p) == ex_kind::wildcard
                                      ? bindings.find(p)->second
                                      : p.subs(bindings, GiNaC::subs_options::no_pattern));
        std::vector<size_t> taken;
        bool found = true;
        for (const ex& part : terms_of(value)) {
            size_t index = 0;
            if (!find_unused(part, index)) {
                found = false;
                break;
            }
            target_used_[index] = true;
            taken.push_back(index);
        }
        if (found && step(bindings))
            return true;
        for (size_t t : taken)
            target_used_[t] = false;
        for (size_t i : unexpanded_targets_) {
            if (target_used_[i] || !same_value(targets_[i], value))
                continue;
            target_used_[i] = true;
            if (step(bindings))
                return true;
            target_used_[i] = false;
        }
        return false;
    }

    /// The last pattern term, a bare unbound wildcard, takes all unused target terms.
    bool step_absorb(const ex& p, exmap& bindings)
    {
        exvector rest;
        for (size_t i = 0; i < targets_.size(); ++i)
            if (!target_used_[i])
                rest.push_back(targets_[i]);
        if (rest.empty())
            return false;
        bindings[p] = sum_of(rest);
        std::fill(target_used_.begin(), target_used_.end(), true);
        return true;
    }

    /// A pattern term with unbound wildcards: try it against every unused target term.
    bool step_search(const ex& p, exmap& bindings)
    {
        for (size_t i = 0; i < targets_.size(); ++i) {
            if (target_used_[i])
                continue;
            if (context_.budget < 0)
                return false;
            exmap saved = bindings;
            if (match_node(targets_[i], p, bindings, context_)) {
                target_used_[i] = true;
                if (step(bindings))
                    return true;
                target_used_[i] = false;
            }
            bindings = std::move(saved);
        }
        return false;
    }

    exvector targets_;
    exvector expanded_targets_;
    exvector patterns_;
    bool partial_;
    match_context& context_;
    std::vector<bool> target_used_;
    std::vector<bool> pattern_done_;
    std::unordered_multimap<unsigned, size_t> by_hash_;
    std::vector<size_t> unexpanded_targets_;
};

/// Matcher of a product pattern against a target's factors: structured pattern factors
/// match distinct target factors in any order, then the wildcard factors share what
/// is left (the last unbound one takes the rest, numeric coefficients included).
class product_matcher {
public:
    product_matcher(const ex& target, const ex& pattern, match_context& context)
        : target_(split_product(target)), context_(context), target_used_(target_.factors.size(), false),
          whole_target_(target)
    {
        const product_parts pattern_parts = split_product(pattern);
        pattern_coefficient_ = pattern_parts.coefficient;
        for (const ex& f : pattern_parts.factors)
            (ex_kind_of(f) == ex_kind::wildcard ? wildcards_ : structured_).push_back(f);
    }

    bool run(exmap& bindings) { return match_structured(0, bindings); }

private:
    bool match_structured(size_t j, exmap& bindings)
    {
        if (j == structured_.size())
            return match_wildcards(bindings);
        for (size_t i = 0; i < target_.factors.size(); ++i) {
            if (target_used_[i])
                continue;
            if (--context_.budget < 0)
                return false;
            exmap saved = bindings;
            if (match_node(target_.factors[i], structured_[j], bindings, context_)) {
                target_used_[i] = true;
                if (match_structured(j + 1, bindings))
                    return true;
                target_used_[i] = false;
            }
            bindings = std::move(saved);
        }
        return false;
    }

    /// Unbound wildcards but the last take single target factors; the last takes the
    /// remainder; bound wildcards must account for what they are bound to.
    bool match_wildcards(exmap& bindings)
    {
        exvector unbound;
        for (const ex& w : wildcards_)
            if (bindings.find(w) == bindings.end() && !contains(unbound, w))
                unbound.push_back(w);
        if (unbound.size() > 1) {
            // The first unbound wildcard takes one factor (which stays in the remainder,
            // divided out again below as a bound value).
            const ex w = unbound.front();
            for (size_t i = 0; i < target_.factors.size(); ++i) {
                if (target_used_[i] || contains(assigned_, target_.factors[i]))
                    continue;
                if (--context_.budget < 0)
                    return false;
                exmap saved = bindings;
                bindings[w] = target_.factors[i];
                assigned_.push_back(target_.factors[i]);
                if (match_wildcards(bindings))
                    return true;
                assigned_.pop_back();
                bindings = std::move(saved);
            }
            return false;
        }
        exvector rest;
        for (size_t i = 0; i < target_.factors.size(); ++i)
            if (!target_used_[i])
                rest.push_back(target_.factors[i]);
        const numeric coefficient = target_.coefficient / pattern_coefficient_;
        if (!coefficient.is_equal(numeric(1)))
            rest.push_back(coefficient);
        const ex remainder = product_of(rest);
        ex bound_product = 1;
        int absorbing_occurrences = 0;
        for (const ex& w : wildcards_) {
            if (!unbound.empty() && w.is_equal(unbound.front())) {
                ++absorbing_occurrences;
                continue;
            }
            bound_product *= bindings.find(w)->second;
        }
        if (unbound.empty())
            return same_value(remainder, bound_product);
        if (absorbing_occurrences > 1)
            return false;
        const ex value = bound_product.is_equal(ex(1)) ? remainder : remainder / bound_product;
        if (value.is_zero())
            return false;
        // Inside an argument a wildcard takes whole multiples only: `cos(2*$0)` matches
        // cos(2*theta) and cos(2*theta-2*phi), not cos(theta) with $0 = theta/2.
        if (context_.in_argument && !coefficient_content(value).is_integer() &&
            coefficient_content(whole_target_).is_integer())
            return false;
        bindings[unbound.front()] = value;
        return true;
    }

    static bool contains(const exvector& v, const ex& x)
    {
        return std::any_of(v.begin(), v.end(), [&](const ex& y) { return y.is_equal(x); });
    }

    product_parts target_;
    match_context& context_;
    std::vector<bool> target_used_;
    ex whole_target_;
    numeric pattern_coefficient_ = 1;
    exvector structured_;
    exvector wildcards_;
    exvector assigned_;
};

bool match_node(const ex& e, const ex& pattern, exmap& bindings, match_context& context)
{
    if (--context.budget < 0)
        return false;
    if (ex_kind_of(pattern) == ex_kind::wildcard) {
        auto it = bindings.find(pattern);
        if (it != bindings.end())
            return same_value(it->second, e);
        bindings[pattern] = e;
        return true;
    }
    if (!has_wildcard(pattern))
        return same_value(e, pattern);
    if (ex_kind_of(pattern) == ex_kind::sum) {
        if (ex_kind_of(e) != ex_kind::sum)
            return false;
        return sum_matcher(e, pattern, false, context).run(bindings);
    }
    if (ex_kind_of(pattern) == ex_kind::product)
        return product_matcher(e, pattern, context).run(bindings);
    if (ex_kind_of(pattern) == ex_kind::power) {
        if (ex_kind_of(e) != ex_kind::power)
            return false;
        return match_node(e.op(0), pattern.op(0), bindings, context) &&
               match_node(e.op(1), pattern.op(1), bindings, context);
    }
    if (ex_kind_of(pattern) == ex_kind::function) {
        if (ex_kind_of(e) != ex_kind::function ||
            GiNaC::ex_to<GiNaC::function>(e).get_serial() !=
                GiNaC::ex_to<GiNaC::function>(pattern).get_serial() ||
            e.nops() != pattern.nops())
            return false;
        const bool was_in_argument = context.in_argument;
        context.in_argument = true;
        bool matched = true;
        for (size_t i = 0; i < e.nops() && matched; ++i)
            matched = match_node(e.op(i), pattern.op(i), bindings, context);
        context.in_argument = was_in_argument;
        return matched;
    }
    // Any other container: same type and size, operands in order.
    const GiNaC::basic &object = GiNaC::ex_to<GiNaC::basic>(e), &model = GiNaC::ex_to<GiNaC::basic>(pattern);
    if (typeid(object) != typeid(model) || e.nops() != pattern.nops())
        return false;
    for (size_t i = 0; i < e.nops(); ++i)
        if (!match_node(e.op(i), pattern.op(i), bindings, context))
            return false;
    return true;
}

} // namespace

GiNaC::numeric coefficient_content(const GiNaC::ex& e)
{
    try {
        return e.expand().integer_content();
    } catch (const std::exception&) {
        return 1;
    }
}

bool has_wildcard(const GiNaC::ex& p)
{
    if (ex_kind_of(p) == ex_kind::wildcard)
        return true;
    for (size_t i = 0; i < p.nops(); ++i)
        if (has_wildcard(p.op(i)))
            return true;
    return false;
}

product_parts split_product(const GiNaC::ex& e)
{
    product_parts parts;
    if (ex_kind_of(e) == ex_kind::number) {
        parts.coefficient = GiNaC::ex_to<numeric>(e);
    } else if (ex_kind_of(e) == ex_kind::product) {
        for (size_t i = 0; i < e.nops(); ++i) {
            const ex& f = e.op(i);
            if (ex_kind_of(f) == ex_kind::number)
                parts.coefficient *= GiNaC::ex_to<numeric>(f);
            else
                parts.factors.push_back(f);
        }
    } else {
        parts.factors.push_back(e);
    }
    return parts;
}

bool match(const GiNaC::ex& e, const GiNaC::ex& pattern, GiNaC::exmap& bindings)
{
    match_context context;
    exmap trial = bindings;
    const bool matched = ex_kind_of(pattern) == ex_kind::sum && ex_kind_of(e) == ex_kind::sum
                             ? sum_matcher(e, pattern, true, context).run(trial)
                             : match_node(e, pattern, trial, context);
    if (matched)
        bindings = std::move(trial);
    return matched;
}

bool match_terms(const GiNaC::ex& e, const GiNaC::ex& pattern, GiNaC::exmap& bindings,
                 std::vector<std::size_t>& used_terms)
{
    match_context context;
    if (ex_kind_of(pattern) == ex_kind::sum && ex_kind_of(e) == ex_kind::sum) {
        sum_matcher matcher(e, pattern, true, context);
        if (!matcher.run(bindings))
            return false;
        used_terms = matcher.used_terms();
        return true;
    }
    return match_node(e, pattern, bindings, context);
}

} // namespace lagrange
