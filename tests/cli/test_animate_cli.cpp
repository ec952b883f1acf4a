// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_animate_cli.cpp
 *  `lagrange animate`: the HTML player's embedded frames against the simulation, its rods
 *  and controls, the error without ffmpeg, and an extension nothing writes. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace lagrange_test;

namespace {

const std::string scene_text = "scene \"Double pendulum\"\nparameters m l g\ncoordinates theta phi\n"
                               "point upper mass m at (l*sin(theta), -l*cos(theta))\n"
                               "point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))\n"
                               "gravity g along (0, -1)\nvalues m = 1, l = 1.5, g = 9.81\n"
                               "initial theta = 1, phi = 2\nsimulate until 3 step 0.1\n";

/// The JSON of the page's `lagrange-data` element.
nlohmann::json page_data(const std::string& html)
{
    const std::string open = "<script id=\"lagrange-data\" type=\"application/json\">";
    const std::size_t begin = html.find(open);
    REQUIRE(begin != std::string::npos);
    const std::size_t end = html.find("</script>", begin);
    return nlohmann::json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

} // namespace

TEST_CASE("cli: animate writes a self-contained player whose frames are the simulation's", "[cli][animate]")
{
    const std::string scene = temporary_file("animated.lag", scene_text);
    const std::string html = temporary_file("animated.html", "");
    const std::string csv = temporary_file("animated.csv", "");
    cli_result drawn = run_cli("animate " + scene + " --fps 10 --trail 1 -o " + html, "", 60);
    REQUIRE(drawn.exit_code == 0);
    cli_result simulated = run_cli("simulate " + scene + " --csv " + csv, "", 60);
    REQUIRE(simulated.exit_code == 0);
    const std::string page = read_file(html);
    // Self-contained: nothing is loaded from elsewhere.
    CHECK(page.find("src=") == std::string::npos);
    CHECK(page.find("http") == std::string::npos);
    CHECK(page.find("location.hash") != std::string::npos);
    CHECK(page.find("lagrangePlayer") != std::string::npos);
    const nlohmann::json data = page_data(page);
    CHECK(data["view"] == "xy");
    CHECK(data["trail"] == 1);
    const std::size_t frames = data["times"].size(), markers = data["markers"].size();
    REQUIRE(frames == 31);
    REQUIRE(markers == 3); // upper, lower, the pivot
    CHECK(data["markers"][2]["name"] == "pivot");
    // Rods: upper to the pivot and lower to upper, which keep their distance; not lower to the pivot.
    CHECK(data["rods"] == nlohmann::json::parse("[[0,1],[0,2]]"));
    // The simulation's CSV (t, theta, phi, …) at the same times: the bobs where it says.
    std::istringstream rows(read_file(csv));
    std::string line;
    std::getline(rows, line); // header
    double worst = 0;
    for (std::size_t f = 0; f < frames && std::getline(rows, line); ++f) {
        double t, theta, phi;
        REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf", &t, &theta, &phi) == 3);
        CHECK(std::abs(data["times"][f].get<double>() - t) <= 1e-12);
        const double l = 1.5;
        const double expected[4] = {l * std::sin(theta), -l * std::cos(theta), l * std::sin(theta) + l * std::sin(phi),
                                    -l * std::cos(theta) - l * std::cos(phi)};
        const auto& p = data["positions"];
        const double got[4] = {p[f * 9 + 0], p[f * 9 + 1], p[f * 9 + 3], p[f * 9 + 4]};
        for (int k = 0; k < 4; ++k)
            worst = std::max(worst, std::abs(got[k] - expected[k]));
    }
    CHECK(worst <= 1e-7);
    // The energy drift is shown, and is small.
    REQUIRE(data["drift"].size() == frames);
    for (const auto& d : data["drift"])
        CHECK(std::abs(d.get<double>()) <= 1e-7);
}

TEST_CASE("cli: animate says when ffmpeg is missing, and refuses an extension nothing writes", "[cli][animate]")
{
    const std::string scene = temporary_file("animated.lag", scene_text);
    // A PATH that holds only `timeout` (which the runner needs): no ffmpeg, no compiler.
    const std::string keep = temporary_file("keep", "");
    const std::string folder = keep.substr(0, keep.rfind('/')) + "/only_timeout";
    cli_result video = run_cli("animate " + scene + " -o " + folder + "/out.mp4", "", 30,
                               "mkdir -p " + folder + " && ln -sf \"$(command -v timeout)\" " + folder +
                                   "/timeout && export PATH=" + folder);
    CHECK(video.exit_code == 1);
    CHECK_THAT(video.err, Catch::Contains("ffmpeg is not installed (Debian package ffmpeg)"));
    cli_result other = run_cli("animate " + scene + " -o " + folder + "/out.avi");
    CHECK(other.exit_code == 2);
    CHECK_THAT(other.err, Catch::Contains("takes a file ending in .html, .mp4 or .gif"));
    cli_result view = run_cli("animate " + scene + " --view yz -o " + folder + "/out.html");
    CHECK(view.exit_code == 2);
}

TEST_CASE("cli: phase draws the pendulum's portrait with its separatrix, and refuses an unknown coordinate",
          "[cli][phase][gnuplot]")
{
    const std::string scene = temporary_file(
        "pendulum.lag", "parameters m l g\ncoordinates theta\npoint P mass m at (l*sin(theta), -l*cos(theta))\n"
                        "gravity g along (0, -1)\nvalues m = 1, l = 1, g = 9.81\n");
    const std::string svg = temporary_file("phase.svg", "");
    cli_result drawn = run_cli("phase " + scene + " -o " + svg, "", 60);
    REQUIRE(drawn.exit_code == 0);
    CHECK_THAT(drawn.err, Catch::Contains("separatrices at energies 9.81"));
    const std::string picture = read_file(svg);
    CHECK(picture.find("<svg") != std::string::npos);
    CHECK(picture.find("separatrices") != std::string::npos);
    cli_result unknown = run_cli("phase " + scene + " --coordinate psi -o " + svg);
    CHECK(unknown.exit_code == 2);
    CHECK_THAT(unknown.err, Catch::Contains("--coordinate:1:1: error: `psi` is not a coordinate"));
}
