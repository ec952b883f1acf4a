// SPDX-License-Identifier: GPL-2.0-or-later
/** @file floquet_report.cpp
 *  The report's section on an L that depends on t: the points that solve the equations
 *  at every t and the Floquet multipliers about them. */
#include "output/report_sections.h"
#include "output/format.h"

#include <cmath>
#include <complex>
#include <string>

namespace lagrange {

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
