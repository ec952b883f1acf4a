// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_pendulum_forms.cpp
 *  SymPy's test_linearize.py pendulums, each written in both forms of our language: as a
 *  Lagrangian (`T = …`, `V = …`) and in points and forces (Kane's, Newtonian form), in the
 *  minimal angle q1 and in Cartesian coordinates (q1, q2) on the rod q1² + q2² = L², with
 *  gravity m g along q1. Every form gives SymPy's A = [[0, 1], [−g/L, 0]] in (q2, q2') hanging
 *  at rest (test_linearize_pendulum_kane_minimal, _kane_nonminimal, _lagrange_nonminimal),
 *  the minimal ones A = [[0, 1], [−g cos q1/L, 0]] at SymPy's free q1, a point that is not an
 *  equilibrium (test_linearize_pendulum_lagrange_minimal), and the Cartesian ones at
 *  (3L/5, 4L/5) the minimal pendulum moved there by hand: A₂₁ = 7g/(15L), residual −12g/25. */
#include "engine/analysis.h"
#include "helpers/expressions.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::same;
using lagrange_test::symbol_of;

namespace {

struct pendulum_form {
    const char* name;
    const char* scene; ///< without its operating point and `want`
};

const std::vector<pendulum_form>& minimal_forms()
{
    static const std::vector<pendulum_form> forms = {
        {"Lagrangian", "parameters m L g\ncoordinates q1\nT = 1/2*m*L^2*q1'^2\nV = -m*g*L*cos(q1)\n"},
        {"points and forces", "parameters m L g\ncoordinates q1\npoint P mass m at (L*cos(q1), L*sin(q1))\n"
                              "force on P (m*g, 0)\n"},
    };
    return forms;
}

const std::vector<pendulum_form>& cartesian_forms()
{
    static const std::vector<pendulum_form> forms = {
        {"Lagrangian", "parameters m L g\ncoordinates q1 q2\nT = 1/2*m*(q1'^2 + q2'^2)\nV = -m*g*q1\n"
                       "constraint rod: q1^2 + q2^2 = L^2\n"},
        {"points and forces", "parameters m L g\ncoordinates q1 q2\npoint P mass m at (q1, q2)\n"
                              "force on P (m*g, 0)\nconstraint rod: q1^2 + q2^2 = L^2\n"},
    };
    return forms;
}

void check_a(const analysis& result, const std::vector<std::vector<GiNaC::ex>>& expected)
{
    REQUIRE(result.state_space);
    lagrange_test::check_matrix(result.state_space->a, expected);
    CHECK(result.state_space->b.cols() == 0);
}

} // namespace

TEST_CASE("pendulum forms: the minimal pendulum at rest and at SymPy's free q1", "[operating_point]")
{
    for (const pendulum_form& form : minimal_forms()) {
        INFO(form.name);
        model rest = load(std::string(form.scene) + "linearize about q1 = 0, q1' = 0\nwant state_space\n");
        const GiNaC::ex g = symbol_of(rest, "g"), L = symbol_of(rest, "L");
        analysis at_rest = analyze(rest, {product::state_space});
        check_a(at_rest, {{0, 1}, {-g / L, 0}});
        CHECK(at_rest.operating->point_kind == operating_linearization::kind::equilibrium);

        model free = load(std::string(form.scene) + "linearize about q1' = 0\nwant state_space\n");
        const GiNaC::ex q1 = symbol_of(free, "q1");
        analysis anywhere = analyze(free, {product::state_space});
        check_a(anywhere, {{0, 1}, {-symbol_of(free, "g") * cos(q1) / symbol_of(free, "L"), 0}});
        REQUIRE(anywhere.operating->residual.size() == 2);
        CHECK(same(anywhere.operating->residual[1], -symbol_of(free, "g") * sin(q1) / symbol_of(free, "L")));
        CHECK(anywhere.operating->point_kind == operating_linearization::kind::moving);
    }
}

TEST_CASE("pendulum forms: the Cartesian pendulum at rest and away from it", "[operating_point]")
{
    for (const pendulum_form& form : cartesian_forms()) {
        INFO(form.name);
        model rest = load(std::string(form.scene) + "linearize about q1 = L, q2 = 0, q1' = 0, q2' = 0\n"
                                                     "independent q2, q2'\nwant state_space\n");
        const GiNaC::ex g = symbol_of(rest, "g"), L = symbol_of(rest, "L"), m = symbol_of(rest, "m");
        analysis at_rest = analyze(rest, {product::state_space});
        check_a(at_rest, {{0, 1}, {-g / L, 0}});
        CHECK(at_rest.operating->coordinates == std::vector<std::size_t>{1});
        CHECK(at_rest.operating->speeds == std::vector<std::size_t>{1});
        CHECK(at_rest.operating->point_kind == operating_linearization::kind::equilibrium);
        // The rod's tension m g pulls along −q1: λ ∂f/∂q1 = λ 2L = −m g.
        REQUIRE(at_rest.operating->multipliers.size() == 1);
        CHECK(same(at_rest.operating->multipliers[0], -m * g / (2 * L)));

        // Chosen by the engine, the same: ∂f/∂q1 = 2L is the only pivot at rest.
        model chosen = load(std::string(form.scene) + "linearize about q1 = L, q2 = 0\nwant state_space\n");
        const GiNaC::ex gc = symbol_of(chosen, "g"), Lc = symbol_of(chosen, "L");
        check_a(analyze(chosen, {product::state_space}), {{0, 1}, {-gc / Lc, 0}});

        model away = load(std::string(form.scene) + "linearize about q1 = 3*L/5, q2 = 4*L/5\nindependent q2\n"
                                                     "want state_space\n");
        analysis moved = analyze(away, {product::state_space});
        const GiNaC::ex ga = symbol_of(away, "g"), La = symbol_of(away, "L");
        check_a(moved, {{0, 1}, {GiNaC::numeric(7, 15) * ga / La, 0}});
        CHECK(same(moved.operating->residual[1], GiNaC::numeric(-12, 25) * ga));
        CHECK(moved.operating->point_kind == operating_linearization::kind::moving);
    }
}
