// SPDX-License-Identifier: GPL-2.0-or-later
/** @file print.h
 *  Deterministic printing of expressions in three syntaxes. GiNaC's own term order
 *  can change from run to run; these printers order terms and factors themselves. */
#pragma once

#include "algebra/sorted_terms.h"
#include "core/number_text.h"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace lagrange {

enum class syntax {
    plain, ///< GiNaC's plain syntax (`^` powers, `q_dot`); used in JSON
    text,  ///< for people: Greek letters, dots over velocities (Unicode)
    latex, ///< LaTeX math: \dot{\theta}, \theta_{1}, no 1.5E-20 floats
};

/// Prints `e`. Factors of a product are ordered by their printed form (numeric
/// coefficient first); sums by `order`, then by printed form. Byte-identical
/// output for equal expressions, whatever GiNaC's internal order.
std::string print(const GiNaC::ex& e, syntax s, const term_order& order = {});

/// The terms of a sum in the order `print` uses, the first with a sign only if
/// negative ("-x"), the others with theirs in front ("+ y", "- z"); for breaking
/// long expressions across lines. Not for `plain`.
std::vector<std::string> print_terms(const GiNaC::ex& e, syntax s, const term_order& order = {});

/// How a symbol name prints: `theta_dot` -> "θ̇" / "\dot{\theta}", `theta1` ->
/// "θ1" / "\theta_{1}", `l_2` -> "l_{2}", `M` -> "M", `omega` -> "\omega".
std::string print_name(const std::string& name, syntax s);

} // namespace lagrange
