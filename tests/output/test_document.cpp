// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_document.cpp
 *  Text, LaTeX and JSON documents of an analysis. */
#include "output/document.h"
#include "output/latex_blocks.h"
#include "output/report.h"
#include "helpers/scene_helpers.h"
#include "system/external.h"
#include "system/latex.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
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

TEST_CASE("document: timings split the simulation into preparation and integration", "[document]")
{
    // examples/double_pendulum.lag: its first run misses the tolerance and is rerun tighter.
    model scene = load("parameters M m l g\ncoordinates theta phi\n"
                       "point upper mass M at (l*sin(theta), -l*cos(theta))\n"
                       "point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))\n"
                       "gravity g along (0, -1)\nvalues M = 1, m = 0.01, l = 1, g = 9.81\n"
                       "initial theta = 0, phi = 0.05, theta' = 0, phi' = 0\nsimulate until 60\n");
    analysis a = analyze(scene, {product::simulation});
    REQUIRE(a.simulation);
    const simulation_result& s = *a.simulation;
    // Each run has one reference run at tolerance/1000: two runs, four with the rerun.
    CHECK(s.integration_runs == (s.missed_error ? 4u : 2u));
    CHECK(s.integration_seconds >= s.run.seconds);
    auto stage = std::find_if(a.stages.begin(), a.stages.end(),
                              [](const stage_time& t) { return t.stage == "simulation"; });
    REQUIRE(stage != a.stages.end());
    REQUIRE(stage->parts.size() == 2);
    CHECK(stage->parts[0].second == s.preparation_seconds);
    CHECK(stage->parts[1].second == s.integration_seconds);
    CHECK(s.preparation_seconds + s.integration_seconds <= stage->seconds);

    std::ostringstream timed, plain, json;
    write_text(timed, a, document_options{true});
    write_text(plain, a);
    const std::string runs = "    integration (" + std::to_string(s.integration_runs) + " runs";
    CHECK(timed.str().find(runs) != std::string::npos);
    CHECK(timed.str().find("    preparation (") != std::string::npos);
    CHECK(plain.str().find("integration (") == std::string::npos);
    // JSON's timings keep one number per stage.
    write_json(json, a, document_options{true});
    nlohmann::json timings = nlohmann::json::parse(json.str())["timings"];
    CHECK(timings.size() == a.stages.size());
    for (const stage_time& t : a.stages)
        CHECK(timings[t.stage] == t.seconds);
}


TEST_CASE("document: timings show the Jacobian's compile of an implicit method", "[document][cc]")
{
    model scene = load("parameters m l g\ncoordinates theta\npoint P mass m at (l*sin(theta), -l*cos(theta))\n"
                       "gravity g along (0, -1)\nvalues m = 1, l = 1, g = 9.81\ninitial theta = 0.5\n"
                       "simulate until 2 method bdf\n");
    analysis a = analyze(scene, {product::simulation});
    REQUIRE(a.simulation);
    const simulation_result& s = *a.simulation;
    CHECK(s.jacobian_seconds > 0);
    auto stage = std::find_if(a.stages.begin(), a.stages.end(),
                              [](const stage_time& t) { return t.stage == "simulation"; });
    REQUIRE(stage != a.stages.end());
    REQUIRE(stage->parts.size() == 3);
    CHECK(stage->parts[1].first.find("Jacobian") != std::string::npos);
    CHECK(stage->parts[1].second == s.jacobian_seconds);
    CHECK(s.preparation_seconds + s.jacobian_seconds + s.integration_seconds <= stage->seconds);
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

TEST_CASE("document: LaTeX body only, with the numeric mode vectors", "[document][latex]")
{
    // Issue 38: the align* blocks to paste into a paper, and the modes the text output lists.
    model scene = load("scene \"Two springs\"\nparameters m k\ncoordinates x y\n"
                       "L = 1/2*m*x'^2 + 1/2*m*y'^2 - 1/2*k*x^2 - 1/2*k*(y - x)^2\n"
                       "equilibrium x = 0, y = 0\nvalues m = 1, k = 1\n");
    document_options options;
    options.latex_body = true;
    std::ostringstream out;
    write_latex(out, analyze(scene), options);
    const std::string latex = out.str();
    CHECK(latex.find("\\documentclass") == std::string::npos);
    CHECK(latex.find("\\begin{document}") == std::string::npos);
    CHECK(latex.find("\\end{document}") == std::string::npos);
    CHECK(latex.find("\\begin{align*}") != std::string::npos);
    CHECK(latex.find("a_{1} &= \\begin{pmatrix}") != std::string::npos);
    CHECK(latex.find("a_{2} &= \\begin{pmatrix}") != std::string::npos);
}

namespace {

/// The widest overfull \hbox of a pdflatex log, in pt (0 if none).
double widest_overfull(const std::string& log)
{
    double widest = 0;
    for (std::size_t at = log.find("Overfull \\hbox ("); at != std::string::npos;
         at = log.find("Overfull \\hbox (", at + 1))
        widest = std::max(widest, std::stod(log.substr(at + 16)));
    return widest;
}

/// The text between `from` and the next `to`, both after `start`.
std::string between(const std::string& text, const std::string& start, const std::string& to)
{
    const std::size_t a = text.find(start);
    if (a == std::string::npos)
        return "";
    const std::size_t b = text.find(to, a);
    return text.substr(a, b == std::string::npos ? std::string::npos : b - a);
}

std::size_t count(const std::string& text, const std::string& what)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size()))
        ++n;
    return n;
}

std::string without(std::string text, const std::string& what)
{
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at))
        text.erase(at, what.size());
    return text;
}

} // namespace

TEST_CASE("document: the triple pendulum's characteristic polynomial breaks across lines, not scaled",
          "[document][latex][pdflatex]")
{
    const std::string path = std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/triple_pendulum.lag";
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    model scene = load_model(source_text(path, text.str()));
    analysis result = analyze(scene);
    REQUIRE(result.characteristic);
    std::ostringstream out;
    write_latex(out, result);
    const std::string latex = out.str();
    const std::string display = between(latex, "\\subsection*{Characteristic polynomial}", "\\end{align*}");
    INFO(display);
    CHECK(display.find("\\resizebox") == std::string::npos);
    CHECK(display.find("\\begin{align*}") != std::string::npos);
    CHECK(count(display, "\\\\\n&\\quad") >= 2);
    // Each line closes what it opens: \left( … \right. and \left. … \right).
    std::istringstream lines(display);
    for (std::string line; std::getline(lines, line);)
        CHECK(count(line, "\\left") == count(line, "\\right"));
    // Without the breaks, the display is the polynomial as the printer writes it.
    std::string joined;
    for (const std::string& term : print_terms(result.characteristic->polynomial, syntax::latex,
                                               term_order{{{result.characteristic->omega}}}))
        joined += (joined.empty() ? "" : " ") + term;
    // (a line that starts with a sign has "{}" before it, to keep the sign binary)
    const std::string unbroken = without(
        without(without(without(without(display, "\\right.\\\\\n&\\quad\\left.{}"), "\\right.\\\\\n&\\quad\\left."),
                        "\\\\\n&\\quad{}"),
                "\\\\\n&\\quad"),
        "\\right.");
    CHECK(unbroken.find("&" + joined + " = 0") != std::string::npos);

    std::string log;
    compile_latex(latex, {}, &log);
    CHECK(widest_overfull(log) <= 10);
    report_document report = build_report(result, source_text(path, text.str()), report_options{false, ""});
    const std::string polynomial = between(report.latex, "gives the characteristic polynomial", "\\end{align*}");
    CHECK(polynomial.find("\\begin{align*}") != std::string::npos);
    CHECK(polynomial.find("fitdisplay") == std::string::npos);
    compile_latex(report.latex, {}, &log);
    CHECK(widest_overfull(log) <= 10);
}

TEST_CASE("document: related equations share one starred align, aligned on =", "[document][latex]")
{
    std::ostringstream out;
    write_latex(out, analyze(load("parameters m l g\ncoordinates theta phi\n"
                                  "point P mass m at (l*sin(theta), -l*cos(theta))\n"
                                  "point Q mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))\n"
                                  "gravity g along (0, -1)\n")));
    const std::string latex = out.str();
    const std::string energies = between(latex, "\\subsection*{Lagrangian}", "\\subsection*{Equations");
    CHECK(count(energies, "\\begin{align*}") == 1);
    CHECK(energies.find("\nT &= ") != std::string::npos);
    CHECK(energies.find("\nV &= ") != std::string::npos);
    CHECK(energies.find("\nL &= ") != std::string::npos);
    const std::string equations = between(latex, "\\subsection*{Equations of motion}", "\\subsection*{Equilibria}");
    CHECK(count(equations, "\\begin{align*}") == 1);
    CHECK(count(equations, " = 0") == 2);
    // The mode vectors hold fractions: their parentheses grow.
    const std::string modes = between(latex, "\\subsection*{Normal modes}", "\\subsection*{Numeric");
    CHECK(modes.find("a_{1} &= \\left(") != std::string::npos);
}

TEST_CASE("document: notes keep -- and `names` as written", "[document][latex]")
{
    CHECK(latex_text("raise --max-seconds") == "raise -{}-max-seconds");
    CHECK(latex_text("want `modes` or `frequencies`") == "want \\texttt{modes} or \\texttt{frequencies}");
    CHECK(latex_text("`a_b` and a lone `") == "\\texttt{a\\_b} and a lone \\`{}");
    CHECK(latex_text("1 < 2 > 0 | x") == "1 $<$ 2 $>$ 0 $|$ x");
    CHECK(latex_text("a – b") == "a -- b"); // an en dash stays one
}
