// SPDX-License-Identifier: GPL-2.0-or-later
/** @file critical.cpp
 *  Critical parameters as text, LaTeX and JSON, and the root locus for gnuplot. */
#include "output/critical.h"

#include "output/format.h"

#include "core/number_text.h"
#include "output/print.h"
#include "output/report_sections.h"
#include "system/gnuplot.h"

#include <sstream>

#include <cmath>

namespace lagrange {

namespace {

/// A crossing's value to the digits the root finder gives (1e-10 and beyond).
std::string crossing_text(double x) { return significant(x, 13); }
std::string entry_text(double x) { return significant(std::abs(x) < 1e-300 ? 0.0 : x, 12); }

/// s as "a + bi", "a - bi" or "a".
std::string complex_text(std::complex<double> s) { return complex_number(s, entry_text, "i"); }

/// What kind of crossing: a complex pair through ±iω, or a real eigenvalue through 0.
std::string crossing_kind(const critical_crossing& c)
{
    if (c.eigenvalue.imag() > 1e-9 * (1 + std::abs(c.eigenvalue.real())))
        return "a complex pair crosses at s = ±" + entry_text(c.eigenvalue.imag()) + "i";
    return "a real eigenvalue crosses s = 0";
}

std::string instability_text(const critical_crossing& c)
{
    return std::to_string(c.unstable_before) + " → " + std::to_string(c.unstable_after) +
           " eigenvalues with Re s > 0";
}

std::string values_text(const critical_result& r)
{
    std::string text;
    for (const auto& [name, value] : r.values)
        text += (text.empty() ? "" : ", ") + name + " = " + shortest(value);
    return text;
}

/// The table's grid points: every table_every-th point of the locus.
template <class F> void for_each_row(const critical_result& r, F&& f)
{
    for (std::size_t i = 0; i < r.grid.size(); i += r.table_every)
        f(i);
}

} // namespace

void write_critical_text(std::ostream& out, const analysis& result)
{
    if (!result.critical)
        return;
    const critical_result& r = *result.critical;
    out << "\nCritical parameters (" << print_name(r.parameter, syntax::text) << " from " << shortest(r.from)
        << " to " << shortest(r.to) << (r.values.empty() ? "" : "; " + values_text(r)) << ")\n";
    if (r.crossings.empty())
        out << "  none in the range: no real part of an eigenvalue crosses 0\n";
    for (const critical_crossing& c : r.crossings)
        out << "  Re s = 0 at " << print_name(r.parameter, syntax::text) << " = " << crossing_text(c.value) << ": "
            << crossing_kind(c) << " (" << instability_text(c) << ")\n";
    out << "  eigenvalues s along the range (q ∝ e^{st})\n";
    for_each_row(r, [&](std::size_t i) {
        out << "    " << print_name(r.parameter, syntax::text) << " = " << shortest(r.grid[i]) << ":";
        for (std::size_t k = 0; k < r.locus[i].size(); ++k)
            out << (k == 0 ? "  " : ",  ") << complex_text(r.locus[i][k]);
        out << '\n';
    });
}

namespace {

void critical_latex(std::ostream& out, const critical_result& r)
{
    const std::string name = print_name(r.parameter, syntax::latex);
    out << "\\subsection*{Critical parameters}\n";
    out << "$" << name << "$ from $" << latex_number(r.from) << "$ to $" << latex_number(r.to) << "$";
    for (const auto& [other, value] : r.values)
        out << ", $" << print_name(other, syntax::latex) << " = " << latex_number(value) << "$";
    out << ".\n";
    if (r.crossings.empty())
        out << "None in the range: no real part of an eigenvalue crosses 0.\n";
    for (const critical_crossing& c : r.crossings)
        out << "\n$\\operatorname{Re} s = 0$ at $" << name << " = " << latex_number(c.value, 13) << "$: "
            << crossing_kind(c) << " (" << c.unstable_before << " $\\to$ " << c.unstable_after
            << " eigenvalues with $\\operatorname{Re} s > 0$).\n";
    // Four complex eigenvalues a row are wider than the page: the second column is a
    // paragraph, each eigenvalue its own formula, so the row wraps between them.
    out << "\n\\noindent\\begin{tabular}{lp{0.8\\linewidth}}\n$" << name
        << "$ & eigenvalues $s$\\\\\n\\hline\n";
    for_each_row(r, [&](std::size_t i) {
        out << "$" << latex_number(r.grid[i]) << "$ & \\raggedright ";
        for (std::size_t k = 0; k < r.locus[i].size(); ++k)
            out << (k == 0 ? "$" : ", $") << complex_text(r.locus[i][k]) << "$";
        out << "\\tabularnewline\n";
    });
    out << "\\end{tabular}\n";
}

} // namespace

void write_critical_latex(std::ostream& out, const analysis& result)
{
    if (result.critical)
        critical_latex(out, *result.critical);
}

void write_critical_json(nlohmann::ordered_json& doc, const analysis& result)
{
    if (!result.critical)
        return;
    const critical_result& r = *result.critical;
    nlohmann::ordered_json entry;
    entry["parameter"] = r.parameter;
    entry["range"] = {r.from, r.to};
    nlohmann::ordered_json values = values_json(r.values);
    entry["values"] = values;
    nlohmann::ordered_json crossings = nlohmann::ordered_json::array();
    for (const critical_crossing& c : r.crossings)
        crossings.push_back({{"value", c.value},
                             {"tolerance", c.tolerance},
                             {"eigenvalue", {c.eigenvalue.real(), c.eigenvalue.imag()}},
                             {"unstable_before", c.unstable_before},
                             {"unstable_after", c.unstable_after}});
    entry["crossings"] = crossings;
    const auto rows = [&](std::size_t every) {
        nlohmann::ordered_json table;
        nlohmann::ordered_json columns = {r.parameter};
        for (std::size_t k = 0; !r.locus.empty() && k < r.locus.front().size(); ++k) {
            columns.push_back("re" + std::to_string(k + 1));
            columns.push_back("im" + std::to_string(k + 1));
        }
        table["columns"] = columns;
        nlohmann::ordered_json list = nlohmann::ordered_json::array();
        for (std::size_t i = 0; i < r.grid.size(); i += every) {
            nlohmann::ordered_json row = {r.grid[i]};
            for (const std::complex<double>& s : r.locus[i]) {
                row.push_back(s.real());
                row.push_back(s.imag());
            }
            list.push_back(row);
        }
        table["rows"] = list;
        return table;
    };
    entry["table"] = rows(r.table_every);
    entry["locus"] = rows(1);
    doc["critical"] = entry;
}

void write_critical_section(report_writer& w)
{
    const critical_result& r = *w.result().critical;
    w.latex("\\section{Critical parameters}\n");
    w.text("The eigenvalues ").latex("$s$").text(" of the linearized equations (").latex("$q \\propto e^{st}$")
        .text(") as the parameter runs over the range, the "
           "other parameters fixed; where a real part crosses 0 the equilibrium gains or loses stability. Each "
           "crossing is bracketed on a grid of " + std::to_string(r.grid.size()) +
           " points and refined with the TOMS 748 root finder.");
    w.latex("\n");
    std::ostringstream body;
    critical_latex(body, r);
    w.latex(body.str());
    w.figure("critical", critical_plot_script(r), 16.5, 8,
             "Root locus: the real (black) and imaginary (grey rings, |Im s|) parts of the eigenvalues against $" +
                 report_writer::name(r.parameter) + "$; dotted lines mark the crossings.");
}

std::string critical_plot_script(const critical_result& r)
{
    std::string script = "$locus << EOD\n";
    for (std::size_t i = 0; i < r.grid.size(); ++i) {
        script += shortest(r.grid[i]);
        for (const std::complex<double>& s : r.locus[i])
            script += " " + shortest(s.real()) + " " + shortest(s.imag());
        script += "\n";
    }
    script += "EOD\n";
    script += "set xlabel " + gnuplot_string(r.parameter) + "\nset ylabel 'Re s (dots), |Im s| (rings)'\nset key off\n";
    script += "set xrange [" + shortest(r.from) + ":" + shortest(r.to) + "]\nset xzeroaxis\n";
    for (const critical_crossing& c : r.crossings)
        script += "set arrow from " + shortest(c.value) + ", graph 0 to " + shortest(c.value) +
                  ", graph 1 nohead dashtype 3 lc rgb 'gray40'\n";
    const std::size_t count = r.locus.empty() ? 0 : r.locus.front().size();
    // points, not lines: the k-th column is not one branch where eigenvalues change order
    script += "plot ";
    for (std::size_t k = 0; k < count; ++k)
        script += std::string(k == 0 ? "" : ", ") + "$locus using 1:" + std::to_string(2 + 2 * k) +
                  " with points pt 7 ps 0.3 lc rgb 'black', $locus using 1:(abs($" + std::to_string(3 + 2 * k) +
                  ")) with points pt 6 ps 0.3 lc rgb 'gray50'";
    script += "\n";
    return script;
}

} // namespace lagrange
