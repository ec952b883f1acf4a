// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_harmonic.cpp
 *  Tests of harmonic polynomials: conversion both ways, the product-to-sum formulas
 *  and the derivatives against numeric evaluation, and the shortcuts they give the
 *  canonical form, the grouping and the equations (the same expressions as before). */
#include "algebra/harmonic.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/lagrangian.h"
#include "algebra/simplify.h"
#include "scene/lower.h"
#include "helpers/scene_helpers.h"
#include "helpers/expressions.h"

#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

using namespace lagrange;
using lagrange_test::chain_scene;

using lagrange_test::same;
using lagrange_test::value_at;

namespace {

using GiNaC::ex;

/// Angles a, b, c and other symbols: a parameter k and velocities.
struct symbols {
    GiNaC::realsymbol a{"a"}, b{"b"}, c{"c"}, a_dot{"a_dot"}, b_dot{"b_dot"}, c_dot{"c_dot"}, t{"t"};
    GiNaC::possymbol k{"k"}, m{"m"};
    GiNaC::lst angles{a, b, c};

    /// A space over the angles and all other symbols.
    harmonic_space space() const
    {
        harmonic_space s(angles);
        for (const ex& x : {ex(a_dot), ex(b_dot), ex(c_dot), ex(t), ex(k), ex(m)})
            s.add_symbol(x);
        return s;
    }

    GiNaC::exmap random_point(std::mt19937& random) const
    {
        std::uniform_real_distribution<double> uniform(-1.5, 1.5);
        GiNaC::exmap at;
        for (const ex& x : {ex(a), ex(b), ex(c), ex(a_dot), ex(b_dot), ex(c_dot), ex(t)})
            at[x] = uniform(random);
        at[k] = 1.7 + 0.5 * uniform(random);
        at[m] = 2.3 + 0.5 * uniform(random);
        return at;
    }

    /// A random expression: sums of products of symbol powers and sin/cos of small
    /// integer combinations of the angles.
    ex random_expression(std::mt19937& random, int terms) const
    {
        std::uniform_int_distribution<int> small(-2, 2), pick(0, 5), coefficient(-5, 5);
        const ex others[] = {a_dot, b_dot, c_dot, t, k, a};
        ex sum = 0;
        for (int i = 0; i < terms; ++i) {
            ex term = GiNaC::numeric(coefficient(random), 1 + pick(random));
            term *= GiNaC::pow(others[pick(random)], 1 + pick(random) % 3);
            const ex argument = small(random) * a + small(random) * b + small(random) * c;
            if (!argument.is_zero())
                term *= pick(random) % 2 == 0 ? GiNaC::cos(argument) : GiNaC::sin(argument);
            sum += term;
        }
        return sum;
    }
};

/// The kinetic energy of a planar chain of `links` links, built from the point velocities.
ex chain_kinetic_energy(int links, GiNaC::lst& angles)
{
    ex kinetic = 0, x_dot = 0, y_dot = 0;
    for (int k = 0; k < links; ++k) {
        const std::string i = std::to_string(k);
        const GiNaC::realsymbol q("q" + i), q_dot("q" + i + "_dot");
        const GiNaC::possymbol l("l" + i), m("m" + i);
        angles.append(q);
        x_dot += l * GiNaC::cos(q) * q_dot;
        y_dot += l * GiNaC::sin(q) * q_dot;
        kinetic += GiNaC::numeric(1, 2) * m * (GiNaC::pow(x_dot, 2) + GiNaC::pow(y_dot, 2));
    }
    return kinetic;
}

} // namespace

TEST_CASE("harmonic: round trip from GiNaC and back keeps the value", "[harmonic]")
{
    const symbols s;
    const harmonic_space space = s.space();
    const ex table[] = {
        0,
        GiNaC::numeric(-3, 7),
        s.k,
        s.a * s.a_dot,
        GiNaC::pow(s.k, -2) * s.a_dot,
        GiNaC::cos(s.a - s.b) * s.a_dot * s.b_dot,
        GiNaC::sin(s.b - s.a),
        GiNaC::cos(2 * s.a - 3 * s.c) * GiNaC::sin(s.a + s.b),
        GiNaC::pow(GiNaC::sin(s.a), 2) + GiNaC::pow(GiNaC::cos(s.a), 2),
        GiNaC::pow(s.k * GiNaC::cos(s.a) + s.m * GiNaC::sin(s.b), 3),
        (s.a + s.t) * (s.a - s.t) * GiNaC::cos(s.c),
    };
    for (const ex& e : table) {
        INFO(e);
        const std::optional<harmonic_polynomial> p = to_harmonic(e, space);
        REQUIRE(p);
        CHECK(trig_equal(to_ex(*p), e, s.angles));
        // The result is in canonical form already.
        CHECK(to_ex(*p).is_equal(trig_canonical_general(e, s.angles)));
    }
}

TEST_CASE("harmonic: what is not a harmonic polynomial does not convert", "[harmonic]")
{
    const symbols s;
    const harmonic_space space = s.space();
    const GiNaC::realsymbol stranger("stranger");
    const ex table[] = {
        GiNaC::sqrt(s.k),
        GiNaC::tan(s.a),
        GiNaC::pow(s.a, -1),
        GiNaC::pow(s.k + s.m, -1),
        GiNaC::cos(s.a / 2),
        GiNaC::cos(s.a + 1),
        GiNaC::cos(s.k),
        GiNaC::cos(s.a * s.b),
        GiNaC::exp(s.a_dot),
        GiNaC::numeric(0.5) * s.k,
        GiNaC::Pi * s.k,
        stranger,
    };
    for (const ex& e : table) {
        INFO(e);
        CHECK_FALSE(to_harmonic(e, space));
    }
    CHECK_THROWS_AS(harmonic_space(GiNaC::lst{s.a + s.b}), std::invalid_argument);
}

TEST_CASE("harmonic: products by the product-to-sum formulas agree numerically", "[harmonic]")
{
    const symbols s;
    const harmonic_space space = s.space();
    std::mt19937 random(20261121);
    for (int trial = 0; trial < 20; ++trial) {
        const ex x = s.random_expression(random, 4);
        const ex y = s.random_expression(random, 3);
        const std::optional<harmonic_polynomial> px = to_harmonic(x, space);
        const std::optional<harmonic_polynomial> py = to_harmonic(y, space);
        REQUIRE(px);
        REQUIRE(py);
        const ex product = to_ex(*px * *py);
        harmonic_polynomial sum = *px;
        sum += *py;
        harmonic_polynomial difference = *px;
        difference -= *py;
        for (int point = 0; point < 3; ++point) {
            const GiNaC::exmap at = s.random_point(random);
            const double vx = value_at(x, at);
            const double vy = value_at(y, at);
            CHECK_THAT(value_at(product, at), Catch::Matchers::WithinAbs(vx * vy, 1e-9));
            CHECK_THAT(value_at(to_ex(sum), at), Catch::Matchers::WithinAbs(vx + vy, 1e-9));
            CHECK_THAT(value_at(to_ex(difference), at), Catch::Matchers::WithinAbs(vx - vy, 1e-9));
        }
        // Canonical: no term multiplies two harmonics, and x − x is zero.
        CHECK(product.is_equal(trig_canonical_general(x * y, s.angles)));
        harmonic_polynomial zero = *px;
        zero -= *px;
        CHECK(zero.is_zero());
    }
}

TEST_CASE("harmonic: derivatives agree with finite differences", "[harmonic][finite-difference]")
{
    const symbols s;
    const harmonic_space space = s.space();
    std::mt19937 random(7);
    const double h = 1e-5;
    for (int trial = 0; trial < 10; ++trial) {
        const ex e = s.random_expression(random, 5);
        const std::optional<harmonic_polynomial> p = to_harmonic(e, space);
        REQUIRE(p);
        const GiNaC::exmap at = s.random_point(random);
        for (const ex& variable : {ex(s.a), ex(s.b), ex(s.a_dot), ex(s.t), ex(s.k)}) {
            INFO(e << " by " << variable);
            GiNaC::exmap up = at, down = at;
            up[variable] = GiNaC::ex_to<GiNaC::numeric>(at.at(variable)).to_double() + h;
            down[variable] = GiNaC::ex_to<GiNaC::numeric>(at.at(variable)).to_double() - h;
            const double difference = (value_at(e, up) - value_at(e, down)) / (2 * h);
            const ex derivative = to_ex(p->derivative(*space.index_of(variable)));
            CHECK_THAT(value_at(derivative, at), Catch::Matchers::WithinAbs(difference, 1e-6));
            CHECK(trig_equal(derivative, e.diff(GiNaC::ex_to<GiNaC::symbol>(variable)), s.angles));
        }
    }
}

TEST_CASE("harmonic: the total time derivative follows a trajectory", "[harmonic][finite-difference]")
{
    // Along q(t) = q0 + v0 t + a0 t²/2 (so q̇ = v0 + a0 t, q̈ = a0), d/dt e(q, q̇, t) by
    // central differences in t equals the total derivative with q -> q̇ -> q̈, t -> 1.
    const GiNaC::realsymbol q("q"), p("p"), q_dot("q_dot"), p_dot("p_dot"), q_ddot("q_ddot"), p_ddot("p_ddot"),
        t("t");
    const GiNaC::possymbol k("k");
    harmonic_space space(GiNaC::lst{q, p});
    const std::size_t time = space.add_symbol(t);
    const std::vector<std::pair<std::size_t, std::size_t>> rates = {
        {space.add_symbol(q), space.add_symbol(q_dot)},
        {space.add_symbol(p), space.add_symbol(p_dot)},
        {space.add_symbol(q_dot), space.add_symbol(q_ddot)},
        {space.add_symbol(p_dot), space.add_symbol(p_ddot)},
    };
    space.add_symbol(k);
    const ex e = k * q_dot * q_dot * GiNaC::cos(q - 2 * p) + t * GiNaC::sin(p) * p_dot + q * q * t * t -
                 GiNaC::pow(k, -1) * GiNaC::cos(q) * q_dot * p_dot;
    const std::optional<harmonic_polynomial> polynomial = to_harmonic(e, space);
    REQUIRE(polynomial);
    const ex rate = to_ex(polynomial->total_derivative(rates, time));
    const double q0 = 0.3, v0 = -0.8, a0 = 0.6, p0 = -1.1, w0 = 0.4, b0 = -0.2, k0 = 1.3, t0 = 0.7;
    auto along = [&](double at_time) {
        const double s = at_time - t0;
        GiNaC::exmap point{{q, q0 + v0 * s + a0 * s * s / 2}, {q_dot, v0 + a0 * s},
                           {p, p0 + w0 * s + b0 * s * s / 2}, {p_dot, w0 + b0 * s},
                           {q_ddot, a0}, {p_ddot, b0}, {k, k0}, {t, at_time}};
        return point;
    };
    const double h = 1e-5;
    const double difference = (value_at(e, along(t0 + h)) - value_at(e, along(t0 - h))) / (2 * h);
    CHECK_THAT(value_at(rate, along(t0)), Catch::Matchers::WithinAbs(difference, 1e-6));
}

TEST_CASE("trig_canonical: the harmonic shortcut gives exactly the general result", "[harmonic][simplify]")
{
    const symbols s;
    GiNaC::lst chain_angles;
    const ex chain = chain_kinetic_energy(6, chain_angles);
    std::vector<std::pair<ex, GiNaC::lst>> table = {
        {GiNaC::pow(GiNaC::sin(s.a), 2) + GiNaC::pow(GiNaC::cos(s.a), 2), s.angles},
        {GiNaC::cos(s.a) * GiNaC::cos(s.b) + GiNaC::sin(s.a) * GiNaC::sin(s.b), s.angles},
        {GiNaC::cos(s.b - s.a) * s.k - GiNaC::cos(s.a - s.b) * s.m, s.angles},
        {GiNaC::pow(GiNaC::cos(s.a), 4) * s.a_dot / s.k, s.angles},
        {GiNaC::pow(s.a * GiNaC::sin(2 * s.b) + s.t, 2), s.angles},
        {GiNaC::sin(s.a) * GiNaC::sin(2 * s.a) * GiNaC::sin(3 * s.a), s.angles},
        {s.k * (s.m + s.a_dot), GiNaC::lst{}},
        {chain, chain_angles},
    };
    std::mt19937 random(3);
    for (int trial = 0; trial < 10; ++trial)
        table.emplace_back(s.random_expression(random, 6) * s.random_expression(random, 2), s.angles);
    for (const auto& [e, angles] : table) {
        INFO(e);
        CHECK(trig_canonical(e, angles).is_equal(trig_canonical_general(e, angles)));
    }
}

TEST_CASE("collect_compact: grouping a harmonic polynomial gives the same expression", "[harmonic][simplify]")
{
    const model scene = load_model(source_text("chain.lag", chain_scene(4)));
    const simplifier simplify = make_simplifier(scene);
    const lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
    harmonic_space space(scene.positions());
    REQUIRE(space.add_symbols_of(lagrangian.lagrangian_canonical));
    for (const coordinate& c : scene.coordinates) {
        space.add_symbol(c.velocity);
        space.add_symbol(c.acceleration);
    }
    const std::optional<harmonic_polynomial> l = to_harmonic(lagrangian.lagrangian_canonical, space);
    REQUIRE(l);
    for (const coordinate& c : scene.coordinates) {
        for (const harmonic_polynomial& p : {l->derivative(*space.index_of(c.velocity)),
                                             l->derivative(*space.index_of(c.position)), *l}) {
            const ex expanded = to_ex(p);
            CHECK(collect_compact(p, simplify.variables, simplify.angles)
                      .is_equal(collect_compact(expanded, simplify.variables, simplify.angles)));
            CHECK(collect_compact(p, simplify.variables).is_equal(collect_compact(expanded, simplify.variables)));
            CHECK(simplify.compact(p).is_equal(simplify.compact(expanded)));
        }
    }
}

TEST_CASE("simplifier: a harmonic polynomial where a rule fires goes through the rules", "[harmonic][simplify]")
{
    // The spherical pendulum's 1/4 m l² φ̇² (1 − cos 2θ) becomes 1/2 m l² sin²θ φ̇².
    const GiNaC::realsymbol theta("theta"), phi("phi"), phi_dot("phi_dot");
    const GiNaC::possymbol m("m"), l("l");
    simplifier simplify;
    simplify.angles = {theta, phi};
    simplify.variables = {phi_dot};
    simplify.rules = embedded_rules();
    harmonic_space space(simplify.angles);
    REQUIRE(space.add_symbols_of(m * l * phi_dot));
    const ex kinetic = GiNaC::numeric(1, 4) * m * l * l * phi_dot * phi_dot * (1 - GiNaC::cos(2 * theta));
    const std::optional<harmonic_polynomial> p = to_harmonic(kinetic, space);
    REQUIRE(p);
    const ex compact = simplify.compact(*p);
    CHECK(compact.is_equal(simplify.compact(to_ex(*p))));
    CHECK(compact.has(GiNaC::pow(GiNaC::sin(theta), 2)));
}

TEST_CASE("equations: the harmonic path gives the expressions of the GiNaC path", "[harmonic][equations]")
{
    for (const std::string& text :
         {chain_scene(2), chain_scene(5),
          std::string("parameters m l g\ncoordinates theta phi\n"
                      "point bob mass m at (l*sin(theta)*cos(phi), l*sin(theta)*sin(phi), -l*cos(theta))\n"
                      "gravity g along (0, 0, -1)\n"),
          std::string("parameters m q0 B\ncoordinates x y\nL = 1/2*m*(x'^2 + y'^2) + q0*B*(x*y' - y*x')/2 - m*x\n")}) {
        INFO(text);
        const model scene = load_model(source_text("test.lag", text));
        const simplifier simplify = make_simplifier(scene);
        const lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
        const std::vector<ex> equations = derive_equations(scene, lagrangian, simplify);
        REQUIRE(equations.size() == scene.coordinates.size());
        const ex& l = lagrangian.lagrangian_canonical;
        for (std::size_t i = 0; i < equations.size(); ++i) {
            const coordinate& c = scene.coordinates[i];
            const ex by_ginac = time_derivative(differentiate(l, c.velocity), scene) - differentiate(l, c.position);
            CHECK(equations[i].is_equal(simplify.compact(by_ginac.expand())));
        }
    }
}
