// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_oscillations.cpp
 *  Equilibria, linearization, characteristic polynomial and symbolic modes against
 *  textbook closed forms, with numeric checks of Aᵀ T A = I and V a = ω² T a. */
#include "mechanics/asymptotic.h"
#include "mechanics/equilibrium.h"
#include "mechanics/lagrangian.h"
#include "mechanics/linearization.h"
#include "mechanics/modes.h"
#include "scene/lower.h"
#include "helpers/scene_helpers.h"
#include "helpers/expressions.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::symbol_of;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

using lagrange_test::same;
using lagrange_test::value_at;

namespace {

/// Everything the stages give for a scene, about the chosen equilibrium.
struct analysed {
    model scene;
    lagrangian_result lagrangian;
    equilibria_result equilibria;
    linearization_result linear;
    characteristic_result characteristic;
    modes_result modes;
    asymptotic_result asymptotic;
};

analysed analyse(const std::string& text)
{
    analysed a{load(text), {}, {}, {}, {GiNaC::possymbol("omega"), 0}, {}, {}};
    simplifier simplify = make_simplifier(a.scene);
    a.lagrangian = derive_lagrangian(a.scene, simplify);
    a.equilibria = find_equilibria(a.scene, a.lagrangian, simplify);
    a.linear = linearize(a.scene, a.lagrangian, a.equilibria.points[a.equilibria.chosen].position, simplify);
    a.characteristic = characteristic_polynomial(a.scene, a.linear);
    a.modes = symbolic_modes(a.scene, a.linear, a.characteristic);
    a.asymptotic = asymptotic_limit(a.scene, a.modes);
    return a;
}

/// Checks V a = W T a for every mode and Aᵀ T A = I for the normal coordinates at a numeric point.
void check_modes_numerically(const analysed& a, const GiNaC::exmap& point)
{
    std::size_t n = a.scene.coordinates.size();
    REQUIRE(a.modes.closed_form);
    REQUIRE(a.modes.frequencies.size() == n);
    REQUIRE(a.modes.modes.size() == n);
    REQUIRE(a.modes.normal_coordinates.size() == n);
    // columns of A: ζ_k = (Aᵀ T q)_k, so the coefficients of ζ_k are (T a_k)ᵀ
    for (std::size_t k = 0; k < n; ++k) {
        const std::vector<GiNaC::ex>& mode = a.modes.modes[k];
        for (std::size_t i = 0; i < n; ++i) {
            double residual = 0, scale = 0;
            for (std::size_t j = 0; j < n; ++j) {
                double v = value_at(a.linear.potential(i, j), point);
                double t = value_at(a.linear.kinetic(i, j), point);
                double w = value_at(a.modes.frequencies[k], point);
                double x = value_at(mode[j], point);
                residual += (v - w * t) * x;
                scale += std::abs(v * x) + std::abs(w * t * x);
            }
            CHECK_THAT(residual, WithinAbs(0, 1e-9 * (1 + scale)));
        }
    }
    // Aᵀ T A = I: recover a_k from ζ_k = (T a_k)ᵀ q as T⁻¹ (coefficients), numerically
    std::vector<std::vector<double>> coefficients(n, std::vector<double>(n));
    for (std::size_t k = 0; k < n; ++k) {
        GiNaC::ex zeta = a.modes.normal_coordinates[k].expand();
        for (std::size_t j = 0; j < n; ++j)
            coefficients[k][j] = value_at(zeta.coeff(a.scene.coordinates[j].position, 1), point);
    }
    GiNaC::matrix kinetic_inverse = GiNaC::ex_to<GiNaC::matrix>(a.linear.kinetic.subs(point)).inverse();
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t l = 0; l < n; ++l) {
            double product = 0; // c_kᵀ T⁻¹ c_l = a_kᵀ T a_l
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = 0; j < n; ++j)
                    product += coefficients[k][i] * value_at(kinetic_inverse(i, j), point) * coefficients[l][j];
            CHECK_THAT(product, WithinAbs(k == l ? 1.0 : 0.0, 1e-9));
        }
}

const char* homework_double_pendulum = R"(scene "Double pendulum: equal lengths, unequal masses"
parameters M m l g
coordinates theta phi
point upper mass M at (l*sin(theta), -l*cos(theta))
point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))
gravity g along (0, -1)
equilibrium theta = 0, phi = 0
ratio rho = m/M
limit rho -> 0
)";

} // namespace

TEST_CASE("oscillations: homework double pendulum, T and V and the characteristic polynomial", "[oscillations]")
{
    analysed a = analyse(homework_double_pendulum);
    GiNaC::ex M = symbol_of(a.scene, "M"), m = symbol_of(a.scene, "m"), l = symbol_of(a.scene, "l"),
              g = symbol_of(a.scene, "g");
    REQUIRE(a.equilibria.given);
    REQUIRE(a.equilibria.points.size() == 1);
    CHECK(a.equilibria.points[0].kind == stability::stable);
    CHECK(same(a.linear.kinetic(0, 0), (M + m) * l * l));
    CHECK(same(a.linear.kinetic(0, 1), m * l * l));
    CHECK(same(a.linear.kinetic(1, 0), m * l * l));
    CHECK(same(a.linear.kinetic(1, 1), m * l * l));
    CHECK(same(a.linear.potential(0, 0), (M + m) * g * l));
    CHECK(same(a.linear.potential(0, 1), 0));
    CHECK(same(a.linear.potential(1, 1), m * g * l));
    CHECK(a.characteristic.omega.get_name() == "omega");
    GiNaC::ex omega = a.characteristic.omega;
    GiNaC::ex expected = M * l * l * pow(omega, 4) - 2 * (M + m) * g * l * pow(omega, 2) + (M + m) * g * g;
    INFO(a.characteristic.polynomial);
    CHECK(same(a.characteristic.polynomial, expected));
}

TEST_CASE("oscillations: homework double pendulum, frequencies and modes", "[oscillations]")
{
    analysed a = analyse(homework_double_pendulum);
    GiNaC::ex M = symbol_of(a.scene, "M"), m = symbol_of(a.scene, "m"), l = symbol_of(a.scene, "l"),
              g = symbol_of(a.scene, "g"), rho = symbol_of(a.scene, "rho");
    REQUIRE(a.modes.closed_form);
    REQUIRE(a.modes.frequencies.size() == 2);
    GiNaC::ex root = sqrt(m * (M + m));
    INFO(a.modes.frequencies[0] << "  " << a.modes.frequencies[1]);
    CHECK(same(a.modes.frequencies[0], ((M + m) - root) * g / (M * l)));
    CHECK(same(a.modes.frequencies[1], ((M + m) + root) * g / (M * l)));
    // in rho: ω±² = [(1+ρ) ± √(ρ(1+ρ))] g/l
    REQUIRE(a.modes.frequencies_in_ratio.size() == 2);
    GiNaC::ex ratio_root = sqrt(rho * (1 + rho));
    INFO(a.modes.frequencies_in_ratio[0] << "  " << a.modes.frequencies_in_ratio[1]);
    CHECK(same(a.modes.frequencies_in_ratio[0], ((1 + rho) - ratio_root) * g / l));
    CHECK(same(a.modes.frequencies_in_ratio[1], ((1 + rho) + ratio_root) * g / l));
    // the faster mode is the antiphase one: a+ = (−√(m/(M+m)), 1), a− = (+√(m/(M+m)), 1)
    INFO(a.modes.modes[0][0] << ", " << a.modes.modes[0][1] << " | " << a.modes.modes[1][0] << ", "
                             << a.modes.modes[1][1]);
    CHECK(same(a.modes.modes[1][1], 1));
    CHECK(same(a.modes.modes[0][1], 1));
    GiNaC::exmap point{{M, 1}, {m, GiNaC::numeric(1, 100)}, {l, 2}, {g, GiNaC::numeric(981, 100)}};
    CHECK_THAT(value_at(a.modes.modes[1][0], point), WithinRel(-std::sqrt(0.01 / 1.01), 1e-12));
    CHECK_THAT(value_at(a.modes.modes[0][0], point), WithinRel(std::sqrt(0.01 / 1.01), 1e-12));
    CHECK(same(a.modes.modes[1][0], -sqrt(m * (M + m)) / (M + m)));
    REQUIRE(a.modes.modes_in_ratio.size() == 2);
    CHECK(same(a.modes.modes_in_ratio[1][0], -ratio_root / (1 + rho)));
    check_modes_numerically(a, point);
}

TEST_CASE("oscillations: homework double pendulum, the limit rho -> 0", "[oscillations]")
{
    analysed a = analyse(homework_double_pendulum);
    GiNaC::ex M = symbol_of(a.scene, "M"), l = symbol_of(a.scene, "l"), g = symbol_of(a.scene, "g"),
              rho = symbol_of(a.scene, "rho"), theta = symbol_of(a.scene, "theta"), phi = symbol_of(a.scene, "phi");
    CHECK(a.asymptotic.label == "rho -> 0");
    REQUIRE(a.asymptotic.frequencies.size() == 2);
    INFO(a.asymptotic.frequencies[0] << "  " << a.asymptotic.frequencies[1]);
    CHECK(same(a.asymptotic.frequencies[0], (1 - sqrt(rho)) * g / l));
    CHECK(same(a.asymptotic.frequencies[1], (1 + sqrt(rho)) * g / l));
    REQUIRE(a.asymptotic.modes.size() == 2);
    CHECK(same(a.asymptotic.modes[0][0], sqrt(rho)));
    CHECK(same(a.asymptotic.modes[0][1], 1));
    CHECK(same(a.asymptotic.modes[1][0], -sqrt(rho)));
    CHECK(same(a.asymptotic.modes[1][1], 1));
    // ζ− → l √(M/2) (θ + √ρ φ), ζ+ → −l √(M/2) (θ − √ρ φ) (the sign of a+ = (−√ρ, 1))
    REQUIRE(a.asymptotic.normal_coordinates.size() == 2);
    INFO(a.asymptotic.normal_coordinates[0] << "  " << a.asymptotic.normal_coordinates[1]);
    CHECK(same(a.asymptotic.normal_coordinates[0], l * sqrt(M / 2) * (theta + sqrt(rho) * phi)));
    CHECK(same(a.asymptotic.normal_coordinates[1], -l * sqrt(M / 2) * (theta - sqrt(rho) * phi)));
}

TEST_CASE("oscillations: equal-mass double pendulum from energies, (2 ∓ √2) g/l", "[oscillations]")
{
    analysed a = analyse(R"(parameters m l g
coordinates theta phi
T = m*l^2*theta'^2 + m*l^2*cos(theta-phi)*theta'*phi' + 1/2*m*l^2*phi'^2
V = -2*m*g*l*cos(theta) - m*g*l*cos(phi)
)");
    GiNaC::ex l = symbol_of(a.scene, "l"), g = symbol_of(a.scene, "g"), m = symbol_of(a.scene, "m");
    // found without an `equilibrium` line: the four combinations of 0 and π
    CHECK_FALSE(a.equilibria.given);
    REQUIRE(a.equilibria.points.size() == 4);
    int stable = 0, unstable = 0;
    for (const equilibrium_point& p : a.equilibria.points) {
        stable += p.kind == stability::stable;
        unstable += p.kind == stability::unstable;
    }
    CHECK(stable == 1);
    CHECK(unstable == 3);
    const equilibrium_point& chosen = a.equilibria.points[a.equilibria.chosen];
    CHECK(chosen.kind == stability::stable);
    CHECK(same(chosen.position[0], 0));
    CHECK(same(chosen.position[1], 0));
    REQUIRE(a.modes.frequencies.size() == 2);
    CHECK(same(a.modes.frequencies[0], (2 - sqrt(GiNaC::ex(2))) * g / l));
    CHECK(same(a.modes.frequencies[1], (2 + sqrt(GiNaC::ex(2))) * g / l));
    check_modes_numerically(a, {{m, 3}, {l, 2}, {g, 10}});
}

TEST_CASE("oscillations: two pendulums coupled by a spring", "[oscillations]")
{
    analysed a = analyse(R"(parameters m l g k
coordinates x1 x2
T = 1/2*m*l^2*x1'^2 + 1/2*m*l^2*x2'^2
V = -m*g*l*cos(x1) - m*g*l*cos(x2) + 1/2*k*l^2*(x1 - x2)^2
equilibrium x1 = 0, x2 = 0
)");
    GiNaC::ex m = symbol_of(a.scene, "m"), l = symbol_of(a.scene, "l"), g = symbol_of(a.scene, "g"),
              k = symbol_of(a.scene, "k");
    REQUIRE(a.modes.frequencies.size() == 2);
    CHECK(same(a.modes.frequencies[0], g / l));
    CHECK(same(a.modes.frequencies[1], g / l + 2 * k / m));
    CHECK(same(a.modes.modes[0][0], 1));  // in phase
    CHECK(same(a.modes.modes[1][0], -1)); // antiphase
    check_modes_numerically(a, {{m, 2}, {l, 3}, {g, 10}, {k, 5}});
}

TEST_CASE("oscillations: free linear three-mass molecule has a zero mode", "[oscillations]")
{
    analysed a = analyse(R"(parameters m M k
coordinates x1 x2 x3
T = 1/2*m*x1'^2 + 1/2*M*x2'^2 + 1/2*m*x3'^2
V = 1/2*k*(x2 - x1)^2 + 1/2*k*(x3 - x2)^2
)");
    GiNaC::ex m = symbol_of(a.scene, "m"), M = symbol_of(a.scene, "M"), k = symbol_of(a.scene, "k");
    REQUIRE(a.equilibria.points.size() == 1);
    CHECK(a.equilibria.points[0].kind == stability::marginal);
    REQUIRE(a.modes.frequencies.size() == 3);
    CHECK(same(a.modes.frequencies[0], 0));
    CHECK(same(a.modes.frequencies[1], k / m));
    CHECK(same(a.modes.frequencies[2], k / m * (1 + 2 * m / M)));
    for (const GiNaC::ex& x : a.modes.modes[0])
        CHECK(same(x, 1)); // translation
    CHECK(same(a.modes.modes[1][1], 0)); // the centre at rest
    CHECK(same(a.modes.modes[1][0], -a.modes.modes[1][2]));
    check_modes_numerically(a, {{m, 1}, {M, 3}, {k, 2}});
}

TEST_CASE("oscillations: pendulum on a sliding cart", "[oscillations]")
{
    analysed a = analyse(R"(parameters M m l g
coordinates x theta
point cart mass M at (x, 0)
point bob mass m at (x + l*sin(theta), -l*cos(theta))
gravity g along (0, -1)
)");
    GiNaC::ex M = symbol_of(a.scene, "M"), m = symbol_of(a.scene, "m"), l = symbol_of(a.scene, "l"),
              g = symbol_of(a.scene, "g");
    const equilibrium_point& chosen = a.equilibria.points[a.equilibria.chosen];
    CHECK(chosen.kind == stability::marginal);
    CHECK(same(chosen.position[1], 0));
    REQUIRE(a.modes.frequencies.size() == 2);
    CHECK(same(a.modes.frequencies[0], 0));
    CHECK(same(a.modes.frequencies[1], (M + m) * g / (M * l)));
    check_modes_numerically(a, {{M, 2}, {m, 1}, {l, 3}, {g, 10}});
}

TEST_CASE("oscillations: inverted pendulum is unstable with ω² < 0", "[oscillations]")
{
    analysed a = analyse(R"(parameters m l g
coordinates theta
point bob mass m at (l*sin(theta), -l*cos(theta))
gravity g along (0, -1)
equilibrium theta = Pi
)");
    GiNaC::ex l = symbol_of(a.scene, "l"), g = symbol_of(a.scene, "g");
    CHECK(a.equilibria.points[0].kind == stability::unstable);
    REQUIRE(a.modes.frequencies.size() == 1);
    CHECK(same(a.modes.frequencies[0], -g / l));
}

TEST_CASE("oscillations: bead on a rotating hoop", "[oscillations]")
{
    analysed a = analyse(R"(parameters m g R w
coordinates q
T = 1/2*m*R^2*q'^2
V = m*g*R*(1 - cos(q)) - 1/2*m*R^2*w^2*sin(q)^2
)");
    GiNaC::ex m = symbol_of(a.scene, "m"), g = symbol_of(a.scene, "g"), R = symbol_of(a.scene, "R"),
              w = symbol_of(a.scene, "w");
    REQUIRE(a.equilibria.points.size() == 3);
    bool bottom = false, top = false, side = false;
    for (const equilibrium_point& p : a.equilibria.points) {
        if (same(p.position[0], 0)) {
            bottom = true;
            CHECK(p.kind == stability::unknown); // V'' = m g R − m R² w²
        } else if (same(p.position[0], GiNaC::Pi)) {
            top = true;
            CHECK(p.kind == stability::unstable);
        } else {
            side = true;
            CHECK(same(p.position[0], acos(g / (R * w * w))));
            CHECK(p.kind == stability::unknown);
        }
    }
    CHECK((bottom && top && side));
    CHECK(same(a.equilibria.points[a.equilibria.chosen].position[0], 0));
    REQUIRE(a.modes.frequencies.size() == 1);
    CHECK(same(a.modes.frequencies[0], g / R - w * w));
}

TEST_CASE("oscillations: a cubic with three real roots in trigonometric form", "[oscillations]")
{
    // wall – m – m – m with three springs k: k/m times the roots of x³ − 5x² + 6x − 1
    analysed a = analyse(R"(parameters m k
coordinates x1 x2 x3
T = 1/2*m*(x1'^2 + x2'^2 + x3'^2)
V = 1/2*k*(x1^2 + (x2 - x1)^2 + (x3 - x2)^2)
)");
    GiNaC::ex m = symbol_of(a.scene, "m"), k = symbol_of(a.scene, "k");
    REQUIRE(a.modes.closed_form);
    REQUIRE(a.modes.frequencies.size() == 3);
    GiNaC::exmap point{{m, 1}, {k, 1}};
    const double pi = std::acos(-1.0);
    std::vector<double> expected;
    for (int j = 1; j <= 3; ++j)
        expected.push_back(2 - 2 * std::cos((2 * j - 1) * pi / 7));
    std::sort(expected.begin(), expected.end());
    for (std::size_t i = 0; i < 3; ++i)
        CHECK_THAT(value_at(a.modes.frequencies[i], point), WithinRel(expected[i], 1e-12));
    check_modes_numerically(a, point);
}

TEST_CASE("oscillations: errors", "[oscillations]")
{
    SECTION("an equilibrium line that is not one")
    {
        model scene = load(R"(parameters m l g
coordinates theta
point bob mass m at (l*sin(theta), -l*cos(theta))
gravity g along (0, -1)
equilibrium theta = 1
)");
        simplifier simplify = make_simplifier(scene);
        lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
        REQUIRE_THROWS_AS(find_equilibria(scene, lagrangian, simplify), computation_error);
        REQUIRE_THROWS_WITH(find_equilibria(scene, lagrangian, simplify), Catch::Matchers::Contains("not one"));
    }
    SECTION("a coordinate with no kinetic energy")
    {
        model scene = load(R"(parameters m k
coordinates x phi
T = 1/2*m*x'^2
V = 1/2*k*x^2 + 1/2*k*phi^2
)");
        simplifier simplify = make_simplifier(scene);
        lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
        equilibria_result equilibria = find_equilibria(scene, lagrangian, simplify);
        REQUIRE_THROWS_MATCHES(linearize(scene, lagrangian, equilibria.points[equilibria.chosen].position, simplify),
                               computation_error,
                               Catch::Matchers::Message(
                                   "coordinate `phi` has no kinetic energy at the equilibrium"));
    }
}

TEST_CASE("oscillations: homework double pendulum, normal coordinates in closed form", "[oscillations]")
{
    // By hand (independent of the engine): with s = √(m(M+m)), w = T a for a∓ = (±s/(M+m), 1)
    // gives ζ∓ = ±l √((M + m ± s)/2) (θ ± √(m/(M+m)) φ); in ρ: l √(M/2) √(1 + ρ ± √(ρ(1+ρ))) (…).
    analysed a = analyse(homework_double_pendulum);
    GiNaC::ex M = symbol_of(a.scene, "M"), m = symbol_of(a.scene, "m"), l = symbol_of(a.scene, "l"),
              g = symbol_of(a.scene, "g"), rho = symbol_of(a.scene, "rho"), theta = symbol_of(a.scene, "theta"),
              phi = symbol_of(a.scene, "phi");
    REQUIRE(a.modes.normal_coordinates.size() == 2);
    REQUIRE(a.modes.normal_coordinates_in_ratio.size() == 2);
    GiNaC::ex s = sqrt(m * (M + m)), r = sqrt(m / (M + m));
    GiNaC::ex slow = l * sqrt((M + m + s) / 2) * (theta + r * phi);
    GiNaC::ex fast = -l * sqrt((M + m - s) / 2) * (theta - r * phi);
    GiNaC::ex sr = sqrt(rho * (1 + rho)), rr = sqrt(rho / (1 + rho));
    GiNaC::ex slow_ratio = l * sqrt(M / 2) * sqrt(1 + rho + sr) * (theta + rr * phi);
    GiNaC::ex fast_ratio = -l * sqrt(M / 2) * sqrt(1 + rho - sr) * (theta - rr * phi);
    for (double ratio : {1e-6, 0.01, 1.0, 37.0, 1e6}) {
        GiNaC::exmap point{{M, GiNaC::numeric(3, 2)}, {m, GiNaC::numeric(ratio) * GiNaC::numeric(3, 2)},
                           {l, GiNaC::numeric(7, 10)}, {g, GiNaC::numeric(981, 100)}, {rho, GiNaC::numeric(ratio)}};
        for (const GiNaC::ex& q : {theta, phi}) {
            auto coefficient = [&](const GiNaC::ex& zeta) { return value_at(zeta.expand().coeff(q, 1), point); };
            INFO("rho = " << ratio << ", coefficient of " << q);
            CHECK_THAT(coefficient(a.modes.normal_coordinates[0]), WithinRel(coefficient(slow), 1e-12));
            CHECK_THAT(coefficient(a.modes.normal_coordinates[1]), WithinRel(coefficient(fast), 1e-12));
            CHECK_THAT(coefficient(a.modes.normal_coordinates_in_ratio[0]), WithinRel(coefficient(slow_ratio), 1e-12));
            CHECK_THAT(coefficient(a.modes.normal_coordinates_in_ratio[1]), WithinRel(coefficient(fast_ratio), 1e-12));
        }
        check_modes_numerically(a, point);
    }
    // the clean form: a coordinate-free factor times (θ ± r φ), the θ coefficient exactly ±1
    for (const GiNaC::ex& zeta : a.modes.normal_coordinates) {
        REQUIRE(GiNaC::is_a<GiNaC::mul>(zeta));
        GiNaC::ex combination = 1, scale = 1;
        for (const GiNaC::ex& factor : zeta)
            (factor.has(theta) || factor.has(phi) ? combination : scale) *= factor;
        CHECK(same(GiNaC::abs(combination.expand().coeff(theta, 1)), 1));
        CHECK_FALSE(scale.has(theta));
    }
}

TEST_CASE("oscillations: homework double pendulum, the beats as rho -> 0", "[oscillations]")
{
    // ω± = √(g/l) √(1 + ρ ± √(ρ(1+ρ))) = √(g/l) (1 ± √ρ/2 + O(ρ)): ω+ − ω− → √ρ √(g/l)
    analysed a = analyse(homework_double_pendulum);
    GiNaC::ex l = symbol_of(a.scene, "l"), g = symbol_of(a.scene, "g"), rho = symbol_of(a.scene, "rho");
    REQUIRE(a.asymptotic.beats.size() == 1);
    const beat& b = a.asymptotic.beats[0];
    CHECK(b.lower == 0);
    CHECK(b.upper == 1);
    INFO(b.difference << "   " << b.period);
    GiNaC::exmap point{{l, GiNaC::numeric(3, 2)}, {g, GiNaC::numeric(981, 100)}, {rho, GiNaC::numeric(1, 10000)}};
    double expected = std::sqrt(1e-4 * 9.81 / 1.5);
    CHECK_THAT(value_at(b.difference, point), WithinRel(expected, 1e-12));
    CHECK_THAT(value_at(b.period, point), WithinRel(2 * std::acos(-1.0) / expected, 1e-12));
    // against the exact frequencies: the relative error of the leading term is O(√ρ)
    for (double r : {1e-4, 1e-6, 1e-8}) {
        double plus = std::sqrt(9.81 / 1.5 * (1 + r + std::sqrt(r * (1 + r))));
        double minus = std::sqrt(9.81 / 1.5 * (1 + r - std::sqrt(r * (1 + r))));
        GiNaC::exmap at{{l, GiNaC::numeric(3, 2)}, {g, GiNaC::numeric(981, 100)}, {rho, GiNaC::numeric(r)}};
        CHECK_THAT(value_at(b.difference, at), WithinRel(plus - minus, 2 * std::sqrt(r)));
    }
    // the ω² keep the leading term outside: (1 ∓ √ρ)·g/l
    REQUIRE(a.asymptotic.frequency_series.size() == 2);
    CHECK(a.asymptotic.frequency_series[0].size() == 3);
    CHECK(same(a.asymptotic.frequency_series[0][0], g / l));
    CHECK(same(a.asymptotic.frequency_series[0][1], 1));
    CHECK(same(a.asymptotic.frequency_series[0][2], -sqrt(rho)));
    CHECK(same(a.asymptotic.frequency_series[1][2], sqrt(rho)));
}

TEST_CASE("oscillations: homework double pendulum, the limit rho -> oo", "[oscillations]")
{
    // ω∓² = [(1+ρ) ∓ √(ρ(1+ρ))] g/l with √(ρ(1+ρ)) = ρ + 1/2 − 1/(8ρ) + …: ω−² → g/(2l),
    // ω+² → 2ρ g/l; a∓ = (±√(ρ/(1+ρ)), 1) → (±1, 1); ζ− → l √M √ρ (θ + φ), ζ+ → −l √M (θ − φ)/2.
    std::string scene = homework_double_pendulum;
    scene.replace(scene.find("limit rho -> 0"), 14, "limit rho -> oo");
    analysed a = analyse(scene);
    GiNaC::ex M = symbol_of(a.scene, "M"), l = symbol_of(a.scene, "l"), g = symbol_of(a.scene, "g"),
              rho = symbol_of(a.scene, "rho"), theta = symbol_of(a.scene, "theta"), phi = symbol_of(a.scene, "phi");
    CHECK(a.asymptotic.label == "rho -> oo");
    REQUIRE(a.asymptotic.frequencies.size() == 2);
    INFO(a.asymptotic.frequencies[0] << "  " << a.asymptotic.frequencies[1]);
    CHECK(same(a.asymptotic.frequencies[0], g / (2 * l)));
    CHECK(same(a.asymptotic.frequencies[1], 2 * rho * g / l));
    REQUIRE(a.asymptotic.modes.size() == 2);
    CHECK(same(a.asymptotic.modes[0][0], 1));
    CHECK(same(a.asymptotic.modes[1][0], -1));
    REQUIRE(a.asymptotic.normal_coordinates.size() == 2);
    INFO(a.asymptotic.normal_coordinates[0] << "  " << a.asymptotic.normal_coordinates[1]);
    CHECK(same(a.asymptotic.normal_coordinates[0], l * sqrt(M) * sqrt(rho) * (theta + phi)));
    CHECK(same(a.asymptotic.normal_coordinates[1], -l * sqrt(M) * (theta - phi) / 2));
    CHECK(a.asymptotic.beats.empty()); // frequencies of different order: no beats
}

TEST_CASE("oscillations: rotating hoop, the bottom turns unstable and the side equilibrium takes over",
          "[oscillations]")
{
    const char* hoop = R"(parameters m g R w
coordinates q
T = 1/2*m*R^2*q'^2
V = m*g*R*(1 - cos(q)) - 1/2*m*R^2*w^2*sin(q)^2
)";
    analysed a = analyse(hoop);
    GiNaC::ex m = symbol_of(a.scene, "m"), g = symbol_of(a.scene, "g"), R = symbol_of(a.scene, "R"),
              w = symbol_of(a.scene, "w");
    // at the bottom ω² = g/R − w²: positive below w² = g/R, negative (a growth rate) above
    REQUIRE(a.modes.frequencies.size() == 1);
    CHECK(value_at(a.modes.frequencies[0], {{g, 9.81}, {R, 1}, {w, 2}}) > 0);
    CHECK(value_at(a.modes.frequencies[0], {{g, 9.81}, {R, 1}, {w, 4}}) < 0);
    // about the side equilibrium cos q0 = g/(R w²): V'' = m R² w² sin² q0, so ω² = w² − g²/(R² w²)
    simplifier simplify = make_simplifier(a.scene);
    const equilibrium_point* side = nullptr;
    for (const equilibrium_point& p : a.equilibria.points)
        if (!same(p.position[0], 0) && !same(p.position[0], GiNaC::Pi))
            side = &p;
    REQUIRE(side != nullptr);
    linearization_result linear = linearize(a.scene, a.lagrangian, side->position, simplify);
    characteristic_result characteristic = characteristic_polynomial(a.scene, linear);
    modes_result modes = symbolic_modes(a.scene, linear, characteristic);
    REQUIRE(modes.frequencies.size() == 1);
    INFO(modes.frequencies[0]);
    CHECK(same(modes.frequencies[0], w * w - g * g / (R * R * w * w)));
    CHECK(value_at(modes.frequencies[0], {{g, 9.81}, {R, 1}, {w, 4}, {m, 1}}) > 0);
}
