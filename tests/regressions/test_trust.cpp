// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_trust.cpp
 *  Issue 32: answers that were wrong with exit 0. Each test failed on the code before
 *  the fix: sweeps that dropped the gyroscopic matrix (the restricted three-body problem
 *  at L4, Foucault's pendulum), parameter values that contradict the positivity the
 *  derivation assumed, unstable modes printed as a negative frequency. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace lagrange_test;

namespace {

const std::string source = std::string(LAGRANGE_SOURCE_DIR) + "/";
const std::string scenes = source + "tests/scenes/";
const std::string examples = source + "examples/";

/// The sweep's rows as JSON arrays (exit 0 checked).
nlohmann::json sweep_rows(const std::string& args)
{
    cli_result r = run_cli(args + " --format json");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out).at("sweep").at("points");
}

/// The first `numeric` entry (exit 0 checked).
nlohmann::json numeric_entry(const std::string& args)
{
    cli_result r = run_cli(args + " --want numeric --format json");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out).at("numeric").at(0);
}

/// A sweep over one value of `parameter` gives the `numeric` stage's ω at that value.
void check_sweep_matches_numeric(const std::string& scene, const std::string& parameter, const std::string& value)
{
    nlohmann::json rows = sweep_rows(scene + " --sweep " + parameter + "=" + value + ".." + value + ":1");
    nlohmann::json numeric = numeric_entry(scene);
    const std::size_t n = numeric.at("omega").size();
    REQUIRE(rows.size() == 1);
    REQUIRE(rows[0].size() == 1 + 2 * n + 1); // the value, ω, errors, stability
    for (std::size_t k = 0; k < n; ++k) {
        INFO(scene << " mode " << k + 1);
        CHECK(rows[0][1 + k].get<double>() == Approx(numeric["omega"][k].get<double>()).epsilon(1e-12));
    }
}

} // namespace

TEST_CASE("trust: the sweep keeps the gyroscopic matrix at L4 of the restricted three-body problem",
          "[trust][sweep]")
{
    const std::string scene = scenes + "three_body_l4.lag";
    check_sweep_matches_numeric(scene, "mu", "0.03");
    // the roots of w^4 - w^2 + 27 mu (1 - mu)/4 = 0, stable below Routh's mass ratio 0.0385
    nlohmann::json rows = sweep_rows(scene + " --sweep mu=0.03..0.03:1");
    const double mu = 0.03, c = 27 * mu * (1 - mu) / 4;
    CHECK(rows[0][1].get<double>() == Approx(std::sqrt((1 - std::sqrt(1 - 4 * c)) / 2)).epsilon(1e-12));
    CHECK(rows[0][2].get<double>() == Approx(std::sqrt((1 + std::sqrt(1 - 4 * c)) / 2)).epsilon(1e-12));
    CHECK(rows[0][5] == "stable");
    nlohmann::json beyond = sweep_rows(scene + " --sweep mu=0.04..0.04:1");
    CHECK(beyond[0][5] == "unstable");
}

TEST_CASE("trust: the sweep over latitude splits Foucault's frequencies by the precession",
          "[trust][sweep]")
{
    const std::string scene = scenes + "foucault.lag";
    check_sweep_matches_numeric(scene, "lat", "0.8");
    nlohmann::json rows = sweep_rows(scene + " --sweep lat=0.5..1.5:3");
    REQUIRE(rows.size() == 3);
    for (const nlohmann::json& row : rows) {
        const double lat = row[0].get<double>(), split = 0.5 * std::sin(lat);
        CHECK(row[1].get<double>() == Approx(std::sqrt(9.81) - split).epsilon(1e-12));
        CHECK(row[2].get<double>() == Approx(std::sqrt(9.81) + split).epsilon(1e-12));
    }
}

TEST_CASE("trust: damped and constrained scenes sweep as the numeric stage computes them", "[trust][sweep]")
{
    check_sweep_matches_numeric(examples + "damped_double_pendulum.lag", "c", "0.5");
    // one independent coordinate: one ω column, not a second one of 0
    check_sweep_matches_numeric(scenes + "rod_pendulum.lag", "l", "2");
}

namespace {

/// The located error of a value that contradicts the positivity of parameters: exit 2,
/// `FILE:LINE:COL: error: ...` naming the assumption, the line, and the caret at `column`.
void check_refused(const cli_result& r, const std::string& file_line_column, const std::string& line,
                   std::size_t column)
{
    INFO(r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.out.empty());
    CHECK(r.err.rfind(file_line_column + ": error: parameter `", 0) == 0);
    CHECK(r.err.find("is assumed real and positive in the derivation") != std::string::npos);
    CHECK(r.err.find("\n" + line + "\n" + std::string(column - 1, ' ') + "^\n") != std::string::npos);
}

} // namespace

TEST_CASE("trust: a value that contradicts the positive parameters is a located bad input", "[trust][values]")
{
    const std::string scene = scenes + "rod_length_pendulum.lag";
    REQUIRE(run_cli("simulate " + scene).exit_code == 0);
    // --values of `simulate`, of the analysis, zero as well as negative
    check_refused(run_cli("simulate " + scene + " --values l=-2"), "--values:1:3", "l=-2", 3);
    check_refused(run_cli(scene + " --want numeric --values m=1,g=9.81,l=0"), "--values:1:14", "m=1,g=9.81,l=0", 14);
    // a scene's `values` line
    const std::string negative = temporary_file("negative_length.lag", "parameters m g l\ncoordinates th\n"
                                                                      "point P mass m at (l*sin(th), -sqrt(l^2)*cos(th))\n"
                                                                      "gravity g along (0, -1)\n"
                                                                      "values m = 1, g = 9.81, l = -2\n");
    check_refused(run_cli(negative + " --want numeric"), negative + ":5:29", "values m = 1, g = 9.81, l = -2", 29);
    // sweeps and ensembles, at the end of the range that breaks it
    check_refused(run_cli(scene + " --sweep l=-1..2:3"), "--sweep:1:3", "l=-1..2:3", 3);
    check_refused(run_cli(scene + " --sweep g=1..-9.81:3"), "--sweep:1:6", "g=1..-9.81:3", 6);
    check_refused(run_cli("ensemble " + scene + " --grid \"l=0..1:3\" --until 1"), "--grid:1:3", "l=0..1:3", 3);
    // a value that is not a real number, from a scene: refused as well (exit 2)
    CHECK(run_cli(scene + " --values \"l=sqrt(-1)\"").exit_code == 2);
}

TEST_CASE("trust: an unstable mode is printed as a growth rate in every format", "[trust][numeric]")
{
    const std::string scene = scenes + "rotating_wire.lag";
    // text: never a negative ω
    cli_result text = run_cli(scene + " --want numeric");
    REQUIRE(text.exit_code == 0);
    CHECK(text.out.find("ω = 1.438i, growth rate s = +1.438 (unstable)") != std::string::npos);
    CHECK(text.out.find("ω = -") == std::string::npos);
    // LaTeX
    cli_result latex = run_cli(scene + " --want numeric --format latex");
    REQUIRE(latex.exit_code == 0);
    CHECK(latex.out.find("\\omega_{1} &= 1.438\\,i &") != std::string::npos);
    CHECK(latex.out.find("Mode 1 is unstable: it grows as $e^{\\gamma t}$ with growth rate $\\gamma = 1.438$.") !=
          std::string::npos);
    CHECK(latex.out.find("-1.438") == std::string::npos);
    // JSON: the contract's `omega` floats stay (ω < 0: i|ω|); `growth_rate` and `stability` say it
    cli_result json = run_cli(scene + " --want numeric --format json");
    REQUIRE(json.exit_code == 0);
    const nlohmann::json point = nlohmann::json::parse(json.out).at("numeric").at(0);
    CHECK(point.at("omega").at(0).get<double>() == Approx(-1.438));
    CHECK(point.at("growth_rate").at(0).get<double>() == Approx(1.438));
    CHECK(point.at("stability") == "unstable");
    // a stable scene's entries keep their keys
    const nlohmann::json stable =
        nlohmann::json::parse(run_cli(examples + "double_pendulum.lag --want numeric --format json").out);
    CHECK_FALSE(stable.at("numeric").at(0).contains("growth_rate"));
    // the report
    const std::string tex = temporary_file("rotating_wire.tex", "");
    REQUIRE(run_cli("report " + scene + " -o " + tex).exit_code == 0);
    const std::string report = read_file(tex);
    CHECK(report.find("1 & $1.438\\,i$ &") != std::string::npos);
    CHECK(report.find("Mode 1 is unstable: it grows as $e^{\\gamma t}$ with growth rate $\\gamma = 1.438$") !=
          std::string::npos);
    CHECK(report.find("-1.438") == std::string::npos);
    // the simulation does not call the growth rate a linearized frequency
    cli_result simulation = run_cli("simulate " + scene);
    REQUIRE(simulation.exit_code == 0);
    CHECK(simulation.out.find("linearized frequencies:") == std::string::npos);
    CHECK(simulation.out.find("linearized growth rates (unstable, q ∝ e^{st}): s = +1.438") != std::string::npos);
    const nlohmann::json run =
        nlohmann::json::parse(run_cli("simulate " + scene + " --format json").out).at("simulation");
    CHECK(run.at("frequencies").empty());
    CHECK(run.at("growth_rates").at(0).get<double>() == Approx(1.438));
}

TEST_CASE("trust: a gyroscopic mode that grows while it oscillates says so", "[trust][numeric]")
{
    // L4 beyond Routh's ratio: a Krein collision, s = γ ± iω
    cli_result r = run_cli(scenes + "three_body_l4.lag --want numeric --values mu=0.04");
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("    unstable\n") != std::string::npos);
    CHECK(r.out.find(", growth rate Re s = +0.0675") != std::string::npos);
}

TEST_CASE("trust: the contract's items gyroscopic and verification are products", "[trust][cli]")
{
    // G ≠ 0: the Penning trap's magnetic field
    cli_result penning = run_cli(examples + "penning_trap.lag --want gyroscopic --format json");
    INFO(penning.err);
    REQUIRE(penning.exit_code == 0);
    const nlohmann::json g = nlohmann::json::parse(penning.out).at("gyroscopic");
    CHECK(g.at(0).at(1) == "B*q0");
    CHECK(g.at(1).at(0) == "-B*q0");
    // asked for where G = 0: the zero matrix, not a refusal
    cli_result pendulum = run_cli(examples + "double_pendulum.lag --want gyroscopic");
    REQUIRE(pendulum.exit_code == 0);
    CHECK(pendulum.out.find("  G = [0, 0]\n") != std::string::npos);
    // verification with other items: their checks, in every format
    cli_result text = run_cli(examples + "penning_trap.lag --want linearization,verification");
    REQUIRE(text.exit_code == 0);
    CHECK(text.out.find("\nVerification (each result checked numerically by an independent route)\n"
                        "  equilibrium: ") != std::string::npos);
    cli_result latex = run_cli(examples + "penning_trap.lag --want linearization,verification --format latex");
    REQUIRE(latex.exit_code == 0);
    CHECK(latex.out.find("\\subsection*{Verification}") != std::string::npos);
    // alone: the default run's products, checked
    cli_result alone = run_cli(examples + "linear_molecule.lag --want verification --format json");
    REQUIRE(alone.exit_code == 0);
    const nlohmann::json doc = nlohmann::json::parse(alone.out);
    CHECK(doc.contains("frequencies"));
    CHECK(doc.at("verification").contains("frequencies"));
}

TEST_CASE("trust: numeric modes of a damped constrained scene are refused and do not crash", "[trust][numeric]")
{
    // The damping matrix was evaluated at the independent coordinates' equilibrium, one value
    // short: a segmentation fault (exit 139) before.
    std::string scene = temporary_file("damped_rod.lag", "parameters m g l c\ncoordinates x y\n"
                                                         "point P mass m at (x, y)\ngravity g along (0, -1)\n"
                                                         "constraint rod: x^2 + y^2 = l^2\n"
                                                         "equilibrium x = 0, y = -l\n"
                                                         "values m = 1, g = 9.81, l = 2, c = 0.1\n"
                                                         "dissipation F = 1/2*c*(x'^2 + y'^2)\n");
    for (const std::string& args : {scene + " --want numeric", scene + " --sweep l=1..2:2"}) {
        cli_result r = run_cli(args);
        INFO(args << "\n" << r.err);
        CHECK(r.exit_code == 1);
        CHECK(r.err.find("damped small oscillations with constraints") != std::string::npos);
    }
    CHECK(run_cli(scene).exit_code == 0); // a default run leaves them out with a note
}

// The report's mode shapes read the modes in the scene's coordinates, but with constraints
// they are in the independent ones: the rod pendulum's report crashed (exit 139).
TEST_CASE("trust: the report of a constrained scene with values draws no out-of-range mode shape", "[trust][report]")
{
    const std::string scene = std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/rod_pendulum.lag";
    const std::string tex = temporary_file("rod_report.tex", "");
    lagrange_test::cli_result r = lagrange_test::run_cli("report " + scene + " -o " + tex, "", 60);
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(read_file(tex).find("\\subsection*{Mode shapes}") != std::string::npos);
}
