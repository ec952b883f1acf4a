// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_symmetries.cpp
 *  Conserved quantities, the Hamiltonian, Routh's reduction and steady motions, each
 *  against an independent closed form. */
#include "helpers/scene_helpers.h"

#include "engine/analysis.h"
#include "mechanics/symmetries.h"
#include "program/expression_program.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace lagrange;
using namespace lagrange_test;
using GiNaC::ex;

namespace {

/// Every symbol in e, by name.
void symbols_of(const ex& e, std::map<std::string, ex>& found)
{
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (GiNaC::is_a<GiNaC::symbol>(*i))
            found.emplace(GiNaC::ex_to<GiNaC::symbol>(*i).get_name(), *i);
}

/// a and b agree at 20 seeded random points of all their symbols (matched by name, so
/// that a symbol made by the test and one made by the engine count as one), values in
/// [0.3, 1.2] (angles away from where the closed forms are singular).
bool same_values(const ex& a, const ex& b)
{
    std::map<std::string, ex> symbols;
    symbols_of(a, symbols);
    symbols_of(b, symbols);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(0.3, 1.2);
    for (int point = 0; point < 20; ++point) {
        std::map<std::string, double> values;
        for (const auto& [name, s] : symbols)
            values[name] = uniform(random);
        auto at = [&](const ex& e) {
            GiNaC::exmap map;
            std::map<std::string, ex> own;
            symbols_of(e, own);
            for (const auto& [name, s] : own)
                map[s] = values[name];
            return GiNaC::ex_to<GiNaC::numeric>(e.subs(map).evalf());
        };
        const GiNaC::numeric x = at(a), y = at(b);
        if (GiNaC::abs(x - y) > 1e-9 * (1 + GiNaC::abs(x)))
            return false;
    }
    return true;
}

analysis run(const model& scene, std::set<product> wanted) { return analyze(scene, wanted); }

ex named(const model& scene, const std::string& name) { return symbol_of(scene, name); }
ex momentum(const std::string& name) { return GiNaC::realsymbol("p_" + name); }

const std::string spherical = "parameters m l g\ncoordinates theta phi\n"
                              "point bob mass m at (l*sin(theta)*cos(phi), l*sin(theta)*sin(phi), -l*cos(theta))\n"
                              "gravity g along (0, 0, -1)\n";

} // namespace

TEST_CASE("conserved: the spherical pendulum's energy and p_phi", "[symmetries]")
{
    model scene = load(spherical);
    analysis a = run(scene, {product::conserved});
    REQUIRE(a.conserved);
    const ex m = named(scene, "m"), l = named(scene, "l"), g = named(scene, "g"), th = named(scene, "theta"),
             thd = named(scene, "theta_dot"), phd = named(scene, "phi_dot");
    REQUIRE(a.conserved->cyclic == std::vector<std::size_t>{1});
    CHECK(same_values(*a.conserved->energy,
                      m * l * l * (thd * thd + pow(sin(th), 2) * phd * phd) / 2 - m * g * l * cos(th)));
    CHECK(same_values(a.conserved->momenta[0], m * l * l * pow(sin(th), 2) * phd));
}

TEST_CASE("conserved: the driven hoop's h is not T + V, the free hoop conserves p_phi", "[symmetries]")
{
    // Driven at the fixed rate w (explicit time): L has no cyclic coordinate, h = T2 − L0.
    model driven = load("parameters m g R w\ncoordinates q\n"
                        "point bead mass m at (R*sin(q)*cos(w*t), R*sin(q)*sin(w*t), -R*cos(q))\n"
                        "gravity g along (0, 0, -1)\n");
    analysis d = run(driven, {product::conserved});
    REQUIRE(d.conserved->energy);
    CHECK(d.conserved->cyclic.empty());
    const ex m = named(driven, "m"), g = named(driven, "g"), r = named(driven, "R"), w = named(driven, "w"),
             q = named(driven, "q"), qd = named(driven, "q_dot");
    const ex h = m * r * r * qd * qd / 2 - m * r * r * w * w * pow(sin(q), 2) / 2 - m * g * r * cos(q);
    const ex t_plus_v = m * r * r * (qd * qd + w * w * pow(sin(q), 2)) / 2 - m * g * r * cos(q);
    CHECK(same_values(*d.conserved->energy, h));
    CHECK_FALSE(same_values(*d.conserved->energy, t_plus_v));

    // A hoop of moment I free to spin: φ is a coordinate, cyclic, and p_φ = (I + m R² sin²q) φ̇.
    model free = load("parameters m g R I\ncoordinates q phi\n"
                      "point bead mass m at (R*sin(q)*cos(phi), R*sin(q)*sin(phi), -R*cos(q))\n"
                      "T = 1/2*I*phi'^2\ngravity g along (0, 0, -1)\n");
    analysis f = run(free, {product::conserved});
    REQUIRE(f.conserved->cyclic == std::vector<std::size_t>{1});
    CHECK(same_values(f.conserved->momenta[0],
                      (named(free, "I") + named(free, "m") * pow(named(free, "R") * sin(named(free, "q")), 2)) *
                          named(free, "phi_dot")));
    // Its energy is T + V (no explicit time), unlike the driven hoop's.
    const ex mf = named(free, "m"), rf = named(free, "R"), qf = named(free, "q");
    CHECK(same_values(*f.conserved->energy,
                      mf * rf * rf * (pow(named(free, "q_dot"), 2) + pow(sin(qf) * named(free, "phi_dot"), 2)) / 2 +
                          named(free, "I") * pow(named(free, "phi_dot"), 2) / 2 -
                          mf * named(free, "g") * rf * cos(qf)));
}

TEST_CASE("conserved and reduced: a charge in a magnetic field, phi cyclic", "[symmetries]")
{
    model scene = load("parameters m q0 B k\ncoordinates r phi\n"
                       "L = 1/2*m*(r'^2 + r^2*phi'^2) + 1/2*q0*B*r^2*phi' - 1/2*k*r^2\n");
    analysis a = run(scene, {product::conserved, product::reduced});
    const ex m = named(scene, "m"), q0 = named(scene, "q0"), b = named(scene, "B"), k = named(scene, "k"),
             r = named(scene, "r");
    REQUIRE(a.conserved->cyclic == std::vector<std::size_t>{1});
    CHECK(same_values(a.conserved->momenta[0], m * r * r * named(scene, "phi_dot") + q0 * b * r * r / 2));
    const ex p = momentum("phi");
    CHECK(same_values(a.reduced->effective_potential,
                      pow(p - q0 * b * r * r / 2, 2) / (2 * m * r * r) + k * r * r / 2));
    CHECK(same_values(a.reduced->routhian, m * pow(named(scene, "r_dot"), 2) / 2 -
                                               pow(p - q0 * b * r * r / 2, 2) / (2 * m * r * r) - k * r * r / 2));
}

TEST_CASE("hamiltonian: singular velocity Hessian names the coordinate", "[symmetries]")
{
    model scene = load("parameters m\ncoordinates x y\nL = 1/2*m*x'^2 + y*x' - y^2\n");
    REQUIRE_THROWS_AS(run(scene, {product::hamiltonian}), computation_error);
    REQUIRE_THROWS_WITH(run(scene, {product::hamiltonian}),
                        Catch::Matchers::Contains("coordinate `y` has no kinetic energy"));
}

namespace {

/// A state's derivative from compiled expressions in (q, v or p, parameters).
struct compiled {
    expression_program program;
    std::vector<double> scratch;
    std::vector<double> operator()(const std::vector<double>& in)
    {
        std::vector<double> out(program.output_count());
        program.run(in.data(), scratch, out.data());
        return out;
    }
};

/// One classical RK4 step of y' = f(y) where f reads y followed by `fixed`.
template <class F> std::vector<double> rk4(F&& f, const std::vector<double>& y, double h)
{
    auto add = [](std::vector<double> a, const std::vector<double>& b, double s) {
        for (std::size_t i = 0; i < a.size(); ++i)
            a[i] += s * b[i];
        return a;
    };
    std::vector<double> k1 = f(y), k2 = f(add(y, k1, h / 2)), k3 = f(add(y, k2, h / 2)), k4 = f(add(y, k3, h));
    std::vector<double> next = y;
    for (std::size_t i = 0; i < y.size(); ++i)
        next[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return next;
}

} // namespace

TEST_CASE("hamiltonian: the homework double pendulum, H = h and the same trajectory", "[symmetries]")
{
    model scene = load("parameters M m l g\ncoordinates theta phi\n"
                       "point upper mass M at (l*sin(theta), -l*cos(theta))\n"
                       "point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))\n"
                       "gravity g along (0, -1)\n");
    analysis a = run(scene, {product::hamiltonian, product::equations});
    REQUIRE(a.hamiltonian);
    const ex big = named(scene, "M"), m = named(scene, "m"), l = named(scene, "l"), g = named(scene, "g"),
             th = named(scene, "theta"), ph = named(scene, "phi"), thd = named(scene, "theta_dot"),
             phd = named(scene, "phi_dot");
    // Written independently: T = ½(M+m)l²θ̇² + m l² cos(θ−φ) θ̇φ̇ + ½ m l² φ̇², V = −(M+m) g l cosθ − m g l cosφ.
    const ex t = (big + m) * l * l * thd * thd / 2 + m * l * l * cos(th - ph) * thd * phd + m * l * l * phd * phd / 2;
    const ex v = -(big + m) * g * l * cos(th) - m * g * l * cos(ph);
    const ex p_theta = t.diff(GiNaC::ex_to<GiNaC::symbol>(thd)), p_phi = t.diff(GiNaC::ex_to<GiNaC::symbol>(phd));
    const hamiltonian_result& h = *a.hamiltonian;
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(-3, 3), positive(0.5, 2);
    for (int point = 0; point < 100; ++point) {
        GiNaC::exmap values{{big, positive(random)}, {m, positive(random)}, {l, positive(random)},
                            {g, positive(random)}, {th, uniform(random)}, {ph, uniform(random)},
                            {thd, uniform(random)}, {phd, uniform(random)}};
        GiNaC::exmap momenta = values;
        momenta[h.momenta[0]] = p_theta.subs(values);
        momenta[h.momenta[1]] = p_phi.subs(values);
        const double hamiltonian = GiNaC::ex_to<GiNaC::numeric>(h.hamiltonian.subs(momenta).evalf()).to_double();
        const double printed = GiNaC::ex_to<GiNaC::numeric>(h.hamiltonian_raw.subs(momenta).evalf()).to_double();
        const double energy = GiNaC::ex_to<GiNaC::numeric>((t + v).subs(values).evalf()).to_double();
        CHECK(hamiltonian == Approx(energy).epsilon(1e-10).margin(1e-10));
        CHECK(printed == Approx(energy).epsilon(1e-10).margin(1e-10));
    }
    // Hamilton's equations against the Lagrangian ones (M q̈ = f), both by RK4.
    const GiNaC::exmap parameters{{big, 1.0}, {m, 0.7}, {l, 1.0}, {g, 9.81}};
    const std::vector<ex> state_qp{th, ph, h.momenta[0], h.momenta[1]};
    std::vector<ex> hamilton_rhs{h.velocities[0].subs(parameters), h.velocities[1].subs(parameters),
                                 h.forces[0].subs(parameters), h.forces[1].subs(parameters)};
    compiled hamilton{expression_program(hamilton_rhs, state_qp), {}};
    const equations_of_motion& eom = *a.equations;
    std::vector<ex> lagrange_parts{eom.mass(0, 0), eom.mass(0, 1), eom.mass(1, 1), eom.forcing[0], eom.forcing[1]};
    for (ex& e : lagrange_parts)
        e = e.subs(parameters);
    compiled lagrange_side{expression_program(lagrange_parts, {th, ph, thd, phd}), {}};
    auto lagrange_rhs = [&](const std::vector<double>& y) {
        std::vector<double> parts = lagrange_side(y);
        Eigen::Matrix2d mass;
        mass << parts[0], parts[1], parts[1], parts[2];
        Eigen::Vector2d acceleration = mass.lu().solve(Eigen::Vector2d(parts[3], parts[4]));
        return std::vector<double>{y[2], y[3], acceleration[0], acceleration[1]};
    };
    std::vector<double> y_lagrange{1.0, -0.5, 0.3, 0.8};
    GiNaC::exmap start{{th, 1.0}, {ph, -0.5}, {thd, 0.3}, {phd, 0.8}};
    for (const auto& [s, x] : parameters)
        start[s] = x;
    std::vector<double> y_hamilton{1.0, -0.5, GiNaC::ex_to<GiNaC::numeric>(p_theta.subs(start).evalf()).to_double(),
                                   GiNaC::ex_to<GiNaC::numeric>(p_phi.subs(start).evalf()).to_double()};
    for (int step = 0; step < 4000; ++step) {
        y_lagrange = rk4(lagrange_rhs, y_lagrange, 5e-4);
        y_hamilton = rk4(hamilton, y_hamilton, 5e-4);
    }
    CHECK(y_hamilton[0] == Approx(y_lagrange[0]).margin(1e-8));
    CHECK(y_hamilton[1] == Approx(y_lagrange[1]).margin(1e-8));
}

TEST_CASE("reduced: the conical pendulum's family and steady motion", "[symmetries]")
{
    model scene = load("parameters m l g th0 Omega\ncoordinates theta phi\n"
                       "point bob mass m at (l*sin(theta)*cos(phi), l*sin(theta)*sin(phi), -l*cos(theta))\n"
                       "gravity g along (0, 0, -1)\nequilibrium theta = th0, phi' = Omega\n");
    analysis a = run(scene, {product::reduced, product::frequencies});
    const ex m = named(scene, "m"), l = named(scene, "l"), g = named(scene, "g"), th = named(scene, "theta"),
             th0 = named(scene, "th0"), omega = named(scene, "Omega");
    const ex p = momentum("phi");
    REQUIRE(a.reduced);
    CHECK(same_values(a.reduced->effective_potential, p * p / (2 * m * l * l * pow(sin(th), 2)) - m * g * l * cos(th)));
    // The family: φ̇² = g/(l cos θ).
    REQUIRE(a.reduced->family.size() == 1);
    CHECK(same_values(a.reduced->family[0].lhs, pow(named(scene, "phi_dot"), 2)));
    CHECK(same_values(a.reduced->family[0].rhs[0], g / (l * cos(th))));
    REQUIRE(a.steady);
    REQUIRE(a.steady->relation);
    CHECK(same_values(a.steady->relation->first, omega * omega));
    CHECK(same_values(a.steady->relation->second, g / (l * cos(th0))));
    CHECK(same_values(a.steady->momenta[0], m * l * l * pow(sin(th0), 2) * omega));
    // ω² = Ω²(1 + 3cos²θ0), in the motion's own data.
    REQUIRE(a.steady->modes.frequencies.size() == 1);
    CHECK(same_values(a.steady->modes.frequencies[0], omega * omega * (1 + 3 * pow(cos(th0), 2))));
}

TEST_CASE("reduced: Kepler's circular orbit and radial frequency", "[symmetries]")
{
    model scene = load("parameters m k r0 Omega\ncoordinates r phi\n"
                       "L = 1/2*m*(r'^2 + r^2*phi'^2) + k/r\nequilibrium r = r0, phi' = Omega\n");
    analysis a = run(scene, {product::reduced, product::frequencies});
    const ex m = named(scene, "m"), k = named(scene, "k"), r0 = named(scene, "r0");
    const ex p = momentum("phi");
    // Circular radius r0 = p²/(m k).
    REQUIRE(a.reduced->circular_orbits.size() == 1);
    CHECK(same_values(a.reduced->circular_orbits[0].values[0], p * p / (m * k)));
    // Ω² = k/(m r0³) and the radial frequency equals the orbital one.
    REQUIRE(a.steady->relation);
    CHECK(same_values(a.steady->relation->second, k / (m * pow(r0, 3))));
    REQUIRE(a.steady->modes.frequencies.size() == 1);
    CHECK(same_values(a.steady->modes.frequencies[0], pow(named(scene, "Omega"), 2)));
}

TEST_CASE("reduced: power-law potential, radial to orbital ratio sqrt(n + 2)", "[symmetries]")
{
    for (int n : {-1, 1, 2, 3, 4}) {
        INFO("n = " << n);
        model scene = load("parameters m k r0 Omega\ncoordinates r phi\nL = 1/2*m*(r'^2 + r^2*phi'^2) - " +
                           std::string(n < 0 ? "-" : "") + "k*r^(" + std::to_string(n) + ")/" +
                           std::to_string(std::abs(n)) + "\nequilibrium r = r0, phi' = Omega\n");
        analysis a = run(scene, {product::frequencies});
        REQUIRE(a.steady->relation);
        REQUIRE(a.steady->modes.frequencies.size() == 1);
        CHECK(same_values(a.steady->modes.frequencies[0], (n + 2) * pow(named(scene, "Omega"), 2)));
    }
}

TEST_CASE("steady motion: errors name the coordinate", "[symmetries]")
{
    model not_cyclic = load("parameters m l g Omega\ncoordinates theta phi\n"
                            "point bob mass m at (l*sin(theta)*cos(phi), l*sin(theta)*sin(phi), -l*cos(theta))\n"
                            "gravity g along (0, 0, -1)\nequilibrium phi = 0, theta' = Omega\n");
    REQUIRE_THROWS_AS(run(not_cyclic, {product::frequencies}), computation_error);
    REQUIRE_THROWS_WITH(run(not_cyclic, {product::frequencies}), Catch::Matchers::Contains("not cyclic"));
}

TEST_CASE("heavy top: conserved momenta, precession rates, nutation and sleeping", "[symmetries][top]")
{
    model scene = load("parameters M g l A C th0 Omega\ncoordinates phi theta psi\n"
                       "body top inertia (A, A, C) mass M at (l*sin(phi)*sin(theta), -l*cos(phi)*sin(theta), "
                       "l*cos(theta)) orientation zxz(phi, theta, psi)\ngravity g along (0, 0, -1)\n"
                       "equilibrium theta = th0, phi' = Omega\n");
    analysis a = run(scene, {product::conserved, product::equations, product::frequencies});
    const ex m = named(scene, "M"), g = named(scene, "g"), l = named(scene, "l"), big_a = named(scene, "A"),
             c = named(scene, "C"), th = named(scene, "theta"), th0 = named(scene, "th0"),
             omega = named(scene, "Omega"), phd = named(scene, "phi_dot"), psd = named(scene, "psi_dot");
    const ex i1 = big_a + m * l * l; // about the pivot
    // p_φ = I1 sin²θ φ̇ + C cos θ (φ̇ cos θ + ψ̇), p_ψ = C (φ̇ cos θ + ψ̇) (Goldstein 5.63).
    REQUIRE(a.conserved->cyclic == std::vector<std::size_t>{0, 2});
    CHECK(same_values(a.conserved->momenta[0], i1 * pow(sin(th), 2) * phd + c * cos(th) * (phd * cos(th) + psd)));
    CHECK(same_values(a.conserved->momenta[1], c * (phd * cos(th) + psd)));
    // The top stage: I1 cos θ Ω² − C ω3 Ω + M g l = 0, its roots, ω_nut² and the sleeping criterion.
    REQUIRE(a.tops);
    REQUIRE(a.tops->size() == 1);
    const top_result& top = a.tops->front();
    const ex w = top.precession, w3 = top.spin;
    const ex quadratic = top.precession_quadratic[2] * w * w + top.precession_quadratic[1] * w +
                         top.precession_quadratic[0];
    CHECK(same_values(quadratic / top.precession_quadratic[0],
                      (i1 * cos(th) * w * w - c * w3 * w + m * g * l) / (m * g * l)));
    const ex discriminant = c * c * w3 * w3 - 4 * i1 * m * g * l * cos(th);
    // At a fast spin (discriminant > 0 at the sample points): C ω3 = 6 + I1 + M g l.
    const GiNaC::exmap fast{{w3, (6 + i1 + m * g * l) / c}};
    CHECK(same_values(top.slow_precession.subs(fast),
                      ((c * w3 - sqrt(discriminant)) / (2 * i1 * cos(th))).subs(fast)));
    CHECK(same_values(top.fast_precession.subs(fast),
                      ((c * w3 + sqrt(discriminant)) / (2 * i1 * cos(th))).subs(fast)));
    CHECK(same_values(top.nutation_frequency_squared,
                      pow(c * w3 - 2 * i1 * w * cos(th), 2) / (i1 * i1) + w * w * pow(sin(th), 2)));
    CHECK(same_values(top.condition, c * c * w3 * w3 - 4 * i1 * m * g * l));
    // The steady motion of the scene: ψ̇ solved, nutation frequency as above with ω3 = Ω cos θ0 + ψ̇.
    REQUIRE(a.steady);
    REQUIRE(a.steady->modes.frequencies.size() == 1);
    const ex spin = omega * cos(th0) + a.steady->rates[1];
    CHECK(same_values(a.steady->modes.frequencies[0],
                      pow(c * spin - 2 * i1 * omega * cos(th0), 2) / (i1 * i1) + omega * omega * pow(sin(th0), 2)));
    CHECK(same_values(i1 * cos(th0) * omega * omega - c * spin * omega + m * g * l, 0));
}

TEST_CASE("verification: a wrong conserved momentum is caught", "[symmetries][verification]")
{
    model scene = load(spherical);
    analysis a = run(scene, {product::conserved});
    conserved_result wrong = *a.conserved;
    wrong.momenta[0] = 2 * wrong.momenta[0];
    verification_input input = verification_input_of(a);
    input.conserved = &wrong;
    REQUIRE_THROWS_AS(verify_results(scene, input, a.wanted), computation_error);
    REQUIRE_THROWS_WITH(verify_results(scene, input, a.wanted),
                        Catch::Matchers::Contains("verification failed: conserved"));
}

TEST_CASE("simulation: a cyclic momentum's drift is reported", "[symmetries][simulation]")
{
    model scene = load(spherical + "values m = 1, l = 1, g = 9.81\ninitial theta = 0.5, phi' = 2\n"
                                   "simulate until 2\n");
    analysis a = run(scene, {product::simulation});
    REQUIRE(a.simulation);
    bool found = false;
    for (const auto& [name, drift] : a.simulation->run.invariant_drift)
        if (name == "p_phi") {
            found = true;
            CHECK(drift < 1e-8);
        }
    CHECK(found);
}

TEST_CASE("steady motion: numeric angle and rate", "[symmetries]")
{
    const std::string pendulum =
        "parameters m l g Omega\ncoordinates theta phi\n"
        "point bob mass m at (l*sin(theta)*cos(phi), l*sin(theta)*sin(phi), -l*cos(theta))\n"
        "gravity g along (0, 0, -1)\n";
    // A decimal angle is studied exactly: Ω² = g/(l cos ½), ω² = Ω²(1 + 3cos²½).
    model decimal = load(pendulum + "equilibrium theta = 0.5, phi' = Omega\n");
    analysis a = run(decimal, {product::frequencies});
    const ex omega = named(decimal, "Omega");
    REQUIRE(a.steady->modes.frequencies.size() == 1);
    CHECK(same_values(a.steady->modes.frequencies[0], omega * omega * (1 + 3 * pow(cos(GiNaC::numeric(1, 2)), 2))));
    // θ0 = π/3 and Ω = 2: steady when g = 2l, and ω² = 4(1 + 3/4) = 7.
    model exact = load(pendulum + "equilibrium theta = 1/3*Pi, phi' = 2\n");
    analysis b = run(exact, {product::frequencies});
    REQUIRE(b.steady->relation);
    CHECK(same_values(b.steady->relation->second, 2 * named(exact, "l")));
    CHECK(same_values(b.steady->modes.frequencies[0], 7));
}
