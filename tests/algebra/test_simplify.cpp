// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_simplify.cpp
 *  Tests of the canonical trigonometric form, the compact grouping and the simplifier. */
#include "algebra/simplify.h"
#include "helpers/expressions.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using lagrange_test::same;
using lagrange_test::value_at;

namespace {

using GiNaC::ex;
using GiNaC::exvector;
using GiNaC::wild;

/// True if some term of the expanded `e` multiplies two sines or cosines (or has one squared).
bool has_trig_product(const ex& e)
{
    auto trig_degree = [](const ex& factor) {
        auto is_trig = [](const ex& f) {
            return GiNaC::is_a<GiNaC::function>(f) &&
                   (GiNaC::is_the_function<GiNaC::sin_SERIAL>(f) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(f));
        };
        if (is_trig(factor))
            return 1;
        if (GiNaC::is_a<GiNaC::power>(factor) && is_trig(factor.op(0)))
            return 2;
        return 0;
    };
    const ex expanded = e.expand();
    exvector terms;
    if (GiNaC::is_a<GiNaC::add>(expanded))
        terms.assign(expanded.begin(), expanded.end());
    else
        terms.push_back(expanded);
    for (const ex& term : terms) {
        int degree = 0;
        if (GiNaC::is_a<GiNaC::mul>(term))
            for (const ex& factor : term)
                degree += trig_degree(factor);
        else
            degree = trig_degree(term);
        if (degree > 1)
            return true;
    }
    return false;
}

/// Symbols of a double pendulum: angles theta, phi of the two links (length l),
/// bob masses M and m, velocities as plain symbols.
struct double_pendulum {
    GiNaC::realsymbol theta{"theta"}, phi{"phi"}, theta_dot{"theta_dot"}, phi_dot{"phi_dot"};
    GiNaC::possymbol M{"M"}, m{"m"}, l{"l"};

    ex time_derivative(const ex& position) const
    {
        return position.diff(theta) * theta_dot + position.diff(phi) * phi_dot;
    }

    ex kinetic_energy() const
    {
        const ex x1 = l * GiNaC::sin(theta);
        const ex y1 = -l * GiNaC::cos(theta);
        const ex x2 = x1 + l * GiNaC::sin(phi);
        const ex y2 = y1 - l * GiNaC::cos(phi);
        const ex v1 = GiNaC::pow(time_derivative(x1), 2) + GiNaC::pow(time_derivative(y1), 2);
        const ex v2 = GiNaC::pow(time_derivative(x2), 2) + GiNaC::pow(time_derivative(y2), 2);
        return GiNaC::numeric(1, 2) * M * v1 + GiNaC::numeric(1, 2) * m * v2;
    }

    ex textbook_kinetic_energy() const
    {
        return GiNaC::numeric(1, 2) * (M + m) * l * l * theta_dot * theta_dot +
               m * l * l * GiNaC::cos(theta - phi) * theta_dot * phi_dot +
               GiNaC::numeric(1, 2) * m * l * l * phi_dot * phi_dot;
    }
};

} // namespace

TEST_CASE("trig_canonical: sin^2+cos^2", "[simplify]")
{
    const GiNaC::realsymbol theta("theta"), phi("phi");
    const GiNaC::possymbol m("m"), l("l");
    const GiNaC::lst angles{theta, phi};
    CHECK(lagrange::trig_canonical(GiNaC::pow(GiNaC::sin(theta), 2) + GiNaC::pow(GiNaC::cos(theta), 2), angles)
              .is_equal(1));
    const ex scaled = m * l * l * (GiNaC::pow(GiNaC::sin(theta - phi), 2) + GiNaC::pow(GiNaC::cos(phi - theta), 2));
    CHECK(same(lagrange::trig_canonical(scaled, angles), m * l * l));
}

TEST_CASE("trig_canonical: cos(x-y) and cos(y-x) are the same", "[simplify]")
{
    const GiNaC::realsymbol x("x"), y("y");
    const GiNaC::lst angles{x, y};
    const ex a = lagrange::trig_canonical(GiNaC::cos(x - y), angles);
    const ex b = lagrange::trig_canonical(GiNaC::cos(y - x), angles);
    CHECK(a.is_equal(b));
    CHECK(lagrange::trig_canonical(GiNaC::sin(y - x), angles).is_equal(-lagrange::trig_canonical(GiNaC::sin(x - y), angles)));
    CHECK(lagrange::trig_equal(GiNaC::cos(x - y), GiNaC::cos(y - x), angles));
    CHECK_FALSE(lagrange::trig_equal(GiNaC::sin(x - y), GiNaC::sin(y - x), angles));
}

TEST_CASE("trig_canonical: cos(a)cos(b)+sin(a)sin(b) is cos(a-b)", "[simplify]")
{
    const GiNaC::realsymbol a("a"), b("b");
    const GiNaC::lst angles{a, b};
    const ex c = lagrange::trig_canonical(GiNaC::cos(a) * GiNaC::cos(b) + GiNaC::sin(a) * GiNaC::sin(b), angles);
    CHECK(c.is_equal(lagrange::trig_canonical(GiNaC::cos(a - b), angles)));
    CHECK(same(c, GiNaC::cos(a - b)));
}

TEST_CASE("trig_canonical: half and double angles", "[simplify]")
{
    const GiNaC::realsymbol theta("theta");
    const GiNaC::lst angles{theta};
    CHECK(same(lagrange::trig_canonical(GiNaC::pow(GiNaC::sin(theta / 2), 2), angles),
               GiNaC::numeric(1, 2) - GiNaC::numeric(1, 2) * GiNaC::cos(theta)));
    CHECK(same(lagrange::trig_canonical(2 * GiNaC::sin(theta / 2) * GiNaC::cos(theta / 2), angles), GiNaC::sin(theta)));
    CHECK(same(lagrange::trig_canonical(GiNaC::pow(GiNaC::cos(theta), 2) - GiNaC::pow(GiNaC::sin(theta), 2), angles),
               GiNaC::cos(2 * theta)));
}

TEST_CASE("trig_canonical: constant offsets in the argument", "[simplify]")
{
    const GiNaC::realsymbol theta("theta");
    const GiNaC::possymbol alpha("alpha");
    const GiNaC::lst angles{theta};
    CHECK(same(lagrange::trig_canonical(GiNaC::cos(theta + GiNaC::Pi / 2), angles), -GiNaC::sin(theta)));
    CHECK(same(lagrange::trig_canonical(GiNaC::sin(theta + GiNaC::Pi), angles), -GiNaC::sin(theta)));
    // A parameter in the argument is one more angle (trig_canonical.h): compared by meaning.
    CHECK(lagrange::trig_equal(lagrange::trig_canonical(GiNaC::sin(theta + alpha), angles),
                               GiNaC::sin(theta) * GiNaC::cos(alpha) + GiNaC::cos(theta) * GiNaC::sin(alpha), angles));
}

TEST_CASE("trig_canonical: non-polynomial parts are atoms with canonical insides", "[simplify]")
{
    const GiNaC::realsymbol theta("theta");
    const GiNaC::lst angles{theta};
    const ex unit = GiNaC::pow(GiNaC::sin(theta), 2) + GiNaC::pow(GiNaC::cos(theta), 2);
    CHECK(same(lagrange::trig_canonical(GiNaC::sqrt(1 + unit), angles), GiNaC::sqrt(ex(2))));
    CHECK(same(lagrange::trig_canonical(GiNaC::tan(theta * unit), angles), GiNaC::tan(theta)));
    CHECK(lagrange::trig_canonical(GiNaC::sin(theta * theta), angles).is_equal(GiNaC::sin(theta * theta)));
    CHECK(same(lagrange::trig_canonical(GiNaC::exp(GiNaC::pow(GiNaC::cos(theta), 2)), angles),
               GiNaC::exp(GiNaC::numeric(1, 2) + GiNaC::numeric(1, 2) * GiNaC::cos(2 * theta))));
}

TEST_CASE("trig_canonical: coefficients with denominators", "[simplify]")
{
    const GiNaC::realsymbol theta("theta");
    const GiNaC::possymbol M("M"), m("m");
    const GiNaC::lst angles{theta};
    const ex split = (m / (M + m) + M / (M + m)) * GiNaC::pow(GiNaC::cos(theta), 2);
    CHECK(same(lagrange::trig_canonical(split, angles), GiNaC::numeric(1, 2) + GiNaC::cos(2 * theta) / 2));

    const ex cart = m * GiNaC::sin(theta) * GiNaC::cos(theta) / (M + m * GiNaC::pow(GiNaC::sin(theta), 2));
    const ex c = lagrange::trig_canonical(cart, angles);
    CHECK(lagrange::trig_canonical(c, angles).is_equal(c));
    const GiNaC::exmap point{{theta, 0.7}, {M, 2.0}, {m, 0.5}};
    CHECK_THAT(value_at(c, point), Catch::Matchers::WithinAbs(value_at(cart, point), 1e-12));
}

TEST_CASE("trig_canonical: idempotent", "[simplify]")
{
    const GiNaC::realsymbol theta("theta"), phi("phi"), w("w");
    const GiNaC::possymbol M("M"), m("m"), l("l");
    const GiNaC::lst angles{theta, phi};
    const std::vector<ex> cases = {
        GiNaC::pow(GiNaC::sin(theta), 2) * GiNaC::cos(phi - theta) * w,
        GiNaC::cos(-theta) + GiNaC::sin(-2 * phi) + GiNaC::cos(phi - theta),
        GiNaC::pow(GiNaC::sin(theta / 2 - phi / 3), 3) * m / (M + m),
        GiNaC::sin(theta + GiNaC::Pi / 3) * GiNaC::cos(phi),
        GiNaC::sin(theta) / (1 + GiNaC::cos(theta)),
        1 / (M + m * GiNaC::pow(GiNaC::sin(theta - phi), 2)),
        GiNaC::sqrt(l * (M + m) * GiNaC::pow(GiNaC::cos(theta), 2)) + GiNaC::tan(phi - theta),
    };
    for (const ex& e : cases) {
        const ex once = lagrange::trig_canonical(e, angles);
        INFO("e = " << e << ", canonical = " << once);
        CHECK(lagrange::trig_canonical(once, angles).is_equal(once));
        CHECK_FALSE(once.has(GiNaC::I));
    }
}

TEST_CASE("trig_canonical: double pendulum kinetic energy", "[simplify]")
{
    const double_pendulum p;
    const GiNaC::lst angles{p.theta, p.phi};
    const ex canonical = lagrange::trig_canonical(p.kinetic_energy(), angles);
    CHECK(same(canonical, lagrange::trig_canonical(p.textbook_kinetic_energy(), angles)));
    CHECK(same(canonical, p.textbook_kinetic_energy()));
    CHECK((canonical.has(GiNaC::cos(p.theta - p.phi)) || canonical.has(GiNaC::cos(p.phi - p.theta))));
    CHECK_FALSE(has_trig_product(canonical));
}

TEST_CASE("trig_canonical: agrees numerically on random trigonometric polynomials", "[simplify]")
{
    const GiNaC::realsymbol theta("theta"), phi("phi"), psi("psi");
    const GiNaC::possymbol k("k");
    const GiNaC::lst angles{theta, phi, psi};
    const std::vector<GiNaC::realsymbol> angle_symbols{theta, phi, psi};
    std::mt19937 random(20240601);
    std::uniform_int_distribution<int> small(-3, 3);
    std::uniform_int_distribution<int> count(1, 3);
    std::uniform_real_distribution<double> point(-3.0, 3.0);

    auto random_argument = [&]() {
        ex argument = 0;
        for (const auto& q : angle_symbols)
            argument += GiNaC::numeric(small(random), small(random) == 0 ? 2 : 1) * q;
        if (small(random) > 1)
            argument += GiNaC::Pi / 3;
        return argument;
    };
    for (int trial = 0; trial < 40; ++trial) {
        ex e = 0;
        for (int term = 0; term < 4; ++term) {
            ex product = small(random) * (small(random) > 0 ? ex(k) : ex(1));
            for (int f = count(random); f > 0; --f)
                product *= small(random) % 2 == 0 ? GiNaC::sin(random_argument()) : GiNaC::cos(random_argument());
            e += product;
        }
        const ex canonical = lagrange::trig_canonical(e, angles);
        INFO("e = " << e << ", canonical = " << canonical);
        CHECK_FALSE(has_trig_product(canonical));
        CHECK(lagrange::trig_canonical(canonical, angles).is_equal(canonical));
        for (int sample = 0; sample < 3; ++sample) {
            const GiNaC::exmap at{{theta, point(random)}, {phi, point(random)}, {psi, point(random)}, {k, 1.5}};
            CHECK_THAT(value_at(canonical, at), Catch::Matchers::WithinAbs(value_at(e, at), 1e-12));
        }
    }
}

TEST_CASE("trig_canonical: chain of links has one harmonic per term", "[simplify]")
{
    const int links = 6;
    std::vector<GiNaC::realsymbol> q, q_dot;
    std::vector<GiNaC::possymbol> length, mass;
    GiNaC::lst angles;
    for (int k = 0; k < links; ++k) {
        q.emplace_back("q" + std::to_string(k));
        q_dot.emplace_back("q" + std::to_string(k) + "_dot");
        length.emplace_back("l" + std::to_string(k));
        mass.emplace_back("m" + std::to_string(k));
        angles.append(q.back());
    }
    ex kinetic = 0, x_dot = 0, y_dot = 0;
    for (int k = 0; k < links; ++k) {
        x_dot += length[k] * GiNaC::cos(q[k]) * q_dot[k];
        y_dot += length[k] * GiNaC::sin(q[k]) * q_dot[k];
        kinetic += GiNaC::numeric(1, 2) * mass[k] * (x_dot * x_dot + y_dot * y_dot);
    }
    const ex canonical = lagrange::trig_canonical(kinetic, angles);
    CHECK_FALSE(has_trig_product(canonical));
    CHECK_FALSE(canonical.has(GiNaC::sin(wild())));
    GiNaC::exmap at;
    for (int k = 0; k < links; ++k) {
        at[q[k]] = 0.3 * k - 0.7;
        at[q_dot[k]] = 0.2 + 0.1 * k;
        at[length[k]] = 1.0 + 0.05 * k;
        at[mass[k]] = 2.0 - 0.1 * k;
    }
    CHECK_THAT(value_at(canonical, at), Catch::Matchers::WithinRel(value_at(kinetic, at), 1e-12));
}

TEST_CASE("collect_compact: groups by velocities with factored coefficients", "[simplify]")
{
    const double_pendulum p;
    const GiNaC::lst angles{p.theta, p.phi};
    const GiNaC::lst velocities{p.theta_dot, p.phi_dot};
    const ex canonical = lagrange::trig_canonical(p.kinetic_energy(), angles);
    const ex compact = lagrange::collect_compact(canonical, velocities);
    CHECK(same(compact, p.textbook_kinetic_energy()));
    CHECK(compact.has(p.M + p.m));
    CHECK(compact.has(p.m * p.l * p.l * GiNaC::cos(p.theta - p.phi) * p.theta_dot * p.phi_dot));
    CHECK(GiNaC::is_a<GiNaC::add>(compact));
    CHECK(compact.nops() == 3);
}

TEST_CASE("collect_compact: coefficients with trigonometric atoms and denominators", "[simplify]")
{
    const GiNaC::realsymbol theta("theta"), phi("phi"), theta_ddot("theta_ddot"), phi_ddot("phi_ddot");
    const GiNaC::possymbol M("M"), m("m"), l("l"), g("g");
    const GiNaC::lst accelerations{theta_ddot, phi_ddot};
    const ex equation = M * l * l * theta_ddot + m * l * l * theta_ddot +
                        m * l * l * GiNaC::cos(theta - phi) * phi_ddot + M * g * l * GiNaC::sin(theta) +
                        m * g * l * GiNaC::sin(theta) + g * l * phi_ddot / (M + m) + m * l * phi_ddot / (M + m);
    const ex compact = lagrange::collect_compact(equation, accelerations);
    CHECK((compact - equation).normal().is_zero());
    CHECK(compact.has((M + m) * l * l * theta_ddot));
    CHECK(compact.has(g * l * (M + m) * GiNaC::sin(theta)));
}

TEST_CASE("simplifier: spherical pendulum prints with sin^2", "[simplify]")
{
    const GiNaC::realsymbol theta("theta"), phi("phi"), theta_dot("theta_dot"), phi_dot("phi_dot");
    const GiNaC::possymbol m("m"), l("l");
    // Cartesian position on the sphere of radius l, velocities by the chain rule.
    const ex x = l * GiNaC::sin(theta) * GiNaC::cos(phi);
    const ex y = l * GiNaC::sin(theta) * GiNaC::sin(phi);
    const ex z = -l * GiNaC::cos(theta);
    auto time_derivative = [&](const ex& position) {
        return position.diff(theta) * theta_dot + position.diff(phi) * phi_dot;
    };
    const ex kinetic = GiNaC::numeric(1, 2) * m *
                       (GiNaC::pow(time_derivative(x), 2) + GiNaC::pow(time_derivative(y), 2) +
                        GiNaC::pow(time_derivative(z), 2));

    lagrange::simplifier simplify;
    simplify.angles = {theta, phi};
    simplify.variables = {theta_dot, phi_dot};
    simplify.rules = {
        {wild(1) - wild(1) * GiNaC::cos(2 * wild(0)), 2 * wild(1) * GiNaC::pow(GiNaC::sin(wild(0)), 2), "trig.rules"},
        {wild(1) + wild(1) * GiNaC::cos(2 * wild(0)), 2 * wild(1) * GiNaC::pow(GiNaC::cos(wild(0)), 2), "trig.rules"},
    };
    const ex result = simplify(kinetic);
    const ex textbook = GiNaC::numeric(1, 2) * m * l * l *
                        (theta_dot * theta_dot + GiNaC::pow(GiNaC::sin(theta), 2) * phi_dot * phi_dot);
    CHECK(same(result, textbook));
    CHECK(result.has(GiNaC::pow(GiNaC::sin(theta), 2)));
    CHECK_FALSE(result.has(GiNaC::cos(2 * theta)));
}
