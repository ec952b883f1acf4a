// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_lagrangian.cpp
 *  L = T − V and the Euler–Lagrange equations against textbook closed forms and
 *  a finite-difference check. */
#include "mechanics/equations_of_motion.h"
#include "mechanics/lagrangian.h"
#include "algebra/simplify.h"
#include "scene/lower.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <random>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::symbol_of;

namespace {

const char* double_pendulum_points = R"(parameters M m l g
coordinates theta phi
point upper mass M at (l*sin(theta), -l*cos(theta))
point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))
gravity g along (0, -1)
)";

const char* double_pendulum_energies = R"(parameters M m l g
coordinates theta phi
T = 1/2*(M+m)*l^2*theta'^2 + m*l^2*cos(theta-phi)*theta'*phi' + 1/2*m*l^2*phi'^2
V = -(M+m)*g*l*cos(theta) - m*g*l*cos(phi)
)";

struct derived {
    model scene;
    lagrangian_result lagrangian;
    std::vector<GiNaC::ex> equations;
};

derived derive(const std::string& text)
{
    derived d{load(text), {}, {}};
    simplifier simplify = make_simplifier(d.scene);
    d.lagrangian = derive_lagrangian(d.scene, simplify);
    d.equations = derive_equations(d.scene, d.lagrangian, simplify);
    return d;
}

/// The textbook double pendulum, in the symbols of `scene`.
struct textbook_double_pendulum {
    GiNaC::ex kinetic, potential, theta_equation, phi_equation;
    explicit textbook_double_pendulum(const model& s)
    {
        GiNaC::ex M = symbol_of(s, "M"), m = symbol_of(s, "m"), l = symbol_of(s, "l"), g = symbol_of(s, "g");
        GiNaC::ex th = symbol_of(s, "theta"), ph = symbol_of(s, "phi");
        GiNaC::ex thd = symbol_of(s, "theta_dot"), phd = symbol_of(s, "phi_dot");
        GiNaC::ex thdd = symbol_of(s, "theta_ddot"), phdd = symbol_of(s, "phi_ddot");
        GiNaC::ex half = GiNaC::numeric(1, 2);
        kinetic = half * (M + m) * l * l * thd * thd + m * l * l * cos(th - ph) * thd * phd + half * m * l * l * phd * phd;
        potential = -(M + m) * g * l * cos(th) - m * g * l * cos(ph);
        theta_equation = (M + m) * l * l * thdd + m * l * l * cos(th - ph) * phdd +
                         m * l * l * sin(th - ph) * phd * phd + (M + m) * g * l * sin(th);
        phi_equation = m * l * l * phdd + m * l * l * cos(th - ph) * thdd - m * l * l * sin(th - ph) * thd * thd +
                       m * g * l * sin(ph);
    }
};

/// Equal as functions of the angles of `scene` (canonical trig form of the difference is 0).
bool same_expanded(const GiNaC::ex& a, const GiNaC::ex& b, const model& scene)
{
    return trig_equal(a, b, scene.positions());
}

/// Number of factors of a term of the expanded form that are sin or cos (with multiplicity).
int most_trig_factors(const GiNaC::ex& e)
{
    GiNaC::ex expanded = e.expand();
    int most = 0;
    auto terms = GiNaC::is_a<GiNaC::add>(expanded) ? expanded : GiNaC::ex(GiNaC::lst{expanded});
    for (const GiNaC::ex& term : terms) {
        int count = 0;
        auto factors = GiNaC::is_a<GiNaC::mul>(term) ? term : GiNaC::ex(GiNaC::lst{term});
        for (const GiNaC::ex& f : factors) {
            GiNaC::ex base = GiNaC::is_a<GiNaC::power>(f) ? f.op(0) : f;
            int multiplicity = GiNaC::is_a<GiNaC::power>(f) ? GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int() : 1;
            if (GiNaC::is_exactly_a<GiNaC::function>(base) &&
                (GiNaC::is_a<GiNaC::function>(base) && (GiNaC::ex_to<GiNaC::function>(base).get_name() == "sin" || GiNaC::ex_to<GiNaC::function>(base).get_name() == "cos")))
                count += multiplicity;
        }
        most = std::max(most, count);
    }
    return most;
}

} // namespace

TEST_CASE("lagrangian: double pendulum from points gives the textbook T exactly", "[lagrangian]")
{
    derived d = derive(double_pendulum_points);
    textbook_double_pendulum textbook(d.scene);
    // Exactly: after the canonical form, no sin^2 + cos^2 and no cos*cos products remain.
    CHECK(same_expanded(d.lagrangian.kinetic, textbook.kinetic, d.scene));
    CHECK(same_expanded(d.lagrangian.potential, textbook.potential, d.scene));
    CHECK(same_expanded(d.lagrangian.lagrangian, textbook.kinetic - textbook.potential, d.scene));
    CHECK(most_trig_factors(d.lagrangian.kinetic) == 1);
    CHECK(most_trig_factors(d.lagrangian.potential) == 1);
}

TEST_CASE("lagrangian: points and energies give the same Lagrangian", "[lagrangian]")
{
    derived from_points = derive(double_pendulum_points);
    derived from_energies = derive(double_pendulum_energies);
    // Different symbol objects: compare through the names.
    GiNaC::exmap rename;
    for (const char* name : {"M", "m", "l", "g", "theta", "phi", "theta_dot", "phi_dot"})
        rename[symbol_of(from_energies.scene, name)] = symbol_of(from_points.scene, name);
    CHECK(same_expanded(from_points.lagrangian.lagrangian, from_energies.lagrangian.lagrangian.subs(rename), from_points.scene));
    CHECK(same_expanded(from_points.lagrangian.kinetic, from_energies.lagrangian.kinetic.subs(rename), from_points.scene));
}

TEST_CASE("equations: double pendulum in compact textbook form", "[equations]")
{
    derived d = derive(double_pendulum_points);
    textbook_double_pendulum textbook(d.scene);
    REQUIRE(d.equations.size() == 2);
    CHECK(same_expanded(d.equations[0], textbook.theta_equation, d.scene));
    CHECK(same_expanded(d.equations[1], textbook.phi_equation, d.scene));
    CHECK(most_trig_factors(d.equations[0]) == 1);
    CHECK(most_trig_factors(d.equations[1]) == 1);
}

TEST_CASE("lagrangian: L given is split by degree in the velocities", "[lagrangian]")
{
    derived d = derive("parameters m q0 B\ncoordinates x y\nL = 1/2*m*(x'^2 + y'^2) + q0*B*(x*y' - y*x')/2 - m*x\n");
    REQUIRE(d.lagrangian.split);
    GiNaC::ex m = symbol_of(d.scene, "m"), x = symbol_of(d.scene, "x");
    CHECK(same_expanded(d.lagrangian.potential, m * x, d.scene));
    CHECK_FALSE(d.lagrangian.gyroscopic.is_zero());
    // Charged particle in a magnetic field (symmetric gauge): m x'' − q B y' + m = 0, m y'' + q B x' = 0.
    GiNaC::ex q0 = symbol_of(d.scene, "q0"), B = symbol_of(d.scene, "B");
    CHECK(same_expanded(d.equations[0], m * symbol_of(d.scene, "x_ddot") - q0 * B * symbol_of(d.scene, "y_dot") + m, d.scene));
    CHECK(same_expanded(d.equations[1], m * symbol_of(d.scene, "y_ddot") + q0 * B * symbol_of(d.scene, "x_dot"), d.scene));
}

TEST_CASE("lagrangian: a non-polynomial L is kept whole", "[lagrangian]")
{
    derived d = derive("parameters m c\ncoordinates x\nL = -m*c^2*sqrt(1 - x'^2/c^2)\n");
    CHECK_FALSE(d.lagrangian.split);
    REQUIRE(d.equations.size() == 1);
    // Relativistic free particle: d/dt(m γ v) = m γ³ a.
    GiNaC::ex m = symbol_of(d.scene, "m"), c = symbol_of(d.scene, "c"), v = symbol_of(d.scene, "x_dot"),
              a = symbol_of(d.scene, "x_ddot");
    GiNaC::ex expected = m * a * GiNaC::pow(1 - v * v / (c * c), GiNaC::numeric(-3, 2));
    GiNaC::exmap at{{m, 2}, {c, 3}, {v, GiNaC::numeric(1, 2)}, {a, GiNaC::numeric(7, 5)}};
    CHECK(GiNaC::ex_to<GiNaC::numeric>((d.equations[0] - expected).subs(at).evalf()).to_double() ==
          Approx(0).margin(1e-12));
}

TEST_CASE("lagrangian: spring with a rest length, and a driven support (explicit t)", "[lagrangian]")
{
    derived spring = derive("parameters m k a\ncoordinates x y\npoint P mass m at (x, y)\n"
                            "spring k between P and (0, 0) rest a\n");
    GiNaC::ex k = symbol_of(spring.scene, "k"), a = symbol_of(spring.scene, "a"), x = symbol_of(spring.scene, "x"),
              y = symbol_of(spring.scene, "y");
    GiNaC::ex expected = GiNaC::numeric(1, 2) * k * GiNaC::pow(GiNaC::sqrt(x * x + y * y) - a, 2);
    GiNaC::exmap at{{k, 3}, {a, GiNaC::numeric(1, 2)}, {x, GiNaC::numeric(3, 10)}, {y, GiNaC::numeric(-7, 10)}};
    CHECK(GiNaC::ex_to<GiNaC::numeric>((spring.lagrangian.potential - expected).subs(at).evalf()).to_double() ==
          Approx(0).margin(1e-14));

    derived driven = derive("parameters m l g A w\ncoordinates q\n"
                            "point P mass m at (A*cos(w*t) + l*sin(q), -l*cos(q))\ngravity g along (0, -1)\n");
    GiNaC::ex m = symbol_of(driven.scene, "m"), l = symbol_of(driven.scene, "l"), g = symbol_of(driven.scene, "g"),
              A = symbol_of(driven.scene, "A"), w = symbol_of(driven.scene, "w"), q = symbol_of(driven.scene, "q"),
              t = symbol_of(driven.scene, "t"), qdd = symbol_of(driven.scene, "q_ddot");
    // m l² q̈ − m A w² l cos(w t) cos q + m g l sin q = 0
    GiNaC::ex expected_equation = m * l * l * qdd - m * A * w * w * l * cos(w * t) * cos(q) + m * g * l * sin(q);
    GiNaC::exmap point{{m, 2}, {l, GiNaC::numeric(3, 2)}, {g, GiNaC::numeric(981, 100)}, {A, GiNaC::numeric(1, 10)},
                       {w, 5}, {q, GiNaC::numeric(2, 5)}, {t, GiNaC::numeric(13, 10)}, {qdd, GiNaC::numeric(-1, 3)}};
    CHECK(GiNaC::ex_to<GiNaC::numeric>((driven.equations[0] - expected_equation).subs(point).evalf()).to_double() ==
          Approx(0).margin(1e-12));
}

TEST_CASE("equations: finite-difference check on a 3-link chain with springs", "[equations][finite-difference]")
{
    // E_i = Σ_j (∂²L/∂q̇_i∂q_j q̇_j + ∂²L/∂q̇_i∂q̇_j q̈_j) − ∂L/∂q_i, every derivative by central differences of L.
    derived d = derive(R"(parameters m1 m2 m3 l1 l2 l3 g k
coordinates a b c
point P1 mass m1 at (l1*sin(a), -l1*cos(a))
point P2 mass m2 at (l1*sin(a) + l2*sin(b), -l1*cos(a) - l2*cos(b))
point P3 mass m3 at (l1*sin(a) + l2*sin(b) + l3*sin(c), -l1*cos(a) - l2*cos(b) - l3*cos(c))
gravity g along (0, -1)
spring k between P3 and (1, -2) rest 1/2
)");
    const model& s = d.scene;
    std::mt19937 random(20261121);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    GiNaC::exmap parameters;
    for (const parameter& p : s.parameters)
        parameters[p.symbol] = GiNaC::numeric(1.5 + uniform(random));
    GiNaC::ex lagrangian = d.lagrangian.lagrangian.subs(parameters);
    std::size_t n = s.coordinates.size();
    for (int trial = 0; trial < 3; ++trial) {
        std::vector<double> q(n), v(n), acc(n);
        for (std::size_t i = 0; i < n; ++i) {
            q[i] = uniform(random);
            v[i] = uniform(random);
            acc[i] = uniform(random);
        }
        auto L = [&](const std::vector<double>& qq, const std::vector<double>& vv) {
            GiNaC::exmap at;
            for (std::size_t i = 0; i < n; ++i) {
                at[s.coordinates[i].position] = qq[i];
                at[s.coordinates[i].velocity] = vv[i];
            }
            return GiNaC::ex_to<GiNaC::numeric>(lagrangian.subs(at).evalf()).to_double();
        };
        const double h = 1e-4;
        for (std::size_t i = 0; i < n; ++i) {
            auto dL_dv = [&](std::vector<double> qq, std::vector<double> vv) {
                std::vector<double> up = vv, down = vv;
                up[i] += h;
                down[i] -= h;
                return (L(qq, up) - L(qq, down)) / (2 * h);
            };
            double total = 0;
            for (std::size_t j = 0; j < n; ++j) {
                std::vector<double> qp = q, qm = q, vp = v, vm = v;
                qp[j] += h;
                qm[j] -= h;
                vp[j] += h;
                vm[j] -= h;
                total += (dL_dv(qp, v) - dL_dv(qm, v)) / (2 * h) * v[j];
                total += (dL_dv(q, vp) - dL_dv(q, vm)) / (2 * h) * acc[j];
            }
            std::vector<double> qp = q, qm = q;
            qp[i] += h;
            qm[i] -= h;
            total -= (L(qp, v) - L(qm, v)) / (2 * h);

            GiNaC::exmap at = parameters;
            for (std::size_t j = 0; j < n; ++j) {
                at[s.coordinates[j].position] = q[j];
                at[s.coordinates[j].velocity] = v[j];
                at[s.coordinates[j].acceleration] = acc[j];
            }
            double symbolic = GiNaC::ex_to<GiNaC::numeric>(d.equations[i].subs(at).evalf()).to_double();
            CHECK(symbolic == Approx(total).epsilon(1e-5).margin(1e-6));
        }
    }
}

TEST_CASE("equations: an equation too large to read is not printed, M and f still are", "[equations]")
{
    // The 34-link chain's largest equation has 1190 terms expanded, over printed_equation_terms;
    // the 30-link chain's (930) prints.
    model scene = load(lagrange_test::chain_scene(34));
    const simplifier simplify = make_simplifier(scene);
    const lagrangian_result lagrangian = derive_lagrangian(scene, simplify);
    const equations_of_motion eom = derive_equations_of_motion(scene, lagrangian, simplify, true);
    CHECK_FALSE(eom.residuals);
    CHECK(eom.too_large_to_print.find("terms expanded (more than 1000)") != std::string::npos);
    CHECK(eom.mass.rows() == 34);
    CHECK(eom.forcing.size() == 34);
    CHECK_THROWS_AS(derive_equations(scene, lagrangian, simplify), equations_too_large);
    // Not asked to print: nothing to refuse.
    CHECK(derive_equations_of_motion(scene, lagrangian, simplify, false).too_large_to_print.empty());
}
