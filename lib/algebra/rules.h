// SPDX-License-Identifier: GPL-2.0-or-later
/** @file rules.h
 *  Rewrite rules (`LHS -> RHS`, wildcards $0 $1 ...) and the matcher that applies them
 *  independently of GiNaC's term order. */
#pragma once

#include "algebra/expression.h"
#include "core/rule.h"

#include <ginac/ginac.h>

#include <memory>
#include <string>
#include <vector>

namespace lagrange {

/// A rules file compiled into the program (generated from rules/*.rules).
struct embedded_rule_file {
    const char* name;
    const char* text;
};
const std::vector<embedded_rule_file>& embedded_rule_files();

/// Matches `pattern` against `e`, extending `bindings` (wildcard -> expression).
/// Sums and products match independently of operand order: a sum pattern of k
/// terms matches k of the terms of a sum, and a product pattern's single
/// unbound wildcard factor takes whatever the other factors leave.
bool match(const GiNaC::ex& e, const GiNaC::ex& pattern, GiNaC::exmap& bindings);

/// Applies the rules everywhere in `e`, innermost first, until nothing changes
/// or `max_passes` passes have run.
GiNaC::ex rewrite(const GiNaC::ex& e, const std::vector<rewrite_rule>& rules, int max_passes = 16);

/// Tells whether any rule may fire in expanded sums of products of atoms, and
/// remembers what it found for each atom, so that many sums over the same atoms
/// (the equations of one system) cost little more than one.
class rewrite_screen {
public:
    explicit rewrite_screen(const std::vector<rewrite_rule>& rules);
    ~rewrite_screen();
    rewrite_screen(const rewrite_screen&) = delete;
    rewrite_screen& operator=(const rewrite_screen&) = delete;

    /// False only if no rule can fire anywhere in the sum of the terms
    /// c_t · Π atoms[a] over a in term_atoms[t] (c_t numbers; atoms are powers of
    /// symbols and functions, each a distinct object): then rewrite() returns that sum
    /// unchanged. It looks at each distinct atom once, and at each term's atom list.
    bool may_fire(const GiNaC::exvector& atoms, const std::vector<std::vector<std::size_t>>& term_atoms);

private:
    struct state;
    std::unique_ptr<state> state_;
};

} // namespace lagrange
