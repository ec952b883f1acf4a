// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_virial.cpp
 *  The virial product: ⟨T⟩ and ⟨V⟩ over a simulation, against the virial theorem
 *  (2⟨T⟩ = n⟨V⟩ over whole periods, for V homogeneous of degree n) and the closed forms of
 *  Kepler's orbit (⟨V⟩ = −k/a) and the quartic oscillator (⟨V⟩ = E/3). */
#include "engine/analysis.h"
#include "helpers/cli_runner.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <string>

using namespace lagrange;
using namespace lagrange_test;

namespace {

std::string digits(double x)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

/// Kepler's problem in the plane with m = k = 1, from periapsis r = 1 at speed 1.2: the
/// energy E = −0.28, the semi-major axis a = −k/(2E) and the period 2π a^(3/2).
const double kepler_a = 1 / 0.56;
std::string kepler(int periods)
{
    const double period = 2 * M_PI * std::pow(kepler_a, 1.5);
    return "parameters m k\ncoordinates r phi\nT = 1/2*m*(r'^2 + r^2*phi'^2)\nV = -k/r\nvalues m = 1, k = 1\n"
           "initial r = 1, phi = 0, r' = 0, phi' = 1.2\nsimulate until " +
           digits(periods * period) + " step 0.001 tolerance 1e-12\n";
}

} // namespace

TEST_CASE("virial: Kepler's orbit over three periods, 2⟨T⟩ = −⟨V⟩ = k/a", "[virial][simulation]")
{
    analysis a = analyze(load(kepler(3)), {product::virial});
    REQUIRE(a.virial);
    const virial_result& v = *a.virial;
    INFO("⟨T⟩ = " << v.kinetic << ", ⟨V⟩ = " << v.potential);
    CHECK(v.from == 0);
    CHECK(v.to == Approx(3 * 2 * M_PI * std::pow(kepler_a, 1.5)).epsilon(1e-15));
    CHECK(std::abs(v.potential + 1 / kepler_a) < 1e-7);
    CHECK(std::abs(2 * v.kinetic + v.potential) < 1e-7);
    REQUIRE(v.quadrature_error);
    CHECK(*v.quadrature_error < 1e-6);
}

TEST_CASE("virial: the quartic oscillator over two periods, 2⟨T⟩ = 4⟨V⟩ and ⟨V⟩ = E/3", "[virial][simulation]")
{
    // V = x⁴ from x = 1 at rest (E = 1): the period is 4 ∫₀¹ dx/√(2(1 − x⁴)) = B(1/4, 1/2)/√2.
    const double beta = std::tgamma(0.25) * std::tgamma(0.5) / std::tgamma(0.75);
    const double period = beta / std::sqrt(2.0);
    model scene = load("coordinates x\nT = 1/2*x'^2\nV = x^4\ninitial x = 1\nsimulate until " + digits(2 * period) +
                       " step 0.0005 tolerance 1e-12\n");
    analysis a = analyze(scene, {product::virial});
    REQUIRE(a.virial);
    const virial_result& v = *a.virial;
    INFO("⟨T⟩ = " << v.kinetic << ", ⟨V⟩ = " << v.potential);
    CHECK(std::abs(v.potential - 1.0 / 3) < 1e-7);
    CHECK(std::abs(2 * v.kinetic - 4 * v.potential) < 1e-6);
    CHECK(std::abs(v.kinetic + v.potential - 1) < 1e-9); // energy, whatever the span
}

TEST_CASE("virial: the JSON key of the product, and its errors", "[virial][cli]")
{
    const std::string scene = temporary_file("kepler_virial.lag", kepler(1));
    cli_result r = run_cli(scene + " --want virial --format json", "", 60);
    REQUIRE(r.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(r.out);
    REQUIRE(doc.contains("virial"));
    CHECK(std::abs(doc["virial"]["V"].get<double>() + 1 / kepler_a) < 1e-6);
    CHECK(std::abs(doc["virial"]["T"].get<double>() - 0.5 / kepler_a) < 1e-6);
    CHECK(doc["virial"]["over"][0].get<double>() == 0);
    CHECK(doc["virial"]["over"][1].get<double>() == Approx(2 * M_PI * std::pow(kepler_a, 1.5)));
    cli_result text = run_cli(scene + " --want virial", "", 60);
    CHECK(text.exit_code == 0);
    CHECK(text.out.find("Time averages (virial)") != std::string::npos);
    // Without a simulation to average over: exit 1 with the reason.
    cli_result none = run_cli("- --want virial", "coordinates x\nT = 1/2*x'^2\nV = x^4\n");
    CHECK(none.exit_code == 1);
    CHECK(none.err.find("end time") != std::string::npos);
}

TEST_CASE("virial: the report section gives the averages", "[virial][report]")
{
    const std::string scene = temporary_file("kepler_virial_report.lag", kepler(1) + "want virial\n");
    const std::string tex = temporary_file("kepler_virial_report.tex", "");
    cli_result r = run_cli("report " + scene + " -o " + tex, "", 60);
    REQUIRE(r.exit_code == 0);
    const std::string latex = read_file(tex);
    REQUIRE(latex.find("\\section{Time averages}") != std::string::npos);
    // ⟨V⟩ as the report prints it, read back as a number
    const std::string key = "\\langle V\\rangle &= ";
    const std::size_t at = latex.find(key);
    REQUIRE(at != std::string::npos);
    CHECK(std::abs(std::stod(latex.substr(at + key.size())) + 1 / kepler_a) < 1e-6);
}
