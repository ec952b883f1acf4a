// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_quadratic_modes.cpp
 *  The quadratic eigenproblem (s²M + sD + K)x = 0 against closed forms: the damped
 *  oscillator in its three regimes (with critical damping's double root), a charge in a
 *  uniform magnetic field (cyclotron frequency and a double zero), the Penning-type trap,
 *  and blocks of these hidden by a random congruence; normalization, conjugate pairs,
 *  error estimates that cover the true errors, and bad input. */
#include "numeric/quadratic_modes.h"

#include "core/errors.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using lagrange::solve_quadratic_modes;
using complex = std::complex<double>;

Eigen::MatrixXd matrix1(double a)
{
    Eigen::MatrixXd m(1, 1);
    m(0, 0) = a;
    return m;
}

/// Each exact eigenvalue matched to a distinct computed one within that one's error
/// estimate (and the estimate not above `loosest` relative to |s| + scale).
void require_eigenvalues(const lagrange::quadratic_modes& r, std::vector<complex> exact, double loosest, double scale)
{
    REQUIRE(r.eigenvalues.size() == exact.size());
    std::vector<bool> used(exact.size(), false);
    for (const complex& e : exact) {
        std::size_t best = exact.size();
        for (std::size_t k = 0; k < r.eigenvalues.size(); ++k)
            if (!used[k] && (best == exact.size() || std::abs(r.eigenvalues[k] - e) < std::abs(r.eigenvalues[best] - e)))
                best = k;
        REQUIRE(best < exact.size());
        used[best] = true;
        INFO("exact " << e << " computed " << r.eigenvalues[best] << " error estimate " << r.error[best]);
        CHECK(std::abs(r.eigenvalues[best] - e) <= r.error[best]);
        CHECK(r.error[best] <= loosest * (std::abs(e) + scale));
    }
}

/// x* M x = 1, the residual of every pair at the level of its backward error, and the
/// order: ascending imaginary part, then real part.
void require_consistent(const lagrange::quadratic_modes& r, const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                        const Eigen::MatrixXd& K)
{
    for (std::size_t k = 0; k < r.eigenvalues.size(); ++k) {
        complex s = r.eigenvalues[k];
        Eigen::VectorXcd x = r.vectors.col(static_cast<Eigen::Index>(k));
        CHECK_THAT((x.adjoint() * M.cast<complex>() * x)(0, 0).real(), Catch::Matchers::WithinAbs(1, 1e-12));
        Eigen::VectorXcd residual = (s * s * M.cast<complex>() + s * D.cast<complex>() + K.cast<complex>()) * x;
        double scale = (std::norm(s) * M.norm() + std::abs(s) * D.norm() + K.norm()) * x.norm();
        CHECK(residual.norm() <= 1e-13 * scale);
        CHECK(r.backward_error[k] <= 1e-13);
        if (s.imag() == 0)
            CHECK(x.imag().norm() == 0);
        if (k > 0) {
            complex before = r.eigenvalues[k - 1];
            CHECK((before.imag() < s.imag() || (before.imag() == s.imag() && before.real() <= s.real())));
        }
    }
    // Conjugate pairs: s̄ is an eigenvalue with the conjugate vector.
    for (std::size_t k = 0; k < r.eigenvalues.size(); ++k) {
        if (r.eigenvalues[k].imag() == 0)
            continue;
        auto partner = std::find(r.eigenvalues.begin(), r.eigenvalues.end(), std::conj(r.eigenvalues[k]));
        REQUIRE(partner != r.eigenvalues.end());
        Eigen::Index j = partner - r.eigenvalues.begin();
        CHECK((r.vectors.col(j) - r.vectors.col(static_cast<Eigen::Index>(k)).conjugate()).norm() == 0);
    }
}

} // namespace

TEST_CASE("quadratic modes: damped oscillator, three regimes", "[quadratic_modes]")
{
    const double m = 1.7, k = 3.1;
    const double w0 = std::sqrt(k / m);
    SECTION("underdamped: s = −c/2m ± i√(k/m − c²/4m²)")
    {
        double c = 0.4;
        double decay = c / (2 * m), wd = std::sqrt(k / m - decay * decay);
        auto r = solve_quadratic_modes(matrix1(m), matrix1(c), matrix1(k));
        require_eigenvalues(r, {{-decay, -wd}, {-decay, wd}}, 1e-14, 0);
        require_consistent(r, matrix1(m), matrix1(c), matrix1(k));
        CHECK(r.eigenvalues[0].imag() < 0);
    }
    SECTION("overdamped: two real roots")
    {
        double c = 9.0;
        double root = std::sqrt(c * c - 4 * m * k);
        auto r = solve_quadratic_modes(matrix1(m), matrix1(c), matrix1(k));
        require_eigenvalues(r, {{(-c - root) / (2 * m), 0}, {(-c + root) / (2 * m), 0}}, 1e-14, 0);
        require_consistent(r, matrix1(m), matrix1(c), matrix1(k));
        CHECK(r.eigenvalues[0].imag() == 0);
        CHECK(r.eigenvalues[0].real() < r.eigenvalues[1].real());
    }
    SECTION("critical: the double root −ω0, known to about √u")
    {
        double c = 2 * std::sqrt(m * k);
        auto r = solve_quadratic_modes(matrix1(m), matrix1(c), matrix1(k));
        require_eigenvalues(r, {{-w0, 0}, {-w0, 0}}, 1e-6, 0);
        CHECK(r.error[0] > 1e-12 * w0); // a defective root is not claimed to full precision
    }
    SECTION("critical at exact numbers: c = 2, m = k = 1")
    {
        auto r = solve_quadratic_modes(matrix1(1), matrix1(2), matrix1(1));
        require_eigenvalues(r, {{-1, 0}, {-1, 0}}, 1e-6, 0);
    }
}

TEST_CASE("quadratic modes: charge in a uniform magnetic field", "[quadratic_modes]")
{
    // L = ½m(ẋ² + ẏ²) + ½qB(xẏ − yẋ): m q̈ − G q̇ = 0 with G = [[0, qB], [−qB, 0]], so D = −G.
    const double m = 2.5, qB = 4.0, wc = qB / m;
    Eigen::MatrixXd M = m * Eigen::MatrixXd::Identity(2, 2), D(2, 2), K = Eigen::MatrixXd::Zero(2, 2);
    D << 0, -qB, qB, 0;
    auto r = solve_quadratic_modes(M, D, K);
    // s = ±iωc and a double zero (free drift of the guiding centre).
    require_eigenvalues(r, {{0, -wc}, {0, 0}, {0, 0}, {0, wc}}, 1e-14, wc);
    require_consistent(r, M, D, K);
    CHECK(r.eigenvalues[3].imag() == Approx(wc).epsilon(1e-14));
    // The cyclotron mode is circular: |x| = |y|, y = ∓i x.
    Eigen::VectorXcd x = r.vectors.col(3);
    CHECK_THAT(std::abs(x(0)), Catch::Matchers::WithinRel(std::abs(x(1)), 1e-13));
}

TEST_CASE("quadratic modes: Penning-type trap", "[quadratic_modes]")
{
    // The trap adds ½k(x² + y²): ω± = √(ω0² + ωc²/4) ± ωc/2.
    const double m = 1.3, qB = 2.2, k = 5.0;
    const double wc = qB / m, w0 = std::sqrt(k / m);
    const double plus = std::sqrt(w0 * w0 + wc * wc / 4) + wc / 2, minus = std::sqrt(w0 * w0 + wc * wc / 4) - wc / 2;
    Eigen::MatrixXd M = m * Eigen::MatrixXd::Identity(2, 2), D(2, 2), K = k * Eigen::MatrixXd::Identity(2, 2);
    D << 0, -qB, qB, 0;
    auto r = solve_quadratic_modes(M, D, K);
    require_eigenvalues(r, {{0, -plus}, {0, -minus}, {0, minus}, {0, plus}}, 1e-14, 0);
    require_consistent(r, M, D, K);
    CHECK_THAT(r.eigenvalues[2].imag(), Catch::Matchers::WithinRel(minus, 1e-14));
    CHECK_THAT(r.eigenvalues[3].imag(), Catch::Matchers::WithinRel(plus, 1e-14));
    CHECK(std::abs(r.eigenvalues[3].real()) <= r.error[3]);
}

TEST_CASE("quadratic modes: known blocks under a random congruence", "[quadratic_modes]")
{
    // Block diagonal M0 = I, D0, K0 of decoupled problems with closed-form roots; SᵀPS has
    // the same eigenvalues for any invertible S.
    std::mt19937 random(20261124);
    std::uniform_real_distribution<double> uniform(-1, 1);
    const int n = 5;
    Eigen::MatrixXd M0 = Eigen::MatrixXd::Identity(n, n), D0 = Eigen::MatrixXd::Zero(n, n),
                    K0 = Eigen::MatrixXd::Zero(n, n);
    std::vector<complex> exact;
    // Penning block in coordinates 0, 1 (unit mass).
    const double wc = 1.5, w0 = 2.0;
    D0(0, 1) = -wc;
    D0(1, 0) = wc;
    K0(0, 0) = K0(1, 1) = w0 * w0;
    for (double sign : {-1.0, 1.0})
        for (double w : {std::sqrt(w0 * w0 + wc * wc / 4) + wc / 2, std::sqrt(w0 * w0 + wc * wc / 4) - wc / 2})
            exact.push_back({0, sign * w});
    // Underdamped oscillator in 2, overdamped in 3, an unstable one (K < 0) in 4.
    D0(2, 2) = 0.3;
    K0(2, 2) = 4.0;
    exact.push_back({-0.15, std::sqrt(4.0 - 0.0225)});
    exact.push_back({-0.15, -std::sqrt(4.0 - 0.0225)});
    D0(3, 3) = 5.0;
    K0(3, 3) = 1.0;
    exact.push_back({(-5.0 + std::sqrt(21.0)) / 2, 0});
    exact.push_back({(-5.0 - std::sqrt(21.0)) / 2, 0});
    K0(4, 4) = -0.7;
    exact.push_back({std::sqrt(0.7), 0});
    exact.push_back({-std::sqrt(0.7), 0});

    Eigen::MatrixXd S(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            S(i, j) = (i == j ? 2.0 : 0.0) + 0.5 * uniform(random);
    Eigen::MatrixXd M = S.transpose() * M0 * S, D = S.transpose() * D0 * S, K = S.transpose() * K0 * S;
    auto r = solve_quadratic_modes(M, D, K);
    require_eigenvalues(r, exact, 1e-12, 1);
    require_consistent(r, M, D, K);
}

TEST_CASE("quadratic modes: bad input", "[quadratic_modes]")
{
    Eigen::MatrixXd I2 = Eigen::MatrixXd::Identity(2, 2);
    REQUIRE_THROWS_AS(solve_quadratic_modes(I2, Eigen::MatrixXd::Zero(3, 3), I2), std::invalid_argument);
    Eigen::MatrixXd indefinite = I2;
    indefinite(1, 1) = -1;
    REQUIRE_THROWS_MATCHES(solve_quadratic_modes(indefinite, I2, I2), lagrange::computation_error,
                           Catch::Matchers::Message("the mass matrix is not positive definite"));
    Eigen::MatrixXd nan = I2;
    nan(0, 1) = std::nan("");
    REQUIRE_THROWS_AS(solve_quadratic_modes(I2, nan, I2), lagrange::computation_error);
    auto empty = solve_quadratic_modes(Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, 0));
    CHECK(empty.eigenvalues.empty());
}
