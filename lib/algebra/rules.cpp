// SPDX-License-Identifier: GPL-2.0-or-later
/** @file rules.cpp
 *  The rewriter: applies rules everywhere in an expression, innermost first, until
 *  nothing changes, with cheap prechecks that skip the matcher (match.cpp) where a
 *  rule cannot fire. */
#include "algebra/rules.h"

#include "algebra/budget.h"
#include "algebra/expression.h"
#include "algebra/match.h"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::exmap;
using GiNaC::exvector;
using GiNaC::numeric;

/// How many times the rules may fire at one node within one pass.
constexpr int applications_per_node = 64;

/// A cheap necessary condition for `pattern` to match at the top of `e`.
bool may_match(const ex& e, const ex& pattern)
{
    if (ex_kind_of(pattern) == ex_kind::wildcard || ex_kind_of(pattern) == ex_kind::product)
        return true;
    if (ex_kind_of(pattern) == ex_kind::sum)
        return ex_kind_of(e) == ex_kind::sum && e.nops() >= pattern.nops();
    if (ex_kind_of(pattern) == ex_kind::function)
        return ex_kind_of(e) == ex_kind::function &&
               GiNaC::ex_to<GiNaC::function>(e).get_serial() ==
                   GiNaC::ex_to<GiNaC::function>(pattern).get_serial();
    const GiNaC::basic &object = GiNaC::ex_to<GiNaC::basic>(e), &model = GiNaC::ex_to<GiNaC::basic>(pattern);
    return typeid(object) == typeid(model);
}

/// A cheap necessary condition for `rule` to match at the top of an expression,
/// beyond may_match: it follows the pattern into products, powers and function
/// arguments without binding wildcards, and so rejects, for instance, a sum pattern
/// whose first structured term needs a factor cos(2*$0) in a target without one.
/// Where it cannot tell, it says "may match"; the matcher then decides as before.
class rule_precheck {
public:
    explicit rule_precheck(const rewrite_rule& rule) : pattern_(rule.pattern)
    {
        count_wildcards(pattern_);
        if (ex_kind_of(pattern_) == ex_kind::sum) {
            // The sum matcher starts with a pattern term free of wildcards if there is
            // one (then nothing is known), else with the first structured term, which
            // must match a single target term while no wildcard is bound.
            bool free_term = false;
            for (size_t i = 0; i < pattern_.nops(); ++i) {
                const ex& term = pattern_.op(i);
                if (!has_wildcard(term))
                    free_term = true;
                else if (ex_kind_of(term) != ex_kind::wildcard && first_structured_.is_zero())
                    first_structured_ = term;
            }
            if (free_term)
                first_structured_ = 0;
        }
    }

    /// False only if the rule cannot match at the top of `e`.
    bool may_apply(const ex& e)
    {
        if (ex_kind_of(pattern_) == ex_kind::sum && ex_kind_of(e) == ex_kind::sum) {
            if (first_structured_.is_zero())
                return true;
            for (size_t i = 0; i < e.nops(); ++i)
                if (may_match_node(e.op(i), first_structured_, false))
                    return true;
            return false;
        }
        return may_match_node(e, pattern_, false);
    }

    /// A pattern node that some node of the target must be able to match for the rule to
    /// fire there (a function or power the pattern needs), or 0 if there is none to tell.
    ex requirement() const
    {
        return requirement_of(ex_kind_of(pattern_) == ex_kind::sum ? first_structured_ : pattern_);
    }

    /// True if the rule may apply at `e` or at a node below.
    bool may_apply_below(const ex& e)
    {
        if (may_match(e, pattern_) && may_apply(e))
            return true;
        for (size_t i = 0; i < e.nops(); ++i)
            if (may_apply_below(e.op(i)))
                return true;
        return false;
    }

    /// For a sum pattern: may_apply for a sum whose terms are numbers times products of
    /// `atoms` (indices per term in `term_atoms`).
    bool may_apply_to_sum_of(const exvector& atoms, const std::vector<std::vector<std::size_t>>& term_atoms)
    {
        if (first_structured_.is_zero())
            return true;
        const ex_kind kind = ex_kind_of(first_structured_);
        if (kind == ex_kind::function || kind == ex_kind::power) {
            // Only a term that is a single atom can be this node.
            for (const std::vector<std::size_t>& term : term_atoms)
                if (term.size() == 1 && may_match_node(atoms[term.front()], first_structured_, false))
                    return true;
            return false;
        }
        if (kind != ex_kind::product)
            return true;
        // Each structured factor needs its own factor of one term (see may_match_product).
        exvector structured;
        for (const ex& f : split_product(first_structured_).factors)
            if (ex_kind_of(f) != ex_kind::wildcard)
                structured.push_back(f);
        if (structured.empty() || structured.size() > 64)
            return true;
        std::vector<std::uint64_t> masks(atoms.size(), 0);
        for (size_t a = 0; a < atoms.size(); ++a) {
            auto known = masks_.find(&GiNaC::ex_to<GiNaC::basic>(atoms[a]));
            if (known != masks_.end()) {
                masks[a] = known->second.second;
                continue;
            }
            for (size_t j = 0; j < structured.size(); ++j)
                if (may_match_node(atoms[a], structured[j], false))
                    masks[a] |= std::uint64_t(1) << j;
            masks_.emplace(&GiNaC::ex_to<GiNaC::basic>(atoms[a]), std::make_pair(atoms[a], masks[a]));
        }
        const std::uint64_t all = structured.size() == 64 ? ~std::uint64_t(0)
                                                          : (std::uint64_t(1) << structured.size()) - 1;
        for (const std::vector<std::size_t>& term : term_atoms) {
            std::uint64_t covered = 0;
            size_t candidates = 0;
            for (std::size_t a : term) {
                covered |= masks[a];
                candidates += masks[a] != 0 ? 1 : 0;
            }
            if (covered == all && candidates >= structured.size())
                return true;
        }
        return false;
    }

    /// True if `e` or a subexpression may match requirement().
    bool found_in(const ex& e, const ex& required)
    {
        if (may_match_node(e, required, false))
            return true;
        for (size_t i = 0; i < e.nops(); ++i)
            if (found_in(e.op(i), required))
                return true;
        return false;
    }

private:
    static ex requirement_of(const ex& p)
    {
        if (p.is_zero() || !has_wildcard(p))
            return 0;
        switch (ex_kind_of(p)) {
        case ex_kind::function:
        case ex_kind::power:
            return p;
        case ex_kind::product:
            for (const ex& f : split_product(p).factors) {
                if (ex_kind_of(f) == ex_kind::wildcard)
                    continue;
                const ex r = requirement_of(f);
                if (!r.is_zero())
                    return r;
            }
            return 0;
        default:
            return 0;
        }
    }

    void count_wildcards(const ex& p)
    {
        if (ex_kind_of(p) == ex_kind::wildcard) {
            for (auto& [w, count] : wildcard_counts_)
                if (w.is_equal(p)) {
                    ++count;
                    return;
                }
            wildcard_counts_.emplace_back(p, 1);
            return;
        }
        for (size_t i = 0; i < p.nops(); ++i)
            count_wildcards(p.op(i));
    }

    bool used_once(const ex& w) const
    {
        for (const auto& [known, count] : wildcard_counts_)
            if (known.is_equal(w))
                return count == 1;
        return false;
    }

    /// A necessary condition for match_node(e, p) with any bindings.
    bool may_match_node(const ex& e, const ex& p, bool in_argument)
    {
        const ex_kind kind = ex_kind_of(p);
        if (kind == ex_kind::wildcard || !has_wildcard(p))
            return true;
        switch (kind) {
        case ex_kind::sum:
            return ex_kind_of(e) == ex_kind::sum;
        case ex_kind::power:
            return ex_kind_of(e) == ex_kind::power && may_match_node(e.op(0), p.op(0), in_argument) &&
                   may_match_node(e.op(1), p.op(1), in_argument);
        case ex_kind::function:
            if (ex_kind_of(e) != ex_kind::function ||
                GiNaC::ex_to<GiNaC::function>(e).get_serial() != GiNaC::ex_to<GiNaC::function>(p).get_serial() ||
                e.nops() != p.nops())
                return false;
            for (size_t i = 0; i < e.nops(); ++i)
                if (!may_match_node(e.op(i), p.op(i), true))
                    return false;
            return true;
        case ex_kind::product:
            return may_match_product(e, p, in_argument);
        default:
            return true;
        }
    }

    /// The product matcher gives each structured factor of the pattern its own factor
    /// of the target; inside an argument, a lone wildcard used nowhere else in the
    /// pattern must take a whole multiple (see product_matcher::match_wildcards).
    bool may_match_product(const ex& e, const ex& p, bool in_argument)
    {
        const product_parts pattern = split_product(p);
        const product_parts target = split_product(e);
        exvector structured;
        exvector wildcards;
        for (const ex& f : pattern.factors)
            (ex_kind_of(f) == ex_kind::wildcard ? wildcards : structured).push_back(f);
        if (structured.size() > target.factors.size())
            return false;
        if (!structured.empty()) {
            std::vector<bool> candidate(target.factors.size(), false);
            for (const ex& s : structured) {
                bool found = false;
                for (size_t i = 0; i < target.factors.size(); ++i)
                    if (may_match_node(target.factors[i], s, in_argument)) {
                        candidate[i] = true;
                        found = true;
                    }
                if (!found)
                    return false;
            }
            return static_cast<size_t>(std::count(candidate.begin(), candidate.end(), true)) >= structured.size();
        }
        if (!in_argument || wildcards.size() != 1 || !used_once(wildcards.front()))
            return true;
        return whole_multiple(e, p, target, pattern.coefficient);
    }

    /// What match_wildcards decides for a pattern c*$k ($k unbound) inside an argument.
    bool whole_multiple(const ex& e, const ex& p, const product_parts& target, const numeric& pattern_coefficient)
    {
        auto& bucket = multiples_[e.gethash()];
        for (const auto& [known, known_pattern, answer] : bucket)
            if (known_pattern.is_equal(p) && known.is_equal(e))
                return answer;
        exvector rest = target.factors;
        const numeric coefficient = target.coefficient / pattern_coefficient;
        if (!coefficient.is_equal(numeric(1)))
            rest.push_back(coefficient);
        const ex value = product_of(rest);
        const bool answer = !value.is_zero() && (coefficient_content(value).is_integer() ||
                                                 !coefficient_content(e).is_integer());
        bucket.emplace_back(e, p, answer);
        return answer;
    }

    ex pattern_;
    ex first_structured_ = 0;
    std::vector<std::pair<ex, int>> wildcard_counts_;
    std::unordered_map<unsigned, std::vector<std::tuple<ex, ex, bool>>> multiples_;
    std::unordered_map<const GiNaC::basic*, std::pair<ex, std::uint64_t>> masks_; ///< by atom object
};

/// Applies `rule` at the top of `e`; returns false if it does not match.
bool apply_rule(const ex& e, const rewrite_rule& rule, rule_precheck& precheck, ex& result)
{
    if (!may_match(e, rule.pattern) || !precheck.may_apply(e))
        return false;
    exmap bindings;
    std::vector<size_t> used_terms;
    if (!match_terms(e, rule.pattern, bindings, used_terms))
        return false;
    if (ex_kind_of(rule.pattern) == ex_kind::sum && ex_kind_of(e) == ex_kind::sum) {
        std::vector<bool> used(e.nops(), false);
        for (size_t i : used_terms)
            used[i] = true;
        exvector rest;
        for (size_t i = 0; i < e.nops(); ++i)
            if (!used[i])
                rest.push_back(e.op(i));
        rest.push_back(rule.replacement.subs(bindings, GiNaC::subs_options::no_pattern));
        result = sum_of(rest);
    } else {
        result = rule.replacement.subs(bindings, GiNaC::subs_options::no_pattern);
    }
    return !result.is_equal(e);
}

/// Hands out precomputed operands, in order, to GiNaC's map().
class replace_operands : public GiNaC::map_function {
public:
    explicit replace_operands(const exvector& operands) : operands_(operands) {}
    ex operator()(const ex&) override { return operands_.at(next_++); }

private:
    const exvector& operands_;
    size_t next_ = 0;
};

/// One bottom-up pass of the rules over an expression. GiNaC's map() rebuilds every
/// sum and product it visits; this rebuilds only what changed.
class rewrite_pass {
public:
    rewrite_pass(const std::vector<rewrite_rule>& rules, std::vector<rule_precheck>& prechecks)
        : rules_(rules), prechecks_(prechecks)
    {
    }

    ex operator()(const ex& e)
    {
        bool node_changed = false;
        ex x = visit(e, node_changed);
        changed = changed || node_changed;
        return x;
    }

    bool changed = false;

private:
    ex visit(const ex& e, bool& node_changed)
    {
        ex x = e;
        if (e.nops() > 0 && ex_kind_of(e) != ex_kind::number) {
            exvector operands;
            operands.reserve(e.nops());
            bool operands_changed = false;
            for (size_t i = 0; i < e.nops(); ++i)
                operands.push_back(visit(e.op(i), operands_changed));
            if (operands_changed) {
                node_changed = true;
                x = rebuild(e, operands);
            }
        }
        for (int applied = 0; applied < applications_per_node; ++applied) {
            bool fired = false;
            for (size_t r = 0; r < rules_.size(); ++r) {
                ex result;
                if (apply_rule(x, rules_[r], prechecks_[r], result)) {
                    x = result;
                    fired = true;
                    node_changed = true;
                    break;
                }
            }
            if (!fired)
                break;
        }
        return x;
    }

    static ex rebuild(const ex& e, const exvector& operands)
    {
        switch (ex_kind_of(e)) {
        case ex_kind::sum:
            return sum_of(operands);
        case ex_kind::product:
            return product_of(operands);
        case ex_kind::power:
            return GiNaC::pow(operands[0], operands[1]);
        default: {
            replace_operands replacer(operands);
            return e.map(replacer);
        }
        }
    }

    const std::vector<rewrite_rule>& rules_;
    std::vector<rule_precheck>& prechecks_;
};

} // namespace

struct rewrite_screen::state {
    /// What one rule needs, and what is known about atoms (by object; the atoms are kept).
    struct rule_state {
        explicit rule_state(const rewrite_rule& rule)
            : precheck(rule), is_sum(ex_kind_of(rule.pattern) == ex_kind::sum), required(precheck.requirement())
        {
        }
        rule_precheck precheck;
        bool is_sum;
        ex required;
        std::unordered_map<const GiNaC::basic*, std::pair<ex, bool>> fires_inside;
        std::unordered_map<const GiNaC::basic*, std::pair<ex, bool>> has_required;
    };
    std::vector<rule_state> rules;
};

rewrite_screen::rewrite_screen(const std::vector<rewrite_rule>& rules) : state_(std::make_unique<state>())
{
    state_->rules.reserve(rules.size());
    for (const rewrite_rule& rule : rules)
        state_->rules.emplace_back(rule);
}

rewrite_screen::~rewrite_screen() = default;

bool rewrite_screen::may_fire(const GiNaC::exvector& atoms, const std::vector<std::vector<std::size_t>>& term_atoms)
{
    auto remembered = [](std::unordered_map<const GiNaC::basic*, std::pair<ex, bool>>& memo, const ex& atom,
                         auto&& decide) {
        const GiNaC::basic* key = &GiNaC::ex_to<GiNaC::basic>(atom);
        auto found = memo.find(key);
        if (found != memo.end())
            return found->second.second;
        const bool answer = decide();
        memo.emplace(key, std::make_pair(atom, answer));
        return answer;
    };
    for (state::rule_state& rule : state_->rules) {
        // Every node inside an atom.
        for (const ex& atom : atoms)
            if (remembered(rule.fires_inside, atom, [&] { return rule.precheck.may_apply_below(atom); }))
                return true;
        if (rule.is_sum) {
            // The sum itself (the terms, products of atoms, are no sums).
            if (term_atoms.size() >= 2 && rule.precheck.may_apply_to_sum_of(atoms, term_atoms))
                return true;
            continue;
        }
        // The terms and the sum: the pattern's function or power must be some atom's node.
        if (rule.required.is_zero())
            return true;
        for (const ex& atom : atoms)
            if (remembered(rule.has_required, atom, [&] { return rule.precheck.found_in(atom, rule.required); }))
                return true;
    }
    return false;
}

GiNaC::ex rewrite(const GiNaC::ex& e, const std::vector<rewrite_rule>& rules, int max_passes)
{
    if (rules.empty())
        return e;
    std::vector<rule_precheck> prechecks(rules.begin(), rules.end());
    ex x = e;
    for (int pass = 0; pass < max_passes; ++pass) {
        budget_check();
        rewrite_pass rewriter(rules, prechecks);
        x = rewriter(x);
        if (!rewriter.changed)
            break;
    }
    return x;
}

} // namespace lagrange
