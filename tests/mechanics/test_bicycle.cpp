// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_bicycle.cpp
 *  The whole Whipple bicycle (examples/bicycle.lag: four bodies, two wheels that `rolls`)
 *  against the benchmark of Meijaard, Papadopoulos, Ruina and Schwab, Proc. R. Soc. A 463
 *  (2007) 1955–1982: its lean/steer eigenvalues at v = 0, 1, …, 10 m/s against Table 2, the
 *  weave and capsize speeds of §5, and the lean/steer rows of A against SymPy's
 *  test_kane3.py::test_bicycle; and a disc written with `rolls` against the same disc
 *  written with its rolling constraints by hand (tests/scenes/rolling_disc.lag). */
#include "engine/analysis.h"
#include "helpers/bicycle_benchmark.h"
#include "helpers/cli_runner.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <complex>
#include <string>
#include <vector>

using namespace lagrange;
using lagrange_test::check_table_2;

namespace {

using complex = std::complex<double>;

/// The example, analysed once for every case (a few seconds).
struct bicycle_run {
    model scene;
    analysis result;
};

const bicycle_run& bicycle()
{
    static const bicycle_run run = [] {
        bicycle_run r{load_model(source_text("bicycle.lag", lagrange_test::read_file(std::string(LAGRANGE_SOURCE_DIR) +
                                                                                   "/examples/bicycle.lag"))),
                      {}};
        r.result = analyze(r.scene, {product::state_space, product::critical});
        return r;
    }();
    return run;
}

double number(const GiNaC::ex& e)
{
    const GiNaC::ex v = e.evalf();
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(v));
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

} // namespace

TEST_CASE("bicycle: the whole bicycle's lean and steer eigenvalues match Meijaard's Table 2", "[bicycle]")
{
    const analysis& result = bicycle().result;
    REQUIRE(result.critical);
    check_table_2(*result.critical);
}

TEST_CASE("bicycle: the whole bicycle's weave and capsize speeds to 1e-10", "[bicycle]")
{
    const analysis& result = bicycle().result;
    REQUIRE(result.critical);
    const std::vector<critical_crossing>& crossings = result.critical->crossings;
    REQUIRE(crossings.size() == 2);
    // Meijaard et al. (2007), §5, to the digits of the reduced model's benchmark matrices
    CHECK(std::abs(crossings[0].value - 4.292382536341129) <= 1e-10);
    CHECK(std::abs(crossings[1].value - 6.024262015388449) <= 1e-10);
    CHECK(std::abs(crossings[0].eigenvalue.imag() - 3.43503384866144) <= 1e-9);
    CHECK(crossings[0].unstable_before == 2);
    CHECK(crossings[0].unstable_after == 0);
    CHECK(crossings[1].unstable_before == 0);
    CHECK(crossings[1].unstable_after == 1);
}

TEST_CASE("bicycle: A's lean and steer rows are SymPy's test_bicycle matrix", "[bicycle]")
{
    const bicycle_run& run = bicycle();
    REQUIRE(run.result.operating);
    const operating_linearization& op = *run.result.operating;
    CHECK(op.point_kind == operating_linearization::kind::steady);
    CHECK(op.moving_cyclic);
    // state (x, y, ψ, φ, δ, θR, θF, φ̇, δ̇, θ̇R): φ, δ, φ̇, δ̇ are 3, 4, 7, 8
    REQUIRE(op.state.size() == 10);
    const std::vector<unsigned> lean_steer{3, 4, 7, 8};
    const GiNaC::ex v = lagrange_test::symbol_of(run.scene, "v");
    const GiNaC::ex lambda = lagrange_test::symbol_of(run.scene, "lambda");
    for (int speed = 0; speed <= 5; ++speed) {
        INFO("v = " << speed);
        const double s = speed;
        // SymPy's `Res` (its eps = 1e-12 absolute)
        const double reference[2][4] = {
            {9.48977444677355, -0.891197738059089 * s * s - 0.571523173729245, -0.105522449805691 * s,
             -0.330515398992311 * s},
            {11.7194768719633, -1.97171508499972 * s * s + 30.9087533932407, 3.67680523332152 * s,
             -3.08486552743311 * s}};
        for (unsigned row = 0; row < 2; ++row)
            for (unsigned column = 0; column < 4; ++column) {
                const double entry =
                    number(op.a(lean_steer[2 + row], lean_steer[column]).subs(GiNaC::lst{v == speed, lambda == GiNaC::Pi / 10}));
                INFO("row " << row << ", column " << column);
                CHECK(std::abs(entry - reference[row][column]) <= 1e-12 * (1 + std::abs(reference[row][column])));
            }
    }
}

TEST_CASE("bicycle: a disc that `rolls` is the disc whose rolling is written by hand", "[bicycle]")
{
    const std::string by_hand =
        lagrange_test::read_file(std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/rolling_disc.lag");
    std::string rolling = by_hand;
    const std::string constraints = "constraint roll_x: x' = r*q3'*cos(q1)\nconstraint roll_y: y' = r*q3'*sin(q1)\n";
    REQUIRE(rolling.find(constraints) != std::string::npos);
    rolling.replace(rolling.find(constraints), constraints.size(), "rolls D on ground\n");
    const model hand = lagrange_test::load(by_hand), rolled = lagrange_test::load(rolling);
    // the centre is written from the contact point, so only the two no-slip constraints
    REQUIRE(rolled.constraints.size() == 2);
    CHECK(rolled.constraints[0].name == "D_roll_x");
    CHECK(rolled.constraints[1].name == "D_roll_y");
    CHECK(rolled.constraints[0].constraint_kind == constraint::kind::pfaffian);
    const analysis a = analyze(hand, {product::state_space}), b = analyze(rolled, {product::state_space});
    REQUIRE(a.operating);
    REQUIRE(b.operating);
    // det(sI − A) = s⁶ (s² + 12w²/5 − 4g/(5r)) both ways, up to a constant factor
    // the two scenes have their own symbols: b's renamed to a's
    GiNaC::exmap rename{{b.operating->s, a.operating->s}};
    for (std::size_t k = 0; k < hand.parameters.size(); ++k)
        rename[rolled.parameters[k].symbol] = hand.parameters[k].symbol;
    const GiNaC::ex ratio = (a.operating->characteristic / b.operating->characteristic.subs(rename)).normal();
    INFO(a.operating->characteristic << " and " << b.operating->characteristic);
    CHECK(GiNaC::is_a<GiNaC::numeric>(ratio));
    REQUIRE(a.state_space_values.size() == 1);
    REQUIRE(b.state_space_values.size() == 1);
    for (const complex& s : a.state_space_values[0].eigenvalues) {
        double nearest = 1e300;
        for (const complex& other : b.state_space_values[0].eigenvalues)
            nearest = std::min(nearest, std::abs(other - s));
        CHECK(nearest <= 1e-12 * (1 + std::abs(s)));
    }
}

TEST_CASE("bicycle: its printed equations are refused early, naming the yaw equation", "[bicycle]")
{
    // The whole bicycle's yaw equation has 2143 terms expanded: pages, refused before compacting
    // (which alone ran past the 30 s budget), with the products to ask for instead.
    const model& scene = bicycle().scene;
    const auto start = std::chrono::steady_clock::now();
    CHECK_THROWS_AS(analyze(scene, {product::equations}), computation_error);
    CHECK_THROWS_WITH(analyze(scene, {product::equations}),
                      Catch::Matchers::Contains("the equation of `psi` has 2143 terms expanded") &&
                          Catch::Matchers::Contains("`state_space` or `critical`"));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 2 * 10 * lagrange_test::time_scale());
    // `export` prints no equations: it gets M and f all the same.
    const analysis exported = analyze_for_export(scene);
    REQUIRE(exported.equations);
    CHECK_FALSE(exported.equations->residuals);
    CHECK(exported.equations->mass.rows() == 8);
    CHECK(exported.equations->forcing.size() == 8);
    // Small scenes print as before: the 30-link chain's largest equation has 930 terms.
    CHECK(printed_equation_terms >= 930);
}
