// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_examples.cpp
 *  Every example scene runs in every format, and its LaTeX compiles with pdflatex. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

using namespace lagrange_test;

TEST_CASE("examples: every scene runs in every format", "[examples]")
{
    std::vector<std::string> scenes = example_scenes();
    REQUIRE(scenes.size() >= 5);
    for (const std::string& scene : scenes) {
        INFO(scene);
        CHECK(run_cli("check " + scene).exit_code == 0);
        cli_result text = run_cli(scene);
        CHECK(text.exit_code == 0);
        CHECK(text.err.empty());
        cli_result json = run_cli(scene + " --format json");
        REQUIRE(json.exit_code == 0);
        nlohmann::json doc = nlohmann::json::parse(json.out);
        CHECK(doc.contains("stages"));
        // a scene whose `want` line leaves the equations out (the whole bicycle's fill pages) has none
        if (doc.contains("equations") || read_file(scene).find("\nwant ") == std::string::npos)
            CHECK(doc["equations"].size() == doc["coordinates"].size());
    }
}

TEST_CASE("examples: every scene's output is byte-identical from run to run", "[examples][determinism]")
{
    // GiNaC's operand order follows hash values that change with memory layout;
    // every printer and the compiled numeric programs must not depend on it.
    for (const std::string& scene : example_scenes()) {
        INFO(scene);
        for (const char* format : {"json", "latex"}) {
            cli_result first = run_cli(scene + " --format " + format);
            for (int run = 0; run < 3; ++run)
                CHECK(run_cli(scene + " --format " + format).out == first.out);
        }
    }
}

TEST_CASE("examples: the LaTeX of every scene compiles with pdflatex, without overfull boxes", "[examples][latex][pdflatex]")
{
    for (const std::string& scene : example_scenes()) {
        INFO(scene);
        std::string stem = scene.substr(scene.rfind('/') + 1);
        std::string tex = temporary_file(stem.substr(0, stem.size() - 4) + ".tex", "");
        REQUIRE(run_cli(scene + " --format latex -o " + tex).exit_code == 0);
        int status = 0;
        std::string log = compile_latex(tex, status);
        INFO(log.substr(log.size() > 3000 ? log.size() - 3000 : 0));
        CHECK(status == 0);
        CHECK(log.find("Overfull \\hbox") == std::string::npos);
    }
}

TEST_CASE("examples: LaTeX with floats, Greek names and subscripts compiles", "[examples][latex][pdflatex]")
{
    std::string scene = temporary_file("floats.lag", "scene \"Floats & names_with_underscores 100%\"\n"
                                                     "parameters m_1 omega0 kappa\ncoordinates theta1 x_cm\n"
                                                     "T = 1/2*m_1*(theta1'^2 + x_cm'^2)\n"
                                                     "V = 1.5e-20*kappa*theta1^2 + 2.5e12*omega0*x_cm^2\n");
    std::string tex = temporary_file("floats.tex", "");
    cli_result r = run_cli(scene + " --format latex -o " + tex);
    REQUIRE(r.exit_code == 0);
    std::string latex = read_file(tex);
    CHECK(latex.find("E-20") == std::string::npos);
    CHECK(latex.find("e-20") == std::string::npos);
    CHECK(latex.find("10^{-20}") != std::string::npos);
    CHECK(latex.find("\\ddot{\\theta}_{1}") != std::string::npos);
    int status = 0;
    std::string log = compile_latex(tex, status);
    INFO(log.substr(log.size() > 3000 ? log.size() - 3000 : 0));
    CHECK(status == 0);
}
