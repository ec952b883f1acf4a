// SPDX-License-Identifier: GPL-2.0-or-later
/** @file oscillations.cpp
 *  The small-oscillations family in text, LaTeX and JSON (see oscillations.h).
 *
 *  The report's sections on a Lagrangian with a part linear in the velocities: the
 *  gyroscopic matrix G and the Kelvin–Tait–Chetaev verdict, and the numeric values from
 *  the quadratic eigenproblem with their complex modes. */
#include "output/oscillations.h"

#include "core/number_text.h"
#include "output/damping.h"
#include "output/format.h"
#include "output/latex_blocks.h"
#include "output/mode_frequency.h"
#include "output/print.h"
#include "output/report_sections.h"

#include <complex>
#include <set>
#include <string>

namespace lagrange {

namespace {

/// Parentheses that grow with what they hold in LaTeX (a fraction, a square root).
std::string open_parenthesis(syntax s) { return s == syntax::latex ? "\\left(" : "("; }
std::string close_parenthesis(syntax s) { return s == syntax::latex ? "\\right)" : ")"; }

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
    std::string out = s == syntax::latex ? "\\left(" : "(";
    for (std::size_t i = 0; i < v.size(); ++i)
        out += (i ? ", " : "") + print(v[i], s);
    return out + (s == syntax::latex ? "\\right)" : ")");
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
    return open_parenthesis(s) + inner + close_parenthesis(s) + times + print(series[0], s);
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
    std::string inner = open_parenthesis(s) + (flip ? minus : plus) + close_parenthesis(s);
    if (scale.is_equal(-1))
        return "-" + inner;
    return print(scale, s) + times + inner;
}



/// A complex mode component as a + bi (b omitted when 0).
std::string complex_text(std::complex<double> z)
{
    return complex_number(z, round_trip, "i");
}

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

/// G is shown where it is not zero, and where `gyroscopic` is asked for (then also G = 0).
bool shows_gyroscopic(const analysis& result)
{
    const linearization_result& l = *result.linearization;
    return l.has_gyroscopic() || (result.wanted.count(product::gyroscopic) && l.gyroscopic.rows() == l.kinetic.rows() &&
                                  l.gyroscopic.cols() == l.kinetic.cols());
}

/// A set of equilibria in words: its relation, V on it, and its stability across it.
std::string family_text(const equilibrium_family& family, syntax s)
{
    const bool latex = s == syntax::latex;
    const std::string math = latex ? "$" : "";
    return std::string(family.dimension == 1 ? "a curve" : "a set of dimension " + std::to_string(family.dimension)) +
           " of equilibria, " + math + print(family.relation, s) + " = 0" + math + ", where " + math + "V = " +
           print(family.potential, s) + math + " is " + (family.across > 0 ? "least" : "greatest") + ": " +
           (family.across > 0 ? "stable" : "unstable") + " across it, neutral along it";
}

} // namespace

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
        if (result.equilibria->family)
            out << "  " << family_text(*result.equilibria->family, s) << '\n';
    }
    if (result.linearization) {
        const linearization_result& l = *result.linearization;
        out << "\nLinearization\n";
        std::vector<const char*> matrices{"T", "V"};
        if (shows_gyroscopic(result))
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
                out << "    " << mode_frequency_text(n, k) << "  (relative error ≤ " << round_trip(n.error[k])
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

void write_oscillations_latex(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax s = syntax::latex;
    if (result.equilibria) {
        out << "\\subsection*{Equilibria}\n\\begin{itemize}\n";
        for (const equilibrium_point& p : result.equilibria->points)
            out << "\\item $" << position_text(scene, p.position, s) << "$: " << to_string(p.kind) << "\n";
        if (result.equilibria->family)
            out << "\\item " << family_text(*result.equilibria->family, s) << "\n";
        out << "\\end{itemize}\n";
    }
    if (result.linearization) {
        // T and V (and G) side by side when they fit on a line, else one below the other.
        const linearization_result& l = *result.linearization;
        std::vector<latex_row> rows{{"T", {latex_matrix(l.kinetic)}}, {"V", {latex_matrix(l.potential)}}};
        if (shows_gyroscopic(result))
            rows.push_back({"G", {latex_matrix(l.gyroscopic)}});
        std::string side_by_side;
        for (const latex_row& r : rows)
            side_by_side += (side_by_side.empty() ? "" : ", & ") + r.lhs + " &= " + r.terms[0];
        out << "\\subsection*{Linearization}\n";
        if (latex_math_width(side_by_side) <= 50) // align*'s gap between the pairs is wide
            out << "\\begin{align*}\n" << side_by_side << "\n\\end{align*}\n";
        else
            out << latex_equations(rows);
    }
    if (result.characteristic)
        out << "\\subsection*{Characteristic polynomial}\n"
            << latex_equation("", print_terms(result.characteristic->polynomial, s, omega_order(result)), " = 0");
    std::string w2 = print_name(result.characteristic ? result.characteristic->omega.get_name() : "omega", s) + "^{2}";
    auto index = [](std::size_t k) { return "_{" + std::to_string(k + 1) + "}"; };
    if (result.modes && result.modes->closed_form) {
        const modes_result& m = *result.modes;
        if (m.gyroscopic)
            w2 = print_name(result.characteristic->omega.get_name(), s);
        out << "\\subsection*{Normal modes}\n";
        if (modes_are_undamped(result))
            out << "These are the modes of the undamped system ($C = 0$); the damping is below.\n\n";
        std::vector<latex_row> rows;
        for (std::size_t k = 0; k < m.frequencies.size(); ++k) {
            rows.push_back({w2 + index(k), print_terms(m.frequencies[k], s)});
            if (k < m.modes.size())
                rows.push_back({"a" + index(k), {vector_text(m.modes[k], s)}});
        }
        for (std::size_t k = 0; k < m.normal_coordinates.size(); ++k)
            rows.push_back({"\\zeta" + index(k), {normal_coordinate_text(m.normal_coordinates[k], scene, s)}});
        out << latex_equations(rows);
        if (scene.ratio && !m.frequencies_in_ratio.empty()) {
            out << "With $" << print_name(scene.ratio->name, s) << " = " << print(scene.ratio->definition, s) << "$:\n";
            std::vector<latex_row> in_ratio;
            for (std::size_t k = 0; k < m.frequencies_in_ratio.size(); ++k)
                in_ratio.push_back({w2 + index(k), print_terms(m.frequencies_in_ratio[k], s)});
            out << latex_equations(in_ratio);
        }
    }
    if (result.asymptotic) {
        const asymptotic_result& a = *result.asymptotic;
        out << "\\subsection*{Asymptotic behaviour}\n";
        std::vector<latex_row> rows;
        for (std::size_t k = 0; k < a.frequencies.size(); ++k)
            rows.push_back({w2 + index(k),
                            k < a.frequency_series.size() ? std::vector<std::string>{series_text(a.frequency_series[k], s)}
                                                          : print_terms(a.frequencies[k], s),
                            "", "\\to"});
        for (std::size_t k = 0; k < a.normal_coordinates.size(); ++k)
            rows.push_back({"\\zeta" + index(k), {normal_coordinate_text(a.normal_coordinates[k], scene, s)}, "", "\\to"});
        for (const beat& b : a.beats) {
            std::string pair = "\\omega" + index(b.upper) + " - \\omega" + index(b.lower);
            rows.push_back({pair, {print(b.difference, s)}, "", "\\to"});
            rows.push_back({"\\frac{2\\pi}{" + pair + "}", {print(b.period, s)}, "", "\\to"});
        }
        out << latex_equations(rows);
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
                out << "\\omega_{" << k + 1 << "} &= "
                    << omega_value_latex(n, k, [&](double x) { return print(GiNaC::numeric(x), s); })
                    << " & \\text{(relative error} &\\le " << print(GiNaC::numeric(n.error[k]), s) << ")"
                    << (k + 1 < n.omega.size() ? "\\\\\n" : "\n");
            out << "\\end{align*}\n";
            // The mode vectors, as the text output lists them: the columns of A, AᵀTA = I.
            if (n.modes.size() > 0) {
                out << "with the mode vectors (the columns of $A$, $A^{\\mathsf{T}}\\mathbf{T}A = I$)\n\\begin{align*}\n";
                for (Eigen::Index k = 0; k < n.modes.cols(); ++k) {
                    out << "a_{" << k + 1 << "} &= \\begin{pmatrix}";
                    for (Eigen::Index i = 0; i < n.modes.rows(); ++i)
                        out << (i ? " \\\\ " : "") << latex_exponent(round_trip(n.modes(i, k)));
                    out << "\\end{pmatrix}" << (k + 1 < n.modes.cols() ? ",\\\\\n" : "\n");
                }
                out << "\\end{align*}\n";
            }
            std::string growth;
            for (std::size_t k = 0; k < n.omega.size(); ++k)
                growth += growth_sentence_latex(n, k, [&](double x) { return print(GiNaC::numeric(x), s); });
            if (!growth.empty())
                out << growth.substr(0, growth.size() - 1) << "\n\n";
            if (n.damped)
                write_damped_eigenvalues_latex(out, n);
        }
    }
    for (const std::string& note : result.notes)
        out << "\\paragraph{Note.} " << latex_text(note) << "\n";
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
        if (e.family)
            doc["equilibrium_set"] = {{"relation", print(e.family->relation, syntax::plain)},
                                      {"dimension", e.family->dimension},
                                      {"potential", print(e.family->potential, syntax::plain)},
                                      {"stability_across", e.family->across > 0 ? "stable" : "unstable"}};
    }
    if (result.linearization) {
        doc["T"] = matrix_json(result.linearization->kinetic);
        doc["V"] = matrix_json(result.linearization->potential);
        if (shows_gyroscopic(result))
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
            nlohmann::ordered_json values = values_json(n.values);
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
            // An unstable mode: `omega` keeps the contract's floats (ω < 0: the imaginary
            // frequency i|ω|); `growth_rate` names the rate at which each mode grows.
            bool grows = false;
            for (std::size_t k = 0; k < n.omega.size(); ++k)
                grows = grows || mode_grows(n, k);
            if (grows) {
                nlohmann::ordered_json rates = nlohmann::ordered_json::array();
                for (std::size_t k = 0; k < n.omega.size(); ++k)
                    rates.push_back(mode_growth_rate(n, k));
                points.back()["growth_rate"] = rates;
                points.back()["stability"] = stability_of(n);
            }
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

namespace {

std::string complex_latex(std::complex<double> z)
{
    return complex_number(z, [](double v) { return report_writer::number(v, 6); }, "\\,i");
}

} // namespace

void write_gyroscopic_matrix(report_writer& w)
{
    const analysis& result = w.result();
    const linearization_result& l = *result.linearization;
    w.latex("\\section{The gyroscopic matrix}\n");
    w.text("The part of L linear in the velocities, ")
        .latex("$L_{1} = \\sum_{i} a_{i}(q)\\,\\dot{q}_{i}$")
        .text(", gives the antisymmetric matrix")
        .latex("\n\\[\\mathbf{G}_{ij} = \\left.\\left(\\frac{\\partial a_{j}}{\\partial q_{i}} - "
               "\\frac{\\partial a_{i}}{\\partial q_{j}}\\right)\\right|_{0}\\]\n")
        .text("and the linearized equations ")
        .latex("$\\mathbf{T}\\ddot{\\eta} - \\mathbf{G}\\dot{\\eta} + \\mathbf{V}\\eta = 0$")
        .text(":");
    w.display_matrix("\\mathbf{G}", l.gyroscopic);
    w.text("Stability follows the Kelvin–Tait–Chetaev theorems: a minimum of the effective potential stays stable "
           "whatever G; an odd number of negative stiffnesses (det V < 0) is unstable whatever G; otherwise the "
           "equilibrium is stable exactly when every root in ")
        .latex("$\\omega^{2}$")
        .text(" of the characteristic polynomial is real, positive and simple (gyroscopic stabilization), which a "
              "Sturm sequence decides.");
    if (result.equilibria)
        w.text(" Here: " + to_string(result.equilibria->points.at(result.equilibria->chosen).kind) + ".");
    w.latex("\n");
}

void write_gyroscopic_numeric(report_writer& w)
{
    const analysis& result = w.result();
    w.latex("\\section{Numeric values}\n");
    w.text("At each parameter point the engine evaluates T, V and G and solves the quadratic eigenproblem ")
        .latex("$(s^{2}\\mathbf{T} - s\\mathbf{G} + \\mathbf{V})\\,x = 0$")
        .text(" through the real eigenproblem of the first-order system. The frequencies are the imaginary parts "
              "of the eigenvalues in the upper half plane; a real eigenvalue s = γ > 0 is an imaginary frequency "
              "iγ, and a mode whose eigenvalue has a positive real part is shown with that growth rate. Each "
              "comes with an estimate of its relative error. The modes are complex, normalized so that ")
        .latex("$x^{*}\\mathbf{T}x = 1$")
        .text(" with their first largest component real and positive.");
    w.latex("\n");
    for (const numeric_modes& nm : *result.numeric) {
        const std::string at = values_latex(nm);
        w.latex("\\subsection*{At $" + at + "$: " + nm.stability + "}\n");
        w.latex("\\begin{center}\n\\renewcommand{\\arraystretch}{1.3}\n\\begin{tabular}{rlll}\n\\hline\n"
                "$k$ & $\\omega_{k}$ & relative error & mode\\\\\n\\hline\n");
        for (std::size_t k = 0; k < nm.omega.size(); ++k) {
            std::string mode;
            for (Eigen::Index i = 0; i < nm.complex_modes.rows(); ++i)
                mode += (i ? ",\\ " : "") + complex_latex(nm.complex_modes(i, static_cast<Eigen::Index>(k)));
            w.latex(std::to_string(k + 1) + " & $" +
                    omega_value_latex(nm, k, [](double x) { return report_writer::number(x); }) + "$ & $\\le " +
                    report_writer::number(nm.error[k], 2) + "$ & $(" + mode + ")$\\\\\n");
        }
        w.latex("\\hline\n\\end{tabular}\n\\end{center}\n");
        write_growth_rates(w, nm);
        w.text("Method: " + nm.method + ".");
        w.latex("\n");
    }
}

} // namespace lagrange
