// SPDX-License-Identifier: GPL-2.0-or-later
/** @file constraints_report.cpp
 *  The report's section on constraints: each constraint with its kind and integrability,
 *  the equations with multipliers, the multipliers solved and the constraint forces. */
#include "output/report_sections.h"

#include "output/latex_blocks.h"
#include "output/print.h"

#include <string>
#include <vector>

namespace lagrange {

void write_constraints_section(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    w.latex("\\section{Constraints}\n");
    w.text("With the constraints the equations of motion read");
    w.latex("\n\\[M\\ddot{q} = f + A^{\\mathsf{T}}\\lambda,\\qquad A\\ddot{q} = -c,\\]\n");
    w.text("where row k of A holds the velocity coefficients of constraint k (its gradient, for a holonomic "
           "one), λ_k is its multiplier and A q̈ = −c is the constraint differentiated to the accelerations. "
           "For constraints linear in the velocities these are the Lagrange–d'Alembert equations. "
           "The constraints are:");
    w.latex("\n");
    const constraint_equations* shown =
        result.equations && result.equations->constraints ? &*result.equations->constraints : nullptr;
    for (std::size_t k = 0; k < scene.constraints.size(); ++k) {
        const constraint& c = scene.constraints[k];
        std::string kind = c.constraint_kind == constraint::kind::holonomic ? "holonomic"
                           : shown && shown->integrable[k] ? "Pfaffian, integrable (a holonomic form exists)"
                                                           : "Pfaffian, not integrable";
        w.latex("\n\\noindent ").text(c.name + " (" + kind + "):");
        w.display_terms("", print_terms(c.function, syntax::latex, velocity_order(scene)), " = 0");
    }
    if (shown && !shown->jointly_integrable)
        w.text("Together the constraints are not integrable (Frobenius): the motion is nonholonomic.");
    if (result.constrained && result.linearization) {
        std::string names;
        for (std::size_t k : result.constrained->independent)
            names += (names.empty() ? "" : ", ") + scene.coordinates[k].name;
        w.text(" The small oscillations below are in the independent coordinates " + names +
               ", on the tangent space of the constraints at the equilibrium.");
    }
    if (!result.multipliers)
        return;
    w.latex("\n\\subsection*{Multipliers}\n");
    w.text("Solving [M −Aᵀ; A 0] [q̈; λ] = [f; −c] gives the multipliers:");
    w.latex("\n");
    for (std::size_t k = 0; k < result.multipliers->constraints.size(); ++k)
        w.display_terms(report_writer::name(scene.constraints[k].multiplier.get_name()),
                        print_terms(result.multipliers->constraints[k].multiplier, syntax::latex, velocity_order(scene)));
    bool any = false;
    for (const constraint_multiplier& m : result.multipliers->constraints)
        any = any || !m.forces.empty();
    if (!any)
        return;
    w.latex("\n\\subsection*{Constraint forces}\n");
    w.text("The force of each constraint on a point, along the point's own motion, does the constraint's "
           "virtual work:");
    w.latex("\n");
    for (const constraint_multiplier& m : result.multipliers->constraints)
        for (const constraint_point_force& f : m.forces)
            for (std::size_t r = 0; r < f.force.size(); ++r)
                w.display_terms("F^{\\mathrm{" + latex_text(m.name) + "}}_{" + latex_text(f.point) + "," +
                                    std::string(1, static_cast<char>('x' + r)) + "}",
                                print_terms(f.force[r], syntax::latex, velocity_order(scene)));
}

} // namespace lagrange
