// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_rigid_body.cpp
 *  Inertia tensors derived by integration, against closed forms and against an
 *  independent numeric quadrature in Cartesian coordinates; Euler's equations and
 *  their solutions; bodies in a Lagrangian. */
#include "scene/lower.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/lagrangian.h"
#include "bodies/euler.h"
#include "bodies/inertia.h"
#include "mechanics/top.h"
#include "helpers/scene_helpers.h"

#include <Eigen/Dense>
#include <boost/numeric/odeint.hpp>
#include "helpers/expressions.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>

using namespace lagrange;
using namespace lagrange_test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

const std::string body_header = "parameters M R l h a b c rho0 g\ncoordinates q\n";

struct loaded_body {
    model scene;
    inertia_result inertia;
};

loaded_body body_of(const std::string& line)
{
    loaded_body b{load(body_header + line + "\n"), {}};
    b.inertia = derive_inertia(b.scene.bodies.at(0));
    return b;
}

/// Checks the tensor is diag(d) exactly.
void require_diagonal(const inertia_result& inertia, const std::vector<GiNaC::ex>& d)
{
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) {
            INFO("I(" << i << "," << j << ") = " << inertia.tensor(i, j));
            CHECK(same(inertia.tensor(i, j), i == j ? d[i] : GiNaC::ex(0)));
        }
    CHECK(inertia.diagonal);
}

/// Gauss–Legendre nodes and weights on [-1, 1] (Newton on P_n), for the independent quadrature.
struct gauss_legendre {
    std::vector<double> nodes, weights;
    explicit gauss_legendre(int n)
    {
        for (int i = 1; i <= n; ++i) {
            double x = std::cos(M_PI * (i - 0.25) / (n + 0.5)), derivative = 0;
            for (int iteration = 0; iteration < 100; ++iteration) {
                double p0 = 1, p1 = x;
                for (int k = 2; k <= n; ++k) {
                    double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = n * (x * p1 - p0) / (x * x - 1);
                double step = p1 / derivative;
                x -= step;
                if (std::abs(step) < 1e-16)
                    break;
            }
            nodes.push_back(x);
            weights.push_back(2 / ((1 - x * x) * derivative * derivative));
        }
    }
    double integrate(double lo, double hi, const std::function<double(double)>& f) const
    {
        double sum = 0;
        for (std::size_t i = 0; i < nodes.size(); ++i)
            sum += weights[i] * f(lo + (hi - lo) * (nodes[i] + 1) / 2);
        return sum * (hi - lo) / 2;
    }
};

/// ∫∫∫ f(x, y, z) over x in [x0, x1], y in [y0(x), y1(x)], z in [z0(x,y), z1(x,y)]: Cartesian, nested.
double cartesian_integral(const std::function<double(double, double, double)>& f, double x0, double x1,
                          const std::function<std::pair<double, double>(double)>& y_limits,
                          const std::function<std::pair<double, double>(double, double)>& z_limits)
{
    static const gauss_legendre rule(40);
    return rule.integrate(x0, x1, [&](double x) {
        auto [y0, y1] = y_limits(x);
        return rule.integrate(y0, y1, [&](double y) {
            auto [z0, z1] = z_limits(x, y);
            return rule.integrate(z0, z1, [&](double z) { return f(x, y, z); });
        });
    });
}

double number(const GiNaC::ex& e, const GiNaC::exmap& values)
{
    return GiNaC::ex_to<GiNaC::numeric>(e.subs(values).evalf()).to_double();
}

} // namespace

TEST_CASE("inertia: the homework's stick, disk, ball and hollow sphere", "[rigid_body][inertia]")
{
    SECTION("stick along y, as the homework orients it: diag(ML²/12, 0, ML²/12)")
    {
        loaded_body b = body_of("body S stick(l) mass M axis y");
        GiNaC::ex m = symbol_of(b.scene, "M"), l = symbol_of(b.scene, "l");
        require_diagonal(b.inertia, {m * l * l / 12, 0, m * l * l / 12});
        // ρ = M/L δ(x)δ(z) and I_xx = ∫ M/L y² dy over [−L/2, L/2] (eqs. 15–16).
        const body_integral& xx = b.inertia.integrals.at(4);
        CHECK(xx.quantity == "xx");
        REQUIRE(xx.deltas.size() == 2);
        const rigid_body& stick = b.scene.bodies[0];
        CHECK(((same(xx.deltas[0], stick.x) && same(xx.deltas[1], stick.z)) ||
               (same(xx.deltas[0], stick.z) && same(xx.deltas[1], stick.x))));
        CHECK(same(xx.density, m / l));
        REQUIRE(xx.limits.size() == 1);
        CHECK(same(xx.limits[0].upper, l / 2));
        CHECK(same(xx.integrand, m / l * GiNaC::pow(xx.limits[0].variable, 2)));
    }
    SECTION("disk: diag(1/4, 1/4, 1/2) MR²")
    {
        loaded_body b = body_of("body D disk(R) mass M");
        GiNaC::ex m = symbol_of(b.scene, "M"), r = symbol_of(b.scene, "R");
        require_diagonal(b.inertia, {m * r * r / 4, m * r * r / 4, m * r * r / 2});
        CHECK(same(b.inertia.density, m / (GiNaC::Pi * r * r)));
        CHECK(b.inertia.coordinates == "cylindrical");
    }
    SECTION("ball: 2/5 MR²")
    {
        loaded_body b = body_of("body B ball(R) mass M");
        GiNaC::ex m = symbol_of(b.scene, "M"), r = symbol_of(b.scene, "R");
        GiNaC::ex i = GiNaC::numeric(2, 5) * m * r * r;
        require_diagonal(b.inertia, {i, i, i});
        CHECK(same(b.inertia.density, 3 * m / (4 * GiNaC::Pi * GiNaC::pow(r, 3))));
    }
    SECTION("hollow sphere: 2/3 MR²")
    {
        loaded_body b = body_of("body H sphere(R) mass M");
        GiNaC::ex m = symbol_of(b.scene, "M"), r = symbol_of(b.scene, "R");
        GiNaC::ex i = GiNaC::numeric(2, 3) * m * r * r;
        require_diagonal(b.inertia, {i, i, i});
        CHECK(b.inertia.integrals.at(4).deltas.size() == 1);
    }
}

TEST_CASE("inertia: ring, box, cylinder, cone, ellipsoid against closed forms", "[rigid_body][inertia]")
{
    const GiNaC::numeric half(1, 2), twelfth(1, 12);
    SECTION("ring: diag(1/2, 1/2, 1) MR²")
    {
        loaded_body b = body_of("body O ring(R) mass M");
        GiNaC::ex m = symbol_of(b.scene, "M"), r = symbol_of(b.scene, "R");
        require_diagonal(b.inertia, {half * m * r * r, half * m * r * r, m * r * r});
    }
    SECTION("box: M(b² + c²)/12, ...")
    {
        loaded_body b = body_of("body X box(a, b, c) mass M");
        GiNaC::ex m = symbol_of(b.scene, "M"), x = symbol_of(b.scene, "a"), y = symbol_of(b.scene, "b"),
                  z = symbol_of(b.scene, "c");
        require_diagonal(b.inertia, {twelfth * m * (y * y + z * z), twelfth * m * (x * x + z * z),
                                     twelfth * m * (x * x + y * y)});
    }
    SECTION("cylinder: M(3R² + h²)/12 across, MR²/2 along")
    {
        loaded_body b = body_of("body C cylinder(R, h) mass M");
        GiNaC::ex m = symbol_of(b.scene, "M"), r = symbol_of(b.scene, "R"), hh = symbol_of(b.scene, "h");
        GiNaC::ex across = twelfth * m * (3 * r * r + hh * hh);
        require_diagonal(b.inertia, {across, across, half * m * r * r});
    }
    SECTION("cylinder with axis x: the symmetry axis becomes body x")
    {
        loaded_body b = body_of("body C cylinder(R, h) mass M axis x");
        GiNaC::ex m = symbol_of(b.scene, "M"), r = symbol_of(b.scene, "R"), hh = symbol_of(b.scene, "h");
        GiNaC::ex across = twelfth * m * (3 * r * r + hh * hh);
        require_diagonal(b.inertia, {half * m * r * r, across, across});
    }
    SECTION("cone about its centre of mass: 3/10 MR² along, 3/80 M(4R² + h²) across")
    {
        loaded_body b = body_of("body K cone(R, h) mass M");
        GiNaC::ex m = symbol_of(b.scene, "M"), r = symbol_of(b.scene, "R"), hh = symbol_of(b.scene, "h");
        GiNaC::ex across = GiNaC::numeric(3, 80) * m * (4 * r * r + hh * hh);
        require_diagonal(b.inertia, {across, across, GiNaC::numeric(3, 10) * m * r * r});
        CHECK(same(b.inertia.centre_of_mass[2], hh / 4)); // found by integration, base at z = 0
    }
    SECTION("ellipsoid: M(b² + c²)/5, ...")
    {
        loaded_body b = body_of("body E ellipsoid(a, b, c) mass M");
        GiNaC::ex m = symbol_of(b.scene, "M"), x = symbol_of(b.scene, "a"), y = symbol_of(b.scene, "b"),
                  z = symbol_of(b.scene, "c");
        const GiNaC::numeric fifth(1, 5);
        require_diagonal(b.inertia, {fifth * m * (y * y + z * z), fifth * m * (x * x + z * z), fifth * m * (x * x + y * y)});
    }
    SECTION("ball of density ρ0(1 + r²/R²): mass 32πρ0R³/15, I = 3/7 MR²")
    {
        loaded_body b = body_of("body B region ball(R) density rho0*(1 + r^2/R^2)");
        GiNaC::ex rho0 = symbol_of(b.scene, "rho0"), r = symbol_of(b.scene, "R");
        GiNaC::ex mass = GiNaC::numeric(32, 15) * GiNaC::Pi * rho0 * GiNaC::pow(r, 3);
        CHECK(same(b.inertia.mass, mass));
        GiNaC::ex i = GiNaC::numeric(3, 7) * mass * r * r;
        require_diagonal(b.inertia, {i, i, i});
    }
    SECTION("a density linear in z moves the centre of mass, and the tensor is about it")
    {
        // Rod of density ρ0(1 + z/L) on [−L/2, L/2]: M = ρ0 L, z_cm = L/12,
        // I_xx about the centre = ∫ρ z² dz − M z_cm² = ρ0 L³/12 − ρ0 L³/144 = 11 ρ0 L³/144.
        loaded_body b = body_of("body S region segment(l) density rho0*(1 + z/l)");
        GiNaC::ex rho0 = symbol_of(b.scene, "rho0"), l = symbol_of(b.scene, "l");
        CHECK(same(b.inertia.mass, rho0 * l));
        CHECK(same(b.inertia.centre_of_mass[2], l / 12));
        CHECK(same(b.inertia.tensor(0, 0), GiNaC::numeric(11, 144) * rho0 * GiNaC::pow(l, 3)));
    }
}

TEST_CASE("inertia: numeric quadrature in Cartesian coordinates agrees", "[rigid_body][inertia][quadrature]")
{
    // Independent of the engine's coordinates and moments: nested Gauss–Legendre
    // over x, y, z with the body's boundary as limits.
    SECTION("cone R = 0.7, h = 1.9, M = 2.3: tensor about the centre of mass")
    {
        loaded_body b = body_of("body K cone(R, h) mass M");
        const double rr = 0.7, hh = 1.9, mm = 2.3;
        GiNaC::exmap values = {{symbol_of(b.scene, "R"), rr}, {symbol_of(b.scene, "h"), hh},
                               {symbol_of(b.scene, "M"), mm}};
        // Cone: z in [0, h], radius R(1 − z/h); integrate z outermost here.
        auto over_cone = [&](const std::function<double(double, double, double)>& f) {
            return cartesian_integral(
                [&](double z, double x, double y) { return f(x, y, z); }, 0, hh,
                [&](double z) {
                    double s = rr * (1 - z / hh);
                    return std::make_pair(-s, s);
                },
                [&](double z, double x) {
                    double s = rr * (1 - z / hh);
                    double w = std::sqrt(std::max(0.0, s * s - x * x));
                    return std::make_pair(-w, w);
                });
        };
        double volume = over_cone([](double, double, double) { return 1.0; });
        double density = mm / volume;
        double z_cm = over_cone([&](double, double, double z) { return density * z; }) / mm;
        double izz = over_cone([&](double x, double y, double) { return density * (x * x + y * y); });
        double ixx = over_cone([&](double, double y, double z) { return density * (y * y + (z - z_cm) * (z - z_cm)); });
        CHECK_THAT(number(b.inertia.tensor(2, 2), values), WithinRel(izz, 1e-4));
        CHECK_THAT(number(b.inertia.tensor(0, 0), values), WithinRel(ixx, 1e-4));
        CHECK_THAT(number(b.inertia.centre_of_mass[2], values), WithinRel(z_cm, 1e-6));
    }
    SECTION("ball of density ρ0(1 + r²/R²), R = 1.3, ρ0 = 0.8: mass and I_zz")
    {
        loaded_body b = body_of("body B region ball(R) density rho0*(1 + r^2/R^2)");
        const double rr = 1.3, rho0 = 0.8;
        GiNaC::exmap values = {{symbol_of(b.scene, "R"), rr}, {symbol_of(b.scene, "rho0"), rho0}};
        auto over_ball = [&](const std::function<double(double, double, double)>& f) {
            return cartesian_integral(
                f, -rr, rr,
                [&](double x) {
                    double w = std::sqrt(rr * rr - x * x);
                    return std::make_pair(-w, w);
                },
                [&](double x, double y) {
                    double w = std::sqrt(std::max(0.0, rr * rr - x * x - y * y));
                    return std::make_pair(-w, w);
                });
        };
        auto rho = [&](double x, double y, double z) { return rho0 * (1 + (x * x + y * y + z * z) / (rr * rr)); };
        double mass = over_ball(rho);
        double izz = over_ball([&](double x, double y, double z) { return rho(x, y, z) * (x * x + y * y); });
        CHECK_THAT(number(b.inertia.mass, values), WithinRel(mass, 1e-4));
        CHECK_THAT(number(b.inertia.tensor(2, 2), values), WithinRel(izz, 1e-4));
    }
    SECTION("ellipsoid a = 1, b = 0.6, c = 0.4, M = 1: I_xx")
    {
        loaded_body b = body_of("body E ellipsoid(a, b, c) mass M");
        const double aa = 1, bb = 0.6, cc = 0.4;
        GiNaC::exmap values = {{symbol_of(b.scene, "a"), aa}, {symbol_of(b.scene, "b"), bb},
                               {symbol_of(b.scene, "c"), cc}, {symbol_of(b.scene, "M"), 1}};
        auto over = [&](const std::function<double(double, double, double)>& f) {
            return cartesian_integral(
                f, -aa, aa,
                [&](double x) {
                    double w = bb * std::sqrt(std::max(0.0, 1 - x * x / (aa * aa)));
                    return std::make_pair(-w, w);
                },
                [&](double x, double y) {
                    double w = cc * std::sqrt(std::max(0.0, 1 - x * x / (aa * aa) - y * y / (bb * bb)));
                    return std::make_pair(-w, w);
                });
        };
        double volume = over([](double, double, double) { return 1.0; });
        double ixx = over([&](double, double y, double z) { return (y * y + z * z) / volume; });
        CHECK_THAT(number(b.inertia.tensor(0, 0), values), WithinRel(ixx, 1e-4));
    }
}

TEST_CASE("inertia: parallel axes, rotation, L = Iω and T = ½ωᵀIω", "[rigid_body][inertia]")
{
    loaded_body b = body_of("body D disk(R) mass M at (0, 0, h)");
    GiNaC::ex m = symbol_of(b.scene, "M"), r = symbol_of(b.scene, "R"), hh = symbol_of(b.scene, "h");
    REQUIRE(b.inertia.about_origin);
    CHECK(same((*b.inertia.about_origin)(0, 0), m * r * r / 4 + m * hh * hh));
    CHECK(same((*b.inertia.about_origin)(2, 2), m * r * r / 2));
    // Rotating the disk's tensor by 90° about x puts its axis along y.
    GiNaC::matrix rotated = rotated_tensor(b.inertia.tensor, euler_rotation(0, GiNaC::Pi / 2, 0));
    CHECK(same(rotated(1, 1), m * r * r / 2));
    CHECK(same(rotated(2, 2), m * r * r / 4));
    // L and T in components (homework eqs. 7–13).
    const std::vector<GiNaC::ex>& w = b.inertia.omega;
    CHECK(same(b.inertia.angular_momentum[2], m * r * r / 2 * w[2]));
    CHECK(same(b.inertia.kinetic_energy, m * r * r / 8 * (w[0] * w[0] + w[1] * w[1] + 2 * w[2] * w[2])));
    // A non-principal tensor: the rotated box is not diagonal; its principal moments are the box's.
    loaded_body box = body_of("body X box(a, b, c) mass M");
    GiNaC::matrix tilted = rotated_tensor(box.inertia.tensor, euler_rotation(GiNaC::Pi / 4, 0, 0));
    CHECK_FALSE(tilted(0, 1).expand().normal().is_zero());
}

TEST_CASE("inertia: principal moments and axes of a non-diagonal tensor", "[rigid_body][inertia]")
{
    // Density 1 + x y over a box: I_xy ≠ 0, so the body axes are not principal. Each
    // principal moment λ is a root of det(I − λ) and its axis v satisfies I v = λ v.
    for (const char* density : {"1 + x*y", "1 + x*y/(a*b)"}) {
        INFO(density);
        loaded_body b = body_of(std::string("body X region box(a, b, c) density ") + density);
        const inertia_result& in = b.inertia;
        CHECK_FALSE(in.diagonal);
        REQUIRE(in.principal.size() == 3);
        REQUIRE(in.principal_axes);
        GiNaC::exmap values = {{symbol_of(b.scene, "a"), 1}, {symbol_of(b.scene, "b"), 2}, {symbol_of(b.scene, "c"), 3}};
        for (unsigned k = 0; k < 3; ++k) {
            double length = 0;
            for (unsigned i = 0; i < 3; ++i)
                length += std::pow(number((*in.principal_axes)(i, k), values), 2);
            CHECK(length > 1e-12);
            for (unsigned i = 0; i < 3; ++i) {
                GiNaC::ex row = 0;
                for (unsigned j = 0; j < 3; ++j)
                    row += in.tensor(i, j) * (*in.principal_axes)(j, k);
                CHECK_THAT(number(row - in.principal[k] * (*in.principal_axes)(i, k), values),
                           WithinAbs(0, 1e-12 * (1 + std::sqrt(length))));
            }
        }
    }
}

TEST_CASE("euler: equations derived for a free body, principal and general", "[rigid_body][euler]")
{
    model scene = load("parameters I1 I2 I3\nbody B inertia (I1, I2, I3) mass 1\nomega B (w1, w2, w3)\n"
                       "torque B (0, 0, 0)\n");
    const rigid_body& body = scene.bodies.at(0);
    inertia_result inertia = derive_inertia(body);
    euler_result e = derive_euler(body, inertia, scene.initial, {});
    GiNaC::ex i1 = scene.parameters[0].symbol, i2 = scene.parameters[1].symbol, i3 = scene.parameters[2].symbol;
    const auto& w = e.omega;
    const auto& d = e.rates;
    // I1 ω̇1 + (I3 − I2) ω2 ω3 = 0 and cyclic (homework eq. 40).
    CHECK(same(e.equations[0], i1 * d[0] + (i3 - i2) * w[1] * w[2]));
    CHECK(same(e.equations[1], i2 * d[1] + (i1 - i3) * w[2] * w[0]));
    CHECK(same(e.equations[2], i3 * d[2] + (i2 - i1) * w[0] * w[1]));
    CHECK(same(e.angular_momentum_squared, i1 * i1 * w[0] * w[0] + i2 * i2 * w[1] * w[1] + i3 * i3 * w[2] * w[2]));
    CHECK(e.stability == std::vector<std::string>{"unknown", "unknown", "unknown"});

    // A general tensor: the equations are (I ω̇ + ω × Iω)_i; compare with the vector form at random numbers.
    model tilted = load("parameters M a b c\nbody X box(a, b, c) mass M\nomega X (p, q, s)\n");
    inertia_result box = derive_inertia(tilted.bodies[0]);
    box.tensor = rotated_tensor(box.tensor, euler_rotation(GiNaC::Pi / 6, GiNaC::Pi / 5, 0));
    box.diagonal = false;
    box.principal = {box.tensor(0, 0), box.tensor(1, 1), box.tensor(2, 2)}; // unused by the general form
    euler_result general = derive_euler(tilted.bodies[0], box, std::nullopt, {});
    GiNaC::exmap at = {{tilted.parameters[0].symbol, 1.3}, {tilted.parameters[1].symbol, 0.7},
                       {tilted.parameters[2].symbol, 1.1}, {tilted.parameters[3].symbol, 0.4},
                       {general.omega[0], 0.3},           {general.omega[1], -1.2},
                       {general.omega[2], 0.5},           {general.rates[0], 0.9},
                       {general.rates[1], 0.1},           {general.rates[2], -0.6}};
    Eigen::Matrix3d tensor;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            tensor(i, j) = number(box.tensor(i, j), at);
    Eigen::Vector3d omega(0.3, -1.2, 0.5), rate(0.9, 0.1, -0.6);
    Eigen::Vector3d expected = tensor * rate + omega.cross(tensor * omega);
    for (int i = 0; i < 3; ++i)
        CHECK_THAT(number(general.equations[i], at), WithinAbs(expected[i], 1e-12));
    REQUIRE(general.principal_equations.size() == 3);
}

TEST_CASE("euler: the symmetric solution satisfies the equations", "[rigid_body][euler]")
{
    model scene = load("parameters M R\nbody D disk(R) mass M\nomega D (w1, w2, w3)\n");
    inertia_result inertia = derive_inertia(scene.bodies[0]);
    euler_result e = derive_euler(scene.bodies[0], inertia, scene.initial, {});
    REQUIRE(e.symmetric);
    CHECK(e.symmetric->axis == 2);
    // Ω = (I3 − I1) ω3 / I1 = ω3 for a thin disk (I3 = 2 I1).
    CHECK(same(e.symmetric->precession, e.symmetric->constants[2]));
    // Substituted back: every equation vanishes identically in t.
    GiNaC::realsymbol t = GiNaC::ex_to<GiNaC::realsymbol>(e.symmetric->time);
    GiNaC::exmap solution;
    for (int i = 0; i < 3; ++i) {
        solution[e.omega[i]] = e.symmetric->omega[i];
        solution[e.rates[i]] = e.symmetric->omega[i].diff(t);
    }
    for (int i = 0; i < 3; ++i)
        CHECK(e.equations[i].subs(solution).expand().is_zero());
    CHECK(e.stability == std::vector<std::string>{"marginal", "marginal", "stable"});
}

TEST_CASE("euler: the elliptic solution matches a numeric integration, T and |L| constant",
          "[rigid_body][euler][elliptic]")
{
    for (const char* start : {"w1 = 0.2, w2 = 1.0, w3 = 0.3", "w1 = 1.0, w2 = 0.4, w3 = -0.2",
                              "w1 = -0.3, w2 = -0.5, w3 = 1.1"}) {
        INFO(start);
        model scene = load(std::string("parameters a b c\nbody X box(a, b, c) mass 1\nomega X (w1, w2, w3)\n"
                                       "values a = 1, b = 2, c = 3\ninitial ") + start + "\n");
        inertia_result inertia = derive_inertia(scene.bodies[0]);
        euler_result e = derive_euler(scene.bodies[0], inertia, scene.initial, value_map(scene, scene.values[0]));
        REQUIRE(e.elliptic);
        const auto& s = *e.elliptic;
        // ω(0) is the initial state.
        std::array<double, 3> w0 = s.evaluate(0);
        for (int i = 0; i < 3; ++i)
            CHECK_THAT(w0[i], WithinAbs(s.initial[i], 1e-12));
        // Runge–Kutta–Dormand–Prince on Euler's equations.
        using state = std::array<double, 3>;
        const std::array<double, 3> I = s.moments;
        auto rhs = [&](const state& w, state& dw, double) {
            dw[0] = (I[1] - I[2]) * w[1] * w[2] / I[0];
            dw[1] = (I[2] - I[0]) * w[2] * w[0] / I[1];
            dw[2] = (I[0] - I[1]) * w[0] * w[1] / I[2];
        };
        state w = s.initial;
        double t = 0;
        auto stepper = boost::numeric::odeint::make_controlled(1e-12, 1e-12,
                                                              boost::numeric::odeint::runge_kutta_dopri5<state>());
        const double end = 1.5 * s.period;
        for (int n = 1; n <= 30; ++n) {
            double next = end * n / 30;
            boost::numeric::odeint::integrate_adaptive(stepper, rhs, w, t, next, 1e-3);
            t = next;
            std::array<double, 3> closed = s.evaluate(t);
            for (int i = 0; i < 3; ++i)
                CHECK_THAT(closed[i], WithinAbs(w[i], 1e-8));
            double energy = 0, l2 = 0;
            for (int i = 0; i < 3; ++i) {
                energy += 0.5 * I[i] * closed[i] * closed[i];
                l2 += I[i] * I[i] * closed[i] * closed[i];
            }
            CHECK_THAT(energy, WithinRel(s.energy, 1e-12));
            CHECK_THAT(l2, WithinRel(s.momentum_squared, 1e-12));
        }
        // Periodic with the period found.
        std::array<double, 3> later = s.evaluate(s.period);
        for (int i = 0; i < 3; ++i)
            CHECK_THAT(later[i], WithinAbs(s.initial[i], 1e-10));
        // Poinsot: the polhode lies on the energy ellipsoid and on the invariable plane.
        REQUIRE(e.poinsot);
        CHECK(e.poinsot->polhode.size() == 64);
        const double l = std::sqrt(s.momentum_squared);
        for (const auto& p : e.poinsot->polhode) {
            double plane = 0;
            for (int i = 0; i < 3; ++i)
                plane += p[i] * I[i] * p[i] / l;
            CHECK_THAT(plane, WithinRel(e.poinsot->plane_distance, 1e-10));
        }
        // Moments 1/12·(b²+c²) … : 13/12, 10/12, 5/12 → axis 2 (the middle, 10/12) is unstable.
        CHECK(e.stability == std::vector<std::string>{"stable", "unstable", "stable"});
    }
}

TEST_CASE("bodies: input errors at their position", "[rigid_body][lower]")
{
    const std::string h = "parameters m g l\ncoordinates q\n";
    require_error(h + "body B cube(l) mass m\n", 3, 8, "unknown shape `cube`");
    require_error(h + "body B region cone(l, l) density 1\n", 3, 15, "unknown region `cone`");
    require_error(h + "body B disk(l) mass m axis w\n", 3, 28, "the axis is `x`, `y` or `z`");
    require_error(h + "body B box(l, l) mass m\n", 3, 8, "takes 3 dimensions");
    require_error(h + "body B disk(-1) mass m\n", 3, 13, "must be positive");
    require_error(h + "body B disk(q) mass m\n", 3, 13, "coordinate `q` cannot appear");
    require_error(h + "body B region ball(l) density q\n", 3, 31, "coordinate `q` cannot appear in a density");
    require_error(h + "omega B (w1, w2, w3)\n", 3, 7, "unknown body `B`");
    require_error(h + "body B region ball(l) density (1 + x + y + z)^1000\n", 3, 46, "degree");
    require_error(h + "body B disk(l) mass m\nbody B ball(l) mass m\n", 4, 6, "already declared");
    require_error(h + "body B disk(l) mass m orientation zxz(q, 0, 0)\nomega B (w1, w2, w3)\n", 4, 1,
                  "derived from them");
    require_error(h + "body B disk(l) mass m\ntorque B (1, 0, 0)\n", 4, 1, "name its angular velocity first");
    require_error(h + "body B disk(l) mass m\nomega B (w1, w2, 2*w3)\n", 4, 18, "a new name");
    require_error(h + "body B disk(l) mass m orientation xyz(q, 0, 0)\n", 3, 35, "zxz(phi, theta, psi)");
    require_error(h + "body B disk(l) mass m\nomega B (w1, w2, w3)\nT = w1^2\n", 5, 5, "only in a `torque`");
}

TEST_CASE("bodies: a free body's scene needs no coordinates, and w1 takes an initial value", "[rigid_body][lower]")
{
    model scene = load("parameters M R\nbody D disk(R) mass M\nomega D (w1, w2, w3)\ntorque D (0, 0, -w3)\n"
                       "initial w1 = 1, w3 = 2\n");
    REQUIRE(scene.coordinates.empty());
    REQUIRE(scene.bodies.size() == 1);
    CHECK(scene.initial->others.at("w1") == 1);
    CHECK(same(scene.bodies[0].torque[2], -(*scene.bodies[0].omega)[2]));
    // The torque enters Euler's equations: I3 ω̇3 = −ω3.
    inertia_result inertia = derive_inertia(scene.bodies[0]);
    euler_result e = derive_euler(scene.bodies[0], inertia, scene.initial, {});
    CHECK_FALSE(e.torque_free);
    CHECK(same(e.equations[2], inertia.tensor(2, 2) * e.rates[2] + e.omega[2]));
}

TEST_CASE("bodies in a Lagrangian: physical pendulum, ω² = 3g/(2l)", "[rigid_body][lagrangian]")
{
    model scene = load("parameters M l g\ncoordinates theta\n"
                       "body rod stick(l) mass M at (0, l/2*sin(theta), -l/2*cos(theta)) orientation zxz(0, theta, 0)\n"
                       "gravity g along (0, 0, -1)\n");
    simplifier simplify = make_simplifier(scene);
    lagrangian_result l = derive_lagrangian(scene, simplify);
    GiNaC::ex m = scene.parameters[0].symbol, len = scene.parameters[1].symbol, g = scene.parameters[2].symbol;
    const coordinate& theta = scene.coordinates[0];
    // T = ½ (M l²/4 + M l²/12) θ̇² = M l² θ̇²/6, V = −M g l/2 cos θ.
    CHECK(same(l.kinetic, m * len * len * GiNaC::pow(theta.velocity, 2) / 6));
    CHECK(same(l.potential, -m * g * len * GiNaC::cos(theta.position) / 2));
    // ω² = V''/T'' at θ = 0.
    GiNaC::ex stiffness = l.potential.diff(theta.position, 2).subs(theta.position == 0);
    GiNaC::ex inertia = l.kinetic.diff(theta.velocity, 2);
    CHECK(same(stiffness / inertia, 3 * g / (2 * len)));
}

TEST_CASE("bodies in a Lagrangian: the ω of z-x-z Euler angles is derived", "[rigid_body][lagrangian]")
{
    model scene = load("coordinates phi theta psi\n");
    std::vector<GiNaC::ex> w = body_angular_velocity(
        euler_rotation(scene.coordinates[0].position, scene.coordinates[1].position, scene.coordinates[2].position),
        scene);
    simplifier simplify = make_simplifier(scene);
    const GiNaC::ex ph = scene.coordinates[0].velocity, th = scene.coordinates[1].velocity,
                    ps = scene.coordinates[2].velocity;
    const GiNaC::ex theta = scene.coordinates[1].position, psi = scene.coordinates[2].position;
    // Goldstein (4.87): ω = (φ̇ sinθ sinψ + θ̇ cosψ, φ̇ sinθ cosψ − θ̇ sinψ, φ̇ cosθ + ψ̇).
    CHECK(simplify.canonical(w[0] - (ph * sin(theta) * sin(psi) + th * cos(psi))).is_zero());
    CHECK(simplify.canonical(w[1] - (ph * sin(theta) * cos(psi) - th * sin(psi))).is_zero());
    CHECK(simplify.canonical(w[2] - (ph * cos(theta) + ps)).is_zero());
}

TEST_CASE("bodies in a Lagrangian: the heavy symmetric top", "[rigid_body][lagrangian][top]")
{
    model scene = load("parameters M g l A C\ncoordinates phi theta psi\n"
                       "body top inertia (A, A, C) mass M at (l*sin(phi)*sin(theta), -l*cos(phi)*sin(theta), "
                       "l*cos(theta)) orientation zxz(phi, theta, psi)\ngravity g along (0, 0, -1)\n");
    simplifier simplify = make_simplifier(scene);
    lagrangian_result l = derive_lagrangian(scene, simplify);
    std::vector<GiNaC::ex> equations = derive_equations(scene, l, simplify);
    const GiNaC::ex m = scene.parameters[0].symbol, g = scene.parameters[1].symbol, len = scene.parameters[2].symbol,
                    a = scene.parameters[3].symbol, c = scene.parameters[4].symbol;
    const coordinate &phi = scene.coordinates[0], &theta = scene.coordinates[1], &psi = scene.coordinates[2];
    const GiNaC::ex pivot = a + m * len * len; // I1 about the pivot (parallel axes)
    // φ and ψ are cyclic; p_ψ = C ω3 with ω3 = φ̇ cos θ + ψ̇.
    CHECK_FALSE(l.lagrangian.has(phi.position));
    CHECK_FALSE(l.lagrangian.has(psi.position));
    const GiNaC::ex omega3 = phi.velocity * cos(theta.position) + psi.velocity;
    CHECK(simplify.canonical(l.lagrangian.diff(psi.velocity) - c * omega3).is_zero());
    // The nutation equation at θ̈ = θ̇ = 0 is sinθ (C ω3 φ̇ − I1 cosθ φ̇² − M g l) = 0: steady precession.
    GiNaC::ex steady = equations[1].subs(GiNaC::lst{theta.acceleration == 0, theta.velocity == 0});
    GiNaC::ex expected = sin(theta.position) * (c * omega3 * phi.velocity -
                                                pivot * cos(theta.position) * pow(phi.velocity, 2) - m * g * len);
    CHECK((simplify.canonical(steady + expected).is_zero() || simplify.canonical(steady - expected).is_zero()));
    // Routh: with the cyclic momenta fixed, V_eff(θ) = V + ½ pᵀ K⁻¹ p, K the (φ̇, ψ̇) block of T.
    GiNaC::matrix k(2, 2);
    const GiNaC::ex cyclic[] = {phi.velocity, psi.velocity};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            k(i, j) = l.kinetic.diff(GiNaC::ex_to<GiNaC::symbol>(cyclic[i])).diff(GiNaC::ex_to<GiNaC::symbol>(cyclic[j]));
    GiNaC::realsymbol w3("w3");
    // Sleeping top: at θ = 0 the φ and ψ axes coincide, so p_φ = p_ψ = C ω3.
    GiNaC::matrix p{{c * w3}, {c * w3}};
    GiNaC::ex effective = l.potential + GiNaC::numeric(1, 2) * p.transpose().mul(k.inverse()).mul(p)(0, 0);
    GiNaC::ex curvature = GiNaC::series_to_poly(effective.series(theta.position == 0, 3)).coeff(theta.position, 2);
    // V_eff ≈ const + θ² (C²ω3²/(8 I1) − M g l/2): stable exactly when C² ω3² > 4 I1 M g l.
    CHECK(same(curvature, (c * c * w3 * w3 - 4 * pivot * m * g * len) / (8 * pivot)));

    // The engine's own top stage derives the same condition: I3² ω3² − 4 I1 M g l > 0.
    std::vector<top_result> tops = analyze_tops(scene, l, simplify);
    REQUIRE(tops.size() == 1);
    CHECK(same(tops[0].pivot_moment, pivot));
    CHECK(same(tops[0].spin_moment, c));
    CHECK(same(tops[0].condition, c * c * pow(tops[0].spin, 2) - 4 * pivot * m * g * len));
}

TEST_CASE("bodies in a Lagrangian: a disk swinging from a point of its rim", "[rigid_body][lagrangian]")
{
    // In its own plane (rotation about the disk's axis, here body x): I = MR²/2 + MR², ω² = 2g/(3R).
    // Across its plane (about a diameter): I = MR²/4 + MR², ω² = 4g/(5R).
    struct swinging {
        const char* axis;
        GiNaC::numeric frequency_squared; ///< in g/R
    };
    for (const swinging& s : {swinging{"x", GiNaC::numeric(2, 3)}, swinging{"z", GiNaC::numeric(4, 5)}}) {
        INFO("disk axis " << s.axis);
        model scene = load(std::string("parameters M R g\ncoordinates theta\nbody D disk(R) mass M axis ") + s.axis +
                           " at (0, R*sin(theta), -R*cos(theta)) orientation zxz(0, theta, 0)\n"
                           "gravity g along (0, 0, -1)\n");
        simplifier simplify = make_simplifier(scene);
        lagrangian_result l = derive_lagrangian(scene, simplify);
        const coordinate& theta = scene.coordinates[0];
        GiNaC::ex stiffness = l.potential.diff(theta.position, 2).subs(theta.position == 0);
        GiNaC::ex inertia = l.kinetic.diff(theta.velocity, 2);
        CHECK(same(stiffness / inertia, s.frequency_squared * scene.parameters[2].symbol / scene.parameters[1].symbol));
    }
}

TEST_CASE("inertia: regression, a mass that is a sum with π (GiNaC's gcd refuses π)", "[rigid_body][inertia]")
{
    // ∫(1 + x)² over the ball = 4πR³/3 + 4πR⁵/15; before π went through as a symbol this threw.
    loaded_body b = body_of("body B region ball(R) density (1 + x)^2");
    GiNaC::ex r = symbol_of(b.scene, "R");
    CHECK(same(b.inertia.mass, 4 * GiNaC::Pi * pow(r, 3) / 3 + 4 * GiNaC::Pi * pow(r, 5) / 15));
    // The first moment ∫2x² shifts the centre along x: x_cm = (8πR⁵/15) / M.
    CHECK(same(b.inertia.centre_of_mass[0] * b.inertia.mass, 8 * GiNaC::Pi * pow(r, 5) / 15));
}
