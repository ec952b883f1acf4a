// SPDX-License-Identifier: GPL-2.0-or-later
/** @file floquet.cpp
*  Printers of the Floquet multipliers about points that solve the equations at every t.
 *
*  The report's section on an L that depends on t: the points that solve the equations
 *  at every t and the Floquet multipliers about them. */
#include "output/floquet.h"

#include "core/number_text.h"
#include "output/format.h"
#include "output/print.h"
#include "output/report_sections.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

namespace lagrange {

namespace {

/// Ten significant digits (text and LaTeX): the integration is accurate far beyond them.
std::string short_number(double x)
{
    return x == 0 ? "0" : significant(x, 10);
}

/// short_number, in LaTeX with the exponent as ×10^{k}.
std::string number_in(double x, syntax s)
{
    return s == syntax::latex ? latex_exponent(short_number(x)) : short_number(x);
}

std::string multiplier_text(const std::complex<double>& mu, syntax s)
{
    return complex_number(mu, [s](double v) { return number_in(v, s); }, s == syntax::latex ? "\\,i" : "i");
}

std::string point_text(const model& scene, const floquet_point& f, syntax s)
{
    std::string text;
    for (std::size_t i = 0; i < scene.coordinates.size() && i < f.point.size(); ++i)
        text += (i ? (s == syntax::latex ? ",\\ " : ", ") : "") + print_name(scene.coordinates[i].name, s) + " = " +
                print(f.point[i], s);
    return text;
}

std::string values_text(const floquet_point& f, syntax s)
{
    std::string text;
    for (std::size_t i = 0; i < f.values.size(); ++i)
        text += (i ? (s == syntax::latex ? ",\\ " : ", ") : "") + print_name(f.values[i].first, s) + " = " +
                number_in(f.values[i].second, s);
    return text;
}

double largest_modulus(const floquet_point& f)
{
    double largest = 0;
    for (const std::complex<double>& mu : f.multipliers)
        largest = std::max(largest, std::abs(mu));
    return largest;
}

} // namespace

void write_floquet_text(std::ostream& out, const analysis& result)
{
    if (!result.floquet)
        return;
    const model& scene = *result.scene;
    out << "\nFloquet multipliers (L depends on t; linearized about points that solve the equations at every t)\n";
    for (const floquet_point& f : *result.floquet) {
        out << "  about " << point_text(scene, f, syntax::text) << "  at " << values_text(f, syntax::text) << '\n';
        out << "    period T = " << short_number(f.period) << "\n    μ = ";
        for (std::size_t k = 0; k < f.multipliers.size(); ++k)
            out << (k ? ",  " : "") << multiplier_text(f.multipliers[k], syntax::text);
        out << "\n    max |μ| = " << short_number(largest_modulus(f)) << ": " << (f.stable ? "stable" : "unstable")
            << '\n';
    }
}

void write_floquet_latex(std::ostream& out, const analysis& result)
{
    if (!result.floquet)
        return;
    const model& scene = *result.scene;
    out << "\\subsection*{Floquet multipliers}\n"
           "$L$ depends on $t$: the equations linearized about a point that solves them at every $t$, "
           "integrated over one period $T$; the multipliers $\\mu$ are the eigenvalues of the monodromy matrix.\n";
    for (const floquet_point& f : *result.floquet) {
        out << "\n\\noindent About $" << point_text(scene, f, syntax::latex) << "$ at $" << values_text(f, syntax::latex)
            << "$:\n\\begin{align*}\nT &= " << number_in(f.period, syntax::latex) << "\\\\\n";
        for (std::size_t k = 0; k < f.multipliers.size(); ++k)
            out << "\\mu_{" << k + 1 << "} &= " << multiplier_text(f.multipliers[k], syntax::latex) << "\\\\\n";
        out << "\\max|\\mu| &= " << number_in(largest_modulus(f), syntax::latex) << " && \\text{"
            << (f.stable ? "stable" : "unstable") << "}\n\\end{align*}\n";
    }
}

void write_floquet_json(nlohmann::ordered_json& doc, const analysis& result)
{
    if (!result.floquet)
        return;
    const model& scene = *result.scene;
    nlohmann::ordered_json entries = nlohmann::ordered_json::array();
    for (const floquet_point& f : *result.floquet) {
        nlohmann::ordered_json point = nlohmann::ordered_json::object();
        for (std::size_t i = 0; i < scene.coordinates.size() && i < f.point.size(); ++i)
            point[scene.coordinates[i].name] = print(f.point[i], syntax::plain);
        nlohmann::ordered_json values = values_json(f.values);
        nlohmann::ordered_json multipliers = nlohmann::ordered_json::array();
        for (const std::complex<double>& mu : f.multipliers)
            multipliers.push_back({mu.real(), mu.imag()});
        entries.push_back({{"point", point}, {"values", values}, {"period", f.period},
                           {"multipliers", multipliers}, {"stable", f.stable}});
    }
    doc["floquet"] = entries;
}

// ---- the report's section ----

void write_floquet_section(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    w.latex("\\section{Periodic drive: Floquet multipliers}\n");
    w.text("The Lagrangian depends on t, so there is no static equilibrium. A point at which the equations of "
           "motion hold at every t is still a solution; the equations linearized about it have coefficients "
           "periodic in t with period T. Integrated over one period from the identity, they give the monodromy "
           "matrix, whose eigenvalues are the Floquet multipliers ")
        .latex("$\\mu$")
        .text(". The motion about the point is stable when every multiplier lies on or inside the unit circle.");
    w.latex("\n");
    for (const floquet_point& f : *result.floquet) {
        std::string about, at;
        for (std::size_t i = 0; i < scene.coordinates.size() && i < f.point.size(); ++i)
            about += (i ? ",\\ " : "") + report_writer::name(scene.coordinates[i].name) + " = " +
                     report_writer::math(f.point[i]);
        for (std::size_t i = 0; i < f.values.size(); ++i)
            at += (i ? ",\\ " : "") + report_writer::name(f.values[i].first) + " = " +
                  report_writer::number(f.values[i].second);
        w.latex("\\subsection*{About $" + about + "$ at $" + at + "$}\n");
        w.latex("\\begin{center}\n\\renewcommand{\\arraystretch}{1.3}\n\\begin{tabular}{rll}\n\\hline\n"
                "$k$ & $\\mu_{k}$ & $|\\mu_{k}|$\\\\\n\\hline\n");
        double largest = 0;
        for (std::size_t k = 0; k < f.multipliers.size(); ++k) {
            const std::complex<double>& mu = f.multipliers[k];
            largest = std::max(largest, std::abs(mu));
            const std::string value =
                complex_number(mu, [](double v) { return report_writer::number(v, 10); }, "\\,i");
            w.latex(std::to_string(k + 1) + " & $" + value + "$ & $" + report_writer::number(std::abs(mu), 10) +
                    "$\\\\\n");
        }
        w.latex("\\hline\n\\end{tabular}\n\\end{center}\n");
        w.text("Period ")
            .latex("$T = " + report_writer::number(f.period, 10) + "$")
            .text(std::string(". The largest modulus is ") + (f.stable ? "at most 1: stable." : "above 1: unstable."));
        w.latex("\n");
    }
}

} // namespace lagrange
