// SPDX-License-Identifier: GPL-2.0-or-later
/** @file quadratic_modes.h
 *  Numeric solution of the quadratic eigenproblem (s²M + sD + K) x = 0 of a linear
 *  system M q̈ + D q̇ + K q = 0 with q ∝ x e^{st}: M symmetric positive definite, D any
 *  real matrix (damping C, symmetric, plus gyroscopic G, antisymmetric), K any real
 *  matrix. Solved through the real eigenproblem of the scaled first-order system, with a
 *  backward error and an error estimate per eigenpair. */
#pragma once

#include <Eigen/Dense>

#include <complex>
#include <vector>

namespace lagrange {

/// The 2n eigenvalues and eigenvectors of s²M + sD + K.
///
/// Order: ascending imaginary part, then ascending real part. Complex eigenvalues of a
/// real problem come in exact conjugate pairs (s̄ with the conjugate vector), real ones
/// have an imaginary part of exactly 0.
///
/// Normalization of each vector x: x* M x = 1, and its first component whose modulus is
/// within a relative 10⁻⁸ of the largest is real and positive. A real eigenvalue has a
/// real vector.
struct quadratic_modes {
    std::vector<std::complex<double>> eigenvalues; ///< s, q ∝ x e^{st}
    Eigen::MatrixXcd vectors;                      ///< n × 2n, column k belongs to eigenvalues[k]
    /// Normwise backward error of each pair: ‖(s²M + sD + K)x‖ / ((|s|²‖M‖ + |s|‖D‖ + ‖K‖)‖x‖),
    /// Frobenius norms: the smallest relative perturbation of M, D, K of which (s, x) is an
    /// exact eigenpair.
    std::vector<double> backward_error;
    /// Estimated absolute error of each eigenvalue: its condition number in the first-order
    /// system times that system's backward error, at least the distance to a neighbour it
    /// cannot be told apart from (a multiple eigenvalue such as critical damping's is
    /// only determined to about the square root of the rounding).
    std::vector<double> error;
};

/// Solves (s²M + sD + K) x = 0. Throws std::invalid_argument if the matrices are not
/// square of one size, computation_error if an entry is not finite, M is not symmetric
/// positive definite, or the eigenvalue iteration fails.
quadratic_modes solve_quadratic_modes(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& velocity_matrix,
                                      const Eigen::MatrixXd& stiffness);

} // namespace lagrange
