// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_forces.cpp
 *  Dissipation, dampers, applied forces and inputs: the front end's statements and
 *  errors, and the generalized forces in the equations of motion, against SymPy's
 *  multi_mass_spring_damper results, Newton's vector form of a damper, and virtual work
 *  by hand; the stiffness of position-dependent forces in the linearization (a circulatory
 *  follower force) against central differences of the nonlinear right-hand side and the
 *  eigenvalues of m s² + b s + k ± ic by the quadratic formula. */
#include "engine/analysis.h"
#include "mechanics/equations_of_motion.h"
#include "numeric/compiled_motion.h"
#include "verify/verify.h"
#include "mechanics/forces.h"
#include "mechanics/lagrangian.h"
#include "scene/lower.h"
#include "helpers/scene_helpers.h"
#include "helpers/expressions.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::require_error;
using lagrange_test::symbol_of;

using lagrange_test::same;
using lagrange_test::value_at;

namespace {

equations_of_motion motion_of(const model& scene, bool printed = true)
{
    simplifier simplify = make_simplifier(scene);
    lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
    return derive_equations_of_motion(scene, lagrangian, simplify, printed);
}

bool same_as_zero(const GiNaC::ex& e) { return e.expand().normal().is_zero(); }

} // namespace

TEST_CASE("forces: the statements lower into the model", "[forces]")
{
    model scene = load(R"(parameters m k b F0 w
coordinates x y
input u
point P mass m at (x, y)
point Q mass 0 at (x + 1, 0)
dissipation F = 1/2*b*x'^2 + b*x'*y'
damper b between P and (0, 0)
force x = -k*x + u
force on Q (F0*cos(w*t), 0)
values m = 1, k = 2, b = 0.1, F0 = 1, w = 2, u = sin(3*t)
)");
    REQUIRE(scene.inputs.size() == 1);
    CHECK(scene.inputs[0].name == "u");
    CHECK(scene.has_generalized_forces());
    GiNaC::ex b = symbol_of(scene, "b"), xd = symbol_of(scene, "x_dot"), yd = symbol_of(scene, "y_dot");
    CHECK(same_as_zero(scene.dissipation - (b * xd * xd / 2 + b * xd * yd)));
    REQUIRE(scene.dampers.size() == 1);
    REQUIRE(scene.forces.size() == 1);
    CHECK(scene.forces[0].coordinate == 0);
    CHECK(same_as_zero(scene.forces[0].value - (-symbol_of(scene, "k") * symbol_of(scene, "x") + scene.inputs[0].symbol)));
    REQUIRE(scene.point_forces.size() == 1);
    CHECK(scene.point_forces[0].point == "Q");
    REQUIRE(scene.values.size() == 1);
    REQUIRE(scene.values[0].inputs.size() == 1);
    CHECK(scene.values[0].inputs[0].first == "u");
    CHECK(same_as_zero(scene.values[0].inputs[0].second - GiNaC::sin(3 * scene.time)));
    CHECK(scene.values[0].values.size() == 5);
}

TEST_CASE("forces: bad input has a caret at the offending token", "[forces][errors]")
{
    const std::string head = "parameters m b k\ncoordinates x y\npoint P mass m at (x, y)\n";
    require_error(head + "dissipation F = 1/2*b*x'^2*x'\n", 4, 17, "quadratic in the velocities");
    require_error(head + "dissipation F = b*x'\n", 4, 17, "quadratic in the velocities");
    require_error(head + "dissipation F = b*x'^2 + k*x^2\n", 4, 17, "quadratic in the velocities");
    require_error(head + "dissipation F = b*sin(x')^2\n", 4, 17, "quadratic in the velocities");
    require_error(head + "dissipation G = b*x'^2\n", 4, 13, "expected `F`");
    require_error(head + "force z = -k*x\n", 4, 7, "`z` is not one");
    require_error(head + "force m = -k*x\n", 4, 7, "`m` is not one");
    require_error(head + "force on R (1, 0)\n", 4, 10, "unknown point `R`");
    require_error(head + "damper b between P and S\n", 4, 24, "unknown point `S`");
    require_error(head + "damper b between P and P\n", 4, 1, "the same point");
    require_error(head + "input u\nT = u*x'^2\n", 5, 5, "input `u` cannot appear in an energy");
    require_error(head + "input m\n", 4, 7, "already declared");
    require_error(head + "input u\nvalues u = x\n", 5, 12, "coordinate `x` cannot appear");
    require_error(head + "force x = k*z\n", 4, 13, "unknown name `z`");
}

TEST_CASE("forces: a damped oscillator's equation is m x'' + b x' + k x = 0", "[forces][equations]")
{
    for (const char* damping : {"dissipation F = 1/2*b*x'^2\n", "damper b between P and (0, 0)\n",
                                "force x = -b*x'\n", "force on P (-b*x', 0)\n"}) {
        INFO(damping);
        model scene = load(std::string("parameters m k b\ncoordinates x\npoint P mass m at (x, 0)\n"
                                       "spring k between P and (0, 0)\n") + damping);
        equations_of_motion eom = motion_of(scene);
        GiNaC::ex m = symbol_of(scene, "m"), k = symbol_of(scene, "k"), b = symbol_of(scene, "b");
        GiNaC::ex x = symbol_of(scene, "x"), xd = symbol_of(scene, "x_dot"), xdd = symbol_of(scene, "x_ddot");
        REQUIRE(eom.residuals);
        CHECK(same_as_zero((*eom.residuals)[0] - (m * xdd + b * xd + k * x)));
        CHECK(same_as_zero(eom.forcing[0] - (-b * xd - k * x)));
        CHECK(eom.forces.any);
    }
}

// SymPy's sympy/physics/mechanics/models.py builds multi_mass_spring_damper(n) in relative
// coordinates: x_i is the stretch of spring i (stiffness k_i, damper c_i) between mass i−1 (or
// the wall) and mass i; with gravity along +x and an external force f_i on each mass. Its
// tests (sympy/physics/mechanics/tests/test_models.py) give the mass matrix and forcing.
TEST_CASE("forces: two- and three-mass spring-damper chains match SymPy's Kane results",
          "[forces][equations][sympy]")
{
    SECTION("n = 2, dampers as statements and as a Rayleigh function agree")
    {
        for (const char* damping : {"damper c0 between (0, 0) and P0\ndamper c1 between P0 and P1\n",
                                    "dissipation F = 1/2*c0*x0'^2 + 1/2*c1*x1'^2\n"}) {
            INFO(damping);
            model scene = load(std::string("parameters m0 m1 k0 k1 c0 c1\ncoordinates x0 x1\n"
                                           "point P0 mass m0 at (x0, 0)\npoint P1 mass m1 at (x0 + x1, 0)\n"
                                           "spring k0 between (0, 0) and P0\nspring k1 between P0 and P1\n") +
                               damping);
            equations_of_motion eom = motion_of(scene);
            auto s = [&](const char* name) { return symbol_of(scene, name); };
            GiNaC::matrix mass = {{s("m0") + s("m1"), s("m1")}, {s("m1"), s("m1")}};
            std::vector<GiNaC::ex> forcing = {-s("c0") * s("x0_dot") - s("k0") * s("x0"),
                                              -s("c1") * s("x1_dot") - s("k1") * s("x1")};
            for (unsigned i = 0; i < 2; ++i) {
                for (unsigned j = 0; j < 2; ++j)
                    CHECK(same_as_zero(eom.mass(i, j) - mass(i, j)));
                CHECK(same_as_zero(eom.forcing[i] - forcing[i]));
                GiNaC::ex residual = mass(i, 0) * s("x0_ddot") + mass(i, 1) * s("x1_ddot") - forcing[i];
                CHECK(same_as_zero((*eom.residuals)[i] - residual));
            }
        }
    }
    SECTION("n = 3")
    {
        model scene = load(R"(parameters m0 m1 m2 k0 k1 k2 c0 c1 c2
coordinates x0 x1 x2
point P0 mass m0 at (x0, 0)
point P1 mass m1 at (x0 + x1, 0)
point P2 mass m2 at (x0 + x1 + x2, 0)
spring k0 between (0, 0) and P0
spring k1 between P0 and P1
spring k2 between P1 and P2
damper c0 between (0, 0) and P0
damper c1 between P0 and P1
damper c2 between P1 and P2
)");
        equations_of_motion eom = motion_of(scene, false);
        auto s = [&](const char* name) { return symbol_of(scene, name); };
        GiNaC::matrix mass = {{s("m0") + s("m1") + s("m2"), s("m1") + s("m2"), s("m2")},
                              {s("m1") + s("m2"), s("m1") + s("m2"), s("m2")},
                              {s("m2"), s("m2"), s("m2")}};
        std::vector<GiNaC::ex> forcing = {-s("c0") * s("x0_dot") - s("k0") * s("x0"),
                                          -s("c1") * s("x1_dot") - s("k1") * s("x1"),
                                          -s("c2") * s("x2_dot") - s("k2") * s("x2")};
        for (unsigned i = 0; i < 3; ++i) {
            for (unsigned j = 0; j < 3; ++j)
                CHECK(same_as_zero(eom.mass(i, j) - mass(i, j)));
            CHECK(same_as_zero(eom.forcing[i] - forcing[i]));
        }
    }
    SECTION("n = 1 with gravity and an external force input")
    {
        model scene = load(R"(parameters m0 k0 c0 g
coordinates x0
input f0
point P0 mass m0 at (x0, 0)
spring k0 between (0, 0) and P0
damper c0 between (0, 0) and P0
gravity g along (1, 0)
force on P0 (f0, 0)
)");
        equations_of_motion eom = motion_of(scene);
        auto s = [&](const char* name) { return symbol_of(scene, name); };
        GiNaC::ex f0 = scene.inputs[0].symbol;
        CHECK(same_as_zero(eom.mass(0, 0) - s("m0")));
        CHECK(same_as_zero(eom.forcing[0] - (-s("c0") * s("x0_dot") + s("g") * s("m0") - s("k0") * s("x0") + f0)));
    }
}

// A damper between two points of a planar double pendulum: Newton's form of the damper's
// force, F_A = −b (û·(v_A − v_B)) û on A and −F_A on B, taken by virtual work by hand, at
// random states.
TEST_CASE("forces: a damper between moving points in 2-D gives Newton's generalized force",
          "[forces][equations]")
{
    model scene = load(R"(parameters m l g b a
coordinates theta phi
point A mass m at (l*sin(theta), -l*cos(theta))
point B mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))
gravity g along (0, -1)
damper b between A and (a, 0)
damper b between A and B
)");
    equations_of_motion eom = motion_of(scene, false);
    const point_mass& pa = scene.points[0];
    const point_mass& pb = scene.points[1];
    std::vector<GiNaC::ex> anchor = {symbol_of(scene, "a"), 0, 0};
    auto velocity = [&](const std::vector<GiNaC::ex>& r) {
        std::vector<GiNaC::ex> v;
        for (const GiNaC::ex& x : r)
            v.push_back(time_derivative(x, scene));
        return v;
    };
    GiNaC::ex b = symbol_of(scene, "b");
    // Force on the first end of a damper from end 1 to end 2 (positions and velocities).
    auto damper_force = [&](const std::vector<GiNaC::ex>& r1, const std::vector<GiNaC::ex>& r2) {
        std::vector<GiNaC::ex> v1 = velocity(r1), v2 = velocity(r2), d(3);
        GiNaC::ex length2 = 0, rate = 0;
        for (int k = 0; k < 3; ++k) {
            d[k] = r1[k] - r2[k];
            length2 += d[k] * d[k];
            rate += d[k] * (v1[k] - v2[k]);
        }
        std::vector<GiNaC::ex> force;
        for (int k = 0; k < 3; ++k)
            force.push_back(-b * rate * d[k] / length2);
        return force;
    };
    std::vector<GiNaC::ex> on_a_anchor = damper_force(pa.position, anchor);
    std::vector<GiNaC::ex> on_a_b = damper_force(pa.position, pb.position);
    std::mt19937 random(22);
    std::uniform_real_distribution<double> uniform(-2, 2);
    for (int trial = 0; trial < 5; ++trial) {
        GiNaC::exmap point;
        for (const char* name : {"theta", "phi", "theta_dot", "phi_dot"})
            point[symbol_of(scene, name)] = uniform(random);
        for (const char* name : {"m", "l", "g", "b", "a"})
            point[symbol_of(scene, name)] = 1.5 + uniform(random) / 4;
        for (std::size_t j = 0; j < 2; ++j) {
            const GiNaC::symbol& q = scene.coordinates[j].position;
            GiNaC::ex expected = 0;
            for (int k = 0; k < 3; ++k)
                expected += on_a_anchor[k] * pa.position[k].diff(q) + on_a_b[k] * pa.position[k].diff(q) -
                            on_a_b[k] * pb.position[k].diff(q);
            double want = value_at(expected, point), got = value_at(eom.forces.total[j], point);
            CHECK_THAT(got, Catch::Matchers::WithinAbs(want, 1e-12 * (1 + std::abs(want))));
        }
    }
}

TEST_CASE("forces: a force on a point acts by virtual work", "[forces][equations]")
{
    model scene = load(R"(parameters m l g F0 w
coordinates theta
point P mass m at (l*sin(theta), -l*cos(theta))
gravity g along (0, -1)
force on P (F0*cos(w*t), 0)
)");
    equations_of_motion eom = motion_of(scene);
    auto s = [&](const char* name) { return symbol_of(scene, name); };
    GiNaC::ex expected = s("F0") * GiNaC::cos(s("w") * scene.time) * s("l") * GiNaC::cos(s("theta"));
    CHECK(same_as_zero(eom.forces.dissipative[0]));
    GiNaC::ex residual = s("m") * s("l") * s("l") * s("theta_ddot") + s("m") * s("g") * s("l") * GiNaC::sin(s("theta")) -
                         expected;
    // by value: the canonical form may write cos(wt)·cos θ as a sum of cosines
    for (double x : {0.3, -1.1}) {
        GiNaC::exmap point{{s("m"), 1.5},  {s("l"), 0.7},     {s("g"), 9.8},     {s("F0"), 2.0},
                           {s("w"), 3.0},  {s("theta"), x},   {scene.time, 0.4}, {s("theta_dot"), 0.2},
                           {s("theta_ddot"), -0.6}};
        CHECK_THAT(value_at(eom.forces.applied[0], point), Catch::Matchers::WithinAbs(value_at(expected, point), 1e-12));
        CHECK_THAT(value_at((*eom.residuals)[0], point), Catch::Matchers::WithinAbs(value_at(residual, point), 1e-12));
    }
}

// The self-verification takes Q from the statements by finite differences (numeric/verification):
// the derived equations pass, and an equation with one damper's force dropped is caught.
TEST_CASE("forces: the verification checks the equations with their generalized forces",
          "[forces][verification]")
{
    model scene = load(R"(parameters m l g b a F0 c
coordinates theta phi
input u
point A mass m at (l*sin(theta), -l*cos(theta))
point B mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))
gravity g along (0, -1)
damper b between B and (a, 0)
dissipation F = 1/2*c*(theta'^2 + phi'^2)
force phi = u*cos(theta)
force on A (F0*sin(t), 0)
)");
    analysis a = analyze(scene, {product::equations});
    verification_input input;
    input.lagrangian = &*a.lagrangian;
    input.equations = &*a.equations;
    verification_result checked = verify_results(scene, input, {product::equations});
    REQUIRE(checked.entries.size() == 1);
    CHECK(checked.entries[0].checked);
    CHECK(checked.entries[0].how.find("generalized forces") != std::string::npos);

    equations_of_motion wrong = *a.equations;
    const generalized_forces& q = wrong.forces;
    (*wrong.residuals)[1] = (*wrong.residuals)[1] + q.dissipative[1];
    input.equations = &wrong;
    CHECK_THROWS_WITH(verify_results(scene, input, {product::equations}),
                      Catch::Contains("verification failed: the equations of motion"));
}

namespace {

/// A follower force −c sin y on x and c sin x cos y on y: its stiffness at the origin,
/// [[0, c], [−c, 0]], is circulatory; b damps, u drives x.
const char* follower = R"(parameters m k c b
coordinates x y
input u
T = 1/2*m*(x'^2 + y'^2)
V = 1/2*k*(x^2 + y^2)
force x = -c*sin(y) - b*x'*cos(y) + u
force y = c*sin(x)*cos(y) - b*y'
equilibrium x = 0, y = 0
values m = 1.5, k = 2, c = 0.7, b = 0.3, u = 0
)";

} // namespace

TEST_CASE("forces: a circulatory force's stiffness in A against central differences of the equations",
          "[forces][state_space]")
{
    const model scene = load(follower);
    const analysis a = analyze(scene, {product::state_space, product::equations});
    REQUIRE(a.linearization);
    CHECK(a.linearization->circulatory());
    REQUIRE(a.state_space_values.size() == 1);
    const state_space_point& at = a.state_space_values.front();
    std::map<std::string, GiNaC::ex> values;
    for (const auto& [name, value] : scene.values.front().values)
        values[name] = value;
    values["u"] = 0;
    compiled_motion motion(scene, *a.equations, values);
    const auto rhs = [&](std::vector<double> x) {
        x.resize(motion.dimension(), 0.0);
        std::vector<double> out(motion.dimension());
        motion.rhs(0, x.data(), out.data());
        return out;
    };
    const double h = 1e-6;
    for (std::size_t j = 0; j < 4; ++j) {
        std::vector<double> plus(4, 0.0), minus(4, 0.0);
        plus[j] = h;
        minus[j] = -h;
        const std::vector<double> up = rhs(plus), down = rhs(minus);
        for (std::size_t i = 0; i < 4; ++i) {
            INFO("A(" << i << ", " << j << ")");
            CHECK_THAT(at.a(i, j), Catch::WithinAbs((up[i] - down[i]) / (2 * h), 1e-8));
        }
    }
    // K = k I + [[0, c], [−c, 0]]: ẍ = −(k x + c y)/m there
    CHECK_THAT(at.a(2, 1), Catch::WithinRel(-0.7 / 1.5, 1e-12));
    CHECK_THAT(at.a(3, 0), Catch::WithinRel(0.7 / 1.5, 1e-12));
}

TEST_CASE("forces: a circulatory force's eigenvalues are the roots of m s² + b s + k ± ic", "[forces][numeric]")
{
    const model scene = load(follower);
    const analysis a = analyze(scene, {product::numeric});
    REQUIRE(a.numeric);
    const std::vector<std::complex<double>>& computed = a.numeric->front().eigenvalues;
    REQUIRE(computed.size() == 4);
    const double m = 1.5, k = 2, c = 0.7, b = 0.3;
    for (double sign : {1.0, -1.0})
        for (double root : {1.0, -1.0}) {
            const std::complex<double> stiffness(k, sign * c);
            const std::complex<double> s = (-b + root * std::sqrt(b * b - 4 * m * stiffness)) / (2 * m);
            double nearest = 1e300;
            for (const std::complex<double>& e : computed)
                nearest = std::min(nearest, std::abs(e - s));
            INFO("s = " << s);
            CHECK(nearest <= 1e-12 * std::abs(s));
        }
    // circulatory: no real ω² nor mode shapes, and V alone does not decide the stability
    CHECK_THROWS_WITH(analyze(scene, {product::modes}), Catch::Contains("not defined"));
}

TEST_CASE("forces: a force that does not vanish at the equilibrium is refused", "[forces][errors]")
{
    std::string text = follower;
    text.replace(text.find("force y = "), std::string("force y = ").size(), "force y = c + ");
    CHECK_THROWS_WITH(analyze(load(text), {product::numeric}),
                      Catch::Contains("at the equilibrium (at rest, inputs 0), not 0"));
    // without an `equilibrium` line the equilibria of V are not those of the motion
    std::string unnamed = follower;
    unnamed.replace(unnamed.find("equilibrium x = 0, y = 0\n"), std::string("equilibrium x = 0, y = 0\n").size(), "");
    CHECK_THROWS_WITH(analyze(load(unnamed), {product::numeric}), Catch::Contains("`equilibrium` line"));
}
