// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_cli.cpp
 *  The command line: exit codes, hostile input, determinism, JSON keys, LaTeX that compiles. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>

using namespace lagrange_test;

namespace {

const std::string examples = std::string(LAGRANGE_SOURCE_DIR) + "/examples/";
const std::string double_pendulum = examples + "double_pendulum.lag";

} // namespace

TEST_CASE("cli: --version and --help", "[cli]")
{
    cli_result version = run_cli("--version");
    CHECK(version.exit_code == 0);
    CHECK(version.out.find("lagrange") != std::string::npos);
    cli_result help = run_cli("--help");
    CHECK(help.exit_code == 0);
    CHECK(help.out.find("--want") != std::string::npos);
}

TEST_CASE("cli: usage errors exit with 2", "[cli]")
{
    CHECK(run_cli("").exit_code == 2);
    CHECK(run_cli("--no-such-option " + double_pendulum).exit_code == 2);
    CHECK(run_cli("--format pdf " + double_pendulum).exit_code == 2);
    cli_result missing = run_cli("/no/such/scene.lag");
    CHECK(missing.exit_code == 2);
    CHECK(missing.err.find("no such file") != std::string::npos);
    CHECK(run_cli("/tmp").exit_code == 2);
    cli_result want = run_cli("--want nonsense " + double_pendulum);
    CHECK(want.exit_code == 2);
    CHECK(want.err.rfind("--want:1:1: error: unknown product", 0) == 0);
}

TEST_CASE("cli: a product the scene cannot give exits with 1 and says why", "[cli]")
{
    cli_result r = run_cli("--want inertia " + double_pendulum);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("need a rigid body") != std::string::npos);
}

TEST_CASE("cli: small-oscillation errors exit with 1 and say why, the same every run", "[cli]")
{
    std::string not_equilibrium = temporary_file(
        "not_equilibrium.lag", "parameters m l g\ncoordinates theta\npoint bob mass m at (l*sin(theta), -l*cos(theta))\n"
                               "gravity g along (0, -1)\nequilibrium theta = 1\n");
    cli_result first = run_cli("--want modes " + not_equilibrium);
    CHECK(first.exit_code == 1);
    CHECK(first.err.find("the equilibrium given is not one") != std::string::npos);
    for (int run = 0; run < 4; ++run)
        CHECK(run_cli("--want modes " + not_equilibrium).err == first.err);
    cli_result by_default = run_cli(not_equilibrium);
    CHECK(by_default.exit_code == 0); // without `want`: a note, the equations still printed
    CHECK(by_default.out.find("note: small oscillations not computed") != std::string::npos);
    std::string no_kinetic = temporary_file(
        "no_kinetic.lag", "parameters m k\ncoordinates x phi\nT = 1/2*m*x'^2\nV = 1/2*k*x^2 + 1/2*k*phi^2\n");
    cli_result r = run_cli("--want frequencies " + no_kinetic);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("coordinate `phi` has no kinetic energy at the equilibrium") != std::string::npos);
}

TEST_CASE("cli: check", "[cli]")
{
    cli_result ok = run_cli("check " + double_pendulum);
    CHECK(ok.exit_code == 0);
    CHECK(ok.out.find("ok (2 coordinates, 4 parameters)") != std::string::npos);
    std::string bad = temporary_file("bad.lag", "parameters m\ncoordinates q\nT = m*w\n");
    cli_result error = run_cli("check " + bad);
    CHECK(error.exit_code == 2);
    CHECK(error.err == bad + ":3:7: error: unknown name `w`: declare it with `parameters`, `coordinates` or `let`\n"
                             "T = m*w\n"
                             "      ^\n");
}

TEST_CASE("cli: check says what the numeric commands still need, and warns of a slip", "[cli]")
{
    // The double pendulum has values and an end time: nothing is missing.
    CHECK(run_cli("check " + double_pendulum).out.find("needed by") == std::string::npos);

    std::string bare = temporary_file("bare.lag", "parameters m k\ncoordinates x\nT = 1/2*m*x^2\nV = 1/2*k*x^2\n"
                                                  "values m = 1\n");
    cli_result r = run_cli("check " + bare);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("needed by simulate, workprecision and the numeric modes: the `values` line at line 5 gives "
                     "no value of `k`") != std::string::npos);
    CHECK(r.out.find("an end time (a `simulate until T` line or --until)") != std::string::npos);
    CHECK(r.err == bare + ":3:1: warning: `T` has no velocities, so it is no kinetic energy: the velocity of `x` "
                          "is written `x'`\nT = 1/2*m*x^2\n^\n");
    // The warning is given by every command that loads the scene, and changes no exit code.
    cli_result run = run_cli("--want equations " + bare);
    CHECK(run.exit_code == 0);
    CHECK(run.err.find(":3:1: warning: `T` has no velocities") != std::string::npos);
}

TEST_CASE("cli: standard input", "[cli]")
{
    cli_result r = run_cli("- --format json", "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n");
    REQUIRE(r.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(r.out);
    CHECK(doc["equations"][0] == "m*x_ddot+k*x");
    cli_result error = run_cli("-", "coordinates x\nT = w\n");
    CHECK(error.exit_code == 2);
    CHECK(error.err.rfind("<stdin>:2:5: error:", 0) == 0);
}

TEST_CASE("cli: the double pendulum's equations as JSON", "[cli]")
{
    cli_result r = run_cli(double_pendulum + " --want equations --format json --timings");
    REQUIRE(r.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(r.out);
    CHECK(doc["scene"] == "Double pendulum: equal lengths, unequal masses");
    CHECK(doc["coordinates"] == nlohmann::json::array({"theta", "phi"}));
    CHECK(doc["parameters"] == nlohmann::json::array({"M", "m", "l", "g"}));
    CHECK(doc["stages"] == nlohmann::json::array({"lagrangian", "equations", "verification"}));
    CHECK(doc["timings"].contains("equations"));
    CHECK(doc["verification"]["equations"].get<std::string>().find("Euler–Lagrange") != std::string::npos);
    REQUIRE(doc["equations"].size() == 2);
    // The strings are checked by meaning in test_lagrangian.cpp; here: the compact form.
    std::string theta = doc["equations"][0];
    CHECK(theta.find("theta_ddot") < theta.find("phi_ddot"));
    CHECK(theta.find("(M+m)") != std::string::npos);
    CHECK(theta.find("sin(theta)") != std::string::npos);
}

TEST_CASE("cli: output is byte-identical from run to run", "[cli][determinism]")
{
    for (const char* format : {"text", "json", "latex"}) {
        cli_result first = run_cli(double_pendulum + " --format " + format);
        cli_result second = run_cli(double_pendulum + " --format " + format);
        REQUIRE(first.exit_code == 0);
        CHECK(first.out == second.out);
    }
}

TEST_CASE("cli: -o writes the file", "[cli]")
{
    std::string path = temporary_file("out.json", "");
    cli_result r = run_cli(double_pendulum + " --format json -o " + path);
    CHECK(r.exit_code == 0);
    CHECK(r.out.empty());
    CHECK(nlohmann::json::parse(read_file(path)).contains("equations"));
}

TEST_CASE("cli: hostile input exits with 2 and a located message, never a crash or a hang", "[cli][hostile]")
{
    const std::string header = "parameters m\ncoordinates q\n";
    std::mt19937 random(7);
    std::string binary(4096, '\0');
    for (char& c : binary)
        c = static_cast<char>(random() & 0xFF);
    std::string sum_line = header + "T = ";
    for (int i = 0; i < 200000; ++i)
        sum_line += "m*q'^2+";
    sum_line += "m\nV = q @\n";
    struct hostile {
        const char* name;
        std::string text;
    };
    std::vector<hostile> inputs = {
        {"nesting 10000 deep", header + "V = " + std::string(10000, '(') + "q" + std::string(10000, ')') + "\n"},
        {"unary minus 10000 deep", header + "V = " + std::string(10000, '-') + "q\n"},
        {"power tower 10000 high", [&] {
             std::string s = header + "V = q";
             for (int i = 0; i < 10000; ++i)
                 s += "^q";
             return s + "\n";
         }()},
        {"1 MB line of garbage", header + std::string(1 << 20, 'x') + "\n"},
        {"1 MB line of sums, error at its end", sum_line},
        {"1 MB number", header + "V = " + std::string(1 << 20, '7') + "\n"},
        {"2^(2^64)", header + "V = 2^(2^64)*q\n"},
        {"factorial(10^9)", header + "V = factorial(10^9)\n"},
        {"huge float", header + "V = 1e999999999*q\n"},
        {"NUL bytes", header + std::string("V = q\0\0\0", 8) + "\n"},
        {"invalid UTF-8", header + "V = q \xC0\xAF\n"},
        {"binary file", binary},
        {"empty file", ""},
        {"only a byte-order mark", "\xEF\xBB\xBF"},
        {"unterminated string", "scene \"title\n"},
        {"imaginary unit", header + "V = (-4)^(1/2)*q\n"},
    };
    for (const hostile& h : inputs) {
        INFO(h.name);
        std::string path = temporary_file("hostile.lag", h.text);
        cli_result r = run_cli(path, "", 10);
        CHECK(r.exit_code == 2);
        CHECK(r.err.rfind(path + ":", 0) == 0);
        CHECK(r.err.find(": error: ") != std::string::npos);
        CHECK(r.err.find('^') != std::string::npos);
        CHECK(r.err.size() < 2000);
    }
}

TEST_CASE("cli: simulate writes CSV, an SVG plot and the JSON simulation keys", "[cli][simulation][gnuplot]")
{
    std::string csv = temporary_file("beats.csv", "");
    std::string svg = temporary_file("beats.svg", "");
    cli_result r = run_cli("simulate " + examples + "beats.lag --until 30 --format json --csv " + csv + " --plot " + svg, "", 60);
    REQUIRE(r.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(r.out);
    const nlohmann::json& s = doc["simulation"];
    CHECK(s["method"] == "dop853");
    CHECK(s["steps"].get<int>() > 0);
    CHECK(s["t"].size() == s["states"]["phi"].size());
    CHECK(s["states"].contains("theta_dot"));
    CHECK(s["invariants"]["energy_drift"].get<double>() < 1e-9);
    std::string table = read_file(csv);
    CHECK(table.rfind("t,theta,phi,theta_dot,phi_dot\n0,0,0.05,0,0\n", 0) == 0);
    // Each number is the shortest that reads back as the JSON's double (nlohmann's parser).
    std::istringstream rows(table);
    std::string row;
    std::getline(rows, row);
    for (std::size_t k = 0; std::getline(rows, row) && k < s["t"].size(); ++k) {
        std::istringstream fields(row);
        std::string field;
        std::getline(fields, field, ',');
        const double t = s["t"][k].get<double>();
        CHECK(std::strtod(field.c_str(), nullptr) == t);
        char longest[40];
        std::snprintf(longest, sizeof longest, "%.17g", t);
        CHECK(field.size() <= std::string(longest).size());
        std::getline(fields, field, ',');
        CHECK(std::strtod(field.c_str(), nullptr) == s["states"]["theta"][k].get<double>());
    }
    INFO(r.err);
    CHECK(read_file(svg).find("<svg") != std::string::npos);
}

TEST_CASE("cli: simulate and workprecision usage errors and impossible runs", "[cli][simulation]")
{
    CHECK(run_cli("simulate " + double_pendulum + " --method leapfrog").exit_code == 2);
    CHECK(run_cli("simulate " + double_pendulum + " --tolerance 0").exit_code == 2);
    CHECK(run_cli("simulate " + double_pendulum + " --until -1").exit_code == 2);
    cli_result no_end = run_cli("simulate -", "parameters k\ncoordinates x\nT = 1/2*x'^2\nV = 1/2*k*x^2\nvalues k = 1\n");
    CHECK(no_end.exit_code == 1);
    CHECK(no_end.err.find("end time") != std::string::npos);
    cli_result runaway = run_cli("simulate -", "parameters k\ncoordinates x\nT = 1/2*x'^2\nV = -x^4\n"
                                              "values k = 1\ninitial x = 1\nsimulate until 100\n");
    CHECK(runaway.exit_code == 1);
    CHECK(runaway.err.find("lagrange: error:") == 0);
}

TEST_CASE("cli: response writes JSON with the resonance peak, CSV and a Bode plot", "[cli][response][gnuplot]")
{
    const std::string scene = examples + "damped_driven_oscillator.lag";
    std::string svg = temporary_file("bode.svg", "");
    cli_result r = run_cli("response " + scene + " --input u --output x --format json --plot " + svg, "", 60);
    REQUIRE(r.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(r.out);
    // m = 1, k = 4, b = 0.4: ω_r = √(ω₀² − 2γ²) = √(4 − 2·0.04).
    CHECK(std::abs(doc["peak"]["omega"].get<double>() - std::sqrt(3.92)) < 1e-7);
    CHECK(doc["omega"].size() == 400);
    CHECK(doc["phase_degrees"].size() == 400);
    INFO(r.err);
    CHECK(read_file(svg).find("<svg") != std::string::npos);

    cli_result csv = run_cli("response " + scene + " --input u --output x --format csv --points 3 --from 1 --to 4");
    REQUIRE(csv.exit_code == 0);
    CHECK(csv.out.rfind("omega,magnitude,magnitude_db,phase_degrees,real,imag\n1,", 0) == 0);

    cli_result unknown = run_cli("response " + scene + " --input v --output x");
    CHECK(unknown.exit_code == 1);
    CHECK(unknown.err.find("no input `v`") != std::string::npos);
    cli_result missing = run_cli("response " + scene + " --input u");
    CHECK(missing.exit_code == 2);
}

TEST_CASE("cli: damped modes in JSON, text and LaTeX", "[cli][damped_modes]")
{
    const std::string scene = examples + "damped_double_pendulum.lag";
    cli_result json = run_cli(scene + " --format json --want numeric", "", 60);
    REQUIRE(json.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(json.out);
    const nlohmann::json& entry = doc["numeric"][0];
    REQUIRE(entry["eigenvalues"].size() == 4);
    REQUIRE(entry["damped_modes"].size() == 4);
    REQUIRE(entry["damped_mode_backward_error"].size() == 4);
    CHECK(entry["proportional_damping"] == false);
    for (std::size_t k = 0; k < 4; ++k) {
        const nlohmann::json& mode = entry["damped_modes"][k];
        REQUIRE(mode.size() == 2);
        // [re, im] pairs; the largest component is exactly 1, the other has an imaginary part.
        double largest = 0;
        bool complex_component = false;
        for (const nlohmann::json& component : mode) {
            REQUIRE(component.size() == 2);
            largest = std::max(largest, std::hypot(component[0].get<double>(), component[1].get<double>()));
            complex_component = complex_component || component[1].get<double>() != 0;
        }
        CHECK(largest == 1);
        CHECK(complex_component);
        CHECK(entry["damped_mode_backward_error"][k].get<double>() < 1e-14);
    }
    // Conjugate eigenvalues, conjugate modes.
    CHECK(entry["damped_modes"][0][0][1].get<double>() == -entry["damped_modes"][3][0][1].get<double>());

    cli_result text = run_cli(scene + " --want numeric", "", 60);
    REQUIRE(text.exit_code == 0);
    CHECK(text.out.find("      mode (") != std::string::npos);
    CHECK(text.out.find("modes x: (s²M + sC + K)x = 0, largest component 1") != std::string::npos);
    cli_result latex = run_cli(scene + " --want numeric --format latex", "", 60);
    REQUIRE(latex.exit_code == 0);
    CHECK(latex.out.find("Their modes $x$, in the same order") != std::string::npos);
    CHECK(latex.out.find("x &= \\begin{pmatrix}") != std::string::npos);
}

TEST_CASE("cli: --latex-body gives the LaTeX without its preamble", "[cli]")
{
    const std::string scene = std::string(LAGRANGE_SOURCE_DIR) + "/examples/double_pendulum.lag";
    cli_result whole = run_cli(scene + " --want frequencies --format latex");
    cli_result body = run_cli(scene + " --want frequencies --format latex --latex-body");
    REQUIRE(whole.exit_code == 0);
    REQUIRE(body.exit_code == 0);
    CHECK(whole.out.find("\\documentclass") != std::string::npos);
    CHECK(body.out.find("\\documentclass") == std::string::npos);
    CHECK(body.out.find("\\begin{document}") == std::string::npos);
    CHECK(body.out.find("\\end{document}") == std::string::npos);
    // after its comment line, the body is the whole document's between \begin and \end{document}
    const std::size_t begin = whole.out.find("\\begin{document}\n") + std::string("\\begin{document}\n").size();
    const std::size_t end = whole.out.find("\\end{document}");
    CHECK(body.out.find("\\subsection*{Lagrangian}") != std::string::npos);
    CHECK(body.out.substr(body.out.find('\n') + 1) == whole.out.substr(begin, end - begin));
}
