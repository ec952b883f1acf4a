// SPDX-License-Identifier: GPL-2.0-or-later
/** @file format.h
 *  Pieces of text that several output families share (numbers themselves are formatted
 *  by core/number_text.h). */
#pragma once

#include <nlohmann/json.hpp>

#include <complex>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// z as "a + bi" or "a - bi", b left out when it is 0, and a real part of −0 written as 0.
/// `number` writes each part (its digits and syntax), `unit` is the imaginary unit: "i",
/// or "\\,i" in LaTeX.
std::string complex_number(std::complex<double> z, const std::function<std::string(double)>& number,
                           const std::string& unit);

/// z as "a ± bi" for a conjugate pair (b = |Im z|), or "a" when z is real, a real part of −0
/// written as 0. `plus_minus` is " ± " or " \\pm " in LaTeX; `number` and `unit` as above.
std::string conjugate_pair(std::complex<double> z, const std::function<std::string(double)>& number,
                           const std::string& plus_minus, const std::string& unit);

/// The parts joined by `separator`.
std::string join(const std::vector<std::string>& parts, const std::string& separator);

/// A parameter point as a JSON object {"m": 1, "l": 2}, in the point's order.
nlohmann::ordered_json values_json(const std::vector<std::pair<std::string, double>>& values);

/// `text` safe to print on a terminal: C0 control characters other than newline and tab,
/// DEL and C1 ones (U+0080 … U+009F: CSI, OSC), on which a terminal acts, each become `?`.
/// For messages that quote what the user typed (an option's value, a file's name).
std::string printable(const std::string& text);

} // namespace lagrange
