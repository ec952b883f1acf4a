// SPDX-License-Identifier: GPL-2.0-or-later
/** @file document.cpp
 *  Text, LaTeX and JSON documents of an analysis. */
#include "output/document.h"

#include "core/number_text.h"

#include "output/latex_blocks.h"
#include "output/bodies_output.h"
#include "output/floquet.h"
#include "output/constraints.h"
#include "output/damping.h"
#include "output/linear_system.h"
#include "output/oscillations.h"
#include "output/symmetries.h"
#include "output/print.h"
#include "output/simulation.h"

#include <nlohmann/json.hpp>

#include <sstream>
#include <stdexcept>

namespace lagrange {

// The writers of the products with an output family of their own (core/products.inc),
// defined in output/<id>.cpp.
#define LAGRANGE_PRODUCT(id, name, scope, by_default)
#define LAGRANGE_OWN_PRODUCT(id, name, scope, by_default, result)                                           \
    void write_##id##_text(std::ostream& out, const analysis& result);                                      \
    void write_##id##_latex(std::ostream& out, const analysis& result);                                     \
    void write_##id##_json(nlohmann::ordered_json& doc, const analysis& result);
#include "core/products.inc"
#undef LAGRANGE_OWN_PRODUCT
#undef LAGRANGE_PRODUCT

namespace {

std::string seconds(double s) { return fixed(s, 6); }

std::string join_names(const std::vector<std::string>& names, syntax s, const char* separator)
{
    std::string out;
    for (const std::string& n : names)
        out += (out.empty() ? "" : separator) + print_name(n, s);
    return out;
}

/// The Lagrangian's family (every scene with coordinates shows T, V and L).
void write_lagrangian_text(std::ostream& out, const analysis& result, const document_options&)
{
    if (!result.lagrangian)
        return;
    const model& scene = *result.scene;
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

void write_lagrangian_latex(std::ostream& out, const analysis& result, const document_options&)
{
    if (!result.lagrangian)
        return;
    const model& scene = *result.scene;
    const lagrangian_result& l = *result.lagrangian;
    out << "\\subsection*{Lagrangian}\n";
    std::vector<latex_row> rows;
    if (l.split) {
        rows.push_back({"T", print_terms(l.kinetic, syntax::latex, velocity_order(scene))});
        if (!l.gyroscopic.is_zero())
            rows.push_back({"L_1", print_terms(l.gyroscopic, syntax::latex, velocity_order(scene))});
        rows.push_back({"V", print_terms(l.potential, syntax::latex)});
    }
    rows.push_back({"L", print_terms(l.lagrangian, syntax::latex, velocity_order(scene))});
    out << latex_equations(rows);
}

void write_lagrangian_json(nlohmann::ordered_json& doc, const analysis& result, const document_options&)
{
    if (!result.lagrangian)
        return;
    const model& scene = *result.scene;
    const lagrangian_result& l = *result.lagrangian;
    doc["lagrangian"] = print(l.lagrangian, syntax::plain, velocity_order(scene));
    if (l.split) {
        doc["kinetic_energy"] = print(l.kinetic, syntax::plain, velocity_order(scene));
        doc["potential_energy"] = print(l.potential, syntax::plain);
    }
}

/// The equations of motion, as printed residuals (`= 0`).
void write_equations_text(std::ostream& out, const analysis& result, const document_options&)
{
    if (!result.equations || !result.equations->residuals)
        return;
    const model& scene = *result.scene;
    out << "\nEquations of motion\n";
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
        out << "  " << print_name(scene.coordinates[i].name, syntax::text) << ":  "
            << print((*result.equations->residuals)[i], syntax::text, equation_order(scene)) << " = 0\n";
}

void write_equations_latex(std::ostream& out, const analysis& result, const document_options&)
{
    if (!result.equations || !result.equations->residuals)
        return;
    const model& scene = *result.scene;
    out << "\\subsection*{Equations of motion}\n";
    std::vector<latex_row> rows;
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
        rows.push_back({"", print_terms((*result.equations->residuals)[i], syntax::latex, equation_order(scene)), " = 0"});
    out << latex_equations(rows);
}

void write_equations_json(nlohmann::ordered_json& doc, const analysis& result, const document_options&)
{
    if (!result.equations || !result.equations->residuals)
        return;
    doc["equations"] = nlohmann::json::array();
    for (const GiNaC::ex& e : *result.equations->residuals)
        doc["equations"].push_back(print(e, syntax::plain, equation_order(*result.scene)));
}

/// How each result was checked: in JSON whenever there are checks (or `verification` was
/// asked for), in text and LaTeX only when `verification` was asked for.
void write_verification_text(std::ostream& out, const analysis& result, const document_options&)
{
    if (!result.verification || !result.wanted.count(product::verification))
        return;
    out << "\nVerification (each result checked numerically by an independent route)\n";
    for (const verification_entry& entry : result.verification->entries)
        out << "  " << entry.item << ": " << entry.how << '\n';
}

void write_verification_latex(std::ostream& out, const analysis& result, const document_options&)
{
    if (!result.verification || !result.wanted.count(product::verification) || result.verification->entries.empty())
        return;
    out << "\\subsection*{Verification}\nEach result checked numerically by an independent route:\n"
           "\\begin{itemize}\n";
    for (const verification_entry& entry : result.verification->entries)
        out << "\\item " << latex_text(entry.item) << ": " << latex_text(entry.how) << "\n";
    out << "\\end{itemize}\n";
}

void write_verification_json(nlohmann::ordered_json& doc, const analysis& result, const document_options&)
{
    if (!result.verification ||
        (result.verification->entries.empty() && !result.wanted.count(product::verification)))
        return;
    nlohmann::ordered_json checks = nlohmann::ordered_json::object();
    for (const verification_entry& entry : result.verification->entries)
        checks[entry.item] = entry.how;
    doc["verification"] = checks;
}

/// One output family: its text, LaTeX and JSON writers (null: the family has none in
/// that format).
struct family_writers {
    void (*text)(std::ostream&, const analysis&, const document_options&);
    void (*latex)(std::ostream&, const analysis&, const document_options&);
    void (*json)(nlohmann::ordered_json&, const analysis&, const document_options&);
};

/// The row of a family whose writers read only the analysis (most families' files).
template <void (*text)(std::ostream&, const analysis&), void (*latex)(std::ostream&, const analysis&),
          void (*json)(nlohmann::ordered_json&, const analysis&)>
family_writers family()
{
    return {[](std::ostream& out, const analysis& r, const document_options&) { text(out, r); },
            [](std::ostream& out, const analysis& r, const document_options&) { latex(out, r); },
            [](nlohmann::ordered_json& doc, const analysis& r, const document_options&) { json(doc, r); }};
}

/// Every family, in the order the three documents show them: the built-in families, with
/// the products that have a family of their own after the work-precision table.
const std::vector<family_writers>& families()
{
    using options = const document_options&;
    static const std::vector<family_writers> table = {
        {write_lagrangian_text, write_lagrangian_latex, write_lagrangian_json},
        {write_equations_text, write_equations_latex, write_equations_json},
        family<write_constraints_text, write_constraints_latex, write_constraints_json>(),
        family<write_oscillations_text, write_oscillations_latex, write_oscillations_json>(),
        family<write_floquet_text, write_floquet_latex, write_floquet_json>(),
        {[](std::ostream& out, const analysis& r, options) {
             if (r.damping)
                 write_damping_text(out, *r.scene, *r.damping);
         },
         [](std::ostream& out, const analysis& r, options) {
             if (r.damping)
                 write_damping_latex(out, *r.scene, *r.damping);
         },
         [](nlohmann::ordered_json& doc, const analysis& r, options) {
             if (r.damping)
                 write_damping_json(doc, *r.scene, *r.damping);
         }},
        family<write_linear_system_text, write_linear_system_latex, write_linear_system_json>(),
        family<write_symmetries_text, write_symmetries_latex, write_symmetries_json>(),
        family<write_bodies_text, write_bodies_latex, write_bodies_json>(),
        {[](std::ostream& out, const analysis& r, options o) {
             if (r.simulation)
                 write_simulation_text(out, *r.simulation, o.timings);
         },
         [](std::ostream& out, const analysis& r, options o) {
             if (r.simulation)
                 write_simulation_latex(out, *r.simulation, o.timings);
         },
         [](nlohmann::ordered_json& doc, const analysis& r, options o) {
             if (r.simulation)
                 doc["simulation"] = simulation_json(*r.simulation, o.timings);
         }},
        {[](std::ostream& out, const analysis& r, options) {
             if (r.workprecision)
                 write_workprecision_text(out, *r.workprecision);
         },
         [](std::ostream& out, const analysis& r, options) {
             if (r.workprecision)
                 write_workprecision_latex(out, *r.workprecision);
         },
         [](nlohmann::ordered_json& doc, const analysis& r, options) {
             if (r.workprecision)
                 doc["workprecision"] = workprecision_json(*r.workprecision);
         }},
#define LAGRANGE_PRODUCT(id, name, scope, by_default)
#define LAGRANGE_OWN_PRODUCT(id, name, scope, by_default, result)                                           \
    family<write_##id##_text, write_##id##_latex, write_##id##_json>(),
#include "core/products.inc"
#undef LAGRANGE_OWN_PRODUCT
#undef LAGRANGE_PRODUCT
        {write_verification_text, write_verification_latex, write_verification_json},
    };
    return table;
}

} // namespace

void write_text(std::ostream& out, const analysis& result, const document_options& options)
{
    const model& scene = *result.scene;
    if (!scene.title.empty())
        out << scene.title << "\n\n";
    out << "coordinates: " << join_names(coordinate_names(scene), syntax::text, ", ") << '\n';
    out << "parameters:  " << join_names(parameter_names(scene), syntax::text, ", ") << '\n';
    if (result.simulation) // a state the user did not write comes first, not buried in the run
        write_projected_initial_text(out, *result.simulation);
    for (const family_writers& family : families())
        if (family.text)
            family.text(out, result, options);
    for (const std::string& note : result.notes)
        out << "\nnote: " << note << '\n';
    if (options.timings) {
        out << "\nStages\n";
        for (const stage_time& s : result.stages) {
            out << "  " << s.stage << ": " << seconds(s.seconds) << " s\n";
            for (const auto& [part, time] : s.parts)
                out << "    " << part << ": " << seconds(time) << " s\n";
        }
    }
}

void write_latex(std::ostream& out, const analysis& result, const document_options& options)
{
    const model& scene = *result.scene;
    if (options.latex_body)
        out << "% lagrange: the body of a LaTeX document (needs \\usepackage{amsmath})\n";
    else
        out << "\\documentclass[11pt]{article}\n"
               "\\usepackage[utf8]{inputenc}\n"
               "\\usepackage{amsmath}\n"
               "\\usepackage{graphicx}\n"
               "\\usepackage[margin=2cm]{geometry}\n"
               "\\begin{document}\n";
    out << "\\section*{" << latex_text(scene.title.empty() ? "Scene" : scene.title) << "}\n";
    if (!scene.coordinates.empty()) // a free body's scene has none
        out << "Coordinates: $" << join_names(coordinate_names(scene), syntax::latex, ",\\ ") << "$.\\\\\n";
    out << "Parameters: $" << join_names(parameter_names(scene), syntax::latex, ",\\ ") << "$.\n";
    for (const family_writers& family : families())
        if (family.latex)
            family.latex(out, result, options);
    if (options.timings) {
        out << "\\subsection*{Stages}\n\\begin{tabular}{lr}\n";
        for (const stage_time& s : result.stages) {
            out << latex_text(s.stage) << " & " << seconds(s.seconds) << " s\\\\\n";
            for (const auto& [part, time] : s.parts)
                out << "\\quad " << latex_text(part) << " & " << seconds(time) << " s\\\\\n";
        }
        out << "\\end{tabular}\n";
    }
    if (!options.latex_body)
        out << "\\end{document}\n";
}

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
    for (const family_writers& family : families())
        if (family.json)
            family.json(doc, result, options);
    if (!result.notes.empty())
        doc["notes"] = result.notes;
    out << doc.dump(2) << '\n';
}

void require_document_format(const std::string& format)
{
    if (format != "text" && format != "latex" && format != "json")
        throw std::invalid_argument("format must be text, latex or json, not '" + format + "'");
}

std::string document_text(const analysis& result, const std::string& format, const document_options& options)
{
    require_document_format(format);
    std::ostringstream out;
    if (format == "text")
        write_text(out, result, options);
    else if (format == "latex")
        write_latex(out, result, options);
    else
        write_json(out, result, options);
    return out.str();
}

} // namespace lagrange
