// SPDX-License-Identifier: GPL-2.0-or-later
/** @file quadratic_modes.cpp
 *  (s²M + sD + K) x = 0 through the first-order system: M = LLᵀ turns the problem into
 *  s²I + sD̃ + K̃ with D̃ = L⁻¹DL⁻ᵀ, K̃ = L⁻¹KL⁻ᵀ; s = γμ with γ² = ‖K̃‖/‖I‖ balances the
 *  coefficients (Fan, Lin and Van Dooren's scaling); the companion matrix
 *  [[0, I], [−K̃/γ², −D̃/γ]] goes to Eigen's real nonsymmetric solver, whose left
 *  eigenvectors (rows of the inverse eigenvector matrix) give each eigenvalue's condition. */
#include "numeric/quadratic_modes.h"

#include "core/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace lagrange {

namespace {

using complex = std::complex<double>;

constexpr double unit_roundoff = std::numeric_limits<double>::epsilon() / 2;

bool all_finite(const Eigen::MatrixXd& m) { return m.allFinite(); }

/// ‖(s²M + sD + K)x‖ / ((|s|²‖M‖ + |s|‖D‖ + ‖K‖)‖x‖), Frobenius norms.
double backward_error(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& velocity_matrix,
                      const Eigen::MatrixXd& stiffness, complex s, const Eigen::VectorXcd& x)
{
    Eigen::VectorXcd residual = (s * s) * (mass.cast<complex>() * x) + s * (velocity_matrix.cast<complex>() * x) +
                                stiffness.cast<complex>() * x;
    double scale = (std::norm(s) * mass.norm() + std::abs(s) * velocity_matrix.norm() + stiffness.norm()) * x.norm();
    if (scale == 0)
        return residual.norm() == 0 ? 0 : std::numeric_limits<double>::infinity();
    return residual.norm() / scale;
}

/// x scaled so that x* M x = 1 and its first component of (nearly) largest modulus is real
/// and positive; a vector of a real eigenvalue is made exactly real.
Eigen::VectorXcd normalized(Eigen::VectorXcd x, const Eigen::MatrixXd& mass, bool real_eigenvalue)
{
    double m_norm = std::sqrt(std::abs((x.adjoint() * mass.cast<complex>() * x)(0, 0).real()));
    if (m_norm > 0)
        x /= m_norm;
    double largest = x.cwiseAbs().maxCoeff();
    for (Eigen::Index k = 0; k < x.size(); ++k) {
        double modulus = std::abs(x(k));
        if (modulus >= (1 - 1e-8) * largest && modulus > 0) {
            x *= std::conj(x(k)) / modulus;
            x(k) = modulus;
            break;
        }
    }
    if (real_eigenvalue)
        x = x.real().cast<complex>();
    return x;
}

} // namespace

quadratic_modes solve_quadratic_modes(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& velocity_matrix,
                                      const Eigen::MatrixXd& stiffness)
{
    const Eigen::Index n = mass.rows();
    if (mass.cols() != n || velocity_matrix.rows() != n || velocity_matrix.cols() != n || stiffness.rows() != n ||
        stiffness.cols() != n)
        throw std::invalid_argument("solve_quadratic_modes: M, D and K must be square matrices of one size");
    quadratic_modes result;
    result.vectors.resize(n, 2 * n);
    if (n == 0)
        return result;
    if (!all_finite(mass) || !all_finite(velocity_matrix) || !all_finite(stiffness))
        throw computation_error("the linearized equations have an entry that is not a finite number");
    if ((mass - mass.transpose()).norm() > 64 * unit_roundoff * mass.norm())
        throw computation_error("the mass matrix is not symmetric");
    const Eigen::MatrixXd symmetric_mass = (mass + mass.transpose()) / 2;
    Eigen::LLT<Eigen::MatrixXd> cholesky(symmetric_mass);
    if (cholesky.info() != Eigen::Success)
        throw computation_error("the mass matrix is not positive definite");
    const Eigen::MatrixXd lower = cholesky.matrixL();
    const Eigen::MatrixXcd upper_complex = lower.transpose().cast<complex>();
    auto congruence = [&](const Eigen::MatrixXd& a) {
        Eigen::MatrixXd left = lower.triangularView<Eigen::Lower>().solve(a);
        return Eigen::MatrixXd(lower.triangularView<Eigen::Lower>().solve(left.transpose()).transpose());
    };
    const Eigen::MatrixXd damping_tilde = congruence(velocity_matrix);
    const Eigen::MatrixXd stiffness_tilde = congruence(stiffness);

    const double identity_norm = std::sqrt(static_cast<double>(n));
    double gamma = std::sqrt(stiffness_tilde.norm() / identity_norm);
    if (gamma == 0)
        gamma = damping_tilde.norm() / identity_norm;
    if (gamma == 0 || !std::isfinite(gamma))
        gamma = 1;

    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    companion.topRightCorner(n, n).setIdentity();
    companion.bottomLeftCorner(n, n) = -stiffness_tilde / (gamma * gamma);
    companion.bottomRightCorner(n, n) = -damping_tilde / gamma;
    Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, true);
    if (solver.info() != Eigen::Success)
        throw computation_error("the eigenvalue iteration of the first-order system did not converge");
    const Eigen::VectorXcd mu = solver.eigenvalues();
    const Eigen::MatrixXcd right = solver.eigenvectors();
    const double companion_norm = companion.norm();

    // Left eigenvectors: the rows of the inverse of the eigenvector matrix (w_k v_k = 1),
    // so that ‖w_k‖‖v_k‖ is eigenvalue k's condition number.
    Eigen::FullPivLU<Eigen::MatrixXcd> lu(right);
    Eigen::MatrixXcd left;
    bool have_left = lu.isInvertible();
    if (have_left) {
        left = lu.inverse();
        have_left = left.allFinite();
    }

    std::vector<complex> s(2 * n);
    std::vector<Eigen::VectorXcd> x(2 * n);
    std::vector<double> eta(2 * n), error(2 * n);
    for (Eigen::Index k = 0; k < 2 * n; ++k) {
        const Eigen::VectorXcd z = right.col(k);
        const bool real_eigenvalue = mu(k).imag() == 0;
        s[k] = real_eigenvalue ? complex(gamma * mu(k).real(), 0) : gamma * mu(k);
        // Either half of z = (y, μy) gives y; keep the one with the smaller backward error.
        Eigen::VectorXcd best;
        double best_eta = std::numeric_limits<double>::infinity();
        for (int half = 0; half < 2; ++half) {
            Eigen::VectorXcd y = half == 0 ? Eigen::VectorXcd(z.head(n)) : Eigen::VectorXcd(z.tail(n));
            if (y.norm() == 0)
                continue;
            Eigen::VectorXcd candidate =
                normalized(upper_complex.triangularView<Eigen::Upper>().solve(y), symmetric_mass,
                           real_eigenvalue);
            double candidate_eta = backward_error(mass, velocity_matrix, stiffness, s[k], candidate);
            if (candidate_eta < best_eta) {
                best = candidate;
                best_eta = candidate_eta;
            }
        }
        if (best.size() == 0)
            throw computation_error("the first-order system gave a zero eigenvector");
        x[k] = best;
        eta[k] = best_eta;

        double companion_residual = (companion.cast<complex>() * z - mu(k) * z).norm() / (companion_norm * z.norm());
        double perturbation = std::max(companion_residual, unit_roundoff) * companion_norm * 4 * static_cast<double>(n);
        double condition = have_left ? left.row(k).norm() * z.norm() : std::numeric_limits<double>::infinity();
        double estimate = condition * perturbation;
        // A defective (Jordan) eigenvalue has no finite condition; a block of size two
        // moves by about the square root of the perturbation.
        if (!std::isfinite(estimate))
            estimate = std::sqrt(perturbation * companion_norm);
        error[k] = gamma * estimate;
    }
    // Eigenvalues closer than their errors cannot be told apart: each is known only to
    // within their distance.
    std::vector<double> widened = error;
    for (Eigen::Index i = 0; i < 2 * n; ++i)
        for (Eigen::Index j = 0; j < 2 * n; ++j)
            if (i != j && std::abs(s[i] - s[j]) <= error[i] + error[j])
                widened[i] = std::max(widened[i], std::abs(s[i] - s[j]));

    std::vector<std::size_t> order(2 * n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (s[a].imag() != s[b].imag())
            return s[a].imag() < s[b].imag();
        return s[a].real() < s[b].real();
    });
    for (std::size_t k = 0; k < order.size(); ++k) {
        result.eigenvalues.push_back(s[order[k]]);
        result.vectors.col(static_cast<Eigen::Index>(k)) = x[order[k]];
        result.backward_error.push_back(eta[order[k]]);
        result.error.push_back(widened[order[k]]);
    }
    return result;
}

} // namespace lagrange
