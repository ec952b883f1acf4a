/** @file document.cpp
 *  Text, LaTeX and JSON documents of an analysis. */
#include "output/document.h"

#include "output/latex_blocks.h"
#include "output/bodies.h"
#include "output/floquet_output.h"
#include "output/constraints_output.h"
#include "output/damping_output.h"
#include "output/linear_system_output.h"
#include "output/symmetries_output.h"
#include "output/print.h"
#include "output/simulation_output.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <charconv>
#include <complex>
#include <cstdio>

namespace lagrange {

namespace {

std::string seconds(double s)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6f", s);
    return buffer;
}

std::string join_names(const std::vector<std::string>& names, syntax s, const char* separator)
{
    std::string out;
    for (const std::string& n : names)
        out += (out.empty() ? "" : separator) + print_name(n, s);
    return out;
}

std::vector<std::string> coordinate_names(const model& scene)
{
    std::vector<std::string> names;
    for (const coordinate& c : scene.coordinates)
        names.push_back(c.name);
    return names;
}

std::vector<std::string> parameter_names(const model& scene)
{
    std::vector<std::string> names;
    for (const parameter& p : scene.parameters)
        names.push_back(p.name);
    return names;
}

/// LaTeX special characters in free text (titles, notes); the few non-ASCII
/// characters that messages use become math, any other one a `?`.
std::string latex_escape(const std::string& text)
{
    static const std::vector<std::pair<std::string, std::string>> unicode = {
        {"∂", "$\\partial$"}, {"²", "$^2$"}, {"≤", "$\\le$"}, {"→", "$\\to$"}, {"·", "$\\cdot$"},
        {"−", "$-$"},          {"ω", "$\\omega$"}, {"θ", "$\\theta$"}, {"φ", "$\\phi$"}, {"ρ", "$\\rho$"},
        // more of what scenes' comments and the report's prose use (the homework's bodies, beats)
        {"π", "$\\pi$"}, {"δ", "$\\delta$"}, {"ψ", "$\\psi$"}, {"λ", "$\\lambda$"}, {"α", "$\\alpha$"},
        {"β", "$\\beta$"}, {"γ", "$\\gamma$"}, {"ε", "$\\varepsilon$"}, {"μ", "$\\mu$"}, {"σ", "$\\sigma$"},
        {"τ", "$\\tau$"}, {"ν", "$\\nu$"}, {"ξ", "$\\xi$"}, {"ζ", "$\\zeta$"}, {"η", "$\\eta$"},
        {"κ", "$\\kappa$"}, {"χ", "$\\chi$"}, {"Ω", "$\\Omega$"}, {"Δ", "$\\Delta$"}, {"Θ", "$\\Theta$"},
        {"Φ", "$\\Phi$"}, {"Ψ", "$\\Psi$"}, {"Λ", "$\\Lambda$"}, {"Σ", "$\\Sigma$"}, {"Γ", "$\\Gamma$"},
        {"¹", "$^1$"}, {"³", "$^3$"}, {"⁴", "$^4$"}, {"₀", "$_0$"}, {"₁", "$_1$"}, {"₂", "$_2$"}, {"₃", "$_3$"},
        {"₊", "$_+$"}, {"₋", "$_-$"}, {"ᵀ", "$^T$"}, {"½", "$\\frac12$"}, {"¼", "$\\frac14$"},
        {"–", "--"}, {"—", "---"}, {"±", "$\\pm$"}, {"∓", "$\\mp$"}, {"×", "$\\times$"}, {"≈", "$\\approx$"},
        {"≥", "$\\ge$"}, {"∫", "$\\int$"}, {"√", "$\\surd$"}, {"…", "\\ldots{}"}, {"§", "\\S{}"}};
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (static_cast<unsigned char>(c) >= 0x80) {
            bool known = false;
            for (const auto& [from, to] : unicode)
                if (text.compare(i, from.size(), from) == 0) {
                    out += to;
                    i += from.size() - 1;
                    known = true;
                    break;
                }
            if (!known) {
                out += '?';
                while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80)
                    ++i;
            }
            continue;
        }
        switch (c) {
        case '\\': out += "\\textbackslash{}"; break;
        case '{': case '}': case '$': case '&': case '#': case '_': case '%':
            out += '\\';
            out += c;
            break;
        case '^': out += "\\^{}"; break;
        case '~': out += "\\~{}"; break;
        default: out += c;
        }
    }
    return out;
}

/// A rough width of LaTeX math in characters: a command counts as one, braces,
/// sub/superscript marks and sizing commands as none.
std::size_t latex_width(const std::string& latex)
{
    std::size_t width = 0;
    for (std::size_t i = 0; i < latex.size(); ++i) {
        char c = latex[i];
        if (c == '\\') {
            std::size_t j = i + 1;
            while (j < latex.size() && std::isalpha(static_cast<unsigned char>(latex[j])))
                ++j;
            std::string command = latex.substr(i + 1, j - i - 1);
            if (command != "left" && command != "right" && command != "frac")
                ++width;
            i = j > i + 1 ? j - 1 : j;
        } else if (c != '{' && c != '}' && c != '^' && c != '_' && c != ' ') {
            ++width;
        }
    }
    return width;
}

/// Rows of an align* environment: `lhs &= terms rhs`, broken before a term
/// when the line would grow wider than the page holds.
std::string latex_rows(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs,
                       const std::string& relation = "=")
{
    constexpr std::size_t line_width = 62;
    std::string out = lhs + (lhs.empty() ? "&" : " &" + relation + " ");
    std::size_t width = latex_width(lhs);
    bool first = true;
    for (const std::string& term : terms) {
        std::size_t w = latex_width(term);
        if (!first && width + w > line_width) {
            out += "\\\\\n&\\quad";
            width = 4;
        }
        out += (first ? "" : " ") + term;
        width += w + 1;
        first = false;
    }
    return out + rhs;
}

/// A whole display of `lhs = terms rhs`: an align* broken across lines, or, when
/// a single term is wider than the page, the line scaled down to the page width.
std::string latex_display(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs,
                          const std::string& relation = "=")
{
    constexpr std::size_t line_width = 62;
    std::size_t widest = 0;
    for (const std::string& term : terms)
        widest = std::max(widest, latex_width(term) + (terms.size() == 1 ? latex_width(lhs) : 0));
    if (widest <= line_width)
        return "\\begin{align*}\n" + latex_rows(lhs, terms, rhs, relation) + "\n\\end{align*}\n";
    std::string joined;
    for (const std::string& term : terms)
        joined += (joined.empty() ? "" : " ") + term;
    return "\\[\\resizebox{\\linewidth}{!}{$\\displaystyle " + (lhs.empty() ? "" : lhs + " " + relation + " ") + joined + rhs +
           "$}\\]\n";
}

/// `coordinate = value` pairs of a point, in coordinate order.
std::string position_text(const model& scene, const std::vector<GiNaC::ex>& position, syntax s)
{
    std::string out;
    for (std::size_t i = 0; i < position.size(); ++i)
        out += (i ? ", " : "") + print_name(scene.coordinates[i].name, s) + " = " + print(position[i], s);
    return out;
}

std::string vector_text(const std::vector<GiNaC::ex>& v, syntax s)
{
    std::string out = "(";
    for (std::size_t i = 0; i < v.size(); ++i)
        out += (i ? ", " : "") + print(v[i], s);
    return out + ")";
}

/// An asymptotic ω² in series order: "(1 - √ρ)·g/l" from {g/l, 1, -√ρ}; the leading
/// term alone when there are no corrections.
std::string series_text(const std::vector<GiNaC::ex>& series, syntax s)
{
    if (series.size() <= 2)
        return print(series.at(0), s);
    std::string inner;
    for (std::size_t t = 1; t < series.size(); ++t) {
        std::string term = print(series[t], s);
        if (t == 1)
            inner = term;
        else if (term.rfind('-', 0) == 0)
            inner += " - " + term.substr(1);
        else
            inner += " + " + term;
    }
    if (series[0].is_equal(1))
        return inner;
    std::string times = s == syntax::text ? "·" : s == syntax::latex ? " " : "*";
    return "(" + inner + ")" + times + print(series[0], s);
}

/// A normal coordinate ζ = scale·(q1 + c2·q2 + …) as "scale·(q1 + c2·q2 + …)": the
/// factor without coordinates first, the combination in coordinate order with its
/// first coefficient positive (a sign goes to the front).
std::string normal_coordinate_text(const GiNaC::ex& zeta, const model& scene, syntax s)
{
    term_order order;
    for (const coordinate& c : scene.coordinates)
        order.groups.push_back({c.position});
    auto has_coordinate = [&](const GiNaC::ex& e) {
        for (const coordinate& c : scene.coordinates)
            if (e.has(c.position))
                return true;
        return false;
    };
    if (!GiNaC::is_a<GiNaC::mul>(zeta))
        return print(zeta, s, order);
    GiNaC::ex scale = 1, combination = 1;
    for (const GiNaC::ex& factor : zeta)
        (has_coordinate(factor) ? combination : scale) *= factor;
    if (!GiNaC::is_a<GiNaC::add>(combination) || scale.is_equal(1))
        return print(zeta, s, order);
    // The sign: the one of ±combination that prints without a leading minus (the
    // shorter, then the smaller, if both or neither do). GiNaC may hold the sign
    // inside or outside the sum from run to run; this choice does not depend on it.
    std::string plus = print(combination, s, order), minus = print(-combination, s, order);
    bool plus_negative = plus.rfind('-', 0) == 0, minus_negative = minus.rfind('-', 0) == 0;
    bool flip = plus_negative != minus_negative
                    ? plus_negative
                    : (minus.size() != plus.size() ? minus.size() < plus.size() : minus < plus);
    if (flip)
        scale = -scale;
    std::string times = s == syntax::text ? "·" : s == syntax::latex ? " " : "*";
    std::string inner = "(" + (flip ? minus : plus) + ")";
    if (scale.is_equal(-1))
        return "-" + inner;
    return print(scale, s) + times + inner;
}

std::string matrix_latex(const GiNaC::matrix& m)
{
    std::string out = "\\begin{pmatrix}";
    for (unsigned i = 0; i < m.rows(); ++i) {
        for (unsigned j = 0; j < m.cols(); ++j)
            out += (j ? " & " : "") + print(m(i, j), syntax::latex);
        out += i + 1 < m.rows() ? " \\\\ " : "";
    }
    return out + "\\end{pmatrix}";
}


/// A complex mode component as a + bi (b omitted when 0).
std::string complex_text(std::complex<double> z)
{
    double re = z.real() == 0 ? 0.0 : z.real(); // no −0
    if (z.imag() == 0)
        return round_trip(re);
    return round_trip(re) + (z.imag() < 0 ? " - " : " + ") + round_trip(std::abs(z.imag())) + "i";
}

} // namespace

namespace {

void write_oscillations_text(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax s = syntax::text;
    if (result.equilibria) {
        out << "\nEquilibria\n";
        for (std::size_t k = 0; k < result.equilibria->points.size(); ++k) {
            const equilibrium_point& p = result.equilibria->points[k];
            out << "  " << position_text(scene, p.position, s) << ": " << to_string(p.kind)
                << (k == result.equilibria->chosen && result.linearization ? "  (linearized about)" : "") << '\n';
        }
    }
    if (result.linearization) {
        const linearization_result& l = *result.linearization;
        out << "\nLinearization\n";
        std::vector<const char*> matrices{"T", "V"};
        if (l.has_gyroscopic())
            matrices.push_back("G");
        for (const char* which : matrices) {
            const GiNaC::matrix& m = std::string(which) == "T" ? l.kinetic
                                     : std::string(which) == "V" ? l.potential
                                                                 : l.gyroscopic;
            out << "  " << which << " =";
            for (unsigned i = 0; i < m.rows(); ++i) {
                out << (i ? "      " : " ") << "[";
                for (unsigned j = 0; j < m.cols(); ++j)
                    out << (j ? ", " : "") << print(m(i, j), s);
                out << "]\n";
            }
        }
    }
    if (result.characteristic)
        out << "\nCharacteristic polynomial\n  " << print(result.characteristic->polynomial, s, omega_order(result))
            << " = 0\n";
    if (result.modes) {
        const modes_result& m = *result.modes;
        if (!m.closed_form) {
            out << "\nNormal modes\n  no closed form found (see the numeric modes)\n";
        } else {
            std::string w2 = print_name(result.characteristic->omega.get_name(), s) + (m.gyroscopic ? "" : "²");
            out << "\nNormal modes" << (modes_are_undamped(result) ? " (of the undamped system, C = 0)" : "") << '\n';
            for (std::size_t k = 0; k < m.frequencies.size(); ++k) {
                out << "  " << w2 << " = " << print(m.frequencies[k], s) << '\n';
                if (k < m.modes.size())
                    out << "    mode " << vector_text(m.modes[k], s) << '\n';
                if (k < m.normal_coordinates.size())
                    out << "    ζ = " << normal_coordinate_text(m.normal_coordinates[k], scene, s) << '\n';
            }
            if (scene.ratio && !m.frequencies_in_ratio.empty()) {
                out << "  with " << print_name(scene.ratio->name, s) << " = " << print(scene.ratio->definition, s)
                    << ":\n";
                for (std::size_t k = 0; k < m.frequencies_in_ratio.size(); ++k) {
                    out << "    " << w2 << " = " << print(m.frequencies_in_ratio[k], s) << '\n';
                    if (k < m.modes_in_ratio.size())
                        out << "      mode " << vector_text(m.modes_in_ratio[k], s) << '\n';
                    if (k < m.normal_coordinates_in_ratio.size())
                        out << "      ζ = " << normal_coordinate_text(m.normal_coordinates_in_ratio[k], scene, s)
                            << '\n';
                }
            }
        }
    }
    if (result.asymptotic) {
        const asymptotic_result& a = *result.asymptotic;
        out << "\nAsymptotic (" << a.label << ")\n";
        for (std::size_t k = 0; k < a.frequencies.size(); ++k) {
            out << "  " << print_name(result.characteristic->omega.get_name(), s) << "² → "
                << (k < a.frequency_series.size() ? series_text(a.frequency_series[k], s) : print(a.frequencies[k], s));
            if (k < a.modes.size())
                out << ",  mode " << vector_text(a.modes[k], s);
            out << '\n';
            if (k < a.normal_coordinates.size())
                out << "    ζ → " << normal_coordinate_text(a.normal_coordinates[k], scene, s) << '\n';
        }
        for (const beat& b : a.beats)
            out << "  beats of modes " << b.lower + 1 << " and " << b.upper + 1 << ": ω" << b.upper + 1 << " - ω"
                << b.lower + 1 << " → " << print(b.difference, s) << ",  period 2π/(ω" << b.upper + 1 << " - ω"
                << b.lower + 1 << ") → " << print(b.period, s) << '\n';
    }
    if (result.numeric) {
        out << "\nNumeric modes" << (modes_are_undamped(result) ? " (ω and modes of the undamped system, C = 0)" : "")
            << '\n';
        for (const numeric_modes& n : *result.numeric) {
            out << "  at";
            for (const auto& [name, value] : n.values)
                out << ' ' << print_name(name, s) << " = " << round_trip(value);
            out << "  (" << n.method << ")\n";
            if (!n.stability.empty() && !n.damped)
                out << "    " << n.stability << '\n';
            for (std::size_t k = 0; k < n.omega.size(); ++k) {
                out << "    ω = " << round_trip(n.omega[k]) << "  (relative error ≤ " << round_trip(n.error[k])
                    << ")  mode (";
                for (Eigen::Index i = 0; i < n.modes.rows(); ++i)
                    out << (i ? ", " : "") << round_trip(n.modes(i, static_cast<Eigen::Index>(k)));
                for (Eigen::Index i = 0; i < n.complex_modes.rows(); ++i)
                    out << (i ? ", " : "") << complex_text(n.complex_modes(i, static_cast<Eigen::Index>(k)));
                out << ")\n";
            }
            if (n.damped)
                write_damped_eigenvalues_text(out, n);
        }
    }
}

} // namespace

void write_text(std::ostream& out, const analysis& result, const document_options& options)
{
    const model& scene = *result.scene;
    if (!scene.title.empty())
        out << scene.title << "\n\n";
    out << "coordinates: " << join_names(coordinate_names(scene), syntax::text, ", ") << '\n';
    out << "parameters:  " << join_names(parameter_names(scene), syntax::text, ", ") << '\n';
    if (result.lagrangian) {
        const lagrangian_result& l = *result.lagrangian;
        out << "\nLagrangian\n";
        if (l.split) {
            out << "  T = " << print(l.kinetic, syntax::text, velocity_order(scene)) << '\n';
            if (!l.gyroscopic.is_zero())
                out << "  L1 = " << print(l.gyroscopic, syntax::text, velocity_order(scene)) << '\n';
            out << "  V = " << print(l.potential, syntax::text) << '\n';
        }
        out << "  L = " << print(l.lagrangian, syntax::text, velocity_order(scene)) << '\n';
    }
    if (result.equations && result.equations->residuals) {
        out << "\nEquations of motion\n";
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            out << "  " << print_name(scene.coordinates[i].name, syntax::text) << ":  "
                << print((*result.equations->residuals)[i], syntax::text, equation_order(scene)) << " = 0\n";
    }
    write_constraints_text(out, result);
    write_oscillations_text(out, result);
    write_floquet_text(out, result);
    if (result.damping)
        write_damping_text(out, scene, *result.damping);
    write_linear_system_text(out, result);
    write_symmetries_text(out, result);
    write_bodies_text(out, result);
    if (result.simulation)
        write_simulation_text(out, *result.simulation, options.timings);
    if (result.workprecision)
        write_workprecision_text(out, *result.workprecision);
    for (const std::string& note : result.notes)
        out << "\nnote: " << note << '\n';
    if (options.timings) {
        out << "\nStages\n";
        for (const stage_time& s : result.stages)
            out << "  " << s.stage << ": " << seconds(s.seconds) << " s\n";
    }
}

namespace {

void write_oscillations_latex(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax s = syntax::latex;
    if (result.equilibria) {
        out << "\\subsection*{Equilibria}\n\\begin{itemize}\n";
        for (const equilibrium_point& p : result.equilibria->points)
            out << "\\item $" << position_text(scene, p.position, s) << "$: " << to_string(p.kind) << "\n";
        out << "\\end{itemize}\n";
    }
    if (result.linearization)
        out << "\\subsection*{Linearization}\n\\begin{align*}\nT &= " << matrix_latex(result.linearization->kinetic)
            << ", & V &= " << matrix_latex(result.linearization->potential)
            << (result.linearization->has_gyroscopic() ? ", & G &= " + matrix_latex(result.linearization->gyroscopic)
                                                       : std::string())
            << "\n\\end{align*}\n";
    if (result.characteristic)
        out << "\\subsection*{Characteristic polynomial}\n"
            << latex_display("", print_terms(result.characteristic->polynomial, s, omega_order(result)), " = 0");
    std::string w2 = print_name(result.characteristic ? result.characteristic->omega.get_name() : "omega", s) + "^{2}";
    auto index = [](std::size_t k) { return "_{" + std::to_string(k + 1) + "}"; };
    if (result.modes && result.modes->closed_form) {
        const modes_result& m = *result.modes;
        if (m.gyroscopic)
            w2 = print_name(result.characteristic->omega.get_name(), s);
        out << "\\subsection*{Normal modes}\n";
        if (modes_are_undamped(result))
            out << "These are the modes of the undamped system ($C = 0$); the damping is below.\n\n";
        for (std::size_t k = 0; k < m.frequencies.size(); ++k) {
            out << latex_display(w2 + index(k), print_terms(m.frequencies[k], s), "");
            if (k < m.modes.size())
                out << latex_display("a" + index(k), {vector_text(m.modes[k], s)}, "");
        }
        for (std::size_t k = 0; k < m.normal_coordinates.size(); ++k)
            out << latex_display("\\zeta" + index(k), {normal_coordinate_text(m.normal_coordinates[k], scene, s)}, "");
        if (scene.ratio && !m.frequencies_in_ratio.empty()) {
            out << "With $" << print_name(scene.ratio->name, s) << " = " << print(scene.ratio->definition, s) << "$:\n";
            for (std::size_t k = 0; k < m.frequencies_in_ratio.size(); ++k)
                out << latex_display(w2 + index(k), print_terms(m.frequencies_in_ratio[k], s), "");
        }
    }
    if (result.asymptotic) {
        const asymptotic_result& a = *result.asymptotic;
        out << "\\subsection*{Asymptotic behaviour}\n";
        for (std::size_t k = 0; k < a.frequencies.size(); ++k)
            out << latex_display(w2 + index(k),
                                 k < a.frequency_series.size() ? std::vector<std::string>{series_text(a.frequency_series[k], s)}
                                                               : print_terms(a.frequencies[k], s),
                                 "", "\\to");
        for (std::size_t k = 0; k < a.normal_coordinates.size(); ++k)
            out << latex_display("\\zeta" + index(k), {normal_coordinate_text(a.normal_coordinates[k], scene, s)}, "",
                                 "\\to");
        for (const beat& b : a.beats) {
            std::string pair = "\\omega" + index(b.upper) + " - \\omega" + index(b.lower);
            out << latex_display(pair, {print(b.difference, s)}, "", "\\to")
                << latex_display("\\frac{2\\pi}{" + pair + "}", {print(b.period, s)}, "", "\\to");
        }
    }
    if (result.numeric) {
        out << "\\subsection*{Numeric modes}\n";
        if (modes_are_undamped(result))
            out << "The frequencies $\\omega$ are those of the undamped system ($C = 0$).\n\n";
        for (const numeric_modes& n : *result.numeric) {
            out << "\\noindent At $";
            for (std::size_t i = 0; i < n.values.size(); ++i)
                out << (i ? ",\\ " : "") << print_name(n.values[i].first, s) << " = "
                    << print(GiNaC::numeric(n.values[i].second), s);
            out << "$" << (n.stability.empty() || n.damped ? "" : " (" + n.stability + ")") << ":\n\\begin{align*}\n";
            for (std::size_t k = 0; k < n.omega.size(); ++k)
                out << "\\omega_{" << k + 1 << "} &= " << print(GiNaC::numeric(n.omega[k]), s)
                    << " & \\text{(relative error} &\\le " << print(GiNaC::numeric(n.error[k]), s) << ")"
                    << (k + 1 < n.omega.size() ? "\\\\\n" : "\n");
            out << "\\end{align*}\n";
            if (n.damped)
                write_damped_eigenvalues_latex(out, n);
        }
    }
    for (const std::string& note : result.notes)
        out << "\\paragraph{Note.} " << latex_escape(note) << "\n";
}

} // namespace

void write_latex(std::ostream& out, const analysis& result, const document_options& options)
{
    const model& scene = *result.scene;
    out << "\\documentclass[11pt]{article}\n"
           "\\usepackage[utf8]{inputenc}\n"
           "\\usepackage{amsmath}\n"
           "\\usepackage{graphicx}\n"
           "\\usepackage[margin=2cm]{geometry}\n"
           "\\begin{document}\n";
    out << "\\section*{" << latex_escape(scene.title.empty() ? "Scene" : scene.title) << "}\n";
    if (!scene.coordinates.empty()) // a free body's scene has none
        out << "Coordinates: $" << join_names(coordinate_names(scene), syntax::latex, ",\\ ") << "$.\\\\\n";
    out << "Parameters: $" << join_names(parameter_names(scene), syntax::latex, ",\\ ") << "$.\n";
    if (result.lagrangian) {
        const lagrangian_result& l = *result.lagrangian;
        out << "\\subsection*{Lagrangian}\n";
        if (l.split) {
            out << latex_display("T", print_terms(l.kinetic, syntax::latex, velocity_order(scene)), "");
            if (!l.gyroscopic.is_zero())
                out << latex_display("L_1", print_terms(l.gyroscopic, syntax::latex, velocity_order(scene)), "");
            out << latex_display("V", print_terms(l.potential, syntax::latex), "");
        }
        out << latex_display("L", print_terms(l.lagrangian, syntax::latex, velocity_order(scene)), "");
    }
    if (result.equations && result.equations->residuals) {
        out << "\\subsection*{Equations of motion}\n";
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            out << latex_display("", print_terms((*result.equations->residuals)[i], syntax::latex, equation_order(scene)), " = 0");
    }
    write_constraints_latex(out, result);
    write_oscillations_latex(out, result);
    write_floquet_latex(out, result);
    if (result.damping)
        write_damping_latex(out, scene, *result.damping);
    write_linear_system_latex(out, result);
    write_symmetries_latex(out, result);
    write_bodies_latex(out, result);
    if (result.simulation)
        write_simulation_latex(out, *result.simulation, options.timings);
    if (result.workprecision)
        write_workprecision_latex(out, *result.workprecision);
    if (options.timings) {
        out << "\\subsection*{Stages}\n\\begin{tabular}{lr}\n";
        for (const stage_time& s : result.stages)
            out << latex_escape(s.stage) << " & " << seconds(s.seconds) << " s\\\\\n";
        out << "\\end{tabular}\n";
    }
    out << "\\end{document}\n";
}

namespace {

nlohmann::ordered_json matrix_json(const GiNaC::matrix& m)
{
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (unsigned i = 0; i < m.rows(); ++i) {
        nlohmann::ordered_json row = nlohmann::ordered_json::array();
        for (unsigned j = 0; j < m.cols(); ++j)
            row.push_back(print(m(i, j), syntax::plain));
        rows.push_back(row);
    }
    return rows;
}

nlohmann::ordered_json strings_json(const std::vector<GiNaC::ex>& v)
{
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const GiNaC::ex& e : v)
        list.push_back(print(e, syntax::plain));
    return list;
}

nlohmann::ordered_json vectors_json(const std::vector<std::vector<GiNaC::ex>>& vectors)
{
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& v : vectors)
        list.push_back(strings_json(v));
    return list;
}

void write_oscillations_json(nlohmann::ordered_json& doc, const analysis& result)
{
    const model& scene = *result.scene;
    if (result.equilibria) {
        const equilibria_result& e = *result.equilibria;
        auto position_json = [&](const equilibrium_point& p) {
            nlohmann::ordered_json position = nlohmann::ordered_json::object();
            for (std::size_t i = 0; i < p.position.size(); ++i)
                position[scene.coordinates[i].name] = print(p.position[i], syntax::plain);
            return position;
        };
        const equilibrium_point& chosen = e.points.at(e.chosen);
        doc["equilibrium"] = position_json(chosen);
        doc["stability"] = to_string(chosen.kind);
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const equilibrium_point& p : e.points)
            all.push_back({{"position", position_json(p)}, {"stability", to_string(p.kind)}});
        doc["equilibria"] = all;
    }
    if (result.linearization) {
        doc["T"] = matrix_json(result.linearization->kinetic);
        doc["V"] = matrix_json(result.linearization->potential);
        if (result.linearization->has_gyroscopic())
            doc["gyroscopic"] = matrix_json(result.linearization->gyroscopic);
    }
    if (result.characteristic)
        doc["characteristic"] = {{"variable", result.characteristic->omega.get_name()},
                                 {"polynomial", print(result.characteristic->polynomial, syntax::plain,
                                                      omega_order(result))}};
    if (result.modes && result.modes->closed_form) {
        const modes_result& m = *result.modes;
        const std::set<product>& w = result.wanted;
        if (w.count(product::frequencies) || w.count(product::asymptotic))
            doc["frequencies"] = strings_json(m.frequencies);
        if (w.count(product::modes))
            doc["modes"] = vectors_json(m.modes);
        if (w.count(product::normal_coordinates))
            doc["normal_coordinates"] = strings_json(m.normal_coordinates);
        if (scene.ratio && !m.frequencies_in_ratio.empty())
            doc["ratio"] = {{"name", scene.ratio->name},
                            {"definition", print(scene.ratio->definition, syntax::plain)},
                            {"frequencies", strings_json(m.frequencies_in_ratio)},
                            {"modes", vectors_json(m.modes_in_ratio)}};
    }
    if (result.asymptotic)
        doc["asymptotic"] = {{result.asymptotic->label,
                              {{"frequencies", strings_json(result.asymptotic->frequencies)},
                               {"modes", vectors_json(result.asymptotic->modes)}}}};
    if (result.asymptotic) {
        nlohmann::ordered_json& limit = doc["asymptotic"][result.asymptotic->label];
        limit["normal_coordinates"] = strings_json(result.asymptotic->normal_coordinates);
        nlohmann::ordered_json beats = nlohmann::ordered_json::array();
        for (const beat& b : result.asymptotic->beats)
            beats.push_back({{"modes", {b.lower + 1, b.upper + 1}},
                             {"difference", print(b.difference, syntax::plain)},
                             {"period", print(b.period, syntax::plain)}});
        limit["beats"] = beats;
    }
    if (result.numeric) {
        nlohmann::ordered_json points = nlohmann::ordered_json::array();
        for (const numeric_modes& n : *result.numeric) {
            nlohmann::ordered_json values = nlohmann::ordered_json::object();
            for (const auto& [name, value] : n.values)
                values[name] = value;
            nlohmann::ordered_json modes = nlohmann::ordered_json::array();
            for (Eigen::Index k = 0; k < n.modes.cols(); ++k) {
                nlohmann::ordered_json column = nlohmann::ordered_json::array();
                for (Eigen::Index i = 0; i < n.modes.rows(); ++i)
                    column.push_back(n.modes(i, k));
                modes.push_back(column);
            }
            for (Eigen::Index k = 0; k < n.complex_modes.cols(); ++k) {
                nlohmann::ordered_json column = nlohmann::ordered_json::array();
                for (Eigen::Index i = 0; i < n.complex_modes.rows(); ++i)
                    column.push_back({n.complex_modes(i, k).real(), n.complex_modes(i, k).imag()});
                modes.push_back(column);
            }
            points.push_back({{"values", values}, {"omega", n.omega}, {"modes", modes},
                              {"error", n.error}, {"method", n.method}});
            if (!n.eigenvalues.empty()) {
                nlohmann::ordered_json eigenvalues = nlohmann::ordered_json::array();
                for (const std::complex<double>& e : n.eigenvalues)
                    eigenvalues.push_back({e.real(), e.imag()});
                points.back()["eigenvalues"] = eigenvalues;
                points.back()["stability"] = n.stability;
                if (n.damped)
                    write_damped_eigenvalues_json(points.back(), n);
            }
        }
        doc["numeric"] = points;
    }
}

} // namespace

void write_json(std::ostream& out, const analysis& result, const document_options& options)
{
    const model& scene = *result.scene;
    nlohmann::ordered_json doc;
    doc["scene"] = scene.title;
    doc["coordinates"] = coordinate_names(scene);
    doc["parameters"] = parameter_names(scene);
    doc["stages"] = nlohmann::json::array();
    for (const stage_time& s : result.stages)
        doc["stages"].push_back(s.stage);
    if (options.timings) {
        nlohmann::ordered_json timings = nlohmann::ordered_json::object();
        for (const stage_time& s : result.stages)
            timings[s.stage] = s.seconds;
        doc["timings"] = timings;
    }
    if (result.lagrangian) {
        const lagrangian_result& l = *result.lagrangian;
        doc["lagrangian"] = print(l.lagrangian, syntax::plain, velocity_order(scene));
        if (l.split) {
            doc["kinetic_energy"] = print(l.kinetic, syntax::plain, velocity_order(scene));
            doc["potential_energy"] = print(l.potential, syntax::plain);
        }
    }
    if (result.equations && result.equations->residuals) {
        doc["equations"] = nlohmann::json::array();
        for (const GiNaC::ex& e : *result.equations->residuals)
            doc["equations"].push_back(print(e, syntax::plain, equation_order(scene)));
    }
    write_constraints_json(doc, result);
    write_oscillations_json(doc, result);
    write_floquet_json(doc, result);
    if (result.damping)
        write_damping_json(doc, scene, *result.damping);
    write_linear_system_json(doc, result);
    write_symmetries_json(doc, result);
    write_bodies_json(doc, result);
    if (result.simulation)
        doc["simulation"] = simulation_json(*result.simulation, options.timings);
    if (result.workprecision)
        doc["workprecision"] = workprecision_json(*result.workprecision);
    if (result.verification && !result.verification->entries.empty()) {
        nlohmann::ordered_json checks = nlohmann::ordered_json::object();
        for (const verification_entry& entry : result.verification->entries)
            checks[entry.item] = entry.how;
        doc["verification"] = checks;
    }
    if (!result.notes.empty())
        doc["notes"] = result.notes;
    out << doc.dump(2) << '\n';
}

// The building blocks above, shared with the report (lib/output/report.cpp).
term_order velocity_order(const model& scene)
{
    term_order order;
    order.groups.emplace_back();
    for (const coordinate& c : scene.coordinates)
        order.groups.back().push_back(c.velocity);
    return order;
}

term_order equation_order(const model& scene)
{
    term_order order;
    order.groups.emplace_back();
    for (const coordinate& c : scene.coordinates)
        order.groups.back().push_back(c.acceleration);
    order.groups.push_back(velocity_order(scene).groups[0]);
    return order;
}

term_order omega_order(const analysis& result)
{
    term_order order;
    if (result.characteristic)
        order.groups.push_back({result.characteristic->omega});
    return order;
}

std::string latex_text(const std::string& text) { return latex_escape(text); }
std::size_t latex_math_width(const std::string& latex) { return latex_width(latex); }
std::string latex_equation(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs,
                           const std::string& relation)
{
    return latex_display(lhs, terms, rhs, relation);
}
std::string latex_matrix(const GiNaC::matrix& m) { return matrix_latex(m); }

} // namespace lagrange
