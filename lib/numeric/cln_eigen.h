// SPDX-License-Identifier: GPL-2.0-or-later
/** @file cln_eigen.h
 *  The symmetric-definite eigenproblem V a = W T a at any precision, in cln::cl_F: the
 *  high-precision route of compiled_modes. Written by hand: Eigen's solvers need a
 *  scalar type with numeric_limits and math functions that cl_F does not provide, and
 *  no multiprecision eigensolver is among the project's dependencies. */
#pragma once

#include <cln/cln.h>

#include <cstddef>
#include <vector>

namespace lagrange {

/// A square matrix of CLN floats, by rows.
using cln_matrix = std::vector<std::vector<cln::cl_F>>;

struct cln_eigen_result {
    /// The pivot of T = L Lᵀ that is not above rounding (T singular or indefinite), or
    /// static_cast<std::size_t>(-1); when there is one, nothing else is set.
    std::size_t failed_pivot = static_cast<std::size_t>(-1);
    std::vector<cln::cl_F> eigenvalues; ///< W, ascending
    /// Bound on the absolute error of each W: rounding at this precision, amplified by the
    /// conditioning of T.
    double error = 0;
    std::vector<double> modes; ///< if asked for: columns a with aᵀ T a = 1, column-major, rounded to double
};

/// V a = W T a for symmetric T and V of one size, their entries at `format`: T = L Lᵀ
/// (Cholesky), K = L⁻¹ V L⁻ᵀ, cyclic Jacobi rotations until K's off-diagonal part is
/// below rounding, a = L⁻ᵀ y. `modes`: whether to compute the mode vectors.
cln_eigen_result cln_generalized_eigen(const cln_matrix& T, const cln_matrix& V, const cln::float_format_t& format,
                                       bool modes);

} // namespace lagrange
