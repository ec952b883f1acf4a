// SPDX-License-Identifier: GPL-2.0-or-later
/** @file mass_matrix.cpp
 *  The message of a mass matrix that is not positive definite (the solve is inline in the header). */
#include "numeric/mass_matrix.h"

#include "numeric/values.h"

namespace lagrange {

std::string singular_mass_matrix_message(double t)
{
    return "the mass matrix is not positive definite at t = " + message_number(t) +
           " (a singular configuration of the coordinates)";
}

} // namespace lagrange
