// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_damping.cpp
 *  Damped small oscillations: the damping matrix, det(K + sC + s²M) and its closed
 *  forms against the single damped oscillator's s = −γ ± i√(ω₀² − γ²) in its three
 *  regimes, and proportional damping of a double pendulum with modal damping ratios
 *  α/(2ω) for C = αM, against a damper on one coordinate that is not proportional. */
#include "engine/analysis.h"
#include "mechanics/damping.h"
#include "helpers/scene_helpers.h"
#include "helpers/expressions.h"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <complex>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::symbol_of;

using lagrange_test::same;
using lagrange_test::value_at;

namespace {

damping_result damping_of(const model& scene)
{
    analysis a = analyze(scene, {product::damping, product::modes});
    REQUIRE(a.damping);
    return *a.damping;
}

std::complex<double> complex_value(const GiNaC::ex& e)
{
    GiNaC::ex v = GiNaC::evalf(e);
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(v));
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(v);
    return {GiNaC::real(n).to_double(), GiNaC::imag(n).to_double()};
}

} // namespace

TEST_CASE("damping: the single oscillator gives s = −γ ± i√(ω₀² − γ²)", "[damping]")
{
    model scene = load(R"(parameters m k b
coordinates x
point P mass m at (x, 0)
spring k between P and (0, 0)
damper b between P and (0, 0)
)");
    damping_result d = damping_of(scene);
    GiNaC::ex m = symbol_of(scene, "m"), k = symbol_of(scene, "k"), b = symbol_of(scene, "b");
    CHECK(same(d.damping(0, 0), b));
    CHECK(same(d.polynomial, m * d.s * d.s + b * d.s + k));
    REQUIRE(d.closed_form);
    REQUIRE(d.factors.size() == 1);
    const damped_factor& f = d.factors[0];
    CHECK(same(f.decay, b / (2 * m)));
    CHECK(same(f.natural_squared, k / m));
    CHECK(same(f.discriminant, k / m - b * b / (4 * m * m)));
    CHECK(f.regime.empty()); // depends on the parameters
    // Both roots solve m s² + b s + k = 0 at a parameter point.
    GiNaC::exmap at{{m, 2}, {k, 3}, {b, GiNaC::numeric(7, 10)}};
    for (const GiNaC::ex& root : f.roots) {
        std::complex<double> s = complex_value(root.subs(at));
        CHECK(std::abs(2.0 * s * s + 0.7 * s + 3.0) < 1e-12);
    }
    CHECK(d.proportional); // one coordinate: always
}

TEST_CASE("damping: the three regimes of the damped oscillator, the critical case a double root",
          "[damping]")
{
    // m = 1, k = 4: critical at b = 4.
    struct regime_case {
        const char* b;
        const char* regime;
        std::complex<double> first, second;
    };
    const double wd = std::sqrt(4 - 0.25);
    for (const regime_case& c : {regime_case{"1", "underdamped", {-0.5, -wd}, {-0.5, wd}},
                                 regime_case{"4", "critical", {-2, 0}, {-2, 0}},
                                 regime_case{"5", "overdamped", {-4, 0}, {-1, 0}}}) {
        INFO("b = " << c.b);
        model scene = load(std::string("coordinates x\npoint P mass 1 at (x, 0)\nspring 4 between P and (0, 0)\n"
                                       "dissipation F = 1/2*") + c.b + "*x'^2\n");
        damping_result d = damping_of(scene);
        REQUIRE(d.factors.size() == 1);
        CHECK(d.factors[0].regime == c.regime);
        REQUIRE(d.factors[0].roots.size() == 2);
        std::complex<double> r1 = complex_value(d.factors[0].roots[0]), r2 = complex_value(d.factors[0].roots[1]);
        CHECK(std::abs(r1 - c.first) < 1e-12);
        CHECK(std::abs(r2 - c.second) < 1e-12);
    }
}

TEST_CASE("damping: a damped double pendulum, proportional and not", "[damping]")
{
    const std::string pendulum = R"(parameters M m l g alpha c
coordinates theta phi
point upper mass M at (l*sin(theta), -l*cos(theta))
point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))
gravity g along (0, -1)
equilibrium theta = 0, phi = 0
)";
    SECTION("C = αM (the Rayleigh function α T) is proportional, with ζ_k = α/(2ω_k)")
    {
        model scene = load(pendulum + "dissipation F = alpha*(1/2*(M+m)*l^2*theta'^2 + "
                                      "m*l^2*cos(theta-phi)*theta'*phi' + 1/2*m*l^2*phi'^2)\n");
        analysis a = analyze(scene, {product::damping, product::modes, product::linearization});
        REQUIRE(a.damping);
        const damping_result& d = *a.damping;
        GiNaC::ex alpha = symbol_of(scene, "alpha");
        for (unsigned i = 0; i < 2; ++i)
            for (unsigned j = 0; j < 2; ++j)
                CHECK(same(d.damping(i, j), alpha * a.linearization->kinetic(i, j)));
        CHECK(d.proportional);
        REQUIRE(a.modes->closed_form);
        REQUIRE(d.modal_damping_ratios.size() == 2);
        GiNaC::exmap at{{symbol_of(scene, "M"), 2}, {symbol_of(scene, "m"), 1}, {symbol_of(scene, "l"), 1},
                        {symbol_of(scene, "g"), 10}, {alpha, GiNaC::numeric(3, 10)}};
        for (std::size_t k = 0; k < 2; ++k) {
            double w = std::sqrt(complex_value(a.modes->frequencies[k].subs(at)).real());
            CHECK(std::abs(complex_value(d.modal_damping_ratios[k].subs(at)).real() - 0.3 / (2 * w)) < 1e-12);
        }
    }
    SECTION("a damper on the upper angle alone is not proportional")
    {
        model scene = load(pendulum + "dissipation F = 1/2*c*theta'^2\n");
        damping_result d = damping_of(scene);
        CHECK(same(d.damping(0, 0), symbol_of(scene, "c")));
        CHECK(same(d.damping(1, 1), 0));
        CHECK_FALSE(d.proportional);
        CHECK(d.modal_damping_ratios.empty());
        // det(K + sC + s²M) at a point against the polynomial: a constant multiple.
        GiNaC::exmap at{{symbol_of(scene, "M"), 2}, {symbol_of(scene, "m"), 1}, {symbol_of(scene, "l"), 1},
                        {symbol_of(scene, "g"), 10}, {symbol_of(scene, "c"), GiNaC::numeric(1, 2)}};
        auto det_at = [&](double s) {
            double m11 = 3, m12 = 1, m22 = 1, k11 = 30, k22 = 10, c11 = 0.5;
            return (k11 + s * c11 + s * s * m11) * (k22 + s * s * m22) - (s * s * m12) * (s * s * m12);
        };
        double ratio = complex_value(d.polynomial.subs(at).subs(d.s == 1)).real() / det_at(1);
        for (double s : {-2.0, 0.5, 3.0})
            CHECK(std::abs(complex_value(d.polynomial.subs(at).subs(d.s == s)).real() - ratio * det_at(s)) <
                  1e-9 * std::abs(ratio * det_at(s)));
    }
}

TEST_CASE("damping: a scene with dissipation has `damping` among its default products", "[damping]")
{
    model scene = load("parameters m k b\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n"
                       "dissipation F = 1/2*b*x'^2\n");
    analysis a = analyze(scene);
    CHECK(a.damping);
    model plain = load("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n");
    CHECK_FALSE(analyze(plain).damping);
}

TEST_CASE("damping: gyroscopic terms with damping enter the polynomial, in a default run too", "[damping]")
{
    // Isotropic: det(K + s(C − G) + s²M) = (m s² + c s + k)² + B² s², which det(K + sC + s²M)
    // alone, (m s² + c s + k)², would get wrong. The default run computes and verifies it.
    model scene = load("parameters m k B c\ncoordinates x y\n"
                       "L = 1/2*m*(x'^2 + y'^2) + 1/2*B*(x*y' - y*x') - 1/2*k*(x^2 + y^2)\n"
                       "dissipation F = 1/2*c*(x'^2 + y'^2)\nequilibrium x = 0, y = 0\n");
    analysis a = analyze(scene);
    REQUIRE(a.damping);
    CHECK(a.damping->gyroscopic);
    const GiNaC::ex s = a.damping->s, m = symbol_of(scene, "m"), k = symbol_of(scene, "k"),
                    B = symbol_of(scene, "B"), c = symbol_of(scene, "c");
    CHECK(same(a.damping->polynomial, GiNaC::pow(m * s * s + c * s + k, 2) + B * B * s * s));
    REQUIRE(a.verification); // a failed check throws; this one was made
    bool checked = false;
    for (const verification_entry& entry : a.verification->entries)
        checked = checked || (entry.item == "damped_characteristic" && entry.checked);
    CHECK(checked);
}

TEST_CASE("damping: with a gyroscopic matrix, det(K + s(C − G) + s²M) and its roots are A's eigenvalues",
          "[damping][gyroscopic]")
{
    // A charge in a magnetic field (G ≠ 0) with a damper on x: numeric, state_space and
    // transfer handled it while `damping` refused. Its polynomial is checked against an
    // independent route: the eigenvalues of state_space's A at the same values.
    model scene = load(R"(parameters m k B c
coordinates x y
L = 1/2*m*(x'^2 + y'^2) + B/2*(x*y' - y*x') - 1/2*k*(x^2 + 2*y^2)
dissipation F = 1/2*c*x'^2
equilibrium x = 0, y = 0
values m = 1, k = 1, B = 0.5, c = 0.2
)");
    analysis a = analyze(scene, {product::damping, product::state_space, product::numeric});
    REQUIRE(a.damping);
    REQUIRE(a.state_space);
    const damping_result& d = *a.damping;
    CHECK(d.gyroscopic);
    CHECK_FALSE(d.proportional);
    CHECK(d.modal_damping_ratios.empty());
    // The closed form at the values: m²s⁴ + c m s³ + (3 k m + B²) s² + 2 c k s + 2 k².
    GiNaC::exmap values{{symbol_of(scene, "m"), 1}, {symbol_of(scene, "k"), 1}, {symbol_of(scene, "B"), GiNaC::numeric(1, 2)},
                        {symbol_of(scene, "c"), GiNaC::numeric(1, 5)}};
    const GiNaC::ex p = d.polynomial.subs(values).expand();
    REQUIRE(p.degree(d.s) == 4);
    // Its roots against the eigenvalues of A (Eigen's EigenSolver on the 4 × 4 state matrix).
    Eigen::Matrix4d A;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            A(i, j) = value_at(a.state_space->a(static_cast<unsigned>(i), static_cast<unsigned>(j)), values);
    Eigen::EigenSolver<Eigen::Matrix4d> solver(A);
    const GiNaC::ex leading = p.coeff(d.s, 4);
    for (int k = 0; k < 4; ++k) {
        const std::complex<double> s = solver.eigenvalues()[k];
        GiNaC::exmap at{{d.s, GiNaC::numeric(s.real()) + GiNaC::I * GiNaC::numeric(s.imag())}};
        const std::complex<double> residual = complex_value((p / leading).subs(at));
        INFO("s = " << s.real() << " + " << s.imag() << "i");
        CHECK(std::abs(residual) < 1e-12);
    }
    // And the numeric damped eigenvalues (the companion linearization) are the same four.
    REQUIRE(a.numeric);
    REQUIRE(a.numeric->front().eigenvalues.size() == 4);
    for (const std::complex<double>& s : a.numeric->front().eigenvalues) {
        double nearest = 1;
        for (int k = 0; k < 4; ++k)
            nearest = std::min(nearest, std::abs(s - std::complex<double>(solver.eigenvalues()[k])));
        CHECK(nearest < 1e-12);
    }
}
