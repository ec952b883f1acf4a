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

} // namespace lagrange
