// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gyroscopic_report.cpp
 *  The report's sections on a Lagrangian with a part linear in the velocities: the
 *  gyroscopic matrix G and the Kelvin–Tait–Chetaev verdict, and the numeric values from
 *  the quadratic eigenproblem with their complex modes. */
#include "output/report_sections.h"
#include "output/format.h"

#include "output/latex_blocks.h"
#include "output/mode_frequency.h"

#include <complex>
#include <string>

namespace lagrange {

namespace {

std::string complex_latex(std::complex<double> z)
{
    return complex_number(z, [](double v) { return report_writer::number(v, 6); }, "\\,i");
}

} // namespace

void write_gyroscopic_matrix(report_writer& w)
{
    const analysis& result = w.result();
    const linearization_result& l = *result.linearization;
    w.latex("\\section{The gyroscopic matrix}\n");
    w.text("The part of L linear in the velocities, ")
        .latex("$L_{1} = \\sum_{i} a_{i}(q)\\,\\dot{q}_{i}$")
        .text(", gives the antisymmetric matrix")
        .latex("\n\\[\\mathbf{G}_{ij} = \\left.\\left(\\frac{\\partial a_{j}}{\\partial q_{i}} - "
               "\\frac{\\partial a_{i}}{\\partial q_{j}}\\right)\\right|_{0}\\]\n")
        .text("and the linearized equations ")
        .latex("$\\mathbf{T}\\ddot{\\eta} - \\mathbf{G}\\dot{\\eta} + \\mathbf{V}\\eta = 0$")
        .text(":");
    w.display_matrix("\\mathbf{G}", l.gyroscopic);
    w.text("Stability follows the Kelvin–Tait–Chetaev theorems: a minimum of the effective potential stays stable "
           "whatever G; an odd number of negative stiffnesses (det V < 0) is unstable whatever G; otherwise the "
           "equilibrium is stable exactly when every root in ")
        .latex("$\\omega^{2}$")
        .text(" of the characteristic polynomial is real, positive and simple (gyroscopic stabilization), which a "
              "Sturm sequence decides.");
    if (result.equilibria)
        w.text(" Here: " + to_string(result.equilibria->points.at(result.equilibria->chosen).kind) + ".");
    w.latex("\n");
}

void write_gyroscopic_numeric(report_writer& w)
{
    const analysis& result = w.result();
    w.latex("\\section{Numeric values}\n");
    w.text("At each parameter point the engine evaluates T, V and G and solves the quadratic eigenproblem ")
        .latex("$(s^{2}\\mathbf{T} - s\\mathbf{G} + \\mathbf{V})\\,x = 0$")
        .text(" through the real eigenproblem of the first-order system. The frequencies are the imaginary parts "
              "of the eigenvalues in the upper half plane; a real eigenvalue s = γ > 0 is an imaginary frequency "
              "iγ, and a mode whose eigenvalue has a positive real part is shown with that growth rate. Each "
              "comes with an estimate of its relative error. The modes are complex, normalized so that ")
        .latex("$x^{*}\\mathbf{T}x = 1$")
        .text(" with their first largest component real and positive.");
    w.latex("\n");
    for (const numeric_modes& nm : *result.numeric) {
        const std::string at = values_latex(nm);
        w.latex("\\subsection*{At $" + at + "$: " + nm.stability + "}\n");
        w.latex("\\begin{center}\n\\renewcommand{\\arraystretch}{1.3}\n\\begin{tabular}{rlll}\n\\hline\n"
                "$k$ & $\\omega_{k}$ & relative error & mode\\\\\n\\hline\n");
        for (std::size_t k = 0; k < nm.omega.size(); ++k) {
            std::string mode;
            for (Eigen::Index i = 0; i < nm.complex_modes.rows(); ++i)
                mode += (i ? ",\\ " : "") + complex_latex(nm.complex_modes(i, static_cast<Eigen::Index>(k)));
            w.latex(std::to_string(k + 1) + " & $" +
                    omega_value_latex(nm, k, [](double x) { return report_writer::number(x); }) + "$ & $\\le " +
                    report_writer::number(nm.error[k], 2) + "$ & $(" + mode + ")$\\\\\n");
        }
        w.latex("\\hline\n\\end{tabular}\n\\end{center}\n");
        write_growth_rates(w, nm);
        w.text("Method: " + nm.method + ".");
        w.latex("\n");
    }
}

} // namespace lagrange
