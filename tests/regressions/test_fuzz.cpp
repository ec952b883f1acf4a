// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_fuzz.cpp
 *  Pins of what the fuzzer found (fuzz/README.md), each named after what it showed; the
 *  scenes are in tests/fuzz_regressions/. */
#include "engine/analysis.h"
#include "algebra/budget.h"
#include "algebra/factor.h"
#include "helpers/cli_runner.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <string>
#include <thread>

using namespace lagrange;
using namespace lagrange_test;

// Regressions from the fuzzer (tests/fuzz_regressions/, named after what they showed).
// Both ran past libFuzzer's wall-clock -timeout while the machine was loaded (1.0–1.5 s
// of CPU under ASan, 0.1–0.3 s in Release): the symbolic modes with surds of
// multivariate polynomials (GiNaC's normal and factor). They must complete, with
// every product, under the default budgets.
TEST_CASE("fuzz regressions: slow symbolic modes complete under the default budgets", "[fuzz]")
{
    for (const char* name : {"slow_modes_unequal_pendulum_arms.lag", "slow_modes_energies_with_surds.lag",
                             "slow_modes_factor_after_factor.lag", "slow_factor_high_degree_hoop.lag"}) {
        INFO(name);
        std::string text = read_file(std::string(LAGRANGE_SOURCE_DIR) + "/tests/fuzz_regressions/" + name);
        REQUIRE_FALSE(text.empty());
        model scene = load(text);
        analysis a = analyze(scene);
        CHECK(a.equations);
        CHECK(a.modes);
        CHECK(a.notes.empty());
    }
}

// The third ran past the 5 s timeout on 2026-11-21: its modes stage is a long series of
// GiNaC normal/factor calls (0.2 s in Release, 2 s under ASan), and the local fallbacks
// around them (`catch (const std::exception&)`: keep the unfactored form) also caught the
// budget's exception and carried on. Every normal/factor is now a checkpoint, and an
// exhausted budget passes through the fallbacks and stops the stage.
TEST_CASE("fuzz regressions: an exhausted budget stops the symbolic modes, through their fallbacks", "[fuzz][budget]")
{
    model scene = load(read_file(std::string(LAGRANGE_SOURCE_DIR) + "/tests/fuzz_regressions/slow_modes_factor_after_factor.lag"));
    analysis a = analyze(scene, {product::characteristic});
    REQUIRE(a.linearization);
    REQUIRE(a.characteristic);
    budget_limits limits;
    limits.max_seconds = 1e-3;
    budget_scope scope("modes", limits);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    CHECK_THROWS_AS(symbolic_modes(scene, *a.linearization, *a.characteristic), budget_exceeded);
    // Under the default budgets the same input completes (the test above); with 10 ms per
    // stage (the modes take about 60 ms in Release), analyze leaves the modes out and says so.
    budget_limits tight;
    tight.max_seconds = 0.01;
    analysis partial = analyze(scene, {product::equations, product::modes}, tight);
    CHECK(partial.equations);
    CHECK_FALSE(partial.modes);
    REQUIRE_FALSE(partial.notes.empty());
    CHECK_THAT(partial.notes.front(), Catch::Matchers::Contains("time budget"));
}

// The fourth: a bead on a hoop with R^22, whose equilibrium's Hessian has R^42 w^4 − g^2.
// GiNaC's factor() of it took 0.05 s or 3.8 s from run to run in Release (random
// evaluation points), one call the time budget cannot interrupt. Polynomials of degree
// above factor_max_degree in some symbol are no longer handed to factor().
TEST_CASE("fuzz regressions: factor() only where it is quick", "[fuzz][budget]")
{
    GiNaC::symbol R("R"), w("w"), g("g"), m("m");
    GiNaC::ex small = m * (GiNaC::pow(R, 8) * GiNaC::pow(w, 4) - GiNaC::pow(g, 2));
    GiNaC::ex factored = factor_if_quick(small);
    CHECK(GiNaC::is_a<GiNaC::mul>(factored));
    CHECK(factored.nops() >= 3); // m, (R^4 w^2 − g), (R^4 w^2 + g)
    CHECK((factored - small).expand().is_zero());
    GiNaC::ex large = m * (GiNaC::pow(R, 42) * GiNaC::pow(w, 4) - GiNaC::pow(g, 2));
    CHECK(too_large_to_factor(large));
    CHECK_FALSE(too_large_to_factor(small));
    CHECK((factor_if_quick(large) - large).is_zero()); // returned as it is
    CHECK(too_large_to_factor(GiNaC::pow(R + 1, factor_max_degree + 1)));
    CHECK_FALSE(too_large_to_factor(GiNaC::pow(R + 1, factor_max_degree)));
    // The scene: all three equilibria, with the Hessian left unfactored.
    model scene = load(read_file(std::string(LAGRANGE_SOURCE_DIR) + "/tests/fuzz_regressions/slow_factor_high_degree_hoop.lag"));
    analysis a = analyze(scene, {product::equilibrium});
    REQUIRE(a.equilibria);
    CHECK(a.equilibria->points.size() == 3);
}

// The sixth (2026-11-24): a rolling coin with its lean offset changed, √3 in its mass matrix,
// whose multipliers took 4.7 s in one symbolic solve of the 7 × 7 system [M −Aᵀ; A 0]. Since
// the mass matrix is reduced to the free coordinates first, they come within 1000 terms, and
// the numeric check agrees with them; a smaller size budget still stops the stage, with a note.
TEST_CASE("fuzz regressions: the multipliers stage checks its size budget", "[fuzz][budget]")
{
    budget_limits limits;
    limits.max_terms = 1000;
    model changed = load(read_file(std::string(LAGRANGE_SOURCE_DIR) +
                                   "/tests/fuzz_regressions/slow_multipliers_rolling_coin.lag"));
    analysis fits = analyze(changed, {product::multipliers}, limits);
    REQUIRE(fits.multipliers);
    CHECK(fits.notes.empty());
    REQUIRE(fits.verification);
    bool multipliers_checked = false;
    for (const verification_entry& e : fits.verification->entries) {
        INFO(e.item << ": " << e.how);
        CHECK(e.checked);
        multipliers_checked = multipliers_checked || e.item == "multipliers";
    }
    CHECK(multipliers_checked);

    limits.max_terms = 100;
    try {
        analysis a = analyze(changed, {product::multipliers}, limits);
        CHECK_FALSE(a.multipliers);
        REQUIRE_FALSE(a.notes.empty());
        CHECK_THAT(a.notes.front(), Catch::Matchers::Contains("more than 100 terms"));
    } catch (const budget_exceeded& e) { // nothing else was asked for: the run stops
        CHECK_THAT(std::string(e.what()), Catch::Matchers::Contains("more than 100 terms"));
    }
}

// The seventh (2026-11-27): a mistyped Kapitza pendulum whose monodromy integration needs
// millions of steps. The integration checks the stage's time budget, so the stage ends at
// it with budget_exceeded instead of running until the watchdog ends the process.
TEST_CASE("fuzz regressions: the floquet integration stops at the stage's time budget", "[fuzz][budget]")
{
    model scene = load(read_file(std::string(LAGRANGE_SOURCE_DIR) +
                                 "/tests/fuzz_regressions/slow_floquet_singular_drive.lag"));
    budget_limits limits;
    limits.max_seconds = 0.2;
    // Without the check the integration would stop at its own 120 s with another message.
    CHECK_THROWS_WITH(analyze(scene, {product::floquet}, limits),
                      Catch::Matchers::Contains("the `floquet` stage exceeded its time budget of 0.2 s"));
}
