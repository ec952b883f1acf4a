// SPDX-License-Identifier: GPL-2.0-or-later
/** @file symmetries_report.cpp
 *  The report's section on symmetries: the conserved quantities, the Hamiltonian,
 *  Routh's reduction of the cyclic coordinates and the steady motion. */
#include "output/report_sections.h"

#include <string>
#include <vector>

namespace lagrange {

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
