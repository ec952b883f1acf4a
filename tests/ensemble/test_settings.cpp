// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_settings.cpp
 *  An ensemble's settings: the end time from --until, the drive's period or the scene,
 *  and the requests that cannot be run (exit 2 in the CLI). */
#include "ensemble/settings.h"
#include "helpers/cli_runner.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lagrange;
using namespace lagrange_test;

TEST_CASE("ensemble settings: the end time, the tolerance and the random points", "[ensemble]")
{
    const std::string oscillator = "parameters m\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*x^2\nvalues m = 1\n";
    model with_end = load(oscillator + "initial x = 1\nsimulate until 7\n");
    ensemble_measure final_state = parse_ensemble_measure("final", with_end);
    CHECK(ensemble_settings_for(with_end, final_state, {}).until == 7);
    ensemble_request asked;
    asked.until = 2.5;
    asked.tolerance = 1e-6;
    asked.random = 10;
    asked.seed = 4;
    asked.native = false;
    ensemble_settings settings = ensemble_settings_for(with_end, final_state, asked);
    CHECK(settings.until == 2.5);
    CHECK(settings.tolerance == 1e-6);
    CHECK(settings.random == 10);
    CHECK(settings.seed == 4);
    CHECK_FALSE(settings.native);
    CHECK(ensemble_products(final_state) == std::set<product>{product::equations});

    model without_end = load(oscillator);
    CHECK_THROWS_AS(ensemble_settings_for(without_end, final_state, {}), ensemble_request_error);
    ensemble_request negative;
    negative.until = -1;
    CHECK_THROWS_AS(ensemble_settings_for(with_end, final_state, negative), ensemble_request_error);
    negative.until = NAN;
    CHECK_THROWS_AS(ensemble_settings_for(with_end, final_state, negative), ensemble_request_error);
    ensemble_request seed_alone;
    seed_alone.seed = 3;
    CHECK_THROWS_AS(ensemble_settings_for(with_end, final_state, seed_alone), ensemble_request_error);

    // The span is read as `simulate` reads it: the scene's tolerance when none is asked for.
    model with_tolerance = load(oscillator + "initial x = 1\nsimulate until 7 tolerance 1e-6\n");
    CHECK(ensemble_settings_for(with_tolerance, final_state, {}).tolerance == 1e-6);
    CHECK(ensemble_settings_for(with_end, final_state, {}).tolerance == 1e-9);
    ensemble_request too_loose;
    too_loose.tolerance = 2;
    CHECK_THROWS_AS(ensemble_settings_for(with_end, final_state, too_loose), ensemble_request_error);

    // The CLI: a usage error, exit 2, with the reason.
    cli_result no_end = run_cli("ensemble - --grid \"x=0..1:2\"", oscillator + "initial x = 1\n");
    CHECK(no_end.exit_code == 2);
    CHECK(no_end.err.find("give the end time of every run with --until T") != std::string::npos);
}
