// SPDX-License-Identifier: GPL-2.0-or-later
/** @file mode_frequency.h
 *  The frequency of one numeric mode as every printer shows it. A mode that grows (an
 *  unstable one, numeric_modes::growth_rate > 0) is shown by its growth rate and named
 *  so, never as a negative ω: ω² < 0 gives "ω = 1.438i, growth rate s = +1.438
 *  (unstable)", a complex s = γ + iω (gyroscopic) "ω = 0.71, growth rate Re s = +0.012
 *  (unstable)". Internal to lib/output. */
#pragma once

#include "numeric/compiled_modes.h"

#include <functional>
#include <string>

namespace lagrange {

/// The rate at which mode k grows (0 unless it does), and whether it does.
double mode_growth_rate(const numeric_modes& n, std::size_t k);
bool mode_grows(const numeric_modes& n, std::size_t k);

/// ω of mode k with its growth, in text: "ω = 2.5", "ω = 1.438i, growth rate s = +1.438
/// (unstable)", "ω = 0.71, growth rate Re s = +0.012 (unstable)"; numbers by `number`
/// (round_trip when null).
std::string mode_frequency_text(const numeric_modes& n, std::size_t k,
                                const std::function<std::string(double)>& number = nullptr);

/// For LaTeX, after the table or display whose ω column shows `1.438\\,i`: "Mode 1 is
/// unstable: it grows as $e^{\\gamma t}$ with growth rate $\\gamma = 1.438$. " (with
/// "\\operatorname{Re} s = " for a complex s); empty for a mode that does not grow.
std::string growth_sentence_latex(const numeric_modes& n, std::size_t k,
                                  const std::function<std::string(double)>& number);

/// The value of ω alone in LaTeX: the number, or "1.438\\,i" for an imaginary frequency.
std::string omega_value_latex(const numeric_modes& n, std::size_t k, const std::function<std::string(double)>& number);

} // namespace lagrange
