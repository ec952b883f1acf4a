// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_constraints.cpp
 *  Constraints with multipliers: the front end's classification and errors, and the
 *  multipliers, accelerations and constraint forces of textbook systems against their
 *  closed forms (Atwood's tension, a bead's normal force, a pendulum's tension in
 *  Cartesian coordinates, a disc rolling down an incline, the Chaplygin sleigh, a
 *  parallelogram four-bar linkage) and SymPy's test_rolling_disc. */
#include "engine/analysis.h"
#include "mechanics/constraints.h"
#include "mechanics/equations_of_motion.h"
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

struct constrained {
    model scene;
    equations_of_motion equations;
    multipliers_result multipliers;
};

constrained solve(const std::string& text)
{
    constrained c{load(text), {}, {}};
    simplifier simplify = make_simplifier(c.scene);
    lagrangian_result lagrangian = derive_lagrangian(c.scene, simplify);
    c.equations = derive_equations_of_motion(c.scene, lagrangian, simplify, true);
    c.multipliers =
        derive_multipliers(c.scene, c.equations.mass, c.equations.forcing, *c.equations.constraints, simplify);
    return c;
}

} // namespace

TEST_CASE("constraints: holonomic and Pfaffian constraints are told apart", "[constraints]")
{
    model scene = load(R"(parameters m R
coordinates x phi z
T = 1/2*m*x'^2 + 1/4*m*R^2*phi'^2 + 1/2*m*z'^2
constraint roll: x' = R*phi'
constraint fixed: x^2 + phi = 1
)");
    REQUIRE(scene.constraints.size() == 2);
    const constraint& roll = scene.constraints[0];
    CHECK(roll.constraint_kind == constraint::kind::pfaffian);
    CHECK(roll.multiplier.get_name() == "lambda_roll");
    CHECK(same(roll.coefficients[0], 1));
    CHECK(same(roll.coefficients[1], -symbol_of(scene, "R")));
    CHECK(roll.rest.is_zero());
    const constraint& fixed = scene.constraints[1];
    CHECK(fixed.constraint_kind == constraint::kind::holonomic);
    CHECK(same(fixed.coefficients[0], 2 * symbol_of(scene, "x")));
    CHECK(same(fixed.coefficients[1], 1));
}

TEST_CASE("constraints: bad constraints are errors with a caret", "[constraints]")
{
    const std::string head = "parameters m l\ncoordinates x y z\nT = 1/2*m*(x'^2 + y'^2 + z'^2)\n";
    // Neither holonomic nor linear in the velocities: the caret at the left side's operator.
    require_error(head + "constraint c: x'^2 = y'\n", 4, 17, "neither");
    require_error(head + "constraint c: x'*y' = 0\n", 4, 15, "not linear in");
    // Redundant: the same constraint twice, scaled, and one that holds identically.
    require_error(head + "constraint a: x + y = l\nconstraint b: 2*x + 2*y = 2*l\n", 5, 12,
                  "constraint `b` is redundant: it follows from constraint `a`");
    require_error(head + "constraint a: x^2 + y^2 = l^2\nconstraint b: (x^2 + y^2)^2 = l^4\n", 5, 12,
                  "is redundant");
    require_error(head + "constraint a: x = x\n", 4, 12, "holds identically");
    // Inconsistent.
    require_error(head + "constraint a: x + y = l\nconstraint b: x + y = 2*l\n", 5, 12,
                  "constraint `b` is inconsistent with constraint `a`");
    require_error(head + "constraint a: x^2 + y^2 = l^2\nconstraint b: x^2 + y^2 = 2*l^2\n", 5, 12,
                  "is inconsistent");
    require_error(head + "constraint a: x' = y'\nconstraint b: x' - y' = l\n", 5, 12, "is inconsistent");
    require_error(head + "constraint a: l = 2\n", 4, 12, "is inconsistent");
    // A redundant Pfaffian constraint: the velocity form of a holonomic one.
    require_error(head + "constraint a: x = l*y\nconstraint b: x' = l*y'\n", 5, 12, "is redundant");
    // Dependent on two others.
    require_error(head + "constraint a: x = y\nconstraint b: y = z\nconstraint c: x = z\n", 6, 12,
                  "follows from constraints `a` and `b`");
    // No freedom left, a name twice, a multiplier's name taken.
    require_error(head + "constraint a: x = 0\nconstraint b: y = 0\nconstraint c: z = 0\n", 6, 12,
                  "no degree of freedom");
    require_error(head + "constraint a: x = 0\nconstraint a: y = 0\n", 5, 12, "already declared");
    require_error("parameters m lambda_a\ncoordinates x y\nT = 1/2*m*x'^2\nconstraint a: x = y\n", 4, 12,
                  "`lambda_a`");
    require_error(head + "constraint a x = 0\n", 4, 14, "`:`");
}

TEST_CASE("constraints: Atwood's machine, the multiplier is the tension", "[constraints]")
{
    constrained c = solve(R"(parameters m1 m2 g l
coordinates y1 y2
point P1 mass m1 at (0, y1)
point P2 mass m2 at (1, y2)
gravity g along (0, -1)
constraint string: y1 + y2 = -l
)");
    GiNaC::ex m1 = symbol_of(c.scene, "m1"), m2 = symbol_of(c.scene, "m2"), g = symbol_of(c.scene, "g");
    GiNaC::ex tension = 2 * m1 * m2 * g / (m1 + m2);
    REQUIRE(c.multipliers.constraints.size() == 1);
    CHECK(same(c.multipliers.constraints[0].multiplier, tension));
    // a = (m2 − m1) g/(m1 + m2) upward for m1.
    CHECK(same(c.multipliers.accelerations[0], (m2 - m1) * g / (m1 + m2)));
    // The string pulls each mass up with the tension.
    REQUIRE(c.multipliers.constraints[0].forces.size() == 2);
    for (const constraint_point_force& f : c.multipliers.constraints[0].forces) {
        REQUIRE(f.force.size() == 2);
        CHECK(f.force[0].is_zero());
        CHECK(same(f.force[1], tension));
    }
    CHECK(c.equations.constraints->integrable[0]);
    // The printed equation of y1: m1 y1'' + m1 g − λ = 0.
    CHECK(same((*c.equations.residuals)[0],
               m1 * symbol_of(c.scene, "y1_ddot") + m1 * g - c.scene.constraints[0].multiplier));
}

TEST_CASE("constraints: a bead on a circular wire, the normal force", "[constraints]")
{
    constrained c = solve(R"(parameters m g R
coordinates r theta
point bead mass m at (r*sin(theta), -r*cos(theta))
gravity g along (0, -1)
constraint wire: r = R
)");
    GiNaC::ex m = symbol_of(c.scene, "m"), g = symbol_of(c.scene, "g"), r = symbol_of(c.scene, "r");
    GiNaC::ex theta = symbol_of(c.scene, "theta"), w = symbol_of(c.scene, "theta_dot");
    // Along r̂ (outward): the wire pulls in with m(r θ̇² + g cos θ).
    GiNaC::ex normal = -m * (r * w * w + g * GiNaC::cos(theta));
    CHECK(same(c.multipliers.constraints[0].multiplier, normal));
    const std::vector<GiNaC::ex>& f = c.multipliers.constraints[0].forces.at(0).force;
    std::mt19937 random(13);
    std::uniform_real_distribution<double> u(-1, 1), positive(0.5, 2.0);
    for (int k = 0; k < 5; ++k) {
        GiNaC::exmap at{{m, positive(random)},   {g, positive(random)},    {r, positive(random)},
                        {theta, 3 * u(random)}, {w, u(random)},           {symbol_of(c.scene, "R"), 1},
                        {symbol_of(c.scene, "r_dot"), 0}};
        CHECK(value_at(f[0], at) == Approx(value_at(normal * GiNaC::sin(theta), at)).margin(1e-12));
        CHECK(value_at(f[1], at) == Approx(value_at(-normal * GiNaC::cos(theta), at)).margin(1e-12));
        // θ̈ = −(g/r) sin θ on the wire (ṙ = 0).
        CHECK(value_at(c.multipliers.accelerations[1], at) ==
              Approx(value_at(-g / r * GiNaC::sin(theta), at)).margin(1e-12));
    }
}

TEST_CASE("constraints: a pendulum in Cartesian coordinates, the tension", "[constraints]")
{
    constrained c = solve(R"(parameters m g l
coordinates x y
point bob mass m at (x, y)
gravity g along (0, -1)
constraint rod: x^2 + y^2 = l^2
)");
    const constraint_multiplier& rod = c.multipliers.constraints.at(0);
    REQUIRE(rod.forces.size() == 1);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> angle(-1.5, 1.5), positive(0.5, 2.0);
    for (int k = 0; k < 5; ++k) {
        const double m = positive(random), g = positive(random), l = positive(random);
        const double theta = angle(random), w = angle(random);
        GiNaC::exmap at{{symbol_of(c.scene, "m"), m},
                        {symbol_of(c.scene, "g"), g},
                        {symbol_of(c.scene, "l"), l},
                        {symbol_of(c.scene, "x"), l * std::sin(theta)},
                        {symbol_of(c.scene, "y"), -l * std::cos(theta)},
                        {symbol_of(c.scene, "x_dot"), l * std::cos(theta) * w},
                        {symbol_of(c.scene, "y_dot"), l * std::sin(theta) * w}};
        const double tension = m * (g * std::cos(theta) + l * w * w);
        // The force on the bob points to the pivot with the tension's magnitude.
        const double fx = value_at(rod.forces[0].force[0], at), fy = value_at(rod.forces[0].force[1], at);
        CHECK(fx == Approx(-tension * std::sin(theta)).margin(1e-12));
        CHECK(fy == Approx(tension * std::cos(theta)).margin(1e-12));
        CHECK(-2 * l * value_at(rod.multiplier, at) == Approx(tension));
        // The angular acceleration of the polar pendulum: −(g/l) sin θ.
        const double ax = value_at(c.multipliers.accelerations[0], at);
        const double ay = value_at(c.multipliers.accelerations[1], at);
        const double angular = (ax * std::cos(theta) + ay * std::sin(theta)) / l;
        CHECK(angular == Approx(-g / l * std::sin(theta)));
    }
}

TEST_CASE("constraints: a disc rolling down an incline accelerates at 2/3 g sin(alpha)", "[constraints]")
{
    constrained c = solve(R"(parameters m g R alpha
coordinates x phi
T = 1/2*m*x'^2 + 1/2*(1/2*m*R^2)*phi'^2
V = -m*g*x*sin(alpha)
constraint roll: x' = R*phi'
)");
    GiNaC::ex m = symbol_of(c.scene, "m"), g = symbol_of(c.scene, "g"), alpha = symbol_of(c.scene, "alpha");
    CHECK(same(c.multipliers.accelerations[0], GiNaC::numeric(2, 3) * g * GiNaC::sin(alpha)));
    CHECK(same(c.multipliers.accelerations[1], GiNaC::numeric(2, 3) * g * GiNaC::sin(alpha) / symbol_of(c.scene, "R")));
    // Friction up the slope: m g sin α / 3.
    CHECK(same(c.multipliers.constraints[0].multiplier, -m * g * GiNaC::sin(alpha) / 3));
    CHECK(c.scene.constraints[0].constraint_kind == constraint::kind::pfaffian);
    CHECK(c.equations.constraints->integrable[0]);
    CHECK(c.equations.constraints->jointly_integrable);
}

TEST_CASE("constraints: the Chaplygin sleigh", "[constraints]")
{
    // Centre of mass at (x, y), the knife edge a behind it along the heading θ.
    constrained c = solve(R"(parameters m I a
coordinates x y theta
T = 1/2*m*(x'^2 + y'^2) + 1/2*I*theta'^2
constraint blade: -sin(theta)*x' + cos(theta)*y' = a*theta'
)");
    CHECK_FALSE(c.equations.constraints->integrable[0]);
    CHECK_FALSE(c.equations.constraints->jointly_integrable);
    // With v the forward speed and ω = θ̇ (Bloch, Nonholonomic Mechanics and Control §1.7):
    // v̇ = a ω², ω̇ = −m a v ω/(I + m a²).
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(-1, 1), positive(0.5, 2.0);
    for (int k = 0; k < 5; ++k) {
        const double m = positive(random), inertia = positive(random), a = positive(random);
        const double theta = 3 * u(random), v = u(random), w = u(random);
        // Velocities that satisfy the constraint.
        const double xd = v * std::cos(theta) - a * w * std::sin(theta);
        const double yd = v * std::sin(theta) + a * w * std::cos(theta);
        GiNaC::exmap at{{symbol_of(c.scene, "m"), m},         {symbol_of(c.scene, "I"), inertia},
                        {symbol_of(c.scene, "a"), a},         {symbol_of(c.scene, "theta"), theta},
                        {symbol_of(c.scene, "x_dot"), xd},    {symbol_of(c.scene, "y_dot"), yd},
                        {symbol_of(c.scene, "theta_dot"), w}, {symbol_of(c.scene, "x"), u(random)},
                        {symbol_of(c.scene, "y"), u(random)}};
        const double xdd = value_at(c.multipliers.accelerations[0], at);
        const double ydd = value_at(c.multipliers.accelerations[1], at);
        const double wd = value_at(c.multipliers.accelerations[2], at);
        const double vd = xdd * std::cos(theta) + ydd * std::sin(theta) + w * (-xd * std::sin(theta) + yd * std::cos(theta));
        CHECK(vd == Approx(a * w * w).margin(1e-12));
        CHECK(wd == Approx(-m * a * v * w / (inertia + m * a * a)).margin(1e-12));
    }
    // λ = I m θ̇ (ẋ cos θ + ẏ sin θ)/(I + m a²): no blade coefficient (sin θ, cos θ or a) is
    // divided out and left in the denominator, where it would make λ 0/0 or uncancelled.
    const GiNaC::ex lambda = c.multipliers.constraints[0].multiplier;
    const GiNaC::ex inertia = symbol_of(c.scene, "I"), m = symbol_of(c.scene, "m"), a = symbol_of(c.scene, "a");
    CHECK(same(lambda.denom(), inertia + m * a * a));
    CHECK(same(lambda, inertia * m * symbol_of(c.scene, "theta_dot") *
                           (symbol_of(c.scene, "x_dot") * cos(symbol_of(c.scene, "theta")) +
                            symbol_of(c.scene, "y_dot") * sin(symbol_of(c.scene, "theta"))) /
                           (inertia + m * a * a)));
}

TEST_CASE("constraints: a parallelogram four-bar linkage has one degree of freedom", "[constraints]")
{
    // Cranks of length l at (0, 0) and (d, 0), coupler of length d: B and C carry masses.
    constrained c = solve(R"(parameters m g l d
coordinates q1 q2 q3
point B mass m at (l*cos(q1), l*sin(q1))
point C mass m at (d + l*cos(q3), l*sin(q3))
gravity g along (0, -1)
constraint closex: l*cos(q1) + d*cos(q2) = d + l*cos(q3)
constraint closey: l*sin(q1) + d*sin(q2) = l*sin(q3)
)");
    CHECK(c.scene.coordinates.size() - c.scene.constraints.size() == 1);
    // On the parallelogram branch q2 = 0, q3 = q1 both cranks swing as one pendulum:
    // q1'' = q3'' = −(g/l) cos q1, q2'' = 0.
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(-1, 1), positive(0.5, 2.0);
    for (int k = 0; k < 5; ++k) {
        const double m = positive(random), g = positive(random), l = positive(random), d = positive(random);
        const double q = 3 * u(random), w = u(random);
        GiNaC::exmap at{{symbol_of(c.scene, "m"), m},       {symbol_of(c.scene, "g"), g},
                        {symbol_of(c.scene, "l"), l},       {symbol_of(c.scene, "d"), d},
                        {symbol_of(c.scene, "q1"), q},      {symbol_of(c.scene, "q2"), 0},
                        {symbol_of(c.scene, "q3"), q},      {symbol_of(c.scene, "q1_dot"), w},
                        {symbol_of(c.scene, "q2_dot"), 0},  {symbol_of(c.scene, "q3_dot"), w}};
        CHECK(value_at(c.multipliers.accelerations[0], at) == Approx(-g / l * std::cos(q)));
        CHECK(value_at(c.multipliers.accelerations[1], at) == Approx(0).margin(1e-12));
        CHECK(value_at(c.multipliers.accelerations[2], at) == Approx(-g / l * std::cos(q)));
    }
}

TEST_CASE("constraints: the rolling disc matches SymPy's test_rolling_disc", "[constraints]")
{
    // SymPy (test_kane.py) orients the disc by z q1, x q2, y q3 with its axis along L.y and
    // takes the generalized speeds u1 = ω·L.x, u2 = ω·L.y, u3 = ω·L.z. Here zxz(q1, q2 + π/2, q3)
    // puts the axis (body z) along −L.y, so q3 is SymPy's −q3: u1 = q2', u2 = −q3' + q1' sin q2,
    // u3 = q1' cos q2. The contact point (x, y) rolls: ẋ + r q3' cos q1 = 0, ẏ + r q3' sin q1 = 0.
    constrained c = solve(R"(parameters m g r
coordinates x y q1 q2 q3
body D disk(r) mass m at (x + r*sin(q2)*sin(q1), y - r*sin(q2)*cos(q1), r*cos(q2)) \
    orientation zxz(q1, q2 + pi/2, q3)
gravity g along (0, 0, -1)
constraint rollx: x' = -r*q3'*cos(q1)
constraint rolly: y' = -r*q3'*sin(q1)
)");
    CHECK_FALSE(c.equations.constraints->integrable[0]);
    CHECK_FALSE(c.equations.constraints->integrable[1]);
    CHECK_FALSE(c.equations.constraints->jointly_integrable);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(-1, 1), positive(0.5, 2.0);
    for (int k = 0; k < 5; ++k) {
        const double m = positive(random), g = positive(random), r = positive(random);
        const double q1 = 3 * u(random), q2 = u(random), q3 = 3 * u(random);
        const double w1 = u(random), w2 = u(random), w3 = u(random);
        GiNaC::exmap at{{symbol_of(c.scene, "m"), m},         {symbol_of(c.scene, "g"), g},
                        {symbol_of(c.scene, "r"), r},         {symbol_of(c.scene, "x"), u(random)},
                        {symbol_of(c.scene, "y"), u(random)}, {symbol_of(c.scene, "q1"), q1},
                        {symbol_of(c.scene, "q2"), q2},       {symbol_of(c.scene, "q3"), q3},
                        {symbol_of(c.scene, "x_dot"), -r * w3 * std::cos(q1)},
                        {symbol_of(c.scene, "y_dot"), -r * w3 * std::sin(q1)},
                        {symbol_of(c.scene, "q1_dot"), w1},   {symbol_of(c.scene, "q2_dot"), w2},
                        {symbol_of(c.scene, "q3_dot"), w3}};
        const double u1 = w2, u2 = -w3 + w1 * std::sin(q2), u3 = w1 * std::cos(q2);
        const double a1 = value_at(c.multipliers.accelerations[2], at);
        const double a2 = value_at(c.multipliers.accelerations[3], at);
        const double a3 = value_at(c.multipliers.accelerations[4], at);
        const double u1_rate = a2;
        const double u2_rate = -a3 + a1 * std::sin(q2) + w1 * w2 * std::cos(q2);
        const double u3_rate = a1 * std::cos(q2) - w1 * w2 * std::sin(q2);
        // SymPy's KM.rhs: (6 u2 u3 r − u3² r tan q2 + 4 g sin q2)/(5r), −2 u1 u3/3, u1 (−2 u2 + u3 tan q2).
        CHECK(u1_rate == Approx((6 * u2 * u3 * r - u3 * u3 * r * std::tan(q2) + 4 * g * std::sin(q2)) / (5 * r)));
        CHECK(u2_rate == Approx(-2 * u1 * u3 / 3).margin(1e-12));
        CHECK(u3_rate == Approx(u1 * (-2 * u2 + u3 * std::tan(q2))).margin(1e-12));
    }
}

TEST_CASE("constraints: the multipliers stage runs with the equations", "[constraints]")
{
    model scene = load(R"(parameters m1 m2 g l
coordinates y1 y2
point P1 mass m1 at (0, y1)
point P2 mass m2 at (1, y2)
gravity g along (0, -1)
constraint string: y1 + y2 = -l
want equations, multipliers
)");
    analysis result = analyze(scene);
    REQUIRE(result.multipliers);
    CHECK(result.equations->constraints);
    model plain = load("parameters m\ncoordinates x\nT = 1/2*m*x'^2\n");
    CHECK_THROWS_AS(analyze(plain, {product::multipliers}), computation_error);
}

TEST_CASE("constraints: the ladder leaves the wall at 2/3 of its initial height", "[constraints][simulation]")
{
    // From rest at θ0 the wall's push vanishes where cos θ = (2/3) cos θ0 (energy and the
    // centre of mass on a circle of radius l/2).
    model scene = load(R"(parameters m l g
coordinates x y theta
T = 1/2*m*(x'^2 + y'^2) + 1/2*(m*l^2/12)*theta'^2
V = m*g*y
constraint wall: x = l/2*sin(theta)
constraint floor: y = l/2*cos(theta)
values m = 1.5, l = 2, g = 9.81
initial x = sin(0.3), y = cos(0.3), theta = 0.3
simulate until 1
want simulation
)");
    analysis result = analyze(scene);
    REQUIRE(result.simulation);
    const simulation_result& s = *result.simulation;
    REQUIRE(s.constraint_residual);
    CHECK(*s.constraint_residual < 1e-9);
    CHECK_FALSE(s.initial_residual);
    REQUIRE_FALSE(s.run.invariant_drift.empty());
    CHECK(s.run.invariant_drift[0].first == "energy");
    CHECK(s.run.invariant_drift[0].second < 1e-9);
    REQUIRE(s.constraint_events.size() == 1);
    const constraint_event& leaves = s.constraint_events[0];
    CHECK(leaves.constraint == "wall");
    const double theta = leaves.state.at(2);
    // The top's height l cos θ is 2/3 of l cos θ0.
    CHECK(std::cos(theta) == Approx(2.0 / 3.0 * std::cos(0.3)).epsilon(1e-8));
    // The time from the energy equation: t = ∫ dθ / θ̇ with θ̇² = (3g/l)(cos θ0 − cos θ), by Simpson's rule
    // in u where θ = θ0 + u² (removing the endpoint singularity).
    const double g = 9.81, l = 2, theta0 = 0.3;
    auto integrand = [&](double u) {
        const double th = theta0 + u * u;
        if (u == 0)
            return 2 / std::sqrt(3 * g / l * std::sin(theta0));
        return 2 * u / std::sqrt(3 * g / l * (std::cos(theta0) - std::cos(th)));
    };
    const double top = std::sqrt(theta - theta0);
    const int steps = 2000;
    double sum = integrand(0) + integrand(top);
    for (int k = 1; k < steps; ++k)
        sum += (k % 2 ? 4 : 2) * integrand(top * k / steps);
    CHECK(leaves.time == Approx(sum * top / steps / 3).epsilon(1e-6));
}

TEST_CASE("constraints: a projected simulation keeps Atwood's string taut", "[constraints][simulation]")
{
    model scene = load(R"(parameters m1 m2 g l
coordinates y1 y2
point P1 mass m1 at (0, y1)
point P2 mass m2 at (1, y2)
gravity g along (0, -1)
constraint string: y1 + y2 = -l
values m1 = 1, m2 = 3, g = 9.81, l = 2
initial y1 = -1.2, y2 = -1
simulate until 1
want simulation
)");
    // Off the string by 0.2: an error by default (below), projected when asked (by least
    // change: 0.1 each).
    simulation_settings project;
    project.project_initial = true;
    analysis result = analyze(scene, {}, {}, project);
    const simulation_result& s = *result.simulation;
    REQUIRE(s.initial_residual);
    REQUIRE(s.projected_initial);
    CHECK((*s.projected_initial)[0] == Approx(-1.1));
    CHECK((*s.projected_initial)[1] == Approx(-0.9));
    CHECK(*s.initial_residual == Approx(0.2));
    CHECK(s.run.states.front()[0] == Approx(-1.1));
    // a = (m2 − m1) g/(m1 + m2) upward for m1, from rest: y1(1) = −1.1 + a/2.
    const double a = (3.0 - 1.0) * 9.81 / 4.0;
    CHECK(s.run.final_state[0] == Approx(-1.1 + a / 2).epsilon(1e-10));
    CHECK(s.run.final_state[0] + s.run.final_state[1] == Approx(-2).epsilon(1e-12));
    CHECK(s.constraint_events.empty());
}

TEST_CASE("constraints: an initial state off the constraints is an error at its value", "[constraints][simulation]")
{
    // The ladder given only θ(0) = 0.3: x = y = 0 is far off both constraints. The
    // least-change projection moves x and y (here onto sin 0.3, cos 0.3), but another scene's
    // may land far from what was meant: it is never done silently. The error points at the
    // written value the projection moves most (θ, the only one written), names the
    // constraints and their residuals, and suggests the projected state.
    const std::string text = R"(parameters m l g
coordinates x y theta
T = 1/2*m*(x'^2 + y'^2) + 1/2*(m*l^2/12)*theta'^2
V = m*g*y
constraint wall: x = l/2*sin(theta)
constraint floor: y = l/2*cos(theta)
values m = 1, l = 2, g = 9.81
initial theta = 0.3
simulate until 0.2
want simulation
)";
    model scene = load(text);
    try {
        analyze(scene);
        FAIL("no error");
    } catch (const scene_error& e) {
        const std::string message = e.what();
        INFO(message);
        CHECK(e.where().line == 8);
        CHECK(e.where().column == 17);
        CHECK(e.has_line_text());
        CHECK(e.line_text() == "initial theta = 0.3");
        CHECK(message.find("`floor` by 0.955") != std::string::npos);
        CHECK(message.find("`wall` by 0.296") != std::string::npos);
        CHECK(message.find("`initial x = 0.2955202066613395") != std::string::npos);
        CHECK(message.find("--project-initial") != std::string::npos);
    }
    // Asked to project, it starts from the projected state and says so.
    simulation_settings project;
    project.project_initial = true;
    analysis result = analyze(scene, {}, {}, project);
    REQUIRE(result.simulation);
    REQUIRE(result.simulation->projected_initial);
    const std::vector<double>& x0 = *result.simulation->projected_initial;
    CHECK(x0[0] == Approx(std::sin(x0[2])).margin(1e-12)); // on the wall
    CHECK(x0[1] == Approx(std::cos(x0[2])).margin(1e-12)); // on the floor
    CHECK(x0[2] == Approx(0.3).epsilon(1e-12));
    CHECK(*result.simulation->initial_residual == Approx(0.955336).epsilon(1e-5));
    // A velocity off a velocity constraint is located at that velocity.
    model rolling = load(R"(parameters m R
coordinates x phi
T = 1/2*m*x'^2 + 1/4*m*R^2*phi'^2
constraint roll: x' = R*phi'
values m = 1, R = 0.5
initial x = 0, phi = 0, x' = 1, phi' = 0.1
simulate until 0.2
want simulation
)");
    try {
        analyze(rolling);
        FAIL("no error");
    } catch (const scene_error& e) {
        INFO(e.what());
        CHECK(e.where().line == 6);
        CHECK(e.where().column == 30); // the 1 of x' = 1
        CHECK(std::string(e.what()).find("`roll` by 0.95") != std::string::npos);
    }
}

TEST_CASE("constraints: a pendulum in Cartesian coordinates oscillates at g/l", "[constraints][linearization]")
{
    model scene = load(R"(parameters m g l
coordinates x y
point bob mass m at (x, y)
gravity g along (0, -1)
constraint rod: x^2 + y^2 = l^2
equilibrium x = 0, y = -l
want frequencies
)");
    analysis result = analyze(scene);
    REQUIRE(result.constrained);
    REQUIRE(result.constrained->independent == std::vector<std::size_t>{0});
    REQUIRE(result.modes);
    REQUIRE(result.modes->frequencies.size() == 1);
    CHECK(same(result.modes->frequencies[0], symbol_of(scene, "g") / symbol_of(scene, "l")));
    CHECK(result.equilibria->points[0].kind == stability::stable);
    // The static tension m g: λ* = −m g/(2l) with the force λ ∇f = λ (2x, 2y).
    CHECK(same(result.constrained->multipliers[0], -symbol_of(scene, "m") * symbol_of(scene, "g") /
                                                        (2 * symbol_of(scene, "l"))));
    // Upside down: unstable. Off the rod: an error.
    model inverted = load(R"(parameters m g l
coordinates x y
point bob mass m at (x, y)
gravity g along (0, -1)
constraint rod: x^2 + y^2 = l^2
equilibrium x = 0, y = l
want frequencies
)");
    CHECK(analyze(inverted).equilibria->points[0].kind == stability::unstable);
    model off = load(R"(parameters m g l
coordinates x y
point bob mass m at (x, y)
gravity g along (0, -1)
constraint rod: x^2 + y^2 = l^2
equilibrium x = l, y = 0
want frequencies
)");
    CHECK_THROWS_AS(analyze(off), computation_error);
}

TEST_CASE("constraints: two Cartesian pendulums reduce to one coordinate each",
          "[constraints][linearization]")
{
    // Two pendulum bobs on rods of lengths l and 2 l side by side, written in Cartesian
    // coordinates: ω² = g/l and g/(2 l), each with its own independent coordinate.
    model scene = load(R"(parameters m g l
coordinates x1 y1 x2 y2
point A mass m at (x1, y1)
point B mass m at (x2, y2)
gravity g along (0, -1)
constraint rod1: x1^2 + y1^2 = l^2
constraint rod2: x2^2 + y2^2 = 4*l^2
equilibrium x1 = 0, y1 = -l, x2 = 0, y2 = -2*l
want frequencies
)");
    analysis result = analyze(scene);
    REQUIRE(result.constrained->independent == std::vector<std::size_t>{0, 2});
    REQUIRE(result.modes->frequencies.size() == 2);
    GiNaC::ex g = symbol_of(scene, "g"), l = symbol_of(scene, "l");
    const bool in_order = same(result.modes->frequencies[0], g / (2 * l)) && same(result.modes->frequencies[1], g / l);
    const bool reversed = same(result.modes->frequencies[1], g / (2 * l)) && same(result.modes->frequencies[0], g / l);
    CHECK((in_order || reversed));
}
