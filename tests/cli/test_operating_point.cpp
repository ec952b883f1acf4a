// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_operating_point.cpp
 *  `linearize about` and `independent` from the command line: the residual printed beside A
 *  and B at a point that is not an equilibrium, the JSON keys, and the bad inputs (a point
 *  off a constraint, independent speeds that do not span the constraints) with a caret and
 *  exit 2. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

using namespace lagrange_test;

namespace {

std::string cartesian(const std::string& point)
{
    return "parameters m L g\ncoordinates q1 q2\npoint P mass m at (q1, q2)\nforce on P (m*g, 0)\n"
           "constraint rod: q1^2 + q2^2 = L^2\n" + point + "\n";
}

} // namespace

TEST_CASE("cli: a point that is not an equilibrium prints its residual", "[cli]")
{
    cli_result r = run_cli("- --want state_space",
                           "parameters m L g\ncoordinates q1\npoint P mass m at (L*cos(q1), L*sin(q1))\n"
                           "force on P (m*g, 0)\nlinearize about q1' = 0\n");
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("residual F(x₀, u₀) = (0, -g·sin(q1)/L)") != std::string::npos);
    CHECK(r.out.find("not an equilibrium") != std::string::npos);
    CHECK(r.out.find("A = [0, 1]\n      [-g·cos(q1)/L, 0]") != std::string::npos);
    CHECK(r.out.find("at the equilibrium") == std::string::npos);
}

TEST_CASE("cli: the operating point in JSON", "[cli]")
{
    cli_result r = run_cli("- --format json", cartesian("linearize about q1 = L, q2 = 0"));
    REQUIRE(r.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(r.out);
    const nlohmann::json& ss = doc.at("state_space");
    CHECK(ss["state"] == nlohmann::json({"q2", "q2_dot"}));
    CHECK(ss["A"] == nlohmann::json::parse(R"([["0", "1"], ["-g/L", "0"]])"));
    CHECK(ss["operating_point"]["kind"] == "equilibrium");
    CHECK(ss["operating_point"]["independent_coordinates"] == nlohmann::json({"q2"}));
    CHECK(ss["operating_point"]["chosen"] == true);
    CHECK(ss["operating_point"]["residual"] == nlohmann::json({"0", "0"}));
}

TEST_CASE("cli: an operating point off a constraint is bad input with its residual", "[cli]")
{
    cli_result r = run_cli("- --want state_space", cartesian("linearize about q1 = L, q2 = 1"));
    CHECK(r.exit_code == 2);
    CHECK(r.err == "<stdin>:6:22: error: the operating point violates constraint `rod`: -L^2+q1^2+q2^2 is 1 there, "
                   "not 0\nlinearize about q1 = L, q2 = 1\n                     ^\n");
}

TEST_CASE("cli: independent speeds that do not span the constraints are bad input", "[cli]")
{
    cli_result r = run_cli("- --want state_space", cartesian("linearize about q1 = L, q2 = 0\nindependent q1"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.rfind("<stdin>:7:1: error: the independent coordinates `q1` do not span the constraints", 0) == 0);
    CHECK(r.err.find("\nindependent q1\n^\n") != std::string::npos);
}
