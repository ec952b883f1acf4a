// SPDX-License-Identifier: GPL-2.0-or-later
/** @file latex_blocks.h
 *  The building blocks of document.cpp shared with the report: LaTeX pieces and the
 *  term orders the printers use. */
#pragma once

#include "engine/analysis.h"
#include "output/print.h"

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

namespace lagrange {

/// Free text with LaTeX's special characters escaped (a few Unicode symbols become math,
/// and a number with an exponent, 1e-14, becomes 10^{-14}).
std::string latex_text(const std::string& text);

/// A rough width of LaTeX math in characters (for line breaking).
std::size_t latex_math_width(const std::string& latex);

/// A display `lhs relation terms rhs`: align* broken across lines, between terms or,
/// for a term wider than a line, at the signs of the sums inside its parentheses
/// (\right. … \left.), its long fractions and square roots first written with
/// parentheses ((a + b)^{1/2}); a matrix wider than the page as the names of its long
/// entries, each then on rows of its own. Never scaled: every formula is at the body size.
std::string latex_equation(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs,
                           const std::string& relation = "=");

/// One row of a group of related equations.
struct latex_row {
    std::string lhs;
    std::vector<std::string> terms;
    std::string rhs;
    std::string relation = "=";
};

/// Related equations in one align*, aligned on their relation, rows apart by 4pt.
/// `before` goes before the display.
std::string latex_equations(const std::vector<latex_row>& rows, const std::string& before = "");

/// A pmatrix of the entries, printed deterministically.
std::string latex_matrix(const GiNaC::matrix& m);

/// Terms ordered by the coordinates' velocities.
term_order velocity_order(const model& scene);
/// Terms ordered by the accelerations, then the velocities (equations of motion).
term_order equation_order(const model& scene);
/// Terms ordered by powers of ω (the characteristic polynomial's variable), if there is one.
term_order omega_order(const analysis& result);

} // namespace lagrange
