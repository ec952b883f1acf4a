// SPDX-License-Identifier: GPL-2.0-or-later
/** @file values.h
 *  Small helpers shared by the numeric stages: an expression at the parameter values
 *  as a double, with a message naming what it was when it is not a finite real number,
 *  numbers for messages, and the `values` of a scene merged and substituted. */
#pragma once

#include <ginac/ginac.h>

#include <complex>
#include <map>
#include <optional>
#include <string>

namespace lagrange {

struct model;

/// `e` evaluated (evalf) to a double; throws computation_error "`what` is not a real
/// number" (a symbol left, or a complex value) or "… is not a finite number".
double real_value(const GiNaC::ex& e, const std::string& what);

/// `e` with `at` substituted, evaluated to a complex double: nothing when a symbol is left,
/// the evaluation throws, or a part is not finite.
std::optional<std::complex<double>> complex_at(const GiNaC::ex& e, const GiNaC::exmap& at);

/// complex_at, and nothing when the imaginary part is beyond rounding (more than
/// 1e-12 (1 + |re|)). For the checks that try points and skip the unusable ones.
std::optional<double> real_at(const GiNaC::ex& e, const GiNaC::exmap& at);

/// x with `digits` significant digits (printf's %g), for messages.
std::string message_number(double x, int digits = 6);

/// Every `values` line overlaid in order: later points (and --values) override earlier ones;
/// the inputs' values (expressions in t) are among them, by name.
std::map<std::string, GiNaC::ex> merged_values(const model& scene);

/// `e` with every floating-point number (a `values` line's 0.1) replaced by the rational
/// number that the double stands for exactly. GiNaC combines the numbers of a sum or a
/// product in its internal order, which changes from process to process; in floating
/// point that order changes the rounding, in rationals it does not.
GiNaC::ex exact_numbers(const GiNaC::ex& e);

/// Substitutes the inputs' and parameters' values (exact_numbers of them, so that the
/// result is the same in every process); throws computation_error naming a parameter
/// that `e` uses without one, and scene_error at an input without a value.
GiNaC::ex at_values(const GiNaC::ex& e, const model& scene, const std::map<std::string, GiNaC::ex>& values);

} // namespace lagrange
