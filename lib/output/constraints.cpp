// SPDX-License-Identifier: GPL-2.0-or-later
/** @file constraints.cpp
*  Printers of the constraints, their multipliers and forces.
 *
*  The report's section on constraints: each constraint with its kind and integrability,
 *  the equations with multipliers, the multipliers solved and the constraint forces. */
#include "output/constraints.h"

#include "output/latex_blocks.h"
#include "output/print.h"
#include "output/report_sections.h"

#include <string>
#include <vector>

namespace lagrange {

namespace {

/// "holonomic", "Pfaffian, integrable" or "Pfaffian, not integrable".
std::string kind_text(const constraint& c, bool integrable)
{
    if (c.constraint_kind == constraint::kind::holonomic)
        return "holonomic";
    return integrable ? "Pfaffian, integrable" : "Pfaffian, not integrable";
}

const constraint_equations* constraints_shown(const analysis& result)
{
    if (!result.equations || !result.equations->residuals || !result.equations->constraints)
        return nullptr;
    return &*result.equations->constraints;
}

std::string vector_text(const std::vector<GiNaC::ex>& v, syntax s)
{
    std::string text = s == syntax::latex ? "\\left(" : "(";
    for (std::size_t k = 0; k < v.size(); ++k)
        text += (k ? ", " : "") + print(v[k], s);
    return text + (s == syntax::latex ? "\\right)" : ")");
}

/// The coordinate constraint k was solved for, if it was.
const eliminated_coordinate* solved_by(const analysis& result, std::size_t k)
{
    if (result.elimination)
        for (const eliminated_coordinate& e : result.elimination->eliminated)
            if (e.constraint == k)
                return &e;
    return nullptr;
}

std::string kept_names(const analysis& result)
{
    std::string names;
    for (std::size_t k : result.elimination->kept)
        names += (names.empty() ? "" : ", ") + result.scene->coordinates[k].name;
    return names;
}

} // namespace

void write_constraints_text(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax s = syntax::text;
    if (const constraint_equations* shown = constraints_shown(result)) {
        out << "\nConstraints (M q'' = f + Aᵀλ)\n";
        for (std::size_t k = 0; k < scene.constraints.size(); ++k) {
            const constraint& c = scene.constraints[k];
            out << "  " << c.name << " (" << kind_text(c, shown->integrable[k]) << "):  "
                << print(c.function, s, velocity_order(scene)) << " = 0\n";
        }
        for (std::size_t k = 0; k < scene.constraints.size(); ++k)
            if (const eliminated_coordinate* e = solved_by(result, k))
                out << "  " << scene.constraints[k].name << " can be eliminated: "
                    << print_name(scene.coordinates[e->coordinate].name, s) << " = "
                    << print(e->value, s, velocity_order(scene)) << '\n';
        if (!shown->jointly_integrable)
            out << "  together the constraints are not integrable: the motion is nonholonomic\n";
    }
    if (result.constrained && result.linearization) {
        out << "\nSmall oscillations in the independent coordinates";
        for (std::size_t k = 0; k < result.constrained->independent.size(); ++k)
            out << (k ? ", " : " ") << print_name(scene.coordinates[result.constrained->independent[k]].name, s);
        out << " (the others follow from the constraints)\n";
    }
    if (result.elimination && !result.elimination->equations.empty()) {
        out << "\nEquations with the constraints eliminated\n";
        for (std::size_t k = 0; k < result.elimination->kept.size(); ++k)
            out << "  " << print_name(scene.coordinates[result.elimination->kept[k]].name, s) << ":  "
                << print(result.elimination->equations[k], s, velocity_order(scene)) << " = 0\n";
    }
    if (!result.multipliers)
        return;
    out << "\nMultipliers\n";
    for (std::size_t k = 0; k < result.multipliers->constraints.size(); ++k) {
        const constraint_multiplier& m = result.multipliers->constraints[k];
        out << "  " << print_name(scene.constraints[k].multiplier.get_name(), s) << " = "
            << print(m.multiplier, s, velocity_order(scene)) << '\n';
    }
    bool any = false;
    for (const constraint_multiplier& m : result.multipliers->constraints)
        any = any || !m.forces.empty();
    if (any) {
        out << "\nConstraint forces\n";
        for (const constraint_multiplier& m : result.multipliers->constraints)
            for (const constraint_point_force& f : m.forces)
                out << "  " << m.name << " on " << f.point << ":  " << vector_text(f.force, s) << '\n';
    }
    for (const std::string& point : result.multipliers->unattributed)
        out << "  " << point << ": its coordinates also move other points or bodies, so the force is not split\n";
    if (!result.contact)
        return;
    out << "\nContact forces (the ground's force on each rolling wheel at its contact point, scene axes)\n";
    for (const contact_force& f : result.contact->contacts)
        out << "  " << f.body << " at " << vector_text(f.point, s) << ":\n    F = " << vector_text(f.force, s)
            << '\n';
}

void write_constraints_latex(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    const syntax s = syntax::latex;
    if (const constraint_equations* shown = constraints_shown(result)) {
        out << "\\subsection*{Constraints}\n";
        for (std::size_t k = 0; k < scene.constraints.size(); ++k) {
            const constraint& c = scene.constraints[k];
            out << latex_text(c.name + " (" + kind_text(c, shown->integrable[k]) + "):") << "\n";
            out << latex_equation("", print_terms(c.function, s, velocity_order(scene)), " = 0");
        }
        for (std::size_t k = 0; k < scene.constraints.size(); ++k)
            if (const eliminated_coordinate* e = solved_by(result, k))
                out << latex_text(scene.constraints[k].name + " can be eliminated:") << "\n"
                    << latex_equation(print_name(scene.coordinates[e->coordinate].name, s),
                                      {print(e->value, s, velocity_order(scene))}, "");
        if (!shown->jointly_integrable)
            out << latex_text("Together the constraints are not integrable: the motion is nonholonomic.") << "\n\n";
    }
    if (result.constrained && result.linearization) {
        std::string names; // as the equations write them: θ, not theta
        for (std::size_t k : result.constrained->independent)
            names += (names.empty() ? "" : ", ") + print_name(scene.coordinates[k].name, s);
        out << latex_text("Small oscillations in the independent coordinates ") << "$" << names << "$"
            << latex_text(" (the others follow from the constraints).") << "\n\n";
    }
    if (result.elimination && !result.elimination->equations.empty()) {
        out << "\\subsection*{Equations with the constraints eliminated}\n";
        std::string kept;
        for (std::size_t k : result.elimination->kept)
            kept += (kept.empty() ? "" : ", ") + print_name(scene.coordinates[k].name, s);
        out << latex_text("In the coordinates ") << "$" << kept << "$:\n";
        for (const GiNaC::ex& e : result.elimination->equations)
            out << latex_equation("", print_terms(e, s, velocity_order(scene)), " = 0");
    }
    if (!result.multipliers)
        return;
    out << "\\subsection*{Multipliers}\n";
    for (std::size_t k = 0; k < result.multipliers->constraints.size(); ++k)
        out << latex_equation(print_name(scene.constraints[k].multiplier.get_name(), s),
                              {print(result.multipliers->constraints[k].multiplier, s, velocity_order(scene))}, "");
    for (const constraint_multiplier& m : result.multipliers->constraints)
        for (const constraint_point_force& f : m.forces)
            out << latex_text("Force of " + m.name + " on " + f.point + ":") << "\n"
                << latex_equation("F", {vector_text(f.force, s)}, "");
    if (!result.contact)
        return;
    out << "\\subsection*{Contact forces}\n"
        << latex_text("The ground's force on each rolling wheel at its contact point, in the scene's axes.") << "\n";
    for (const contact_force& f : result.contact->contacts)
        out << latex_text(f.body + " at") << "\n"
            << latex_equation("P", {vector_text(f.point, s)}, "")
            << latex_equation("F", {vector_text(f.force, s)}, "");
}

void write_constraints_json(nlohmann::ordered_json& doc, const analysis& result)
{
    const model& scene = *result.scene;
    if (const constraint_equations* shown = constraints_shown(result)) {
        nlohmann::ordered_json constraints = nlohmann::ordered_json::object();
        for (std::size_t k = 0; k < scene.constraints.size(); ++k) {
            const constraint& c = scene.constraints[k];
            constraints[c.name] = {
                {"kind", c.constraint_kind == constraint::kind::holonomic ? "holonomic" : "pfaffian"},
                {"equation", print(c.function, syntax::plain, velocity_order(scene))},
                {"integrable", static_cast<bool>(shown->integrable[k])}};
            if (const eliminated_coordinate* e = solved_by(result, k))
                constraints[c.name]["eliminates"] = {
                    {"coordinate", scene.coordinates[e->coordinate].name},
                    {"value", print(e->value, syntax::plain, velocity_order(scene))}};
        }
        doc["constraints"] = constraints;
        doc["constraints_integrable"] = shown->jointly_integrable;
    }
    if (result.constrained && result.linearization) {
        nlohmann::ordered_json names = nlohmann::ordered_json::array();
        for (std::size_t k : result.constrained->independent)
            names.push_back(scene.coordinates[k].name);
        doc["independent_coordinates"] = names;
    }
    if (result.elimination && !result.elimination->equations.empty()) {
        nlohmann::ordered_json eliminated = nlohmann::ordered_json::object();
        for (std::size_t k = 0; k < result.elimination->kept.size(); ++k)
            eliminated[scene.coordinates[result.elimination->kept[k]].name] =
                print(result.elimination->equations[k], syntax::plain, velocity_order(scene));
        doc["eliminated"] = eliminated;
    }
    if (!result.multipliers)
        return;
    nlohmann::ordered_json multipliers = nlohmann::ordered_json::object();
    nlohmann::ordered_json forces = nlohmann::ordered_json::object();
    for (const constraint_multiplier& m : result.multipliers->constraints) {
        multipliers[m.name] = print(m.multiplier, syntax::plain, velocity_order(scene));
        nlohmann::ordered_json on = nlohmann::ordered_json::object();
        for (const constraint_point_force& f : m.forces) {
            nlohmann::ordered_json components = nlohmann::ordered_json::array();
            for (const GiNaC::ex& x : f.force)
                components.push_back(print(x, syntax::plain, velocity_order(scene)));
            on[f.point] = components;
        }
        forces[m.name] = on;
    }
    doc["multipliers"] = multipliers;
    doc["constraint_forces"] = forces;
    if (!result.contact)
        return;
    const auto components = [&](const std::vector<GiNaC::ex>& v) {
        nlohmann::ordered_json list = nlohmann::ordered_json::array();
        for (const GiNaC::ex& x : v)
            list.push_back(print(x, syntax::plain, velocity_order(scene)));
        return list;
    };
    nlohmann::ordered_json contacts = nlohmann::ordered_json::object();
    for (const contact_force& f : result.contact->contacts)
        contacts[f.body] = {{"point", components(f.point)}, {"force", components(f.force)}};
    doc["contact_forces"] = contacts;
}

// ---- the report's section ----

void write_constraints_section(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    w.latex("\\section{Constraints}\n");
    w.text("With the constraints the equations of motion read");
    w.latex("\n\\[M\\ddot{q} = f + A^{\\mathsf{T}}\\lambda,\\qquad A\\ddot{q} = -c,\\]\n");
    w.text("where row ").latex("$k$").text(" of ").latex("$A$")
        .text(" holds the velocity coefficients of constraint ").latex("$k$")
        .text(" (its gradient, for a holonomic one), ").latex("$\\lambda_{k}$").text(" is its multiplier and ")
        .latex("$A\\ddot{q} = -c$")
        .text(" is the constraint differentiated to the accelerations. For constraints linear in the velocities "
              "these are the Lagrange–d'Alembert equations. The constraints are:");
    w.latex("\n");
    const constraint_equations* shown =
        result.equations && result.equations->constraints ? &*result.equations->constraints : nullptr;
    for (std::size_t k = 0; k < scene.constraints.size(); ++k) {
        const constraint& c = scene.constraints[k];
        std::string kind = c.constraint_kind == constraint::kind::holonomic ? "holonomic"
                           : shown && shown->integrable[k] ? "Pfaffian, integrable (a holonomic form exists)"
                                                           : "Pfaffian, not integrable";
        w.latex("\n\n\\noindent ").text(c.name + " (" + kind + "):");
        w.display_terms("", print_terms(c.function, syntax::latex, velocity_order(scene)), " = 0");
    }
    if (shown && !shown->jointly_integrable)
        w.text("Together the constraints are not integrable (Frobenius): the motion is nonholonomic.");
    if (result.constrained && result.linearization) {
        std::string names; // as the equations write them: θ, not theta
        for (std::size_t k : result.constrained->independent)
            names += (names.empty() ? "" : ", ") + report_writer::name(scene.coordinates[k].name);
        w.text(" The small oscillations below are in the independent coordinates ")
            .latex("$" + names + "$")
            .text(", on the tangent space of the constraints at the equilibrium.");
    }
    if (!result.multipliers)
        return;
    w.latex("\n\\subsection*{Multipliers}\n");
    w.text("Solving ")
        .latex("$\\begin{pmatrix} M & -A^{\\mathsf{T}} \\\\ A & 0\\end{pmatrix}"
               "\\begin{pmatrix}\\ddot{q} \\\\ \\lambda\\end{pmatrix} = "
               "\\begin{pmatrix} f \\\\ -c\\end{pmatrix}$")
        .text(" gives the multipliers:");
    w.latex("\n");
    for (std::size_t k = 0; k < result.multipliers->constraints.size(); ++k)
        w.display_terms(report_writer::name(scene.constraints[k].multiplier.get_name()),
                        print_terms(result.multipliers->constraints[k].multiplier, syntax::latex, velocity_order(scene)));
    if (result.contact) {
        w.latex("\n\\subsection*{Contact forces}\n");
        w.text("Each constraint of a rolling wheel holds its contact point ").latex("$P$").text(" along a vector ")
            .latex("$e_k$").text(" (its velocity form is ").latex("$e_k \\cdot v_P$")
            .text("), so its generalized force is that of the force ").latex("$\\lambda_k e_k$")
            .text(" at ").latex("$P$").text(", and the ground's force on the wheel there, in the scene's axes, is ")
            .latex("$F = \\sum_k \\lambda_k e_k$").text(":");
        w.latex("\n");
        for (const contact_force& f : result.contact->contacts)
            for (std::size_t r = 0; r < f.force.size(); ++r)
                w.display_terms("F^{\\mathrm{" + latex_text(f.body) + "}}_{" +
                                    std::string(1, static_cast<char>('x' + r)) + "}",
                                print_terms(f.force[r], syntax::latex, velocity_order(scene)));
    }
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
