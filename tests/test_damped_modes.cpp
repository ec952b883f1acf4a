/** @file test_damped_modes.cpp
 *  Numeric damped eigenvalues of the `numeric` entries: the single damped oscillator
 *  against s = −γ ± i√(ω₀² − γ²) (and its overdamped real roots), and a non-proportionally
 *  damped two-mass chain against Eigen's eigenvalues of the 2n × 2n companion matrix
 *  written out here and against det(K + sC + s²M) = 0 at each eigenvalue. */
#include "engine/analysis.h"
#include "numeric/damped_modes.h"
#include "scene_helpers.h"

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
