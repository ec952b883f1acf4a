// SPDX-License-Identifier: GPL-2.0-or-later
/** @file format.cpp
 *  Shared pieces of output text (see format.h). */
#include "output/format.h"

#include <cmath>

namespace lagrange {

std::string complex_number(std::complex<double> z, const std::function<std::string(double)>& number,
                           const std::string& unit)
{
    const std::string real = number(z.real() == 0 ? 0.0 : z.real());
    if (z.imag() == 0)
        return real;
    return real + (z.imag() < 0 ? " - " : " + ") + number(std::abs(z.imag())) + unit;
}

std::string conjugate_pair(std::complex<double> z, const std::function<std::string(double)>& number,
                           const std::string& plus_minus, const std::string& unit)
{
    const std::string real = number(z.real() == 0 ? 0.0 : z.real());
    if (z.imag() == 0)
        return real;
    return real + plus_minus + number(std::abs(z.imag())) + unit;
}

nlohmann::ordered_json values_json(const std::vector<std::pair<std::string, double>>& values)
{
    nlohmann::ordered_json object = nlohmann::ordered_json::object();
    for (const auto& [name, value] : values)
        object[name] = value;
    return object;
}

std::string printable(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const unsigned char next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0;
        if (c == 0xC2 && next >= 0x80 && next <= 0x9F) { // a C1 control, two bytes in UTF-8
            out += '?';
            ++i;
        } else if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7F) {
            out += '?';
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

std::string join(const std::vector<std::string>& parts, const std::string& separator)
{
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i)
        out += (i ? separator : "") + parts[i];
    return out;
}

} // namespace lagrange
