// SPDX-License-Identifier: GPL-2.0-or-later
/** @file report.cpp
 *  The derivation report: the framework (report_writer, figures through
 *  gnuplot, pdflatex) and the sections of the equations and small oscillations.
 *  Every equation printed here is a result of the stages; the only arithmetic
 *  done here is for presentation (picking the coefficients of q̈ out of an
 *  equation, evaluating positions to draw them). */
#include "output/report.h"
#include "output/damping.h"

#include "mechanics/lagrangian.h"
#include "core/number_text.h"
#include "system/gnuplot.h"
#include "system/latex.h"
#include "output/latex_blocks.h"
#include "output/mode_frequency.h"
#include "output/print.h"
#include "output/report_sections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace lagrange {

namespace {

bool wants(const analysis& result, product p) { return result.wanted.count(p) > 0; }

std::string index(std::size_t k) { return "_{" + std::to_string(k + 1) + "}"; }

/// "θ, φ and ψ" in LaTeX math.
std::string name_list(const std::vector<std::string>& names)
{
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0)
            out += i + 1 == names.size() ? " and " : ", ";
        out += "$" + report_writer::name(names[i]) + "$";
    }
    return out;
}

std::string column_latex(const std::vector<std::string>& entries)
{
    std::string out = "\\begin{pmatrix}";
    for (std::size_t i = 0; i < entries.size(); ++i)
        out += (i ? " \\\\ " : "") + entries[i];
    return out + "\\end{pmatrix}";
}

std::string column_latex(const std::vector<GiNaC::ex>& entries)
{
    std::vector<std::string> printed;
    for (const GiNaC::ex& e : entries)
        printed.push_back(report_writer::math(e));
    return column_latex(printed);
}

// ---------------------------------------------------------------------------
// The sections

void write_title(report_writer& w)
{
    const model& scene = w.scene();
    w.latex("\\title{" + latex_text(scene.title.empty() ? "Derivation" : scene.title) + "}\n")
        .latex("\\author{\\texttt{lagrange} derivation report}\n\\date{}\n\\maketitle\n");
    w.latex("\\section{The scene}\n")
        .text("The system is given by the scene file below. Everything that follows is derived from it by the "
              "engine: each equation is printed from the engine's results.")
        .latex("\n\\begin{quote}\\small\\ttfamily\\raggedright\\noindent\n");
    // Verbatim, line by line, escaped; long lines wrap at the margin (\raggedright).
    const std::string& text = w.source().text();
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        // One character (UTF-8 code point) at a time: spaces kept (`\ ` does not
        // collapse, and may break), a break allowed after operators and inside
        // any run of 40 characters without one, so no line runs past the margin.
        std::string escaped;
        std::size_t run = 0;
        for (std::size_t i = 0; i < line.size();) {
            std::size_t length = 1;
            while (i + length < line.size() && (static_cast<unsigned char>(line[i + length]) & 0xC0) == 0x80)
                ++length;
            std::string character = line.substr(i, length);
            i += length;
            if (character == " " || character == "\t") {
                escaped += "\\ ";
                run = 0;
                continue;
            }
            char c = character[0];
            bool control = length == 1 && (static_cast<unsigned char>(c) < 0x20 || c == 0x7F);
            escaped += control ? std::string("?") : latex_text(character);
            if (c == ',' || c == '+' || c == '*' || c == '/' || c == '=' || c == '(' || ++run >= 40) {
                escaped += "\\allowbreak{}";
                run = 0;
            }
        }
        w.latex(escaped.empty() ? "\\mbox{}\\\\\n" : escaped + "\\\\\n");
        if (end == std::string::npos)
            break;
        start = end + 1;
    }
    w.latex("\\end{quote}\n");
}

void write_coordinates(report_writer& w)
{
    const model& scene = w.scene();
    w.latex("\\section{Coordinates and parameters}\n");
    std::size_t n = scene.coordinates.size();
    if (n == 0) // a scene of rigid bodies only (their inertia, Euler's equations in ω)
        w.text("The scene has no generalized coordinates");
    else
    w.text("The configuration is described by " + std::string(n == 1 ? "the generalized coordinate " :
                                                             "the " + std::to_string(n) + " generalized coordinates "))
        .latex(name_list(coordinate_names(scene)));
    std::vector<std::string> parameters;
    for (const parameter& p : scene.parameters)
        parameters.push_back(p.name);
    if (!parameters.empty())
        w.text("; the parameters ").latex(name_list(parameters)).text(parameters.size() == 1 ? " is a positive constant" :
                                                                      " are positive constants");
    w.text(". A dot denotes the derivative with respect to time ").latex("$t$.");
    w.latex("\n\n");
    if (scene.ratio)
        w.text("Results are also written in the ratio ")
            .latex("$" + report_writer::name(scene.ratio->name) + " = " + report_writer::math(scene.ratio->definition) + "$.\n\n");
}

std::string point_name(const std::string& name) { return "\\mathbf{r}_{\\text{" + latex_text(name) + "}}"; }

void write_lagrangian(report_writer& w)
{
    const model& scene = w.scene();
    const lagrangian_result& l = *w.result().lagrangian;
    const term_order velocities = velocity_order(scene);
    w.latex("\\section{Kinetic and potential energy}\n");
    if (!scene.points.empty()) {
        w.text("The point masses are at");
        w.latex("\n");
        // A planar scene (every z zero) is shown in the plane.
        bool planar = std::all_of(scene.points.begin(), scene.points.end(), [](const point_mass& p) {
            return p.position.size() < 3 || p.position[2].is_zero();
        });
        std::vector<report_writer::row> rows;
        for (const point_mass& p : scene.points) {
            std::vector<std::string> components;
            for (std::size_t i = 0; i < p.position.size() && (i < 2 || !planar); ++i)
                components.push_back(report_writer::math(p.position[i]));
            std::string row = "\\left(";
            for (std::size_t i = 0; i < components.size(); ++i)
                row += (i ? ",\\ " : "") + components[i];
            row += "\\right)";
            rows.push_back({point_name(p.name), {row}, ""});
        }
        w.display_rows(rows);
        w.text("with masses ");
        for (std::size_t i = 0; i < scene.points.size(); ++i)
            w.latex((i ? (i + 1 == scene.points.size() ? " and " : ", ") : "") + std::string("$") +
                    report_writer::math(scene.points[i].mass) + "$");
        w.text(". Each contributes ").latex("$\\frac{1}{2} m |\\dot{\\mathbf{r}}|^{2}$").text(" to T");
        if (scene.gravity)
            w.text(" and, in the uniform gravity of strength ")
                .latex("$" + report_writer::math(scene.gravity->strength) + "$")
                .text(", ")
                .latex("$-m\\,\\mathbf{g}\\cdot\\mathbf{r}$")
                .text(" to V");
        w.text(".");
        w.latex("\n");
    }
    if (!scene.springs.empty())
        w.text(" Each spring of stiffness k and rest length a between the points ")
            .latex("$\\mathbf{r}_A$, $\\mathbf{r}_B$")
            .text(" adds ")
            .latex("$\\frac{1}{2} k \\left(|\\mathbf{r}_A - \\mathbf{r}_B| - a\\right)^{2}$")
            .text(" to V.")
            .latex("\n");
    if (!l.split) {
        w.text("The Lagrangian is not a polynomial of degree two in the velocities, so it is kept whole:");
        w.display("L", l.lagrangian);
        return;
    }
    if (!scene.points.empty() || !scene.springs.empty() || scene.gravity) {
        w.text("As built from these contributions (and any energy written in the scene), before simplification:");
        w.display_rows({{"T", print_terms(l.kinetic_built, syntax::latex, velocities)},
                        {"V", print_terms(l.potential_built, syntax::latex)}});
        w.text("Simplified (the trigonometric terms in their canonical form, then grouped):");
    } else {
        w.text("The energies, simplified (the trigonometric terms in their canonical form, then grouped), are");
    }
    std::vector<report_writer::row> energies{{"T", print_terms(l.kinetic, syntax::latex, velocities)}};
    if (!l.gyroscopic.is_zero())
        energies.push_back({"L_{1}", print_terms(l.gyroscopic, syntax::latex, velocities)});
    energies.push_back({"V", print_terms(l.potential, syntax::latex)});
    w.display_rows(energies);
    if (!l.gyroscopic.is_zero())
        w.text("(").latex("$L_{1}$").text(" is the part of the Lagrangian linear in the velocities.) ");
    w.text("and the Lagrangian is ").latex(l.gyroscopic.is_zero() ? "$L = T - V$:" : "$L = T + L_{1} - V$:");
    w.display_terms("L", print_terms(l.lagrangian, syntax::latex, velocities));
}

void write_equations(report_writer& w)
{
    const model& scene = w.scene();
    const std::vector<GiNaC::ex>& equations = *w.result().equations->residuals;
    const std::size_t n = scene.coordinates.size();
    w.latex("\\section{Equations of motion}\n");
    w.text("The Euler–Lagrange equations");
    w.latex("\n\\[\\frac{d}{dt}\\frac{\\partial L}{\\partial \\dot{q}_{i}} - \\frac{\\partial L}{\\partial q_{i}} = 0\\]\n");
    w.text("give, one for each coordinate, after simplification:");
    w.latex("\n");
    for (std::size_t i = 0; i < n; ++i) {
        w.latex("\n\\noindent For $" + report_writer::name(scene.coordinates[i].name) + "$:");
        w.display_terms("", print_terms(equations[i], syntax::latex, equation_order(scene)), " = 0");
    }
    const std::optional<acceleration_form>& grouped = w.result().equations->grouped;
    if (!grouped)
        return;
    const GiNaC::matrix& mass = grouped->mass;
    const std::vector<GiNaC::ex>& rest = grouped->rest;
    std::vector<std::string> accelerations;
    for (const coordinate& c : scene.coordinates)
        accelerations.push_back(report_writer::name(c.acceleration.get_name()));
    w.text("Grouped by the accelerations, they read");
    w.latex("\n\\[\\mathcal{M}(q)\\," + column_latex(accelerations) + " + \\mathbf{f}(q, \\dot{q}) = 0\\]\n");
    w.text("with the mass matrix");
    w.display_matrix("\\mathcal{M}(q)", mass);
    w.text("and the remaining terms (velocity-dependent forces and the forces of the potential)");
    std::vector<report_writer::row> rows;
    for (std::size_t i = 0; i < n; ++i)
        rows.push_back({"f" + index(i), print_terms(rest[i], syntax::latex, velocity_order(scene))});
    w.display_rows(rows);
}

void write_equilibria(report_writer& w)
{
    const model& scene = w.scene();
    const analysis& result = w.result();
    const equilibria_result& e = *result.equilibria;
    w.latex("\\section{Equilibria and their stability}\n");
    if (e.given) {
        w.text("The scene names an equilibrium; the engine checked that the generalized forces vanish there, ");
    } else {
        w.text("An equilibrium is a point where the generalized forces vanish, ");
    }
    w.latex("$\\partial V / \\partial q_{i} = 0$");
    if (result.lagrangian && result.lagrangian->split) {
        w.text(":");
        std::vector<report_writer::row> rows;
        for (const coordinate& c : scene.coordinates)
            rows.push_back({"\\frac{\\partial V}{\\partial " + report_writer::name(c.name) + "}",
                            print_terms(differentiate(result.lagrangian->potential, c.position), syntax::latex), " = 0"});
        w.display_rows(rows);
    } else {
        w.text(".");
    }
    w.text(e.points.size() == 1 ? "The equilibrium " : "The equilibria ");
    w.text(e.given ? "is" : (e.points.size() == 1 ? "found is" : "found are"));
    w.text(" (stability from the Hessian of V: positive definite means stable):");
    w.latex("\n\\begin{itemize}\n");
    for (std::size_t k = 0; k < e.points.size(); ++k) {
        const equilibrium_point& p = e.points[k];
        std::string position;
        for (std::size_t i = 0; i < p.position.size(); ++i)
            position += (i ? ",\\ " : "") + report_writer::name(scene.coordinates[i].name) + " = " +
                        report_writer::math(p.position[i]);
        w.latex("\\item $" + position + "$: " + to_string(p.kind) +
                (k == e.chosen && result.linearization ? " (the small oscillations below are about this one)" : "") +
                "\n");
    }
    w.latex("\\end{itemize}\n");
}

void write_linearization(report_writer& w)
{
    const linearization_result& l = *w.result().linearization;
    w.latex("\\section{Small oscillations: the matrices T and V}\n");
    w.text("Near the equilibrium, with small displacements ")
        .latex("$\\eta = q - q_{0}$")
        .text(", the Lagrangian is to second order ")
        .latex("$L_{2} = \\frac{1}{2}\\dot{\\eta}^{\\mathsf{T}}\\mathbf{T}\\dot{\\eta} - "
               "\\frac{1}{2}\\eta^{\\mathsf{T}}\\mathbf{V}\\eta$")
        .text(" with")
        .latex("\n\\[\\mathbf{T}_{ij} = \\left.\\frac{\\partial^{2} T}{\\partial \\dot{q}_{i}\\partial "
               "\\dot{q}_{j}}\\right|_{0},\\qquad \\mathbf{V}_{ij} = \\left.\\frac{\\partial^{2} V}{\\partial q_{i}\\partial "
               "q_{j}}\\right|_{0}:\\]\n");
    w.display_rows({{"\\mathbf{T}", {latex_matrix(l.kinetic)}}, {"\\mathbf{V}", {latex_matrix(l.potential)}}});
}

void write_characteristic(report_writer& w)
{
    const analysis& result = w.result();
    const linearization_result& l = *result.linearization;
    const characteristic_result& c = *result.characteristic;
    const std::string omega = report_writer::name(c.omega.get_name());
    const bool gyroscopic = l.has_gyroscopic();
    const std::string pencil = "\\mathbf{V} - " + omega + "^{2}\\mathbf{T}" +
                               (gyroscopic ? " + i" + omega + "\\mathbf{G}" : "");
    w.latex("\\section{The characteristic equation}\n");
    w.text("Solutions ")
        .latex("$\\eta = a\\, e^{-i" + omega + " t}$")
        .text(" exist when ")
        .latex("$(" + pencil + ")\\,a = 0$")
        .text(" has a nonzero solution a, that is when");
    if (gyroscopic)
        w.text(" (with G, ").latex("$\\det(" + pencil + ")$").text(" is real and even in ").latex("$" + omega + "$")
            .text(", as G is antisymmetric)");
    GiNaC::matrix shifted(l.kinetic.rows(), l.kinetic.cols());
    for (unsigned i = 0; i < l.kinetic.rows(); ++i)
        for (unsigned j = 0; j < l.kinetic.cols(); ++j)
            shifted(i, j) = l.potential(i, j) - GiNaC::pow(c.omega, 2) * l.kinetic(i, j) +
                            (gyroscopic ? GiNaC::I * c.omega * l.gyroscopic(i, j) : GiNaC::ex(0));
    std::string matrix = latex_matrix(shifted);
    matrix.replace(0, std::string("\\begin{pmatrix}").size(), "\\begin{vmatrix}");
    matrix.replace(matrix.size() - std::string("\\end{pmatrix}").size(), std::string::npos, "\\end{vmatrix}");
    if (latex_math_width("\\det(" + pencil + ") = " + matrix) <= 70) {
        w.display_terms("\\det(" + pencil + ")", {matrix}, " = 0");
    } else { // too wide for a line: the matrix named D, its entries listed
        w.display_terms("\\det \\mathbf{D}", {"0"});
        w.text("where ").latex("$\\mathbf{D} = " + pencil + "$:");
        w.display_matrix("\\mathbf{D}", shifted);
    }
    w.text("Expanding the determinant (fraction-free elimination) and dividing out the factors common to all "
           "coefficients, with the leading coefficient positive, gives the characteristic polynomial in ")
        .latex("$" + omega + "^{2}$:");
    w.display_terms("", print_terms(c.polynomial, syntax::latex, omega_order(result)), " = 0");
}

void write_modes(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    const modes_result& m = *result.modes;
    const std::string omega = report_writer::name(result.characteristic->omega.get_name());
    const std::string w2 = m.gyroscopic ? omega : omega + "^{2}";
    w.latex("\\section{Frequencies and normal modes}\n");
    if (modes_are_undamped(result)) {
        w.text("These are the small oscillations without the damping (C = 0); the damped motion is in the section "
               "on damping.");
        w.latex("\n");
    }
    if (!m.closed_form) {
        w.text("The characteristic polynomial has no closed-form roots the engine finds; the numeric modes are in "
               "the section on numeric values.");
        w.latex("\n");
        return;
    }
    if (wants(result, product::frequencies) || wants(result, product::modes) || wants(result, product::asymptotic)) {
        w.text("The roots of the characteristic polynomial, in ascending order, are");
        std::vector<report_writer::row> rows;
        for (std::size_t k = 0; k < m.frequencies.size(); ++k)
            rows.push_back({w2 + index(k), print_terms(m.frequencies[k], syntax::latex)});
        w.display_rows(rows);
        if (scene.ratio && !m.frequencies_in_ratio.empty()) {
            w.text("With ").latex("$" + report_writer::name(scene.ratio->name) + " = " +
                                  report_writer::math(scene.ratio->definition) + "$").text(" they read");
            std::vector<report_writer::row> in_ratio;
            for (std::size_t k = 0; k < m.frequencies_in_ratio.size(); ++k)
                in_ratio.push_back({w2 + index(k), print_terms(m.frequencies_in_ratio[k], syntax::latex)});
            w.display_rows(in_ratio);
        }
    }
    if (wants(result, product::modes) && !m.modes.empty()) {
        w.text("For each root, the mode vector ")
            .latex("$a_{k}$")
            .text(" solves ")
            .latex("$(\\mathbf{V} - " + w2 + "_{k}\\mathbf{T})\\,a_{k} = 0$")
            .text("; it is scaled so that its last component is 1. In the order of ")
            .latex("$(" + [&] {
                std::string names;
                for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
                    names += (i ? ", " : "") + report_writer::name(scene.coordinates[i].name);
                return names;
            }() + ")$:");
        std::vector<report_writer::row> rows;
        for (std::size_t k = 0; k < m.modes.size(); ++k)
            rows.push_back({"a" + index(k), {column_latex(m.modes[k])}});
        w.display_rows(rows);
        if (scene.ratio && m.modes_in_ratio.size() == m.modes.size()) {
            w.text("In ").latex("$" + report_writer::name(scene.ratio->name) + "$:");
            std::vector<report_writer::row> in_ratio;
            for (std::size_t k = 0; k < m.modes_in_ratio.size(); ++k)
                in_ratio.push_back({"a" + index(k), {column_latex(m.modes_in_ratio[k])}});
            w.display_rows(in_ratio);
        }
    }
    if (wants(result, product::normal_coordinates) && !m.normal_coordinates.empty()) {
        w.text("With the modes as the columns of A, normalized so that ")
            .latex("$A^{\\mathsf{T}}\\mathbf{T}A = I$")
            .text(", the normal coordinates ")
            .latex("$\\zeta = A^{\\mathsf{T}}\\mathbf{T}\\,\\eta$")
            .text(" each oscillate at one frequency, ")
            .latex("$\\ddot{\\zeta}_{k} + " + w2 + "_{k}\\zeta_{k} = 0$");
        const std::vector<GiNaC::ex>& zeta =
            scene.ratio && m.normal_coordinates_in_ratio.size() == m.normal_coordinates.size()
                ? m.normal_coordinates_in_ratio
                : m.normal_coordinates;
        if (&zeta == &m.normal_coordinates_in_ratio)
            w.text(" (written in ").latex("$" + report_writer::name(scene.ratio->name) + "$").text(")");
        w.text(":");
        std::vector<report_writer::row> rows;
        for (std::size_t k = 0; k < zeta.size(); ++k)
            rows.push_back({"\\zeta" + index(k), print_terms(zeta[k], syntax::latex)});
        w.display_rows(rows);
    }
}

void write_asymptotic(report_writer& w)
{
    const analysis& result = w.result();
    const asymptotic_result& a = *result.asymptotic;
    const model& scene = w.scene();
    const std::string omega = report_writer::name(result.characteristic->omega.get_name());
    w.latex("\\section{Asymptotic limit}\n");
    std::string variable = scene.limit ? report_writer::name(scene.limit->variable) : "";
    std::string to = scene.limit && scene.limit->to_infinity ? "\\infty" : "0";
    w.text("To leading order as ").latex("$" + variable + " \\to " + to + "$").text(", the frequencies behave as");
    std::vector<report_writer::row> rows;
    for (std::size_t k = 0; k < a.frequencies.size(); ++k)
        rows.push_back({omega + "^{2}" + index(k), print_terms(a.frequencies[k], syntax::latex), "", "\\to"});
    w.display_rows(rows);
    if (!a.modes.empty()) {
        w.text("and the mode vectors as");
        std::vector<report_writer::row> modes;
        for (std::size_t k = 0; k < a.modes.size(); ++k)
            modes.push_back({"a" + index(k), {column_latex(a.modes[k])}, "", "\\to"});
        w.display_rows(modes);
    }
    if (a.frequencies.size() == 2)
        w.text("The two frequencies differ by a term that vanishes in the limit: their squares approach each other, "
               "so a motion that starts in one coordinate slowly passes its energy to the other and back (beats).");
    w.latex("\n");
}

void write_numeric(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    w.latex("\\section{Numeric values}\n");
    w.text("At each parameter point the engine evaluates T and V and solves the generalized eigenproblem; each "
           "frequency comes with a bound on its relative error. The columns of A are the mode vectors with ")
        .latex("$A^{\\mathsf{T}}\\mathbf{T}A = I$")
        .text(". An unstable mode (")
        .latex("$\\omega^{2} < 0$")
        .text(") has the imaginary frequency ")
        .latex("$\\omega = i\\gamma$")
        .text(" and grows as ")
        .latex("$e^{\\gamma t}$")
        .text(": it is shown by its growth rate.");
    if (modes_are_undamped(result))
        w.text(" These are the frequencies and modes of the undamped system (C = 0); the damped eigenvalues are in "
               "the section on damping.");
    w.latex("\n");
    for (const numeric_modes& nm : *result.numeric) {
        const std::string at = values_latex(nm);
        w.latex("\\subsection*{At $" + at + "$}\n");
        w.latex("\\begin{center}\n\\renewcommand{\\arraystretch}{1.3}\n\\begin{tabular}{rll}\n\\hline\n$k$ & $\\omega_{k}$ & relative error bound\\\\\n"
                "\\hline\n");
        for (std::size_t k = 0; k < nm.omega.size(); ++k)
            w.latex(std::to_string(k + 1) + " & $" +
                    omega_value_latex(nm, k, [](double x) { return report_writer::number(x); }) + "$ & $\\le " +
                    report_writer::number(nm.error[k], 2) + "$\\\\\n");
        w.latex("\\hline\n\\end{tabular}\n\\end{center}\n");
        write_growth_rates(w, nm);
        w.text("Method: " + nm.method + ". The mode matrix:");
        GiNaC::matrix modes(static_cast<unsigned>(nm.modes.rows()), static_cast<unsigned>(nm.modes.cols()));
        std::string rows = "\\begin{pmatrix}";
        for (Eigen::Index i = 0; i < nm.modes.rows(); ++i) {
            for (Eigen::Index j = 0; j < nm.modes.cols(); ++j)
                rows += (j ? " & " : "") + report_writer::number(nm.modes(i, j), 6);
            rows += i + 1 < nm.modes.rows() ? " \\\\ " : "";
        }
        rows += "\\end{pmatrix}";
        (void)scene;
        w.display_terms("A", {rows});
    }
}

void write_notes(report_writer& w)
{
    w.latex("\\section*{Notes}\n");
    for (const std::string& note : w.result().notes)
        w.latex("\\paragraph{Note.} " + latex_text(note) + "\n");
}

} // namespace

// ---------------------------------------------------------------------------
// report_writer

report_writer::report_writer(const analysis& result, const source_text& source, const report_options& options)
    : result_(result), source_(source), options_(options)
{
}

report_writer& report_writer::text(const std::string& prose)
{
    out_ << latex_text(prose);
    return *this;
}

report_writer& report_writer::latex(const std::string& code)
{
    out_ << code;
    return *this;
}

void report_writer::display(const std::string& lhs, const GiNaC::ex& e, const std::string& rhs,
                            const std::string& relation)
{
    display_terms(lhs, print_terms(e, syntax::latex), rhs, relation);
}

void report_writer::display_terms(const std::string& lhs, const std::vector<std::string>& terms,
                                  const std::string& rhs, const std::string& relation)
{
    display_rows({{lhs, terms, rhs, relation}});
}

void report_writer::display_rows(const std::vector<row>& rows)
{
    // A closed form of thousands of characters (a cubic's roots in many parameters)
    // helps no reader and can exceed what TeX reads in one line: it is named, not printed.
    constexpr std::size_t longest_printed = 3000;
    std::vector<latex_row> shown;
    for (const row& r : rows) {
        std::size_t length = 0;
        for (const std::string& term : r.terms)
            length += term.size();
        if (length <= longest_printed)
            shown.push_back({r.lhs, r.terms, r.rhs, r.relation});
        else
            shown.push_back({r.lhs,
                             {"\\text{(a closed form of " + std::to_string(length) +
                              " characters of \\LaTeX, too long to print)}"},
                             "",
                             r.relation});
    }
    out_ << latex_equations(shown, "\n");
}

void report_writer::display_matrix(const std::string& lhs, const GiNaC::matrix& m)
{
    display_terms(lhs, {latex_matrix(m)});
}

std::string report_writer::name(const std::string& symbol_name) { return print_name(symbol_name, syntax::latex); }

std::string report_writer::math(const GiNaC::ex& e) { return print(e, syntax::latex); }

std::string report_writer::number(double x, int digits) { return latex_number(x, digits); }

bool report_writer::figure(const std::string& name, const std::string& script, double width_cm, double height_cm,
                           const std::string& caption)
{
    if (!options_.plots)
        return false;
    if (gnuplot_state_ == 0)
        gnuplot_state_ = gnuplot_available() ? 1 : -1;
    if (gnuplot_state_ < 0) {
        text("(gnuplot was not found, so this figure is left out.)");
        out_ << "\n";
        return false;
    }
    const std::string size = fixed(width_cm, 2) + "cm," + fixed(height_cm, 2) + "cm";
    // Labels at the body size (11 pt): pdfcairo draws a font of n points at n·fontscale·4/3.
    gnuplot_run run = run_gnuplot("set encoding utf8\nset terminal pdfcairo noenhanced color font 'Sans,11' fontscale 0.75 size " +
                                      size +
                                      "\nset output 'figure.pdf'\n" + script + "unset output\n",
                                  "figure.pdf", {}, {"SOURCE_DATE_EPOCH=0"});
    if (!run.drawn)
        throw computation_error("gnuplot could not draw the figure `" + name + "`" +
                                (run.timed_out ? std::string(" (timed out)") : "") + ": " + run.log.substr(0, 400));
    std::string file = options_.figure_prefix + name;
    figures_.push_back({file + ".pdf", strip_pdf_dates(run.plot)});
    out_ << "\\begin{figure}[!htbp]\n\\centering\n\\includegraphics[width=" << (width_cm >= 16.5 ? "\\linewidth" : "")
         << (width_cm >= 16.5 ? "" : std::to_string(static_cast<int>(width_cm * 10)) + "mm") << "]{" << file
         << "}\n\\caption{" << caption << "}\n\\end{figure}\n";
    return true;
}

report_document report_writer::finish() { return {out_.str(), std::move(figures_)}; }

// ---------------------------------------------------------------------------

const std::vector<report_section>& report_sections()
{
    static const std::vector<report_section> sections = {
        {"title", [](const analysis&) { return true; }, write_title},
        {"coordinates", [](const analysis&) { return true; }, write_coordinates},
        {"lagrangian", [](const analysis& r) { return r.lagrangian.has_value(); }, write_lagrangian},
        {"equations", [](const analysis& r) { return r.equations && r.equations->residuals; }, write_equations},
        {"constraints", [](const analysis& r) { return !r.scene->constraints.empty() && (r.multipliers || r.equations); },
         write_constraints_section},
        {"equilibrium", [](const analysis& r) { return r.equilibria.has_value(); }, write_equilibria},
        {"linearization",
         [](const analysis& r) {
             return r.linearization.has_value() &&
                    (wants(r, product::linearization) || r.characteristic.has_value());
         },
         write_linearization},
        {"gyroscopic", [](const analysis& r) { return r.linearization && r.linearization->has_gyroscopic(); },
         write_gyroscopic_matrix},
        {"characteristic", [](const analysis& r) { return r.characteristic.has_value(); }, write_characteristic},
        {"modes", [](const analysis& r) { return r.modes.has_value(); }, write_modes},
        {"mode shapes",
         [](const analysis& r) {
             return r.modes.has_value() && !r.modes->gyroscopic && wants(r, product::modes) &&
                    r.scene->coordinates.size() >= 2;
         },
         write_mode_figures},
        {"asymptotic", [](const analysis& r) { return r.asymptotic.has_value(); }, write_asymptotic},
        {"numeric",
         [](const analysis& r) {
             return r.numeric.has_value() && !r.linearization->has_gyroscopic() && !r.linearization->circulatory();
         },
         write_numeric},
        {"gyroscopic numeric",
         [](const analysis& r) {
             return r.numeric.has_value() && (r.linearization->has_gyroscopic() || r.linearization->circulatory());
         },
         write_gyroscopic_numeric},
        {"damping",
         [](const analysis& r) {
             if (r.damping)
                 return true;
             if (r.numeric)
                 for (const numeric_modes& n : *r.numeric)
                     if (n.damped)
                         return true;
             return false;
         },
         write_damping_section},
        {"linear system",
         [](const analysis& r) {
             return !r.operating &&
                    ((r.state_space && wants(r, product::state_space)) || (r.transfer && wants(r, product::transfer)));
         },
         write_linear_system_section},
        {"linearization with constraints",
         [](const analysis& r) { return r.operating && r.state_space && wants(r, product::state_space); },
         write_operating_point_section},
        {"floquet", [](const analysis& r) { return r.floquet.has_value(); }, write_floquet_section},
#define LAGRANGE_PRODUCT(id, name, scope, by_default)
#define LAGRANGE_OWN_PRODUCT(id, name, scope, by_default, result)                                           \
    {name, [](const analysis& r) { return r.id.has_value(); }, write_##id##_section},
#include "core/products.inc"
#undef LAGRANGE_OWN_PRODUCT
#undef LAGRANGE_PRODUCT
        {"phase portrait", [](const analysis& r) { return r.phase.has_value(); }, write_phase_section},
        {"symmetries",
         [](const analysis& r) {
             return r.conserved.has_value() || r.hamiltonian.has_value() || r.steady.has_value() ||
                    (r.reduced.has_value() && r.wanted.count(product::reduced));
         },
         write_symmetries_section},
        // Rigid bodies (inertia integrals, Euler's equations) and the simulation
        // (beats, polhode, work-precision) add their section writers here.
        {"bodies",
         [](const analysis& r) { return r.inertia.has_value() || r.euler.has_value() || (r.tops && !r.tops->empty()); },
         write_body_sections},
        {"motion", [](const analysis& r) { return r.simulation.has_value() || r.workprecision.has_value(); },
         write_motion_sections},
        {"notes", [](const analysis& r) { return !r.notes.empty(); }, write_notes},
    };
    return sections;
}

report_document build_report(const analysis& result, const source_text& source, const report_options& options)
{
    report_writer w(result, source, options);
    w.latex("\\documentclass[11pt]{article}\n"
            "\\usepackage[utf8]{inputenc}\n"
            "\\usepackage{amsmath}\n"
            "\\usepackage{amssymb}\n"
            "\\usepackage{graphicx}\n"
            "\\usepackage[margin=2cm]{geometry}\n"
            "\\ifdefined\\pdftrailerid \\pdftrailerid{}\\fi\n"
            "\\ifdefined\\pdfinfoomitdate \\pdfinfoomitdate=1\\fi\n"
            "\\allowdisplaybreaks\n"
            // A page of floats starts at its top (a last figure alone on a page is not centred
            // in it, half a page blank above it), and floats may fill most of a text page.
            "\\makeatletter\\setlength{\\@fptop}{0pt}\\makeatother\n"
            "\\renewcommand{\\topfraction}{0.85}\n\\renewcommand{\\floatpagefraction}{0.6}\n"
            "\\begin{document}\n");
    for (const report_section& section : report_sections())
        if (section.applies(result))
            section.write(w);
    w.latex("\\end{document}\n");
    return w.finish();
}

std::string compile_report(const report_document& document)
{
    std::vector<std::pair<std::string, std::string>> files;
    for (const report_file& f : document.figures)
        files.emplace_back(f.name, f.bytes);
    return compile_latex(document.latex, files);
}

void write_growth_rates(report_writer& w, const numeric_modes& nm)
{
    std::string growth;
    for (std::size_t k = 0; k < nm.omega.size(); ++k)
        growth += growth_sentence_latex(nm, k, [](double x) { return report_writer::number(x); });
    if (!growth.empty())
        w.latex(growth);
}

std::string values_latex(const numeric_modes& point)
{
    std::string at;
    for (std::size_t i = 0; i < point.values.size(); ++i)
        at += (i ? ",\\ " : "") + report_writer::name(point.values[i].first) + " = " +
              report_writer::number(point.values[i].second);
    return at;
}

} // namespace lagrange
