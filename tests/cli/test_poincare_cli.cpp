// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_poincare_cli.cpp
 *  `lagrange poincare`: the CSV on 1 and 2 threads, the picture, and bad input with its
 *  exit codes (an unknown coordinate with a caret, an energy below the minimum, a section
 *  no orbit crosses, an output extension nothing writes). */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <string>

using namespace lagrange_test;

namespace {

const std::string scenes = std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/";
const std::string henon_heiles = scenes + "henon_heiles.lag";

} // namespace

TEST_CASE("cli: poincare writes the same CSV on 1 and 2 threads", "[cli][poincare]")
{
    const std::string args = "poincare " + henon_heiles + " --section \"x = 0, x' > 0\" --energy 0.0833333333333333 "
                                                          "--orbits 12 --crossings 40 --seed 3";
    cli_result one = run_cli(args + " --threads 1", "", 60);
    cli_result two = run_cli(args + " --threads 2", "", 60);
    REQUIRE(one.exit_code == 0);
    REQUIRE(two.exit_code == 0);
    CHECK(one.out == two.out);
    CHECK(one.out.rfind("orbit,t,x,y,x_dot,y_dot\n", 0) == 0);
    std::size_t lines = 0;
    for (char c : one.out)
        lines += c == '\n';
    CHECK(lines == 1 + 12 * 40);
    CHECK_THAT(one.err, Catch::Contains("480 crossings of 12 orbits on 1 thread"));
    CHECK_THAT(two.err, Catch::Contains("on 2 threads"));
    CHECK(one.seconds < 30 * time_scale());
}

TEST_CASE("cli: poincare refuses an unknown coordinate with a caret, a low energy and an unknown extension",
          "[cli][poincare]")
{
    cli_result unknown = run_cli("poincare " + henon_heiles + " --section \"x = 0, psi' > 0\" --energy 0.1");
    CHECK(unknown.exit_code == 2);
    CHECK_THAT(unknown.err, Catch::Contains("--section:1:8: error: `psi` is not a coordinate of the scene"));
    CHECK_THAT(unknown.err, Catch::Contains("x = 0, psi' > 0\n       ^"));

    cli_result low = run_cli("poincare " + henon_heiles + " --section \"x = 0\" --energy -1");
    CHECK(low.exit_code == 2);
    CHECK_THAT(low.err, Catch::Contains("below the minimum of the energy, 0"));
    CHECK(low.out.empty());

    const std::string text = temporary_file("section.txt", "");
    std::remove(text.c_str());
    cli_result extension = run_cli("poincare " + henon_heiles + " --section \"x = 0\" --energy 0.1 -o " + text);
    CHECK(extension.exit_code == 2);
    CHECK_THAT(extension.err, Catch::Contains("takes a file ending in .csv, .svg, .png or .pdf"));
    CHECK(!std::fopen(text.c_str(), "r"));
}

TEST_CASE("cli: poincare says why there are no crossings, and exits 0", "[cli][poincare]")
{
    // On the section x = 1.2 the lowest energy of the well is V(1.2, y) > 1/12.
    cli_result none = run_cli("poincare " + henon_heiles + " --section \"x = 1.2, x' > 0\" --energy 0.0833");
    CHECK(none.exit_code == 0);
    CHECK_THAT(none.err, Catch::Contains("no crossings: the section x = 1.2 lies outside the energy surface"));
    CHECK(none.out == "orbit,t,x,y,x_dot,y_dot\n");
}

TEST_CASE("cli: poincare draws the section as SVG", "[cli][poincare][gnuplot]")
{
    const std::string svg = temporary_file("section.svg", "");
    cli_result drawn = run_cli("poincare " + henon_heiles + " --section \"x = 0, x' > 0\" --energy 0.125 --orbits 8 "
                               "--crossings 50 -o " + svg, "", 60);
    REQUIRE(drawn.exit_code == 0);
    const std::string picture = read_file(svg);
    CHECK(picture.find("<svg") != std::string::npos);
    // 400 points, each a small circle or path in the SVG: far more elements than an empty plot's.
    std::size_t uses = 0;
    for (std::size_t at = picture.find("<use"); at != std::string::npos; at = picture.find("<use", at + 1))
        ++uses;
    std::size_t paths = 0;
    for (std::size_t at = picture.find("<path"); at != std::string::npos; at = picture.find("<path", at + 1))
        ++paths;
    CHECK(uses + paths >= 400);
}

TEST_CASE("cli: poincare of three coordinates writes every quantity and draws the chosen axes",
          "[cli][poincare][gnuplot]")
{
    const std::string three = scenes + "three_oscillators.lag";
    const std::string args = "poincare " + three + " --section \"x = 0, x' > 0\" --energy 1 --orbits 6 --crossings 20";
    cli_result one = run_cli(args + " --threads 1", "", 60);
    cli_result two = run_cli(args + " --threads 2", "", 60);
    REQUIRE(one.exit_code == 0);
    CHECK(one.out == two.out);
    CHECK(one.out.rfind("orbit,t,x,y,z,x_dot,y_dot,z_dot\n", 0) == 0);
    CHECK_THAT(one.err, Catch::Contains("120 crossings of 6 orbits"));

    const std::string svg = temporary_file("section_zz.svg", "");
    cli_result drawn = run_cli(args + " --axes \"z, z'\" -o " + svg, "", 60);
    REQUIRE(drawn.exit_code == 0);
    const std::string picture = read_file(svg);
    // gnuplot writes the axes' labels as text.
    CHECK(picture.find(">z'</text>") != std::string::npos);

    cli_result bad = run_cli(args + " --axes \"y, w'\" -o " + svg);
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.err, Catch::Contains("--axes:1:4: error: `w` is not a coordinate of the scene"));
    CHECK_THAT(bad.err, Catch::Contains("y, w'\n   ^"));
    cli_result level = run_cli(args + " --axes \"x, y\"");
    CHECK(level.exit_code == 2);
    CHECK_THAT(level.err, Catch::Contains("is the section's coordinate"));
}
