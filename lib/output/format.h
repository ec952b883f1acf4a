// SPDX-License-Identifier: GPL-2.0-or-later
/** @file format.h
 *  Pieces of text that several output families share (numbers themselves are formatted
 *  by core/number_text.h). */
#pragma once

#include <complex>
#include <functional>
#include <string>

namespace lagrange {

/// z as "a + bi" or "a - bi", b left out when it is 0, and a real part of −0 written as 0.
/// `number` writes each part (its digits and syntax), `unit` is the imaginary unit: "i",
/// or "\\,i" in LaTeX.
std::string complex_number(std::complex<double> z, const std::function<std::string(double)>& number,
                           const std::string& unit);

/// `text` safe to print on a terminal: C0 control characters other than newline and tab,
/// DEL and C1 ones (U+0080 … U+009F: CSI, OSC), on which a terminal acts, each become `?`.
/// For messages that quote what the user typed (an option's value, a file's name).
std::string printable(const std::string& text);

} // namespace lagrange
