/** @file test_document.cpp
 *  Text, LaTeX and JSON documents of an analysis. */
#include "output/document.h"
#include "scene_helpers.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sstream>

using namespace lagrange;
using namespace lagrange_test;

namespace {

const std::string pendulum = "scene \"Pendulum & co\"\nparameters m l g\ncoordinates theta\n"
                             "point P mass m at (l*sin(theta), -l*cos(theta))\ngravity g along (0, -1)\n";

} // namespace

TEST_CASE("document: JSON has the spec's keys, with stages always present", "[document]")
{
    model scene = load(pendulum);
    analysis a = analyze(scene, {product::equations});
    std::ostringstream out;
    write_json(out, a);
    nlohmann::json doc = nlohmann::json::parse(out.str());
    CHECK(doc["scene"] == "Pendulum & co");
    CHECK(doc["coordinates"] == nlohmann::json::array({"theta"}));
    CHECK(doc["parameters"] == nlohmann::json::array({"m", "l", "g"}));
    CHECK(doc["stages"] == nlohmann::json::array({"lagrangian", "equations", "verification"}));
    CHECK_FALSE(doc.contains("timings"));
    CHECK(doc["equations"] == nlohmann::json::array({"l^2*m*theta_ddot+g*l*m*sin(theta)"}));
    CHECK(doc["kinetic_energy"] == "1/2*l^2*m*theta_dot^2");
    CHECK(doc["potential_energy"] == "-g*l*m*cos(theta)");

    std::ostringstream timed;
    write_json(timed, a, document_options{true});
    CHECK(nlohmann::json::parse(timed.str())["timings"].contains("lagrangian"));
}

TEST_CASE("document: text shows dots over velocities and Greek letters", "[document]")
{
    model scene = load(pendulum);
    std::ostringstream out;
    write_text(out, analyze(scene));
    CHECK(out.str().find("θ:  l²·m·θ\u0308 + g·l·m·sin(θ) = 0") != std::string::npos);
    CHECK(out.str().find("T = (1/2)·l²·m·θ\u0307²") != std::string::npos);
}

TEST_CASE("document: LaTeX is a whole document with escaped title and relations as =", "[document]")
{
    model scene = load(pendulum);
    std::ostringstream out;
    write_latex(out, analyze(scene));
    const std::string latex = out.str();
    CHECK(latex.rfind("\\documentclass", 0) == 0);
    CHECK(latex.find("Pendulum \\& co") != std::string::npos);
    CHECK(latex.find("&l^{2} m \\ddot{\\theta} + g l m \\sin\\theta = 0") != std::string::npos);
    CHECK(latex.find("\\end{document}") != std::string::npos);
}
