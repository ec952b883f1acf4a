// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_operating_point.cpp
 *  Linearization about an operating point, with holonomic and Pfaffian constraints, against
 *  SymPy's tests (sympy/physics/mechanics/tests/test_linearize.py and test_kane.py): the
 *  pendulum in minimal and Cartesian coordinates (A = [[0, 1], [−g/L, 0]] in (q2, q2'), and
 *  [[0, 1], [−g cos q1/L, 0]] at SymPy's free q1, a point that is not an equilibrium), the
 *  one- and two-degree-of-freedom mass–spring–dampers of test_kane.py without an input, and
 *  the rolling disc upright at spin rate w (test_rolling_disc, test_linearize_rolling_disc_kane:
 *  lean row 4g/(5r) q2 + 6w/5 yaw rate, yaw row −2w lean rate, all eigenvalues 0 at
 *  w² = g/(3r)); the Cartesian pendulum at the point (3L/5, 4L/5) against the minimal
 *  pendulum transformed by hand (A₂₁ = −g cos 2θ/(L cos θ) = 7g/(15L), residual
 *  −g sin θ cos θ = −12g/25); and the errors at the statement. */
#include "engine/analysis.h"
#include "helpers/expressions.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

using namespace lagrange;
using lagrange_test::check_matrix;
using lagrange_test::load;
using lagrange_test::same;
using lagrange_test::symbol_of;

namespace {

std::string scene_file(const std::string& name)
{
    std::ifstream in(std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/" + name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

const char* cartesian_at(const char* point)
{
    static std::string text;
    text = std::string("parameters m L g\ncoordinates q1 q2\npoint P mass m at (q1, q2)\nforce on P (m*g, 0)\n"
                       "constraint rod: q1^2 + q2^2 = L^2\n") + point + "\nwant state_space\n";
    return text.c_str();
}

} // namespace

TEST_CASE("operating point: the Cartesian pendulum gives SymPy's A in q2", "[operating_point]")
{
    model scene = load(scene_file("pendulum_cartesian.lag"));
    analysis result = analyze(scene, {product::state_space});
    REQUIRE(result.operating);
    const GiNaC::ex g = symbol_of(scene, "g"), L = symbol_of(scene, "L");
    check_matrix(result.state_space->a, {{0, 1}, {-g / L, 0}});
    CHECK(result.state_space->b.cols() == 0);
    CHECK(result.operating->coordinates == std::vector<std::size_t>{1});
    CHECK(result.operating->speeds == std::vector<std::size_t>{1});
    CHECK(result.operating->point_kind == operating_linearization::kind::equilibrium);
    CHECK(same(result.operating->multipliers.at(0), -symbol_of(scene, "m") * g / (2 * L)));
}

TEST_CASE("operating point: the minimal pendulum at SymPy's free q1 is not an equilibrium", "[operating_point]")
{
    model scene = load("parameters m L g\ncoordinates q1\npoint P mass m at (L*cos(q1), L*sin(q1))\n"
                       "force on P (m*g, 0)\nlinearize about q1' = 0\nwant state_space\n");
    analysis result = analyze(scene, {product::state_space});
    const GiNaC::ex g = symbol_of(scene, "g"), L = symbol_of(scene, "L"), q1 = symbol_of(scene, "q1");
    check_matrix(result.state_space->a, {{0, 1}, {-g * cos(q1) / L, 0}});
    REQUIRE(result.operating->residual.size() == 2);
    CHECK(same(result.operating->residual[0], 0));
    CHECK(same(result.operating->residual[1], -g * sin(q1) / L));
    CHECK(result.operating->point_kind == operating_linearization::kind::moving);
}

TEST_CASE("operating point: the Cartesian pendulum away from rest against the minimal one", "[operating_point]")
{
    // There the best-conditioned choice solves for q2 (∂f/∂q2 = 8L/5 > ∂f/∂q1); q2 is named.
    model scene = load(cartesian_at("linearize about q1 = 3*L/5, q2 = 4*L/5\nindependent q2"));
    analysis result = analyze(scene, {product::state_space});
    const GiNaC::ex g = symbol_of(scene, "g"), L = symbol_of(scene, "L");
    REQUIRE(result.operating->coordinates == std::vector<std::size_t>{1});
    check_matrix(result.state_space->a, {{0, 1}, {GiNaC::numeric(7, 15) * g / L, 0}});
    CHECK(same(result.operating->residual[1], GiNaC::numeric(-12, 25) * g));
    CHECK(result.operating->point_kind == operating_linearization::kind::moving);
}

TEST_CASE("operating point: mass-spring-dampers give SymPy's A without an input", "[operating_point]")
{
    const char* one = "parameters m c k\ncoordinates q\nT = 1/2*m*q'^2\nV = 1/2*k*q^2\n"
                      "dissipation F = 1/2*c*q'^2\nwant state_space\n";
    for (const std::string& point : {std::string(""), std::string("linearize about q = 0\n")}) {
        model scene = load(one + point);
        analysis result = analyze(scene, {product::state_space});
        const GiNaC::ex m = symbol_of(scene, "m"), c = symbol_of(scene, "c"), k = symbol_of(scene, "k");
        check_matrix(result.state_space->a, {{0, 1}, {-k / m, -c / m}});
        CHECK(result.state_space->b.cols() == 0);
    }
    // test_two_dof: q2 is the second particle's displacement relative to the first.
    const char* two = "parameters m c1 c2 k1 k2\ncoordinates q1 q2\npoint P1 mass m at (q1, 0)\n"
                      "point P2 mass m at (q1 + q2, 0)\nV = 1/2*k1*q1^2 + 1/2*k2*q2^2\n"
                      "dissipation F = 1/2*c1*q1'^2 + 1/2*c2*q2'^2\nwant state_space\n";
    for (const std::string& point : {std::string(""), std::string("linearize about q1 = 0, q2 = 0\n")}) {
        model scene = load(two + point);
        analysis result = analyze(scene, {product::state_space});
        const GiNaC::ex m = symbol_of(scene, "m"), c1 = symbol_of(scene, "c1"), c2 = symbol_of(scene, "c2"),
                        k1 = symbol_of(scene, "k1"), k2 = symbol_of(scene, "k2");
        check_matrix(result.state_space->a, {{0, 0, 1, 0},
                                             {0, 0, 0, 1},
                                             {-k1 / m, k2 / m, -c1 / m, c2 / m},
                                             {k1 / m, -2 * k2 / m, c1 / m, -2 * c2 / m}});
    }
}

TEST_CASE("operating point: the rolling disc upright, against SymPy's test_rolling_disc", "[operating_point]")
{
    model scene = load(scene_file("rolling_disc.lag"));
    analysis result = analyze(scene, {product::state_space});
    const GiNaC::ex g = symbol_of(scene, "g"), r = symbol_of(scene, "r"), w = symbol_of(scene, "w");
    const GiNaC::matrix& a = result.state_space->a;
    REQUIRE(a.rows() == 8); // q1 q2 q3 x y and the speeds q1' q2' q3'
    // SymPy's rows: lean u1' = 4g/(5r) lean + 6w/5 yaw rate, yaw u3' = −2w lean rate.
    CHECK(same(a(6, 1), 4 * g / (5 * r)));
    CHECK(same(a(6, 5), GiNaC::numeric(6, 5) * w));
    CHECK(same(a(5, 6), -2 * w));
    CHECK(result.operating->point_kind == operating_linearization::kind::steady);
    CHECK(result.operating->moving_cyclic);
    // det(sI − A) = s⁶ (s² + 12w²/5 − 4g/(5r)): upright rolling is stable exactly for w² > g/(3r),
    // and every eigenvalue is 0 at w² = g/(3r) (SymPy's check at r = g = 1, w = 1/√3).
    GiNaC::symbol s("s");
    GiNaC::matrix pencil(8, 8);
    for (unsigned i = 0; i < 8; ++i)
        for (unsigned j = 0; j < 8; ++j)
            pencil(i, j) = (i == j ? GiNaC::ex(s) : GiNaC::ex(0)) - a(i, j);
    const GiNaC::ex determinant = pencil.determinant();
    CHECK(same(determinant, pow(s, 6) * (s * s + GiNaC::numeric(12, 5) * w * w - 4 * g / (5 * r))));
    const GiNaC::ex s_of = result.operating->s;
    CHECK(same(result.operating->characteristic,
               pow(s_of, 6) * (5 * r * s_of * s_of + 12 * r * w * w - 4 * g)));
    REQUIRE(result.state_space_values.size() == 1);
    const auto& eigenvalues = result.state_space_values[0].eigenvalues; // at m = r = g = w = 1
    REQUIRE(eigenvalues.size() == 8);
    CHECK_THAT(eigenvalues.back().imag(), Catch::WithinRel(std::sqrt(8.0 / 5.0), 1e-12));
    CHECK(result.state_space_values[0].stability == "marginal");
    // Below the critical rate, w² = 1/4 < g/(3r) = 1/3: the lean grows at s = √((4 − 3)/5).
    model slow = load(scene_file("rolling_disc.lag") + "values m = 1, r = 1, g = 1, w = 1/2\n");
    analysis slower = analyze(slow, {product::state_space});
    REQUIRE(slower.state_space_values.size() == 2);
    CHECK(slower.state_space_values[1].stability == "unstable");
    CHECK_THAT(slower.state_space_values[1].eigenvalues.back().real(), Catch::WithinRel(std::sqrt(0.2), 1e-12));
}

TEST_CASE("operating point: the independent coordinate chosen by the pivots", "[operating_point]")
{
    model scene = load(cartesian_at("linearize about q1 = 3*L/5, q2 = 4*L/5"));
    analysis result = analyze(scene, {product::state_space});
    REQUIRE(result.operating->coordinates == std::vector<std::size_t>{0}); // chosen: q2 is the pivot
    CHECK(result.operating->chosen);
    // At rest q1'' = −L sin θ θ'' = g sin²θ = g (1 − q1²/L²): ∂/∂q1 = −2g q1/L² = −6g/(5L), and
    // the residual is 16g/25.
    check_matrix(result.state_space->a, {{0, 1}, {-6 * symbol_of(scene, "g") / (5 * symbol_of(scene, "L")), 0}});
    CHECK(same(result.operating->residual[1], GiNaC::numeric(16, 25) * symbol_of(scene, "g")));
}

TEST_CASE("operating point: errors at the statement", "[operating_point]")
{
    auto error_of = [](const std::string& text) -> std::optional<scene_error> {
        model scene = load(text);
        try {
            analyze(scene, {product::state_space});
        } catch (const scene_error& e) {
            return e;
        }
        return std::nullopt;
    };
    // q2 cannot be solved from the rod at q2 = 0: q1 alone does not span the constraint.
    std::optional<scene_error> span = error_of(cartesian_at("linearize about q1 = L, q2 = 0\nindependent q1"));
    REQUIRE(span);
    CHECK(span->where().line == 7);
    CHECK(span->where().column == 1);
    CHECK_THAT(span->what(), Catch::Contains("do not span the constraints"));
    // The point is off the rod: the residual is named.
    std::optional<scene_error> off = error_of(cartesian_at("linearize about q1 = L, q2 = 1"));
    REQUIRE(off);
    CHECK(off->where().line == 6);
    CHECK(off->where().column == 22);
    CHECK_THAT(off->what(), Catch::Contains("violates constraint `rod`") && Catch::Contains("is 1 there"));
    // Too many independent coordinates.
    std::optional<scene_error> count = error_of(cartesian_at("linearize about q1 = L, q2 = 0\nindependent q1, q2"));
    REQUIRE(count);
    CHECK_THAT(count->what(), Catch::Contains("leave 1 independent coordinate"));
}

TEST_CASE("operating point: transfer functions of the driven Cartesian pendulum", "[operating_point][transfer]")
{
    // A force u along q2 on the hanging bob: in the angle θ, m L² θ'' = −m g L θ + u L, and
    // δq2 = L δθ, δq1 = 0, so H(u → q2) = L/(m L s² + m g) and H(u → q1) = 0.
    model scene = load("parameters m L g\ncoordinates q1 q2\ninput u\npoint P mass m at (q1, q2)\n"
                       "force on P (m*g, u)\nconstraint rod: q1^2 + q2^2 = L^2\nlinearize about q1 = L, q2 = 0\n"
                       "want state_space, transfer\n");
    analysis result = analyze(scene, {product::state_space, product::transfer});
    const GiNaC::ex m = symbol_of(scene, "m"), g = symbol_of(scene, "g"), L = symbol_of(scene, "L");
    REQUIRE(result.transfer);
    REQUIRE(result.transfer->entries.size() == 2);
    const GiNaC::ex s = result.transfer->s;
    CHECK(result.transfer->entries[0].coordinate == 0);
    CHECK(same(result.transfer->entries[0].function(), 0));
    CHECK(same(result.transfer->entries[1].function(), L / (m * L * s * s + m * g)));
    check_matrix(result.state_space->b, {{0}, {1 / m}});
}

TEST_CASE("operating point: a steady motion of a constrained scene is its `equilibrium` line", "[operating_point]")
{
    // The disc's upright rolling named as a steady motion: the spin angle and the contact
    // point are left free, and A is that of the `linearize about` line.
    std::string text = scene_file("rolling_disc.lag");
    const std::size_t line = text.find("linearize about");
    text = text.substr(0, line) + "equilibrium q1 = 0, q2 = 0, q3' = w\n" + text.substr(text.find('\n', line) + 1);
    model scene = load(text);
    analysis steady = analyze(scene, {product::state_space});
    analysis about = analyze(load(scene_file("rolling_disc.lag")), {product::state_space});
    const GiNaC::ex g = symbol_of(scene, "g"), r = symbol_of(scene, "r"), w = symbol_of(scene, "w");
    REQUIRE(steady.state_space->a.rows() == 8);
    CHECK(same(steady.state_space->a(6, 1), 4 * g / (5 * r)));
    CHECK(same(steady.state_space->a(6, 5), GiNaC::numeric(6, 5) * w));
    CHECK(same(steady.state_space->a(5, 6), -2 * w));
    REQUIRE(steady.state_space_values.size() == 1);
    REQUIRE(about.state_space_values.size() == 1);
    CHECK(steady.state_space_values[0].a == about.state_space_values[0].a);
    CHECK(steady.operating->point_kind == operating_linearization::kind::steady);
    CHECK(steady.state_space_values[0].stability == "marginal");
}

TEST_CASE("steady motion: the conical pendulum's stability at its values", "[operating_point][steady]")
{
    // About θ = th0, φ' = Ω the reduced system oscillates at ω² = (3 cos² th0 + 1) Ω²: stable,
    // s = ±iω at the values.
    model scene = load(scene_file("../../examples/conical_pendulum.lag"));
    analysis result = analyze(scene, {product::reduced});
    REQUIRE(result.steady);
    REQUIRE(result.steady->at_values.size() == 1);
    const auto& point = result.steady->at_values[0];
    CHECK(point.verdict == stability::stable);
    REQUIRE(point.eigenvalues.size() == 2);
    const double omega = std::sqrt(3 * std::cos(0.6) * std::cos(0.6) + 1) * 3.4477;
    CHECK_THAT(point.eigenvalues[1].imag(), Catch::WithinRel(omega, 1e-12));
    CHECK_THAT(point.eigenvalues[1].real(), Catch::WithinAbs(0, 1e-12));
}
