// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_critical.cpp
 *  The `critical` product on the command line: the reduced bicycle's weave and capsize
 *  speeds in JSON (Meijaard et al. 2007: 4.292382536341 and 6.024262015388 m/s) and text,
 *  "none in the range" with exit 0, a bad range with a caret (exit 2), the modes of a
 *  circulatory stiffness refused with exit 1, and the root locus in the report. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace lagrange_test;

namespace {

const std::string bicycle = std::string(LAGRANGE_SOURCE_DIR) + "/examples/bicycle_reduced.lag";

std::string with_range(const std::string& range)
{
    std::string text = read_file(bicycle);
    const std::string line = "critical v from 0 to 10";
    text.replace(text.find(line), line.size(), range);
    return text;
}

} // namespace

TEST_CASE("cli: critical gives the bicycle's weave and capsize speeds", "[cli][critical]")
{
    const cli_result json = run_cli("--want critical --format json " + bicycle, "", 60);
    REQUIRE(json.exit_code == 0);
    const nlohmann::json doc = nlohmann::json::parse(json.out);
    const nlohmann::json& crossings = doc.at("critical").at("crossings");
    REQUIRE(crossings.size() == 2);
    CHECK(std::abs(crossings[0].at("value").get<double>() - 4.292382536341) <= 1e-10);
    CHECK(std::abs(crossings[1].at("value").get<double>() - 6.024262015388) <= 1e-10);
    CHECK(doc.at("critical").at("table").at("rows").size() == 11);
    const cli_result text = run_cli("--want critical " + bicycle, "", 60);
    REQUIRE(text.exit_code == 0);
    CHECK(text.out.find("Re s = 0 at v = 4.292382536341") != std::string::npos);
    CHECK(text.out.find("Re s = 0 at v = 6.024262015388") != std::string::npos);
}

TEST_CASE("cli: critical over a range without a crossing says none, exit 0", "[cli][critical]")
{
    const cli_result r = run_cli("--want critical -", with_range("critical v from 7 to 10"), 60);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("none in the range") != std::string::npos);
}

TEST_CASE("cli: a bad critical range is an error at the value, exit 2", "[cli][critical]")
{
    const cli_result r = run_cli("--want critical -", with_range("critical v from 3 to 1"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("above its start") != std::string::npos);
    CHECK(r.err.find("^") != std::string::npos);
}

TEST_CASE("cli: the modes of a circulatory stiffness are refused with a reason, exit 1", "[cli][critical]")
{
    const cli_result r = run_cli("--want modes " + bicycle, "", 60);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("not symmetric (circulatory)") != std::string::npos);
    // a default run leaves them out with a note and gives the eigenvalues
    const cli_result all = run_cli(bicycle, "", 60);
    CHECK(all.exit_code == 0);
    CHECK(all.out.find("frequencies and modes not computed") != std::string::npos);
}

TEST_CASE("cli: the report draws the root locus", "[cli][critical][gnuplot]")
{
    const std::string tex = temporary_file("bicycle.tex", "");
    const cli_result r = run_cli("report --want critical " + bicycle + " -o " + tex, "", 60);
    REQUIRE(r.exit_code == 0);
    const std::string document = read_file(tex);
    CHECK(document.find("\\section{Critical parameters}") != std::string::npos);
    CHECK(document.find("Root locus") != std::string::npos);
}
