// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_bodies.cpp
 *  The rigid-body products through the command line: JSON keys of the spec, exit
 *  codes, the stages that run. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using namespace lagrange_test;

namespace {

const std::string examples = std::string(LAGRANGE_SOURCE_DIR) + "/examples/";

} // namespace

TEST_CASE("bodies output: the spec's inertia and euler keys", "[bodies][cli]")
{
    cli_result r = run_cli(examples + "free_asymmetric_top.lag --format json");
    REQUIRE(r.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(r.out);
    CHECK(doc["stages"] == nlohmann::json::array({"inertia", "euler", "verification"}));
    const nlohmann::json& body = doc["inertia"]["X"];
    CHECK(body["tensor"].size() == 3);
    CHECK(body["tensor"][0][0] == "1/12*M*b^2+1/12*M*c^2");
    CHECK(body["principal"].size() == 3);
    CHECK(body["mass"] == "M");
    CHECK(body["integrals"].size() == 10); // measure, three first moments, six components
    const nlohmann::json& euler = doc["euler"]["X"];
    REQUIRE(euler["equations"].size() == 3);
    CHECK(euler["equations"][0].get<std::string>().find("w1_dot") != std::string::npos);
    CHECK(euler["solution"]["kind"] == "elliptic");
    CHECK(euler["solution"]["period"].get<double>() > 0);
    CHECK(euler["poinsot"]["polhode"].size() == 64);
    CHECK(euler["stability"] == nlohmann::json::array({"stable", "unstable", "stable"}));
}

TEST_CASE("bodies output: the symmetric solution and the top in JSON", "[bodies][cli]")
{
    nlohmann::json disk = nlohmann::json::parse(run_cli(examples + "disk.lag --format json").out);
    CHECK(disk["euler"]["D"]["solution"]["kind"] == "symmetric");
    CHECK(disk["euler"]["D"]["solution"]["axis"] == 3);
    nlohmann::json top = nlohmann::json::parse(run_cli(examples + "heavy_top.lag --format json").out);
    CHECK(top["equations"].size() == 3);
    CHECK(top["top"]["top"]["sleeping_condition"].get<std::string>().find("> 0") != std::string::npos);
}

TEST_CASE("bodies output: what cannot be done exits with 1, bad input with 2", "[bodies][cli]")
{
    cli_result odd = run_cli("-", "parameters R h\nbody B region cylinder(R, h) density r\n");
    CHECK(odd.exit_code == 1);
    CHECK(odd.err.find("cannot be integrated exactly") != std::string::npos);
    cli_result no_coordinates = run_cli("- --want equations", "parameters M R\nbody B disk(R) mass M\n");
    CHECK(no_coordinates.exit_code == 1);
    cli_result shape = run_cli("-", "parameters M R\nbody B cube(R) mass M\n");
    CHECK(shape.exit_code == 2);
    CHECK(shape.err.rfind("<stdin>:2:8: error: unknown shape `cube`", 0) == 0);
}
