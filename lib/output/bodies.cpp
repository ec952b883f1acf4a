// SPDX-License-Identifier: GPL-2.0-or-later
/** @file bodies.cpp
 *  The rigid-body family (see body_family.h): the heavy top, inertia and Euler's equations
 *  in the order the documents and the report show them, and what their files share. */
#include "output/bodies_output.h"
#include "output/body_family.h"

#include "output/print.h"

#include <nlohmann/json.hpp>

#include <cctype>

namespace lagrange {

std::vector<std::string> printed(const std::vector<GiNaC::ex>& v, syntax s, const term_order& order)
{
    std::vector<std::string> out;
    for (const GiNaC::ex& e : v)
        out.push_back(print(e, s, order));
    return out;
}

std::string body_title(const std::string& name) { return "$" + report_writer::name(name) + "$"; }

namespace {

/// A rough width of LaTeX math in characters (as document.cpp measures it): a command
/// counts as one, braces and sub/superscript marks as none.
std::size_t latex_width(const std::string& latex)
{
    std::size_t width = 0;
    for (std::size_t i = 0; i < latex.size(); ++i) {
        const char c = latex[i];
        if (c == '\\') {
            std::size_t j = i + 1;
            while (j < latex.size() && std::isalpha(static_cast<unsigned char>(latex[j])))
                ++j;
            ++width;
            i = j > i + 1 ? j - 1 : j;
        } else if (c != '{' && c != '}' && c != '^' && c != '_' && c != ' ' && c != '&') {
            ++width;
        }
    }
    return width;
}

} // namespace

/// A displayed line of math; one wider than the page is scaled down to the page width.
std::string latex_line(const std::string& math)
{
    constexpr std::size_t line_width = 75;
    if (latex_width(math) <= line_width)
        return "\\[" + math + "\\]\n";
    return "\\[\\resizebox{\\linewidth}{!}{$\\displaystyle " + math + "$}\\]\n";
}

nlohmann::ordered_json json_strings(const std::vector<GiNaC::ex>& v, const term_order& order)
{
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const GiNaC::ex& e : v)
        list.push_back(print(e, syntax::plain, order));
    return list;
}

void write_bodies_text(std::ostream& out, const analysis& result)
{
    write_tops_text(out, result);
    write_inertia_text(out, result);
    write_euler_text(out, result);
}

void write_bodies_latex(std::ostream& out, const analysis& result)
{
    write_tops_latex(out, result);
    write_inertia_latex(out, result);
    write_euler_latex(out, result);
}

void write_bodies_json(nlohmann::ordered_json& doc, const analysis& result)
{
    write_inertia_json(doc, result);
    write_tops_json(doc, result);
    write_euler_json(doc, result);
}

void write_body_sections(report_writer& w)
{
    const analysis& r = w.result();
    if (r.inertia)
        write_inertia_section(w);
    if (r.tops && !r.tops->empty())
        write_tops_section(w);
    if (r.euler)
        write_euler_section(w);
}

} // namespace lagrange
