// SPDX-License-Identifier: GPL-2.0-or-later
/** @file floquet_output.cpp
 *  Printers of the Floquet multipliers about points that solve the equations at every t. */
#include "output/floquet_output.h"
#include "output/format.h"

#include "core/number_text.h"

#include "output/print.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

} // namespace lagrange
