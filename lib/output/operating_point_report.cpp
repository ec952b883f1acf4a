// SPDX-License-Identifier: GPL-2.0-or-later
/** @file operating_point_report.cpp
 *  The report section "Linearization with constraints": A and B about an operating point in
 *  the independent coordinates and speeds, with the residual and what it means, and the
 *  transfer functions. */
#include "output/linear_system_output.h"
#include "output/report.h"
#include "output/report_sections.h"

#include <string>
#include <vector>

namespace lagrange {

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
                           : " (named by the scene's \\texttt{independent} line)")
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
