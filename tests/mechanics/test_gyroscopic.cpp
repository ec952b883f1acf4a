// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_gyroscopic.cpp
 *  L = L2 + L1 + L0 and gyroscopic small oscillations against textbook closed forms: a
 *  charge in a uniform magnetic field (cyclotron frequency and a zero mode), a harmonic
 *  Penning-type trap and the Penning trap proper (magnetron and modified cyclotron
 *  frequencies, stable only above ωc² = 2ωz²), the sleeping top (stable only above
 *  C²n² = 4AMgl), a bead on a hoop, a wire and a parabola turned at an imposed rate, the
 *  flyball governor, and the Kelvin–Tait–Chetaev verdicts. Symbolic results are compared
 *  with the closed forms at seeded random parameter points. */
#include "engine/analysis.h"
#include "mechanics/gyroscopic.h"
#include "verify/verify.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::symbol_of;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

using point = std::map<std::string, double>;

GiNaC::exmap substitution(const model& scene, const point& p)
{
    GiNaC::exmap m;
    for (const auto& [name, value] : p)
        m[symbol_of(scene, name)] = GiNaC::numeric(value);
    return m;
}

/// e at the point, a real number.
double value_at(const model& scene, const GiNaC::ex& e, const point& p)
{
    GiNaC::ex x = e.subs(substitution(scene, p)).evalf();
    INFO("expression " << e << " at the point: " << x);
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(x));
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(x);
    CHECK(std::abs(GiNaC::imag(n).to_double()) <= 1e-10 * (1 + std::abs(GiNaC::real(n).to_double())));
    return GiNaC::real(n).to_double();
}

/// The symbolic frequencies (ω, gyroscopic) at the point, ascending.
std::vector<double> omegas_at(const analysis& a, const point& p)
{
    REQUIRE(a.modes);
    REQUIRE(a.modes->closed_form);
    REQUIRE(a.modes->gyroscopic);
    std::vector<double> w;
    for (const GiNaC::ex& f : a.modes->frequencies)
        w.push_back(value_at(*a.scene, f, p));
    std::sort(w.begin(), w.end());
    return w;
}

void require_close(const std::vector<double>& computed, std::vector<double> expected, double tolerance = 1e-10)
{
    std::sort(expected.begin(), expected.end());
    REQUIRE(computed.size() == expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        INFO("frequency " << k << ": " << computed[k] << " against " << expected[k]);
        CHECK_THAT(computed[k], WithinAbs(expected[k], tolerance * (1 + std::abs(expected[k]))));
    }
}

/// The characteristic polynomial is `reference` times a nonzero number.
void require_proportional(const analysis& a, const GiNaC::ex& reference)
{
    REQUIRE(a.characteristic);
    GiNaC::ex ratio = (a.characteristic->polynomial / reference).normal();
    INFO("characteristic " << a.characteristic->polynomial << " against " << reference);
    CHECK(GiNaC::is_a<GiNaC::numeric>(ratio));
    CHECK(!ratio.is_zero());
}

const std::set<product> small_oscillations = {product::equilibrium, product::linearization, product::characteristic,
                                              product::frequencies};
const std::set<product> with_numeric = {product::equilibrium, product::linearization, product::characteristic,
                                        product::frequencies, product::numeric};

/// A scene and its analysis, which points into it: kept together.
struct analysed {
    model scene;
    analysis result;
};

std::unique_ptr<analysed> analyse(const std::string& text, const std::set<product>& products)
{
    auto a = std::make_unique<analysed>();
    a->scene = load(text);
    a->result = analyze(a->scene, products);
    return a;
}

std::mt19937 random_engine(20261124);
double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(random_engine); }

const std::string charge = "parameters m q0 B\ncoordinates x y\n"
                           "L = 1/2*m*(x'^2 + y'^2) + 1/2*q0*B*(x*y' - y*x')\n";

} // namespace

TEST_CASE("gyroscopic: L split by degree, U = V minus the velocity-free part of T", "[gyroscopic]")
{
    // A bead on a hoop turned at the imposed rate w: T holds ½ m R² w² sin² q.
    model scene = load("parameters m g R w\ncoordinates q\n"
                       "T = 1/2*m*R^2*(q'^2 + w^2*sin(q)^2)\nV = -m*g*R*cos(q)\n");
    simplifier simplify = make_simplifier(scene);
    lagrangian_result l = derive_lagrangian(scene, simplify);
    REQUIRE(l.split);
    CHECK(l.gyroscopic.is_zero());
    GiNaC::ex m = symbol_of(scene, "m"), g = symbol_of(scene, "g"), R = symbol_of(scene, "R"),
              w = symbol_of(scene, "w"), q = symbol_of(scene, "q"), q_dot = symbol_of(scene, "q_dot");
    GiNaC::ex kinetic = m * R * R * q_dot * q_dot / 2;
    GiNaC::ex effective = -m * g * R * GiNaC::cos(q) - m * R * R * w * w * GiNaC::pow(GiNaC::sin(q), 2) / 2;
    for (int k = 0; k < 5; ++k) {
        point p{{"m", uniform(0.5, 2)}, {"g", uniform(5, 15)}, {"R", uniform(0.5, 2)}, {"w", uniform(0.1, 5)},
                {"q", uniform(-3, 3)}, {"q_dot", uniform(-3, 3)}};
        CHECK_THAT(value_at(scene, l.kinetic, p), WithinAbs(value_at(scene, kinetic, p), 1e-12));
        CHECK_THAT(value_at(scene, l.potential, p), WithinAbs(value_at(scene, effective, p), 1e-12));
    }
    // A plain T = ½ m ẋ² with V: nothing changes.
    lagrangian_result plain =
        derive_lagrangian(load("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n"), simplify);
    CHECK(plain.gyroscopic.is_zero());
}

TEST_CASE("gyroscopic: charge in a uniform magnetic field, cyclotron frequency and a zero mode", "[gyroscopic]")
{
    model scene = load(charge + "equilibrium x = 0, y = 0\nvalues m = 2, q0 = 3, B = 0.5\n");
    analysis a = analyze(scene, with_numeric);
    GiNaC::ex m = symbol_of(scene, "m"), q0 = symbol_of(scene, "q0"), B = symbol_of(scene, "B");
    // G_xy = ∂a_y/∂x − ∂a_x/∂y = q0 B with a = ½ q0 B (−y, x).
    REQUIRE(a.linearization);
    REQUIRE(a.linearization->has_gyroscopic());
    CHECK((a.linearization->gyroscopic(0, 1) - q0 * B).normal().is_zero());
    CHECK((a.linearization->gyroscopic(1, 0) + q0 * B).normal().is_zero());
    GiNaC::ex omega = a.characteristic->omega;
    require_proportional(a, GiNaC::pow(omega, 2) * (m * m * GiNaC::pow(omega, 2) - q0 * q0 * B * B));
    CHECK(a.equilibria->points.at(a.equilibria->chosen).kind == stability::marginal);
    for (int k = 0; k < 5; ++k) {
        point p{{"m", uniform(0.5, 3)}, {"q0", uniform(0.5, 3)}, {"B", uniform(0.1, 4)}};
        require_close(omegas_at(a, p), {0, p["q0"] * p["B"] / p["m"]});
    }
    REQUIRE(a.numeric);
    const numeric_modes& n = a.numeric->front();
    require_close(n.omega, {0, 3 * 0.5 / 2}, 1e-13);
    CHECK(n.stability == "marginal");
    CHECK(n.eigenvalues.size() == 4);
}

TEST_CASE("gyroscopic: Penning-type harmonic trap, √(ω0² + ωc²/4) ± ωc/2", "[gyroscopic]")
{
    model scene = load("parameters m q0 B k\ncoordinates x y\n"
                 "L = 1/2*m*(x'^2 + y'^2) + 1/2*q0*B*(x*y' - y*x') - 1/2*k*(x^2 + y^2)\n"
                 "values m = 1.5, q0 = 2, B = 1.25, k = 3\n");
    analysis a = analyze(scene, with_numeric);
    auto expected = [](const point& p) {
        double wc = p.at("q0") * p.at("B") / p.at("m"), w0 = std::sqrt(p.at("k") / p.at("m"));
        double center = std::sqrt(w0 * w0 + wc * wc / 4);
        return std::vector<double>{center - wc / 2, center + wc / 2};
    };
    for (int k = 0; k < 5; ++k) {
        point p{{"m", uniform(0.5, 3)}, {"q0", uniform(0.5, 3)}, {"B", uniform(0.1, 4)}, {"k", uniform(0.1, 5)}};
        require_close(omegas_at(a, p), expected(p));
    }
    // The closed form denests: no square root inside a square root.
    for (const GiNaC::ex& f : a.modes->frequencies)
        for (GiNaC::const_preorder_iterator i = f.preorder_begin(); i != f.preorder_end(); ++i)
            if (GiNaC::is_a<GiNaC::power>(*i) && i->op(1).is_equal(GiNaC::numeric(1, 2)))
                CHECK(!i->op(0).has(GiNaC::pow(GiNaC::wild(), GiNaC::numeric(1, 2))));
    CHECK(a.equilibria->points.at(a.equilibria->chosen).kind == stability::stable);
    const numeric_modes& n = a.numeric->front();
    require_close(n.omega, expected({{"m", 1.5}, {"q0", 2}, {"B", 1.25}, {"k", 3}}), 1e-13);
    CHECK(n.stability == "stable");
}

TEST_CASE("gyroscopic: Penning trap, stable only above ωc² = 2ωz²", "[gyroscopic]")
{
    // Radially the electric potential is a maximum (−k/4 (x² + y²)); the magnetic field
    // holds the charge: ω = ωc/2 ± √(ωc²/4 − ωz²/2) radially, ωz = √(k/m) axially.
    const std::string trap = "parameters m q0 B k\ncoordinates x y z\n"
                             "L = 1/2*m*(x'^2 + y'^2 + z'^2) + 1/2*q0*B*(x*y' - y*x') - k/2*(z^2 - (x^2 + y^2)/2)\n"
                             "equilibrium x = 0, y = 0, z = 0\n";
    model above = load(trap + "values m = 1, q0 = 1, B = 3, k = 2\n");
    analysis a = analyze(above, with_numeric);
    CHECK(a.equilibria->points.front().kind == stability::stable);
    CHECK(a.numeric->front().stability == "stable");
    for (int k = 0; k < 5; ++k) {
        double m = uniform(0.5, 2), k_ = uniform(0.5, 2), wz2 = k_ / m;
        double wc = std::sqrt(2 * wz2) * uniform(1.05, 3), q0 = uniform(0.5, 2), B = wc * m / q0;
        point p{{"m", m}, {"q0", q0}, {"B", B}, {"k", k_}};
        double root = std::sqrt(wc * wc / 4 - wz2 / 2);
        require_close(omegas_at(a, p), {std::sqrt(wz2), wc / 2 - root, wc / 2 + root});
    }
    model below = load(trap + "values m = 1, q0 = 1, B = 1.9, k = 2\n");
    analysis b = analyze(below, with_numeric);
    CHECK(b.equilibria->points.front().kind == stability::unstable);
    CHECK(b.numeric->front().stability == "unstable");
    // The symbolic verdict alone depends on the parameters.
    CHECK(analyse(trap, small_oscillations)->result.equilibria->points.front().kind == stability::unknown);
}

TEST_CASE("gyroscopic: sleeping top, stable only above C²n² = 4AMgl", "[gyroscopic]")
{
    // A symmetric top spinning at n about its upright axis, tilted by small x, y (θ² = x² + y²):
    // with the spin's momentum Cn fixed, L = ½A(ẋ² + ẏ²) − ½Cn(xẏ − yẋ) + ½Mgl(x² + y²)
    // near the top of U = Mgl cos θ; ω = (Cn ± √(C²n² − 4AMgl))/(2A).
    const std::string top = "parameters A C n M g l\ncoordinates x y\n"
                            "L = 1/2*A*(x'^2 + y'^2) - 1/2*C*n*(x*y' - y*x') + 1/2*M*g*l*(x^2 + y^2)\n"
                            "equilibrium x = 0, y = 0\n";
    auto fast = analyse((top + "values A = 1, C = 2, n = 3, M = 1, g = 9.81, l = 0.5\n"), with_numeric);
    CHECK(fast->result.equilibria->points.front().kind == stability::stable); // 36 > 19.62
    CHECK(fast->result.numeric->front().stability == "stable");
    auto slow = analyse((top + "values A = 1, C = 2, n = 2, M = 1, g = 9.81, l = 0.5\n"), with_numeric);
    CHECK(slow->result.equilibria->points.front().kind == stability::unstable); // 16 < 19.62
    CHECK(slow->result.numeric->front().stability == "unstable");
    for (int k = 0; k < 5; ++k) {
        double A = uniform(0.5, 2), C = uniform(0.5, 2), M = uniform(0.5, 2), g = 9.81, l = uniform(0.2, 1);
        double n = std::sqrt(4 * A * M * g * l) / C * uniform(1.05, 3);
        point p{{"A", A}, {"C", C}, {"n", n}, {"M", M}, {"g", g}, {"l", l}};
        double root = std::sqrt(C * C * n * n - 4 * A * M * g * l);
        require_close(omegas_at(fast->result, p), {(C * n - root) / (2 * A), (C * n + root) / (2 * A)});
    }
}

TEST_CASE("gyroscopic: bead on a hoop turned at an imposed rate", "[gyroscopic]")
{
    const std::string hoop = "parameters m g R w\ncoordinates q\n"
                             "T = 1/2*m*R^2*(q'^2 + w^2*sin(q)^2)\nV = -m*g*R*cos(q)\n";
    // The bottom: ω² = g/R − w², stable below w² = g/R and unstable above.
    auto bottom = analyse((hoop + "equilibrium q = 0\n"), small_oscillations);
    REQUIRE(bottom->result.modes->closed_form);
    for (int k = 0; k < 5; ++k) {
        point p{{"m", uniform(0.5, 2)}, {"g", uniform(5, 15)}, {"R", uniform(0.5, 2)}, {"w", uniform(0.1, 5)}};
        CHECK_THAT(value_at(*bottom->result.scene, bottom->result.modes->frequencies.at(0), p),
                   WithinAbs(p["g"] / p["R"] - p["w"] * p["w"], 1e-10));
    }
    auto bottom_at = [&](double w) {
        return analyse((hoop + "values m = 1, g = 9.81, R = 1, w = " + std::to_string(w) + "\n"), small_oscillations);
    };
    auto slow = bottom_at(2);
    auto fast = bottom_at(5);
    auto kind_at_bottom = [](const analysis& a) {
        for (const equilibrium_point& p : a.equilibria->points)
            if (p.position[0].is_zero())
                return p.kind;
        FAIL("no equilibrium at q = 0");
        return stability::unknown;
    };
    CHECK(kind_at_bottom(slow->result) != stability::unstable);
    CHECK(kind_at_bottom(fast->result) != stability::stable);
    // Off the axis, cos q0 = g/(R w²): ω² = w² − g²/(R² w²).
    auto off = analyse((hoop + "equilibrium q = acos(g/(R*w^2))\n"), small_oscillations);
    REQUIRE(off->result.modes->closed_form);
    for (int k = 0; k < 5; ++k) {
        double g = uniform(5, 15), R = uniform(0.5, 2), w = std::sqrt(g / R) * uniform(1.05, 3);
        point p{{"m", uniform(0.5, 2)}, {"g", g}, {"R", R}, {"w", w}};
        CHECK_THAT(value_at(*off->result.scene, off->result.modes->frequencies.at(0), p),
                   WithinAbs(w * w - g * g / (R * R * w * w), 1e-10));
    }
}

TEST_CASE("gyroscopic: bead on a turning wire is unstable, ω² = −w²", "[gyroscopic]")
{
    auto run = analyse(("parameters m w\ncoordinates r\nT = 1/2*m*(r'^2 + w^2*r^2)\n"), small_oscillations);
    const analysis& a = run->result;
    CHECK(a.equilibria->points.at(a.equilibria->chosen).kind == stability::unstable);
    REQUIRE(a.modes->closed_form);
    GiNaC::ex w = symbol_of(*a.scene, "w");
    CHECK((a.modes->frequencies.at(0) + w * w).normal().is_zero());
}

TEST_CASE("gyroscopic: flyball governor", "[gyroscopic]")
{
    // Two balls m on arms a hinged on a shaft turned at w, a collar M below: cos θ0 =
    // (m + M) g/(m a w²) and ω² = m w² sin²θ0/(m + 2 M sin²θ0) (Goldstein).
    auto run = analyse(("parameters m M a g w\ncoordinates th\n"
                              "T = m*a^2*(th'^2 + w^2*sin(th)^2) + 2*M*a^2*sin(th)^2*th'^2\n"
                              "V = -2*(m + M)*g*a*cos(th)\n"
                              "equilibrium th = acos((m + M)*g/(m*a*w^2))\n"),
                         small_oscillations);
    const analysis& a = run->result;
    REQUIRE(a.modes->closed_form);
    for (int k = 0; k < 5; ++k) {
        double m = uniform(0.5, 2), M = uniform(0.5, 2), g = 9.81, len = uniform(0.2, 1);
        double w = std::sqrt((m + M) * g / (m * len)) * uniform(1.05, 3);
        double c = (m + M) * g / (m * len * w * w), s2 = 1 - c * c;
        point p{{"m", m}, {"M", M}, {"a", len}, {"g", g}, {"w", w}};
        CHECK_THAT(value_at(*a.scene, a.modes->frequencies.at(0), p),
                   WithinRel(m * w * w * s2 / (m + 2 * M * s2), 1e-10));
    }
    // U'' = 2 m a² w² sin²θ0 ≥ 0; positive only where the equilibrium exists (cos θ0 < 1).
    CHECK(a.equilibria->points.front().kind != stability::unstable);
}

TEST_CASE("gyroscopic: bead on a spinning parabola", "[gyroscopic]")
{
    // On the wire z = c r² turned at w: ω² = 2gc − w² at the vertex.
    auto wire = analyse(("parameters m g c w\ncoordinates r\n"
                                 "T = 1/2*m*(r'^2*(1 + 4*c^2*r^2) + w^2*r^2)\nV = m*g*c*r^2\n"),
                            small_oscillations);
    REQUIRE(wire->result.modes->closed_form);
    for (int k = 0; k < 5; ++k) {
        point p{{"m", uniform(0.5, 2)}, {"g", 9.81}, {"c", uniform(0.1, 2)}, {"w", uniform(0.1, 5)}};
        CHECK_THAT(value_at(*wire->result.scene, wire->result.modes->frequencies.at(0), p),
                   WithinAbs(2 * p["g"] * p["c"] - p["w"] * p["w"], 1e-10));
    }
    // Free on the surface, seen from axes turning at w: the Coriolis terms hold the bead
    // even where U = m(gc − w²/2)(x² + y²) has a maximum; ω = |√(2gc) ± w|.
    const std::string bowl = "parameters m g c w\ncoordinates x y\n"
                             "T = 1/2*m*((x' - w*y)^2 + (y' + w*x)^2 + (2*c*(x*x' + y*y'))^2)\n"
                             "V = m*g*c*(x^2 + y^2)\nequilibrium x = 0, y = 0\n";
    auto fast = analyse((bowl + "values m = 1, g = 9.81, c = 0.5, w = 5\n"), with_numeric);
    REQUIRE(fast->result.linearization->has_gyroscopic());
    CHECK(fast->result.equilibria->points.front().kind == stability::stable);
    CHECK(fast->result.numeric->front().stability == "stable");
    require_close(fast->result.numeric->front().omega, {5 - std::sqrt(9.81), 5 + std::sqrt(9.81)}, 1e-13);
    for (int k = 0; k < 5; ++k) {
        point p{{"m", uniform(0.5, 2)}, {"g", 9.81}, {"c", uniform(0.1, 2)}, {"w", uniform(0.1, 5)}};
        double root = std::sqrt(2 * p["g"] * p["c"]);
        require_close(omegas_at(fast->result, p), {std::abs(root - p["w"]), root + p["w"]});
    }
}

TEST_CASE("gyroscopic: Kelvin–Tait–Chetaev verdicts", "[gyroscopic]")
{
    // One negative stiffness (an odd index) is unstable whatever G.
    auto odd = analyse(("parameters m k h\ncoordinates x y\n"
                                "L = 1/2*m*(x'^2 + y'^2) + h*x*y' + 1/2*k*x^2 - 1/2*k*y^2\n"
                                "equilibrium x = 0, y = 0\n"),
                           small_oscillations);
    CHECK(odd->result.equilibria->points.front().kind == stability::unstable);
    // A minimum stays stable whatever G.
    auto minimum = analyse(("parameters m k h\ncoordinates x y\n"
                                    "L = 1/2*m*(x'^2 + y'^2) + h*x*y' - 1/2*k*(x^2 + 2*y^2)\n"
                                    "equilibrium x = 0, y = 0\n"),
                               small_oscillations);
    CHECK(minimum->result.equilibria->points.front().kind == stability::stable);
}

TEST_CASE("gyroscopic: verification checks G, the polynomial and ω against L as built", "[gyroscopic]")
{
    auto run = analyse("parameters m q0 B k\ncoordinates x y\n"
                       "L = 1/2*m*(x'^2 + y'^2) + 1/2*q0*B*(x*y' - y*x') - 1/2*k*(x^2 + y^2)\n"
                       "equilibrium x = 0, y = 0\n",
                       small_oscillations);
    const analysis& a = run->result;
    verification_input input{&*a.lagrangian, nullptr, &*a.equilibria, &*a.linearization, &*a.characteristic,
                             &*a.modes};
    verification_result checked = verify_results(run->scene, input, small_oscillations);
    REQUIRE(checked.entries.size() == 4);
    for (const verification_entry& e : checked.entries)
        CHECK(e.checked);
    // G with the wrong sign, or a polynomial without G, is caught.
    linearization_result flipped = *a.linearization;
    flipped.gyroscopic = GiNaC::ex_to<GiNaC::matrix>(flipped.gyroscopic.mul_scalar(-1));
    input.linearization = &flipped;
    REQUIRE_THROWS_AS(verify_results(run->scene, input, small_oscillations), computation_error);
    linearization_result without = *a.linearization;
    without.gyroscopic = GiNaC::matrix(2, 2);
    characteristic_result plain = characteristic_polynomial(run->scene, without);
    input.linearization = &*a.linearization;
    input.characteristic = &plain;
    REQUIRE_THROWS_AS(verify_results(run->scene, input, small_oscillations), computation_error);
}

TEST_CASE("gyroscopic: symbolic modes and asymptotics are refused, not left empty", "[gyroscopic]")
{
    model scene = load(charge + "equilibrium x = 0, y = 0\n");
    REQUIRE_THROWS_WITH(analyze(scene, {product::modes}), Catch::Matchers::Contains("the modes are complex"));
    analysis by_default = analyze(scene);
    REQUIRE(by_default.modes);
    CHECK(by_default.modes->gyroscopic);
    CHECK(by_default.modes->modes.empty());
    bool noted = false;
    for (const std::string& note : by_default.notes)
        noted = noted || note.find("modes and normal coordinates not computed") != std::string::npos;
    CHECK(noted);
}

TEST_CASE("gyroscopic: bead on a hoop and on a wire written with explicit t", "[gyroscopic]")
{
    // The positions turn with cos(w t), sin(w t); L is free of t, and its velocity-free part
    // of T (the centrifugal term) goes into U.
    const std::string hoop = "parameters m g R w\ncoordinates q\n"
                             "point P mass m at (R*sin(q)*cos(w*t), R*sin(q)*sin(w*t), -R*cos(q))\n"
                             "gravity g along (0, 0, -1)\n";
    auto bottom = analyse(hoop + "equilibrium q = 0\n", small_oscillations);
    REQUIRE(bottom->result.modes->closed_form);
    auto off = analyse(hoop + "equilibrium q = acos(g/(R*w^2))\n", small_oscillations);
    REQUIRE(off->result.modes->closed_form);
    for (int k = 0; k < 5; ++k) {
        double g = uniform(5, 15), R = uniform(0.5, 2), w = std::sqrt(g / R) * uniform(1.05, 3);
        point p{{"m", uniform(0.5, 2)}, {"g", g}, {"R", R}, {"w", w}};
        CHECK_THAT(value_at(bottom->scene, bottom->result.modes->frequencies.at(0), p),
                   WithinAbs(g / R - w * w, 1e-10 * w * w));
        CHECK_THAT(value_at(off->scene, off->result.modes->frequencies.at(0), p),
                   WithinAbs(w * w - g * g / (R * R * w * w), 1e-10 * w * w));
    }
    auto kind_at_bottom = [](const analysis& a) {
        for (const equilibrium_point& p : a.equilibria->points)
            if (p.position[0].is_zero())
                return p.kind;
        FAIL("no equilibrium at q = 0");
        return stability::unknown;
    };
    auto slow = analyse(hoop + "values m = 1, g = 9.81, R = 1, w = 2\n", {product::equilibrium});
    auto fast = analyse(hoop + "values m = 1, g = 9.81, R = 1, w = 5\n", {product::equilibrium});
    CHECK(kind_at_bottom(slow->result) == stability::stable);
    CHECK(kind_at_bottom(fast->result) == stability::unstable);

    auto wire = analyse("parameters m w\ncoordinates r\npoint P mass m at (r*cos(w*t), r*sin(w*t))\n",
                        small_oscillations);
    CHECK(wire->result.equilibria->points.at(wire->result.equilibria->chosen).kind == stability::unstable);
    GiNaC::ex w = symbol_of(wire->scene, "w");
    CHECK((wire->result.modes->frequencies.at(0) + w * w).normal().is_zero());
}
