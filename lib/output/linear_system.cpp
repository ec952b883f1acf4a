// SPDX-License-Identifier: GPL-2.0-or-later
/** @file linear_system.cpp
 *  Printers of the state-space form and the transfer functions.
 *
 *  The report's section on the linearized input–output system: A, B and the transfer functions.
 *
 *  The report section "Linearization with constraints": A and B about an operating point in
 *  the independent coordinates and speeds, with the residual and what it means, and the
 *  transfer functions. */
#include "output/linear_system.h"

#include "algebra/sign.h"
#include "output/damping.h"
#include "output/format.h"
#include "output/latex_blocks.h"
#include "output/print.h"
#include "output/report.h"
#include "output/report_sections.h"

#include <charconv>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

namespace lagrange {

namespace {

bool shows(const analysis& result, product p) { return result.wanted.count(p) > 0; }

std::vector<std::string> state_names(const analysis& result, syntax how)
{
    std::vector<std::string> names;
    for (const GiNaC::ex& x : result.state_space->state)
        names.push_back(print(x, how));
    return names;
}

std::vector<std::string> input_names(const model& scene, syntax how)
{
    std::vector<std::string> names;
    for (const input_signal& u : scene.inputs)
        names.push_back(print_name(u.name, how));
    return names;
}

void matrix_text(std::ostream& out, const std::string& label, const GiNaC::matrix& m, const std::string& indent)
{
    out << indent << label << " =";
    for (unsigned i = 0; i < m.rows(); ++i) {
        out << (i ? indent + std::string(label.size() + 3, ' ') : std::string(" ")) << "[";
        for (unsigned j = 0; j < m.cols(); ++j)
            out << (j ? ", " : "") << print(m(i, j), syntax::text);
        out << "]\n";
    }
}

void numbers_text(std::ostream& out, const std::string& label, const Eigen::MatrixXd& m, const std::string& indent)
{
    out << indent << label << " =";
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
        out << (i ? indent + std::string(label.size() + 3, ' ') : std::string(" ")) << "[";
        for (Eigen::Index j = 0; j < m.cols(); ++j)
            out << (j ? ", " : "") << round_trip(m(i, j));
        out << "]\n";
    }
}

std::string numbers_latex(const Eigen::MatrixXd& m)
{
    std::string out = "\\begin{pmatrix}";
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
        for (Eigen::Index j = 0; j < m.cols(); ++j)
            out += (j ? " & " : "") + print(GiNaC::numeric(m(i, j) == 0 ? 0.0 : m(i, j)), syntax::latex);
        out += i + 1 < m.rows() ? " \\\\ " : "";
    }
    return out + "\\end{pmatrix}";
}

std::string values_text(const std::vector<std::pair<std::string, double>>& values, syntax how)
{
    std::string out;
    for (const auto& [name, value] : values)
        out += (out.empty() ? "" : how == syntax::latex ? ",\\ " : " ") + print_name(name, how) + " = " +
               (how == syntax::latex ? print(GiNaC::numeric(value), how) : round_trip(value));
    return out;
}

/// A polynomial in s, printed in descending powers, in parentheses when it is a sum.
std::string polynomial_part(const GiNaC::ex& e, const GiNaC::symbol& s, syntax how, bool parenthesize)
{
    const std::string printed = print(e, how, term_order{{{s}}});
    if (parenthesize && GiNaC::is_a<GiNaC::add>(e))
        return "(" + printed + ")";
    return printed;
}

/// Eigenvalues as "a ± bi" pairs and reals, in the order given.
std::string eigenvalues_text(const std::vector<std::complex<double>>& values)
{
    std::string out;
    for (const std::complex<double>& z : values) {
        if (z.imag() < 0)
            continue; // printed with its conjugate
        out += (out.empty() ? "" : ", ") + conjugate_pair(z, round_trip, " ± ", "i");
    }
    return out;
}

/// The operating point in words: where, which states are independent, the residual
/// F(x₀, u₀) and what it means.
void operating_point_text(std::ostream& out, const model& scene, const operating_linearization& point)
{
    const syntax how = syntax::text;
    std::string where;
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
        where += (where.empty() ? "" : ", ") + print(scene.coordinates[i].position, how) + " = " +
                 print(point.position[i], how);
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
        where += ", " + print(scene.coordinates[i].velocity, how) + " = " + print(point.velocity[i], how);
    for (std::size_t k = 0; k < scene.inputs.size(); ++k)
        where += ", " + print_name(scene.inputs[k].name, how) + " = " + print(point.inputs[k], how);
    out << "  at " << where << "\n";
    if (!scene.constraints.empty()) {
        std::vector<std::string> coordinates, speeds;
        for (std::size_t i : point.coordinates)
            coordinates.push_back(print(scene.coordinates[i].position, how));
        for (std::size_t i : point.speeds)
            speeds.push_back(print(scene.coordinates[i].velocity, how));
        out << "  independent coordinates " << join(coordinates, ", ") << ", speeds " << join(speeds, ", ")
            << (point.chosen ? " (chosen: the dependent ones are the best-conditioned pivots of the constraint "
                               "Jacobians there)"
                             : " (the `independent` line)")
            << "\n";
    }
    std::vector<std::string> residual;
    for (const GiNaC::ex& e : point.residual)
        residual.push_back(print(e, how));
    out << "  residual F(x₀, u₀) = (" << join(residual, ", ") << ")\n";
    using kind = operating_linearization::kind;
    if (point.point_kind == kind::equilibrium) {
        out << "  F(x₀, u₀) = 0: the point is an equilibrium\n";
        return;
    }
    if (point.point_kind == kind::steady) {
        std::vector<std::string> moving;
        for (std::size_t i : point.moving)
            moving.push_back(print(scene.coordinates[i].position, how));
        out << "  not an equilibrium: a steady motion (every acceleration is 0; " << join(moving, ", ")
            << " move at constant rates). "
            << (point.moving_cyclic ? "They enter no equation, so A and B hold all along the motion: δx = x − x₀(t) "
                                      "with x₀(t) = x₀ + F t obeys δẋ = A δx + B δu\n"
                                    : "They enter the equations, so A and B hold at this instant of the motion "
                                      "only\n");
        return;
    }
    out << "  not an equilibrium nor a steady motion: the state leaves x₀ at the rate F(x₀, u₀), and "
           "ẋ ≈ F(x₀, u₀) + A δx + B δu near x₀ only, for short times\n";
}

nlohmann::ordered_json operating_point_json(const model& scene, const operating_linearization& point)
{
    const syntax how = syntax::plain;
    nlohmann::ordered_json entry, position = nlohmann::ordered_json::object(),
                                  velocity = nlohmann::ordered_json::object(),
                                  inputs = nlohmann::ordered_json::object();
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i) {
        position[scene.coordinates[i].name] = print(point.position[i], how);
        velocity[scene.coordinates[i].name] = print(point.velocity[i], how);
    }
    for (std::size_t k = 0; k < scene.inputs.size(); ++k)
        inputs[scene.inputs[k].name] = print(point.inputs[k], how);
    entry["position"] = position;
    entry["velocity"] = velocity;
    entry["inputs"] = inputs;
    std::vector<std::string> coordinates, speeds, residual, moving;
    for (std::size_t i : point.coordinates)
        coordinates.push_back(scene.coordinates[i].name);
    for (std::size_t i : point.speeds)
        speeds.push_back(scene.coordinates[i].name);
    for (const GiNaC::ex& e : point.residual)
        residual.push_back(print(e, how));
    for (std::size_t i : point.moving)
        moving.push_back(scene.coordinates[i].name);
    entry["independent_coordinates"] = coordinates;
    entry["independent_speeds"] = speeds;
    entry["chosen"] = point.chosen;
    entry["residual"] = residual;
    using kind = operating_linearization::kind;
    entry["kind"] = point.point_kind == kind::equilibrium ? "equilibrium"
                    : point.point_kind == kind::steady    ? "steady_motion"
                                                          : "not_an_equilibrium";
    if (point.point_kind == kind::steady) {
        entry["moving"] = moving;
        entry["holds_along_motion"] = point.moving_cyclic;
    }
    return entry;
}

} // namespace

std::string transfer_text(const transfer_function& h, const GiNaC::symbol& s, syntax how)
{
    if (h.numerator.is_zero())
        return "0";
    if (how == syntax::latex)
        return "\\frac{" + polynomial_part(h.numerator, s, how, false) + "}{" +
               polynomial_part(h.denominator, s, how, false) + "}";
    const bool simple_denominator =
        GiNaC::is_a<GiNaC::symbol>(h.denominator) || GiNaC::is_a<GiNaC::numeric>(h.denominator);
    if (h.denominator == 1)
        return polynomial_part(h.numerator, s, how, false);
    return polynomial_part(h.numerator, s, how, true) + "/" +
           (simple_denominator ? print(h.denominator, how) : "(" + print(h.denominator, how, term_order{{{s}}}) + ")");
}

void write_linear_system_text(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax how = syntax::text;
    if (result.state_space && shows(result, product::state_space)) {
        const state_space_result& ss = *result.state_space;
        if (result.operating) {
            out << "\nState space (linearized about the operating point: ẋ ≈ F(x₀, u₀) + A δx + B δu)\n";
            operating_point_text(out, scene, *result.operating);
        } else
            out << "\nState space (ẋ = A x + B u at the equilibrium)\n";
        out << "  x = (" << join(state_names(result, how), ", ") << "),  u = (" << join(input_names(scene, how), ", ")
            << ")\n";
        matrix_text(out, "A", ss.a, "  ");
        if (result.operating && !result.operating->characteristic_left_out.empty())
            out << "  det(" << print_name(result.operating->s.get_name(), how) << "I − A): "
                << result.operating->characteristic_left_out << "\n";
        else if (result.operating)
            out << "  det(" << print_name(result.operating->s.get_name(), how) << "I − A) ∝ "
                << print(result.operating->characteristic, how, term_order{{{result.operating->s}}}) << "\n";
        if (ss.b.cols())
            matrix_text(out, "B", ss.b, "  ");
        else
            out << "  B: no columns (the scene has no inputs)\n";
        for (const state_space_point& p : result.state_space_values) {
            out << "  at " << values_text(p.values, how) << "\n";
            numbers_text(out, "A", p.a, "    ");
            if (p.b.cols())
                numbers_text(out, "B", p.b, "    ");
            out << "    eigenvalues of A: " << eigenvalues_text(p.eigenvalues) << "\n";
            if (!p.stability.empty())
                out << "    " << p.stability
                    << (p.stability == "stable"     ? ": every eigenvalue has Re s < 0"
                        : p.stability == "unstable" ? ": an eigenvalue has Re s > 0, a mode grows"
                                                    : ": the largest Re s is 0 (zero or imaginary eigenvalues), no "
                                                      "mode grows exponentially")
                    << "\n";
        }
    }
    if (result.transfer && shows(result, product::transfer)) {
        const transfer_result& tr = *result.transfer;
        const std::string s = print_name(tr.s.get_name(), how);
        out << "\nTransfer functions (X(" << s << ") = H(" << s << ") U(" << s << "), q ∝ e^{" << s << "t})\n";
        for (const transfer_function& h : tr.entries)
            out << "  " << print_name(scene.inputs[h.input].name, how) << " → "
                << print_name(scene.coordinates[h.coordinate].name, how) << ":  H(" << s
                << ") = " << transfer_text(h, tr.s, how) << '\n';
    }
}

namespace {

/// Above this many characters a symbolic A (the whole bicycle's) is not typeset: TeX cannot
/// measure a display that wide, and nobody reads it.
constexpr std::size_t largest_typeset_matrix = 20000;

/// A matrix with many columns (the bicycle's 10 states), scaled to the line width
/// (graphicx), where its entries or their full digits would run off the page.
std::string page_wide(const std::string& matrix, Eigen::Index columns)
{
    return columns > 6 ? "\\resizebox{0.9\\linewidth}{!}{$" + matrix + "$}" : matrix;
}

} // namespace

void write_linear_system_latex(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax how = syntax::latex;
    if (result.state_space && shows(result, product::state_space)) {
        const state_space_result& ss = *result.state_space;
        out << "\\subsection*{State space}\n$\\dot{x} = A x + B u$ "
            << (result.operating ? "linearized about the operating point (see the text output for its residual)"
                                 : "at the equilibrium")
            << ", with $x = ("
            << join(state_names(result, how), ", ") << ")$ and $u = (" << join(input_names(scene, how), ", ")
            << ")$:\n";
        const std::string a = latex_matrix(ss.a);
        if (a.size() > largest_typeset_matrix)
            out << "$A$ is too large to typeset (" << a.size() << " characters of \\LaTeX); the text and JSON "
                << "outputs hold it, and its values follow.\n";
        else
            out << "\\begin{align*}\nA &= " << page_wide(a, ss.a.cols()) << ",\\\\\nB &= " << latex_matrix(ss.b)
                << "\n\\end{align*}\n";
        for (const state_space_point& p : result.state_space_values)
            out << "At $" << values_text(p.values, how) << "$:\n\\begin{align*}\nA &= " << page_wide(numbers_latex(p.a), p.a.cols())
                << ",\\\\\nB &= " << page_wide(numbers_latex(p.b), p.b.cols()) << "\n\\end{align*}\n";
    }
    if (result.transfer && shows(result, product::transfer)) {
        const transfer_result& tr = *result.transfer;
        const std::string s = print_name(tr.s.get_name(), how);
        out << "\\subsection*{Transfer functions}\n$X(" << s << ") = H(" << s << ")\\,U(" << s
            << ")$, one for each input and coordinate:\n\\begin{align*}\n";
        for (std::size_t k = 0; k < tr.entries.size(); ++k) {
            const transfer_function& h = tr.entries[k];
            out << "H_{" << print_name(scene.inputs[h.input].name, how) << " \\to "
                << print_name(scene.coordinates[h.coordinate].name, how) << "}(" << s
                << ") &= " << transfer_text(h, tr.s, how) << (k + 1 < tr.entries.size() ? "\\\\\n" : "\n");
        }
        out << "\\end{align*}\n";
    }
}

void write_linear_system_json(nlohmann::ordered_json& doc, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax how = syntax::plain;
    auto symbolic = [&](const GiNaC::matrix& m) {
        nlohmann::ordered_json rows = nlohmann::ordered_json::array();
        for (unsigned i = 0; i < m.rows(); ++i) {
            nlohmann::ordered_json row = nlohmann::ordered_json::array();
            for (unsigned j = 0; j < m.cols(); ++j)
                row.push_back(print(m(i, j), how));
            rows.push_back(row);
        }
        return rows;
    };
    auto numbers = [](const Eigen::MatrixXd& m) {
        nlohmann::ordered_json rows = nlohmann::ordered_json::array();
        for (Eigen::Index i = 0; i < m.rows(); ++i) {
            nlohmann::ordered_json row = nlohmann::ordered_json::array();
            for (Eigen::Index j = 0; j < m.cols(); ++j)
                row.push_back(m(i, j) == 0 ? 0.0 : m(i, j));
            rows.push_back(row);
        }
        return rows;
    };
    if (result.state_space && shows(result, product::state_space)) {
        const state_space_result& ss = *result.state_space;
        nlohmann::ordered_json entry;
        entry["state"] = state_names(result, how);
        entry["inputs"] = input_names(scene, how);
        entry["A"] = symbolic(ss.a);
        entry["B"] = symbolic(ss.b);
        nlohmann::ordered_json points = nlohmann::ordered_json::array();
        for (const state_space_point& p : result.state_space_values) {
            nlohmann::ordered_json values = values_json(p.values);
            nlohmann::ordered_json eigenvalues = nlohmann::ordered_json::array();
            for (const std::complex<double>& z : p.eigenvalues)
                eigenvalues.push_back({z.real(), z.imag()});
            points.push_back({{"values", values},
                              {"A", numbers(p.a)},
                              {"B", numbers(p.b)},
                              {"eigenvalues", eigenvalues},
                              {"stability", p.stability}});
        }
        entry["numeric"] = points;
        if (result.operating) {
            entry["operating_point"] = operating_point_json(scene, *result.operating);
            if (result.operating->characteristic_left_out.empty())
                entry["characteristic"] = {{"variable", result.operating->s.get_name()},
                                           {"polynomial", print(result.operating->characteristic, how)}};
            else
                entry["characteristic"] = {{"variable", result.operating->s.get_name()},
                                           {"left_out", result.operating->characteristic_left_out}};
        }
        doc["state_space"] = entry;
    }
    if (result.transfer && shows(result, product::transfer)) {
        const transfer_result& tr = *result.transfer;
        nlohmann::ordered_json entry = nlohmann::ordered_json::object();
        for (const transfer_function& h : tr.entries)
            entry[scene.inputs[h.input].name + " -> " + scene.coordinates[h.coordinate].name] =
                transfer_text(h, tr.s, how);
        doc["transfer"] = entry;
    }
}

void write_linear_system_section(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    w.latex("\\section{Inputs: state space and transfer functions}\n");
    if (result.state_space && result.wanted.count(product::state_space)) {
        const state_space_result& ss = *result.state_space;
        std::string state, inputs;
        for (const GiNaC::ex& x : ss.state)
            state += (state.empty() ? "" : ",\\ ") + report_writer::math(x);
        for (const input_signal& u : scene.inputs)
            inputs += (inputs.empty() ? "" : ",\\ ") + report_writer::name(u.name);
        w.text("Linearized at the equilibrium, with the state ")
            .latex("$x = (" + state + ")$")
            .text(" and the inputs ")
            .latex("$u = (" + inputs + ")$")
            .text(", the equations of motion ")
            .latex("$M\\ddot q + (C - G)\\dot q + K q = B_q u$")
            .text(" become ")
            .latex("$\\dot x = A x + B u$")
            .text(" with ")
            .latex("$A = \\begin{pmatrix} 0 & I \\\\ -M^{-1}K & M^{-1}(G - C)\\end{pmatrix}$")
            .text(" and ")
            .latex("$B = \\begin{pmatrix} 0 \\\\ M^{-1}B_q\\end{pmatrix}$")
            .text(", where ")
            .latex("$B_q = \\partial Q/\\partial u$")
            .text(":");
        w.latex("\n");
        w.display_matrix("A", ss.a);
        w.display_matrix("B", ss.b);
    }
    if (result.transfer && result.wanted.count(product::transfer)) {
        const transfer_result& tr = *result.transfer;
        const std::string s = report_writer::name(tr.s.get_name());
        w.text("The Laplace transform of the linearized equations from rest gives ")
            .latex("$(" + s + "^{2}M + " + s + "(C - G) + K)\\,X(" + s + ") = B_q U(" + s + ")$")
            .text("; solved by Cramer's rule, each input drives each coordinate through the transfer function ")
            .latex("$H(" + s + ") = X(" + s + ")/U(" + s + ")$")
            .text(". Its poles are the roots of the damped characteristic polynomial that the input reaches; a pole "
                  "with a positive real part is an instability.");
        w.latex("\n");
        write_transfer_rows(w, scene, tr, s);
    }
}

void write_transfer_rows(report_writer& w, const model& scene, const transfer_result& transfer, const std::string& s)
{
    std::vector<report_writer::row> rows;
    for (const transfer_function& h : transfer.entries)
        rows.push_back({"H_{" + report_writer::name(scene.inputs[h.input].name) + " \\to " +
                            report_writer::name(scene.coordinates[h.coordinate].name) + "}(" + s + ")",
                        {transfer_text(h, transfer.s, syntax::latex)},
                        ""});
    w.display_rows(rows);
}

namespace {

std::string listed(const std::vector<std::string>& parts)
{
    std::string out;
    for (const std::string& p : parts)
        out += (out.empty() ? "" : ",\\ ") + p;
    return out;
}

} // namespace

void write_operating_point_section(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    const operating_linearization& point = *result.operating;
    w.latex("\n\\section{Linearization with constraints}\n");
    std::vector<std::string> where, coordinates, speeds, state, residual;
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
        where.push_back(report_writer::math(scene.coordinates[i].position) + " = " +
                        report_writer::math(point.position[i]));
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
        where.push_back(report_writer::math(scene.coordinates[i].velocity) + " = " +
                        report_writer::math(point.velocity[i]));
    for (std::size_t k = 0; k < scene.inputs.size(); ++k)
        where.push_back(report_writer::name(scene.inputs[k].name) + " = " + report_writer::math(point.inputs[k]));
    for (std::size_t i : point.coordinates)
        coordinates.push_back(report_writer::math(scene.coordinates[i].position));
    for (std::size_t i : point.speeds)
        speeds.push_back(report_writer::math(scene.coordinates[i].velocity));
    for (const GiNaC::ex& x : point.state)
        state.push_back(report_writer::math(x));
    for (const GiNaC::ex& e : point.residual)
        residual.push_back(report_writer::math(e));
    w.text("The equations are linearized about the operating point ")
        .latex("$" + listed(where) + "$")
        .text(". With the constraints ")
        .latex("$f(q) = 0$ and $A(q)\\dot q + b(q) = 0$")
        .text(" and the accelerations from ")
        .latex("$\\begin{pmatrix} M & -A^{T} \\\\ A & 0\\end{pmatrix}"
               "\\begin{pmatrix}\\ddot q \\\\ \\lambda\\end{pmatrix} = "
               "\\begin{pmatrix} f + Q \\\\ -c\\end{pmatrix}$")
        .text(", the dependent coordinates and speeds follow from the independent ones through the constraint "
              "Jacobians at the point, ")
        .latex("$\\delta q = C_0\\,\\delta q_I$, $\\delta\\dot q = C_1\\,\\delta q + C_2\\,\\delta\\dot q_J$")
        .text(". The independent coordinates are ")
        .latex("$" + listed(coordinates) + "$")
        .text(" and the independent speeds ")
        .latex("$" + listed(speeds) + "$")
        .text(point.chosen ? " (chosen as the complement of the best-conditioned pivots of the constraint Jacobians)"
                           : " (named by the scene's `independent` line)")
        .text(", so the state is ")
        .latex("$x = (" + listed(state) + ")$")
        .text(" and ")
        .latex("$\\dot x \\approx F(x_0, u_0) + A\\,\\delta x + B\\,\\delta u$")
        .text(" with");
    w.latex("\n");
    w.display_matrix("A", result.state_space->a);
    if (result.state_space->b.cols())
        w.display_matrix("B", result.state_space->b);
    w.display_terms("F(x_0, u_0)", {"(" + listed(residual) + ")"});
    using kind = operating_linearization::kind;
    if (point.point_kind == kind::equilibrium)
        w.text("The residual vanishes: the point is an equilibrium.");
    else if (point.point_kind == kind::steady)
        w.text(std::string("The accelerations vanish but some coordinates move at constant rates: a steady "
                           "motion, not an equilibrium. ") +
               (point.moving_cyclic ? "The moving coordinates enter no equation, so A and B hold all along it."
                                    : "The moving coordinates enter the equations, so A and B hold at this "
                                      "instant only."));
    else
        w.text("The residual does not vanish: the point is not an equilibrium, and A and B describe the motion "
               "near it for short times only.");
    w.latex("\n");
    if (result.transfer && result.wanted.count(product::transfer)) {
        const transfer_result& tr = *result.transfer;
        const std::string s = report_writer::name(tr.s.get_name());
        w.text("Each input drives each coordinate through ")
            .latex("$H(" + s + ") = X(" + s + ")/U(" + s + ")$")
            .text(" from ")
            .latex("$(" + s + "I - A)\\,X = B\\,U$")
            .text(", a dependent coordinate through ")
            .latex("$C_0$")
            .text(":");
        w.latex("\n");
        write_transfer_rows(w, scene, tr, s);
    }
}

} // namespace lagrange
