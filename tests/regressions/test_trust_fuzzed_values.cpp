// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_trust_fuzzed_values.cpp
 *  Issue 32: fuzzed values (random signs, zeros, 1e±300; a fixed seed) on the four surfaces
 *  that take them: a scene's `values` line, `--values`, `--sweep` and an ensemble's `--grid`.
 *  A value that contradicts an assumption of the derivation (parameters are positive) is bad
 *  input, exit 2 with the place of the value; any other value gives exit 0 with finite
 *  numbers, or exit 1 with a message saying what could not be done (an ensemble's point
 *  that fails is nan in its row, counted on standard error). Never exit 0 with a result for
 *  a value the derivation excluded. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace lagrange_test;

namespace {

const char* const pendulum_scene = R"(scene "pendulum"
parameters m l g
coordinates theta
point bob mass m at (l*sin(theta), -l*cos(theta))
gravity g along (0, -1)
initial theta = 0.1
simulate until 0.5
)";

const std::vector<std::string> names{"m", "l", "g"};

std::string exact_text(double x)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

/// One fuzzed value: ordinary, extreme (1e±300), zero, or of either sign.
double fuzzed(std::mt19937_64& random)
{
    std::uniform_real_distribution<double> ordinary(0.25, 8);
    const double sign = std::bernoulli_distribution(0.3)(random) ? -1 : 1;
    switch (std::uniform_int_distribution<int>(0, 5)(random)) {
    case 0: return sign * 1e300;
    case 1: return sign * 1e-300;
    case 2: return 0;
    default: return sign * ordinary(random);
    }
}

/// Every number of a JSON document is finite (nan and inf are written as null).
bool all_finite(const nlohmann::json& j)
{
    if (j.is_null())
        return false;
    if (j.is_number())
        return std::isfinite(j.get<double>());
    if (j.is_array() || j.is_object()) {
        for (const auto& item : j)
            if (!all_finite(item))
                return false;
    }
    return true;
}

/// Checks one run against what its values allow. `where` is the pseudo-file (or scene
/// file) an error about a value must be located in.
void check_run(const cli_result& r, bool contradicts, const std::string& where, bool csv)
{
    INFO("stderr: " << r.err);
    if (contradicts) {
        CHECK(r.exit_code == 2);
        const std::regex located("(^|\n)" + std::regex_replace(where, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                                 ":[0-9]+:[0-9]+: error: ");
        CHECK(std::regex_search(r.err, located));
        return;
    }
    REQUIRE((r.exit_code == 0 || r.exit_code == 1));
    if (r.exit_code == 1) {
        CHECK(r.err.find("error: ") != std::string::npos);
        return;
    }
    if (csv) {
        std::stringstream rows(r.out);
        std::string line;
        std::getline(rows, line); // the header
        while (std::getline(rows, line)) {
            std::stringstream cells(line);
            for (std::string cell; std::getline(cells, cell, ',');) {
                INFO(line);
                // a run that failed is nan in its row, and said so (ensemble.md)
                CHECK((std::isfinite(std::stod(cell)) || r.err.find("points failed (nan in the output)") != std::string::npos));
            }
        }
        return;
    }
    INFO(r.out.substr(0, 2000));
    CHECK(all_finite(nlohmann::json::parse(r.out).at(r.out.find("\"sweep\"") != std::string::npos ? "sweep" : "numeric")));
}

} // namespace

TEST_CASE("trust: fuzzed values on every surface are refused where they contradict an assumption",
          "[trust][values]")
{
    std::mt19937_64 random(32);
    const std::string scene_file = temporary_file("fuzzed_pendulum.lag", pendulum_scene);
    for (int trial = 0; trial < 25; ++trial) {
        std::vector<double> values;
        bool contradicts = false;
        std::string list;
        for (const std::string& name : names) {
            values.push_back(fuzzed(random));
            contradicts = contradicts || values.back() <= 0;
            list += (list.empty() ? "" : ",") + name + "=" + exact_text(values.back());
        }
        INFO("values " << list);
        {
            INFO("a `values` line");
            const std::string file = temporary_file("fuzzed_values_line.lag", std::string(pendulum_scene) + "values " + list + "\n");
            check_run(run_cli(file + " --want numeric --format json", "", 60), contradicts, file, false);
        }
        {
            INFO("--values");
            check_run(run_cli(scene_file + " --want numeric --format json --values " + list, "", 60), contradicts,
                      "--values", false);
        }
        {
            INFO("--sweep over l, the others by --values");
            const std::string l = exact_text(values[1]);
            const std::string others = "m=" + exact_text(values[0]) + ",g=" + exact_text(values[2]);
            const bool others_bad = values[0] <= 0 || values[2] <= 0;
            cli_result r = run_cli(scene_file + " --format json --values " + others + " --sweep l=" + l + ".." + l + ":1", "", 60);
            check_run(r, contradicts, values[1] <= 0 && !others_bad ? "--sweep" : others_bad ? "--values" : "", false);
        }
        {
            INFO("an ensemble over g, the others by --values");
            const std::string g = exact_text(values[2]);
            const std::string others = "m=" + exact_text(values[0]) + ",l=" + exact_text(values[1]);
            const bool others_bad = values[0] <= 0 || values[1] <= 0;
            cli_result r = run_cli("ensemble " + scene_file + " --threads 1 --values " + others + " --grid \"g=" + g + ".." + g +
                                       ":1, theta=0.2..0.2:1\" --until 0.5",
                                   "", 60);
            check_run(r, contradicts, values[2] <= 0 && !others_bad ? "--grid" : others_bad ? "--values" : "", true);
        }
    }
}
