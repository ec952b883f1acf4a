// SPDX-License-Identifier: GPL-2.0-or-later
/** @file symmetries.cpp
*  Printers of the conserved quantities, the Hamiltonian, the reduction and the
 *  steady motion.
 *
*  The report's section on symmetries: the conserved quantities, the Hamiltonian,
 *  Routh's reduction of the cyclic coordinates and the steady motion. */
#include "output/symmetries.h"

#include "core/number_text.h"
#include "output/format.h"
#include "output/latex_blocks.h"
#include "output/print.h"
#include "output/report_sections.h"

#include <string>
#include <utility>
#include <vector>

namespace lagrange {

namespace {

using GiNaC::ex;

/// The velocity symbol's name of coordinate i, and its momentum's.
std::string velocity_name(const model& scene, std::size_t i) { return scene.coordinates[i].name + "_dot"; }
std::string momentum_name(const model& scene, std::size_t i) { return "p_" + scene.coordinates[i].name; }

/// Terms ordered by the momenta, then the velocities.
term_order momentum_order(const model& scene, const std::vector<GiNaC::realsymbol>& momenta)
{
    term_order order = velocity_order(scene);
    std::vector<ex> group(momenta.begin(), momenta.end());
    order.groups.insert(order.groups.begin(), group);
    return order;
}

/// The named results of the sections, in printing order: (lhs name, expression).
struct line {
    std::string lhs; ///< a symbol name (printed by print_name) or text
    bool name;       ///< lhs is a symbol name
    ex value;
    term_order order;
};

std::vector<line> conserved_lines(const model& scene, const conserved_result& c)
{
    std::vector<line> lines;
    if (c.energy)
        lines.push_back({"h", true, *c.energy, velocity_order(scene)});
    for (std::size_t k = 0; k < c.cyclic.size(); ++k)
        lines.push_back({momentum_name(scene, c.cyclic[k]), true, c.momenta[k], velocity_order(scene)});
    return lines;
}

/// A matrix as [a, b; c, d] (a 1×1 matrix as its entry).
std::string matrix_text(const GiNaC::matrix& m, syntax s)
{
    if (m.rows() == 1 && m.cols() == 1)
        return print(m(0, 0), s);
    std::string text = "[";
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j)
            text += (j ? ", " : i ? "; " : "") + print(m(i, j), s);
    return text + "]";
}

std::string relation_text(const std::pair<ex, ex>& relation, syntax s)
{
    return print(relation.first, s) + " = " + print(relation.second, s);
}

std::string frequency_lhs(const steady_motion_result& steady, syntax s)
{
    const std::string omega = print_name(steady.characteristic.omega.get_name(), s);
    return steady.modes.gyroscopic ? omega : omega + (s == syntax::latex ? "^2" : "²");
}

} // namespace

void write_symmetries_text(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax s = syntax::text;
    if (result.conserved) {
        const conserved_result& c = *result.conserved;
        out << "\nConserved quantities\n";
        if (!c.energy)
            out << "  energy: not conserved (L depends on t)\n";
        for (const line& l : conserved_lines(scene, c))
            out << "  " << print_name(l.lhs, s) << " = " << print(l.value, s, l.order) << '\n';
        if (c.cyclic.empty())
            out << "  no cyclic coordinate\n";
    }
    if (result.hamiltonian) {
        const hamiltonian_result& h = *result.hamiltonian;
        const term_order order = momentum_order(scene, h.momenta);
        out << "\nHamiltonian\n  H = " << print(h.hamiltonian, s, order) << '\n';
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            out << "  " << print_name(velocity_name(scene, i), s) << " = " << print(h.velocities[i], s, order) << '\n';
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            out << "  " << print_name(momentum_name(scene, i) + "_dot", s) << " = " << print(h.forces[i], s, order)
                << '\n';
    }
    if (result.reduced && result.wanted.count(product::reduced)) {
        const reduced_result& r = *result.reduced;
        out << "\nReduced (Routh)\n  momenta held constant:";
        for (std::size_t k = 0; k < r.cyclic.size(); ++k)
            out << (k ? ", " : " ") << print_name(momentum_name(scene, r.cyclic[k]), s);
        out << "\n  R = " << print(r.routhian, s, velocity_order(scene)) << '\n';
        out << "  V_eff = " << print(r.effective_potential, s) << '\n';
        for (const reduced_result::family_member& f : r.family) {
            out << "  steady motions (" << print_name(scene.coordinates[f.coordinate].name, s) << " at rest): "
                << print(f.lhs, s) << " = ";
            for (std::size_t k = 0; k < f.rhs.size(); ++k)
                out << (k ? " or " : "") << print(f.rhs[k], s);
            out << '\n';
        }
        for (const reduced_result::circular& c : r.circular_orbits) {
            out << "  equilibrium of V_eff: " << print_name(scene.coordinates[c.coordinate].name, s) << " = ";
            for (std::size_t k = 0; k < c.values.size(); ++k)
                out << (k ? " or " : "") << print(c.values[k], s);
            out << '\n';
        }
    }
    if (result.steady) {
        const steady_motion_result& m = *result.steady;
        out << "\nSteady motion\n ";
        for (std::size_t k = 0; k < m.kept.size(); ++k)
            out << ' ' << print_name(scene.coordinates[m.kept[k]].name, s) << " = " << print(m.position[k], s) << ',';
        for (std::size_t k = 0; k < m.cyclic.size(); ++k)
            out << ' ' << print_name(velocity_name(scene, m.cyclic[k]), s) << " = " << print(m.rates[k], s)
                << (k + 1 < m.cyclic.size() ? "," : "");
        out << '\n';
        if (m.relation)
            out << "  steady when " << relation_text(*m.relation, s) << '\n';
        for (std::size_t k = 0; k < m.cyclic.size(); ++k)
            out << "  " << print_name(momentum_name(scene, m.cyclic[k]), s) << " = " << print(m.momenta[k], s) << '\n';
        out << "  reduced T = " << matrix_text(m.linear.kinetic, s) << '\n';
        out << "  reduced V = " << matrix_text(m.linear.potential, s) << '\n';
        if (m.linear.has_gyroscopic())
            out << "  reduced G = " << matrix_text(m.linear.gyroscopic, s) << '\n';
        for (const ex& f : m.modes.frequencies)
            out << "  " << frequency_lhs(m, s) << " = " << print(f, s) << '\n';
        out << "  stability: " << to_string(m.verdict) << " (" << m.stability_reason << ")\n";
        for (const steady_motion_result::at_point& p : m.at_values) {
            out << "  at";
            for (const auto& [name, value] : p.values)
                out << ' ' << print_name(name, s) << " = " << round_trip(value);
            out << ": " << to_string(p.verdict) << ", s =";
            for (std::size_t k = 0; k < p.eigenvalues.size(); ++k)
                out << (k ? ", " : " ") << complex_number(p.eigenvalues[k], round_trip, "i");
            out << '\n';
        }
        if (!m.modes.closed_form)
            out << "  frequencies: no closed form\n";
    }
}

void write_symmetries_latex(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax s = syntax::latex;
    if (result.conserved) {
        const conserved_result& c = *result.conserved;
        out << "\\subsection*{Conserved quantities}\n";
        if (!c.energy)
            out << "The energy function is not conserved: $L$ depends on $t$.\n";
        for (const line& l : conserved_lines(scene, c))
            out << latex_equation(print_name(l.lhs, s), print_terms(l.value, s, l.order), "");
    }
    if (result.hamiltonian) {
        const hamiltonian_result& h = *result.hamiltonian;
        const term_order order = momentum_order(scene, h.momenta);
        out << "\\subsection*{Hamiltonian}\n";
        out << latex_equation("H", print_terms(h.hamiltonian, s, order), "");
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            out << latex_equation(print_name(velocity_name(scene, i), s), print_terms(h.velocities[i], s, order), "");
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            out << latex_equation(print_name(momentum_name(scene, i) + "_dot", s), print_terms(h.forces[i], s, order),
                                  "");
    }
    if (result.reduced && result.wanted.count(product::reduced)) {
        const reduced_result& r = *result.reduced;
        out << "\\subsection*{Reduced system (Routh)}\nMomenta held constant: $";
        for (std::size_t k = 0; k < r.cyclic.size(); ++k)
            out << (k ? ",\\ " : "") << print_name(momentum_name(scene, r.cyclic[k]), s);
        out << "$.\n";
        out << latex_equation("R", print_terms(r.routhian, s, velocity_order(scene)), "");
        out << latex_equation("V_{\\mathrm{eff}}", print_terms(r.effective_potential, s), "");
        for (const reduced_result::family_member& f : r.family) {
            out << "Steady motions with $" << print_name(scene.coordinates[f.coordinate].name, s) << "$ at rest:\n";
            for (const ex& v : f.rhs)
                out << latex_equation(print(f.lhs, s), print_terms(v, s), "");
        }
        for (const reduced_result::circular& c : r.circular_orbits)
            for (const ex& v : c.values)
                out << "Equilibrium of $V_{\\mathrm{eff}}$: $" << print_name(scene.coordinates[c.coordinate].name, s)
                    << " = " << print(v, s) << "$.\n\n";
    }
    if (result.steady) {
        const steady_motion_result& m = *result.steady;
        out << "\\subsection*{Steady motion}\n";
        for (std::size_t k = 0; k < m.kept.size(); ++k)
            out << latex_equation(print_name(scene.coordinates[m.kept[k]].name, s), print_terms(m.position[k], s), "");
        for (std::size_t k = 0; k < m.cyclic.size(); ++k)
            out << latex_equation(print_name(velocity_name(scene, m.cyclic[k]), s), print_terms(m.rates[k], s), "");
        if (m.relation)
            out << "It is steady when\n"
                << latex_equation(print(m.relation->first, s), print_terms(m.relation->second, s), "");
        for (std::size_t k = 0; k < m.cyclic.size(); ++k)
            out << latex_equation(print_name(momentum_name(scene, m.cyclic[k]), s), print_terms(m.momenta[k], s), "");
        out << "\\begin{align*}\nT_{\\mathrm{red}} &= " << latex_matrix(m.linear.kinetic) << "\n\\end{align*}\n";
        if (m.linear.kinetic.rows() == 1)
            out << latex_equation("V_{\\mathrm{red}}", print_terms(m.linear.potential(0, 0), s), "");
        else
            out << "\\begin{align*}\nV_{\\mathrm{red}} &= " << latex_matrix(m.linear.potential) << "\n\\end{align*}\n";
        if (m.linear.has_gyroscopic())
            out << "\\begin{align*}\nG_{\\mathrm{red}} &= " << latex_matrix(m.linear.gyroscopic)
                << "\n\\end{align*}\n";
        for (const ex& f : m.modes.frequencies)
            out << latex_equation(frequency_lhs(m, s), print_terms(f, s), "");
    }
}

void write_symmetries_json(nlohmann::ordered_json& doc, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax s = syntax::plain;
    if (result.conserved) {
        nlohmann::ordered_json c = nlohmann::ordered_json::object();
        for (const line& l : conserved_lines(scene, *result.conserved))
            c[l.lhs == "h" ? "energy" : l.lhs] = print(l.value, s, l.order);
        doc["conserved"] = c;
    }
    if (result.hamiltonian) {
        const hamiltonian_result& h = *result.hamiltonian;
        const term_order order = momentum_order(scene, h.momenta);
        nlohmann::ordered_json equations = nlohmann::ordered_json::array();
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            equations.push_back(velocity_name(scene, i) + " = " + print(h.velocities[i], s, order));
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            equations.push_back(momentum_name(scene, i) + "_dot = " + print(h.forces[i], s, order));
        std::vector<std::string> momenta;
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            momenta.push_back(momentum_name(scene, i));
        doc["hamiltonian"] = {{"H", print(h.hamiltonian, s, order)}, {"momenta", momenta}, {"equations", equations}};
    }
    if (result.reduced && result.wanted.count(product::reduced)) {
        const reduced_result& r = *result.reduced;
        std::vector<std::string> momenta;
        for (std::size_t c : r.cyclic)
            momenta.push_back(momentum_name(scene, c));
        nlohmann::ordered_json reduced = {{"routhian", print(r.routhian, s, velocity_order(scene))},
                                          {"effective_potential", print(r.effective_potential, s)},
                                          {"momenta", momenta}};
        nlohmann::ordered_json family = nlohmann::ordered_json::array();
        for (const reduced_result::family_member& f : r.family) {
            std::vector<std::string> values;
            for (const ex& v : f.rhs)
                values.push_back(print(v, s));
            family.push_back({{"at_rest", scene.coordinates[f.coordinate].name}, {"lhs", print(f.lhs, s)},
                              {"values", values}});
        }
        if (!family.empty())
            reduced["steady_motions"] = family;
        nlohmann::ordered_json circular = nlohmann::ordered_json::object();
        for (const reduced_result::circular& c : r.circular_orbits) {
            std::vector<std::string> values;
            for (const ex& v : c.values)
                values.push_back(print(v, s));
            circular[scene.coordinates[c.coordinate].name] = values;
        }
        if (!circular.empty())
            reduced["equilibria"] = circular;
        doc["reduced"] = reduced;
    }
    if (result.steady) {
        const steady_motion_result& m = *result.steady;
        nlohmann::ordered_json position = nlohmann::ordered_json::object(), rates = nlohmann::ordered_json::object(),
                               momenta = nlohmann::ordered_json::object();
        for (std::size_t k = 0; k < m.kept.size(); ++k)
            position[scene.coordinates[m.kept[k]].name] = print(m.position[k], s);
        for (std::size_t k = 0; k < m.cyclic.size(); ++k) {
            rates[scene.coordinates[m.cyclic[k]].name] = print(m.rates[k], s);
            momenta[momentum_name(scene, m.cyclic[k])] = print(m.momenta[k], s);
        }
        auto rows = [&](const GiNaC::matrix& matrix) {
            nlohmann::ordered_json out = nlohmann::ordered_json::array();
            for (unsigned i = 0; i < matrix.rows(); ++i) {
                std::vector<std::string> row;
                for (unsigned j = 0; j < matrix.cols(); ++j)
                    row.push_back(print(matrix(i, j), s));
                out.push_back(row);
            }
            return out;
        };
        std::vector<std::string> frequencies;
        for (const ex& f : m.modes.frequencies)
            frequencies.push_back(print(f, s));
        nlohmann::ordered_json steady = {{"position", position}, {"rates", rates}, {"momenta", momenta}};
        if (m.relation)
            steady["condition"] = print(m.relation->first, s) + " = " + print(m.relation->second, s);
        steady["T"] = rows(m.linear.kinetic);
        steady["V"] = rows(m.linear.potential);
        if (m.linear.has_gyroscopic())
            steady["G"] = rows(m.linear.gyroscopic);
        steady["frequencies"] = frequencies;
        steady["frequency_variable"] = m.modes.gyroscopic ? "omega" : "omega^2";
        steady["stability"] = to_string(m.verdict);
        nlohmann::ordered_json points = nlohmann::ordered_json::array();
        for (const steady_motion_result::at_point& p : m.at_values) {
            nlohmann::ordered_json values = values_json(p.values), eigenvalues = nlohmann::ordered_json::array();
            for (const std::complex<double>& z : p.eigenvalues)
                eigenvalues.push_back({z.real(), z.imag()});
            points.push_back({{"values", values}, {"eigenvalues", eigenvalues}, {"stability", to_string(p.verdict)}});
        }
        steady["numeric"] = points;
        doc["steady_motion"] = steady;
    }
}

// ---- the report's section ----

namespace {

std::string momentum(const model& scene, std::size_t i) { return report_writer::name("p_" + scene.coordinates[i].name); }

std::string names_of(const model& scene, const std::vector<std::size_t>& which)
{
    std::string text;
    for (std::size_t k = 0; k < which.size(); ++k)
        text += (k ? ",\\ " : "") + report_writer::name(scene.coordinates[which[k]].name);
    return text;
}

} // namespace

void write_symmetries_section(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    w.latex("\\section{Symmetries}\n");
    if (result.conserved) {
        const conserved_result& c = *result.conserved;
        w.latex("\\subsection*{Conserved quantities}\n");
        if (c.energy) {
            w.text("L does not depend on t, so the energy function ")
                .latex("$h = \\sum_i \\dot{q}_i\\,\\partial L/\\partial \\dot{q}_i - L$")
                .text(" is conserved (it is T + V only when T is a quadratic form in the velocities and V is free "
                      "of them):");
            w.display("h", *c.energy);
        } else {
            w.text("L depends on t, so the energy function is not conserved.");
            w.latex("\n");
        }
        if (!c.cyclic.empty()) {
            w.text("The cyclic coordinates ")
                .latex("$" + names_of(scene, c.cyclic) + "$")
                .text(" appear in L only through their velocities; their momenta are conserved:");
            for (std::size_t k = 0; k < c.cyclic.size(); ++k)
                w.display(momentum(scene, c.cyclic[k]), c.momenta[k]);
        }
    }
    if (result.hamiltonian) {
        const hamiltonian_result& h = *result.hamiltonian;
        w.latex("\\subsection*{Hamiltonian}\n");
        w.text("With the momenta ")
            .latex("$p_i = \\partial L/\\partial \\dot{q}_i$")
            .text(", the Legendre transform gives");
        w.display("H", h.hamiltonian);
        w.text("and Hamilton's equations");
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            w.display(report_writer::name(scene.coordinates[i].name + "_dot"), h.velocities[i]);
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            w.display("\\dot{" + momentum(scene, i) + "}", h.forces[i]);
    }
    if (result.reduced && result.wanted.count(product::reduced)) {
        const reduced_result& r = *result.reduced;
        w.latex("\\subsection*{Routh's reduction}\n");
        w.text("Holding the momenta of the cyclic coordinates constant and eliminating their velocities, the "
               "Routhian ")
            .latex("$R = L - \\sum_c p_c \\dot{q}_c$")
            .text(" is a Lagrangian of the remaining coordinates:");
        w.display("R", r.routhian);
        w.text("Its velocity-free part, with the sign changed, is the effective potential");
        w.display("V_{\\mathrm{eff}}", r.effective_potential);
        for (const reduced_result::family_member& f : r.family) {
            std::string values;
            for (std::size_t k = 0; k < f.rhs.size(); ++k)
                values += (k ? " \\text{ or } " : "") + report_writer::math(f.rhs[k]);
            w.text("With ")
                .latex("$" + report_writer::name(scene.coordinates[f.coordinate].name) + "$")
                .text(" at rest, the cyclic coordinates turn steadily when");
            w.display_terms(report_writer::math(f.lhs), {values});
        }
        for (const reduced_result::circular& c : r.circular_orbits)
            for (const GiNaC::ex& v : c.values) {
                w.text("The effective potential is stationary at");
                w.display(report_writer::name(scene.coordinates[c.coordinate].name), v);
            }
    }
    if (result.steady) {
        const steady_motion_result& m = *result.steady;
        w.latex("\\subsection*{Steady motion}\n");
        std::string point;
        for (std::size_t k = 0; k < m.kept.size(); ++k)
            point += (point.empty() ? "" : ",\\ ") + report_writer::name(scene.coordinates[m.kept[k]].name) + " = " +
                     report_writer::math(m.position[k]);
        for (std::size_t k = 0; k < m.cyclic.size(); ++k)
            point += (point.empty() ? "" : ",\\ ") + report_writer::name(scene.coordinates[m.cyclic[k]].name + "_dot") +
                     " = " + report_writer::math(m.rates[k]);
        w.text("The scene names the steady motion ").latex("$" + point + "$").text(".");
        if (m.relation) {
            w.text(" It is an equilibrium of the reduced system only when");
            w.display(report_writer::math(m.relation->first), m.relation->second);
            w.text("which the results below use.");
        }
        w.text(" The momenta of the motion are");
        for (std::size_t k = 0; k < m.cyclic.size(); ++k)
            w.display(momentum(scene, m.cyclic[k]), m.momenta[k]);
        w.text("At these fixed momenta the reduced system, linearized about the motion, has the matrices");
        w.display_matrix("T_{\\mathrm{red}}", m.linear.kinetic);
        w.display_matrix("V_{\\mathrm{red}}", m.linear.potential);
        if (m.linear.has_gyroscopic())
            w.display_matrix("G_{\\mathrm{red}}", m.linear.gyroscopic);
        w.text("and small oscillations about the steady motion have");
        const std::string lhs = m.modes.gyroscopic ? "\\omega" : "\\omega^{2}";
        for (const GiNaC::ex& f : m.modes.frequencies)
            w.display(lhs, f);
    }
}

} // namespace lagrange
