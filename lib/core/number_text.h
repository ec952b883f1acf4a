// SPDX-License-Identifier: GPL-2.0-or-later
/** @file number_text.h
 *  Numbers as text: the one place where the library turns a double into digits, for
 *  printed results, tables, CSV, plot scripts, generated C and messages. Every form is
 *  the same from run to run and on every platform with IEEE doubles. */
#pragma once

#include <string>

namespace lagrange {

/// The shortest decimal that reads back as the same double (`std::to_chars`): "9.81",
/// "1e-14", "-0", "inf". For numbers printed as data (CSV, sweeps).
std::string shortest(double x);

/// `shortest`, with zero as "0", never "-0": for numbers shown to people and in JSON.
std::string round_trip(double x);

/// `digits` significant digits, as printf's `%.*g` (and an iostream's default
/// format with that precision): "0.333333", "1e-05", "-0".
std::string significant(double x, int digits);

/// `decimals` digits after the point, as printf's `%.*f`: "0.125000".
std::string fixed(double x, int decimals);

/// `decimals` digits after the point of a mantissa with an exponent, as printf's `%.*e`:
/// "1e-08" for 0 decimals, "3.142e+00" for 3.
std::string scientific(double x, int decimals);

/// The exact hexadecimal form of printf's `%a` ("0x1.8p+1"), for generated C source.
std::string hexadecimal(double x);

/// The shortest decimal that reads back as the same double, in a form GiNaC's parser
/// takes as a float: always with a point or an exponent ("9.81", "2.0", "1e-14",
/// "1.5e20"; the exponent without '+' or leading zeros).
std::string float_decimal(double x);

/// A decimal with an exponent ("1.5e-20", "2e+05", "1e+03") in LaTeX, "1.5\times10^{-20}",
/// "2\times10^{5}", "10^{3}" (a mantissa of 1 left out); one without an exponent unchanged.
std::string latex_exponent(const std::string& decimal);

/// The same in Unicode text: "1.5×10⁻²⁰".
std::string text_exponent(const std::string& decimal);

/// An integer as Unicode superscript: "-20" -> "⁻²⁰".
std::string superscript(const std::string& integer);

/// x in LaTeX math: `shortest` when `digits` ≤ 0, else `significant`, with the exponent
/// as ×10^{k}; NaN and infinities as \mathrm{NaN}, \infty, -\infty.
std::string latex_number(double x, int digits = 0);

} // namespace lagrange
