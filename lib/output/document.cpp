/** @file document.cpp
 *  Text, LaTeX and JSON documents of an analysis. */
#include "output/document.h"

#include "output/print.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdio>

namespace lagrange {

namespace {

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

/// LaTeX special characters in free text (titles).
std::string latex_escape(const std::string& text)
{
    std::string out;
    for (char c : text) {
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
std::string latex_rows(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs)
{
    constexpr std::size_t line_width = 62;
    std::string out = lhs + (lhs.empty() ? "&" : " &= ");
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
    if (result.equations) {
        out << "\nEquations of motion\n";
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            out << "  " << print_name(scene.coordinates[i].name, syntax::text) << ":  "
                << print((*result.equations)[i], syntax::text, equation_order(scene)) << " = 0\n";
    }
    if (options.timings) {
        out << "\nStages\n";
        for (const stage_time& s : result.stages)
            out << "  " << s.stage << ": " << seconds(s.seconds) << " s\n";
    }
}

void write_latex(std::ostream& out, const analysis& result, const document_options& options)
{
    const model& scene = *result.scene;
    out << "\\documentclass[11pt]{article}\n"
           "\\usepackage[utf8]{inputenc}\n"
           "\\usepackage{amsmath}\n"
           "\\usepackage[margin=2cm]{geometry}\n"
           "\\begin{document}\n";
    out << "\\section*{" << latex_escape(scene.title.empty() ? "Scene" : scene.title) << "}\n";
    out << "Coordinates: $" << join_names(coordinate_names(scene), syntax::latex, ",\\ ") << "$.\\\\\n";
    out << "Parameters: $" << join_names(parameter_names(scene), syntax::latex, ",\\ ") << "$.\n";
    if (result.lagrangian) {
        const lagrangian_result& l = *result.lagrangian;
        out << "\\subsection*{Lagrangian}\n\\begin{align*}\n";
        if (l.split) {
            out << latex_rows("T", print_terms(l.kinetic, syntax::latex, velocity_order(scene)), "") << "\\\\\n";
            if (!l.gyroscopic.is_zero())
                out << latex_rows("L_1", print_terms(l.gyroscopic, syntax::latex, velocity_order(scene)), "")
                    << "\\\\\n";
            out << latex_rows("V", print_terms(l.potential, syntax::latex), "") << "\\\\\n";
        }
        out << latex_rows("L", print_terms(l.lagrangian, syntax::latex, velocity_order(scene)), "")
            << "\n\\end{align*}\n";
    }
    if (result.equations) {
        out << "\\subsection*{Equations of motion}\n\\begin{align*}\n";
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
            out << latex_rows("", print_terms((*result.equations)[i], syntax::latex, equation_order(scene)), " = 0")
                << (i + 1 < scene.coordinates.size() ? "\\\\\n" : "\n");
        out << "\\end{align*}\n";
    }
    if (options.timings) {
        out << "\\subsection*{Stages}\n\\begin{tabular}{lr}\n";
        for (const stage_time& s : result.stages)
            out << latex_escape(s.stage) << " & " << seconds(s.seconds) << " s\\\\\n";
        out << "\\end{tabular}\n";
    }
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
    if (result.lagrangian) {
        const lagrangian_result& l = *result.lagrangian;
        doc["lagrangian"] = print(l.lagrangian, syntax::plain, velocity_order(scene));
        if (l.split) {
            doc["kinetic_energy"] = print(l.kinetic, syntax::plain, velocity_order(scene));
            doc["potential_energy"] = print(l.potential, syntax::plain);
        }
    }
    if (result.equations) {
        doc["equations"] = nlohmann::json::array();
        for (const GiNaC::ex& e : *result.equations)
            doc["equations"].push_back(print(e, syntax::plain, equation_order(scene)));
    }
    out << doc.dump(2) << '\n';
}

} // namespace lagrange
