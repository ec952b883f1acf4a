// SPDX-License-Identifier: GPL-2.0-or-later
/** @file mass_matrix.h
 *  q̈ from M q̈ = f at one evaluation, M symmetric positive definite and small (the
 *  2–6 coordinates of a scene): Cramer's rule for two coordinates, LDLᵀ otherwise.
 *  Inline, because the integrators' inner loop calls it on every evaluation (see
 *  ode_system::compiled); compiled_motion uses the same functions, so both paths give
 *  the same numbers.
 *
 *  Written by hand: for such sizes a plain loop without square roots beats a general
 *  library call, and it reports the failing pivot (a mass matrix that is not positive
 *  definite: a singular configuration of the coordinates). */
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>

namespace lagrange {

/// LDLᵀ factor of the symmetric n × n matrix `m` (row-major) in place: L below the
/// diagonal, D on it; false at a pivot that is not positive.
inline bool factor_ldlt(double* m, std::size_t n)
{
    for (std::size_t j = 0; j < n; ++j) {
        double d = m[j * n + j];
        for (std::size_t k = 0; k < j; ++k)
            d -= m[j * n + k] * m[j * n + k] * m[k * n + k];
        if (!(d > 0))
            return false;
        m[j * n + j] = d;
        for (std::size_t i = j + 1; i < n; ++i) {
            double s = m[i * n + j];
            for (std::size_t k = 0; k < j; ++k)
                s -= m[i * n + k] * m[j * n + k] * m[k * n + k];
            m[i * n + j] = s / d;
        }
    }
    return true;
}

/// Solves L D Lᵀ y = b in place with the factor from factor_ldlt().
inline void ldlt_solve(const double* l, std::size_t n, double* b)
{
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < i; ++k)
            b[i] -= l[i * n + k] * b[k];
    for (std::size_t i = 0; i < n; ++i)
        b[i] /= l[i * n + i];
    for (std::size_t i = n; i-- > 0;)
        for (std::size_t k = i + 1; k < n; ++k)
            b[i] -= l[k * n + i] * b[k];
}

/// `acceleration` = M⁻¹ f with `mass_and_force` = (M row-major, n², then f, n) as the
/// compiled programs write them; `factor` is n² doubles of scratch, left holding the
/// LDLᵀ factor when n ≠ 2 or `keep_factor`. False, with `acceleration` undefined, when
/// M is not positive definite.
inline bool solve_mass_matrix(const double* mass_and_force, std::size_t n, double* factor, double* acceleration,
                              bool keep_factor = false)
{
    if (n == 2 && !keep_factor) {
        // Two coordinates (the common case): Cramer's rule, without the factorization's loops.
        const double* o = mass_and_force;
        double a = o[0], b = o[1], d = o[3], determinant = a * d - b * b;
        if (!(a > 0 && determinant > 0))
            return false;
        double inverse = 1 / determinant;
        acceleration[0] = (d * o[4] - b * o[5]) * inverse;
        acceleration[1] = (a * o[5] - b * o[4]) * inverse;
        return true;
    }
    std::copy(mass_and_force, mass_and_force + n * n, factor);
    std::copy(mass_and_force + n * n, mass_and_force + n * n + n, acceleration);
    if (!factor_ldlt(factor, n))
        return false;
    ldlt_solve(factor, n, acceleration);
    return true;
}

/// The message for a mass matrix that cannot be solved at time t in the state x (size
/// entries): not positive definite, or, when t or the state is no longer finite, an overflow.
std::string singular_mass_matrix_message(double t, const double* x, std::size_t size);

} // namespace lagrange
