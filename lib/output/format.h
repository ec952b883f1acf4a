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

} // namespace lagrange
