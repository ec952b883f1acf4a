// SPDX-License-Identifier: GPL-2.0-or-later
/** @file number_text.cpp
 *  Numbers as text (see number_text.h). */
#include "core/number_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lagrange {

namespace {

/// The exponent of a decimal's "e±0k" without '+' or leading zeros: "+05" -> "5", "-07" -> "-7".
std::string bare_exponent(std::string digits)
{
    const bool negative = !digits.empty() && digits[0] == '-';
    if (!digits.empty() && (digits[0] == '-' || digits[0] == '+'))
        digits.erase(0, 1);
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
    return (negative ? "-" : "") + digits;
}

} // namespace

std::string shortest(double x)
{
    char buffer[64];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

std::string round_trip(double x)
{
    if (x == 0)
        x = 0; // no −0
    return shortest(x);
}

std::string significant(double x, int digits)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    return buffer;
}

std::string fixed(double x, int decimals)
{
    char buffer[400]; // %f of the largest double has 309 digits before the point
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
    return buffer;
}

std::string scientific(double x, int decimals)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*e", decimals, x);
    return buffer;
}

std::string hexadecimal(double x)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%a", x);
    return buffer;
}

std::string float_decimal(double value)
{
    // %.*g with the fewest digits that read back (not to_chars, which writes 0.0001 as 1e-04).
    std::string s;
    for (int digits = 1; digits <= 17; ++digits) {
        s = significant(value, digits);
        if (std::strtod(s.c_str(), nullptr) == value)
            break;
    }
    std::string mantissa = s;
    std::string exponent;
    const std::size_t e = s.find('e');
    if (e != std::string::npos) {
        mantissa = s.substr(0, e);
        exponent = bare_exponent(s.substr(e + 1));
    }
    if (exponent.empty() && mantissa.find('.') == std::string::npos)
        mantissa += ".0";
    return exponent.empty() ? mantissa : mantissa + "e" + exponent;
}

std::string latex_exponent(const std::string& decimal)
{
    const std::size_t e = decimal.find_first_of("eE");
    if (e == std::string::npos)
        return decimal;
    // A mantissa of 1 is left out, as a textbook writes it: 10^{3}, -10^{-8}.
    const std::string mantissa = decimal.substr(0, e);
    const std::string power = "10^{" + bare_exponent(decimal.substr(e + 1)) + "}";
    if (mantissa == "1" || mantissa == "+1")
        return power;
    if (mantissa == "-1")
        return "-" + power;
    return mantissa + "\\times" + power;
}

std::string text_exponent(const std::string& decimal)
{
    const std::size_t e = decimal.find_first_of("eE");
    if (e == std::string::npos)
        return decimal;
    return decimal.substr(0, e) + "×10" + superscript(bare_exponent(decimal.substr(e + 1)));
}

std::string superscript(const std::string& integer)
{
    static const char* const digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string out;
    for (char c : integer)
        out += c == '-' ? "⁻" : digits[c - '0'];
    return out;
}

std::string latex_number(double x, int digits)
{
    if (!std::isfinite(x))
        return std::isnan(x) ? "\\mathrm{NaN}" : x > 0 ? "\\infty" : "-\\infty";
    return latex_exponent(digits <= 0 ? shortest(x) : significant(x, digits));
}

} // namespace lagrange
