/** @file test_report.cpp
 *  The derivation report: every example's report compiles with pdflatex without
 *  overfull boxes; the double pendulum's report holds the homework's results
 *  (checked by meaning against the homework's closed forms, then found in the
 *  document); the output is byte-identical from run to run. */
#include "cli_runner.h"

#include "engine/analysis.h"
#include "output/print.h"
#include "output/report.h"
#include "scene/lower.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <regex>

using namespace lagrange_test;

namespace {

std::vector<std::string> example_scenes()
{
    std::vector<std::string> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(LAGRANGE_SOURCE_DIR) + "/examples"))
        if (entry.path().extension() == ".lag")
            scenes.push_back(entry.path().string());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

bool have(const char* program)
{
    return std::system((std::string("command -v ") + program + " >/dev/null 2>&1").c_str()) == 0;
}

/// Compiles `tex` (a path) with pdflatex in its folder; returns pdflatex's log.
std::string compile_latex(const std::string& tex, int& status)
{
    std::string directory = tex.substr(0, tex.rfind('/'));
    std::string name = tex.substr(tex.rfind('/') + 1);
    std::string command = "cd " + directory + " && pdflatex -interaction=nonstopmode -halt-on-error " + name +
                          " >/dev/null 2>&1";
    status = std::system(command.c_str());
    return read_file(tex.substr(0, tex.size() - 4) + ".log");
}

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
          "[report][latex]")
{
    if (!have("pdflatex"))
        FAIL("pdflatex is not installed (the test command installs texlive-latex-base)");
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

TEST_CASE("report: the double pendulum's report holds the homework's results", "[report]")
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
        if (!have("gnuplot"))
            FAIL("gnuplot is not installed (the test command installs gnuplot-nox)");
        REQUIRE(built->document.figures.size() == 1);
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
    std::optional<lagrange::acceleration_form> grouped = lagrange::group_by_accelerations(scene, *result.equations);
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
        CHECK((rebuilt - (*result.equations)[i]).expand().is_zero());
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

TEST_CASE("report: byte-identical from run to run, .tex with its figures and .pdf", "[report][determinism]")
{
    std::string scene = std::string(LAGRANGE_SOURCE_DIR) + "/examples/double_pendulum.lag";
    std::string folder = temporary_file("determinism_probe", "");
    folder = folder.substr(0, folder.rfind('/'));
    std::string tex = folder + "/same.tex", figure = folder + "/same-modes.pdf";
    REQUIRE(run_cli("report " + scene + " -o " + tex, "", 60).exit_code == 0);
    std::string first_tex = read_file(tex), first_figure = read_file(figure);
    REQUIRE(run_cli("report " + scene + " -o " + tex, "", 60).exit_code == 0);
    CHECK(read_file(tex) == first_tex);
    CHECK(read_file(figure) == first_figure);
    if (have("pdflatex")) {
        std::string pdf = folder + "/same.pdf";
        REQUIRE(run_cli("report " + scene + " -o " + pdf, "", 60).exit_code == 0);
        std::string first_pdf = read_file(pdf);
        CHECK(first_pdf.compare(0, 5, "%PDF-") == 0);
        REQUIRE(run_cli("report " + scene + " -o " + folder + "/other.pdf", "", 60).exit_code == 0);
        CHECK(read_file(folder + "/other.pdf") == first_pdf);
    }
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

TEST_CASE("report: a scene with LaTeX's special characters, Unicode and long lines compiles", "[report][latex]")
{
    if (!have("pdflatex"))
        FAIL("pdflatex is not installed (the test command installs texlive-latex-base)");
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

TEST_CASE("report: a scene without points in a plane gets bar charts of its modes", "[report]")
{
    lagrange::source_text source(std::string(LAGRANGE_SOURCE_DIR) + "/examples/linear_molecule.lag",
                                 read_file(std::string(LAGRANGE_SOURCE_DIR) + "/examples/linear_molecule.lag"));
    lagrange::model scene = lagrange::load_model(source);
    lagrange::analysis result = lagrange::analyze(scene);
    lagrange::report_options options;
    options.figure_prefix = "lm-";
    lagrange::report_document document = lagrange::build_report(result, source, options);
    if (!have("gnuplot"))
        FAIL("gnuplot is not installed (the test command installs gnuplot-nox)");
    REQUIRE(document.figures.size() == 1);
    CHECK(document.figures[0].name == "lm-modes.pdf");
    CHECK(contains(document.latex, "The components of each mode vector"));
    options.plots = false;
    lagrange::report_document without = lagrange::build_report(result, source, options);
    CHECK(without.figures.empty());
    CHECK(!contains(without.latex, "includegraphics"));
}
