// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_floquet.cpp
 *  Floquet multipliers of periodically driven systems against independent references:
 *  the Kapitza pendulum's upright position against the averaged (Kapitza) potential,
 *  the Mathieu equation's first instability tongue against its perturbative boundary
 *  and growth rate, and a constant-coefficient oscillator against exp(A T). */
#include "engine/analysis.h"
#include "numeric/floquet.h"
#include "verify/verify.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

using namespace lagrange;
using namespace lagrange_test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

double largest_modulus(const floquet_point& f)
{
    double largest = 0;
    for (const std::complex<double>& mu : f.multipliers)
        largest = std::max(largest, std::abs(mu));
    return largest;
}

/// Kapitza: support y = a cos(γ t), φ from the downward vertical, asked about φ = π.
std::string kapitza(double gamma)
{
    return "parameters m g l a gamma\ncoordinates phi\n"
           "point bob mass m at (l*sin(phi), a*cos(gamma*t) - l*cos(phi))\n"
           "gravity g along (0, -1)\nequilibrium phi = pi\n"
           "values m = 1, g = 9.81, l = 1, a = 0.05, gamma = " + std::to_string(gamma) + "\n";
}

/// Mathieu: x'' + (a − 2 e cos 2t) x = 0, L = ½ x'² − ½ (a − 2 e cos 2t) x².
std::string mathieu(double a, double e)
{
    return "parameters a e\ncoordinates x\nL = 1/2*x'^2 - 1/2*(a - 2*e*cos(2*t))*x^2\n"
           "values a = " + std::to_string(a) + ", e = " + std::to_string(e) + "\n";
}

std::vector<floquet_point> floquet_of(const std::string& text)
{
    const model scene = load(text);
    const analysis result = analyze(scene, {product::floquet});
    REQUIRE(result.floquet);
    return *result.floquet;
}

} // namespace

TEST_CASE("floquet: the Kapitza pendulum stands upright above a^2 gamma^2 = 2 g l", "[floquet]")
{
    // The averaged potential U = −m g l cos φ + (m a² γ²/4) sin² φ has a minimum at φ = π
    // iff a² γ² > 2 g l; here the threshold is γ = √(2 g l)/a ≈ 88.6.
    const double g = 9.81, l = 1, a = 0.05;
    const double threshold = std::sqrt(2 * g * l) / a;
    REQUIRE(threshold == Approx(88.59).epsilon(1e-3));
    const std::vector<floquet_point> above = floquet_of(kapitza(120));
    REQUIRE(above.size() == 1);
    CHECK(above[0].stable);
    CHECK_THAT(above[0].period, WithinRel(2 * M_PI / 120, 1e-12));
    // The slow oscillation in the averaged potential: Ω² = a²γ²/(2 l²) − g/l, so the
    // multipliers are e^{±iΩT} up to corrections of order (a/l)² and (Ω/γ)².
    const double slow = std::sqrt(a * a * 120 * 120 / (2 * l * l) - g / l);
    REQUIRE(above[0].multipliers.size() == 2);
    CHECK_THAT(std::abs(above[0].multipliers[0]), WithinAbs(1, 1e-8));
    CHECK_THAT(std::abs(std::arg(above[0].multipliers[0])), WithinRel(slow * above[0].period, 0.05));

    const std::vector<floquet_point> below = floquet_of(kapitza(60));
    REQUIRE(below.size() == 1);
    CHECK_FALSE(below[0].stable);
    // Below the threshold the upright position is a saddle of the averaged potential:
    // growth rate κ² = g/l − a²γ²/(2 l²), multiplier e^{κT}.
    const double kappa = std::sqrt(g / l - a * a * 60 * 60 / (2 * l * l));
    CHECK_THAT(std::log(largest_modulus(below[0])) / below[0].period, WithinRel(kappa, 0.05));
}

TEST_CASE("floquet: the Kapitza pendulum's bottom and top, without an equilibrium line", "[floquet]")
{
    const std::vector<floquet_point> both = floquet_of(
        "parameters m g l a gamma\ncoordinates phi\n"
        "point bob mass m at (l*sin(phi), a*cos(gamma*t) - l*cos(phi))\n"
        "gravity g along (0, -1)\nvalues m = 1, g = 9.81, l = 1, a = 0.05, gamma = 120\n");
    REQUIRE(both.size() == 2);
    CHECK(both[0].point[0].is_zero());
    CHECK(both[0].stable);
    CHECK(both[1].point[0].is_equal(GiNaC::Pi));
    CHECK(both[1].stable);
    // Hamiltonian: the multipliers of each point multiply to det Φ(T) = 1.
    for (const floquet_point& f : both)
        CHECK_THAT(std::abs(f.multipliers[0] * f.multipliers[1] - 1.0), WithinAbs(0, 1e-9));
}

TEST_CASE("floquet: the Mathieu equation's first instability tongue", "[floquet]")
{
    // x'' + (a − 2e cos 2t) x = 0 is unstable for 1 − e − e²/8 < a < 1 + e − e²/8 (small e);
    // at e = 0.1 that is 0.89875 < a < 1.09875. Inside, at a = 1, the growth per period π
    // is e^{π e/2} (first order in e).
    const double e = 0.1;
    const std::vector<floquet_point> inside = floquet_of(mathieu(1.0, e));
    REQUIRE(inside.size() == 1);
    CHECK_FALSE(inside[0].stable);
    CHECK_THAT(inside[0].period, WithinRel(M_PI, 1e-12));
    CHECK_THAT(largest_modulus(inside[0]), WithinRel(std::exp(M_PI * e / 2), 0.01));
    CHECK_FALSE(floquet_of(mathieu(1.08, e))[0].stable);
    CHECK_FALSE(floquet_of(mathieu(0.92, e))[0].stable);
    CHECK(floquet_of(mathieu(1.12, e))[0].stable);
    CHECK(floquet_of(mathieu(0.88, e))[0].stable);
    CHECK(floquet_of(mathieu(0.75, e))[0].stable);
}

TEST_CASE("floquet: a constant rate gives exp(A T)", "[floquet]")
{
    // x' = y, y' = −4 x: Φ(T) = rotation by 2T in the scaled phase plane, trace 2 cos 2T.
    const double period = 1.3;
    const std::vector<double> phi = monodromy(
        2,
        [](double, double* a) {
            a[0] = 0;
            a[1] = 1;
            a[2] = -4;
            a[3] = 0;
        },
        period);
    CHECK_THAT(phi[0], WithinAbs(std::cos(2 * period), 1e-10));
    CHECK_THAT(phi[1], WithinAbs(std::sin(2 * period) / 2, 1e-10));
    CHECK_THAT(phi[2], WithinAbs(-2 * std::sin(2 * period), 1e-10));
    CHECK_THAT(phi[3], WithinAbs(std::cos(2 * period), 1e-10));
}

TEST_CASE("floquet: the common period of several drive frequencies", "[floquet]")
{
    const GiNaC::possymbol w("w"), v("v");
    CHECK_THAT(common_period({2 * w, 3 * w}, {{w, 1}}), WithinRel(2 * M_PI, 1e-14));
    CHECK_THAT(common_period({w, v}, {{w, 2}, {v, 3}}), WithinRel(2 * M_PI, 1e-14));
    CHECK_THAT(common_period({w, v}, {{w, 0.5}, {v, 1.5}}), WithinRel(4 * M_PI, 1e-14));
    REQUIRE_THROWS_WITH(common_period({w, v}, {{w, 1}, {v, GiNaC::sqrt(GiNaC::ex(2))}}),
                        Catch::Contains("not periodic"));
}

TEST_CASE("floquet: errors", "[floquet]")
{
    REQUIRE_THROWS_WITH(analyze(load("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n"
                                     "values m = 1, k = 1\n"),
                                {product::floquet}),
                        Catch::Contains("needs an L that depends on t"));
    REQUIRE_THROWS_WITH(analyze(load("parameters a\ncoordinates x\nL = 1/2*x'^2 - 1/2*(a + t)*x^2\n"
                                     "values a = 1\n"),
                                {product::floquet}),
                        Catch::Contains("not periodic"));
    // A support whose height is √(cos γt − 2), never real: the linearization is NaN from
    // t = 0 on, which is said as such rather than as a collapsing step size.
    REQUIRE_THROWS_WITH(analyze(load("parameters m g l a gamma\ncoordinates phi\n"
                                     "point bob mass m at (l*sin(phi), a*sqrt(cos(gamma*t) - 2) - l*cos(phi))\n"
                                     "gravity g along (0, -1)\nequilibrium phi = pi\n"
                                     "values m = 1, g = 9.81, l = 1, a = 0.05, gamma = 120\n"),
                                {product::floquet}),
                        Catch::Contains("the linearized equations are not finite at t = 0"));
}

TEST_CASE("floquet: verified against the nonlinear flow, and a wrong multiplier is caught", "[floquet][verification]")
{
    for (const std::string& text : {kapitza(120), kapitza(60), mathieu(1.0, 0.1)}) {
        const model scene = load(text);
        const analysis result = analyze(scene, {product::floquet});
        REQUIRE(result.floquet);
        REQUIRE(result.verification);
        bool found = false;
        for (const verification_entry& e : result.verification->entries)
            if (e.item == "floquet") {
                INFO(e.how);
                CHECK(e.checked);
                found = true;
            }
        CHECK(found);

        // One multiplier moved by 1 % (its partner kept, as a wrong linearization would not):
        // the characteristic polynomial no longer matches the flow's.
        std::vector<floquet_point> wrong = *result.floquet;
        wrong[0].multipliers[0] *= 1.01;
        try {
            verify_floquet(scene, *result.equations, wrong);
            FAIL("a wrong multiplier passed verification");
        } catch (const computation_error& e) {
            CHECK_THAT(std::string(e.what()), Catch::Matchers::Contains("verification failed: floquet"));
        }
    }
}
