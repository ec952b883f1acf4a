// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_report.cpp
 *  The derivation report: every example's report compiles with pdflatex without
 *  overfull boxes; the double pendulum's report holds the homework's results
 *  (checked by meaning against the homework's closed forms, then found in the
 *  document); the output is byte-identical from run to run. */
#include "helpers/cli_runner.h"

#include "engine/analysis.h"
#include "engine/pictures.h"
#include "output/latex_blocks.h"
#include "output/print.h"
#include "output/report.h"
#include "scene/lower.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <cstdlib>
#include <filesystem>
#include <regex>

using namespace lagrange_test;

namespace {

/// The widest overfull \hbox of a pdflatex log, in pt (0 if none).
double widest_overfull_box(const std::string& log)
{
    static const std::regex overfull(R"(Overfull \\hbox \(([0-9.]+)pt too wide\))");
    double widest = 0;
    for (auto it = std::sregex_iterator(log.begin(), log.end(), overfull); it != std::sregex_iterator(); ++it)
        widest = std::max(widest, std::stod((*it)[1].str()));
    return widest;
}

struct built_report {
    lagrange::source_text source;
    lagrange::model scene;
    lagrange::analysis result;
    lagrange::report_document document;
};

/// The report of an example, built in-process.
std::unique_ptr<built_report> report_of(const std::string& example)
{
    std::string path = std::string(LAGRANGE_SOURCE_DIR) + "/examples/" + example;
    auto built = std::unique_ptr<built_report>(
        new built_report{lagrange::source_text(path, read_file(path)), {}, {}, {}});
    built->scene = lagrange::load_model(built->source);
    built->result = lagrange::analyze(built->scene);
    lagrange::report_options options;
    options.figure_prefix = "dp-";
    built->document = lagrange::build_report(built->result, built->source, options);
    return built;
}

const lagrange::parameter& parameter_named(const lagrange::model& scene, const std::string& name)
{
    for (const lagrange::parameter& p : scene.parameters)
        if (p.name == name)
            return p;
    FAIL("no parameter " << name);
    throw;
}

bool contains(const std::string& text, const std::string& piece) { return text.find(piece) != std::string::npos; }

} // namespace

TEST_CASE("report: every example's report compiles with pdflatex, no box overfull by more than 10 pt",
          "[report][latex][pdflatex]")
{
    for (const std::string& scene : example_scenes()) {
        INFO(scene);
        std::string stem = scene.substr(scene.rfind('/') + 1);
        stem = stem.substr(0, stem.size() - 4);
        std::string tex = temporary_file("report_" + stem + ".tex", "");
        cli_result r = run_cli("report " + scene + " -o " + tex, "", 60);
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        int status = 0;
        std::string log = compile_latex(tex, status);
        INFO(log.substr(log.size() > 3000 ? log.size() - 3000 : 0));
        CHECK(status == 0);
        CHECK(!contains(log, "\n! "));
        CHECK(widest_overfull_box(log) <= 10.0);
        CHECK(!contains(log, "LaTeX Warning: File"));
    }
}

TEST_CASE("report: the double pendulum's report holds the homework's results", "[report][gnuplot]")
{
    auto built = report_of("double_pendulum.lag");
    const lagrange::analysis& result = built->result;
    const std::string& latex = built->document.latex;
    const lagrange::model& scene = built->scene;
    using GiNaC::ex;
    ex M = parameter_named(scene, "M").symbol, m = parameter_named(scene, "m").symbol,
       l = parameter_named(scene, "l").symbol, g = parameter_named(scene, "g").symbol;
    REQUIRE(result.characteristic);
    REQUIRE(result.modes);
    REQUIRE(result.asymptotic);
    ex w = result.characteristic->omega;
    ex rho = scene.ratio->symbol;

    // The homework's eq. (59): M l² ω⁴ − 2(M + m) g l ω² + (M + m) g² = 0.
    ex homework = M * pow(l, 2) * pow(w, 4) - 2 * (M + m) * g * l * pow(w, 2) + (M + m) * pow(g, 2);
    CHECK((result.characteristic->polynomial - homework).expand().is_zero());
    lagrange::term_order by_omega;
    by_omega.groups.push_back({w});
    CHECK(contains(latex, lagrange::print(result.characteristic->polynomial, lagrange::syntax::latex, by_omega)));

    // Eq. (60): ω±² = [(1 + ρ) ± √(ρ(1 + ρ))] g/l, the slower first.
    REQUIRE(result.modes->frequencies_in_ratio.size() == 2);
    for (int k = 0; k < 2; ++k) {
        ex sign = k == 0 ? -1 : 1;
        ex reference = ((1 + rho) + sign * sqrt(rho * (1 + rho))) * g / l;
        const ex& engine = result.modes->frequencies_in_ratio[static_cast<std::size_t>(k)];
        // by meaning, at a few exact points (sqrt does not normalize symbolically)
        for (int r : {1, 3, 7}) {
            GiNaC::exmap at{{rho, GiNaC::numeric(r, 5)}, {g, 9}, {l, 2}};
            CHECK(GiNaC::abs((engine - reference).subs(at).evalf()) < 1e-30);
        }
        std::string printed;
        for (const std::string& term : lagrange::print_terms(engine, lagrange::syntax::latex))
            printed += (printed.empty() ? "" : " ") + term;
        CHECK(contains(latex, printed));
    }

    // Eq. (61): as ρ → 0, ω∓² → (1 ∓ √ρ) g/l; the modes (±√ρ, 1) (eq. 64).
    REQUIRE(result.asymptotic->frequencies.size() == 2);
    for (int k = 0; k < 2; ++k) {
        ex sign = k == 0 ? -1 : 1;
        ex reference = (1 + sign * sqrt(rho)) * g / l;
        CHECK((result.asymptotic->frequencies[static_cast<std::size_t>(k)] - reference).expand().is_zero());
        const std::vector<ex>& mode = result.asymptotic->modes[static_cast<std::size_t>(k)];
        REQUIRE(mode.size() == 2);
        CHECK((mode[0] + sign * sqrt(rho)).expand().is_zero());
        CHECK((mode[1] - 1).expand().is_zero());
        std::string printed;
        for (const std::string& term :
             lagrange::print_terms(result.asymptotic->frequencies[static_cast<std::size_t>(k)], lagrange::syntax::latex))
            printed += (printed.empty() ? "" : " ") + term;
        CHECK(contains(latex, "\\omega^{2}_{" + std::to_string(k + 1) + "} &\\to " + printed));
    }
    CHECK(contains(latex, "\\rho \\to 0"));

    // The mode shapes: the slower mode in phase, the faster in antiphase.
    CHECK(contains(latex, "the coordinates move in phase; in mode 2"));
    CHECK(contains(latex, "the coordinates move in antiphase."));
    CHECK(contains(latex, "The antiphase mode is the faster one."));
    REQUIRE(result.numeric);
    const Eigen::MatrixXd& a = result.numeric->front().modes;
    CHECK(a(0, 0) * a(1, 0) > 0);
    CHECK(a(0, 1) * a(1, 1) < 0);
    CHECK(result.numeric->front().omega[0] < result.numeric->front().omega[1]);

    // The figure of the modes, drawn by gnuplot, included by the document.
    {
        REQUIRE(built->document.figures.size() >= 1);
        CHECK(built->document.figures[0].name == "dp-modes.pdf");
        CHECK(built->document.figures[0].bytes.compare(0, 5, "%PDF-") == 0);
        CHECK(!contains(built->document.figures[0].bytes, "/CreationDate"));
        CHECK(contains(latex, "\\includegraphics[width=110mm]{dp-modes}"));
        // drawn as pendulums (rods from the pivot), not as a bar chart
        CHECK(contains(latex, "displaced along each mode"));
    }
    // The scene as written, and the energies before simplification.
    CHECK(contains(latex, "point\\ upper\\ mass\\ M\\ at"));
    CHECK(contains(latex, "As built from these contributions"));
    CHECK(contains(latex, "\\mathcal{M}(q) &= \\begin{pmatrix}"));

    // The mass matrix printed is ∂²T/∂q̇i∂q̇j of the homework's T (eq. 54), entry by entry.
    ex theta = scene.coordinates[0].position, phi = scene.coordinates[1].position;
    ex theta_dot = scene.coordinates[0].velocity, phi_dot = scene.coordinates[1].velocity;
    ex kinetic = M * pow(l, 2) * pow(theta_dot, 2) / 2 +
                 m * pow(l, 2) * (pow(theta_dot, 2) + pow(phi_dot, 2) + 2 * theta_dot * phi_dot * cos(theta - phi)) / 2;
    const std::optional<lagrange::acceleration_form>& grouped = result.equations->grouped;
    REQUIRE(grouped);
    const ex velocities[] = {theta_dot, phi_dot};
    for (unsigned i = 0; i < 2; ++i)
        for (unsigned j = 0; j < 2; ++j) {
            ex hessian = kinetic.diff(GiNaC::ex_to<GiNaC::symbol>(velocities[i]))
                             .diff(GiNaC::ex_to<GiNaC::symbol>(velocities[j]));
            CHECK((grouped->mass(i, j) - hessian).expand().is_zero());
        }
    // and f is the rest: 𝓜 q̈ + f gives back each equation
    for (unsigned i = 0; i < 2; ++i) {
        ex rebuilt = grouped->rest[i];
        for (unsigned j = 0; j < 2; ++j)
            rebuilt += grouped->mass(i, j) * scene.coordinates[j].acceleration;
        CHECK((rebuilt - (*result.equations->residuals)[i]).expand().is_zero());
    }
    std::string matrix = "\\begin{pmatrix}";
    for (unsigned i = 0; i < 2; ++i)
        for (unsigned j = 0; j < 2; ++j)
            matrix += (j ? " & " : "") + lagrange::print(grouped->mass(i, j), lagrange::syntax::latex) +
                      (j == 1 && i == 0 ? " \\\\ " : "");
    matrix += "\\end{pmatrix}";
    CHECK(contains(latex, "\\mathcal{M}(q) &= " + matrix));
}

TEST_CASE("report: only the sections the scene wants", "[report]")
{
    std::string scene = temporary_file("wants.lag", "scene \"Only equations\"\nparameters m g l\ncoordinates q\n"
                                                    "T = 1/2*m*l^2*q'^2\nV = -m*g*l*cos(q)\nwant equations\n");
    cli_result r = run_cli("report " + scene + " -o -");
    REQUIRE(r.exit_code == 0);
    CHECK(contains(r.out, "\\section{Equations of motion}"));
    CHECK(!contains(r.out, "characteristic"));
    CHECK(!contains(r.out, "Numeric values"));
    CHECK(contains(r.out, "\\end{document}"));
}

TEST_CASE("report: byte-identical from run to run, .tex with its figures and .pdf", "[report][determinism][gnuplot][pdflatex]")
{
    std::string scene = std::string(LAGRANGE_SOURCE_DIR) + "/examples/double_pendulum.lag";
    std::string folder = temporary_file("determinism_probe", "");
    folder = folder.substr(0, folder.rfind('/'));
    std::string tex = folder + "/same.tex", figure = folder + "/same-modes.pdf";
    REQUIRE(run_cli("report " + scene + " -o " + tex, "", 60).exit_code == 0);
    std::string first_tex = read_file(tex), first_figure = read_file(figure);
    const std::string beats = folder + "/same-beats.pdf"; // the simulation's figure, drawn from the trajectory
    std::string first_beats = read_file(beats);
    REQUIRE(run_cli("report " + scene + " -o " + tex, "", 60).exit_code == 0);
    CHECK(read_file(tex) == first_tex);
    CHECK(read_file(figure) == first_figure);
    CHECK(first_beats.compare(0, 5, "%PDF-") == 0);
    CHECK(read_file(beats) == first_beats);
    std::string pdf = folder + "/same.pdf";
    REQUIRE(run_cli("report " + scene + " -o " + pdf, "", 60).exit_code == 0);
    std::string first_pdf = read_file(pdf);
    CHECK(first_pdf.compare(0, 5, "%PDF-") == 0);
    REQUIRE(run_cli("report " + scene + " -o " + folder + "/other.pdf", "", 60).exit_code == 0);
    CHECK(read_file(folder + "/other.pdf") == first_pdf);
}

TEST_CASE("report: errors", "[report]")
{
    std::string scene = std::string(LAGRANGE_SOURCE_DIR) + "/examples/double_pendulum.lag";
    cli_result wrong = run_cli("report " + scene + " -o out.docx");
    CHECK(wrong.exit_code == 2);
    CHECK(contains(wrong.err, ".tex or .pdf"));
    CHECK(run_cli("report").exit_code == 2);
    cli_result bad = run_cli("report " + temporary_file("bad.lag", "coordinates q\nT = q'^2\nV = @\n"));
    CHECK(bad.exit_code == 2);
    CHECK(contains(bad.err, "bad.lag:3:"));

    // Without pdflatex on the PATH, a PDF cannot be made: a clear computation_error.
    auto built = report_of("double_pendulum.lag");
    const char* path = std::getenv("PATH");
    std::string saved = path ? path : "";
    setenv("PATH", "/nonexistent", 1);
    CHECK_THROWS_AS(lagrange::compile_report(built->document), lagrange::computation_error);
    setenv("PATH", saved.c_str(), 1);
}

TEST_CASE("report: a scene with LaTeX's special characters, Unicode and long lines compiles", "[report][latex][pdflatex]")
{
    std::string long_word(150, 'x');
    std::string scene = temporary_file(
        "special.lag", "# \\end{quote} $x$ 100% {braces} ^~ & #hash_ and Unicode: θ, ü, ∂, 漢\n# " + long_word +
                           "\nscene \"Specials & 100% $money$ \\input{x} {}\"\nparameters m_1 k\ncoordinates x_a\n"
                           "T = 1/2*m_1*x_a'^2\nV = 1/2*k*x_a^2 + 1/2*k*x_a^2*0 + 1/2*k*x_a^2*0 + 1/2*k*x_a^2*0 + "
                           "1/2*k*x_a^2*0 + 1/2*k*x_a^2*0\nvalues m_1 = 1.5e-20, k = 2\n");
    std::string tex = temporary_file("special_report.tex", "");
    cli_result r = run_cli("report " + scene + " -o " + tex, "", 60);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    std::string latex = read_file(tex);
    CHECK(contains(latex, "Specials \\& 100\\% \\$money\\$ \\textbackslash{}input\\{x\\} \\{\\}"));
    CHECK(contains(latex, "1.5\\times10^{-20}"));
    CHECK(!contains(latex.substr(latex.find("\\end{quote}")), "e-20")); // only the scene as written has it
    int status = 0;
    std::string log = compile_latex(tex, status);
    INFO(log.substr(log.size() > 3000 ? log.size() - 3000 : 0));
    CHECK(status == 0);
    CHECK(widest_overfull_box(log) <= 10.0);
}

TEST_CASE("report: a rolling wheel's contact force has its subsection", "[report]")
{
    // The upright disc of test_contact.cpp: the force F = Σ λ_k e_k, one display per axis.
    std::string scene = temporary_file("contact.lag", "parameters m g r I J\ncoordinates q1 q2 q3 x y z\n"
                                                      "body D inertia (I, J, I) mass m at (x, y, z) orientation "
                                                      "rotations(z q1, x q2, y q3)\ngravity g along (0, 0, 1)\n"
                                                      "rolls D on ground radius r axis y\nwant contact\n");
    cli_result r = run_cli("report " + scene + " -o -");
    REQUIRE(r.exit_code == 0);
    CHECK(contains(r.out, "\\subsection*{Contact forces}"));
    CHECK(contains(r.out, "$F = \\sum_k \\lambda_k e_k$"));
    for (const char* axis : {"x", "y", "z"})
        CHECK(contains(r.out, std::string("F^{\\mathrm{D}}_{") + axis + "}"));
}

TEST_CASE("report: a closed form too long to read is named, not printed", "[report]")
{
    // (A cubic's roots in many parameters run to megabytes of LaTeX, which TeX
    // cannot even read as one line.)
    lagrange::source_text source("long.lag", "parameters a\ncoordinates x\nT = 1/2*a*x'^2\n");
    lagrange::model scene = lagrange::load_model(source);
    lagrange::analysis result;
    result.scene = &scene;
    lagrange::report_options options;
    lagrange::report_writer w(result, source, options);
    std::vector<std::string> long_terms(400, "+ \\frac{a}{b}");
    w.display_rows({{"\\omega^{2}_{1}", {"a"}}, {"\\omega^{2}_{2}", long_terms}});
    std::string latex = w.finish().latex;
    CHECK(contains(latex, "\\omega^{2}_{1} &= a"));
    CHECK(contains(latex, "\\omega^{2}_{2} &= \\text{(a closed form of 5200 characters of \\LaTeX, too long to print)}"));
    CHECK(!contains(latex, "\\frac{a}{b}"));
}

TEST_CASE("report: a scene without points in a plane gets bar charts of its modes", "[report][gnuplot]")
{
    lagrange::source_text source(std::string(LAGRANGE_SOURCE_DIR) + "/examples/linear_molecule.lag",
                                 read_file(std::string(LAGRANGE_SOURCE_DIR) + "/examples/linear_molecule.lag"));
    lagrange::model scene = lagrange::load_model(source);
    lagrange::analysis result = lagrange::analyze(scene);
    lagrange::report_options options;
    options.figure_prefix = "lm-";
    lagrange::report_document document = lagrange::build_report(result, source, options);
    REQUIRE(document.figures.size() == 1);
    CHECK(document.figures[0].name == "lm-modes.pdf");
    CHECK(contains(document.latex, "The components of each mode vector"));
    options.plots = false;
    lagrange::report_document without = lagrange::build_report(result, source, options);
    CHECK(without.figures.empty());
    CHECK(!contains(without.latex, "includegraphics"));
}

// ---------------------------------------------------------------------------
// Rigid bodies in the report

namespace {

/// ∫ f over the box of limits (constant limits, innermost first) by nested
/// 16-point Gauss–Legendre quadrature, at the numeric point `at`: an evaluation
/// independent of the engine's exact integration.
double quadrature(const GiNaC::ex& f, const std::vector<lagrange::integration_limit>& limits, const GiNaC::exmap& at,
                  std::size_t level)
{
    static const double nodes[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                                    0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
    static const double weights[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                                      0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
    if (level == 0)
        return GiNaC::ex_to<GiNaC::numeric>(f.subs(at).evalf()).to_double();
    const lagrange::integration_limit& l = limits[level - 1];
    double a = GiNaC::ex_to<GiNaC::numeric>(l.lower.subs(at).evalf()).to_double();
    double b = GiNaC::ex_to<GiNaC::numeric>(l.upper.subs(at).evalf()).to_double();
    double sum = 0;
    for (int k = 0; k < 8; ++k)
        for (double sign : {-1.0, 1.0}) {
            GiNaC::exmap inner = at;
            inner[l.variable] = (a + b) / 2 + sign * nodes[k] * (b - a) / 2;
            sum += weights[k] * quadrature(f.subs(inner), limits, inner, level - 1);
        }
    return sum * (b - a) / 2;
}

/// The part of the report from `start` to the next \subsection or \section.
std::string section_of(const std::string& latex, const std::string& start)
{
    std::size_t from = latex.find(start);
    if (from == std::string::npos)
        return "";
    std::size_t to = std::min(latex.find("\\subsection", from + start.size()), latex.find("\\section", from + start.size()));
    return latex.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

} // namespace

TEST_CASE("report: the four homework bodies, each tensor with the integrals it came from", "[report][bodies]")
{
    auto built = report_of("homework_bodies.lag");
    const lagrange::analysis& result = built->result;
    const lagrange::model& scene = built->scene;
    const std::string& latex = built->document.latex;
    using GiNaC::ex;
    ex M = parameter_named(scene, "M").symbol, l = parameter_named(scene, "l").symbol,
       R = parameter_named(scene, "R").symbol;
    REQUIRE(result.inertia);
    REQUIRE(result.inertia->size() == 4);
    // The homework's eqs. 20, 25, 30 and 35 (the stick along y).
    const std::map<std::string, std::array<ex, 3>> homework = {
        {"S", {M * l * l / 12, 0, M * l * l / 12}},
        {"D", {M * R * R / 4, M * R * R / 4, M * R * R / 2}},
        {"B", {2 * M * R * R / 5, 2 * M * R * R / 5, 2 * M * R * R / 5}},
        {"H", {2 * M * R * R / 3, 2 * M * R * R / 3, 2 * M * R * R / 3}},
    };
    const GiNaC::exmap point{{M, GiNaC::numeric(13, 10)}, {l, GiNaC::numeric(7, 10)}, {R, GiNaC::numeric(11, 10)}};
    const char* axes = "xyz";
    CHECK(contains(latex, "\\section{Inertia tensors}"));
    for (const lagrange::inertia_result& in : *result.inertia) {
        INFO("body " << in.body);
        REQUIRE(homework.count(in.body));
        const std::string body = section_of(latex, "\\subsection{Body $" + in.body + "$}");
        REQUIRE(!body.empty());
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j)
                CHECK((in.tensor(i, j) - (i == j ? homework.at(in.body)[i] : ex(0))).expand().is_zero());
        CHECK(contains(body, "\\mathbf{I} &= " + lagrange::latex_matrix(in.tensor)));
        // Every component, as its integral: shown, and the integrand over the limits
        // printed gives the value printed (by quadrature), which is the tensor's entry.
        int components = 0;
        for (const lagrange::body_integral& integral : in.integrals) {
            if (integral.quantity.size() != 2)
                continue;
            INFO("I_" << integral.quantity);
            ++components;
            unsigned i = static_cast<unsigned>(std::string(axes).find(integral.quantity[0]));
            unsigned j = static_cast<unsigned>(std::string(axes).find(integral.quantity[1]));
            CHECK((integral.value - in.tensor(i, j)).expand().is_zero());
            double exact = GiNaC::ex_to<GiNaC::numeric>(integral.value.subs(point).evalf()).to_double();
            double numeric = quadrature(integral.integrand, integral.limits, point, integral.limits.size());
            CHECK(std::abs(numeric - exact) <= 1e-10 * (1 + std::abs(exact)));
            CHECK(contains(body, "I_{" + integral.quantity + "} &= \\int_{V} "));
            for (const lagrange::integration_limit& limit : integral.limits)
                CHECK(contains(body, "\\int_{" + lagrange::print(limit.lower, lagrange::syntax::latex) + "}^{" +
                                         lagrange::print(limit.upper, lagrange::syntax::latex) + "}"));
            CHECK(contains(body, "= " + lagrange::print(integral.value, lagrange::syntax::latex)));
        }
        CHECK(components == 6);
        // The density, with the deltas of the thin bodies.
        CHECK(contains(body, "\\varrho(\\mathbf{r}) &= "));
        CHECK(contains(body, "\\delta(") == (in.body != "B"));
        // L = I ω and T = ½ ωᵀ I ω in components.
        CHECK(contains(body, "\\mathbf{L} &= \\begin{pmatrix}"));
        CHECK(contains(body, "T &= "));
    }
    CHECK(contains(latex, "\\delta(r - R)"));
}

TEST_CASE("report: Euler's equations, conserved quantities and the symmetric solution of the disk", "[report][bodies]")
{
    auto built = report_of("disk.lag");
    const lagrange::analysis& result = built->result;
    const std::string& latex = built->document.latex;
    REQUIRE(result.euler);
    REQUIRE(result.euler->size() == 1);
    const lagrange::euler_result& e = result.euler->front();
    const lagrange::rigid_body& disk = built->scene.bodies.front();
    REQUIRE(disk.omega);
    // |L|² is Σ I_k² ω_k² with the disk's moments MR²/4, MR²/4, MR²/2.
    using GiNaC::ex;
    ex M = parameter_named(built->scene, "M").symbol, R = parameter_named(built->scene, "R").symbol;
    const ex moments[] = {M * R * R / 4, M * R * R / 4, M * R * R / 2};
    ex L2 = 0, T = 0;
    for (int k = 0; k < 3; ++k) {
        L2 += pow(moments[k], 2) * pow((*disk.omega)[static_cast<std::size_t>(k)], 2);
        T += moments[k] * pow((*disk.omega)[static_cast<std::size_t>(k)], 2) / 2;
    }
    CHECK((e.angular_momentum_squared - L2).expand().is_zero());
    CHECK((e.kinetic_energy - T).expand().is_zero());
    CHECK(contains(latex, "|\\mathbf{L}|^{2} &= I_{1}^{2}"));
    // A thin disk precesses at Ω = (I3 − I1) ω3 / I1 = ω3.
    REQUIRE(e.symmetric);
    CHECK((e.symmetric->precession - e.symmetric->constants[2]).expand().is_zero());
    CHECK(contains(latex, "\\Omega &= " + lagrange::print(e.symmetric->precession, lagrange::syntax::latex)));
    CHECK(contains(latex, "\\section{Euler's equations}"));
    CHECK(contains(latex, " = 0"));
    CHECK(contains(latex, "marginal"));
}

TEST_CASE("report: the free asymmetric top's elliptic solution, stability and polhode", "[report][bodies][gnuplot]")
{
    auto built = report_of("free_asymmetric_top.lag");
    const lagrange::analysis& result = built->result;
    const std::string& latex = built->document.latex;
    REQUIRE(result.euler);
    const lagrange::euler_result& e = result.euler->front();
    REQUIRE(e.elliptic);
    REQUIRE(e.poinsot);
    // The period printed is that of the closed form; check it against Euler's
    // equations integrated numerically (RK4) over one period: ω returns to ω(0).
    const auto& s = *e.elliptic;
    std::array<double, 3> w = s.evaluate(0);
    auto rate = [&](const std::array<double, 3>& v) {
        const auto& I = s.moments;
        return std::array<double, 3>{(I[1] - I[2]) * v[1] * v[2] / I[0], (I[2] - I[0]) * v[2] * v[0] / I[1],
                                     (I[0] - I[1]) * v[0] * v[1] / I[2]};
    };
    const int steps = 20000;
    const double h = s.period / steps;
    for (int n = 0; n < steps; ++n) {
        auto add = [](std::array<double, 3> a, const std::array<double, 3>& b, double f) {
            for (int k = 0; k < 3; ++k)
                a[static_cast<std::size_t>(k)] += f * b[static_cast<std::size_t>(k)];
            return a;
        };
        auto k1 = rate(w), k2 = rate(add(w, k1, h / 2)), k3 = rate(add(w, k2, h / 2)), k4 = rate(add(w, k3, h));
        for (std::size_t k = 0; k < 3; ++k)
            w[k] += h / 6 * (k1[k] + 2 * k2[k] + 2 * k3[k] + k4[k]);
    }
    std::array<double, 3> start = s.evaluate(0);
    for (std::size_t k = 0; k < 3; ++k)
        CHECK(std::abs(w[k] - start[k]) < 1e-8);
    CHECK(contains(latex, "4K(k)/\\lambda = " + lagrange::report_writer::number(s.period, 10)));
    // The intermediate axis (2: moments 5/6·M·… of the box 1 × 2 × 3) is the unstable one.
    REQUIRE(e.stability.size() == 3);
    CHECK(e.stability[1] == "unstable");
    CHECK(contains(latex, "2 & $"));
    CHECK(contains(latex, "$ & unstable\\\\"));
    std::vector<std::string> names;
    for (const lagrange::report_file& f : built->document.figures)
        names.push_back(f.name);
    CHECK(std::count(names.begin(), names.end(), "dp-body-X-polhode.pdf") == 1);
    CHECK(std::count(names.begin(), names.end(), "dp-body-X-omega.pdf") == 1);
    CHECK(contains(latex, "{dp-body-X-polhode}"));
    // Poinsot's figure (the seed's Figure 8): the ellipsoid on the plane at √(2T)/|L|, T and L from ω(0) by hand.
    CHECK(std::count(names.begin(), names.end(), "dp-body-X-poinsot.pdf") == 1);
    CHECK(contains(latex, "{dp-body-X-poinsot}"));
    REQUIRE(result.poinsot);
    REQUIRE(result.poinsot->size() == 1);
    const std::array<double, 3> I{13.0 / 12, 10.0 / 12, 5.0 / 12}, w0{0.2, 1, 0.3};
    const double two_t = I[0] * w0[0] * w0[0] + I[1] * w0[1] * w0[1] + I[2] * w0[2] * w0[2];
    const double l = std::sqrt(I[0] * I[0] * w0[0] * w0[0] + I[1] * I[1] * w0[1] * w0[1] + I[2] * I[2] * w0[2] * w0[2]);
    CHECK_THAT(result.poinsot->front().plane_distance, Catch::Matchers::WithinRel(std::sqrt(two_t) / l, 1e-13));
    CHECK(contains(latex, "\\sqrt{2T}/|\\mathbf{L}| = " + lagrange::report_writer::number(std::sqrt(two_t) / l, 6)));
    // byte-identical from run to run, figures included
    auto again = report_of("free_asymmetric_top.lag");
    CHECK(again->document.latex == latex);
    REQUIRE(again->document.figures.size() == built->document.figures.size());
    for (std::size_t k = 0; k < built->document.figures.size(); ++k)
        CHECK(again->document.figures[k].bytes == built->document.figures[k].bytes);
}

TEST_CASE("report: the heavy top's sleeping-top condition", "[report][bodies]")
{
    auto built = report_of("heavy_top.lag");
    const lagrange::analysis& result = built->result;
    const std::string& latex = built->document.latex;
    REQUIRE(result.tops);
    REQUIRE(result.tops->size() == 1);
    const lagrange::top_result& top = result.tops->front();
    using GiNaC::ex;
    const lagrange::model& scene = built->scene;
    ex M = parameter_named(scene, "M").symbol, g = parameter_named(scene, "g").symbol,
       l = parameter_named(scene, "l").symbol, A = parameter_named(scene, "A").symbol,
       C = parameter_named(scene, "C").symbol;
    // Textbook (Goldstein §5.7): stable when I3² ω3² > 4 I1 M g l, I1 = A + M l² about the pivot.
    CHECK((top.condition - (C * C * pow(top.spin, 2) - 4 * (A + M * l * l) * M * g * l)).expand().is_zero());
    CHECK(contains(latex, "\\section{The heavy top}"));
    std::string printed;
    lagrange::term_order order{{{top.spin}}};
    for (const std::string& term : lagrange::print_terms(top.condition, lagrange::syntax::latex, order))
        printed += (printed.empty() ? "" : " ") + term;
    CHECK(contains(latex, printed + " > 0."));
    CHECK(contains(latex, "V_{\\mathrm{eff}}(\\theta)"));
}

TEST_CASE("report: the double pendulum's beats, measured against 2π/(ω+ − ω−)", "[report][motion][gnuplot]")
{
    for (const char* example : {"double_pendulum.lag", "beats.lag"}) {
        INFO(example);
        auto built = report_of(example);
        const lagrange::analysis& result = built->result;
        const std::string& latex = built->document.latex;
        REQUIRE(result.simulation);
        REQUIRE(result.simulation->beats);
        const lagrange::beat_measurement& b = *result.simulation->beats;
        // The homework's eq. (60) at the scene's values (ρ = m/M = 0.01, g = 9.81, l = 1):
        // ω±² = [(1 + ρ) ± √(ρ(1 + ρ))] g/l, so the beat period is 2π/(ω+ − ω−).
        const double rho = 0.01, g = 9.81, l = 1;
        const double plus = std::sqrt(((1 + rho) + std::sqrt(rho * (1 + rho))) * g / l);
        const double minus = std::sqrt(((1 + rho) - std::sqrt(rho * (1 + rho))) * g / l);
        const double predicted = 2 * M_PI / (plus - minus);
        CHECK(std::abs(b.predicted - predicted) < 1e-9 * predicted);
        CHECK(std::abs(b.measured - predicted) < 0.01 * predicted);
        CHECK(b.coordinate == "phi");
        CHECK(contains(latex, "\\section{Motion in time}"));
        CHECK(contains(latex, "predicted $2\\pi/(\\omega_{+} - \\omega_{-}) = " +
                                  lagrange::report_writer::number(b.predicted, 5) + "$"));
        CHECK(contains(latex, "measured $" + lagrange::report_writer::number(b.measured, 5) + "$"));
        bool found = false;
        for (const lagrange::report_file& f : built->document.figures)
            if (f.name == "dp-beats.pdf") {
                found = true;
                CHECK(f.bytes.compare(0, 5, "%PDF-") == 0);
            }
        CHECK(found);
        CHECK(contains(latex, "{dp-beats}"));
        CHECK(contains(latex, "$\\theta(t)$ and $\\phi(t)$ from the simulation"));
    }
}

TEST_CASE("report: the work-precision diagram when the scene wants it", "[report][motion][gnuplot]")
{
    std::string path = temporary_file("wp_oscillator.lag", "scene \"Oscillator\"\nparameters m k\ncoordinates x\n"
                                                           "T = 1/2*m*x'^2\nV = 1/2*k*x^2\nvalues m = 1, k = 1\n"
                                                           "initial x = 1, x' = 0\nsimulate until 2\n"
                                                           "want workprecision\n");
    lagrange::source_text source(path, read_file(path));
    lagrange::model scene = lagrange::load_model(source);
    // workprecision compiles native code in a temporary folder: keep it out of the
    // system's temporary folder, where a test running beside this one counts them.
    const std::filesystem::path private_tmp =
        std::filesystem::path(temporary_file("wp_probe", "")).parent_path() / "wp_native_tmp";
    std::filesystem::create_directories(private_tmp);
    const char* old_tmp = std::getenv("TMPDIR");
    const std::string saved_tmp = old_tmp ? old_tmp : "";
    setenv("TMPDIR", private_tmp.c_str(), 1);
    lagrange::analysis result = lagrange::analyze(scene);
    if (old_tmp)
        setenv("TMPDIR", saved_tmp.c_str(), 1);
    else
        unsetenv("TMPDIR");
    REQUIRE(result.workprecision);
    lagrange::report_options options;
    options.figure_prefix = "wp-";
    lagrange::report_document document = lagrange::build_report(result, source, options);
    CHECK(contains(document.latex, "\\subsection{Work and precision}"));
    CHECK(contains(document.latex, "exact normal-mode solution") == result.workprecision->exact);
    REQUIRE(document.figures.size() == 1);
    CHECK(document.figures[0].name == "wp-workprecision.pdf");
    CHECK(contains(document.latex, "{wp-workprecision}"));
    // the diagram holds every run that measured an error, by steps: byte-identical on a second build
    lagrange::report_document again = lagrange::build_report(result, source, options);
    CHECK(again.figures[0].bytes == document.figures[0].bytes);
}

TEST_CASE("report: a cone, a region of given density and a free box compile, centre of mass as integrals",
          "[report][bodies][latex][pdflatex]")
{
    std::string path = temporary_file("bodies_region.lag",
                                      "scene \"Cone, ball of varying density, box\"\nparameters M R h a rho0\n"
                                      "body C cone(R, h) mass M\nbody B region ball(R) density rho0*(1 + z/R)\n"
                                      "body X box(a, 2*a, 3*a) mass M at (a, 0, 0)\nomega X (w1, w2, w3)\n"
                                      "want inertia, euler\n");
    lagrange::source_text source(path, read_file(path));
    lagrange::model scene = lagrange::load_model(source);
    lagrange::analysis result = lagrange::analyze(scene);
    lagrange::report_options options;
    options.figure_prefix = "region-";
    lagrange::report_document document = lagrange::build_report(result, source, options);
    const std::string& latex = document.latex;
    REQUIRE(result.inertia);
    REQUIRE(result.inertia->size() == 3);
    using GiNaC::ex;
    ex h = parameter_named(scene, "h").symbol, R = parameter_named(scene, "R").symbol,
       rho0 = parameter_named(scene, "rho0").symbol;
    // A solid cone's centre of mass is a quarter of its height above the base;
    // the ball's mass ∫ρ0(1 + z/R) dV = 4/3 π R³ ρ0 (the z term integrates to zero).
    CHECK((result.inertia->at(0).centre_of_mass[2] - h / 4).expand().is_zero());
    CHECK((result.inertia->at(1).mass - GiNaC::numeric(4, 3) * GiNaC::Pi * pow(R, 3) * rho0).expand().is_zero());
    const std::string cone = section_of(latex, "\\subsection{Body $C$}");
    CHECK(contains(cone, "M z_{\\mathrm{cm}} &= \\int_{V} "));
    CHECK(contains(cone, "so the centre of mass is at"));
    const std::string ball = section_of(latex, "\\subsection{Body $B$}");
    CHECK(contains(ball, "M &= \\int_{V} "));
    CHECK(contains(latex, "\\mathbf{I}_{O} &= "));
    std::string tex = temporary_file("bodies_region.tex", latex);
    int status = 0;
    std::string log = compile_latex(tex, status);
    INFO(log.substr(log.size() > 3000 ? log.size() - 3000 : 0));
    CHECK(status == 0);
    CHECK(widest_overfull_box(log) <= 10.0);
}

TEST_CASE("report: the damped driven oscillator shows C, the damped eigenvalues and the transfer function",
          "[report][damping]")
{
    auto built = report_of("damped_driven_oscillator.lag");
    const std::string& tex = built->document.latex;
    CHECK(contains(tex, "\\section{Damping}"));
    CHECK(contains(tex, "C = "));
    CHECK(contains(tex, "Damped eigenvalues at"));
    CHECK(contains(tex, "underdamped where it is positive"));
    CHECK(contains(tex, "\\section{Inputs: state space and transfer functions}"));
    CHECK(contains(tex, "H_{u \\to x}(s)"));
    CHECK(contains(tex, "frequencies and modes of the undamped system"));
    CHECK(contains(tex, "small oscillations without the damping"));
}

TEST_CASE("report: the damped double pendulum's table gives each eigenvalue its complex mode",
          "[report][damping]")
{
    auto built = report_of("damped_double_pendulum.lag");
    const std::string& tex = built->document.latex;
    CHECK(contains(tex, "The damping is not proportional ("));
    CHECK(contains(tex, " & mode $x_{k}$"));
    CHECK(contains(tex, "The damping is not proportional here: a mode is in general complex"));
    REQUIRE(built->result.numeric);
    const lagrange::numeric_modes& n = built->result.numeric->front();
    REQUIRE(n.damped_modes.cols() == 4);
    CHECK_FALSE(n.proportional_damping);
    // Every row of the table carries a mode with an imaginary part.
    const std::string table = section_of(tex, "\\subsection*{Damped eigenvalues at");
    std::size_t rows = 0;
    for (std::size_t at = table.find("& $("); at != std::string::npos; at = table.find("& $(", at + 1)) {
        const std::string mode = table.substr(at, table.find(")$", at) - at);
        INFO("mode " << mode);
        CHECK(contains(mode, "\\,i"));
        ++rows;
    }
    CHECK(rows == 4);
}

TEST_CASE("report: linearization with constraints gives A and the residual", "[report]")
{
    cli_result r = run_cli("report " + std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/rolling_disc.lag -o -");
    REQUIRE(r.exit_code == 0);
    CHECK(contains(r.out, "\\section{Linearization with constraints}"));
    CHECK(contains(r.out, "\\frac{4 g}{5 r}"));
    CHECK(contains(r.out, "F(x_0, u_0) &= (0,\\ 0,\\ w,\\ r w,\\ 0,\\ 0,\\ 0,\\ 0)"));
    CHECK(contains(r.out, "a steady motion, not an equilibrium"));
    CHECK(!contains(r.out, "Linearized at the equilibrium"));
}

TEST_CASE("report: a scene of one coordinate gets its phase portrait with the separatrices", "[report][gnuplot]")
{
    // The bead on the rotating hoop below the critical rate (w² = 4 < g/R): h = ½mR²q̇² + V with
    // V = mgR(1 − cos q) − ½mR²w² sin²q, least (0) at the bottom, and the separatrix through
    // the top q = ±π at h = 2mgR.
    std::unique_ptr<built_report> hoop = report_of("rotating_hoop.lag");
    hoop->result.phase = lagrange::report_phase_portrait(hoop->scene, hoop->result);
    REQUIRE(hoop->result.phase);
    const lagrange::phase_portrait& p = *hoop->result.phase;
    CHECK(std::abs(p.minimum) < 1e-12);
    REQUIRE(p.separatrices.size() == 1);
    CHECK(std::abs(p.separatrices[0] - 2 * 9.81) < 1e-9);
    REQUIRE_FALSE(p.unstable.empty());
    for (double q : p.unstable)
        CHECK(std::abs(std::abs(q) - M_PI) < 1e-9);
    lagrange::report_options options;
    options.figure_prefix = "hoop-";
    const lagrange::report_document document = lagrange::build_report(hoop->result, hoop->source, options);
    CHECK(document.latex.find("\\section{Phase portrait}") != std::string::npos);
    CHECK(std::any_of(document.figures.begin(), document.figures.end(),
                      [](const lagrange::report_file& f) { return f.name == "hoop-phase.pdf"; }));
    // Two coordinates: no phase portrait.
    std::unique_ptr<built_report> pendulum = report_of("double_pendulum.lag");
    CHECK_FALSE(lagrange::report_phase_portrait(pendulum->scene, pendulum->result));
}
