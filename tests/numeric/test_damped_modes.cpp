// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_damped_modes.cpp
 *  Numeric damped eigenvalues of the `numeric` entries: the single damped oscillator
 *  against s = −γ ± i√(ω₀² − γ²) (and its overdamped real roots), and a non-proportionally
 *  damped two-mass chain against Eigen's eigenvalues of the 2n × 2n companion matrix
 *  written out here and against det(K + sC + s²M) = 0 at each eigenvalue. */
#include "engine/analysis.h"
#include "numeric/damped_modes.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>

using namespace lagrange;
using lagrange_test::load;

namespace {

using complex = std::complex<double>;

const numeric_modes& only_entry(const analysis& a)
{
    REQUIRE(a.numeric);
    REQUIRE(a.numeric->size() == 1);
    return a.numeric->front();
}

bool by_parts(complex x, complex y) { return x.imag() != y.imag() ? x.imag() < y.imag() : x.real() < y.real(); }

} // namespace

TEST_CASE("damped modes: the single oscillator gives s = −γ ± i√(ω₀² − γ²)", "[damped_modes]")
{
    model scene = load(R"(parameters m k b
coordinates x
point P mass m at (x, 0)
spring k between P and (0, 0)
damper b between P and (0, 0)
values m = 2, k = 3, b = 0.7
)");
    analysis a = analyze(scene, {product::numeric});
    const numeric_modes& n = only_entry(a);
    REQUIRE(n.damped);
    REQUIRE(n.eigenvalues.size() == 2);
    const double gamma = 0.7 / (2 * 2), omega0 = std::sqrt(3.0 / 2);
    const double damped_frequency = std::sqrt(omega0 * omega0 - gamma * gamma);
    CHECK_THAT(n.eigenvalues[0].real(), Catch::WithinRel(-gamma, 1e-13));
    CHECK_THAT(n.eigenvalues[0].imag(), Catch::WithinRel(-damped_frequency, 1e-13));
    CHECK_THAT(n.eigenvalues[1].real(), Catch::WithinRel(-gamma, 1e-13));
    CHECK_THAT(n.eigenvalues[1].imag(), Catch::WithinRel(damped_frequency, 1e-13));
    // ζ = γ/ω₀ = b/(2√(km)) for both.
    for (double z : n.damping_ratio)
        CHECK_THAT(z, Catch::WithinRel(0.7 / (2 * std::sqrt(6.0)), 1e-13));
    for (double e : n.eigenvalue_error) {
        CHECK(e > 0);
        CHECK(e < 1e-13);
    }
    CHECK(n.stability == "stable");
    // The undamped frequency is still there, as the undamped system's.
    REQUIRE(n.omega.size() == 1);
    CHECK_THAT(n.omega[0], Catch::WithinRel(omega0, 1e-14));
}

TEST_CASE("damped modes: the overdamped oscillator has two real roots −γ ± √(γ² − ω₀²)", "[damped_modes]")
{
    model scene = load(R"(parameters m k b
coordinates x
T = 1/2*m*x'^2
V = 1/2*k*x^2
dissipation F = 1/2*b*x'^2
values m = 1, k = 4, b = 5
)");
    analysis a = analyze(scene, {product::numeric});
    const numeric_modes& n = only_entry(a);
    REQUIRE(n.eigenvalues.size() == 2);
    CHECK(n.eigenvalues[0].imag() == 0);
    CHECK(n.eigenvalues[1].imag() == 0);
    CHECK_THAT(n.eigenvalues[0].real(), Catch::WithinRel(-4.0, 1e-13));
    CHECK_THAT(n.eigenvalues[1].real(), Catch::WithinRel(-1.0, 1e-13));
    CHECK(n.damping_ratio[0] == 1); // a real negative s has ζ = 1
    CHECK(n.damping_ratio[1] == 1);
}

TEST_CASE("damped modes: a non-proportionally damped two-mass chain against the companion matrix",
          "[damped_modes]")
{
    // A damper on the first mass only: C M⁻¹K ≠ K M⁻¹C, so the modes are complex.
    model scene = load(R"(parameters m1 m2 k1 k2 b
coordinates x1 x2
T = 1/2*m1*x1'^2 + 1/2*m2*x2'^2
V = 1/2*k1*x1^2 + 1/2*k2*(x2 - x1)^2
dissipation F = 1/2*b*x1'^2
values m1 = 1.5, m2 = 0.7, k1 = 3, k2 = 2, b = 0.9
)");
    analysis a = analyze(scene, {product::numeric, product::damping});
    REQUIRE(a.damping);
    CHECK_FALSE(a.damping->proportional);
    const numeric_modes& n = only_entry(a);
    REQUIRE(n.damped);
    REQUIRE(n.eigenvalues.size() == 4);

    const double m1 = 1.5, m2 = 0.7, k1 = 3, k2 = 2, b = 0.9;
    Eigen::Matrix2d mass, stiffness, damping;
    mass << m1, 0, 0, m2;
    stiffness << k1 + k2, -k2, -k2, k2;
    damping << b, 0, 0, 0;
    // ẋ = A x with x = (q, q̇): A = [[0, I], [−M⁻¹K, −M⁻¹C]].
    Eigen::Matrix4d companion = Eigen::Matrix4d::Zero();
    companion.block<2, 2>(0, 2) = Eigen::Matrix2d::Identity();
    companion.block<2, 2>(2, 0) = -mass.inverse() * stiffness;
    companion.block<2, 2>(2, 2) = -mass.inverse() * damping;
    Eigen::EigenSolver<Eigen::Matrix4d> solver(companion);
    std::vector<complex> reference(solver.eigenvalues().data(), solver.eigenvalues().data() + 4);
    std::sort(reference.begin(), reference.end(), by_parts);
    for (std::size_t k = 0; k < 4; ++k) {
        INFO("eigenvalue " << k << ": " << n.eigenvalues[k] << " against " << reference[k]);
        CHECK(std::abs(n.eigenvalues[k] - reference[k]) < 1e-12 * std::abs(reference[k]));
        CHECK(std::abs(n.eigenvalues[k] - reference[k]) <= std::max(n.eigenvalue_error[k], 1e-15));
        CHECK_THAT(n.damping_ratio[k], Catch::WithinAbs(-reference[k].real() / std::abs(reference[k]), 1e-12));
        // det(K + sC + s²M) vanishes there, relative to the size of its terms.
        const complex s = n.eigenvalues[k];
        Eigen::Matrix2cd pencil = stiffness.cast<complex>() + s * damping.cast<complex>() + s * s * mass.cast<complex>();
        const double scale = (stiffness.norm() + std::abs(s) * damping.norm() + std::norm(s) * mass.norm());
        CHECK(std::abs(pencil.determinant()) < 1e-12 * scale * scale);
    }
    // Complex modes: two conjugate pairs with distinct, nonzero damping ratios below 1.
    CHECK(n.eigenvalues[0].imag() < 0);
    CHECK(n.eigenvalues[3].imag() > 0);
    CHECK(n.damping_ratio[2] > 0);
    CHECK(n.damping_ratio[3] > 0);
    CHECK(n.damping_ratio[2] != Approx(n.damping_ratio[3]));
    CHECK(n.stability == "stable");
}

TEST_CASE("damped modes: a free coordinate with a damper is marginal and s = 0 has no ratio", "[damped_modes]")
{
    model scene = load(R"(parameters m b
coordinates x
T = 1/2*m*x'^2
dissipation F = 1/2*b*x'^2
equilibrium x = 0
values m = 2, b = 3
)");
    analysis a = analyze(scene, {product::numeric});
    const numeric_modes& n = only_entry(a);
    REQUIRE(n.eigenvalues.size() == 2);
    CHECK_THAT(n.eigenvalues[0].real(), Catch::WithinRel(-1.5, 1e-13));
    CHECK(std::abs(n.eigenvalues[1]) <= n.eigenvalue_error[1]);
    CHECK(n.damping_ratio[0] == 1);
    CHECK(std::isnan(damping_ratio(0.0)));
    CHECK(n.stability == "marginal");
}

namespace {

/// x scaled so that its first component of largest modulus is 1 (to a relative 10⁻⁸).
Eigen::VectorXcd largest_one(Eigen::VectorXcd x)
{
    const double largest = x.cwiseAbs().maxCoeff();
    for (Eigen::Index i = 0; i < x.size(); ++i)
        if (std::abs(x(i)) >= (1 - 1e-8) * largest)
            return x / x(i);
    return x;
}

const std::string damped_double_pendulum = R"(parameters M m l g alpha c
coordinates theta phi
point upper mass M at (l*sin(theta), -l*cos(theta))
point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))
gravity g along (0, -1)
equilibrium theta = 0, phi = 0
values M = 2, m = 1, l = 1, g = 10, alpha = 0.3, c = 0.5
)";

} // namespace

TEST_CASE("damped modes: a damped double pendulum with C on the upper angle has complex modes",
          "[damped_modes]")
{
    model scene = load(damped_double_pendulum + "dissipation F = 1/2*c*theta'^2\n");
    analysis a = analyze(scene, {product::numeric, product::damping});
    REQUIRE(a.damping);
    CHECK_FALSE(a.damping->proportional);
    const numeric_modes& n = only_entry(a);
    REQUIRE(n.damped);
    CHECK_FALSE(n.proportional_damping);
    REQUIRE(n.damped_modes.rows() == 2);
    REQUIRE(n.damped_modes.cols() == 4);
    REQUIRE(n.damped_mode_backward_error.size() == 4);

    // M, K, C of the double pendulum at rest, written out: M = l²[[M + m, m], [m, m]],
    // K = g l diag(M + m, m), C = diag(c, 0).
    Eigen::Matrix2d mass, stiffness, damping;
    mass << 3, 1, 1, 1;
    stiffness << 30, 0, 0, 10;
    damping << 0.5, 0, 0, 0;
    // The first-order system ẋ = A x, x = (q, q̇), A = [[0, I], [−M⁻¹K, −M⁻¹C]]: its
    // eigenvectors are (v, s v), so the top half is the mode.
    Eigen::Matrix4d companion = Eigen::Matrix4d::Zero();
    companion.block<2, 2>(0, 2) = Eigen::Matrix2d::Identity();
    companion.block<2, 2>(2, 0) = -mass.inverse() * stiffness;
    companion.block<2, 2>(2, 2) = -mass.inverse() * damping;
    Eigen::ComplexEigenSolver<Eigen::Matrix4cd> solver(companion.cast<complex>());
    REQUIRE(solver.info() == Eigen::Success);

    for (Eigen::Index k = 0; k < 4; ++k) {
        const complex s = n.eigenvalues[static_cast<std::size_t>(k)];
        const Eigen::Vector2cd x = n.damped_modes.col(k);
        INFO("eigenvalue " << s << ", mode (" << x(0) << ", " << x(1) << ")");
        // The stated normalization: the largest component is exactly 1.
        CHECK(x.cwiseAbs().maxCoeff() == 1);
        CHECK((x(0) == complex(1) || x(1) == complex(1)));
        // (s²M + sC + K) x = 0 relative to the sizes of its terms.
        const Eigen::Vector2cd residual =
            (s * s * mass.cast<complex>() + s * damping.cast<complex>() + stiffness.cast<complex>()) * x;
        const double scale = (std::norm(s) * mass.norm() + std::abs(s) * damping.norm() + stiffness.norm()) * x.norm();
        CHECK(residual.norm() < 1e-13 * scale);
        CHECK(n.damped_mode_backward_error[static_cast<std::size_t>(k)] < 1e-14);
        // The same vector from the companion matrix's eigenvector of the nearest eigenvalue.
        Eigen::Index nearest = 0;
        for (Eigen::Index j = 1; j < 4; ++j)
            if (std::abs(solver.eigenvalues()(j) - s) < std::abs(solver.eigenvalues()(nearest) - s))
                nearest = j;
        CHECK(std::abs(solver.eigenvalues()(nearest) - s) < 1e-12 * std::abs(s));
        const Eigen::VectorXcd reference = largest_one(solver.eigenvectors().col(nearest).head(2));
        CHECK((reference - x).norm() < 1e-11);
        // Non-proportional damping: the two angles swing out of phase by neither 0 nor π.
        const complex ratio = x(0) / x(1);
        CHECK(std::abs(ratio.imag()) > 1e-3 * std::abs(ratio));
    }
    // A conjugate pair has conjugate modes.
    CHECK((n.damped_modes.col(0) - n.damped_modes.col(3).conjugate()).norm() == 0);
    CHECK((n.damped_modes.col(1) - n.damped_modes.col(2).conjugate()).norm() == 0);
}

TEST_CASE("damped modes: proportional damping keeps the real undamped mode shapes", "[damped_modes]")
{
    // C = αM + cK: the Rayleigh function αT + c·(½ q̇ᵀK q̇) (Rayleigh damping).
    model scene = load(damped_double_pendulum +
                       "dissipation F = alpha*(1/2*(M+m)*l^2*theta'^2 + m*l^2*cos(theta-phi)*theta'*phi' + "
                       "1/2*m*l^2*phi'^2) + c*(1/2*(M+m)*g*l*theta'^2 + 1/2*m*g*l*phi'^2)\n");
    analysis a = analyze(scene, {product::numeric, product::damping});
    REQUIRE(a.damping);
    CHECK(a.damping->proportional);
    const numeric_modes& n = only_entry(a);
    REQUIRE(n.damped);
    CHECK(n.proportional_damping);
    REQUIRE(n.damped_modes.cols() == 4);

    // The undamped modes of M = [[3, 1], [1, 1]], K = diag(30, 10), independently: ω² solves
    // det(K − ω²M) = 2ω⁴ − 60ω² + 300 = 0, ω² = 15 ∓ √75, mode (1, (30 − 3ω²)/ω²)
    // from the first row, scaled so that the largest component is 1.
    std::vector<double> omega_squared{15 - std::sqrt(75.0), 15 + std::sqrt(75.0)};
    std::vector<Eigen::Vector2d> undamped;
    for (double w2 : omega_squared)
        undamped.push_back(largest_one(Eigen::Vector2cd(1, (30 - 3 * w2) / w2)).real());
    int matched[2] = {0, 0};
    for (Eigen::Index k = 0; k < 4; ++k) {
        const complex s = n.eigenvalues[static_cast<std::size_t>(k)];
        INFO("eigenvalue " << s);
        CHECK(n.damped_modes.col(k).imag().isZero(0)); // exactly real
        const Eigen::Vector2d x = n.damped_modes.col(k).real();
        for (std::size_t j = 0; j < 2; ++j)
            if ((x - undamped[j]).norm() < 1e-12) {
                ++matched[j];
                // Mode j's pair solves s² + (α + cω²)s + ω² = 0.
                const double w2 = omega_squared[j];
                CHECK(std::abs(s * s + (0.3 + 0.5 * w2) * s + w2) < 1e-12 * w2);
            }
    }
    CHECK(matched[0] == 2);
    CHECK(matched[1] == 2);
    // The printed undamped modes (columns with Aᵀ T A = I) agree, up to scale.
    for (Eigen::Index j = 0; j < 2; ++j) {
        const Eigen::Vector2d printed = largest_one(n.modes.col(j).cast<complex>()).real();
        CHECK((printed - undamped[static_cast<std::size_t>(j)]).norm() < 1e-12);
    }
}
