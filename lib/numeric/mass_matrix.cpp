// SPDX-License-Identifier: GPL-2.0-or-later
/** @file mass_matrix.cpp
 *  The message of a mass matrix that is not positive definite (the solve is inline in the header). */
#include "numeric/mass_matrix.h"

#include "numeric/values.h"

#include <algorithm>
#include <cmath>

namespace lagrange {

std::string singular_mass_matrix_message(double t, const double* x, std::size_t size)
{
    const bool finite = std::isfinite(t) && std::all_of(x, x + size, [](double v) { return std::isfinite(v); });
    if (!finite)
        return "the motion overflowed: the state is no longer finite" +
               (std::isfinite(t) ? " at t = " + message_number(t) : std::string()) +
               " (the initial values or parameters may be too large)";
    return "the mass matrix is not positive definite at t = " + message_number(t) +
           " (a singular configuration of the coordinates)";
}

} // namespace lagrange
