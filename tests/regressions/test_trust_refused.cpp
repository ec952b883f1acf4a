// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_trust_refused.cpp
 *  Issue 32: correct results that were refused or left out. Each test failed on the code
 *  before the fix: verification false alarms (the Kapitza pendulum driven at γ = 200, a
 *  Yukawa orbit whose V has terms that cancel), the default size budget that refused the
 *  7-link chain's characteristic polynomial, computed in a quarter of a second. */
#include "helpers/chain_scene.h"
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

using namespace lagrange_test;

namespace {

const std::string scenes = std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/";

/// A default run's JSON (exit 0 checked), with the verification asked for.
nlohmann::json verified(const std::string& args)
{
    cli_result r = run_cli(args + " --format json", "", 60);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out);
}

} // namespace

TEST_CASE("trust: a fast-driven Kapitza pendulum is not refused by its own verification", "[trust][verification]")
{
    nlohmann::json j = verified(scenes + "kapitza_fast_drive.lag");
    CHECK(j.contains("floquet"));
    CHECK(j.contains("equations"));
}

TEST_CASE("trust: a Yukawa orbit's exact linearization is not refused by its verification", "[trust][verification]")
{
    nlohmann::json j = verified(scenes + "yukawa_orbit.lag");
    REQUIRE(j.contains("V"));
    CHECK(j.contains("frequencies"));
}

TEST_CASE("trust: the default budget gives the 7-link chain's characteristic polynomial", "[trust][budget]")
{
    std::string values = "values g = 9.81", equilibrium = "equilibrium ";
    for (int k = 1; k <= 7; ++k) {
        const std::string i = std::to_string(k);
        values += ", m" + i + " = " + std::to_string(1 + k) + ", l" + i + " = 1";
        equilibrium += (k > 1 ? ", q" : "q") + i + " = 0";
    }
    const std::string scene = temporary_file("chain7.lag", chain_scene(7) + equilibrium + "\n" + values + "\n");
    cli_result r = run_cli(scene + " --want characteristic --format json", "", 60);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j.at("characteristic").at("polynomial").get<std::string>().find("omega^14") != std::string::npos);
}

TEST_CASE("trust: asking for the equilibrium beside the simulation does not change it", "[trust][simulation]")
{
    const std::string top = std::string(LAGRANGE_SOURCE_DIR) + "/examples/heavy_top.lag";
    nlohmann::json alone = verified("simulate " + top);
    nlohmann::json beside = verified(top + " --want equilibrium,simulation");
    REQUIRE(beside.contains("equilibria"));
    CHECK(beside.at("simulation").at("states") == alone.at("simulation").at("states"));
    CHECK(beside.at("simulation").at("method") == alone.at("simulation").at("method"));
}
